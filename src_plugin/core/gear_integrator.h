// Explicit integrators for point masses, d²x/dt² = a(x, v): the 6-value (fifth-order)
// Gear predictor–corrector and velocity Verlet. Stateless kernels on one particle's
// arrays, so the LIGGGHTS fix only owns the storage.
#pragma once

#include <array>

namespace wiregrain {

// Gear corrector coefficients for second-order equations, 6 values x, x', ..., x^(5)
// (Gear 1966; Allen & Tildesley, Computer Simulation of Liquids, 1987, Table E.2).
struct GearCoefficients {
  std::array<double, 6> c;

  // c0 = 3/16: the table's value for forces that depend on positions only.
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

// Per-particle Gear history: unscaled derivatives a = x'', j = x''', s = x^(4), c = x^(5),
// stored as 4 x 3 doubles in that order. Unscaled storage stays valid if the user
// changes the time step between runs.
constexpr int kGearHistorySize = 12;

// Predictor: Taylor expansion of x, v and the history over dt.
void gear5_predict(double x[3], double v[3], double history[kGearHistorySize], double dt);

// Corrector: with the acceleration a_new evaluated at the predicted state,
// Δa = a_new − a_pred; every scaled derivative q_k = dt^k/k! x^(k) gets c_k · Δa dt²/2.
void gear5_correct(double x[3], double v[3], double history[kGearHistorySize],
                   const double a_new[3], double dt, const GearCoefficients& coeff);

// Start a history from the current acceleration (higher derivatives zero).
void gear5_start(double history[kGearHistorySize], const double a[3]);

// Velocity Verlet: half kick + drift, then (after the force update) half kick.
void verlet_kick_drift(double x[3], double v[3], const double a[3], double dt);
void verlet_kick(double v[3], const double a[3], double dt);

}  // namespace wiregrain
