// Drawing from the project's seeded random streams (std::mt19937_64). The standard
// distributions (std::uniform_real_distribution, ...) may differ between library
// implementations; these helpers do not, so a seed gives the same grains to the bit on
// every platform.
#pragma once

#include <random>

namespace wiregrain {

// Uniform double in [0, 1) from the top 53 bits of one engine output: (x >> 11) · 2^-53.
inline double uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

}  // namespace wiregrain
