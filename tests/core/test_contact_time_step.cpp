// The stability limits of a soft contact (core/contact/contact_time_step.h) against
// independent computations: the period of a mass on a spring, and the growth of a
// damped oscillator integrated step by step with velocity Verlet (written out here) and
// with the core's gear5 kernels.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/common/errors.h"
#include "core/contact/contact_laws.h"
#include "core/contact/contact_time_step.h"
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
  const SoftContactLaw wall = wire_wall_contact_law(ElasticMaterial(), 0.2, 0.1, damped);
  const double bead = 0.5 * kPi * 0.01 * 0.2;
  const ContactTimeStep t = contact_time_step(wall, bead);
  const ContactTimeStep normal = spring_dashpot_time_step(wall.normal_stiffness, bead, damped.damping_ratio);
  EXPECT_EQ(t.critical, normal.critical);
  EXPECT_EQ(t.gear5, normal.gear5);
  // ζ = 0.2154 (e = 0.5): √(1 + ζ²) − ζ = 0.8075
  EXPECT_NEAR(t.gear5 / spring_dashpot_time_step(wall.normal_stiffness, bead, 0.0).gear5, 0.80749, 1e-5);
  // a short segment (l = 0.05 < 4r/π): k_t = 10 > k_n = 1.25π
  const SoftContactLaw short_segment = wire_wall_contact_law(ElasticMaterial(), 0.05, 0.1, {});
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
