#include "core/common/validation.h"

#include <cmath>
#include <sstream>

#include "core/common/errors.h"

namespace wiregrain {

std::string format_number(double value) {
  std::ostringstream out;
  out.precision(12);
  out << value;
  return out.str();
}

void require_finite(const char* name, double value) {
  if (!std::isfinite(value))
    throw InvalidArgument(name, std::string(name) + " must be a finite number, got " + format_number(value));
}

void require_positive(const char* name, double value) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw InvalidArgument(name, std::string(name) + " must be a finite number > 0, got " +
                                    format_number(value));
}

void throw_not_nonnegative(const char* name, double value) {
  throw InvalidArgument(name, std::string(name) + " must be a finite number >= 0, got " +
                                  format_number(value));
}

}  // namespace wiregrain
