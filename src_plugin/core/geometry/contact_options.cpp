// Input checks of the contact queries. See contact_options.h.
#include "core/geometry/contact_options.h"

#include <cmath>
#include <string>

#include "core/common/errors.h"
#include "core/common/validation.h"

namespace wiregrain {

void check_contact_options(const ContactOptions& options) {
  if (!(options.angle_tolerance >= 0.0 && options.angle_tolerance <= 0.5))
    throw InvalidArgument("angle_tolerance", "angle_tolerance must be in [0, 0.5] rad, got " +
                                                 format_number(options.angle_tolerance));
  if (options.max_points < 0)
    throw InvalidArgument("max_points", "max_points must be >= 0 (0: no limit), got " +
                                            std::to_string(options.max_points));
  if (std::isnan(options.feature_gap_limit))
    throw InvalidArgument("feature_gap_limit", "feature_gap_limit must not be NaN");
  if (!(options.exit_beyond_activation >= 0.0))
    throw InvalidArgument("exit_beyond_activation", "exit_beyond_activation must be >= 0, got " +
                                                        format_number(options.exit_beyond_activation));
  if (!(options.exit_gap >= 0.0))
    throw InvalidArgument("exit_gap", "exit_gap must be >= 0, got " + format_number(options.exit_gap));
}

void require_not_nan(const char* name, double value) {
  if (std::isnan(value))
    throw InvalidArgument(name, std::string(name) + " must be a number (±inf allowed), got nan");
}

void require_finite_vector(const char* name, const Eigen::Vector3d& value) {
  if (!value.allFinite())
    throw InvalidArgument(name, std::string(name) + " must have finite coordinates");
}

}  // namespace wiregrain
