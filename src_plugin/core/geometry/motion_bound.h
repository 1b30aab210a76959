// How far any point of a rigid body within `radius` of its reference point can have moved
// between two poses: the translation plus the chord of the turn,
//     |c − c_ref| + 2 R |vec(q_ref⁻¹ q)| = |c − c_ref| + 2 R sin(θ/2),
// θ the angle of the relative rotation (either sign of the quaternions). The pair caches
// of the wire–grain contact and of the NSCD detection keep pairs while this stays below
// their skin (core/contact/wire_grain_pairs.h, core/nscd/grain_pairs.h).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace wiregrain {

// translation: c − c_ref (in a periodic box its minimum image); reference_orientation must
// be a unit quaternion, orientation any non-zero one.
inline double rigid_motion_bound(const Eigen::Vector3d& translation, const Eigen::Quaterniond& reference_orientation,
                                 const Eigen::Quaterniond& orientation, double radius) {
  const double turn = (reference_orientation.conjugate() * orientation.normalized()).vec().norm();
  return translation.norm() + 2.0 * radius * turn;
}

}  // namespace wiregrain
