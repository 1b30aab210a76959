// Explicit integrators for point masses, d²x/dt² = a(x, v): the 6-value (fifth-order)
// Gear predictor–corrector and velocity Verlet. Stateless per-particle kernels, inline
// because they run once per atom and step; the LIGGGHTS fix only owns the storage.
#pragma once

#include <array>

namespace wiregrain {

// Gear corrector coefficients for second-order equations, 6 values x, x', ..., x^(5)
// (Gear 1966; Allen & Tildesley, Computer Simulation of Liquids, 1987, appendix E).
struct GearCoefficients {
  std::array<double, 6> c;

  // c0 = 3/16: the value for forces that depend on positions only.
  static GearCoefficients position_forces() {
    return {{3.0 / 16.0, 251.0 / 360.0, 1.0, 11.0 / 18.0, 1.0 / 6.0, 1.0 / 60.0}};
  }
  // c0 = 3/20: Allen & Tildesley's recommendation when forces depend on velocities
  // (damped contacts).
  static GearCoefficients velocity_forces() {
    GearCoefficients g = position_forces();
    g.c[0] = 3.0 / 20.0;
    return g;
  }
};

// The 6-value corrector with c0 = 3/16 is stable on a harmonic mode of frequency ω only
// for ω·dt below this (spectral radius of its one-step map ≤ 1; measured, see
// tests/core/test_gear_integrator.cpp and docs/design.md, "Wire forces and integration"). Velocity Verlet's bound is 2.
constexpr double kGear5StableOmegaDt = 0.313;

// Per-particle Gear history: unscaled derivatives a = x'', j = x''', s = x^(4), c = x^(5),
// stored as 4 x 3 doubles in that order. Unscaled storage stays valid if the user
// changes the time step between runs.
constexpr int kGearHistorySize = 12;

// The corrector's increments per unit Δa for one time step. The scaled derivatives
// q_k = dt^k/k! x^(k) each get c_k Δq2 with Δq2 = Δa dt²/2, hence
// Δx^(k) = c_k · (dt²/2) · k!/dt^k · Δa.
struct GearCorrector {
  double dx, dv, da, dj, ds, dc;
  GearCorrector(const GearCoefficients& coeff, double dt);
};

// Predictor: Taylor expansion of x, v and the history over dt.
inline void gear5_predict(double x[3], double v[3], double h[kGearHistorySize], double dt) {
  const double t2 = dt * dt / 2.0, t3 = t2 * dt / 3.0, t4 = t3 * dt / 4.0, t5 = t4 * dt / 5.0;
  double* a = h;
  double* j = h + 3;
  double* s = h + 6;
  const double* c = h + 9;
  for (int d = 0; d < 3; ++d) {
    x[d] += v[d] * dt + a[d] * t2 + j[d] * t3 + s[d] * t4 + c[d] * t5;
    v[d] += a[d] * dt + j[d] * t2 + s[d] * t3 + c[d] * t4;
    a[d] += j[d] * dt + s[d] * t2 + c[d] * t3;
    j[d] += s[d] * dt + c[d] * t2;
    s[d] += c[d] * dt;
  }
}

// Higher derivatives below this are set to zero. Once the force becomes smooth (free
// flight) the corrector damps x''' ... x^(5) geometrically; without a floor they reach
// subnormal numbers, where arithmetic is ~100 times slower (measured: the Gear step of a
// settled bed cost 15 times a Verlet step).
constexpr double kGearDerivativeFloor = 1e-150;

inline double flush_tiny(double value) {
  return (value < kGearDerivativeFloor && value > -kGearDerivativeFloor) ? 0.0 : value;
}

// Corrector with the acceleration a_new evaluated at the predicted state.
inline void gear5_correct(double x[3], double v[3], double h[kGearHistorySize],
                          const double a_new[3], const GearCorrector& k) {
  for (int d = 0; d < 3; ++d) {
    const double delta = a_new[d] - h[d];
    x[d] += k.dx * delta;
    v[d] += k.dv * delta;
    h[d] += k.da * delta;
    h[3 + d] = flush_tiny(h[3 + d] + k.dj * delta);
    h[6 + d] = flush_tiny(h[6 + d] + k.ds * delta);
    h[9 + d] = flush_tiny(h[9 + d] + k.dc * delta);
  }
}

// Start a history from the current acceleration (higher derivatives zero).
inline void gear5_start(double h[kGearHistorySize], const double a[3]) {
  for (int d = 0; d < 3; ++d) h[d] = a[d];
  for (int k = 3; k < kGearHistorySize; ++k) h[k] = 0.0;
}

// Velocity Verlet: half kick + drift, then (after the force update) half kick.
inline void verlet_kick_drift(double x[3], double v[3], const double a[3], double dt) {
  for (int d = 0; d < 3; ++d) {
    v[d] += 0.5 * dt * a[d];
    x[d] += dt * v[d];
  }
}

inline void verlet_kick(double v[3], const double a[3], double dt) {
  for (int d = 0; d < 3; ++d) v[d] += 0.5 * dt * a[d];
}

}  // namespace wiregrain
