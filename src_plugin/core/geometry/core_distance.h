// The signed distance of two grains' cores: the first step of every contact query.
//
// A grain is its core dilated by its sweep radius (posed_shape.h). Two grains A and B
// touch when the distance between their cores equals r_A + r_B, so every query first
// solves the distance problem of the sharp cores and then subtracts the radii:
//
//   gap g = d_core − (r_A + r_B),      normal n: unit vector from A to B.
//
// The core distance d_core is signed: the Euclidean distance of the cores when they are
// disjoint, minus their penetration depth when they overlap (the length of the shortest
// translation of B that separates the cores; n is its direction). So g < 0 means
// interpenetration of the dilated grains, whatever its depth.
//
// Algorithms (details and measured accuracy in docs/design.md, "Contact geometry"):
//   - distance of disjoint cores: GJK (gjk.h) on the Minkowski difference A − B;
//   - overlapping cores (and, for the normal, cores closer than kNearTouching × their
//     size, where the GJK direction is ill-conditioned; the direction that separates the
//     cores more is kept): the separating-axis test (sat.h), exact to rounding for
//     polytopes.
// Spheres (ConvexShape::is_sphere(): the core is one point, no edges, no faces) go
// through the same code: their support point is the centre (the SAT's cases in sat.h).
//
// Inputs are checked (InvalidArgument, argument() names the C++ parameter): non-finite
// positions or orientations, zero quaternions, negative radii, bad options.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include "core/geometry/convex_shape.h"
#include "core/geometry/gjk.h"
#include "core/geometry/posed_shape.h"

namespace wiregrain {

// Cores closer than this (relative to the size of the configuration) are "nearly
// touching": the direction of the GJK closest-point difference, whose rounding is
// ~1e-16 × |x|, is then worse than ~1e-8 rad, and the normal is taken from the SAT unless
// the GJK direction separates the cores more.
constexpr double kNearTouching = 1e-8;

// How the signed core distance was obtained.
enum class DistanceMethod {
  gjk,         // disjoint cores: GJK distance, normal along the closest points
  gjk_sat,     // disjoint but nearly touching cores (< 1e-8 × size): GJK distance,
               // normal from the SAT
  sat,         // overlapping cores: SAT penetration depth and normal
  gjk_far,     // GJK stopped early: the cores are farther apart than the early-exit
               // distance; `distance` is a lower bound, points and normal approximate
  plane        // wall contact: exact support-point query against the plane
};

// Signed distance of the two sharp cores.
struct CoreDistance {
  double distance = 0.0;  // > 0: Euclidean distance; <= 0: minus the penetration depth
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  // unit, from A to B
  // disjoint: the closest points of the cores (point_b − point_a = distance · normal);
  // overlapping: a deepest point of each core along the normal
  // (normal · (point_b − point_a) = distance)
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d point_b = Eigen::Vector3d::Zero();
  DistanceMethod method = DistanceMethod::gjk;
  int gjk_iterations = 0;
  bool overlapping() const { return distance <= 0.0; }
};

// min over the core's vertices of n · x, the shape placed at (position, orientation)
// without posing it (n turned into the body frame). For two cores and any unit n,
//     lowest_core_point(B, n) + lowest_core_point(A, −n) ≤ signed core distance of A and B
// (the separation along n; equal for the optimal n, the signed distance of two convex sets
// being their largest separation over all axes).
double lowest_core_point(const ConvexShape& shape, const Eigen::Vector3d& position,
                         const Eigen::Quaterniond& orientation, const Eigen::Vector3d& n);

// A lower bound of the distance from x to the core of `shape`: x's largest height above
// the core's face planes, max_f (n_f·x − o_f) (the core is the intersection of the
// half-spaces n_f·y <= o_f, so |x − y| >= n_f·(x − y) >= n_f·x − o_f for every y in it;
// equal to the distance when x's foot on that plane lies in the face; <= 0 inside).
// (Not used for the wire segments' early exit: the GJK of a segment apart stops within one
// or two iterations, cheaper than the face loop.)
double height_above_faces(const PosedShape& shape, const Eigen::Vector3d& x);

// Distance of the cores of a and b. early_exit_distance: if > 0, GJK stops as soon as its
// lower bound proves distance > early_exit_distance (method gjk_far); 0 or +inf: always
// solve (negative or NaN: InvalidArgument). simplex: GJK's warm start and last simplex
// (see GjkSimplex), or null.
CoreDistance core_distance(const PosedShape& a, const PosedShape& b,
                           double early_exit_distance = 0.0, GjkSimplex* simplex = nullptr);

}  // namespace wiregrain
