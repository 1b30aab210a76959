// Pieces of the scenes the grain-step tests share (test_grain_step.cpp,
// test_grain_plate.cpp, test_distributed_step.cpp): a library of one unit cube, a grain under
// gravity and a unit cube, the floor, a tight solver.
#pragma once

#include <Eigen/Dense>

#include "core/geometry/convex_shape.h"
#include "core/nscd/grain_step.h"

namespace wiregrain {
namespace test_scenes {

inline ShapeLibrary unit_cube_library() {
  ShapeLibrary library;
  library.add(ConvexShape::cube(1.0, 0.0));
  return library;
}

// a grain of library shape `shape`, mass m and principal inertia I (the same about its
// three axes, aligned with the world's) with its centre at `position`, moving at
// `velocity`, its weight m g along −z
inline GrainState grain_under_gravity(long tag, int shape, const Eigen::Vector3d& position, double mass,
                                      double inertia, double g,
                                      const Eigen::Vector3d& velocity = Eigen::Vector3d::Zero()) {
  GrainState grain;
  grain.tag = tag;
  grain.shape = shape;
  grain.position = position;
  grain.velocity = velocity;
  grain.force = Eigen::Vector3d(0, 0, -mass * g);
  grain.mass = mass;
  grain.inertia = Eigen::Vector3d::Constant(inertia);
  return grain;
}

// a unit cube (shape 0 of unit_cube_library) of mass m, I = m/6
inline GrainState unit_cube(long tag, const Eigen::Vector3d& position, double mass, double g,
                            const Eigen::Vector3d& velocity = Eigen::Vector3d::Zero()) {
  return grain_under_gravity(tag, 0, position, mass, mass / 6.0, g, velocity);
}

// the plane z = 0, normal +z
inline PlaneWall floor_wall(double friction = 0.5) {
  PlaneWall w;
  w.point = Eigen::Vector3d::Zero();
  w.normal = Eigen::Vector3d::UnitZ();
  w.friction = friction;
  return w;
}

inline GrainStepOptions tight_options(double tolerance) {
  GrainStepOptions options;
  options.solver.tolerance = tolerance;
  options.solver.max_iterations = 100000;
  return options;
}

}  // namespace test_scenes
}  // namespace wiregrain
