// Our slide-case solver of the local Coulomb problem against GSL's 1-D root finders on the
// same scalar equation g(φ) = v(φ) × t(φ) (core/nscd/coulomb_local.h).
//
// The paper solves the slide case with GSL's Newton solver; our core reduces it to g(φ) = 0
// and runs its own Newton iteration from a guess (slide_newton_unbracketed, step limited to
// 0.5 rad) with a scan of g at 24 angles and a root search in every sign change as
// fallback. This tool measures, on one set of slide problems:
//   from a guess    ours (Newton, clamped) | GSL fdfsolver newton, secant, steffenson
//                   (same start, same stop |Δφ| ≤ 1e-13 rad, at most 30 iterations);
//   in a bracket    safeguarded Newton–bisection (rtsafe, below) | the core's
//                   slide_root_in_bracket (GSL brent) | GSL brent with its solver
//                   allocated once, on every sign change of the 24-angle scan that
//                   the fallback would refine;
//   whole solve     solve_coulomb_local (stick test + Newton + fallback), for scale.
// Two start sets: cold (the direction of the rejected stick impulse −W⁻¹q, what
// solve_coulomb_local uses without a guess) and warm (our solution direction + a normal
// perturbation, as a Gauss–Seidel sweep passes the previous impulse).
//
// Problems: W = Σ_bodies H_b M_b⁻¹ H_bᵀ of two rigid boxes (random sides, unit density,
// random orientation, contact point on the box surface; one body in four is a fixed wall),
// H_b = [I, −[ℓ_b]×] mapping (v, ω) to the contact point velocity v + ω × ℓ_b, so
//     W = Σ_b ( I/m_b − [ℓ_b]× I_b⁻¹ [ℓ_b]× )                     (contact frame = world frame),
// q_n ∈ −[0.01, 1], |q_t| = |q_n| · s with s log-uniform in [0.05, 20], random direction,
// μ ∈ {0.1, 0.3, 0.5, 1.0}; only problems whose solution (solve_coulomb_local) is a slide
// are kept.
//
// "solved" = converged within the iteration limit to φ with |g| ≤ 1e-12 · scale and the
// slide admissible (a > 0, λ ≥ 0) — SlideEquation::is_root and ::admissible. "same root" =
// within 1e-8 rad of our solve_coulomb_local root. Residual: the natural-map residual
// ‖F(r, u)‖ = ‖r − proj_K(r − û)‖ (natural_map_residual, De Saxcé's û) of r = r_n c(φ),
// u = W r + q, divided by ‖r‖ + ‖q‖ (the map mixes impulse and velocity), largest over the
// solved problems. ns per solve: best of --repeat timed passes over the whole set.
//
// Usage: local_slide_gsl [--count N per μ] [--seed S] [--repeat R] [--perturbation RAD]
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "core/nscd/coulomb_local.h"

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using wiregrain::SlideEquation;

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;
constexpr int kMaxNewtonIterations = 30;  // as solve_coulomb_local's first stage
constexpr int kScanSamples = 24;          // as solve_coulomb_local's scan
constexpr double kStepTolerance = 1e-13;  // rad, as slide_newton_unbracketed

double wrap_angle(double phi) {
  phi = std::remainder(phi, kTwoPi);
  return phi <= -kPi ? phi + kTwoPi : phi;
}

Matrix3d skew(const Vector3d& v) {
  Matrix3d m;
  m << 0.0, -v[2], v[1], v[2], 0.0, -v[0], -v[1], v[0], 0.0;
  return m;
}

// A uniformly random rotation from a normalized Gaussian quaternion.
Matrix3d random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Eigen::Quaterniond quaternion(normal(rng), normal(rng), normal(rng), normal(rng));
  quaternion.normalize();
  return quaternion.toRotationMatrix();
}

// One body's term I/m − [ℓ]× I⁻¹ [ℓ]× of the contact Delassus block: a box of sides
// s ∈ L·[0.3, 1]³, L log-uniform in [0.5, 2], unit density (m = s1 s2 s3,
// I_1 = m (s2² + s3²)/12, ...), random orientation R, contact point on a random face.
Matrix3d random_box_block(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double size = std::exp(std::log(0.5) + unit(rng) * std::log(4.0));
  Vector3d side;
  for (int k = 0; k < 3; ++k) side[k] = size * (0.3 + 0.7 * unit(rng));
  const double mass = side.prod();
  const Vector3d principal_inertia(mass * (side[1] * side[1] + side[2] * side[2]) / 12.0,
                                   mass * (side[0] * side[0] + side[2] * side[2]) / 12.0,
                                   mass * (side[0] * side[0] + side[1] * side[1]) / 12.0);
  Vector3d lever_body;
  for (int k = 0; k < 3; ++k) lever_body[k] = side[k] * (unit(rng) - 0.5);
  const int face = static_cast<int>(unit(rng) * 3.0) % 3;
  lever_body[face] = (unit(rng) < 0.5 ? -0.5 : 0.5) * side[face];
  const Matrix3d rotation = random_rotation(rng);
  const Matrix3d inverse_inertia =
      rotation * principal_inertia.cwiseInverse().asDiagonal() * rotation.transpose();
  const Matrix3d lever = skew(rotation * lever_body);
  return Matrix3d::Identity() / mass - lever * inverse_inertia * lever;
}

struct SlideProblem {
  Matrix3d W;
  Vector3d q;
  double mu = 0.0;
  double phi_cold = 0.0;      // direction of the rejected stick impulse −W⁻¹q
  double phi_solution = 0.0;  // our solve_coulomb_local root, in (−π, π]
  double r_n = 0.0;           // our normal impulse
  double phi_warm = 0.0;      // phi_solution + perturbation
  bool ours_needed_scan = false;
};

std::vector<SlideProblem> make_problems(int count_per_mu, double perturbation,
                                        std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal;
  std::vector<SlideProblem> problems;
  for (double mu : {0.1, 0.3, 0.5, 1.0}) {
    int kept = 0;
    while (kept < count_per_mu) {
      SlideProblem problem;
      problem.mu = mu;
      problem.W = random_box_block(rng);
      if (unit(rng) >= 0.25) problem.W += random_box_block(rng);  // else: a fixed wall
      problem.W = 0.5 * (problem.W + problem.W.transpose());
      const double q_n = -(0.01 + 0.99 * unit(rng));
      const double tangential = -q_n * std::exp(std::log(0.05) + unit(rng) * std::log(400.0));
      const double angle = kTwoPi * unit(rng);
      problem.q = Vector3d(q_n, tangential * std::cos(angle), tangential * std::sin(angle));
      const wiregrain::LocalDelassus delassus(problem.W);
      const wiregrain::LocalSolution solution = wiregrain::solve_coulomb_local(delassus, problem.q, mu);
      if (solution.state != wiregrain::ContactState::slide) continue;
      const Vector3d stick = -(delassus.inverse() * problem.q);
      problem.phi_cold = std::atan2(stick[2], stick[1]);
      problem.phi_solution = std::atan2(solution.impulse[2], solution.impulse[1]);
      problem.r_n = solution.impulse[0];
      problem.phi_warm = problem.phi_solution + perturbation * normal(rng);
      problem.ours_needed_scan = solution.slide_method == wiregrain::SlideMethod::scan;
      problems.push_back(problem);
      ++kept;
    }
  }
  return problems;
}

// Natural-map residual of the slide state at φ, relative to ‖r‖ + ‖q‖.
double coulomb_residual(const SlideProblem& problem, const SlideEquation& equation, double phi) {
  const double r_n = -problem.q[0] / equation.at(phi).a;
  const Vector3d r(r_n, problem.mu * r_n * std::cos(phi), problem.mu * r_n * std::sin(phi));
  const Vector3d u = problem.W * r + problem.q;
  return wiregrain::natural_map_residual(r, u, problem.mu).norm() / (r.norm() + problem.q.norm());
}

// Outcome of one root-finder run.
struct RootResult {
  double phi = 0.0;
  int iterations = 0;
  bool converged = false;
};

// ---- GSL adapters: g and dg/dφ of SlideEquation through gsl_function(_fdf) ----
double gsl_slide_g(double phi, void* params) {
  return static_cast<const SlideEquation*>(params)->at(phi).g;
}
double gsl_slide_dg(double phi, void* params) {
  return static_cast<const SlideEquation*>(params)->at(phi).dg;
}
void gsl_slide_g_dg(double phi, void* params, double* g, double* dg) {
  const SlideEquation::Value value = static_cast<const SlideEquation*>(params)->at(phi);
  *g = value.g;
  *dg = value.dg;
}

// A GSL derivative-based solver (newton, secant, steffenson) from phi0: iterate until
// gsl_root_test_delta(φ_k, φ_{k−1}, 1e-13, 0) (|Δφ| < 1e-13 rad, our Newton's stop) or
// 30 iterations; a GSL error status (zero derivative, non-finite value) is a failure.
RootResult gsl_fdf_root(gsl_root_fdfsolver* solver, const SlideEquation& equation,
                        double phi0) {
  gsl_function_fdf function;
  function.f = &gsl_slide_g;
  function.df = &gsl_slide_dg;
  function.fdf = &gsl_slide_g_dg;
  function.params = const_cast<SlideEquation*>(&equation);
  RootResult result;
  if (gsl_root_fdfsolver_set(solver, &function, phi0) != GSL_SUCCESS) return result;
  double previous = phi0;
  for (int it = 0; it < kMaxNewtonIterations; ++it) {
    const int status = gsl_root_fdfsolver_iterate(solver);
    ++result.iterations;
    if (status != GSL_SUCCESS) return result;
    const double phi = gsl_root_fdfsolver_root(solver);
    if (!std::isfinite(phi)) return result;
    if (gsl_root_test_delta(phi, previous, kStepTolerance, 0.0) == GSL_SUCCESS) {
      result.phi = phi;
      result.converged = true;
      return result;
    }
    previous = phi;
  }
  result.phi = previous;
  return result;
}

RootResult ours_newton_root(const SlideEquation& equation, double phi0) {
  RootResult result;
  result.phi = phi0;
  result.converged = wiregrain::slide_newton_unbracketed(equation, result.phi, result.iterations,
                                                         kMaxNewtonIterations);
  return result;
}

// A bracket [lo, hi] of g from the 24-angle scan starting at phi0.
struct Bracket {
  const SlideProblem* problem;
  double lo, hi, g_lo;
};

std::vector<Bracket> scan_brackets(const std::vector<SlideProblem>& problems) {
  std::vector<Bracket> brackets;
  for (const SlideProblem& problem : problems) {
    const SlideEquation equation(problem.W, problem.q, problem.mu);
    double angle[kScanSamples + 1], g[kScanSamples + 1];
    for (int j = 0; j <= kScanSamples; ++j) {
      angle[j] = problem.phi_cold + kTwoPi * j / kScanSamples;
      g[j] = j < kScanSamples ? equation.at(angle[j]).g : g[0];
    }
    for (int j = 0; j < kScanSamples; ++j) {
      if (g[j] != 0.0 && g[j + 1] != 0.0 && (g[j] < 0.0) != (g[j + 1] < 0.0)) {
        brackets.push_back({&problem, angle[j], angle[j + 1], g[j]});
      }
    }
  }
  return brackets;
}

// GSL Brent (gsl_root_fsolver_brent) on [lo, hi]: iterate until
// gsl_root_test_interval(lo, hi, 1e-14, 0) (bracket width < 1e-14 rad, our rtsafe's step
// stop) or 200 iterations.
RootResult gsl_brent_root(gsl_root_fsolver* solver, const Bracket& bracket,
                          const SlideEquation& equation) {
  gsl_function function;
  function.function = &gsl_slide_g;
  function.params = const_cast<SlideEquation*>(&equation);
  RootResult result;
  if (gsl_root_fsolver_set(solver, &function, bracket.lo, bracket.hi) != GSL_SUCCESS) return result;
  for (int it = 0; it < 200; ++it) {
    const int status = gsl_root_fsolver_iterate(solver);
    ++result.iterations;
    if (status != GSL_SUCCESS) return result;
    result.phi = gsl_root_fsolver_root(solver);
    if (gsl_root_test_interval(gsl_root_fsolver_x_lower(solver), gsl_root_fsolver_x_upper(solver),
                               1e-14, 0.0) == GSL_SUCCESS) {
      result.converged = true;
      return result;
    }
  }
  return result;
}

// The bracketed search compared with the core's GSL Brent:
// safeguarded Newton–bisection ("rtsafe", Press et al., Numerical Recipes, Sec. 9.4) on
// [lo, hi] — a Newton step when it stays inside the bracket, else bisection — stopping
// when a step is below 1e-14 rad or the bracket below 1e-15 rad, at most 200 evaluations.
// Both stops lie at or below the round-off of φ ∈ [φ0, φ0 + 2π] (an ulp of 9 is 1.8e-15)
// and of g's Newton step, so about a quarter of the brackets end by bisecting to 1e-15.
RootResult rtsafe_root(const Bracket& bracket, const SlideEquation& equation) {
  RootResult result;
  double lo = bracket.lo, hi = bracket.hi, g_lo = bracket.g_lo;
  double phi = 0.5 * (lo + hi);
  result.converged = true;  // returns a point of the (shrunk) bracket in every case
  for (int it = 0; it < 200; ++it) {
    const SlideEquation::Value value = equation.at(phi);
    ++result.iterations;
    if (value.g == 0.0) break;
    if ((value.g < 0.0) == (g_lo < 0.0)) {
      lo = phi;
      g_lo = value.g;
    } else {
      hi = phi;
    }
    double next = phi - value.g / value.dg;
    if (!(value.dg != 0.0 && next > lo && next < hi)) next = 0.5 * (lo + hi);
    const double step = next - phi;
    phi = next;
    if (std::abs(step) <= 1e-14 || hi - lo <= 1e-15) break;
  }
  result.phi = phi;
  return result;
}

// The core's fallback (GSL Brent, a solver allocated per bracket).
RootResult core_bracket_root(const Bracket& bracket, const SlideEquation& equation) {
  RootResult result;
  result.phi = wiregrain::slide_root_in_bracket(equation, bracket.lo, bracket.hi,
                                                result.iterations);
  result.converged = true;
  return result;
}

struct Row {
  std::string group, method;
  long attempts = 0, solved = 0, same_root = 0;
  double mean_iterations = 0.0, ns_per_solve = 0.0, worst_residual = 0.0;
  double reference_ns = 0.0;  // ours in the same group
};

// Best-of-`repeat` wall time of `pass` (one pass over the whole set), in ns per item.
double time_per_item(const std::function<double()>& pass, long items, int repeat) {
  double best = 1e300;
  volatile double sink = 0.0;
  for (int k = 0; k < repeat; ++k) {
    const auto start = std::chrono::steady_clock::now();
    sink = sink + pass();
    const auto stop = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double, std::nano>(stop - start).count());
  }
  return best / static_cast<double>(items);
}

// One "from a guess" row: `root(equation, phi0)` on every problem.
Row measure_from_guess(const std::string& group, const std::string& method,
                       const std::vector<SlideProblem>& problems, bool warm, int repeat,
                       const std::function<RootResult(const SlideEquation&, double)>& root) {
  Row row;
  row.group = group;
  row.method = method;
  long iterations = 0;
  for (const SlideProblem& problem : problems) {
    const SlideEquation equation(problem.W, problem.q, problem.mu);
    const RootResult result = root(equation, warm ? problem.phi_warm : problem.phi_cold);
    ++row.attempts;
    iterations += result.iterations;
    if (!result.converged) continue;
    const double phi = wrap_angle(result.phi);
    const SlideEquation::Value value = equation.at(phi);
    if (!(equation.is_root(value) && equation.admissible(value))) continue;
    ++row.solved;
    if (std::abs(wrap_angle(phi - problem.phi_solution)) <= 1e-8) ++row.same_root;
    row.worst_residual = std::max(row.worst_residual, coulomb_residual(problem, equation, phi));
  }
  row.mean_iterations = static_cast<double>(iterations) / row.attempts;
  row.ns_per_solve = time_per_item(
      [&]() {
        double sum = 0.0;
        for (const SlideProblem& problem : problems) {
          const SlideEquation equation(problem.W, problem.q, problem.mu);
          sum += root(equation, warm ? problem.phi_warm : problem.phi_cold).phi;
        }
        return sum;
      },
      static_cast<long>(problems.size()), repeat);
  return row;
}

// One "in a bracket" row: solved = converged to a root of g (admissible or not; the
// fallback refines every sign change and then chooses); the residual is over the brackets
// whose root is an admissible slide.
Row measure_in_bracket(const std::string& method, const std::vector<Bracket>& brackets,
                       int repeat,
                       const std::function<RootResult(const Bracket&, const SlideEquation&)>& root) {
  Row row;
  row.group = "bracket (fallback)";
  row.method = method;
  long iterations = 0;
  for (const Bracket& bracket : brackets) {
    const SlideProblem& problem = *bracket.problem;
    const SlideEquation equation(problem.W, problem.q, problem.mu);
    const RootResult result = root(bracket, equation);
    ++row.attempts;
    iterations += result.iterations;
    const double phi = wrap_angle(result.phi);
    const SlideEquation::Value value = equation.at(phi);
    if (!(result.converged && equation.is_root(value))) continue;
    ++row.solved;
    if (std::abs(wrap_angle(phi - problem.phi_solution)) <= 1e-8) ++row.same_root;
    if (equation.admissible(value)) {
      row.worst_residual = std::max(row.worst_residual, coulomb_residual(problem, equation, phi));
    }
  }
  row.mean_iterations = static_cast<double>(iterations) / row.attempts;
  row.ns_per_solve = time_per_item(
      [&]() {
        double sum = 0.0;
        for (const Bracket& bracket : brackets) {
          const SlideProblem& problem = *bracket.problem;
          const SlideEquation equation(problem.W, problem.q, problem.mu);
          sum += root(bracket, equation).phi;
        }
        return sum;
      },
      static_cast<long>(brackets.size()), repeat);
  return row;
}

// The whole local solve (stick test, Newton, fallback) with solve_coulomb_local.
Row measure_whole_solve(const std::string& group, const std::vector<SlideProblem>& problems,
                        bool warm, int repeat) {
  Row row;
  row.group = group;
  row.method = "ours solve_coulomb_local (whole)";
  std::vector<wiregrain::LocalDelassus> delassus;
  std::vector<Vector3d> guesses;
  for (const SlideProblem& problem : problems) {
    delassus.emplace_back(problem.W);  // once per time step in the solver: not timed
    const double r_n = problem.r_n;
    guesses.push_back(warm ? Vector3d(r_n, problem.mu * r_n * std::cos(problem.phi_warm),
                                      problem.mu * r_n * std::sin(problem.phi_warm))
                           : Vector3d::Zero());
  }
  long iterations = 0;
  for (std::size_t i = 0; i < problems.size(); ++i) {
    const SlideProblem& problem = problems[i];
    const wiregrain::LocalSolution solution =
        wiregrain::solve_coulomb_local(delassus[i], problem.q, problem.mu, guesses[i]);
    ++row.attempts;
    iterations += solution.newton_iterations;
    if (solution.state != wiregrain::ContactState::slide) continue;
    ++row.solved;
    const double phi = std::atan2(solution.impulse[2], solution.impulse[1]);
    if (std::abs(wrap_angle(phi - problem.phi_solution)) <= 1e-8) ++row.same_root;
    row.worst_residual = std::max(
        row.worst_residual,
        wiregrain::natural_map_residual(solution.impulse, solution.velocity, problem.mu).norm() /
            (solution.impulse.norm() + problem.q.norm()));
  }
  row.mean_iterations = static_cast<double>(iterations) / row.attempts;
  row.ns_per_solve = time_per_item(
      [&]() {
        double sum = 0.0;
        for (std::size_t i = 0; i < problems.size(); ++i) {
          sum += wiregrain::solve_coulomb_local(delassus[i], problems[i].q, problems[i].mu,
                                                guesses[i])
                     .impulse[0];
        }
        return sum;
      },
      static_cast<long>(problems.size()), repeat);
  return row;
}

void print_table(const std::vector<Row>& rows) {
  std::printf("%-20s %-34s %9s %8s %8s %8s %9s %9s %10s\n", "group", "method", "attempts",
              "solved", "same", "mean it", "ns/solve", "ns/ours", "max resid");
  for (const Row& row : rows) {
    std::printf("%-20s %-34s %9ld %7.3f%% %7.3f%% %8.2f %9.1f %9.2f %10.1e\n", row.group.c_str(),
                row.method.c_str(), row.attempts, 100.0 * row.solved / row.attempts,
                100.0 * row.same_root / row.attempts, row.mean_iterations, row.ns_per_solve,
                row.ns_per_solve / row.reference_ns, row.worst_residual);
  }
}

}  // namespace

int main(int argc, char** argv) {
  int count_per_mu = 25000;
  unsigned long seed = 20240611;
  int repeat = 5;
  double perturbation = 0.02;
  for (int i = 1; i < argc; ++i) {
    const bool has_value = i + 1 < argc;
    if (!std::strcmp(argv[i], "--count") && has_value) {
      count_per_mu = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--seed") && has_value) {
      seed = std::strtoul(argv[++i], nullptr, 10);
    } else if (!std::strcmp(argv[i], "--repeat") && has_value) {
      repeat = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--perturbation") && has_value) {
      perturbation = std::atof(argv[++i]);
    } else {
      std::fprintf(stderr,
                   "usage: %s [--count N per mu] [--seed S] [--repeat R] [--perturbation RAD]\n",
                   argv[0]);
      return 2;
    }
  }
  if (count_per_mu < 1 || repeat < 1) {
    std::fprintf(stderr, "--count and --repeat must be >= 1\n");
    return 2;
  }
  gsl_set_error_handler_off();  // GSL failures are counted, not fatal

  std::mt19937_64 rng(seed);
  const std::vector<SlideProblem> problems = make_problems(count_per_mu, perturbation, rng);
  const long needed_scan = std::count_if(problems.begin(), problems.end(),
                                         [](const SlideProblem& p) { return p.ours_needed_scan; });
  const std::vector<Bracket> brackets = scan_brackets(problems);
  std::printf("%zu slide problems (%d per mu in {0.1, 0.3, 0.5, 1.0}), seed %lu; %ld of them "
              "needed our scan fallback (cold); %zu scan brackets; warm perturbation %g rad; "
              "best of %d passes\n",
              problems.size(), count_per_mu, seed, needed_scan, brackets.size(), perturbation,
              repeat);

  gsl_root_fdfsolver* gsl_newton = gsl_root_fdfsolver_alloc(gsl_root_fdfsolver_newton);
  gsl_root_fdfsolver* gsl_secant = gsl_root_fdfsolver_alloc(gsl_root_fdfsolver_secant);
  gsl_root_fdfsolver* gsl_steffenson = gsl_root_fdfsolver_alloc(gsl_root_fdfsolver_steffenson);
  gsl_root_fsolver* gsl_brent = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);

  std::vector<Row> rows;
  for (const bool warm : {false, true}) {
    const std::string group = warm ? "guess warm" : "guess cold";
    const std::size_t first = rows.size();
    rows.push_back(measure_from_guess(group, "ours Newton (clamped 0.5 rad)", problems, warm,
                                      repeat, &ours_newton_root));
    rows.push_back(measure_from_guess(
        group, "GSL fdfsolver_newton", problems, warm, repeat,
        [&](const SlideEquation& eq, double phi0) { return gsl_fdf_root(gsl_newton, eq, phi0); }));
    rows.push_back(measure_from_guess(
        group, "GSL fdfsolver_secant", problems, warm, repeat,
        [&](const SlideEquation& eq, double phi0) { return gsl_fdf_root(gsl_secant, eq, phi0); }));
    rows.push_back(measure_from_guess(group, "GSL fdfsolver_steffenson", problems, warm, repeat,
                                      [&](const SlideEquation& eq, double phi0) {
                                        return gsl_fdf_root(gsl_steffenson, eq, phi0);
                                      }));
    rows.push_back(measure_whole_solve(group, problems, warm, repeat));
    for (std::size_t i = first; i < rows.size(); ++i) rows[i].reference_ns = rows[first].ns_per_solve;
  }
  const std::size_t first_bracket = rows.size();
  rows.push_back(measure_in_bracket("rtsafe (former core fallback)", brackets, repeat,
                                    &rtsafe_root));
  rows.push_back(measure_in_bracket("core slide_root_in_bracket (brent)", brackets, repeat,
                                    &core_bracket_root));
  rows.push_back(measure_in_bracket("GSL fsolver_brent, allocated once", brackets, repeat,
                                    [&](const Bracket& bracket, const SlideEquation& eq) {
                                      return gsl_brent_root(gsl_brent, bracket, eq);
                                    }));
  for (std::size_t i = first_bracket; i < rows.size(); ++i) {
    rows[i].reference_ns = rows[first_bracket].ns_per_solve;
  }

  print_table(rows);
  std::printf("solved: converged to an admissible slide root (bracket rows: to a root of g); "
              "same: root of our solve_coulomb_local; mean it: iterations (ours Newton: steps; "
              "GSL: iterate calls; rtsafe: evaluations; brent: iterate calls; whole: newton_iterations); "
              "max resid: natural-map residual / (|r| + |q|) over solved; ns/ours: ratio to the "
              "first row of the group\n");

  gsl_root_fdfsolver_free(gsl_newton);
  gsl_root_fdfsolver_free(gsl_secant);
  gsl_root_fdfsolver_free(gsl_steffenson);
  gsl_root_fsolver_free(gsl_brent);
  return 0;
}
