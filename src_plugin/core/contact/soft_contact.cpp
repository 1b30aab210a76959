#include "core/contact/soft_contact.h"

#include <cmath>

#include "core/common/errors.h"
#include "core/common/constants.h"
#include "core/common/validation.h"

namespace wiregrain {

void SoftContactLaw::validate() const {
  require_nonnegative("k_n", normal_stiffness);
  require_nonnegative("k_t", tangential_stiffness);
  require_nonnegative("damping_ratio", damping_ratio);
  require_nonnegative("mu_s", static_friction);
  require_nonnegative("mu_d", dynamic_friction);
  if (dynamic_friction > static_friction)
    throw InvalidArgument("mu_d", "mu_d (" + format_number(dynamic_friction) +
                                      ") must not exceed mu_s (" + format_number(static_friction) + ")");
}

double damping_ratio_from_restitution(double e) {
  if (!(e >= 0.0 && e <= 1.0)) throw InvalidArgument("restitution", "restitution must be in [0, 1], got " + format_number(e));
  if (e == 0.0) return 1.0;
  const double l = std::log(e);
  return -l / std::sqrt(kPi * kPi + l * l);
}

double restitution_from_damping_ratio(double zeta) {
  if (zeta >= 1.0) return 0.0;
  return std::exp(-kPi * zeta / std::sqrt(1.0 - zeta * zeta));
}

SoftContactForce soft_contact_force(const SoftContactLaw& law, double overlap,
                                    const Eigen::Vector3d& n, const Eigen::Vector3d& u,
                                    double dt, double m, TangentialHistory& history) {
  SoftContactForce out;
  const double gamma_n = 2.0 * law.damping_ratio * std::sqrt(law.normal_stiffness * m);
  const double gamma_t = 2.0 * law.damping_ratio * std::sqrt(law.tangential_stiffness * m);
  const double u_n = u.dot(n);
  double f_n = law.normal_stiffness * overlap - gamma_n * u_n;
  if (law.limit_force && f_n < 0.0) f_n = 0.0;
  out.normal_force = f_n;

  // keep the spring in the tangent plane of the current normal, with its length
  Eigen::Vector3d& spring = history.spring;
  const double length = spring.norm();
  spring -= spring.dot(n) * n;
  const double projected = spring.norm();
  if (projected > 0.0) spring *= length / projected;

  const Eigen::Vector3d u_t = u - u_n * n;
  spring += u_t * dt;
  Eigen::Vector3d f_t = -law.tangential_stiffness * spring - gamma_t * u_t;
  const double f_t_norm = f_t.norm();
  const double friction_force = f_n > 0.0 ? f_n : 0.0;
  const double threshold = (history.sliding ? law.dynamic_friction : law.static_friction) * friction_force;
  if (f_t_norm > threshold) {
    history.sliding = true;
    f_t *= f_t_norm > 0.0 ? law.dynamic_friction * friction_force / f_t_norm : 0.0;
    spring = -f_t / (law.tangential_stiffness > 0.0 ? law.tangential_stiffness : 1.0);
  } else {
    history.sliding = false;
  }
  out.tangential_force = f_t.norm();
  out.force = f_n * n + f_t;
  return out;
}

}  // namespace wiregrain
