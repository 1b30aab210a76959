// The exact solution of the frictional contact problem of ONE contact point (the
// "projector" of the NSCD Gauss–Seidel solver, core/nscd/gauss_seidel.h).
//
// Local frame (n, t1, t2), n the contact normal. Unknowns: the impulse r = (r_n, r_t) and
// the local relative velocity u = (u_n, u_t) at the end of the step, linked by
//     u = W r + q,
// W the 3×3 local Delassus block (H M⁻¹ Hᵀ, symmetric positive definite) and q the
// velocity the contact would have with no impulse from itself (any gap-anticipation or
// restitution shift already added to q_n, so the normal constraint reads u_n ≥ 0).
// The Signorini–Coulomb law (Moreau; Jean, Comput. Methods Appl. Mech. Engrg. 177 (1999)
// 235; the paper's Sec. 2.1 and Fig. 2):
//     r_n ≥ 0, u_n ≥ 0, r_n u_n = 0                                     (Signorini)
//     ‖r_t‖ ≤ μ r_n;  ‖r_t‖ < μ r_n ⇒ u_t = 0;
//     ‖r_t‖ = μ r_n ⇒ u_t = −λ r_t for some λ ≥ 0                         (Coulomb)
// Solved by enumerating the three cases of the paper, in its order:
//   open   q_n ≥ 0: r = 0 (u = q).
//   stick  r = −W⁻¹ q, accepted when r_n ≥ 0 and ‖r_t‖ ≤ μ r_n (then u = 0).
//   slide  r = r_n c(φ), c(φ) = (1, μ cos φ, μ sin φ), t(φ) = (cos φ, sin φ). u_n = 0 gives
//          r_n = −q_n / a(φ) with a(φ) = (W c(φ))_n; then
//              a(φ) u_t(φ) = v(φ) := a(φ) q_t − q_n (W c(φ))_t,
//          and u_t ∥ −t(φ) is the scalar equation
//              g(φ) = v(φ) × t(φ) = v_1 sin φ − v_2 cos φ = 0,
//          admissible when a(φ) > 0 (so r_n > 0, as q_n < 0) and v(φ)·t(φ) ≤ 0 (λ ≥ 0).
//          g is a trigonometric polynomial of degree 2 in φ (at most 4 roots). It is
//          solved by Newton's method in φ from a guess (the previous impulse direction,
//          else the direction of the rejected stick impulse), carried out on t(φ) itself,
//          rotated by each step (no sin, cos or atan2 per solve); if that fails or gives an
//          inadmissible root, by a scan of g over [0, 2π) with Brent's method (GSL) in
//          every bracket, and if no bracket holds an admissible root
//          (a double root, or two roots closer than the sampling), by Newton from each
//          local minimum of |g| among the samples. The paper solves this case
//          with a Newton iteration from GSL (our own Newton measured faster, see
//          docs/design.md, "The local solve"); the 1-D reduction makes u_n = 0 and
//          ‖r_t‖ = μ r_n hold by construction, so only u_t ∥ −r_t is iterated.
// μ = 0 (frictionless): r = (−q_n / W_nn, 0, 0) when q_n < 0, counted as slide.
//
// With W symmetric positive definite a solution always exists; the slide solution need
// not be unique for large μ, and the root closest to the guess direction is returned.
#pragma once

#include <Eigen/Dense>
#include <cmath>

namespace wiregrain {

enum class ContactState { open = 0, stick = 1, slide = 2 };
const char* contact_state_name(ContactState state);

// How the slide equation was solved (for tests and statistics).
enum class SlideMethod { none = 0, newton = 1, scan = 2 };

// A 3×3 local Delassus block with its inverse, computed once per time step (the
// Gauss–Seidel sweep solves each contact many times with the same W).
class LocalDelassus {
 public:
  LocalDelassus() = default;
  // W finite with W_nn > 0, else InvalidArgument("W", ...). W need not be symmetric. The
  // stick case needs W invertible; a (numerically) singular W is accepted and the stick
  // case is then skipped.
  explicit LocalDelassus(const Eigen::Matrix3d& W);

  const Eigen::Matrix3d& matrix() const { return matrix_; }
  const Eigen::Matrix3d& inverse() const { return inverse_; }
  bool invertible() const { return invertible_; }

 private:
  Eigen::Matrix3d matrix_ = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d inverse_ = Eigen::Matrix3d::Identity();
  bool invertible_ = true;
};

struct LocalSolution {
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();   // r
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // u = W r + q
  ContactState state = ContactState::open;
  SlideMethod slide_method = SlideMethod::none;
  int newton_iterations = 0;  // Newton steps on g(φ), all stages together
};

// Solves the local problem. `guess` is a previous impulse of this contact: when it is on
// the cone boundary its tangential direction starts the slide Newton iteration (any
// value is allowed; zero means no guess). μ ≥ 0 finite and q finite, else
// InvalidArgument("mu"/"q", ...). Throws NumericalFailure only if no admissible slide
// root is found (never observed for symmetric positive definite W).
LocalSolution solve_coulomb_local(const LocalDelassus& W, const Eigen::Vector3d& q, double mu,
                                  const Eigen::Vector3d& guess = Eigen::Vector3d::Zero());
LocalSolution solve_coulomb_local(const Eigen::Matrix3d& W, const Eigen::Vector3d& q,
                                  double mu);

// The slide equation g(φ) = v(φ) × t(φ) of the slide case above, with its derivative, and
// the two root finders solve_coulomb_local applies to it. Public so that other root
// finders can be run on the same g (bench/local_slide_gsl compares GSL's); the core's only
// user is solve_coulomb_local.
class SlideEquation {
 public:
  struct Value {
    double g;    // v × t
    double dg;   // dg/dφ = v' × t + v·t
    double d2g;  // d²g/dφ² = v'' × t + 2 v'·t − g
    double a;    // (W c(φ))_n; r_n = −q_n / a
    double dot;  // v·t; at a root v = a u_t = −a λ r_t, so v·t = −a λ μ r_n ≤ 0
  };

  // With c = cos φ, s = sin φ: a = W_nn + μ (W_n1 c + W_n2 s), b_i = W_i0 + μ (W_i1 c +
  // W_i2 s) (i = 1, 2), v_i = a q_i − q_n b_i, g = v_1 s − v_2 c. The v_i are linear in
  // (1, c, s); their coefficients are formed here, once per solve.
  SlideEquation(const Eigen::Matrix3d& W, const Eigen::Vector3d& q, double mu) {
    const double w_size = W.cwiseAbs().maxCoeff() * (1.0 + mu);
    v_scale_ = 2.0 * w_size * q.cwiseAbs().maxCoeff();
    a_floor_ = 1e-14 * w_size;
    for (int k = 0; k < 3; ++k) {
      const double m = k == 0 ? 1.0 : mu;  // coefficient of 1, c, s in a and b_i
      a_[k] = m * W(0, k);
      v1_[k] = q[1] * a_[k] - q[0] * (m * W(1, k));
      v2_[k] = q[2] * a_[k] - q[0] * (m * W(2, k));
    }
  }

  Value at(double phi) const { return at(std::cos(phi), std::sin(phi)); }
  // At the direction t(φ) = (c, s) = (cos φ, sin φ).
  Value at(double c, double s) const {
    const double v1 = v1_[0] + (v1_[1] * c + v1_[2] * s);
    const double v2 = v2_[0] + (v2_[1] * c + v2_[2] * s);
    const double dv1 = v1_[2] * c - v1_[1] * s, dv2 = v2_[2] * c - v2_[1] * s;
    Value value;
    value.g = v1 * s - v2 * c;
    value.dot = v1 * c + v2 * s;
    value.dg = dv1 * s - dv2 * c + value.dot;
    // v_i'' = −(v_i − v_i(0 terms))
    value.d2g = (v2 - v2_[0]) * c - (v1 - v1_[0]) * s + 2.0 * (dv1 * c + dv2 * s) - value.g;
    value.a = a_[0] + (a_[1] * c + a_[2] * s);
    return value;
  }

  // a > 0 (r_n > 0) and λ ≥ 0 (v·t ≤ 0, to round-off).
  bool admissible(const Value& value) const {
    return value.a > a_floor_ && value.dot <= 1e-12 * v_scale_;
  }
  // |g| small enough to be a root to round-off.
  bool is_root(const Value& value) const { return std::abs(value.g) <= 1e-12 * v_scale_; }

 private:
  double a_[3], v1_[3], v2_[3];  // coefficients of 1, c, s
  double v_scale_;
  double a_floor_;
};

// Newton's method on g from phi, without bracket; the step is limited to 0.5 rad.
// Returns true on convergence: g = 0, a step below 1e-13 rad, or a step δ ≤ 1e-6 rad whose
// Newton error |g''| δ² / (2 |g'|) is below 1e-17 rad (the root to round-off; the step
// below 1e-13 that would follow only confirms it); phi is not wrapped. `iterations` is
// increased by the number of steps.
bool slide_newton_unbracketed(const SlideEquation& equation, double& phi, int& iterations,
                              int max_iterations);
// The same iteration carried out on the direction t(φ) = (cos φ, sin φ), which each step δ
// rotates (cos δ and sin δ of a step below 1/32 rad by their series: no call to sin or
// cos); the φ form above runs through it. `direction`: a unit vector on entry and,
// renormalised, on return; `turned` (optional) gets Σ δ.
bool slide_newton_unbracketed(const SlideEquation& equation, Eigen::Vector2d& direction,
                              int& iterations, int max_iterations, double* turned = nullptr);

// A root of g in the bracket [lo, hi], g(lo) g(hi) < 0, by Brent's method (GSL's
// gsl_root_fsolver_brent), stopping when the bracket is below 1e-14 rad (at most 100
// iterations). `iterations` is increased by the number of Brent iterations (each one
// evaluation of g, plus two at the start). Chosen over a safeguarded Newton–bisection by
// bench/local_slide_gsl (docs/design.md, "The local solve").
double slide_root_in_bracket(const SlideEquation& equation, double lo, double hi,
                             int& iterations);

// Euclidean projection onto the Coulomb cone K_μ = {r : ‖r_t‖ ≤ μ r_n}:
//   r if r ∈ K_μ; 0 if μ‖r_t‖ ≤ −r_n (r in the polar cone); otherwise
//   r_n' = (r_n + μ‖r_t‖)/(1 + μ²), r_t' = μ r_n' r_t/‖r_t‖.
Eigen::Vector3d project_on_coulomb_cone(const Eigen::Vector3d& r, double mu);

// Natural-map residual of one contact with De Saxcé's modified velocity
// û = u + μ‖u_t‖ e_n (De Saxcé & Feng, Math. Comput. Modelling 28 (1998) 225):
//   F(r, u) = r − proj_{K_μ}(r − û),
// zero exactly when (r, u) satisfies the Signorini–Coulomb law above. This is the
// per-contact term of Siconos' fc3d_compute_error (core/nscd/contact_operator.h).
Eigen::Vector3d natural_map_residual(const Eigen::Vector3d& r, const Eigen::Vector3d& u,
                                     double mu);

}  // namespace wiregrain
