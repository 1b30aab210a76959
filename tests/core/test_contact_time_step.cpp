// The stability limits of a soft contact (core/contact/contact_time_step.h) against
// independent computations: the period of a mass on a spring, and the growth of a
// damped oscillator integrated step by step with velocity Verlet (written out here) and
// with the core's gear5 kernels.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/common/errors.h"
#include "core/contact/contact_laws.h"
#include "core/contact/contact_time_step.h"
#include "core/contact/soft_contact.h"
#include "core/wire/gear_integrator.h"

using namespace wiregrain;

namespace {
constexpr double kPi = 3.14159265358979323846;

// x'' = −ω² x − 2ζω v from x = 1, v = 0 over `steps` steps of ω dt = omega_dt (ω = 1);
// returns the largest |x| of the last tenth of the steps (∞ once it overflows).
double late_amplitude(bool gear, double zeta, double omega_dt, long steps) {
  const double dt = omega_dt;
  double x[3] = {1.0, 0.0, 0.0}, v[3] = {0.0, 0.0, 0.0}, a[3], h[kGearHistorySize];
  const auto acceleration = [&](const double *p, const double *u, double *out) {
    for (int d = 0; d < 3; ++d) out[d] = -p[d] - 2.0 * zeta * u[d];
  };
  acceleration(x, v, a);
  gear5_start(h, a);
  const GearCorrector corrector(GearCoefficients::position_forces(), dt);
  double largest = 0.0;
  for (long n = 0; n < steps; ++n) {
    if (gear) {
      gear5_predict(x, v, h, dt);
      acceleration(x, v, a);
      gear5_correct(x, v, h, a, corrector);
    } else {
      // velocity Verlet as LIGGGHTS runs it: the force of the new positions sees the
      // half-step velocity
      for (int d = 0; d < 3; ++d) {
        v[d] += 0.5 * dt * a[d];
        x[d] += dt * v[d];
      }
      acceleration(x, v, a);
      for (int d = 0; d < 3; ++d) v[d] += 0.5 * dt * a[d];
    }
    if (!std::isfinite(x[0])) return std::numeric_limits<double>::infinity();
    if (n >= steps - steps / 10) largest = std::max(largest, std::abs(x[0]));
  }
  return largest;
}
}  // namespace

// Undamped: dt_crit = 2/ω = T/π with T = 2π √(m/k) the period of the mass on the spring;
// the gear5 limit is fix wire/elastic's fraction 0.313/2 of it.
TEST(ContactTimeStep, UndampedIsThePeriodOverPi) {
  const double k = 7.853981633974483, m = 0.0015707963267948967;  // Table 1 wire–wire, half a bead
  const double period = 2.0 * kPi * std::sqrt(m / k);
  const ContactTimeStep t = spring_dashpot_time_step(k, m, 0.0);
  EXPECT_NEAR(t.critical, period / kPi, 1e-15);
  EXPECT_NEAR(t.gear5, 0.313 * period / (2.0 * kPi), 1e-15);
  EXPECT_NEAR(t.gear5, 0.00442649, 1e-8);  // bench/stress_matrix.py's figure 0.00443
  EXPECT_EQ(t.limit(false), t.critical);
  EXPECT_EQ(t.limit(true), t.gear5);
}

// Damped, velocity Verlet: just below dt_crit the oscillator stays bounded, just above it
// grows; for every ζ, strong damping included.
TEST(ContactTimeStep, VerletBoundOfDampedOscillator) {
  for (double zeta : {0.0, 0.1, 0.2154, 0.5, 1.0, 3.0}) {
    const double limit = spring_dashpot_time_step(1.0, 1.0, zeta).critical;  // ω = 1: ω dt
    EXPECT_NEAR(limit, 2.0 * (std::sqrt(1.0 + zeta * zeta) - zeta), 1e-14) << zeta;
    EXPECT_LE(late_amplitude(false, zeta, 0.99 * limit, 20000), 1.0 + 1e-6) << zeta;
    EXPECT_GT(late_amplitude(false, zeta, 1.01 * limit, 20000), 1e3) << zeta;
  }
}

// Damped, 6-value Gear: stable below the limit for every ζ; where the damping bound
// ζ ω dt < 0.075 decides (ζ ≥ 0.5) it is within 15 % of the measured instability.
TEST(ContactTimeStep, Gear5BoundOfDampedOscillator) {
  for (double zeta : {0.0, 0.05, 0.1, 0.2154, 0.3, 0.4, 0.5, 1.0, 2.0}) {
    const double limit = spring_dashpot_time_step(1.0, 1.0, zeta).gear5;
    EXPECT_LE(late_amplitude(true, zeta, 0.97 * limit, 40000), 1.0 + 1e-6) << zeta;
  }
  for (double zeta : {0.5, 1.0, 2.0}) {
    const double limit = spring_dashpot_time_step(1.0, 1.0, zeta).gear5;
    EXPECT_NEAR(limit, kGear5StableDampedOmegaDt / zeta, 1e-15) << zeta;
    EXPECT_GT(late_amplitude(true, zeta, 1.15 * limit, 40000), 1.0) << zeta;
  }
  // ζ = 0: the bound of the harmonic mode (test_gear_integrator.cpp), ω dt < 0.313
  EXPECT_GT(late_amplitude(true, 0.0, 1.03 * spring_dashpot_time_step(1.0, 1.0, 0.0).gear5, 200000), 1.05);
}

// A contact law: the stiffer spring and the law's ζ; ω scales with √(k/m).
TEST(ContactTimeStep, ContactLawTakesTheStifferSpring) {
  ContactFriction damped;
  damped.damping_ratio = damping_ratio_from_restitution(0.5);
  // Table 1 wall: E* = 100, l = 0.2, r = 0.1: k_n = 5π > k_t = 10
  const SoftContactLaw wall = segment_contact_law(wire_wall_modulus(ElasticMaterial()), 0.2, 0.1, damped);
  const double bead = 0.5 * kPi * 0.01 * 0.2;
  const ContactTimeStep t = contact_time_step(wall, bead);
  const ContactTimeStep normal = spring_dashpot_time_step(wall.normal_stiffness, bead, damped.damping_ratio);
  EXPECT_EQ(t.critical, normal.critical);
  EXPECT_EQ(t.gear5, normal.gear5);
  // ζ = 0.2154 (e = 0.5): √(1 + ζ²) − ζ = 0.8075
  EXPECT_NEAR(t.gear5 / spring_dashpot_time_step(wall.normal_stiffness, bead, 0.0).gear5, 0.80749, 1e-5);
  // a short segment (l = 0.05 < 4r/π): k_t = 10 > k_n = 1.25π
  const SoftContactLaw short_segment = segment_contact_law(wire_wall_modulus(ElasticMaterial()), 0.05, 0.1, {});
  EXPECT_EQ(contact_time_step(short_segment, bead).critical, 2.0 / std::sqrt(10.0 / bead));
  // four times the mass: twice the step
  EXPECT_NEAR(contact_time_step(wall, 4.0 * bead).critical, 2.0 * t.critical, 1e-15);
}

TEST(ContactTimeStep, ReducedMassAndLimits) {
  EXPECT_DOUBLE_EQ(reduced_mass(2.0, 2.0), 1.0);
  EXPECT_DOUBLE_EQ(reduced_mass(1.0, 3.0), 0.75);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(reduced_mass(0.3, inf), 0.3);
  EXPECT_EQ(reduced_mass(inf, 0.3), 0.3);
  EXPECT_TRUE(std::isinf(spring_dashpot_time_step(0.0, 1.0, 0.5).critical));
  EXPECT_TRUE(std::isinf(spring_dashpot_time_step(0.0, 1.0, 0.5).gear5));
  EXPECT_THROW(spring_dashpot_time_step(-1.0, 1.0, 0.0), InvalidArgument);
  EXPECT_THROW(spring_dashpot_time_step(1.0, 0.0, 0.0), InvalidArgument);
  EXPECT_THROW(spring_dashpot_time_step(1.0, 1.0, -0.1), InvalidArgument);
  EXPECT_THROW(spring_dashpot_time_step(1.0, 1.0, std::nan("")), InvalidArgument);
}

// The springs and dashpots summed on one bead (bead_contact_time_step), against beads
// integrated step by step with the core's gear5 kernels.
namespace {
using Beads = std::vector<Eigen::Vector3d>;
// Beads of mass m under linear forces force(x, v, f), at rest at x_j = s_j (1, −0.6, 0.3)
// with s = (1, −0.6, 0.3, −0.6, 0.3, …); the largest |x| component of the last tenth of the
// steps (∞ once it overflows). Modes that no force holds keep their share of the start,
// which stays below 1 for the systems below.
template <class Force>
double late_amplitude_of_beads(std::size_t n, double m, double dt, long steps, Force force) {
  Beads x(n), v(n, Eigen::Vector3d::Zero()), f(n);
  for (std::size_t j = 0; j < n; ++j) x[j] = (j == 0 ? 1.0 : (j % 2 ? -0.6 : 0.3)) * Eigen::Vector3d(1.0, -0.6, 0.3);
  std::vector<std::array<double, kGearHistorySize>> h(n);
  const auto accelerations = [&]() {
    force(x, v, f);
    for (Eigen::Vector3d &fj : f) fj /= m;
  };
  accelerations();
  for (std::size_t j = 0; j < n; ++j) gear5_start(h[j].data(), f[j].data());
  const GearCorrector corrector(GearCoefficients::position_forces(), dt);
  double largest = 0.0;
  for (long s = 0; s < steps; ++s) {
    for (std::size_t j = 0; j < n; ++j) gear5_predict(x[j].data(), v[j].data(), h[j].data(), dt);
    accelerations();
    for (std::size_t j = 0; j < n; ++j) gear5_correct(x[j].data(), v[j].data(), h[j].data(), f[j].data(), corrector);
    for (const Eigen::Vector3d &xj : x) {
      if (!xj.allFinite()) return std::numeric_limits<double>::infinity();
      if (s >= steps - steps / 10) largest = std::max(largest, xj.cwiseAbs().maxCoeff());
    }
  }
  return largest;
}

// Contacts along one axis: contact c has the gap g_c = Σ_j w_cj x_j and pushes bead j by
// −w_cj (k g_c + γ ġ_c) (each component alike).
double late_amplitude_of_beads(const std::vector<std::vector<double>> &weights, double k, double gamma, double m,
                               double dt, long steps) {
  return late_amplitude_of_beads(weights.front().size(), m, dt, steps, [&](const Beads &x, const Beads &v, Beads &f) {
    for (Eigen::Vector3d &fj : f) fj.setZero();
    for (const std::vector<double> &w : weights) {
      Eigen::Vector3d gap = Eigen::Vector3d::Zero(), rate = Eigen::Vector3d::Zero();
      for (std::size_t j = 0; j < w.size(); ++j) gap += w[j] * x[j], rate += w[j] * v[j];
      for (std::size_t j = 0; j < w.size(); ++j) f[j] -= w[j] * (k * gap + gamma * rate);
    }
  });
}
}  // namespace

// contact_spring_dashpot's γ is the damping soft_contact_force applies: at zero overlap
// a closing speed u gives f_n = γ u (the normal spring is the stiffer one here).
TEST(ContactTimeStep, SpringDashpotOfALawIsItsForce) {
  ContactFriction damped;
  damped.damping_ratio = damping_ratio_from_restitution(0.5);
  damped.static_friction = damped.dynamic_friction = 10.0;  // the tangential test sticks
  const SoftContactLaw wall = segment_contact_law(wire_wall_modulus(ElasticMaterial()), 0.2, 0.1, damped);
  const double m = 0.5 * kPi * 0.01 * 0.2;
  const SpringDashpot sd = contact_spring_dashpot(wall, m);
  EXPECT_EQ(sd.normal_stiffness, wall.normal_stiffness);
  EXPECT_EQ(sd.tangential_stiffness, wall.tangential_stiffness);
  // the normal dashpot: f_n at zero overlap; the tangential one: the trial f_t of a
  // sticking contact with a zero spring after a step of dt = 0 (no spring growth)
  TangentialHistory history;
  const double u = 0.37;
  const SoftContactForce f = soft_contact_force(wall, 0.0, Eigen::Vector3d::UnitZ(), Eigen::Vector3d(0, 0, -u), 1e-3, m, history);
  EXPECT_NEAR(f.normal_force, sd.normal_damping * u, 1e-14);
  TangentialHistory sticking;
  const SoftContactForce t = soft_contact_force(wall, 0.01, Eigen::Vector3d::UnitZ(), Eigen::Vector3d(u, 0, 0), 0.0, m, sticking);
  EXPECT_NEAR(t.tangential_force, sd.tangential_damping * u, 1e-14);
  // one contact on one bead: the limits of that spring–dashpot (the normal spring is the stiffer)
  BeadContactLoad load;
  load.add(1.0, sd, Eigen::Vector3d(0.6, 0.0, 0.8));
  const ContactTimeStep one = bead_contact_time_step(load, m);
  const ContactTimeStep law = contact_time_step(wall, m);
  EXPECT_NEAR(one.gear5, law.gear5, 1e-15);
  EXPECT_NEAR(one.critical, law.critical, 1e-15);
  EXPECT_TRUE(std::isinf(bead_contact_time_step(BeadContactLoad(), m).gear5));
  EXPECT_THROW(bead_contact_time_step(1.0, -1.0, 1.0), InvalidArgument);
  EXPECT_THROW(bead_contact_time_step(1.0, 1.0, 0.0), InvalidArgument);
  EXPECT_TRUE(std::isinf(bead_contact_time_step(0.0, 0.0, 1.0).gear5));
}

// Strongly damped contacts (e = 0.1: the damping bound of Gear decides), k = 1, m = 1:
// - a bead pressed by six bodies (both its segments against three grains, the load at the
//   bead: weights 1), K = 6k, Γ = 6γ;
// - two beads of a segment loaded at its middle (weights ½, ½): each K = k/2, Γ = γ/2;
// - two segments of two beads each touching at their middles (weights ∓½): each K = k, Γ = γ.
// Each system is stable at 0.97 of the bead's limit and grows at 1.15 of it; the single
// contact's own limit (contact_time_step) would let the wedged bead run a step 6 times too
// long (the damping decides both: Γ/(2m) is six times γ/(2m)).
TEST(ContactTimeStep, BeadLimitOfSummedContacts) {
  const double zeta = damping_ratio_from_restitution(0.1), k = 1.0, m = 1.0;
  const double gamma = 2.0 * zeta * std::sqrt(k * m);
  struct Case {
    const char *name;
    std::vector<std::vector<double>> weights;
    double bead_stiffness, bead_damping;  // w S k and w S γ summed (contact_time_step.h)
  };
  const std::vector<Case> cases = {
      {"wedged bead", std::vector<std::vector<double>>(6, {1.0}), 6.0 * k, 6.0 * gamma},
      {"segment loaded at its middle", {{0.5, 0.5}}, 0.5 * k, 0.5 * gamma},
      {"two segments touching", {{-0.5, -0.5, 0.5, 0.5}}, 2.0 * 0.5 * k, 2.0 * 0.5 * gamma},
  };
  for (const Case &c : cases) {
    const double limit = bead_contact_time_step(c.bead_stiffness, c.bead_damping, m).gear5;
    EXPECT_LE(late_amplitude_of_beads(c.weights, k, gamma, m, 0.97 * limit, 40000), 1.0 + 1e-6) << c.name;
    EXPECT_GT(late_amplitude_of_beads(c.weights, k, gamma, m, 1.15 * limit, 40000), 1.0) << c.name;
  }
  const double single = spring_dashpot_time_step(k, m, zeta).gear5;
  EXPECT_NEAR(single / bead_contact_time_step(6.0 * k, 6.0 * gamma, m).gear5, 6.0, 1e-12);
}

// Contacts in different directions do not add up along one: a bead pressed by three walls
// with orthogonal normals and two along the same normal (strong damping, k_t = k_n / 2),
// integrated in 3-D with the gear5 kernels, is stable at 0.97 of the limit from the
// largest eigenvalues of K and Γ and grows at 1.15 of it; the five contacts summed as if
// parallel would have asked for a step 1.21 times shorter.
TEST(ContactTimeStep, BeadLimitTakesTheStiffestDirection) {
  const double zeta = damping_ratio_from_restitution(0.1), m = 1.0;
  SpringDashpot contact;
  contact.normal_stiffness = 1.0;
  contact.tangential_stiffness = 0.5;
  contact.normal_damping = 2.0 * zeta * std::sqrt(contact.normal_stiffness * m);
  contact.tangential_damping = 2.0 * zeta * std::sqrt(contact.tangential_stiffness * m);
  const std::vector<Eigen::Vector3d> normals = {Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitX(),
                                                Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(),
                                                Eigen::Vector3d::UnitZ()};
  BeadContactLoad load;
  for (const Eigen::Vector3d &n : normals) load.add(1.0, contact, n);
  EXPECT_EQ(load.contacts, 5);
  const double limit = bead_contact_time_step(load, m).gear5;
  // by hand: K = diag(2 k_n + 3 k_t, k_n + 4 k_t, 2 k_n + 3 k_t) = diag(3.5, 3, 3.5), Γ the
  // same with the γ's: λ_max(Γ) = 2 γ_n + 3 γ_t
  const double largest_damping = 2.0 * contact.normal_damping + 3.0 * contact.tangential_damping;
  EXPECT_NEAR(limit, bead_contact_time_step(3.5, largest_damping, m).gear5, 1e-14);
  const auto late = [&](double dt) {
    return late_amplitude_of_beads(1, m, dt, 40000, [&](const Beads &x, const Beads &v, Beads &f) {
      f[0] = -(load.stiffness * x[0] + load.damping * v[0]);
    });
  };
  EXPECT_LE(late(0.97 * limit), 1.0 + 1e-6);
  EXPECT_GT(late(1.15 * limit), 1.0);
  // the five stiffer springs summed as if parallel: the damping decides both limits
  const double scalar = bead_contact_time_step(5.0 * contact.normal_stiffness, 5.0 * contact.normal_damping, m).gear5;
  EXPECT_NEAR(limit / scalar, 5.0 / (2.0 + 3.0 / std::sqrt(2.0)), 1e-12);
}

// The trace bound never exceeds the bead's limit (K, Γ positive semi-definite: λ_max ≤
// trace) and equals it for contacts along one direction with k_t = 0.
TEST(ContactTimeStep, TraceBoundIsBelowTheBeadLimit) {
  SpringDashpot contact;
  contact.normal_stiffness = 15.7;
  contact.tangential_stiffness = 10.0;
  contact.normal_damping = 0.26;
  contact.tangential_damping = 0.21;
  const double m = 0.00314;
  std::uint64_t state = 12345;
  const auto uniform = [&]() {  // xorshift64*: the same numbers on every platform
    state ^= state >> 12, state ^= state << 25, state ^= state >> 27;
    return double((state * 2685821657736338717ULL) >> 11) / double(1ULL << 53);
  };
  for (int trial = 0; trial < 200; ++trial) {
    BeadContactLoad load;
    const int contacts = 1 + trial % 12;
    for (int c = 0; c < contacts; ++c) {
      const Eigen::Vector3d n = Eigen::Vector3d(uniform() - 0.5, uniform() - 0.5, uniform() - 0.5).normalized();
      load.add(2.0 * uniform(), contact, n);
    }
    for (bool gear : {true, false})
      EXPECT_LE(bead_contact_time_step_bound(load, m).limit(gear), bead_contact_time_step(load, m).limit(gear) * (1 + 1e-12));
  }
  SpringDashpot normal_only = contact;
  normal_only.tangential_stiffness = normal_only.tangential_damping = 0.0;
  BeadContactLoad aligned;
  aligned.add(1.0, normal_only, Eigen::Vector3d::UnitZ());
  aligned.add(0.5, normal_only, -Eigen::Vector3d::UnitZ());
  EXPECT_NEAR(bead_contact_time_step_bound(aligned, m).gear5, bead_contact_time_step(aligned, m).gear5, 1e-15);
}
