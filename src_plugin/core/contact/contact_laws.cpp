// Materials → soft-contact laws; the equations are in contact_laws.h.
#include "core/contact/contact_laws.h"

#include <cmath>

#include "core/common/errors.h"
#include "core/common/constants.h"
#include "core/common/validation.h"

namespace wiregrain {

void ElasticMaterial::validate() const {
  require_positive("E", youngs_modulus);
  require_finite("nu", poisson_ratio);
  if (!(poisson_ratio >= 0.0 && poisson_ratio < 0.5))
    throw InvalidArgument("nu", "nu must be in [0, 0.5), got " + format_number(poisson_ratio));
}

double effective_modulus(double e_a, double nu_a, double e_b, double nu_b) {
  return 1.0 / ((1.0 - nu_a * nu_a) / e_a + (1.0 - nu_b * nu_b) / e_b);
}

double wire_wire_modulus(const ElasticMaterial& a, const ElasticMaterial& b) {
  // one material on both sides: E_ww = E_w / (2(1−ν_w²)), the mixing rule with E_b = E_a
  // written without its two divisions
  if (a.youngs_modulus == b.youngs_modulus && a.poisson_ratio == b.poisson_ratio)
    return a.youngs_modulus / (2.0 * (1.0 - a.poisson_ratio * a.poisson_ratio));
  return effective_modulus(a.youngs_modulus, a.poisson_ratio, b.youngs_modulus, b.poisson_ratio);
}

double wire_grain_modulus(const ElasticMaterial& wire, const ElasticMaterial& grain) {
  return effective_modulus(wire.youngs_modulus, wire.poisson_ratio, grain.youngs_modulus, grain.poisson_ratio);
}

double wire_wall_modulus(const ElasticMaterial& wire) {
  return wire.youngs_modulus / (1.0 - wire.poisson_ratio * wire.poisson_ratio);
}

SoftContactLaw segment_contact_law(double e_star, double segment_length, double wire_radius,
                                   const ContactFriction& friction) {
  SoftContactLaw law;
  law.normal_stiffness = e_star * segment_length * kPi / 4.0;  // k_n = E* l_w π/4
  law.tangential_stiffness = e_star * wire_radius;             // k_t = E* r_w
  law.damping_ratio = friction.damping_ratio;
  law.static_friction = friction.static_friction;
  law.dynamic_friction = friction.dynamic_friction;
  law.limit_force = friction.limit_force;
  return law;
}

double bead_segment_length(double own_rest_length, double previous_rest_length, double radius) {
  if (own_rest_length > 0.0) return own_rest_length;
  if (previous_rest_length > 0.0) return previous_rest_length;
  return 2.0 * radius;
}

}  // namespace wiregrain
