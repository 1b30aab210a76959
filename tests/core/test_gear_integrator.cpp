// Gear predictor–corrector and velocity Verlet on problems with known solutions.
#include <gtest/gtest.h>

#include <cmath>

#include "core/wire/gear_integrator.h"

using namespace wiregrain;

namespace {

// x'' = -ω² x from x(0)=1, v(0)=0, integrated to t_end; returns |x - cos ωt| at t_end.
double oscillator_error(bool gear, double dt, double t_end, double omega = 1.0) {
  double x[3] = {1.0, 0.0, 0.0}, v[3] = {0.0, 0.0, 0.0}, h[kGearHistorySize];
  const auto acc = [&](const double* p, double* a) {
    for (int d = 0; d < 3; ++d) a[d] = -omega * omega * p[d];
  };
  double a[3];
  acc(x, a);
  gear5_start(h, a);
  const long steps = std::lround(t_end / dt);
  const GearCorrector c(GearCoefficients::position_forces(), dt);
  for (long n = 0; n < steps; ++n) {
    if (gear) {
      gear5_predict(x, v, h, dt);
      acc(x, a);
      gear5_correct(x, v, h, a, c);
    } else {
      verlet_kick_drift(x, v, a, dt);
      acc(x, a);
      verlet_kick(v, a, dt);
    }
  }
  return std::abs(x[0] - std::cos(omega * steps * dt));
}

}  // namespace

// Under a constant acceleration both schemes are exact: x = x0 + v0 t + g t²/2.
TEST(GearIntegrator, ConstantAccelerationIsExact) {
  for (bool gear : {true, false}) {
    double x[3] = {0.5, -1.0, 2.0}, v[3] = {0.3, 0.0, -0.7}, h[kGearHistorySize];
    const double g[3] = {0.0, 0.0, -9.81}, x0[3] = {0.5, -1.0, 2.0}, v0[3] = {0.3, 0.0, -0.7};
    gear5_start(h, g);
    const double dt = 1e-3;
    const int steps = 2000;
    for (int n = 0; n < steps; ++n) {
      if (gear) {
        gear5_predict(x, v, h, dt);
        gear5_correct(x, v, h, g, GearCorrector(GearCoefficients::position_forces(), dt));
      } else {
        verlet_kick_drift(x, v, g, dt);
        verlet_kick(v, g, dt);
      }
    }
    const double t = steps * dt;
    // round-off only: a few ulps of the value per step
    const double roundoff = 4.0 * steps * 2.2e-16 * 25.0;
    for (int d = 0; d < 3; ++d) {
      EXPECT_NEAR(x[d], x0[d] + v0[d] * t + 0.5 * g[d] * t * t, roundoff) << "gear=" << gear;
      EXPECT_NEAR(v[d], v0[d] + g[d] * t, roundoff) << "gear=" << gear;
    }
  }
}

// Velocity Verlet is second order: halving dt divides the phase error by 4.
TEST(GearIntegrator, VerletIsSecondOrder) {
  const double e1 = oscillator_error(false, 0.02, 10.0);
  const double e2 = oscillator_error(false, 0.01, 10.0);
  const double order = std::log2(e1 / e2);
  EXPECT_NEAR(order, 2.0, 0.05);
}

// The 6-value Gear corrector (c0 = 3/16) is of higher order than Verlet on an
// oscillator (observed order 4.3 between dt = 0.02 and 0.01) and far more accurate at
// the same step.
TEST(GearIntegrator, GearOrderAndAccuracyOnOscillator) {
  const double e1 = oscillator_error(true, 0.02, 10.0);
  const double e2 = oscillator_error(true, 0.01, 10.0);
  const double order = std::log2(e1 / e2);
  RecordProperty("gear_observed_order", std::to_string(order));
  std::printf("gear5 oscillator error dt=0.02: %.3e, dt=0.01: %.3e, order %.3f\n", e1, e2, order);
  EXPECT_GT(order, 3.8);
  EXPECT_LT(e2, 1e-2 * oscillator_error(false, 0.01, 10.0));
}

// After a contact-like force pulse, free flight damps the higher derivatives
// geometrically; they must end as exact zeros, never subnormal numbers (which make
// every later step ~100 times slower).
TEST(GearIntegrator, HistoryNeverSubnormalAfterPulse) {
  double x[3] = {0.0, 0.0, 0.0}, v[3] = {1.0, 0.5, 0.0}, h[kGearHistorySize];
  const double dt = 1e-4;
  const GearCorrector c(GearCoefficients::position_forces(), dt);
  double a[3] = {0.0, 0.0, 0.0};
  gear5_start(h, a);
  int subnormal_steps = 0;
  for (int n = 0; n < 200000; ++n) {
    gear5_predict(x, v, h, dt);
    // a stiff spring acting during the first 100 steps, then free flight
    for (int d = 0; d < 3; ++d) a[d] = n < 100 ? -1e4 * x[d] : 0.0;
    gear5_correct(x, v, h, a, c);
    for (double value : h)
      if (std::fpclassify(value) == FP_SUBNORMAL) ++subnormal_steps;
  }
  EXPECT_EQ(subnormal_steps, 0);
  for (int k = 3; k < kGearHistorySize; ++k) EXPECT_EQ(h[k], 0.0) << k;
}

// The stability bound kGear5StableOmegaDt: an oscillator integrated at ω·dt just below it
// keeps its amplitude, just above it the amplitude grows (slowly: +12 % over 2e5 steps).
TEST(GearIntegrator, StabilityBoundOnHarmonicMode) {
  const auto amplitude_growth = [](double omega_dt) {
    const double omega = 1.0, dt = omega_dt / omega;
    double x[3] = {1.0, 0.0, 0.0}, v[3] = {0.0, 0.0, 0.0}, h[kGearHistorySize], a[3];
    const GearCorrector c(GearCoefficients::position_forces(), dt);
    for (int d = 0; d < 3; ++d) a[d] = -omega * omega * x[d];
    gear5_start(h, a);
    for (int n = 0; n < 200000; ++n) {
      gear5_predict(x, v, h, dt);
      for (int d = 0; d < 3; ++d) a[d] = -omega * omega * x[d];
      gear5_correct(x, v, h, a, c);
    }
    return std::sqrt(x[0] * x[0] + v[0] * v[0] / (omega * omega));
  };
  EXPECT_LT(amplitude_growth(0.97 * kGear5StableOmegaDt), 1.0 + 1e-6);
  EXPECT_GT(amplitude_growth(1.03 * kGear5StableOmegaDt), 1.05);
}
