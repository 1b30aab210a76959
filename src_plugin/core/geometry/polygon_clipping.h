// Convex polygons in the contact plane (2D coordinates of contact_frame.h): clipping of a
// polygon and of a segment by a convex polygon, the hull that cleans a clipped polygon,
// and its reduction to a few points. Used by the contact manifolds (contact_manifold.h)
// and the wire segment's contact interval (segment_contact.h).
#pragma once

#include <Eigen/Dense>
#include <boost/container/small_vector.hpp>

namespace wiregrain {

// A polygon of the contact plane and a value or an index per vertex: a face's loop or a
// clipped polygon, inline up to 16 vertices: clipping allocates nothing on the heap.
using PlanePolygon = boost::container::small_vector<Eigen::Vector2d, 16>;
using PolygonValues = boost::container::small_vector<double, 16>;
using PolygonIndices = boost::container::small_vector<int, 16>;

// a × b, the z component of the 3D cross product of two plane vectors.
inline double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Sutherland–Hodgman: the part of `subject` inside the convex counter-clockwise `clip`.
// A point counts as inside an edge when at most `tol` outside it.
PlanePolygon clip_polygon(const PlanePolygon& subject, const PlanePolygon& clip, double tol);

// Cyrus–Beck: the parameter interval [lo, hi] of the segment p0 + s (p1 − p0), s ∈ [0, 1],
// inside the convex counter-clockwise polygon (tolerance as above). False if empty.
bool clip_segment(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const PlanePolygon& poly, double tol, double& lo, double& hi);

// Convex hull (Andrew's monotone chain), counter-clockwise, of a clipped polygon's
// vertices: merges vertices closer than tol and drops vertices within tol of the line
// through their neighbours. A degenerate polygon becomes its two extreme points (a line
// contact) or one point.
PlanePolygon convex_hull_2d(PlanePolygon points, double tol);

// Reduce a convex polygon (with a gap per vertex) to at most max_points vertices by
// repeatedly removing the vertex whose triangle with its neighbours has the smallest
// area, never the deepest vertex (max_points 0: no limit). Returns the kept indices in
// polygon order.
PolygonIndices reduce_polygon(const PlanePolygon& poly, const PolygonValues& gaps, int max_points);

}  // namespace wiregrain
