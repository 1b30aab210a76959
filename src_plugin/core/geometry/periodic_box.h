// The simulation box as the contact searches see it: an orthogonal box [lo, hi) whose
// periodic dimensions wrap (LIGGGHTS' `boundary p`). Plain data, passed in by the styles.
//
// Minimum image (the rule of LIGGGHTS' Domain::minimum_image for orthogonal boxes, also
// BroadPhaseGrid's): in a periodic dimension of length L a displacement d with |d| > L/2
// is taken to d − L round(d / L), so |d| ≤ L/2; a displacement within L/2 is left as it
// is, to the bit, and a box without periodic dimensions changes nothing. Contacts are
// found once, in the minimum image of the pair: unambiguous while every interaction
// reach is at most L/2 (the callers check their own reach: fix nscd/polyhedra and
// HeldGrains).
#pragma once

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <string>

#include "core/common/errors.h"

namespace wiregrain {

struct PeriodicBox {
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Ones();
  std::array<bool, 3> periodic = {false, false, false};

  bool any() const { return periodic[0] || periodic[1] || periodic[2]; }
  double length(int d) const { return hi[d] - lo[d]; }

  // The multiple of L (per periodic dimension; 0 elsewhere) to add to the displacement d
  // for its minimum image.
  double image_offset(int dim, double d) const {
    if (!periodic[dim]) return 0.0;
    const double l = length(dim);
    if (!(std::fabs(d) > 0.5 * l)) return 0.0;
    return -l * std::round(d / l);
  }
  // d in its minimum image
  Eigen::Vector3d minimum_image(const Eigen::Vector3d& d) const {
    if (!any()) return d;
    Eigen::Vector3d out = d;
    for (int k = 0; k < 3; k++) {
      const double offset = image_offset(k, d[k]);
      if (offset != 0.0) out[k] += offset;
    }
    return out;
  }
  // The shift to add to `to` for its image nearest to `from` (zero in non-periodic
  // dimensions and for points within half a period).
  Eigen::Vector3d image_shift(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const {
    Eigen::Vector3d shift = Eigen::Vector3d::Zero();
    if (!any()) return shift;
    for (int k = 0; k < 3; k++) shift[k] = image_offset(k, to[k] - from[k]);
    return shift;
  }
  // InvalidArgument("box", ...) unless every periodic dimension has finite lo < hi
  void validate() const {
    for (int k = 0; k < 3; k++)
      if (periodic[k] && !(std::isfinite(lo[k]) && std::isfinite(hi[k]) && hi[k] > lo[k]))
        throw InvalidArgument("box", std::string("periodic box: dimension ") + "xyz"[k] +
                                         " needs finite lo < hi");
  }
  // The shortest periodic length (infinity without periodic dimensions) and its dimension.
  double shortest_period(int* dimension = nullptr) const {
    double shortest = INFINITY;
    for (int k = 0; k < 3; k++)
      if (periodic[k] && length(k) < shortest) {
        shortest = length(k);
        if (dimension) *dimension = k;
      }
    return shortest;
  }
};

}  // namespace wiregrain
