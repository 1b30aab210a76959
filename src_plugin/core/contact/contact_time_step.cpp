// Stability limits of a soft contact's spring–dashpot; the formulas are in contact_time_step.h.
#include "core/contact/contact_time_step.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/validation.h"
#include "core/wire/gear_integrator.h"

namespace wiregrain {

ContactTimeStep spring_dashpot_time_step(double k, double m, double zeta) {
  require_nonnegative("k", k);
  require_positive("m", m);
  require_nonnegative("damping_ratio", zeta);
  ContactTimeStep out;
  if (k == 0.0) {
    out.critical = out.gear5 = std::numeric_limits<double>::infinity();
    return out;
  }
  const double omega = std::sqrt(k / m);
  // √(1 + ζ²) − ζ written as 1/(√(1 + ζ²) + ζ): no cancellation for large ζ
  const double damped = 1.0 / (std::sqrt(1.0 + zeta * zeta) + zeta);
  out.critical = 2.0 / omega * damped;
  out.gear5 = kGear5StableOmegaDt / omega * damped;
  if (zeta > 0.0) out.gear5 = std::min(out.gear5, kGear5StableDampedOmegaDt / (zeta * omega));
  return out;
}

ContactTimeStep contact_time_step(const SoftContactLaw& law, double effective_mass) {
  return spring_dashpot_time_step(std::max(law.normal_stiffness, law.tangential_stiffness), effective_mass,
                                  law.damping_ratio);
}

double reduced_mass(double a, double b) {
  if (std::isinf(b)) return a;
  if (std::isinf(a)) return b;
  return a * b / (a + b);
}

}  // namespace wiregrain
