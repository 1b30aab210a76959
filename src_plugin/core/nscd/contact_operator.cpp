// The Siconos error on a contact operator (contact_operator.h).
#include "core/nscd/contact_operator.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace wiregrain {

double siconos_error(const ContactOperator& op, const std::vector<Eigen::Vector3d>& impulses) {
  double sum = 0.0, norm_r_squared = 0.0, norm_u_squared = 0.0;
  for (int c = 0; c < op.contact_count(); ++c) {
    const Eigen::Vector3d u = op.velocity(c);
    // an open contact (r = 0, u_n ≥ 0) has residual 0 exactly: r − u♯ = −(u_n + μ|u_t|, u_t)
    // lies in the polar cone, whose projection on K_μ is 0 (most points of a pile are open)
    if (!(impulses[c].isZero(0.0) && u[0] >= 0.0))
      sum += natural_map_residual(impulses[c], u, op.friction_coefficient(c)).squaredNorm();
    norm_r_squared += impulses[c].squaredNorm();
    norm_u_squared += u.squaredNorm();
  }
  const double scale = std::max(
      {op.free_velocity_norm(), std::sqrt(norm_r_squared), std::sqrt(norm_u_squared)});
  const double error = std::sqrt(sum);
  return scale > DBL_EPSILON ? error / scale : error;
}

}  // namespace wiregrain
