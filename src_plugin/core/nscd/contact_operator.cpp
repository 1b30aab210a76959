// The Siconos error on a contact operator (contact_operator.h).
#include "core/nscd/contact_operator.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace wiregrain {

SiconosErrorSums siconos_error_sums(const ContactOperator& op, const std::vector<Eigen::Vector3d>& impulses) {
  SiconosErrorSums sums;
  for (int c = 0; c < op.contact_count(); ++c) {
    const Eigen::Vector3d u = op.velocity(c);
    // an open contact (r = 0, u_n ≥ 0) has residual 0 exactly: r − u♯ = −(u_n + μ|u_t|, u_t)
    // lies in the polar cone, whose projection on K_μ is 0 (most points of a pile are open)
    if (!(impulses[c].isZero(0.0) && u[0] >= 0.0))
      sums.residual_squared += natural_map_residual(impulses[c], u, op.friction_coefficient(c)).squaredNorm();
    sums.impulses_squared += impulses[c].squaredNorm();
    sums.velocities_squared += u.squaredNorm();
  }
  return sums;
}

double siconos_error(const SiconosErrorSums& sums, double free_velocity_norm) {
  const double scale =
      std::max({free_velocity_norm, std::sqrt(sums.impulses_squared), std::sqrt(sums.velocities_squared)});
  const double error = std::sqrt(sums.residual_squared);
  return scale > DBL_EPSILON ? error / scale : error;
}

double siconos_error(const ContactOperator& op, const std::vector<Eigen::Vector3d>& impulses) {
  return siconos_error(siconos_error_sums(op, impulses), op.free_velocity_norm());
}

}  // namespace wiregrain
