// nscd_body_sweep: the cost of one contact update of the Gauss–Seidel sweep on bodies
// (solve_nscd_step, BodyContactOperator in core/nscd/body_operator.h) on the generated pile
// of bench/fclib_nscd (cube_lattice.h), without Siconos.
//
//   nscd_body_sweep NX NY NZ [--sweeps S (200)] [--repeat R (5: best wall time of R)]
//                   [--seed N (1)] [--mu M (0.5)] [--impulses FILE]
//
// Per row: the Siconos error and Σ|r| at the end, the time, the contact states in the
// last sweep and the local slide Newton steps per contact update. Rows: method gauss_seidel, forward order with the check schedule of the Siconos error
// (natural_map; fix nscd/polyhedra's settings, grain_solver_defaults), and the random order
// with the core's default measure (fclib_nscd's row "on bodies"). Tolerance 0: every solve
// makes exactly S sweeps, so the time per contact update is time / (S × contacts) (the
// Siconos error checks of the schedule included). The Siconos error and Σ|r|, printed in
// full, tell whether a change of the sweep changed the result;
// --impulses writes the forward row's impulses (one contact a line, %.17g) for a closer
// comparison.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/nscd/nscd_solver.h"
#include "cube_lattice.h"

using namespace wiregrain;

namespace {

struct Row {
  const char* name;
  SweepOrder order;
  ConvergenceMeasure measure;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr,
                 "usage: nscd_body_sweep NX NY NZ [--sweeps S] [--repeat R] [--seed N] "
                 "[--mu M] [--impulses FILE]\n");
    return 2;
  }
  const int nx = std::atoi(argv[1]), ny = std::atoi(argv[2]), nz = std::atoi(argv[3]);
  int sweeps = 200, repeat = 5;
  std::uint64_t seed = 1;
  double mu = 0.5;
  std::string impulses_path;
  for (int k = 4; k + 1 < argc; k += 2) {
    const std::string flag = argv[k];
    const char* value = argv[k + 1];
    if (flag == "--sweeps") sweeps = std::max(1, std::atoi(value));
    else if (flag == "--repeat") repeat = std::max(1, std::atoi(value));
    else if (flag == "--seed") seed = std::strtoull(value, nullptr, 10);
    else if (flag == "--mu") mu = std::atof(value);
    else if (flag == "--impulses") impulses_path = value;
    else {
      std::fprintf(stderr, "nscd_body_sweep: unknown option %s\n", flag.c_str());
      return 2;
    }
  }
  if (nx < 1 || ny < 1 || nz < 1) {
    std::fprintf(stderr, "nscd_body_sweep: NX, NY, NZ must be >= 1\n");
    return 2;
  }
  const NscdStep step = wiregrain_bench::cube_lattice(nx, ny, nz, seed, mu, true);
  const int n = static_cast<int>(step.contacts.size());
  std::printf("pile %dx%dx%d: %zu bodies, %d contacts; %d sweeps, best of %d\n", nx, ny, nz,
              step.bodies.size(), n, sweeps, repeat);
  std::printf("%-44s %16s %24s %10s %12s %10s %18s %8s\n", "sweep", "siconos error", "sum |r|",
              "time [s]", "us/sweep", "ns/update", "open/stick/slide", "newton");
  const Row rows[] = {
      {"forward, natural map (fix, gauss_seidel)", SweepOrder::forward, ConvergenceMeasure::natural_map},
      {"random, increment then natural map", SweepOrder::random,
       ConvergenceMeasure::increment_then_natural_map}};
  for (const Row& row : rows) {
    SolverSettings options;
    options.tolerance = 0.0;
    options.max_iterations = sweeps;
    options.order = row.order;
    options.measure = row.measure;
    options.method = SolverMethod::gauss_seidel;
    options.seed = seed;
    double seconds = 1e300;
    NscdStepResult result;
    for (int k = 0; k < repeat; ++k) {
      const auto start = std::chrono::steady_clock::now();
      result = solve_nscd_step(step, options);
      seconds = std::min(
          seconds, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    double sum = 0.0;
    for (const Eigen::Vector3d& r : result.contacts.impulses) sum += r.cwiseAbs().sum();
    const int done = result.contacts.report.iterations;
    const NscdReport& report = result.contacts.report;
    const std::string states = std::to_string(report.open) + "/" + std::to_string(report.stick) +
                               "/" + std::to_string(report.slide);
    std::printf("%-44s %16.10e %24.17g %10.4f %12.2f %10.1f %18s %8.2f\n", row.name,
                report.siconos_error, sum, seconds, 1e6 * seconds / done,
                1e9 * seconds / (static_cast<double>(done) * n), states.c_str(),
                static_cast<double>(report.newton_iterations) / (static_cast<double>(done) * n));
    if (row.order == SweepOrder::forward && !impulses_path.empty()) {
      std::FILE* out = std::fopen(impulses_path.c_str(), "w");
      if (out == nullptr) {
        std::fprintf(stderr, "nscd_body_sweep: cannot write %s\n", impulses_path.c_str());
        return 1;
      }
      for (const Eigen::Vector3d& r : result.contacts.impulses) {
        std::fprintf(out, "%.17g %.17g %.17g\n", r[0], r[1], r[2]);
      }
      std::fclose(out);
    }
  }
  return 0;
}
