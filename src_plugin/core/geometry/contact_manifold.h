// Contact manifolds of two grains and of a grain on a wall: the contact points, each with
// its own gap, normal and points on both dilated surfaces.
//
// After the signed core distance (core_distance.h: gap g = d_core − (r_A + r_B), normal n
// from A to B), the closest features: the features of A and B in the directions n and −n
// (vertex, edge or face, chosen with an angle tolerance; contact_features.h) are
// projected on the plane ⟂ n; face–face → Sutherland–Hodgman polygon clipping, edge–face
// → clipping of the segment by the polygon, parallel edges → overlap interval, otherwise
// one point (polygon_clipping.h). Each point gets its own gap measured along n (exact for
// every point, also for a feature that is parallel only within the tolerance). A sphere's
// contact feature is its vertex, so every manifold with a sphere has one point.
// docs/design.md, "Contact geometry".
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "core/geometry/contact_features.h"
#include "core/geometry/contact_options.h"
#include "core/geometry/core_distance.h"
#include "core/geometry/gjk.h"
#include "core/geometry/posed_shape.h"

namespace wiregrain {

struct ContactPoint {
  Eigen::Vector3d position;  // mid-point between the two dilated surfaces
  Eigen::Vector3d normal;    // the manifold normal, from A to B
  double gap = 0.0;          // normal · (point_b − point_a); < 0: interpenetration
  Eigen::Vector3d point_a;   // on the dilated surface of A (core point + r_A n)
  Eigen::Vector3d point_b;   // on the dilated surface of B (core point − r_B n)
};

struct ContactManifold {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  // from A to B
  double gap = 0.0;            // of the pair: core_distance − (r_A + r_B)
  double core_distance = 0.0;  // signed, see CoreDistance
  DistanceMethod method = DistanceMethod::gjk;
  ContactFeature feature_a, feature_b;  // for a wall: feature_b only
  // Empty when gap >= activation_distance. Otherwise one point (vertex involved, or
  // crossing edges), two (edge–face, parallel edges) or the clipped polygon (face–face,
  // up to max_points), all with the manifold normal; then, with options.near_vertices,
  // the near vertices' points (each with its own normal). The smallest point gap equals
  // `gap` to rounding.
  std::vector<ContactPoint> points;
};

// Contact of two grains. Points are produced when gap < activation_distance (e.g. a
// margin for gap anticipation in NSCD; +inf: always; NaN is rejected).
// simplex: the core distance's GJK warm start and last simplex (GjkSimplex), or null.
ContactManifold contact_manifold(const PosedShape& a, const PosedShape& b,
                                 double activation_distance,
                                 const ContactOptions& options = ContactOptions(),
                                 GjkSimplex* simplex = nullptr);

// An infinite wall: the plane through `point` with unit normal `normal` pointing out of
// the wall, into the space the grains occupy.
struct Plane {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

// Contact of a wall (body A, no radius) and a grain (body B); normal = the wall normal.
// Points: the vertex of the core nearest to the plane, or all vertices of the edge or
// face at that vertex that is parallel to the plane within the angle tolerance (a face
// polygon is reduced to max_points as above); gap per point = n·(v − point) − r_B.
// Points are produced when the pair gap < activation_distance.
ContactManifold plane_contact(const Plane& wall, const PosedShape& grain,
                              double activation_distance,
                              const ContactOptions& options = ContactOptions());

}  // namespace wiregrain
