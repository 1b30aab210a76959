// Checks of the contact solver's input (the bodies and contacts of a step, a reduced
// problem, warm starts): they run for every body and contact of every step, so the
// subject of the message, `what()`, is built only when a check fails.
#pragma once

#include <cmath>
#include <string>

#include "core/common/errors.h"
#include "core/common/validation.h"

namespace wiregrain {

// "contact <c>: ", the start of a message about one contact
inline std::string contact_label(int c) { return "contact " + std::to_string(c) + ": "; }

// "<what> has a non-finite entry" under the keyword `argument` unless `finite`.
template <class What>
void check_finite(bool finite, const char* argument, const What& what) {
  if (!finite) throw InvalidArgument(argument, std::string(what()) + " has a non-finite entry");
}

// "<what> must be a finite number >= 0, got <value>" under the keyword `argument`.
template <class What>
void check_nonnegative(double value, const char* argument, const What& what) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw InvalidArgument(argument, std::string(what()) + " must be a finite number >= 0, got " +
                                        format_number(value));
  }
}

}  // namespace wiregrain
