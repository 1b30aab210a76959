// Rigid-body rotation by splitting: conservation, analytic tops, stability of rotation axes.
#include <gtest/gtest.h>

#include <gsl/gsl_mode.h>
#include <gsl/gsl_sf_ellint.h>
#include <gsl/gsl_sf_elljac.h>

#include <cmath>
#include <cstdio>

#include "core/common/errors.h"
#include "core/nscd/rigid_body.h"

using namespace wiregrain;
using Eigen::AngleAxisd;
using Eigen::Matrix3d;
using Eigen::Quaterniond;
using Eigen::Vector3d;

namespace {

// Rotation angle between two orientations.
double angle_between(const Quaterniond& a, const Quaterniond& b) {
  return 2.0 * std::asin(std::min(1.0, (a.conjugate() * b).vec().norm()));
}

const Quaterniond kTilted(AngleAxisd(0.7, Vector3d(1.0, -2.0, 0.5).normalized()));

// Asymmetric top I_1 < I_2 < I_3 started from ω = (ω_1, 0, ω_3) with L² > 2E I_2:
// ω_1 = ω_1 cn(λt, k), ω_2 = A_2 sn(λt, k), ω_3 = ω_3 dn(λt, k) with
// A_2² = (2E I_3 − L²)/(I_2 (I_3 − I_2)), λ² = (I_3 − I_2)(L² − 2E I_1)/(I_1 I_2 I_3),
// k² = (I_2 − I_1)(2E I_3 − L²)/((I_3 − I_2)(L² − 2E I_1)) (Landau & Lifshitz, Mechanics
// §37). Returns the error of the body-frame angular velocity at t_end.
double asymmetric_top_error(double dt, FreeRotationScheme scheme, double t_end = 10.0) {
  const Vector3d moments(1.0, 2.0, 3.0), omega0(1.0, 0.0, 0.8);
  RigidRotation body = RigidRotation::from_angular_velocity(moments, kTilted, kTilted * omega0);
  const long steps = std::lround(t_end / dt);
  for (long n = 0; n < steps; ++n) body.rotate_free(dt, scheme);
  const double t = steps * dt;
  const Vector3d pi0 = moments.cwiseProduct(omega0);
  const double l2 = pi0.squaredNorm(), two_e = pi0.dot(omega0);
  const double i1 = moments[0], i2 = moments[1], i3 = moments[2];
  const double lambda = std::sqrt((i3 - i2) * (l2 - two_e * i1) / (i1 * i2 * i3));
  const double m = (i2 - i1) * (two_e * i3 - l2) / ((i3 - i2) * (l2 - two_e * i1));
  const double a2 = std::sqrt((two_e * i3 - l2) / (i2 * (i3 - i2)));
  double sn, cn, dn;
  gsl_sf_elljac_e(lambda * t, m, &sn, &cn, &dn);
  const Vector3d exact(omega0[0] * cn, a2 * sn, omega0[2] * dn);
  return (body.angular_velocity_body() - exact).norm();
}

}  // namespace

// Torque-free tops: the space-frame angular momentum is untouched by the free rotation,
// |π| = |L| (the quaternion stays unit), and the energy error stays bounded. Moments of a
// solid ellipsoid with the grains' axis ratios (1, 0.8, 0.6): I ∝ (b² + c², a² + c²,
// a² + b²), and the strongly anisotropic (1, 2, 3).
TEST(RigidRotation, TorqueFreeConservation) {
  struct Case {
    Vector3d moments;
    double dt;
  };
  for (const Case& c : {Case{Vector3d(1.0, 1.36, 1.64), 1e-3}, Case{Vector3d(1.0, 2.0, 3.0), 5e-4}}) {
    for (auto scheme : {FreeRotationScheme::splitting2, FreeRotationScheme::splitting4}) {
      RigidRotation body = RigidRotation::from_angular_velocity(c.moments, kTilted,
                                                                kTilted * Vector3d(1.0, 0.5, 0.8));
      const double energy = body.kinetic_energy();
      const Vector3d momentum = body.angular_momentum();
      double energy_error = 0.0, momentum_error = 0.0, unit_error = 0.0;
      for (int n = 0; n < 10000; ++n) {
        body.rotate_free(c.dt, scheme);
        energy_error = std::max(energy_error, std::abs(body.kinetic_energy() - energy) / energy);
        momentum_error = std::max(momentum_error,
                                  std::abs(body.angular_momentum_body().norm() - momentum.norm()) /
                                      momentum.norm());
        unit_error = std::max(unit_error, std::abs(body.orientation().norm() - 1.0));
      }
      std::printf("I = (%g, %g, %g), %s, dt = %g, 1e4 steps: max |dE|/E = %.2e, "
                  "max ||pi| - |L0||/|L0| = %.2e\n",
                  c.moments[0], c.moments[1], c.moments[2],
                  scheme == FreeRotationScheme::splitting2 ? "splitting2" : "splitting4", c.dt,
                  energy_error, momentum_error);
      EXPECT_LT(energy_error, scheme == FreeRotationScheme::splitting2 ? 1e-8 : 1e-12);
      EXPECT_LT(momentum_error, 1e-13);
      EXPECT_LT(unit_error, 1e-15);
      EXPECT_EQ(body.angular_momentum(), momentum);
    }
  }
}

// Observed orders of the angular-velocity error against the analytic asymmetric top.
TEST(RigidRotation, OrderAgainstAsymmetricTop) {
  const double e2a = asymmetric_top_error(0.02, FreeRotationScheme::splitting2);
  const double e2b = asymmetric_top_error(0.01, FreeRotationScheme::splitting2);
  const double e4a = asymmetric_top_error(0.04, FreeRotationScheme::splitting4);
  const double e4b = asymmetric_top_error(0.02, FreeRotationScheme::splitting4);
  const double order2 = std::log2(e2a / e2b), order4 = std::log2(e4a / e4b);
  std::printf("asymmetric top, |omega(10) - exact|: splitting2 %.2e (dt 0.02), %.2e (dt 0.01), "
              "order %.3f; splitting4 %.2e (dt 0.04), %.2e (dt 0.02), order %.3f\n",
              e2a, e2b, order2, e4a, e4b, order4);
  EXPECT_NEAR(order2, 2.0, 0.1);
  EXPECT_NEAR(order4, 4.0, 0.2);
}

// A symmetric top (I_1 = I_2) is integrated exactly: the body-frame angular velocity
// precesses about e_3 at Ω = ω_3 (I_3 − I_1)/I_1 and R(t) = Rot(L̂, |L| t/I_1) R_0
// Rot(e_3, −Ω t) (then ω_body = π/I_1 − Ω e_3 = π/I); for an oblate (I_3 > I_1) and a
// prolate (I_3 < I_1) top.
TEST(RigidRotation, SymmetricTopIsExact) {
  const Vector3d omega_body(0.6, -0.3, 1.2);
  const double dt = 0.05;
  const int steps = 400;
  for (double i3 : {2.5, 0.4}) {
    const Vector3d moments(1.0, 1.0, i3);
    RigidRotation body = RigidRotation::from_angular_velocity(moments, kTilted, kTilted * omega_body);
    for (int n = 0; n < steps; ++n) body.rotate_free(dt);
    const double t = steps * dt;
    const Vector3d l = body.angular_momentum();
    const double precession = omega_body[2] * (i3 - 1.0);
    const Quaterniond exact = Quaterniond(AngleAxisd(l.norm() * t, l.normalized())) * kTilted *
                              Quaterniond(AngleAxisd(-precession * t, Vector3d::UnitZ()));
    EXPECT_LT(angle_between(body.orientation(), exact), 1e-12) << "I_3 = " << i3;
  }
}

// Dzhanibekov effect: spun about the intermediate axis (I_1 < I_2 < I_3) with a small
// perturbation, ω_2 reverses. From ω(0) = (0, ω_2, ε) the exact solution is
// ω_2 = ω_2 sn(τ + K), τ = λ t, λ² = (I_3 − I_2)(L² − 2E I_1)/(I_1 I_2 I_3),
// k² = (I_2 − I_1)(2E I_3 − L²)/((I_3 − I_2)(L² − 2E I_1)) (Landau & Lifshitz,
// Mechanics §37), so ω_2 first vanishes at t = K(k)/λ.
TEST(RigidRotation, IntermediateAxisFlips) {
  const Vector3d moments(1.0, 2.0, 3.0);
  const double epsilon = 1e-3;
  const Vector3d omega0(0.0, 1.0, epsilon);
  RigidRotation body = RigidRotation::from_angular_velocity(moments, kTilted, kTilted * omega0);
  const Vector3d pi0 = moments.cwiseProduct(omega0);
  const double l2 = pi0.squaredNorm(), two_e = pi0.dot(omega0);
  const double lambda = std::sqrt((moments[2] - moments[1]) * (l2 - two_e * moments[0]) /
                                  (moments[0] * moments[1] * moments[2]));
  const double k2 = (moments[1] - moments[0]) * (two_e * moments[2] - l2) /
                    ((moments[2] - moments[1]) * (l2 - two_e * moments[0]));
  const double t_flip = gsl_sf_ellint_Kcomp(std::sqrt(k2), GSL_PREC_DOUBLE) / lambda;

  const double dt = 1e-3, energy = body.kinetic_energy();
  double previous = body.angular_velocity_body()[1], t_zero = -1.0, lowest = previous;
  double energy_error = 0.0;
  for (int n = 1; n <= 20000; ++n) {
    body.rotate_free(dt);
    const double w2 = body.angular_velocity_body()[1];
    if (t_zero < 0.0 && previous > 0.0 && w2 <= 0.0) t_zero = (n - 1 + previous / (previous - w2)) * dt;
    lowest = std::min(lowest, w2);
    previous = w2;
    energy_error = std::max(energy_error, std::abs(body.kinetic_energy() - energy) / energy);
  }
  std::printf("intermediate axis: omega_2 first zero at t = %.6f, analytic %.6f; min omega_2 %.6f\n",
              t_zero, t_flip, lowest);
  ASSERT_GT(t_zero, 0.0) << "omega_2 never changed sign";
  EXPECT_LT(std::abs(t_zero - t_flip) / t_flip, 1e-4);
  EXPECT_LT(lowest, -0.999);  // a full flip: ω_2 → −ω_2
  EXPECT_LT(energy_error, 1e-8);
}

// Spun about the smallest or the largest axis, the body stays: the spin component keeps
// its sign and the transverse momentum stays within the bound set by E and |L|:
// about I_3, π_1² + π_2² <= (2E − L²/I_3)/(1/I_2 − 1/I_3); about I_1,
// π_2² + π_3² <= (L²/I_1 − 2E)/(1/I_1 − 1/I_2).
TEST(RigidRotation, ExtremeAxesAreStable) {
  const Vector3d moments(1.0, 2.0, 3.0);
  const double epsilon = 0.01;
  for (int axis : {0, 2}) {
    Vector3d omega0 = Vector3d::Constant(epsilon);
    omega0[axis] = 1.0;
    RigidRotation body = RigidRotation::from_angular_velocity(moments, kTilted, kTilted * omega0);
    const Vector3d pi0 = moments.cwiseProduct(omega0);
    const double l2 = pi0.squaredNorm(), two_e = pi0.dot(omega0);
    const double bound = axis == 2 ? (two_e - l2 / moments[2]) / (1.0 / moments[1] - 1.0 / moments[2])
                                   : (l2 / moments[0] - two_e) / (1.0 / moments[0] - 1.0 / moments[1]);
    double largest = 0.0, smallest_spin = 1e300;
    for (int n = 0; n < 20000; ++n) {
      body.rotate_free(1e-3);
      const Vector3d pi = body.angular_momentum_body();
      largest = std::max(largest, pi.squaredNorm() - pi[axis] * pi[axis]);
      smallest_spin = std::min(smallest_spin, pi[axis]);
    }
    std::printf("axis %d: max transverse |pi| %.4e, bound %.4e, |L| %.4f\n", axis + 1,
                std::sqrt(largest), std::sqrt(bound), std::sqrt(l2));
    EXPECT_GT(smallest_spin, 0.0) << "axis " << axis;
    EXPECT_LE(largest, bound * (1.0 + 1e-6)) << "axis " << axis;
    EXPECT_LT(std::sqrt(bound), 0.05 * std::sqrt(l2)) << "axis " << axis;
  }
}

// The splitting is symmetric: stepping back with −dt retraces the trajectory.
TEST(RigidRotation, TimeReversible) {
  RigidRotation body = RigidRotation::from_angular_velocity(Vector3d(0.4, 1.1, 1.3), kTilted,
                                                            Vector3d(0.3, -2.0, 1.0));
  const Quaterniond start = body.orientation();
  for (int n = 0; n < 1000; ++n) body.step(Vector3d(0.1, 0.0, -0.2), 2e-3);
  EXPECT_GT(angle_between(body.orientation(), start), 0.5);
  for (int n = 0; n < 1000; ++n) body.step(Vector3d(0.1, 0.0, -0.2), -2e-3);
  EXPECT_LT(angle_between(body.orientation(), start), 1e-12);
  EXPECT_LT((body.angular_velocity() - Vector3d(0.3, -2.0, 1.0)).norm(), 1e-12);
}

// Isotropic body under a constant torque parallel to L: L = L_0 + T t, and the body turns
// about the fixed axis by θ = (L_0 t + T t²/2)/I, which kick–rotate–kick reproduces
// exactly (the midpoint momentum integrates a linear ω exactly).
TEST(RigidRotation, ConstantTorqueOnIsotropicBody) {
  const double inertia = 0.8, l0 = 0.5, torque = 0.3, dt = 1e-2;
  const Vector3d axis = Vector3d(1.0, 2.0, -1.0).normalized();
  RigidRotation body(Vector3d::Constant(inertia), kTilted, l0 * axis);
  const int steps = 500;
  for (int n = 0; n < steps; ++n) body.step(torque * axis, dt);
  const double t = steps * dt;
  const double theta = (l0 * t + 0.5 * torque * t * t) / inertia;
  EXPECT_LT((body.angular_momentum() - (l0 + torque * t) * axis).norm(), 1e-13);
  EXPECT_LT(angle_between(body.orientation(), Quaterniond(AngleAxisd(theta, axis)) * kTilted), 1e-11);
}

// Space-frame tensors agree with the body-frame definitions.
TEST(RigidRotation, SpaceFrameInertia) {
  const Vector3d moments(0.5, 1.5, 2.0), omega(0.2, -1.0, 0.7);
  const RigidRotation body = RigidRotation::from_angular_velocity(moments, kTilted, omega);
  EXPECT_LT((body.angular_velocity() - omega).norm(), 1e-14);
  EXPECT_LT((body.inertia_space() * omega - body.angular_momentum()).norm(), 1e-14);
  EXPECT_LT((body.inverse_inertia_space() * body.inertia_space() - Matrix3d::Identity()).norm(), 1e-14);
  EXPECT_NEAR(body.kinetic_energy(), 0.5 * omega.dot(body.inertia_space() * omega), 1e-14);
}

// Velocity Verlet pieces are exact under a constant force: x = x0 + v0 t + F t²/(2m).
TEST(RigidTranslation, ConstantForceIsExact) {
  RigidTranslation body(2.0, Vector3d(1.0, 0.0, 0.0), Vector3d(0.0, 1.0, 0.5));
  const Vector3d force(0.0, 0.0, -3.0);
  const double dt = 1e-2;
  for (int n = 0; n < 100; ++n) {
    body.kick(force, 0.5 * dt);
    body.drift(dt);
    body.kick(force, 0.5 * dt);
  }
  const double t = 1.0;
  EXPECT_LT((body.position() - (Vector3d(1.0, 0.0, 0.0) + Vector3d(0.0, 1.0, 0.5) * t +
                                force / 2.0 * t * t / 2.0)).norm(), 1e-13);
  EXPECT_LT((body.velocity() - (Vector3d(0.0, 1.0, 0.5) + force / 2.0 * t)).norm(), 1e-13);
}

TEST(RigidRotation, BadInputThrows) {
  const auto expect_argument = [](auto&& f, const std::string& argument) {
    try {
      f();
      ADD_FAILURE() << "no InvalidArgument for " << argument;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.argument(), argument) << e.what();
    }
  };
  expect_argument([] { RigidRotation(Vector3d(1.0, 0.0, 1.0), kTilted, Vector3d::Zero()); },
                  "principal_moments");
  expect_argument([] { RigidRotation(Vector3d(1.0, 1.0, 1.0), Quaterniond(0, 0, 0, 0), Vector3d::Zero()); },
                  "orientation");
  expect_argument([] { RigidRotation(Vector3d::Ones(), kTilted, Vector3d::Zero()).rotate_free(NAN); },
                  "dt");
  expect_argument([] { RigidTranslation(-1.0, Vector3d::Zero(), Vector3d::Zero()); }, "mass");
}
