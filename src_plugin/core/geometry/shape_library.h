// The grain shapes of a simulation: each grain refers to one entry by index. Every MPI
// rank holds the same library (shapes are generated from seeds, or read, identically on
// all ranks), so a grain migrates with just its index.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "core/geometry/convex_shape.h"

namespace wiregrain {

// One shape in its body frame: centroid at the origin, principal axes of inertia along
// x, y, z with the moments ascending.
struct GrainShape {
  ConvexShape shape;
  double volume = 0.0;                         // of the mass model used
  Eigen::Vector3d unit_inertia = Eigen::Vector3d::Zero();  // principal moments at density 1
  double bounding_radius = 0.0;                // farthest surface point (sweep included)
};

class ShapeLibrary {
 public:
  // model: which body carries the mass, the sharp polyhedron or the swept (dilated) one
  explicit ShapeLibrary(MassModel model = MassModel::dilated) : model_(model) {}

  // Adds a shape given in any frame. Returns its index; `placement`, if given, receives
  // the rotation body frame → given frame and the centroid in the given frame, so a grain
  // placed with that orientation and position reproduces the input exactly. A sphere
  // cannot join a library of the sharp model (it has no sharp volume):
  // InvalidArgument("model", ...).
  struct Placement {
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  };
  int add(const ConvexShape& shape, Placement* placement = nullptr);

  const GrainShape& operator[](int index) const { return shapes_[index]; }
  int size() const { return static_cast<int>(shapes_.size()); }
  MassModel model() const { return model_; }

  // A flat image for restart files and broadcasts: [model, count, then per shape: sweep
  // radius, vertex count, x y z of each body-frame vertex]. deserialize() rebuilds the same
  // library (same vertices, faces from the same hull, same mass properties); a sphere is
  // its one vertex and its radius (ConvexShape::from_points with one point).
  std::vector<double> serialize() const;
  static ShapeLibrary deserialize(const std::vector<double>& data);

 private:
  MassModel model_;
  std::vector<GrainShape> shapes_;
  void append_body_frame(const ConvexShape& body_frame_shape);
};

}  // namespace wiregrain
