// nscd_stack: a stack of boxes at rest on a frictional floor, step after step with the
// core grain step; the loads at every interface against the weights above (box_stack.h).
//
//   nscd_stack [--n N] [--steps S] [--method gauss_seidel|subspace] [--alternate]
//              [--tol T] [--max-iter K] [--order forward|random|alternating]
//              [--measure natural_map|increment_then_natural_map] [--mu MU] [--verbose]
//
// Printed per run: the worst relative load error over all steps and interfaces, the steps
// where it exceeds 1e-4, steps that hit the sweep cap, sweeps (mean, max), stick solves,
// the largest speed of a box, wall time. bench/nscd_stacks.py runs the table of
// docs/benchmarks.md, "Stacks at rest".
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "box_stack.h"

using namespace wiregrain;

namespace {

[[noreturn]] void usage(const char* what) {
  std::fprintf(stderr, "nscd_stack: %s\n", what);
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  int n = 20, steps = 1000;
  bool alternate = false, verbose = false;
  wiregrain::GrainStepOptions options;
  options.friction = 0.5;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> const char* {
      if (i + 1 >= argc) usage(("missing value after " + arg).c_str());
      return argv[++i];
    };
    if (arg == "--n") n = std::atoi(value());
    else if (arg == "--steps") steps = std::atoi(value());
    else if (arg == "--alternate") alternate = true;
    else if (arg == "--verbose") verbose = true;
    else if (arg == "--tol") options.solver.tolerance = std::atof(value());
    else if (arg == "--max-iter") options.solver.max_iterations = std::atoi(value());
    else if (arg == "--mu") options.friction = std::atof(value());
    else if (arg == "--method") {
      const std::string m = value();
      if (m == "gauss_seidel") options.solver.method = SolverMethod::gauss_seidel;
      else if (m == "subspace") options.solver.method = SolverMethod::subspace;
      else usage(("unknown method " + m).c_str());
    } else if (arg == "--order") {
      const std::string o = value();
      if (o == "forward") options.solver.order = SweepOrder::forward;
      else if (o == "random") options.solver.order = SweepOrder::random;
      else if (o == "alternating") options.solver.order = SweepOrder::alternating;
      else usage(("unknown order " + o).c_str());
    } else if (arg == "--measure") {
      const std::string m = value();
      if (m == "natural_map") options.solver.measure = ConvergenceMeasure::natural_map;
      else if (m == "increment_then_natural_map") options.solver.measure = ConvergenceMeasure::increment_then_natural_map;
      else usage(("unknown measure " + m).c_str());
    } else usage(("unknown argument " + arg).c_str());
  }
  if (n < 1 || steps < 1) usage("--n and --steps must be >= 1");
  const auto start = std::chrono::steady_clock::now();
  const wiregrain_bench::BoxStackRun r = wiregrain_bench::run_box_stack(n, alternate, steps, options, verbose);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("n %d%s steps %d tol %g: worst load error %.3e, steps over 1e-4 %d, capped %d, "
              "sweeps mean %.1f max %d, stick solves %ld (kept %ld), largest speed %.2e, %.3f s\n",
              n, alternate ? " (alternating)" : "", steps, options.solver.tolerance, r.worst_load_error,
              r.steps_over_1e4, r.capped_steps, double(r.sweeps) / steps, r.max_sweeps, r.subspace_solves,
              r.subspace_kept, r.largest_speed, seconds);
  return 0;
}
