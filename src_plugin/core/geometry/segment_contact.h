// Contact of a grain and a wire element: the segment [end0, end1] dilated by the wire
// radius (a spherocylinder), against a spheropolyhedron (here) or a superquadric
// (superquadric_contact.h). The signed distance of the grain's core and the segment's
// axis follows core_distance.h (GJK apart, the SAT overlapping: sat_segment); the closest
// feature of the core gives the interval of closest points of a segment parallel to it.
// docs/design.md, "Contact geometry".
#pragma once

#include <Eigen/Dense>

#include "core/geometry/contact_options.h"
#include "core/geometry/core_distance.h"
#include "core/geometry/gjk.h"
#include "core/geometry/posed_shape.h"

namespace wiregrain {

struct SegmentContact {
  double distance = 0.0;  // signed core–axis distance (<= 0: minus the penetration depth)
  double gap = 0.0;       // distance − (r_grain + wire_radius)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  // unit, from the grain to the wire
  Eigen::Vector3d point_on_core = Eigen::Vector3d::Zero();
  Eigen::Vector3d point_on_segment = Eigen::Vector3d::Zero();
  // point_on_segment = end0 + t (end1 − end0), t ∈ [0, 1]: the closest point; when the
  // segment is parallel (within the angle tolerance) to the contact face or edge the
  // closest points form an interval [t_begin, t_end] and t is its middle (the force is
  // then shared by the nodes); otherwise t_begin = t_end = t.
  double t = 0.0, t_begin = 0.0, t_end = 0.0;
  DistanceMethod method = DistanceMethod::gjk;
  int gjk_iterations = 0;
};

// simplex: GJK's warm start and last simplex (GjkSimplex: a the grain's vertex, b the
// segment's end), or null.
SegmentContact segment_contact(const PosedShape& grain, const Eigen::Vector3d& end0,
                               const Eigen::Vector3d& end1, double wire_radius,
                               const ContactOptions& options = ContactOptions(),
                               GjkSimplex* simplex = nullptr);

// The input checks of a segment query: InvalidArgument("end0"/"end1") for a non-finite
// end, ("wire_radius") for a radius negative, NaN or infinite.
void check_segment_inputs(const Eigen::Vector3d& end0, const Eigen::Vector3d& end1, double wire_radius);

}  // namespace wiregrain
