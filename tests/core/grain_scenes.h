// Pieces of the scenes the grain-step tests share (test_grain_step.cpp,
// test_grain_plate.cpp, test_distributed_step.cpp): a library of one unit cube, a unit cube
// at rest, the floor, a tight solver.
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

// a unit cube of mass m (I = m/6 about its axes, aligned with the world's) with its centre
// at `position`, moving at `velocity`, its weight m g along −z
inline GrainState unit_cube(long tag, const Eigen::Vector3d& position, double mass, double g,
                            const Eigen::Vector3d& velocity = Eigen::Vector3d::Zero()) {
  GrainState cube;
  cube.tag = tag;
  cube.position = position;
  cube.velocity = velocity;
  cube.force = Eigen::Vector3d(0, 0, -mass * g);
  cube.mass = mass;
  cube.inertia = Eigen::Vector3d::Constant(mass / 6.0);
  return cube;
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
