#include "core/gear_integrator.h"

namespace wiregrain {

void gear5_predict(double x[3], double v[3], double h[kGearHistorySize], double dt) {
  const double dt2 = dt * dt / 2.0, dt3 = dt2 * dt / 3.0, dt4 = dt3 * dt / 4.0,
               dt5 = dt4 * dt / 5.0;
  double* a = h;
  double* j = h + 3;
  double* s = h + 6;
  const double* c = h + 9;
  for (int d = 0; d < 3; ++d) {
    x[d] += v[d] * dt + a[d] * dt2 + j[d] * dt3 + s[d] * dt4 + c[d] * dt5;
    v[d] += a[d] * dt + j[d] * dt2 + s[d] * dt3 + c[d] * dt4;
    a[d] += j[d] * dt + s[d] * dt2 + c[d] * dt3;
    j[d] += s[d] * dt + c[d] * dt2;
    s[d] += c[d] * dt;
  }
}

void gear5_correct(double x[3], double v[3], double h[kGearHistorySize], const double a_new[3],
                   double dt, const GearCoefficients& coeff) {
  // q_k = dt^k/k! x^(k) gets c_k Δq2 with Δq2 = Δa dt²/2, hence
  // Δx^(k) = c_k Δa · (dt²/2) · k!/dt^k.
  const double* c = coeff.c.data();
  const double fx = c[0] * dt * dt / 2.0;
  const double fv = c[1] * dt / 2.0;
  const double fj = c[3] * 3.0 / dt;
  const double fs = c[4] * 12.0 / (dt * dt);
  const double fc = c[5] * 60.0 / (dt * dt * dt);
  double* a = h;
  double* j = h + 3;
  double* s = h + 6;
  double* cc = h + 9;
  for (int d = 0; d < 3; ++d) {
    const double da = a_new[d] - a[d];
    x[d] += fx * da;
    v[d] += fv * da;
    a[d] += c[2] * da;
    j[d] += fj * da;
    s[d] += fs * da;
    cc[d] += fc * da;
  }
}

void gear5_start(double h[kGearHistorySize], const double a[3]) {
  for (int d = 0; d < 3; ++d) h[d] = a[d];
  for (int k = 3; k < kGearHistorySize; ++k) h[k] = 0.0;
}

void verlet_kick_drift(double x[3], double v[3], const double a[3], double dt) {
  for (int d = 0; d < 3; ++d) {
    v[d] += 0.5 * dt * a[d];
    x[d] += dt * v[d];
  }
}

void verlet_kick(double v[3], const double a[3], double dt) {
  for (int d = 0; d < 3; ++d) v[d] += 0.5 * dt * a[d];
}

}  // namespace wiregrain
