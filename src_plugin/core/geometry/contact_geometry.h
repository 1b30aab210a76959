// Contact geometry of spheropolyhedra (grains), walls and wire segments.
//
// A grain is a convex polyhedron P (its "core", a ConvexShape in the body frame) dilated
// by its sweep radius r (ConvexShape::sweep_radius()). Two grains A and B touch when the
// distance between their cores equals r_A + r_B, so every query first solves the
// distance problem of the sharp cores and then subtracts the radii:
//
//   gap g = d_core − (r_A + r_B),      normal n: unit vector from A to B.
//
// The core distance d_core is signed: the Euclidean distance of the cores when they are
// disjoint, minus their penetration depth when they overlap (the length of the shortest
// translation of B that separates the cores; n is its direction). So g < 0 means
// interpenetration of the dilated grains, whatever its depth.
//
// Algorithms (details and measured accuracy in docs/design.md, "Contact geometry"):
//   - distance of disjoint cores: GJK (Gilbert, Johnson & Keerthi, IEEE J. Robot. Autom.
//     4 (1988) 193) on the Minkowski difference A − B, with the signed-volumes
//     sub-simplex solver of Montanari, Petrinic & Barbieri, ACM Trans. Graph. 36 (2017)
//     32, made exhaustive (every face/edge of a simplex whose barycentric coordinates
//     fail the sign test is tried, the nearest wins). Terminates when the support point
//     repeats a simplex vertex (exact optimality for polytopes) or gains less than
//     1e-15 relative;
//   - overlapping cores (and, for the normal, cores closer than 1e-8 × their size, where
//     the GJK direction is ill-conditioned; the direction that separates the cores more
//     is kept): separating-axis test over the face normals of both
//     cores and the cross products of edge pairs that form a face of the Minkowski
//     difference (Gauss-map arc test, Gregorius, GDC 2013). For polytopes this candidate
//     set contains the minimum, so the depth is exact to rounding;
//   - contact manifold: closest features. The features of A and B in the directions n
//     and −n (vertex, edge or face, chosen with an angle tolerance) are projected on the
//     plane ⟂ n; face–face → Sutherland–Hodgman polygon clipping, edge–face → clipping of
//     the segment by the polygon, parallel edges → overlap interval, otherwise one point.
//     Each point gets its own gap measured along n (exact for every point, also for a
//     feature that is parallel only within the tolerance).
//
// Spheres (ConvexShape::is_sphere(): the core is one point, no edges, no faces) go
// through the same code: their support point is the centre, their contact feature the
// vertex, so every manifold with a sphere has one point. Where the SAT would need a
// face of the sphere (details in contact_geometry.cpp, docs/design.md, "Contact geometry"):
//   - sphere–polytope: the polytope's faces are the whole candidate set (exact);
//   - sphere–sphere with coincident centres: depth 0, normal +x (fixed choice);
//   - segment through a sphere's centre: depth 0, the normal a fixed unit vector ⟂ the
//     segment (u of plane_basis: e_k × s/|s|, e_k the axis least aligned with s).
//
// Inputs are checked (InvalidArgument, argument() names the C++ parameter): non-finite
// positions or orientations, zero quaternions, negative radii, bad options.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <array>
#include <limits>
#include <vector>

#include "core/geometry/convex_shape.h"

namespace wiregrain {

class PosedSuperquadric;  // core/geometry/superquadric.h

// A ConvexShape (body frame) placed in the world: x_world = R(q) x_body + position.
// Holds a pointer to the shape (which must outlive it) and the world-frame vertices,
// face normals and face offsets, computed once at construction (so a grain posed once
// per time step can be used in all its pair queries).
class PosedShape {
 public:
  // orientation: body -> world, any non-zero finite quaternion (normalised here).
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
  const std::vector<Eigen::Vector3d>& vertices() const { return vertices_; }
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
  std::vector<Eigen::Vector3d> vertices_;
};

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

// GJK's simplex of a pair: the support indices of its 1–4 points of the Minkowski
// difference A − B (a: A's vertex, b: B's vertex or the segment's end 0/1). A query given
// one starts GJK from it (reduced to its nearest sub-simplex first) instead of from the
// support along the centres, and leaves its own last simplex there (the tetrahedron when
// the cores overlap): the warm start of a pair queried again a step later, whose closest
// features rarely change. GJK converges to the closest point from any simplex of the
// difference (Gilbert, Johnson & Keerthi 1988) with the same stopping rules, so the
// answer is the same to GJK's tolerance, not to the bit: where the closest point lies on
// a face of the difference with more than three vertices (face–face, edge–edge) the
// simplex that holds it depends on the path. size 0 (or indices out of range): a cold
// start, the same result to the bit as without a simplex. docs/design.md, "Contact geometry".
struct GjkSimplex {
  std::array<int, 4> a{}, b{};
  int size = 0;
};

// Distance of the cores of a and b. early_exit_distance: if > 0, GJK stops as soon as its
// lower bound proves distance > early_exit_distance (method gjk_far); 0 or +inf: always
// solve. simplex: GJK's warm start and last simplex (see GjkSimplex), or null.
CoreDistance core_distance(const PosedShape& a, const PosedShape& b,
                           double early_exit_distance = 0.0, GjkSimplex* simplex = nullptr);

// Tolerances and limits of the contact manifold.
struct ContactOptions {
  // A face (edge) counts as parallel to the contact plane when its normal (direction) is
  // within this angle of n (of the plane). Radians, in [0, 0.5]. Larger values give
  // multi-point manifolds for more tilted resting contacts; the point gaps stay exact.
  double angle_tolerance = 1e-2;
  // At most this many points per manifold (0: no limit). Polygons with more vertices
  // are reduced by repeatedly dropping the vertex whose removal loses the least area,
  // never the deepest one.
  int max_points = 8;
  // segment_contact only: the closest feature and the parallel interval are looked up
  // only when the gap is at most this; a segment farther away gets GJK's closest points
  // and t_begin = t_end = t (callers that only need the gap of pairs apart pass 0: the
  // feature lookup was a quarter of the wire–grain contact time, bench/wire_grain_contacts.py).
  double feature_gap_limit = std::numeric_limits<double>::infinity();
  // contact_manifold and plane_contact: besides the closest features' points, a point for
  // every other vertex of a core whose own gap is below the activation distance (its
  // closest point on the other core, its own normal along the two; for a wall the wall
  // normal). Without them a grain tumbling onto another (or a wall) closes its next vertex
  // one step late: overlaps of ~1e-3 a_max in deposits (docs/design.md, "Contact geometry").
  bool near_vertices = false;
  // contact_manifold: GJK may stop once the gap is known to exceed activation_distance +
  // this (≥ 0, +inf: never early); the
  // manifold's gap is then a lower bound (method gjk_far). A pair within it gets its exact
  // gap, and the same points as with 0. The grain pair cache (core/nscd/grain_pairs.h)
  // passes its skin to learn which pairs lie beyond activation + skin.
  double exit_beyond_activation = 0.0;
  // segment_contact (polytope) only: GJK may stop once the gap (between the swept surfaces)
  // is known to exceed this (+inf: never, the default; negative or NaN: InvalidArgument);
  // the gap is then GJK's lower bound (method gjk_far, normal along the centres, t = ½).
  // A pair with gap ≤ exit_gap gets exactly the result it gets without it (its lower
  // bounds never exceed it). The wire–grain contact passes the gap below which it needs
  // exact values (0 for a touching test, the pair cache's skin at a build): most of its
  // evaluated pairs are apart.
  double exit_gap = std::numeric_limits<double>::infinity();
};

enum class FeatureKind { vertex, edge, face };

// The feature of a core that carries the contact: index into the shape's vertices(),
// edges() or faces().
struct ContactFeature {
  FeatureKind kind = FeatureKind::vertex;
  int index = -1;
};

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

// Contact of a grain and a wire element: the segment [end0, end1] dilated by
// wire_radius (a spherocylinder).
struct SegmentContact {
  double distance = 0.0;  // signed core–axis distance (<= 0: minus the penetration depth)
  double gap = 0.0;       // distance − (r_grain + wire_radius)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  // unit, from the grain to the wire
  Eigen::Vector3d point_on_core = Eigen::Vector3d::Zero();
  Eigen::Vector3d point_on_segment = Eigen::Vector3d::Zero();
  // point_on_segment = end0 + t (end1 − end0), t ∈ [0, 1]: the closest point; when the
  // segment is parallel (within the angle tolerance) to the contact face or edge the
  // closest points form an interval [t_begin, t_end] and t is its middle (the force is
  // then shared by the nodes); otherwise t_begin = t_end = t.
  double t = 0.0, t_begin = 0.0, t_end = 0.0;
  DistanceMethod method = DistanceMethod::gjk;
  int gjk_iterations = 0;
};

// simplex: GJK's warm start and last simplex (GjkSimplex: a the grain's vertex, b the
// segment's end), or null.
SegmentContact segment_contact(const PosedShape& grain, const Eigen::Vector3d& end0,
                               const Eigen::Vector3d& end1, double wire_radius,
                               const ContactOptions& options = ContactOptions(),
                               GjkSimplex* simplex = nullptr);

// The same against a superquadric (core/geometry/superquadric.h; no sweep radius: gap =
// distance − wire_radius). Apart: GJK with the closed-form support point (stopped when
// the distance bound gains less than 1e-16 of the size), then a Newton polish of the
// closest points in the normal and the segment parameter; the nearest of the genuine
// pairs (support point c(n), its projection on the segment) built from GJK's direction,
// the polished one and GJK's own body point (docs/design.md, "Contact geometry"). Closer than 1e-8 of
// the size: the surface normal (∇F) at GJK's body point. An axis that touches or crosses
// the body (overlap ≥ r_w): the normal is ∇F at the segment point nearest the body's
// centre, the distance minus the overlap of body and segment along it (a
// separating-axis depth along that one axis: ≥ the penetration depth), t that point's
// parameter. No flat features: t_begin = t_end = t.
// early_exit_distance > 0 (0 or +inf: never; negative or NaN: InvalidArgument): GJK stops
// as soon as its lower bound v·w/|v| shows the distance exceeds it (method gjk_far; the
// distance is that lower bound, so the gap is one too; normal along the centres, t = ½).
// Callers that need only touching pairs (and the gaps below some bound) pass it: the
// Newton polish of pairs apart was 90 % of a superquadric column's run time.
//
// guess (optional): a previous solution of the same pair (normal from the body to the
// segment, segment parameter t), e.g. last step's. The Newton polish starts there; its
// result (n, t) is kept only if it certifies itself: with c = c(n), p = x0 + t s, d =
// n·(p − c) > 0, the plane n·x = n·c supports the body, and the segment lies beyond
// n·p − |s|·ε_s (ε_s = |s·n|/|s| for t inside, the outward part of it at an end), so the
// true distance lies in [d − |s| ε_s, |p − c|]; accepted when that interval is below 1e-12
// of the size (then method gjk, gjk_iterations 0). Otherwise the full query. The last
// step's pair moves ~1e-5 a step: the polish converges in one or two iterations, and GJK
// (≈20 support points and simplex solves) and the two cold polishes are skipped.
struct SmoothContactGuess {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double t = 0.0;
};
SegmentContact segment_contact(const PosedSuperquadric& grain, const Eigen::Vector3d& end0,
                               const Eigen::Vector3d& end1, double wire_radius,
                               double early_exit_distance = 0.0, const SmoothContactGuess* guess = nullptr);

}  // namespace wiregrain
