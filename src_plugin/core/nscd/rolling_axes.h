// Rolling resistance of one pair of a grain step (not in the paper; the couples themselves:
// core/nscd/body_operator.h, "Rolling resistance"): its couples act only about the tangent
// axes about which the pair's own contact points do not already resist rolling. About a
// tangent axis e, the normal impulses of points spread across e (by a half-width w_e, half
// the extent of the points along n × e) resist with a moment of up to w_e r_n, the couples
// with μ_r R r_n; e is left to the couples where w_e ≤ μ_r R (`arm`). So a single point
// keeps both axes, an edge on a face (points on a line) the axis along the edge, a face on
// a face none. Couples about an axis the points also hold are redundant with the normal
// impulses, and Gauss–Seidel drifts along that redundancy: with couples about every
// tangent axis a box resting face down hits the 1000-sweep cap on every step, and the
// 500-grain deposit does on some steps from t = 3 (2026-11-27, commit b774b66;
// docs/design.md, "Rolling resistance"). The axes are the principal axes of the points'
// spread in the plane normal to `normal`.
#pragma once

#include <Eigen/Dense>

#include <cstddef>
#include <vector>

#include "core/nscd/nscd_step.h"

namespace wiregrain {

struct RollingAxes {
  int count = 2;                                   // free axes: 0, 1 or 2
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();  // count 1: the free axis (unit, tangent)
};
RollingAxes rolling_axes(const std::vector<Eigen::Vector3d>& positions, const Eigen::Vector3d& normal, double arm);

// rolling_axes on each run of consecutive rows of one pair among `count` rows: key(i),
// position(i), normal(i) of row i, and its NscdContact& row(i) (rolling and rolling_axis
// set; rows without rolling resistance are left alone)
template <class Key, class Position, class Normal, class Row>
void restrict_rolling(std::size_t count, const Key& key, const Position& position, const Normal& normal,
                      const Row& row) {
  std::vector<Eigen::Vector3d> positions;
  for (std::size_t first = 0, last = 0; first < count; first = last) {
    positions.clear();
    for (last = first; last < count && key(last) == key(first); last++) positions.push_back(position(last));
    const double arm = row(first).rolling_friction * row(first).rolling_radius;  // μ_r R
    if (arm == 0.0) continue;
    const RollingAxes axes = rolling_axes(positions, normal(first), arm);
    for (std::size_t i = first; i < last; i++) {
      if (axes.count == 0) row(i).rolling_friction = 0.0;
      if (axes.count == 1) row(i).rolling_axis = axes.axis;
    }
  }
}

}  // namespace wiregrain
