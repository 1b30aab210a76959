// Domain checks shared by the core: each throws InvalidArgument naming the parameter,
// with one message form, "<name> must be a finite number > 0, got <value>".
#pragma once

#include <cmath>
#include <string>

namespace wiregrain {

// the value with 12 significant digits, for messages
std::string format_number(double value);

void require_finite(const char* name, double value);
void require_positive(const char* name, double value);
[[noreturn]] void throw_not_nonnegative(const char* name, double value);
// inline: the local contact solve checks μ on every call
inline void require_nonnegative(const char* name, double value) {
  if (!(value >= 0.0) || !std::isfinite(value)) throw_not_nonnegative(name, value);
}

}  // namespace wiregrain
