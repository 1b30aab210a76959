// A grain's core placed in the world, as the contact queries read it.
//
// A grain is a convex polyhedron P (its "core", a ConvexShape in the body frame) dilated
// by its sweep radius r (ConvexShape::sweep_radius()). The contact queries
// (core_distance.h, contact_manifold.h, segment_contact.h) work on the sharp cores placed
// in the world and subtract the radii at the end.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <boost/container/small_vector.hpp>

#include "core/geometry/convex_shape.h"

namespace wiregrain {

// A ConvexShape (body frame) placed in the world: x_world = R(q) x_body + position.
// Holds a pointer to the shape (which must outlive it) and the world-frame vertices,
// face normals and face offsets, computed once at construction (so a grain posed once
// per time step can be used in all its pair queries).
class PosedShape {
 public:
  // The world-frame vertices, inline up to 24 (the paper's grains have 20): posing a grain
  // allocates nothing.
  using Vertices = boost::container::small_vector<Eigen::Vector3d, 24>;

  // orientation: body -> world, any non-zero finite quaternion (normalised here).
  // Non-finite position: InvalidArgument("position"); zero or non-finite orientation:
  // InvalidArgument("orientation").
  PosedShape(const ConvexShape& shape, const Eigen::Vector3d& position,
             const Eigen::Quaterniond& orientation);
  // it keeps a reference to the shape: a temporary would dangle (found by AddressSanitizer)
  PosedShape(ConvexShape&&, const Eigen::Vector3d&, const Eigen::Quaterniond&) = delete;

  const ConvexShape& shape() const { return *shape_; }
  const Eigen::Vector3d& position() const { return position_; }
  const Eigen::Quaterniond& orientation() const { return orientation_; }
  const Eigen::Matrix3d& rotation() const { return rotation_; }
  double sweep_radius() const { return shape_->sweep_radius(); }
  // max |v_body| over the core's vertices (the core's radius about `position`)
  double core_radius() const { return core_radius_; }

  // world-frame core: vertex i, unit outward normal and plane offset of face f
  // (normal · x = offset on the face). The faces are turned when asked for: most pairs
  // need those at one vertex only (posing them all was half of the posing time).
  const Vertices& vertices() const { return vertices_; }
  Eigen::Vector3d face_normal(int f) const { return rotation_ * shape_->faces()[f].normal; }
  double face_offset(int f) const { return shape_->faces()[f].offset + face_normal(f).dot(position_); }

  Eigen::Vector3d to_world(const Eigen::Vector3d& body_point) const {
    return rotation_ * body_point + position_;
  }
  // Index of a vertex of the core maximising direction · v (the support point).
  int support_vertex(const Eigen::Vector3d& direction) const;

 private:
  const ConvexShape* shape_;
  Eigen::Vector3d position_;
  Eigen::Quaterniond orientation_;
  Eigen::Matrix3d rotation_;
  double core_radius_ = 0.0;
  Vertices vertices_;
};

// h(n) = max over the core's world vertices of n·x (the support function; n any vector).
double support_value(const PosedShape& p, const Eigen::Vector3d& n);

// The length the relative tolerances of a query are taken of: the largest of the core
// radius of `a`, the other body's radius about its centre, the distance of the centres
// (and the smallest normal double, so that it is never 0).
double configuration_size(const PosedShape& a, const Eigen::Vector3d& other_center, double other_radius);

}  // namespace wiregrain
