// Mathematical constants of the core (one definition).
#pragma once

namespace wiregrain {

inline constexpr double kPi = 3.14159265358979323846;

}  // namespace wiregrain
