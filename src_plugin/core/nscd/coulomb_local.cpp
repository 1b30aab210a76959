// Exact local Signorini–Coulomb solution; the equations are in core/coulomb_local.h.
#include "core/nscd/coulomb_local.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/common/errors.h"
#include "core/common/constants.h"
#include "core/common/validation.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

namespace wiregrain {

const char* contact_state_name(ContactState state) {
  switch (state) {
    case ContactState::open: return "open";
    case ContactState::stick: return "stick";
    case ContactState::slide: return "slide";
  }
  return "unknown";
}

LocalDelassus::LocalDelassus(const Eigen::Matrix3d& W) : matrix_(W) {
  if (!W.allFinite()) throw InvalidArgument("W", "local Delassus block W has a non-finite entry");
  if (!(W(0, 0) > 0.0)) {
    throw InvalidArgument("W", "local Delassus block needs W_nn > 0, got " +
                                   format_number(W(0, 0)));
  }
  // Singular (to round-off) when |det W| is below 1e-13 of the product of the row norms.
  const double scale = W.row(0).norm() * W.row(1).norm() * W.row(2).norm();
  double determinant = 0.0;
  W.computeInverseAndDetWithCheck(inverse_, determinant, invertible_, 1e-13 * scale);
  if (!invertible_) inverse_.setZero();
}

namespace {

constexpr double kTwoPi = 2.0 * kPi;

// Wraps an angle to (−π, π].
double wrap_angle(double phi) {
  phi = std::remainder(phi, kTwoPi);
  return phi <= -kPi ? phi + kTwoPi : phi;
}

struct Candidate {
  double phi;
  double distance;  // angular distance to the guess
};

}  // namespace

// Newton from a guess, step limited to 0.5 rad (coulomb_local.h).
bool slide_newton_unbracketed(const SlideEquation& eq, double& phi, int& iterations,
                              int max_iterations) {
  Eigen::Vector2d direction(std::cos(phi), std::sin(phi));
  double turned = 0.0;
  const bool converged = slide_newton_unbracketed(eq, direction, iterations, max_iterations, &turned);
  phi += turned;
  return converged;
}

bool slide_newton_unbracketed(const SlideEquation& eq, Eigen::Vector2d& direction,
                              int& iterations, int max_iterations, double* turned) {
  bool converged = false;
  double total = 0.0;
  for (int it = 0; it < max_iterations; ++it) {
    const SlideEquation::Value value = eq.at(direction[0], direction[1]);
    if (value.g == 0.0) {
      converged = true;
      break;
    }
    if (value.dg == 0.0 || !std::isfinite(value.dg)) break;
    const double step = std::clamp(-value.g / value.dg, -0.5, 0.5);
    const bool last = std::abs(step) <= 1e-13 ||
                      (std::abs(step) <= 1e-6 &&
                       std::abs(value.d2g) * step * step <= 2e-17 * std::abs(value.dg));
    // t(φ + δ) = R(δ) t(φ). The series below are exact to below 1e-17 (first terms left
    // out: δ⁴/5! relative and δ⁴/4! for |δ| ≤ 1e-4, δ⁸/9! relative and δ¹⁰/10! for
    // |δ| ≤ 1/32).
    double c, s;
    const double d2 = step * step;
    if (std::abs(step) <= 1e-4) {
      s = step * (1.0 - d2 * (1.0 / 6.0));
      c = 1.0 - 0.5 * d2;
    } else if (std::abs(step) <= 1.0 / 32.0) {
      s = step * (1.0 + d2 * (-1.0 / 6.0 + d2 * (1.0 / 120.0 - d2 * (1.0 / 5040.0))));
      c = 1.0 + d2 * (-0.5 + d2 * (1.0 / 24.0 + d2 * (-1.0 / 720.0 + d2 * (1.0 / 40320.0))));
    } else {
      c = std::cos(step);
      s = std::sin(step);
    }
    direction = Eigen::Vector2d(c * direction[0] - s * direction[1], s * direction[0] + c * direction[1]);
    total += step;
    ++iterations;
    if (last) {
      converged = true;
      break;
    }
  }
  direction /= direction.norm();
  if (turned != nullptr) *turned = total;
  return converged;
}

// Brent's method (GSL gsl_root_fsolver_brent: inverse quadratic interpolation, secant
// and bisection; Brent, Algorithms for Minimization without Derivatives, 1973, ch. 4) on a
// bracket of g (coulomb_local.h). GSL's default error handler aborts; it is switched off
// around the call and restored, so a GSL error (none is expected: the bracket straddles a
// root of a finite g) ends the iteration at the current estimate instead.
double slide_root_in_bracket(const SlideEquation& equation, double lo, double hi,
                             int& iterations) {
  gsl_function function;
  function.function = [](double phi, void* params) {
    return static_cast<const SlideEquation*>(params)->at(phi).g;
  };
  function.params = const_cast<SlideEquation*>(&equation);
  gsl_error_handler_t* const previous_handler = gsl_set_error_handler_off();
  gsl_root_fsolver* const solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  double phi = 0.5 * (lo + hi);
  if (solver != nullptr && gsl_root_fsolver_set(solver, &function, lo, hi) == GSL_SUCCESS) {
    for (int it = 0; it < 100; ++it) {
      const int status = gsl_root_fsolver_iterate(solver);
      ++iterations;
      if (status != GSL_SUCCESS) break;
      phi = gsl_root_fsolver_root(solver);
      if (gsl_root_test_interval(gsl_root_fsolver_x_lower(solver),
                                 gsl_root_fsolver_x_upper(solver), 1e-14, 0.0) == GSL_SUCCESS) {
        break;
      }
    }
  }
  gsl_root_fsolver_free(solver);
  gsl_set_error_handler(previous_handler);
  return phi;
}

LocalSolution solve_coulomb_local(const LocalDelassus& delassus, const Eigen::Vector3d& q,
                                  double mu, const Eigen::Vector3d& guess) {
  require_nonnegative("mu", mu);
  if (!q.allFinite()) throw InvalidArgument("q", "local free velocity q has a non-finite entry");

  const Eigen::Matrix3d& W = delassus.matrix();
  LocalSolution solution;

  // Open: the contact separates (or stays at the anticipated gap) without impulse.
  if (q[0] >= 0.0) {
    solution.velocity = q;
    solution.state = ContactState::open;
    return solution;
  }

  // Frictionless closed contact: r_n from u_n = 0, no tangential impulse.
  if (mu == 0.0) {
    solution.impulse = Eigen::Vector3d(-q[0] / W(0, 0), 0.0, 0.0);
    solution.velocity = W * solution.impulse + q;
    solution.state = ContactState::slide;
    return solution;
  }

  // Stick: u = 0. (‖r_t‖ ≤ μ r_n compared in squares, r_n ≥ 0.)
  Eigen::Vector3d stick = Eigen::Vector3d::Zero();
  if (delassus.invertible()) {
    stick = -(delassus.inverse() * q);
    if (stick[0] >= 0.0 && stick.tail<2>().squaredNorm() <= (mu * stick[0]) * (mu * stick[0])) {
      solution.impulse = stick;
      solution.velocity = W * stick + q;
      solution.state = ContactState::stick;
      return solution;
    }
  }

  // Slide. Starting direction t0 of r_t: the guess's if it lies on the cone boundary, else
  // that of the rejected stick impulse, else −q_t.
  const SlideEquation equation(W, q, mu);
  Eigen::Vector2d t0(1.0, 0.0);
  const double guess_t = guess.tail<2>().norm();
  if (guess[0] > 0.0 && guess_t > 0.0 && guess_t >= (1.0 - 1e-6) * mu * guess[0]) {
    t0 = guess.tail<2>() / guess_t;
  } else if (!stick.tail<2>().isZero(0.0)) {
    t0 = stick.tail<2>().normalized();
  } else if (!q.tail<2>().isZero(0.0)) {
    t0 = -q.tail<2>().normalized();
  }

  int iterations = 0;
  Eigen::Vector2d t = t0;
  SlideEquation::Value value;
  bool found = false;
  if (slide_newton_unbracketed(equation, t, iterations, 30)) {
    value = equation.at(t[0], t[1]);
    found = equation.is_root(value) && equation.admissible(value);
    if (found) solution.slide_method = SlideMethod::newton;
  }

  if (!found) {
    // Scan g on 24 angles from phi0; refine every sign change; keep the admissible root
    // nearest to phi0.
    const double phi0 = std::atan2(t0[1], t0[0]);
    constexpr int kSamples = 24;
    std::array<double, kSamples + 1> angle{};
    std::array<double, kSamples + 1> g{};
    for (int j = 0; j <= kSamples; ++j) {
      angle[j] = phi0 + kTwoPi * j / kSamples;
      g[j] = j < kSamples ? equation.at(angle[j]).g : g[0];
    }
    std::vector<Candidate> roots;
    auto consider = [&](double candidate) {
      candidate = wrap_angle(candidate);
      const SlideEquation::Value value = equation.at(candidate);
      if (equation.is_root(value) && equation.admissible(value)) {
        roots.push_back({candidate, std::abs(wrap_angle(candidate - phi0))});
      }
    };
    for (int j = 0; j < kSamples; ++j) {
      if (g[j] == 0.0) {
        consider(angle[j]);
      } else if ((g[j] < 0.0) != (g[j + 1] < 0.0) && g[j + 1] != 0.0) {
        consider(slide_root_in_bracket(equation, angle[j], angle[j + 1], iterations));
      }
    }
    if (roots.empty()) {
      // No sign change holds an admissible root: a double (tangent) root, or two roots
      // closer than the sampling. Newton from every local minimum of |g| among the samples.
      for (int j = 0; j < kSamples; ++j) {
        const double left = std::abs(g[(j + kSamples - 1) % kSamples]);
        if (std::abs(g[j]) <= left && std::abs(g[j]) <= std::abs(g[j + 1])) {
          double candidate = angle[j];
          slide_newton_unbracketed(equation, candidate, iterations, 60);
          consider(candidate);
        }
      }
    }
    solution.slide_method = SlideMethod::scan;
    if (roots.empty()) {
      throw NumericalFailure(
          "coulomb_local: no admissible sliding solution (W not positive definite?)");
    }
    const double phi = std::min_element(roots.begin(), roots.end(),
                                        [](const Candidate& x, const Candidate& y) {
                                          return x.distance < y.distance;
                                        })
                           ->phi;
    t = Eigen::Vector2d(std::cos(phi), std::sin(phi));
    value = equation.at(phi);
  }

  const double r_n = -q[0] / value.a;
  solution.impulse = Eigen::Vector3d(r_n, mu * r_n * t[0], mu * r_n * t[1]);
  solution.velocity = W * solution.impulse + q;
  solution.state = ContactState::slide;
  solution.newton_iterations = iterations;
  return solution;
}

LocalSolution solve_coulomb_local(const Eigen::Matrix3d& W, const Eigen::Vector3d& q,
                                  double mu) {
  return solve_coulomb_local(LocalDelassus(W), q, mu);
}

Eigen::Vector3d project_on_coulomb_cone(const Eigen::Vector3d& r, double mu) {
  const double r_t = r.tail<2>().norm();
  // inside K_μ (r_n ≥ 0 asked explicitly: for μ = 0, r_t = 0 and r_n < 0 the test
  // r_t ≤ μ r_n reads 0 ≤ −0 and would keep a negative normal impulse)
  if (r[0] >= 0.0 && r_t <= mu * r[0]) return r;
  if (mu * r_t <= -r[0]) return Eigen::Vector3d::Zero();  // inside the polar cone
  const double r_n = (r[0] + mu * r_t) / (1.0 + mu * mu);
  const double scale = mu * r_n / r_t;
  return Eigen::Vector3d(r_n, scale * r[1], scale * r[2]);
}

Eigen::Vector3d natural_map_residual(const Eigen::Vector3d& r, const Eigen::Vector3d& u,
                                     double mu) {
  const Eigen::Vector3d modified(u[0] + mu * u.tail<2>().norm(), u[1], u[2]);
  return r - project_on_coulomb_cone(r - modified, mu);
}

}  // namespace wiregrain
