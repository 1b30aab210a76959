// Exact local Signorini–Coulomb solution: complementarity on random coupled problems,
// closed forms for decoupled W, cone projection, bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/nscd/coulomb_local.h"
#include "core/common/errors.h"

using namespace wiregrain;
using Eigen::Matrix3d;
using Eigen::Vector2d;
using Eigen::Vector3d;

namespace {

// Random symmetric positive definite W = R diag(λ) Rᵀ, λ log-uniform in [0.1, 10], R a
// random rotation; q uniform in [−1, 1]³; μ uniform in [0, 1.5].
struct RandomLocalProblem {
  Matrix3d W;
  Vector3d q;
  double mu;
};

RandomLocalProblem random_problem(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0), log_lambda(std::log(0.1), std::log(10.0)),
      friction(0.0, 1.5);
  Eigen::Quaterniond rotation(unit(rng), unit(rng), unit(rng), unit(rng));
  rotation.normalize();
  const Matrix3d R = rotation.toRotationMatrix();
  const Vector3d lambda(std::exp(log_lambda(rng)), std::exp(log_lambda(rng)),
                        std::exp(log_lambda(rng)));
  RandomLocalProblem p;
  p.W = R * lambda.asDiagonal() * R.transpose();
  p.W = 0.5 * (p.W + p.W.transpose());
  p.q = Vector3d(unit(rng), unit(rng), unit(rng));
  p.mu = friction(rng);
  return p;
}

// Largest violation of the Signorini–Coulomb conditions by (r, u) for the state claimed.
double law_violation(const Vector3d& r, const Vector3d& u, double mu, ContactState state) {
  const double r_t = std::hypot(r[1], r[2]), u_t = std::hypot(u[1], u[2]);
  double worst = 0.0;
  worst = std::max(worst, -r[0]);                       // r_n ≥ 0
  worst = std::max(worst, -u[0]);                       // u_n ≥ 0
  worst = std::max(worst, std::abs(r[0] * u[0]));       // r_n u_n = 0
  worst = std::max(worst, r_t - mu * r[0]);             // ‖r_t‖ ≤ μ r_n
  switch (state) {
    case ContactState::open:
      worst = std::max(worst, r.norm());
      break;
    case ContactState::stick:
      worst = std::max(worst, u_t);  // u_t = 0
      break;
    case ContactState::slide:
      worst = std::max(worst, std::abs(r_t - mu * r[0]));  // on the cone
      if (r_t > 0.0) {
        // u_t = −λ r_t with λ ≥ 0: no component of u_t across r_t, none along +r_t.
        const Vector2d dir(r[1] / r_t, r[2] / r_t);
        const Vector2d ut(u[1], u[2]);
        worst = std::max(worst, std::abs(ut[0] * dir[1] - ut[1] * dir[0]));
        worst = std::max(worst, ut.dot(dir));
      }
      break;
  }
  return worst;
}

}  // namespace

// 10⁵ random coupled problems: every solution satisfies the law to 1e-10 (data of order
// one), the natural-map residual vanishes, and all three cases occur.
TEST(CoulombLocal, RandomCoupledProblemsSatisfyTheLaw) {
  std::mt19937_64 rng(20240611);
  int count[3] = {0, 0, 0};
  int method[3] = {0, 0, 0};
  double worst = 0.0, worst_natural = 0.0;
  long newton = 0;
  const int cases = 100000;
  for (int k = 0; k < cases; ++k) {
    const RandomLocalProblem p = random_problem(rng);
    const LocalSolution s = solve_coulomb_local(p.W, p.q, p.mu);
    const Vector3d u = p.W * s.impulse + p.q;
    ASSERT_LT((u - s.velocity).norm(), 1e-12);
    const double violation = law_violation(s.impulse, u, p.mu, s.state);
    worst = std::max(worst, violation);
    worst_natural = std::max(worst_natural, natural_map_residual(s.impulse, u, p.mu).norm());
    ASSERT_LT(violation, 1e-10) << "case " << k << " state " << contact_state_name(s.state);
    ++count[static_cast<int>(s.state)];
    ++method[static_cast<int>(s.slide_method)];
    newton += s.newton_iterations;
  }
  EXPECT_LT(worst_natural, 1e-10);
  std::printf("  open %d stick %d slide %d; slide by newton %d scan %d; "
              "mean Newton steps per slide %.2f; worst violation %.2e, natural map %.2e\n",
              count[0], count[1], count[2], method[1], method[2],
              double(newton) / count[2], worst, worst_natural);
  // q_n ≥ 0 half the time; the rest splits between stick and slide.
  EXPECT_GT(count[0], cases / 4);
  EXPECT_GT(count[1], cases / 20);
  EXPECT_GT(count[2], cases / 20);
}

// Strongly coupled W (normal–tangential coupling close to the PD limit) and large μ.
TEST(CoulombLocal, StronglyCoupledLargeFriction) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), friction(0.5, 5.0);
  int slides = 0;
  for (int k = 0; k < 20000; ++k) {
    // W = L Lᵀ + 1e-3 I with L random: condition numbers up to ~1e4.
    Matrix3d L;
    for (int i = 0; i < 9; ++i) L(i / 3, i % 3) = unit(rng);
    Matrix3d W = L * L.transpose() + 1e-3 * Matrix3d::Identity();
    if (W(0, 0) < 1e-2) continue;
    const Vector3d q(unit(rng), unit(rng), unit(rng));
    const double mu = friction(rng);
    const LocalSolution s = solve_coulomb_local(W, q, mu);
    const Vector3d u = W * s.impulse + q;
    const double scale = 1.0 + s.impulse.norm() * W.norm();
    ASSERT_LT(law_violation(s.impulse, u, mu, s.state), 1e-10 * scale) << "case " << k;
    if (s.state == ContactState::slide) ++slides;
  }
  EXPECT_GT(slides, 1000);
}

// Problems built so that the slide equation g(φ) = v(φ) × t(φ) has a double (tangent)
// root at a chosen φ*: g and g' are linear in q_t (v = a q_t − q_n b), so q_t solves the
// 2×2 system g(φ*) = g'(φ*) = 0. Such roots have no sign change, so Newton converges
// slowly and the scan cannot bracket them; the law must hold all the same.
TEST(CoulombLocal, TangentSlideRoots) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), angle(-3.0, 3.0), friction(0.2, 2.0);
  int tested = 0;
  int method[3] = {0, 0, 0};
  for (int k = 0; k < 2000000 && tested < 2000; ++k) {
    const RandomLocalProblem base = random_problem(rng);
    const Matrix3d& W = base.W;
    const double mu = friction(rng), phi = angle(rng), q_n = -0.2 - std::abs(unit(rng));
    const double c = std::cos(phi), s = std::sin(phi);
    const double a = W(0, 0) + mu * (W(0, 1) * c + W(0, 2) * s);
    const double da = mu * (-W(0, 1) * s + W(0, 2) * c);
    const Vector2d b(W(1, 0) + mu * (W(1, 1) * c + W(1, 2) * s),
                     W(2, 0) + mu * (W(2, 1) * c + W(2, 2) * s));
    const Vector2d db(mu * (-W(1, 1) * s + W(1, 2) * c), mu * (-W(2, 1) * s + W(2, 2) * c));
    // g = (a q_1 − q_n b_1) s − (a q_2 − q_n b_2) c;
    // g' = (a' q_1 − q_n b_1') s − (a' q_2 − q_n b_2') c + (a q_1 − q_n b_1) c + (a q_2 − q_n b_2) s.
    Eigen::Matrix2d A;
    A << a * s, -a * c, da * s + a * c, -da * c + a * s;
    const Vector2d rhs(q_n * (b[0] * s - b[1] * c),
                       q_n * (db[0] * s - db[1] * c + b[0] * c + b[1] * s));
    if (std::abs(A.determinant()) < 1e-3) continue;
    const Vector2d q_t = A.partialPivLu().solve(rhs);
    const Vector3d q(q_n, q_t[0], q_t[1]);
    const Vector2d v = a * q_t - q_n * b;
    if (!(a > 0.1) || !(v.dot(Vector2d(c, s)) < -1e-3) || q.norm() > 20.0) continue;
    const LocalSolution s_ = solve_coulomb_local(W, q, mu);
    if (s_.state != ContactState::slide) continue;
    const Vector3d u = W * s_.impulse + q;
    ASSERT_LT(law_violation(s_.impulse, u, mu, s_.state), 1e-9 * (1.0 + q.norm()))
        << "case " << k << " method " << static_cast<int>(s_.slide_method);
    ++method[static_cast<int>(s_.slide_method)];
    ++tested;
  }
  std::printf("  tangent roots: %d problems; solved by newton %d scan %d\n", tested,
              method[1], method[2]);
  EXPECT_GT(tested, 1000);
}

// W = diag(w_n, w_t, w_t): r_n = max(0, −q_n/w_n); stick r_t = −q_t/w_t when
// ‖q_t‖/w_t ≤ μ r_n, else r_t = −μ r_n q_t/‖q_t‖.
TEST(CoulombLocal, DecoupledIsotropicClosedForm) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), stiffness(0.2, 5.0), friction(0.0, 1.0);
  int count[3] = {0, 0, 0};
  for (int k = 0; k < 10000; ++k) {
    const double w_n = stiffness(rng), w_t = stiffness(rng), mu = friction(rng);
    const Vector3d q(unit(rng), unit(rng), unit(rng));
    Vector3d expected = Vector3d::Zero();
    const double r_n = std::max(0.0, -q[0] / w_n);
    const double q_t = std::hypot(q[1], q[2]);
    expected[0] = r_n;
    if (q_t / w_t <= mu * r_n) {
      expected[1] = -q[1] / w_t;
      expected[2] = -q[2] / w_t;
    } else {
      expected[1] = -mu * r_n * q[1] / q_t;
      expected[2] = -mu * r_n * q[2] / q_t;
    }
    const LocalSolution s = solve_coulomb_local(Vector3d(w_n, w_t, w_t).asDiagonal().toDenseMatrix(), q, mu);
    ASSERT_LT((s.impulse - expected).norm(), 1e-13 * (1.0 + expected.norm())) << "case " << k;
    ++count[static_cast<int>(s.state)];
  }
  EXPECT_GT(count[0], 1000);
  EXPECT_GT(count[1], 500);
  EXPECT_GT(count[2], 500);
}

// W = diag(w_n, w_1, w_2), w_1 ≠ w_2, sliding: u_i = w_i r_i + q_i = −λ r_i gives
// r_i = −q_i/(w_i + λ) and ‖r_t‖ = μ r_n the secular equation
//   Σ_i q_i² / (w_i + λ)² = (μ r_n)²,   λ > 0,
// solved here by bisection (its left side decreases in λ).
TEST(CoulombLocal, DecoupledAnisotropicSecularEquation) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), stiffness(0.2, 5.0), friction(0.05, 1.0);
  int slides = 0;
  for (int k = 0; k < 5000; ++k) {
    const Vector3d w(stiffness(rng), stiffness(rng), stiffness(rng));
    const double mu = friction(rng);
    const Vector3d q(-std::abs(unit(rng)) - 0.05, unit(rng), unit(rng));
    const double r_n = -q[0] / w[0], bound = mu * r_n;
    if (std::hypot(q[1] / w[1], q[2] / w[2]) <= bound) continue;  // stick
    auto excess = [&](double lambda) {
      return std::pow(q[1] / (w[1] + lambda), 2) + std::pow(q[2] / (w[2] + lambda), 2) -
             bound * bound;
    };
    double lo = 0.0, hi = 1.0;
    while (excess(hi) > 0.0) hi *= 2.0;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      (excess(mid) > 0.0 ? lo : hi) = mid;
    }
    const double lambda = 0.5 * (lo + hi);
    const Vector3d expected(r_n, -q[1] / (w[1] + lambda), -q[2] / (w[2] + lambda));
    const LocalSolution s = solve_coulomb_local(w.asDiagonal().toDenseMatrix(), q, mu);
    ASSERT_EQ(s.state, ContactState::slide);
    ASSERT_LT((s.impulse - expected).norm(), 1e-11 * (1.0 + expected.norm())) << "case " << k;
    ++slides;
  }
  EXPECT_GT(slides, 2000);
}

// A guess on the solution's direction reproduces it with at most a couple of Newton steps.
TEST(CoulombLocal, GuessFromThePreviousSolution) {
  std::mt19937_64 rng(5);
  int slides = 0;
  long steps = 0;
  for (int k = 0; k < 20000; ++k) {
    const RandomLocalProblem p = random_problem(rng);
    const LocalDelassus W(p.W);
    const LocalSolution first = solve_coulomb_local(W, p.q, p.mu);
    if (first.state != ContactState::slide || p.mu == 0.0) continue;
    const LocalSolution again = solve_coulomb_local(W, p.q, p.mu, first.impulse);
    EXPECT_LT((again.impulse - first.impulse).norm(), 1e-12 * (1.0 + first.impulse.norm()));
    EXPECT_EQ(again.slide_method, SlideMethod::newton);
    steps += again.newton_iterations;
    ++slides;
  }
  ASSERT_GT(slides, 1000);
  EXPECT_LT(double(steps) / slides, 2.5);
}

// Frictionless: r = (−q_n/W_nn, 0, 0), u_n = 0, counted as slide.
TEST(CoulombLocal, Frictionless) {
  Matrix3d W;
  W << 2.0, 0.3, -0.2, 0.3, 1.5, 0.1, -0.2, 0.1, 1.0;
  const LocalSolution s = solve_coulomb_local(W, Vector3d(-0.5, 0.2, 0.1), 0.0);
  EXPECT_EQ(s.state, ContactState::slide);
  EXPECT_DOUBLE_EQ(s.impulse[0], 0.25);
  EXPECT_EQ(s.impulse[1], 0.0);
  EXPECT_NEAR(s.velocity[0], 0.0, 1e-15);
  EXPECT_EQ(solve_coulomb_local(W, Vector3d(0.0, 0.2, 0.1), 0.0).state, ContactState::open);
}

// Projection on K_μ: inside, polar cone, and the boundary formula; a second projection
// changes nothing, and r − P(r) is orthogonal to P(r).
TEST(CoulombLocal, ConeProjection) {
  const double mu = 0.5;
  EXPECT_EQ(project_on_coulomb_cone(Vector3d(1.0, 0.3, 0.2), mu), Vector3d(1.0, 0.3, 0.2));
  EXPECT_EQ(project_on_coulomb_cone(Vector3d(-1.0, 0.3, 0.2), mu), Vector3d::Zero());
  // (1, 2, 0): r_n' = (1 + 0.5·2)/1.25 = 1.6, r_t' = 0.5·1.6 = 0.8 along t1.
  const Vector3d p = project_on_coulomb_cone(Vector3d(1.0, 2.0, 0.0), mu);
  EXPECT_NEAR((p - Vector3d(1.6, 0.8, 0.0)).norm(), 0.0, 1e-15);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> unit(-2.0, 2.0);
  for (int k = 0; k < 1000; ++k) {
    const Vector3d r(unit(rng), unit(rng), unit(rng));
    const Vector3d pr = project_on_coulomb_cone(r, mu);
    EXPECT_LT((project_on_coulomb_cone(pr, mu) - pr).norm(), 1e-14);
    EXPECT_NEAR((r - pr).dot(pr), 0.0, 1e-13);
    EXPECT_LE(std::hypot(pr[1], pr[2]), mu * pr[0] + 1e-14);
  }
  // Frictionless (μ = 0): K_0 is the ray r_t = 0, r_n ≥ 0; a negative normal impulse
  // without tangential part projects to 0, not onto itself.
  EXPECT_EQ(project_on_coulomb_cone(Vector3d(-1.0, 0.0, 0.0), 0.0), Vector3d::Zero());
  EXPECT_EQ(project_on_coulomb_cone(Vector3d(2.0, 0.0, 0.0), 0.0), Vector3d(2.0, 0.0, 0.0));
  EXPECT_EQ(project_on_coulomb_cone(Vector3d(2.0, 1.0, 0.0), 0.0), Vector3d(2.0, 0.0, 0.0));
  // An open contact (r = 0, separating) is a solution of the law for any μ: residual 0,
  // also frictionless and without tangential velocity.
  for (double m : {0.0, 0.3}) {
    EXPECT_EQ(natural_map_residual(Vector3d::Zero(), Vector3d(0.7, 0.0, 0.0), m), Vector3d::Zero()) << m;
    EXPECT_EQ(natural_map_residual(Vector3d::Zero(), Vector3d(0.0, 0.4, -0.1), m), Vector3d::Zero()) << m;
    EXPECT_EQ(natural_map_residual(Vector3d::Zero(), Vector3d(0.2, 0.4, -0.1), m), Vector3d::Zero()) << m;
  }
  // The natural map does not vanish away from a solution.
  EXPECT_GT(natural_map_residual(Vector3d(1.0, 0.0, 0.0), Vector3d(0.5, 0.0, 0.0), mu).norm(), 0.4);
}

TEST(CoulombLocal, BadInput) {
  const Matrix3d W = Matrix3d::Identity();
  try {
    solve_coulomb_local(W, Vector3d(-1.0, 0.0, 0.0), -0.1);
    FAIL() << "negative mu accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), "mu");
  }
  try {
    solve_coulomb_local(W, Vector3d(std::nan(""), 0.0, 0.0), 0.3);
    FAIL() << "NaN q accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), "q");
  }
  Matrix3d bad = W;
  bad(0, 0) = 0.0;
  try {
    LocalDelassus block(bad);
    FAIL() << "W_nn = 0 accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), "W");
  }
}
