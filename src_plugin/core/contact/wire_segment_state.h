// The state of one wire segment in a soft contact: its two beads' positions, velocities
// and masses, and its radius (the segment is a spherocylinder of radius r_w around
// [x0, x1]). Read by the wire–grain and wire–wire contacts.
#pragma once

#include <Eigen/Core>

namespace wiregrain {

struct WireSegmentState {
  Eigen::Vector3d x0 = Eigen::Vector3d::Zero(), x1 = Eigen::Vector3d::Zero();
  Eigen::Vector3d v0 = Eigen::Vector3d::Zero(), v1 = Eigen::Vector3d::Zero();
  double m0 = 0.0, m1 = 0.0;  // bead masses
  double radius = 0.0;        // r_w
};

}  // namespace wiregrain
