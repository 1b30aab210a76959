#include "core/wire/gear_integrator.h"

namespace wiregrain {

GearCorrector::GearCorrector(const GearCoefficients& coeff, double dt) {
  const double* c = coeff.c.data();
  const double half_dt2 = dt * dt / 2.0;
  dx = c[0] * half_dt2;                         // k = 0
  dv = c[1] * half_dt2 / dt;                    // k = 1
  da = c[2];                                    // k = 2: (dt²/2)·2/dt² = 1
  dj = c[3] * half_dt2 * 6.0 / (dt * dt * dt);  // k = 3
  ds = c[4] * half_dt2 * 24.0 / (dt * dt * dt * dt);
  dc = c[5] * half_dt2 * 120.0 / (dt * dt * dt * dt * dt);
}

}  // namespace wiregrain
