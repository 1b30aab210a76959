// The separating-axis test: the penetration depth and normal of overlapping cores, and the
// normal of nearly touching ones (core_distance.h, segment_contact.h).
//
// depth(n) = h_A(n) + h_B(−n) (h the support function) is, for every unit n, an upper
// bound of the penetration depth (the distance from the origin to the boundary of A − B
// when the origin is inside); its minimum over the face normals of A − B is the depth.
// Those normals are the face normals of A, minus those of B, and e_A × e_B for the edge
// pairs that form a face of the difference: those whose arcs on the Gauss sphere cross
// (A's arc and the antipode of B's; Gregorius, "The Separating Axis Test between Convex
// Polyhedra", GDC 2013). For polytopes this candidate set contains the minimum, so the
// depth is exact to rounding. For disjoint cores the minimum is minus the largest
// separation along a candidate axis.
//
// Where the test would need a face of a sphere (a point core, no edges, no faces):
//   - sphere–polytope: the polytope's faces are the whole candidate set (exact);
//   - sphere–sphere with coincident centres: depth 0, normal +x (fixed choice);
//   - segment through a sphere's centre: depth 0, the normal a fixed unit vector ⟂ the
//     segment (u of plane_basis: e_k × s/|s|, e_k the axis least aligned with s).
#pragma once

#include <Eigen/Dense>
#include <array>
#include <limits>

#include "core/geometry/posed_shape.h"

namespace wiregrain {

// The best axis found: its depth(n) and n (unit, from A to B).
struct SatAxis {
  double depth = std::numeric_limits<double>::infinity();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  // from A to B
};

// Two point cores a and b (spheres, or a sphere and a zero-length segment): A − B is the
// single point a − b and depth(n) = n·(a − b) is least, −|b − a|, along
// n = (b − a)/|b − a|. Coincident points give depth 0 in every direction; the normal is
// then +x, a fixed choice (the default normal of CoreDistance).
SatAxis point_point_axis(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

// The least depth of two posed cores over the face normals of both and the crossing edge
// pairs (two spheres: point_point_axis).
SatAxis sat_polytopes(const PosedShape& A, const PosedShape& B);

// h(n) = max(n·end0, n·end1), the support function of a segment.
double segment_support(const std::array<Eigen::Vector3d, 2>& end, const Eigen::Vector3d& n);

// The same for a polytope P (as A) and a segment S (as B): the faces of P − S are the
// faces of P and the products of an edge of P with the segment, for the edges whose arc
// crosses the great circle ⟂ S (S has no faces). size: the configuration's, as for GJK.
//
// A sphere (core: the point c) has neither faces nor edges: P − S is the segment c − S.
// Its candidate axes ⟂ S give depth(n) = n·(c − end0), least, −(distance of c from the
// axis line), along the direction from c to its foot on the line. When the line passes
// through c (within the rounding of GJK's origin test, kGjkOrigin × size, below which
// that direction is noise) every ⟂ direction gives depth 0: the normal is then u of
// plane_basis(S/|S|), a fixed unit vector ⟂ S, and the overlap finite,
// r_grain + wire_radius. The end caps (axes ±S) need no candidate: a centre beyond an
// end is either within rounding of it or nearly touching, where segment_contact keeps
// GJK's direction when it separates more. A zero-length segment is a point:
// point_point_axis.
SatAxis sat_segment(const PosedShape& P, const std::array<Eigen::Vector3d, 2>& end, double size);

}  // namespace wiregrain
