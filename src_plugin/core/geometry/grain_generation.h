// The shapes and orientations of new grains (create_grains), drawn from one seeded
// random stream (std::mt19937_64): a random ellipsoid hull per grain, the grains of the
// paper (Table 1: semi-axis a uniform in [a_min, a_max], b/a, c/a, N vertices, sweep
// radius), or one given shape for all of them. Which numbers each function takes from the
// stream, and in which order, is part of its contract: a seed gives the same grains to
// the bit on every platform and any number of MPI ranks.
#pragma once

#include <Eigen/Geometry>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "core/common/random_stream.h"
#include "core/geometry/convex_shape.h"
#include "core/geometry/shape_library.h"

namespace wiregrain {

// Uniformly distributed unit quaternion from three draws u1, u2, u3 (Shoemake, Graphics
// Gems III, 1992): (√u1 cos 2πu3, √(1−u1) sin 2πu2, √(1−u1) cos 2πu2, √u1 sin 2πu3), w first.
Eigen::Quaterniond random_orientation(std::mt19937_64& rng);

// The grains' shape: kind ellipsoid (a random ellipsoid hull per grain) or one shape for
// all: cube, tetrahedron, octahedron (edge size[0]), box (edges size[0..2]), sphere
// (radius size[0]) or file (the hull of the points in `path`).
struct GrainShapeRecipe {
  std::string kind = "ellipsoid";
  double size[3] = {0.0, 0.0, 0.0};
  std::string path;
  double a_min = 0.8, a_max = 1.0;    // ellipsoid: the largest semi-axis a
  double b_over_a = 0.8, c_over_a = 0.6;
  int n_vertices = 20;
  double sweep = 0.1;                 // sweep radius (not of a sphere)
};

// The shape of every grain as an index into the caller's library and the rotation body
// frame → the frame the shape was given in (a grain drawn with the orientation
// q_random · body_to_input[k] is the input shape turned by q_random).
struct GrainShapeDraw {
  std::vector<int> shape_of;
  std::vector<Eigen::Quaterniond> body_to_input;
};

// Puts a shape into the caller's library: returns its index and sets the rotation body
// frame → given frame.
using AddGrainShape = std::function<int(const ConvexShape& shape, Eigen::Quaterniond& body_to_input)>;

// The shapes of n grains, added through `add` in the order of the grains. Ellipsoid: per
// grain a = a_min + (a_max − a_min) u (one draw), then ConvexShape::random_ellipsoid from
// the same stream, one library shape per grain; any other kind: one shape, added once, no
// draw. Throws what ConvexShape's constructors and `add` throw (InvalidArgument,
// NumericalFailure).
GrainShapeDraw draw_grain_shapes(std::mt19937_64& rng, const GrainShapeRecipe& recipe, int n,
                                 const AddGrainShape& add);

// Grains as spheres of their volumes: every shape of `library` gets the sphere of radius
// r = (3V / 4π)^(1/3) (V: the library's volume of the shape), added after the existing
// shapes in library order, and every index of shape_of is turned to its shape's sphere.
void replace_by_spheres_of_volume(ShapeLibrary& library, std::vector<int>& shape_of);

}  // namespace wiregrain
