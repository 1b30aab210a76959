// Domain checks shared by the core: each throws InvalidArgument naming the parameter,
// with one message form, "<name> must be a finite number > 0, got <value>".
#pragma once

#include <string>

namespace wiregrain {

// the value with 12 significant digits, for messages
std::string format_number(double value);

void require_finite(const char* name, double value);
void require_positive(const char* name, double value);
void require_nonnegative(const char* name, double value);

}  // namespace wiregrain
