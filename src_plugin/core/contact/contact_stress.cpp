// Love–Weber grain stress; the equations are in contact_stress.h.
#include "core/contact/contact_stress.h"

#include <cmath>

#include "core/common/errors.h"
#include "core/common/validation.h"

namespace wiregrain {

Eigen::Matrix3d love_weber_stress(const Eigen::Matrix3d& moment_sum, double volume) {
  if (!(volume > 0.0 && std::isfinite(volume)))
    throw InvalidArgument("volume", "volume must be > 0 and finite, got " + format_number(volume));
  return moment_sum / volume;
}

double pressure(const Eigen::Matrix3d& stress) { return -stress.trace() / 3.0; }

}  // namespace wiregrain
