// The grain shapes of a simulation: each grain refers to one entry by index. Every MPI
// rank holds the same library (shapes are generated from seeds, or read, identically on
// all ranks), so a grain migrates with just its index.
//
// An entry is kept in two parts: its record (the body-frame vertices, the sweep radius and
// the mass properties: about 0.6 KiB for a 20-vertex grain), always held, and the shape
// built from it (hull, faces, adjacency: about 11 KiB), built on first use and dropped by
// release_built_except(), so that a rank holds built only the shapes of the grains it
// works on (fix nscd/polyhedra `solve distributed`: its own and ghost grains). A shape
// built again is ConvexShape::from_points of the record, the shape deserialize() makes;
// one made by add() is the input turned into the body frame, which can differ from it in
// the last bits of its face normals. Not thread-safe: operator[] may build.
#pragma once

#include <Eigen/Geometry>
#include <memory>
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

  // entry `index`, built now if it is not; the reference holds until the entry is
  // released
  const GrainShape& operator[](int index) const {
    const Entry& e = entries_[index];
    return e.built ? *e.built : build(index);
  }
  int size() const { return static_cast<int>(entries_.size()); }
  MassModel model() const { return model_; }
  // entry `index`'s record, without building it: its body-frame vertices (those of its
  // built shape) and sweep radius
  const std::vector<Eigen::Vector3d>& vertices(int index) const { return entries_[index].vertices; }
  double sweep_radius(int index) const { return entries_[index].sweep_radius; }

  // The built shapes: how many are held, and dropping those whose needed[index] is 0
  // (entries beyond needed's size are dropped too); their records stay, so operator[]
  // builds them again when asked.
  int built_count() const;
  void release_built_except(const std::vector<char>& needed);

  // A flat image for restart files and broadcasts: [model, count, then per shape: sweep
  // radius, vertex count, x y z of each body-frame vertex]. deserialize() rebuilds the same
  // library (same vertices, faces from the same hull, same mass properties); a sphere is
  // its one vertex and its radius (ConvexShape::from_points with one point). It builds each
  // shape once for its mass properties and keeps none built.
  std::vector<double> serialize() const;
  static ShapeLibrary deserialize(const std::vector<double>& data);

 private:
  struct Entry {
    double sweep_radius = 0.0;
    std::vector<Eigen::Vector3d> vertices;  // body frame
    double volume = 0.0;
    Eigen::Vector3d unit_inertia = Eigen::Vector3d::Zero();
    double bounding_radius = 0.0;
    mutable std::shared_ptr<const GrainShape> built;
  };
  MassModel model_;
  std::vector<Entry> entries_;
  // appends the entry of a body-frame shape; keeps it built when `keep`
  void append_body_frame(ConvexShape body_frame_shape, bool keep);
  const GrainShape& build(int index) const;
};

}  // namespace wiregrain
