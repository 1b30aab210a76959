// fclib_nscd: wiregrain's NSCD Gauss–Seidel (core/nscd_solver.h, solve_reduced) against
// Siconos numerics' fc3d_nsgs on the same frictional contact problem u = W r + q.
//
//   fclib_nscd solve FILE [options]     an FCLib local problem (FILE.hdf5, fclib_read_local)
//                                       or a problem written by fix nscd/polyhedra's
//                                       write_problems (text, core/reduced_problem_io.h)
//   fclib_nscd convert IN.txt OUT.hdf5  such a text problem as an FCLib file (compressed
//                                       rows), read back and compared entry by entry
//   fclib_nscd generate KIND ARGS [options]     a problem built here, no input file:
//       pile NX NY NZ     NX×NY columns of NZ unit cubes on a frictional ground, in face
//                         contact with their neighbours (4 points per face), random
//                         start velocities of 0.1 g h, small random gaps
//       column N          one column of N cubes at rest
//       random NB NC      NB random bodies, NC random contacts (random frames and arms)
//   fclib_nscd write OUT.hdf5 KIND ARGS [options]   write that problem as an FCLib file
//                         (bench/fclib_io.h), read it back and check the round trip
// options: --tol T (1e-4: Siconos' default tolerance), --siconos-max-iter N (1000, its
//          default), --max-iter N (ours, 100000), --repeat R (3: best wall time of R),
//          --seed S (1), --mu M (0.5, generated problems)
//
// For each solver: sweeps, the Siconos error of its impulses (fc3d_compute_error's
// measure as computed in the core, and as computed by the Siconos library itself),
// wall time. Siconos runs first with its default options (NSGS, local solver
// NSN_GP_HYBRID, light error then full check); ours then runs until its Siconos error is
// at most Siconos' final error (the tolerance if Siconos converged, what it reached at
// its iteration cap otherwise), in the forward order (Siconos' order), the alternating
// order and with the core defaults (random order), then checking the Siconos error after
// every sweep in the forward order (fix nscd/polyhedra's default) and the random order;
// for generated problems also on the
// bodies themselves (solve_nscd_step, W never formed); the ratio is our time over
// Siconos'.
// Debian's Siconos 4.4 has no FCLib interface: the Siconos problem is built here from what
// libfclib reads (W as a sparse block matrix of 3×3 blocks).
#include <FrictionContactProblem.h>
#include <Friction_cst.h>
#include <NonSmoothDrivers.h>
#include <NumericsMatrix.h>
#include <SolverOptions.h>
#include <SparseBlockMatrix.h>
#include <fc3d_compute_error.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/nscd/nscd_solver.h"
#include "core/nscd/reduced_problem_io.h"
#include "cube_lattice.h"
#include "fclib_io.h"

using namespace wiregrain;
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

struct Options {
  double tolerance = 1e-4;
  int siconos_max_iterations = 1000;
  int max_iterations = 100000;
  int repeat = 3;
  std::uint64_t seed = 1;
  double mu = 0.5;
};

// ---------------------------------------------------------------------------------------
// Generated problems (cube_lattice.h; random bodies below), assembled into the reduced
// problem of one Moreau–Jean step.

NscdStep random_bodies(int bodies, int contacts, const Options& options) {
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), positive(0.5, 2.0);
  NscdStep step;
  step.time_step = 1e-3;
  for (int b = 0; b < bodies; ++b) {
    NscdBody body;
    body.inverse_mass = positive(rng);
    Matrix3d A;
    for (int i = 0; i < 9; ++i) A(i / 3, i % 3) = unit(rng);
    body.inverse_inertia = A * A.transpose() + 0.5 * Matrix3d::Identity();
    body.velocity_begin = 1e-3 * Vector3d(unit(rng), unit(rng), unit(rng));
    body.velocity_free = body.velocity_begin + Vector3d(0.0, 0.0, -1e-3);
    step.bodies.push_back(body);
  }
  for (int c = 0; c < contacts; ++c) {
    NscdContact contact;
    contact.body_b = static_cast<int>(rng() % bodies);
    do {
      contact.body_a = static_cast<int>(rng() % (bodies + 1)) - 1;
    } while (contact.body_a == contact.body_b);
    const Matrix3d frame = contact_frame(Vector3d(unit(rng), unit(rng), unit(rng)));
    contact.jacobian_b = contact_jacobian(frame, 0.5 * Vector3d(unit(rng), unit(rng), unit(rng)), 1.0);
    if (contact.body_a >= 0) {
      contact.jacobian_a =
          contact_jacobian(frame, 0.5 * Vector3d(unit(rng), unit(rng), unit(rng)), -1.0);
    }
    contact.friction = options.mu;
    contact.gap = 1e-6 * unit(rng);
    step.contacts.push_back(contact);
  }
  return step;
}

// Parses KIND ARGS at argv[next...]; returns the problem, a label and the step it was
// assembled from.
ReducedProblem generate(int argc, char** argv, int& next, const Options& options,
                        std::string& label, NscdStep& step) {
  if (next >= argc) throw std::runtime_error("missing problem kind (pile, column, random)");
  const std::string kind = argv[next++];
  auto integer = [&](const char* what) {
    if (next >= argc) throw std::runtime_error(std::string("missing ") + what);
    const int value = std::atoi(argv[next++]);
    if (value < 1) throw std::runtime_error(std::string(what) + " must be >= 1");
    return value;
  };
  if (kind == "pile") {
    const int nx = integer("NX"), ny = integer("NY"), nz = integer("NZ");
    label = "pile " + std::to_string(nx) + "x" + std::to_string(ny) + "x" + std::to_string(nz);
    step = wiregrain_bench::cube_lattice(nx, ny, nz, options.seed, options.mu, true);
    return assemble_reduced(step);
  }
  if (kind == "column") {
    const int n = integer("N");
    label = "column of " + std::to_string(n) + " cubes";
    step = wiregrain_bench::cube_lattice(1, 1, n, options.seed, options.mu, false);
    return assemble_reduced(step);
  }
  if (kind == "random") {
    const int nb = integer("NB"), nc = integer("NC");
    label = "random " + std::to_string(nb) + " bodies";
    step = random_bodies(nb, nc, options);
    return assemble_reduced(step);
  }
  throw std::runtime_error("unknown problem kind '" + kind + "' (pile, column, random)");
}

// ---------------------------------------------------------------------------------------
// Siconos.

// The Siconos problem: W as a sparse block matrix (3×3 blocks, column-major), q, μ.
struct SiconosProblem {
  FrictionContactProblem* problem = nullptr;
  explicit SiconosProblem(const ReducedProblem& reduced) {
    const int n = reduced.contact_count();
    SparseBlockStructuredMatrix* sbm = SBM_new();
    const long blocks = reduced.W.stored_blocks();
    sbm->nbblocks = static_cast<unsigned>(blocks);
    sbm->blocknumber0 = sbm->blocknumber1 = static_cast<unsigned>(n);
    sbm->blocksize0 = static_cast<unsigned*>(std::malloc(sizeof(unsigned) * n));
    sbm->blocksize1 = static_cast<unsigned*>(std::malloc(sizeof(unsigned) * n));
    for (int i = 0; i < n; ++i) sbm->blocksize0[i] = sbm->blocksize1[i] = 3u * (i + 1);
    sbm->filled1 = static_cast<size_t>(n) + 1;
    sbm->filled2 = static_cast<size_t>(blocks);
    sbm->index1_data = static_cast<size_t*>(std::malloc(sizeof(size_t) * (n + 1)));
    sbm->index2_data = static_cast<size_t*>(std::malloc(sizeof(size_t) * blocks));
    sbm->block = static_cast<double**>(std::malloc(sizeof(double*) * blocks));
    size_t k = 0;
    for (int i = 0; i < n; ++i) {
      sbm->index1_data[i] = k;
      for (const BlockSparseMatrix3::Entry& entry : reduced.W.row(i)) {
        sbm->index2_data[k] = static_cast<size_t>(entry.column);
        sbm->block[k] = static_cast<double*>(std::malloc(9 * sizeof(double)));
        Eigen::Map<Matrix3d>(sbm->block[k]) = entry.block;  // column-major, as Siconos
        ++k;
      }
    }
    sbm->index1_data[n] = k;
    NumericsMatrix* M = NM_new_SBM(3 * n, 3 * n, sbm);
    double* q = static_cast<double*>(std::malloc(sizeof(double) * 3 * n));
    double* mu = static_cast<double*>(std::malloc(sizeof(double) * n));
    std::copy(reduced.q.data(), reduced.q.data() + 3 * n, q);
    std::copy(reduced.mu.begin(), reduced.mu.end(), mu);
    problem = frictionContactProblem_new_with_data(3, n, M, q, mu);
  }
  ~SiconosProblem() { frictionContactProblem_free(problem); }
  SiconosProblem(const SiconosProblem&) = delete;
  SiconosProblem& operator=(const SiconosProblem&) = delete;

  // Siconos' own fc3d_compute_error, called as fc3d_nsgs calls it (norm = ‖q‖; 4.4
  // divides by max(norm, ‖r‖, ‖u‖)).
  double error(const std::vector<Vector3d>& impulses) const {
    const int n = problem->numberOfContacts;
    std::vector<double> r(3 * n), u(3 * n);
    for (int c = 0; c < n; ++c) {
      for (int a = 0; a < 3; ++a) r[3 * c + a] = impulses[c][a];
    }
    SolverOptions* options = solver_options_create(SICONOS_FRICTION_3D_NSGS);
    double norm_q = 0.0;
    for (int i = 0; i < 3 * n; ++i) norm_q += problem->q[i] * problem->q[i];
    double value = 0.0;
    fc3d_compute_error(problem, r.data(), u.data(), 0.0, options, std::sqrt(norm_q), &value);
    solver_options_delete(options);
    return value;
  }
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Run {
  std::string name;
  int iterations = 0;
  double error = 0.0;          // our implementation of the measure
  double library_error = 0.0;  // Siconos' fc3d_compute_error
  double seconds = 0.0;
  bool converged = true;
  std::vector<Vector3d> impulses;
};

Run run_siconos(const ReducedProblem& reduced, SiconosProblem& siconos, const Options& options) {
  Run run;
  run.name = "siconos fc3d_nsgs (defaults)";
  run.seconds = 1e300;
  const int n = reduced.contact_count();
  for (int k = 0; k < options.repeat; ++k) {
    std::vector<double> r(3 * n, 0.0), u(3 * n, 0.0);
    SolverOptions* solver = solver_options_create(SICONOS_FRICTION_3D_NSGS);
    solver->dparam[SICONOS_DPARAM_TOL] = options.tolerance;
    solver->iparam[SICONOS_IPARAM_MAX_ITER] = options.siconos_max_iterations;
    const auto start = std::chrono::steady_clock::now();
    const int info = fc3d_driver(siconos.problem, r.data(), u.data(), solver);
    run.seconds = std::min(run.seconds, seconds_since(start));
    run.iterations = solver->iparam[SICONOS_IPARAM_ITER_DONE];
    run.converged = info == 0;
    solver_options_delete(solver);
    run.impulses.assign(n, Vector3d::Zero());
    for (int c = 0; c < n; ++c) run.impulses[c] = Vector3d(r[3 * c], r[3 * c + 1], r[3 * c + 2]);
  }
  run.error = siconos_error(reduced, run.impulses);
  run.library_error = siconos.error(run.impulses);
  return run;
}

Run run_ours(const ReducedProblem& reduced, SiconosProblem& siconos, const Options& options,
             SweepOrder order, double tolerance, const std::string& name,
             ConvergenceMeasure measure = ConvergenceMeasure::increment_then_natural_map,
             SolverMethod method = SolverMethod::gauss_seidel) {
  Run run;
  run.name = name;
  run.seconds = 1e300;
  SolverSettings nscd;
  nscd.tolerance = tolerance;
  nscd.max_iterations = options.max_iterations;
  nscd.order = order;
  nscd.seed = options.seed;
  nscd.measure = measure;
  nscd.method = method;
  for (int k = 0; k < options.repeat; ++k) {
    const auto start = std::chrono::steady_clock::now();
    ContactSolution solution = solve_reduced(reduced, nscd);
    run.seconds = std::min(run.seconds, seconds_since(start));
    run.iterations = solution.report.iterations;
    run.converged = !solution.report.hit_iteration_cap;
    run.error = solution.report.siconos_error;
    run.impulses = std::move(solution.impulses);
  }
  run.library_error = siconos.error(run.impulses);
  return run;
}

// The same solve on the bodies (solve_nscd_step: W never formed, body velocities kept up
// to date).
Run run_bodies(const NscdStep& step, SiconosProblem& siconos, const Options& options,
               double tolerance, SweepOrder order, ConvergenceMeasure measure,
               const std::string& name) {
  Run run;
  run.name = name;
  run.seconds = 1e300;
  SolverSettings nscd;
  nscd.tolerance = tolerance;
  nscd.max_iterations = options.max_iterations;
  nscd.seed = options.seed;
  nscd.order = order;
  nscd.measure = measure;
  nscd.method = SolverMethod::gauss_seidel;
  for (int k = 0; k < options.repeat; ++k) {
    const auto start = std::chrono::steady_clock::now();
    NscdStepResult result = solve_nscd_step(step, nscd);
    run.seconds = std::min(run.seconds, seconds_since(start));
    run.iterations = result.contacts.report.iterations;
    run.converged = !result.contacts.report.hit_iteration_cap;
    run.error = result.contacts.report.siconos_error;
    run.impulses = std::move(result.contacts.impulses);
  }
  run.library_error = siconos.error(run.impulses);
  return run;
}

void compare(const ReducedProblem& reduced, const std::string& label, const Options& options,
             const NscdStep* step = nullptr) {
  std::printf("problem: %s: %d contacts, %ld W blocks, |q| = %.6g\n", label.c_str(),
              reduced.contact_count(), reduced.W.stored_blocks(), reduced.q.norm());
  SiconosProblem siconos(reduced);
  const Run reference = run_siconos(reduced, siconos, options);
  // Ours must reach Siconos' final error (below the tolerance when Siconos converged,
  // what it reached at its iteration cap otherwise).
  const double target = std::max(reference.error, 1e-300);
  std::vector<Run> runs = {reference};
  runs.push_back(run_ours(reduced, siconos, options, SweepOrder::forward, target,
                          "wiregrain nscd, forward order"));
  runs.push_back(run_ours(reduced, siconos, options, SweepOrder::alternating, target,
                          "wiregrain nscd, alternating order"));
  runs.push_back(run_ours(reduced, siconos, options, SweepOrder::random, target,
                          "wiregrain nscd, random order"));
  // the Siconos error checked after every sweep; forward is what fix nscd/polyhedra does
  // by default (its contacts listed top-down)
  runs.push_back(run_ours(reduced, siconos, options, SweepOrder::forward, target,
                          "wiregrain nscd, forward, natural map", ConvergenceMeasure::natural_map));
  runs.push_back(run_ours(reduced, siconos, options, SweepOrder::random, target,
                          "wiregrain nscd, random, natural map", ConvergenceMeasure::natural_map));
  // with the subspace correction (the fix's default method)
  runs.push_back(run_ours(reduced, siconos, options, SweepOrder::forward, target,
                          "wiregrain nscd, forward, subspace (fix)", ConvergenceMeasure::natural_map,
                          SolverMethod::subspace));
  if (step != nullptr) {
    runs.push_back(run_bodies(*step, siconos, options, target, SweepOrder::random,
                              ConvergenceMeasure::increment_then_natural_map,
                              "wiregrain nscd on bodies, random order"));
    // fix nscd/polyhedra's sweep and error-check schedule (method gauss_seidel)
    runs.push_back(run_bodies(*step, siconos, options, target, SweepOrder::forward,
                              ConvergenceMeasure::natural_map,
                              "wiregrain nscd on bodies, forward (fix)"));
  }
  std::printf("tolerance %.3g; our target: Siconos' final error %.3e; best of %d runs\n",
              options.tolerance, target, options.repeat);
  std::printf("%-40s %8s %14s %14s %12s %12s %8s\n", "solver", "sweeps", "siconos error",
              "(library)", "time [s]", "us/sweep", "ratio");
  for (const Run& run : runs) {
    std::printf("%-40s %8d %14.4e %14.4e %12.6f %12.2f %8.3f%s\n", run.name.c_str(),
                run.iterations, run.error, run.library_error, run.seconds,
                1e6 * run.seconds / std::max(run.iterations, 1), run.seconds / reference.seconds,
                run.converged ? "" : "  (iteration cap)");
  }
}

// A problem file: FCLib HDF5, or the text format of fix nscd/polyhedra (by its first line).
ReducedProblem read_problem(const std::string& path, std::string& title) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::string first;
  std::getline(in, first);
  if (first.rfind("wiregrain_reduced_problem", 0) == 0) {
    in.seekg(0);
    return read_reduced_problem(in, &title);
  }
  bench::FclibInfo info;
  ReducedProblem problem = bench::read_fclib_local(path, &info);
  title = info.title;
  return problem;
}

// Largest difference of W entries, q and μ between two problems (1 if b has extra blocks).
double difference(const ReducedProblem& a, const ReducedProblem& b) {
  if (a.contact_count() != b.contact_count() || b.W.stored_blocks() > a.W.stored_blocks()) return 1.0;
  double d = a.contact_count() ? (a.q - b.q).cwiseAbs().maxCoeff() : 0.0;
  for (int c = 0; c < a.contact_count(); ++c) {
    for (const BlockSparseMatrix3::Entry& entry : a.W.row(c)) {
      const Matrix3d* read = b.W.find(c, entry.column);
      const Matrix3d stored = read != nullptr ? *read : Matrix3d::Zero();
      d = std::max(d, (stored - entry.block).cwiseAbs().maxCoeff());
    }
    d = std::max(d, std::abs(a.mu[c] - b.mu[c]));
  }
  return d;
}

void usage() {
  std::fprintf(stderr,
               "usage: fclib_nscd solve FILE.hdf5|FILE.txt [options]\n"
               "       fclib_nscd convert IN.txt OUT.hdf5\n"
               "       fclib_nscd generate pile NX NY NZ | column N | random NB NC [options]\n"
               "       fclib_nscd write OUT.hdf5 pile NX NY NZ | column N | random NB NC "
               "[options]\n"
               "options: --tol T --siconos-max-iter N --max-iter N --repeat R --seed S --mu M\n");
}

Options parse_options(int argc, char** argv, int first) {
  Options options;
  for (int k = first; k < argc; ++k) {
    const std::string flag = argv[k];
    if (k + 1 >= argc) throw std::runtime_error("missing value after " + flag);
    const char* value = argv[++k];
    if (flag == "--tol") options.tolerance = std::atof(value);
    else if (flag == "--siconos-max-iter") options.siconos_max_iterations = std::atoi(value);
    else if (flag == "--max-iter") options.max_iterations = std::atoi(value);
    else if (flag == "--repeat") options.repeat = std::max(1, std::atoi(value));
    else if (flag == "--seed") options.seed = std::strtoull(value, nullptr, 10);
    else if (flag == "--mu") options.mu = std::atof(value);
    else throw std::runtime_error("unknown option " + flag);
  }
  return options;
}

// Index of the first option flag after the positional arguments of a generated problem.
int first_flag(int argc, char** argv, int from) {
  while (from < argc && std::strncmp(argv[from], "--", 2) != 0) ++from;
  return from;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    usage();
    return 2;
  }
  try {
    const std::string mode = argv[1];
    if (mode == "solve") {
      const Options options = parse_options(argc, argv, 3);
      std::string title;
      const ReducedProblem problem = read_problem(argv[2], title);
      compare(problem, std::string(argv[2]) + (title.empty() ? "" : " (" + title + ")"), options);
    } else if (mode == "convert") {
      if (argc != 4) {
        usage();
        return 2;
      }
      std::string title;
      std::ifstream in(argv[2]);
      if (!in) throw std::runtime_error(std::string("cannot open ") + argv[2]);
      const ReducedProblem problem = read_reduced_problem(in, &title);
      const bench::FclibInfo info{title,
                                  "reduced problem u = W r + q of one Moreau-Jean step of fix "
                                  "nscd/polyhedra (wiregrain)",
                                  "W symmetric positive semi-definite"};
      bench::write_fclib_local(argv[3], problem, info);
      const double d = difference(problem, bench::read_fclib_local(argv[3]));
      std::printf("wrote %s: %d contacts, %ld W blocks; read back, max difference %.3g\n", argv[3],
                  problem.contact_count(), problem.W.stored_blocks(), d);
      if (d != 0.0) return 1;
    } else if (mode == "generate") {
      const Options options = parse_options(argc, argv, first_flag(argc, argv, 2));
      int next = 2;
      std::string label;
      NscdStep step;
      const ReducedProblem problem = generate(argc, argv, next, options, label, step);
      compare(problem, label, options, &step);
    } else if (mode == "write") {
      const std::string path = argv[2];
      const Options options = parse_options(argc, argv, first_flag(argc, argv, 3));
      int next = 3;
      std::string label;
      NscdStep step;
      const ReducedProblem problem = generate(argc, argv, next, options, label, step);
      const bench::FclibInfo info{"wiregrain " + label,
                                  "reduced problem of one Moreau-Jean step (theta = 1, e = 0, "
                                  "h = 1e-3)",
                                  "W symmetric positive semi-definite"};
      // Round trip in the three layouts libfclib knows, for the problem and for a small
      // non-symmetric W (which a row/column mix-up would not survive); the file keeps the
      // problem in compressed rows.
      ReducedProblem skew;
      skew.W = BlockSparseMatrix3(3);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          Matrix3d block;
          for (int e = 0; e < 9; ++e) block(e / 3, e % 3) = 1.0 + i + 10 * j + 100 * e;
          if (i != 1 || j != 2) skew.W.add(i, j, block);  // one missing block
        }
      }
      skew.q = Eigen::VectorXd::LinSpaced(9, -1.0, 1.0);
      skew.mu = {0.1, 0.2, 0.3};
      const std::pair<bench::FclibMatrixFormat, const char*> formats[] = {
          {bench::FclibMatrixFormat::triplets, "triplets"},
          {bench::FclibMatrixFormat::compressed_columns, "compressed columns"},
          {bench::FclibMatrixFormat::compressed_rows, "compressed rows"}};
      for (const auto& [format, name] : formats) {
        bench::write_fclib_local(path, skew, info, format);
        const double skew_difference = difference(skew, bench::read_fclib_local(path));
        bench::write_fclib_local(path, problem, info, format);
        const double problem_difference = difference(problem, bench::read_fclib_local(path));
        std::printf("wrote %s (%s): %s, %d contacts; read back, max difference %.3g "
                    "(non-symmetric check: %.3g)\n",
                    path.c_str(), name, label.c_str(), problem.contact_count(),
                    problem_difference, skew_difference);
        if (problem_difference != 0.0 || skew_difference != 0.0) return 1;
      }
    } else {
      usage();
      return 2;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fclib_nscd: %s\n", e.what());
    return 1;
  }
  return 0;
}
