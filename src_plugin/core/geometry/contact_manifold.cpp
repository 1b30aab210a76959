// Contact manifolds of two posed cores and of a core on a wall: closest features,
// clipped in the contact plane, and the near vertices. See contact_manifold.h and
// docs/design.md, "Contact geometry".
#include "core/geometry/contact_manifold.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/container/small_vector.hpp>

#include "core/common/errors.h"
#include "core/geometry/contact_frame.h"
#include "core/geometry/polygon_clipping.h"
#include "core/geometry/segment_distance.h"

namespace wiregrain {

namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

constexpr double kInf = std::numeric_limits<double>::infinity();

// Pairs of core points (on A, on B) making up a manifold, before the radii are applied.
struct CorePair {
  Vector3d a, b;
  Vector2d in_plane;  // position in the contact plane (for the polygon reduction)
};
// a manifold's few points and pairs, inline (no heap allocation per contact)
using CorePairs = boost::container::small_vector<CorePair, 16>;
using CorePoints = boost::container::small_vector<Vector3d, 16>;
using NearContactPoints = boost::container::small_vector<ContactPoint, 16>;

ContactPoint make_point(const Vector3d& core_a, const Vector3d& core_b, const Vector3d& n,
                        double r_a, double r_b) {
  ContactPoint p;
  p.normal = n;
  p.point_a = core_a + r_a * n;
  p.point_b = core_b - r_b * n;
  p.gap = n.dot(p.point_b - p.point_a);
  p.position = 0.5 * (p.point_a + p.point_b);
  return p;
}

// Multi-point manifolds from the two features; empty when the features give no
// polygon/segment (a vertex is involved, crossing edges, or degenerate clipping).
CorePairs feature_pairs(const PosedShape& A, const ContactFeature& fa, const PosedShape& B,
                        const ContactFeature& fb, const ContactFrame& frame, double sin_tol, double tol) {
  CorePairs out;
  const Vector3d& n = frame.n;
  if (fa.kind == FeatureKind::face && fb.kind == FeatureKind::face) {
    PlanePolygon poly =
        clip_polygon(face_polygon(A, fa.index, frame), face_polygon(B, fb.index, frame), tol);
    poly = convex_hull_2d(poly, tol);
    const Vector3d Na = A.face_normal(fa.index);
    const Vector3d Nb = B.face_normal(fb.index);
    for (const auto& p : poly) {
      const Vector3d x = frame.lift(p);
      out.push_back({frame.onto_plane(x, Na, A.face_offset(fa.index)),
                     frame.onto_plane(x, Nb, B.face_offset(fb.index)), p});
    }
    return out;
  }
  const bool edge_face = fa.kind == FeatureKind::edge && fb.kind == FeatureKind::face;
  const bool face_edge = fa.kind == FeatureKind::face && fb.kind == FeatureKind::edge;
  if (edge_face || face_edge) {
    const PosedShape& E = edge_face ? A : B;  // the body with the edge
    const PosedShape& F = edge_face ? B : A;  // the body with the face
    const int edge = edge_face ? fa.index : fb.index;
    const int face = edge_face ? fb.index : fa.index;
    const auto& e = E.shape().edges()[edge];
    const Vector3d& e0 = E.vertices()[e[0]];
    const Vector3d& e1 = E.vertices()[e[1]];
    double lo = 0.0, hi = 1.0;
    if (!clip_segment(frame.project(e0), frame.project(e1), face_polygon(F, face, frame), tol,
                      lo, hi))
      return out;
    const double length = (frame.project(e1) - frame.project(e0)).norm();
    PolygonValues params = {lo, hi};
    if ((hi - lo) * length <= tol) params = {0.5 * (lo + hi)};
    for (double s : params) {
      const Vector3d on_edge = e0 + s * (e1 - e0);
      const Vector3d on_face =
          frame.onto_plane(on_edge, F.face_normal(face), F.face_offset(face));
      if (edge_face)
        out.push_back({on_edge, on_face, frame.project(on_edge)});
      else
        out.push_back({on_face, on_edge, frame.project(on_edge)});
    }
    return out;
  }
  if (fa.kind == FeatureKind::edge && fb.kind == FeatureKind::edge) {
    const auto& ea = A.shape().edges()[fa.index];
    const auto& eb = B.shape().edges()[fb.index];
    const Vector3d &a0 = A.vertices()[ea[0]], &a1 = A.vertices()[ea[1]];
    const Vector3d &b0 = B.vertices()[eb[0]], &b1 = B.vertices()[eb[1]];
    const Vector3d da = (a1 - a0).normalized(), db = (b1 - b0).normalized();
    if (da.cross(db).norm() > sin_tol) return out;  // crossing edges: one point
    // parallel edges: the overlap of their intervals along the common direction
    Vector3d dir = da - n.dot(da) * n;
    dir.normalize();
    const double alpha0 = dir.dot(a0), alpha1 = dir.dot(a1);
    const double beta0 = dir.dot(b0), beta1 = dir.dot(b1);
    const double lo = std::max(std::min(alpha0, alpha1), std::min(beta0, beta1));
    const double hi = std::min(std::max(alpha0, alpha1), std::max(beta0, beta1));
    if (hi < lo - tol) return out;
    PolygonValues at = {lo, hi};
    if (hi - lo <= tol) at = {0.5 * (lo + hi)};
    for (double sigma : at) {
      const double sa = std::clamp((sigma - alpha0) / (alpha1 - alpha0), 0.0, 1.0);
      const double sb = std::clamp((sigma - beta0) / (beta1 - beta0), 0.0, 1.0);
      const Vector3d pa = a0 + sa * (a1 - a0), pb = b0 + sb * (b1 - b0);
      out.push_back({pa, pb, frame.project(pa)});
    }
    return out;
  }
  return out;
}

// One pair of core points from the features, for a normal that does not come from the
// closest points (SAT): a vertex and its projection along n on the other feature, or the
// closest points of two crossing edges.
CorePair single_pair(const PosedShape& A, const ContactFeature& fa, const PosedShape& B,
                     const ContactFeature& fb, const ContactFrame& frame,
                     double signed_distance) {
  const Vector3d& n = frame.n;
  CorePair out;
  if (fa.kind == FeatureKind::vertex) {
    out.a = A.vertices()[fa.index];
    out.b = feature_point_on_line(B, fb, out.a, n);
  } else if (fb.kind == FeatureKind::vertex) {
    out.b = B.vertices()[fb.index];
    out.a = feature_point_on_line(A, fa, out.b, n);
  } else if (fa.kind == FeatureKind::edge && fb.kind == FeatureKind::edge) {
    const auto& ea = A.shape().edges()[fa.index];
    const auto& eb = B.shape().edges()[fb.index];
    // the closest points of the two edges (segment_distance.h)
    const SegmentClosestPoints closest =
        segment_closest_points(A.vertices()[ea[0]], A.vertices()[ea[1]], B.vertices()[eb[0]], B.vertices()[eb[1]]);
    out.a = A.vertices()[ea[0]] + closest.s * (A.vertices()[ea[1]] - A.vertices()[ea[0]]);
    out.b = B.vertices()[eb[0]] + closest.t * (B.vertices()[eb[1]] - B.vertices()[eb[0]]);
  } else {
    // degenerate clipping of parallel features: A's support vertex and the point at the
    // separation along n
    out.a = A.vertices()[A.support_vertex(n)];
    out.b = out.a + signed_distance * n;
  }
  out.in_plane = frame.project(out.a);
  return out;
}

// The points of the vertices of P that come within the activation distance of Q and
// carry no point yet (ContactOptions::near_vertices). n is the pair normal from P to Q
// and core_distance their signed core distance along it; reach = activation distance +
// r_A + r_B is the core distance below which a vertex is activated. Prefilter: a vertex
// whose height n·v lies h below P's support height is at least h + core_distance from Q
// (Q lies beyond the plane n·x = support + core_distance), so only h < reach −
// core_distance can qualify. Then the vertex's exact distance to Q's core (GJK of the point
// against Q) and its own normal along the closest points; a vertex inside Q's core gets
// the face of Q nearest to it (depth = its distance to that face's plane, normal ∓ the
// face normal), so its gap is never below the pair's (a translation that separates the
// cores moves the vertex at least its depth). Points go to `out` as (core point on A,
// core point on B, unit normal from A to B).
// Near vertices are looked for within this fraction of the pair's size (the sum of the
// core radii; for a wall the grain's) of the other core, if the activation distance is
// larger: a vertex closes within a step by h times its speed, h ω L ~ 0.01–0.03 a_max in
// a deposit at h = 1e-3; a time step so large that the activation distance spans whole
// grains would otherwise put every vertex of every pair into the solve (30 grains at
// h = 0.24: 8279 points, 8 s per step, against 0.1 s with the closest features).
constexpr double kNearVertexSlab = 0.1;

// At most max_points of them (0: all), the smallest gaps first.
void keep_deepest(NearContactPoints& points, int max_points) {
  if (max_points <= 0 || static_cast<int>(points.size()) <= max_points) return;
  std::stable_sort(points.begin(), points.end(),
                   [](const ContactPoint& x, const ContactPoint& y) { return x.gap < y.gap; });
  points.resize(max_points);
}

struct NearPoint {
  Vector3d a, b, normal;
};
using NearPoints = boost::container::small_vector<NearPoint, 16>;

void add_near_vertices(const PosedShape& P, const PosedShape& Q, bool p_is_a, const Vector3d& n,
                       double core_distance, double reach, double size, double tol,
                       const CorePoints& taken, NearPoints& out) {
  const double support = support_value(P, n);
  const double depth_limit = reach - core_distance;
  const auto is_taken = [&](const Vector3d& v) {
    for (const Vector3d& t : taken)
      if ((t - v).squaredNorm() <= tol * tol) return true;
    for (const NearPoint& p : out)
      if (((p_is_a ? p.a : p.b) - v).squaredNorm() <= tol * tol) return true;
    return false;
  };
  const double margin = 1e-12 * size;
  for (const Vector3d& v : P.vertices()) {
    // beyond the reach by the lower bound (with a margin for the rounding of the body
    // frame): the GJK below would leave the vertex out as well. Saves 81 % of the GJKs
    // on the core tests' pours and random pairs (19 % of the candidates reach the GJK)
    if (!(support - n.dot(v) < depth_limit) || is_taken(v) || height_above_faces(Q, v) > reach + margin)
      continue;
    const GjkResult g = gjk(SegmentSet{{v, v}}, PolytopeSet{&Q}, v - Q.position(), size, reach);
    if (g.far) continue;
    Vector3d on_q, normal;  // normal from P to Q
    if (!g.touching && g.distance > kNearTouching * size) {
      if (!(g.distance < reach)) continue;
      on_q = g.point_b;
      normal = (on_q - v) / g.distance;
    } else {
      // inside (or on) Q's core: the face of Q whose plane is nearest
      int face = 0;
      double depth = kInf;
      for (int f = 0; f < static_cast<int>(Q.shape().faces().size()); ++f) {
        const double d = Q.shape().faces()[f].offset - Q.face_normal(f).dot(v - Q.position());
        if (d < depth) {
          depth = d;
          face = f;
        }
      }
      normal = -Q.face_normal(face);
      on_q = v - depth * normal;
    }
    // the vertex–vertex point of B's pass may repeat one of A's pass
    bool repeated = false;
    for (const NearPoint& p : out)
      repeated = repeated || (((p_is_a ? p.b : p.a) - on_q).squaredNorm() <= tol * tol &&
                              ((p_is_a ? p.a : p.b) - v).squaredNorm() <= tol * tol);
    if (repeated) continue;
    if (p_is_a)
      out.push_back({v, on_q, normal});
    else
      out.push_back({on_q, v, -normal});
  }
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Contact manifold of two grains

ContactManifold contact_manifold(const PosedShape& a, const PosedShape& b,
                                 double activation_distance, const ContactOptions& options,
                                 GjkSimplex* simplex) {
  require_not_nan("activation_distance", activation_distance);
  check_contact_options(options);
  const double r_a = a.sweep_radius(), r_b = b.sweep_radius();
  const double reach = activation_distance + options.exit_beyond_activation + r_a + r_b;
  const CoreDistance cd = core_distance(a, b, reach > 0.0 ? reach : 0.0, simplex);  // inf: never

  ContactManifold m;
  m.normal = cd.normal;
  m.core_distance = cd.distance;
  m.gap = cd.distance - (r_a + r_b);
  m.method = cd.method;
  if (cd.method == DistanceMethod::gjk_far || !(m.gap < activation_distance)) return m;

  const Vector3d& n = cd.normal;
  const double cos_tol = std::cos(options.angle_tolerance);
  const double sin_tol = std::sin(options.angle_tolerance);
  const double size = configuration_size(a, b.position(), b.core_radius());
  const double tol = kMergeTolerance * size;
  m.feature_a = select_feature(a, n, cos_tol, sin_tol, tol);
  m.feature_b = select_feature(b, -n, cos_tol, sin_tol, tol);

  const ContactFrame frame(cd.point_a, n);
  CorePairs pairs = feature_pairs(a, m.feature_a, b, m.feature_b, frame, sin_tol, tol);
  if (pairs.empty()) {
    if (cd.method == DistanceMethod::gjk || cd.method == DistanceMethod::gjk_sat)
      pairs.push_back({cd.point_a, cd.point_b, frame.project(cd.point_a)});
    else
      pairs.push_back(single_pair(a, m.feature_a, b, m.feature_b, frame, cd.distance));
  }

  PlanePolygon in_plane;
  PolygonValues gaps;
  for (const auto& p : pairs) {
    in_plane.push_back(p.in_plane);
    gaps.push_back(n.dot(p.b - p.a));
  }
  const PolygonIndices kept = reduce_polygon(in_plane, gaps, options.max_points);

  NearContactPoints near_points;
  if (options.near_vertices) {
    CorePoints taken_a, taken_b;
    for (const auto& p : pairs) {
      taken_a.push_back(p.a);
      taken_b.push_back(p.b);
    }
    NearPoints near;
    const double near_reach =
        std::min(activation_distance, kNearVertexSlab * (a.core_radius() + b.core_radius())) + r_a + r_b;
    add_near_vertices(a, b, true, n, cd.distance, near_reach, size, tol, taken_a, near);
    add_near_vertices(b, a, false, -n, cd.distance, near_reach, size, tol, taken_b, near);
    for (const NearPoint& p : near) near_points.push_back(make_point(p.a, p.b, p.normal, r_a, r_b));
    keep_deepest(near_points, options.max_points);
  }
  m.points.reserve(kept.size() + near_points.size());  // one allocation
  for (int i : kept) m.points.push_back(make_point(pairs[i].a, pairs[i].b, n, r_a, r_b));
  m.points.insert(m.points.end(), near_points.begin(), near_points.end());
  return m;
}

// ---------------------------------------------------------------------------------------
// Wall

ContactManifold plane_contact(const Plane& wall, const PosedShape& grain,
                              double activation_distance, const ContactOptions& options) {
  require_not_nan("activation_distance", activation_distance);
  check_contact_options(options);
  require_finite_vector("wall.point", wall.point);
  const double length = wall.normal.norm();
  if (!std::isfinite(length) || !(length > 0.0))
    throw InvalidArgument("wall.normal", "wall.normal must be a finite non-zero vector");
  const Vector3d n = wall.normal / length;
  const double r = grain.sweep_radius();

  ContactManifold m;
  m.normal = n;
  m.method = DistanceMethod::plane;
  m.feature_a = {FeatureKind::face, -1};
  const int lowest = grain.support_vertex(-n);
  m.core_distance = n.dot(grain.vertices()[lowest] - wall.point);
  m.gap = m.core_distance - r;
  if (!(m.gap < activation_distance)) return m;

  const double size = grain.core_radius();
  m.feature_b = select_feature(grain, -n, std::cos(options.angle_tolerance),
                               std::sin(options.angle_tolerance), kMergeTolerance * size);
  PolygonIndices vertices;
  switch (m.feature_b.kind) {
    case FeatureKind::face: {
      const auto& loop = grain.shape().faces()[m.feature_b.index].vertices;
      vertices.assign(loop.begin(), loop.end());
      break;
    }
    case FeatureKind::edge: {
      const auto& e = grain.shape().edges()[m.feature_b.index];
      vertices = {e[0], e[1]};
      break;
    }
    case FeatureKind::vertex:
    default:
      vertices = {m.feature_b.index};
  }
  const ContactFrame frame(wall.point, n);
  PlanePolygon in_plane;
  PolygonValues gaps;
  for (int v : vertices) {
    in_plane.push_back(frame.project(grain.vertices()[v]));
    gaps.push_back(n.dot(grain.vertices()[v] - wall.point));
  }
  const PolygonIndices kept = reduce_polygon(in_plane, gaps, options.max_points);
  NearContactPoints near_points;
  if (options.near_vertices) {
    const double near_reach = std::min(activation_distance, kNearVertexSlab * grain.core_radius());
    for (int i = 0; i < static_cast<int>(grain.vertices().size()); ++i) {
      const Vector3d& v = grain.vertices()[i];
      const double core_gap = n.dot(v - wall.point);
      if (core_gap - r < near_reach && std::find(vertices.begin(), vertices.end(), i) == vertices.end())
        near_points.push_back(make_point(v - core_gap * n, v, n, 0.0, r));
    }
    keep_deepest(near_points, options.max_points);
  }
  m.points.reserve(kept.size() + near_points.size());  // one allocation
  for (int i : kept) {
    const Vector3d& v = grain.vertices()[vertices[i]];
    m.points.push_back(make_point(v - gaps[i] * n, v, n, 0.0, r));
  }
  m.points.insert(m.points.end(), near_points.begin(), near_points.end());
  return m;
}

}  // namespace wiregrain
