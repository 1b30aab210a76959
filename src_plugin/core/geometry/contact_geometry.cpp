// Contact geometry of spheropolyhedra, walls and wire segments: GJK distance with the
// signed-volumes sub-simplex solver, separating-axis penetration depth, closest-feature
// contact manifolds. See contact_geometry.h and docs/design.md, "Contact geometry".
#include "core/geometry/contact_geometry.h"
#include "core/geometry/nearest_simplex.h"
#include "core/geometry/segment_distance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <utility>

#include "core/common/errors.h"
#include "core/geometry/superquadric.h"

namespace wiregrain {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector2d;
using Eigen::Vector3d;

constexpr double kInf = std::numeric_limits<double>::infinity();

// Cores closer than this (relative to the size of the configuration) are "nearly
// touching": the direction of the GJK closest-point difference, whose rounding is
// ~1e-16 × |x|, is then worse than ~1e-8 rad, and the normal is taken from the SAT unless
// the GJK direction separates the cores more.
constexpr double kNearTouching = 1e-8;
// GJK: the origin counts as reached (cores touch or overlap) when |v| is below this
// times the size; the iteration stops when the support point improves the bound by less
// than this (relative to |v| and to the size).
constexpr double kGjkOrigin = 1e-14;
constexpr double kGjkProgress = 1e-15;
constexpr int kGjkMaxIterations = 200;
// GJK against a smooth body (a superquadric) approaches the closest points without ever
// repeating a support point: it stops when the distance bound improves by less than this
// (relative to the size): at most 58 iterations over tests/core's random segments.
constexpr double kGjkSmoothProgress = 1e-16;
// Clipped polygon vertices closer than this times the size are merged; a vertex this
// close to the line through its neighbours is dropped; clipping treats points this far
// outside a polygon edge as on it; vertices this close to a supporting plane belong to
// the support set.
constexpr double kMergeTolerance = 1e-10;
// Edge pairs whose cross product is below this (relative to the edge lengths) are
// parallel: their separating axis coincides with a face normal (tested anyway).
constexpr double kParallelEdges = 1e-12;

std::string number(double x) {
  std::ostringstream s;
  s.precision(12);
  s << x;
  return s.str();
}

bool finite(const Vector3d& v) { return v.allFinite(); }

double cross2(const Vector2d& a, const Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

void check_options(const ContactOptions& options) {
  if (!(options.angle_tolerance >= 0.0 && options.angle_tolerance <= 0.5))
    throw InvalidArgument("angle_tolerance", "angle_tolerance must be in [0, 0.5] rad, got " +
                                                 number(options.angle_tolerance));
  if (options.max_points < 0)
    throw InvalidArgument("max_points", "max_points must be >= 0 (0: no limit), got " +
                                            std::to_string(options.max_points));
  if (std::isnan(options.feature_gap_limit))
    throw InvalidArgument("feature_gap_limit", "feature_gap_limit must not be NaN");
  if (!(options.exit_beyond_activation >= 0.0))
    throw InvalidArgument("exit_beyond_activation", "exit_beyond_activation must be >= 0, got " +
                                                        number(options.exit_beyond_activation));
  if (!(options.exit_gap >= 0.0))
    throw InvalidArgument("exit_gap", "exit_gap must be >= 0, got " + number(options.exit_gap));
}

void check_not_nan(const char* name, double value) {
  if (std::isnan(value))
    throw InvalidArgument(name, std::string(name) + " must be a number (±inf allowed), got nan");
}

void check_finite(const char* name, const Vector3d& value) {
  if (!finite(value))
    throw InvalidArgument(name, std::string(name) + " must have finite coordinates");
}

// ---------------------------------------------------------------------------------------
// Convex sets seen by GJK through their support points (vertex indices).

struct PolytopeSet {
  const PosedShape* shape;
  int count() const { return static_cast<int>(shape->vertices().size()); }
  int support(const Vector3d& d) const { return shape->support_vertex(d); }
  const Vector3d& point(int i) const { return shape->vertices()[i]; }
};

// A superquadric: its support points are computed on demand and kept, so that an index
// names a point as for the polytopes (indices never repeat: GJK stops on progress alone).
struct SuperquadricSet {
  explicit SuperquadricSet(const PosedSuperquadric& b) : body(&b) { points.reserve(kGjkMaxIterations + 2); }
  const PosedSuperquadric* body;
  mutable std::vector<Vector3d> points;
  int count() const { return 0; }  // no warm simplex: its points are made anew by each query
  int support(const Vector3d& d) const {
    points.push_back(body->support(d));
    return static_cast<int>(points.size()) - 1;
  }
  const Vector3d& point(int i) const { return points[i]; }
};

struct SegmentSet {
  std::array<Vector3d, 2> end;
  int count() const { return 2; }
  int support(const Vector3d& d) const { return d.dot(end[1]) > d.dot(end[0]) ? 1 : 0; }
  const Vector3d& point(int i) const { return end[i]; }
};

// ---------------------------------------------------------------------------------------
// The sub-simplex solver: nearest_simplex.h.

// ---------------------------------------------------------------------------------------
// GJK on the Minkowski difference A − B.

struct GjkResult {
  bool touching = false;   // |v| reached ~0: the cores touch or overlap
  bool far = false;        // stopped by the early-exit bound
  double distance = 0.0;   // |v| (far: the lower bound)
  Vector3d point_a = Vector3d::Zero(), point_b = Vector3d::Zero();
  double weight_b1 = 0.0;  // total barycentric weight of B's support index 1 (segments)
  int iterations = 0;
};

// A warm simplex a set can take: 1–4 distinct index pairs within the sets' counts.
template <class SetA, class SetB>
bool usable_simplex(const GjkSimplex& s, const SetA& A, const SetB& B) {
  if (s.size < 1 || s.size > 4) return false;
  for (int j = 0; j < s.size; j++) {
    if (s.a[j] < 0 || s.a[j] >= A.count() || s.b[j] < 0 || s.b[j] >= B.count()) return false;
    for (int k = 0; k < j; k++)
      if (s.a[k] == s.a[j] && s.b[k] == s.b[j]) return false;
  }
  return true;
}

// simplex (SetA and SetB with count()): the warm start and last simplex (GjkSimplex).
template <class SetA, class SetB>
GjkResult gjk(const SetA& A, const SetB& B, const Vector3d& initial_direction, double size,
              double early_exit_distance, double progress = kGjkProgress, GjkSimplex* simplex = nullptr) {
  std::array<Vector3d, 4> w;
  std::array<int, 4> ia{}, ib{};
  std::array<double, 4> lambda{};
  int n = 0;

  const auto support = [&](const Vector3d& v, int& i_a, int& i_b) {
    i_a = A.support(-v);
    i_b = B.support(v);
    return Vector3d(A.point(i_a) - B.point(i_b));
  };
  // the simplex kept for the next query: the last one, or the tetrahedron that holds the
  // origin
  bool kept = false;
  const auto keep_simplex = [&](int size_kept, const std::array<int, 4>& a, const std::array<int, 4>& b) {
    kept = true;
    if (!simplex) return;
    simplex->size = size_kept;
    simplex->a = a;
    simplex->b = b;
  };

  GjkResult result;
  const double origin_tol = kGjkOrigin * size;
  Vector3d v;
  if (simplex && usable_simplex(*simplex, A, B)) {
    // warm: the old simplex's points now, reduced to the sub-simplex nearest the origin
    const int m = simplex->size;
    for (int j = 0; j < m; j++) w[j] = A.point(simplex->a[j]) - B.point(simplex->b[j]);
    NearestSimplex r = m == 1   ? nearest_simplex_detail::single(w.data(), 0)
                       : m == 2 ? nearest_on_segment(w.data(), 0, 1)
                       : m == 3 ? nearest_on_triangle(w.data(), 0, 1, 2)
                                : nearest_on_tetrahedron(w.data());
    if (r.n == 4) {  // the origin inside: the cores overlap
      result.touching = true;
      keep_simplex(4, simplex->a, simplex->b);
      return result;
    }
    const std::array<Vector3d, 4> start = w;
    for (int j = 0; j < r.n; j++) {
      w[j] = start[r.index[j]];
      ia[j] = simplex->a[r.index[j]];
      ib[j] = simplex->b[r.index[j]];
      lambda[j] = r.lambda[j];
    }
    n = r.n;
    v = r.v;
  } else {
    Vector3d dir = initial_direction;
    if (!(dir.squaredNorm() > 0.0)) dir = Vector3d::UnitX();
    int a0 = 0, b0 = 0;
    w[0] = support(dir, a0, b0);
    ia[0] = a0;
    ib[0] = b0;
    lambda[0] = 1.0;
    n = 1;
    v = w[0];
  }

  int iteration = 0;
  for (; iteration < kGjkMaxIterations; ++iteration) {
    const double vv = v.squaredNorm();
    if (vv <= origin_tol * origin_tol) {
      result.touching = true;
      break;
    }
    int i_a = 0, i_b = 0;
    const Vector3d p = support(v, i_a, i_b);
    const double vp = v.dot(p);
    // v·p/|v| is a lower bound of the distance, |v| an upper bound
    if (early_exit_distance > 0.0 && vp > 0.0 &&
        vp * vp > early_exit_distance * early_exit_distance * vv) {
      result.far = true;
      result.distance = vp / std::sqrt(vv);
      break;
    }
    bool repeated = false;
    for (int j = 0; j < n; ++j) repeated = repeated || (ia[j] == i_a && ib[j] == i_b);
    if (repeated) break;  // the support is already a simplex vertex: v is optimal
    const double norm_v = std::sqrt(vv);
    if (vv - vp <= progress * std::max(vv, norm_v * size)) break;

    std::array<Vector3d, 4> trial = w;
    trial[n] = p;
    const int m = n + 1;
    NearestSimplex r;
    if (m == 2)
      r = nearest_on_segment(trial.data(), 0, 1);
    else if (m == 3)
      r = nearest_on_triangle(trial.data(), 0, 1, 2);
    else
      r = nearest_on_tetrahedron(trial.data());
    std::array<int, 4> trial_ia = ia, trial_ib = ib;
    trial_ia[n] = i_a;
    trial_ib[n] = i_b;
    if (r.n == 4) {
      result.touching = true;
      ++iteration;
      keep_simplex(4, trial_ia, trial_ib);
      break;
    }
    if (!(r.v.squaredNorm() < vv)) break;  // no progress (rounding): keep the last simplex

    for (int j = 0; j < r.n; ++j) {
      w[j] = trial[r.index[j]];
      ia[j] = trial_ia[r.index[j]];
      ib[j] = trial_ib[r.index[j]];
      lambda[j] = r.lambda[j];
    }
    n = r.n;
    v = r.v;
  }
  result.iterations = iteration;
  if (!kept) keep_simplex(n, ia, ib);
  if (result.far) return result;
  for (int j = 0; j < n; ++j) {
    result.point_a += lambda[j] * A.point(ia[j]);
    result.point_b += lambda[j] * B.point(ib[j]);
    if (ib[j] == 1) result.weight_b1 += lambda[j];
  }
  result.distance = result.touching ? 0.0 : (result.point_b - result.point_a).norm();
  return result;
}

// ---------------------------------------------------------------------------------------
// Topology helpers (body-frame indices; the PosedShape has the world coordinates).

// The two faces of every edge, in the order of shape.edges(): every face loop's directed
// edge i → j is recorded at vertex i as (j, face); edge (i, j) then finds its faces in
// the short lists of i and j (a vertex has a handful of neighbours).
std::vector<std::array<int, 2>> edge_faces(const ConvexShape& shape) {
  const auto& faces = shape.faces();
  const int n_v = static_cast<int>(shape.vertices().size());
  std::vector<int> start(n_v + 1, 0);
  for (const auto& f : faces)
    for (int i : f.vertices) ++start[i + 1];
  for (int i = 0; i < n_v; ++i) start[i + 1] += start[i];
  std::vector<std::array<int, 2>> directed(start[n_v]);  // (head vertex, face) by tail
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
    const auto& loop = faces[f].vertices;
    const std::size_t m = loop.size();
    for (std::size_t k = 0; k < m; ++k) directed[fill[loop[k]]++] = {loop[(k + 1) % m], f};
  }
  const auto face_of = [&](int tail, int head) {
    for (int k = start[tail]; k < start[tail + 1]; ++k)
      if (directed[k][0] == head) return directed[k][1];
    return -1;
  };
  std::vector<std::array<int, 2>> out;
  out.reserve(shape.edges().size());
  for (const auto& e : shape.edges()) {
    std::array<int, 2> f = {face_of(e[0], e[1]), face_of(e[1], e[0])};
    if (f[0] < 0) f[0] = f[1];  // cannot happen for a closed hull; keeps the code total
    if (f[1] < 0) f[1] = f[0];
    out.push_back(f);
  }
  return out;
}

bool face_has_vertex(const ConvexShape::Face& face, int vertex) {
  return std::find(face.vertices.begin(), face.vertices.end(), vertex) != face.vertices.end();
}

// h(n) = max over the core of n·x
double support_value(const PosedShape& p, const Vector3d& n) {
  double h = -kInf;
  for (const auto& v : p.vertices()) h = std::max(h, n.dot(v));
  return h;
}

// Orthonormal basis (u, w) of the plane ⟂ n (unit) with u × w = n: u = e_k × n / |e_k × n|,
// e_k the coordinate axis least aligned with n (the first of ties).
void plane_basis(const Vector3d& n, Vector3d& u, Vector3d& w) {
  int k = 0;
  n.cwiseAbs().minCoeff(&k);
  u = Vector3d::Unit(k).cross(n).normalized();
  w = n.cross(u);
}

// ---------------------------------------------------------------------------------------
// Separating-axis test. depth(n) = h_A(n) + h_B(−n) is, for every unit n, an upper bound
// of the penetration depth (the distance from the origin to the boundary of A − B when
// the origin is inside); its minimum over the face normals of A − B is the depth. Those
// normals are the face normals of A, minus those of B, and e_A × e_B for the edge pairs
// whose arcs on the Gauss sphere cross (A's arc and the antipode of B's). For disjoint
// cores the minimum is minus the largest separation along a candidate axis.

struct SatAxis {
  double depth = kInf;
  Vector3d normal = Vector3d::UnitX();  // from A to B
};

// Two point cores a and b (spheres, or a sphere and a zero-length segment): A − B is the
// single point a − b and depth(n) = n·(a − b) is least, −|b − a|, along
// n = (b − a)/|b − a|. Coincident points give depth 0 in every direction; the normal is
// then +x, a fixed choice (the default normal of CoreDistance).
SatAxis point_point_axis(const Vector3d& a, const Vector3d& b) {
  SatAxis axis;
  const Vector3d d = b - a;
  const double length = d.norm();
  axis.depth = -length;
  if (length > 0.0) axis.normal = d / length;
  return axis;
}

// Gauss-map test for edge pairs (Gregorius, "The Separating Axis Test between Convex
// Polyhedra", GDC 2013): the great arcs a1→a2 of A's edge and c→d = −b1→−b2 of B's
// (each shorter than π) intersect iff c·(a2×a1) and d·(a2×a1) differ in sign, a1·(d×c)
// and a2·(d×c) differ in sign, and c·(a2×a1), a2·(d×c) agree (same hemisphere).
// Inclusive by a rounding margin: an extra candidate axis is harmless (it only gives an
// upper bound of the depth).

// An edge of a posed core, as the SAT needs it: a point, the direction, the normals of
// its two faces (for B negated: the arc of −B) and their cross product.
struct SatEdge {
  Vector3d point, dir, n1, n2, n2_x_n1;
};

std::vector<SatEdge> sat_edges(const PosedShape& P, double sign) {
  const auto faces = edge_faces(P.shape());
  const auto& edges = P.shape().edges();
  std::vector<SatEdge> out(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    SatEdge& e = out[i];
    e.point = P.vertices()[edges[i][0]];
    e.dir = P.vertices()[edges[i][1]] - e.point;
    e.n1 = sign * P.face_normal(faces[i][0]);
    e.n2 = sign * P.face_normal(faces[i][1]);
    e.n2_x_n1 = e.n2.cross(e.n1);
  }
  return out;
}

SatAxis sat_polytopes(const PosedShape& A, const PosedShape& B) {
  // Two spheres: neither core has a face or an edge. A sphere and a polytope need no
  // special case: their difference is the polytope moved (and reflected), whose faces
  // are the polytope's, all tried below, and there are no edge pairs.
  if (A.shape().is_sphere() && B.shape().is_sphere())
    return point_point_axis(A.vertices()[0], B.vertices()[0]);
  SatAxis best;
  const auto consider = [&best](double depth, const Vector3d& n) {
    if (depth < best.depth) {
      best.depth = depth;
      best.normal = n;
    }
  };
  for (std::size_t f = 0; f < A.shape().faces().size(); ++f) {
    const Vector3d n = A.face_normal(f);
    consider(A.face_offset(f) + support_value(B, -n), n);
  }
  for (std::size_t g = 0; g < B.shape().faces().size(); ++g) {
    const Vector3d m = B.face_normal(g);
    consider(support_value(A, -m) + B.face_offset(g), -m);
  }
  // Edge pairs: the arcs (a1, a2) of A and (−b1, −b2) of B must cross (the test of
  // arcs_cross, unrolled so that half the pairs stop after two dot products). For a
  // crossing pair the two edges are the supports along the axis, so n·(p_A − p_B) is
  // the depth; it never exceeds the depth from the full supports, which is computed
  // only when the edge value would improve the minimum (and then counts).
  constexpr double eps = 1e-14;
  const std::vector<SatEdge> ea = sat_edges(A, 1.0), eb = sat_edges(B, -1.0);
  for (const SatEdge& a : ea) {
    for (const SatEdge& b : eb) {
      const double cba = b.n1.dot(a.n2_x_n1), dba = b.n2.dot(a.n2_x_n1);
      if (cba * dba > eps) continue;
      const double adc = a.n1.dot(b.n2_x_n1), bdc = a.n2.dot(b.n2_x_n1);
      if (adc * bdc > eps || cba * bdc < -eps) continue;
      Vector3d axis = a.dir.cross(b.dir);
      const double length = axis.norm();
      if (!(length > kParallelEdges * a.dir.norm() * b.dir.norm())) continue;
      axis /= length;
      if (axis.dot(a.n1 + a.n2) < 0.0) axis = -axis;  // outward of A at its edge
      if (axis.dot(a.point - b.point) >= best.depth) continue;
      consider(support_value(A, axis) + support_value(B, -axis), axis);
    }
  }
  return best;
}

double segment_support(const std::array<Vector3d, 2>& end, const Vector3d& n) {
  return std::max(n.dot(end[0]), n.dot(end[1]));
}

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
SatAxis sat_segment(const PosedShape& P, const std::array<Vector3d, 2>& end, double size) {
  SatAxis best;
  const auto consider = [&best](double depth, const Vector3d& n) {
    if (depth < best.depth) {
      best.depth = depth;
      best.normal = n;
    }
  };
  if (P.shape().is_sphere()) {
    const Vector3d& c = P.vertices()[0];
    const Vector3d s = end[1] - end[0];
    const double length = s.norm();
    if (!(length > 0.0)) return point_point_axis(c, end[0]);
    const Vector3d along = s / length;
    const Vector3d to_line = (end[0] - c) - along.dot(end[0] - c) * along;  // ⟂ S
    const double off_line = to_line.norm();
    SatAxis axis;
    if (off_line > kGjkOrigin * size) {
      axis.depth = -off_line;
      axis.normal = to_line / off_line;
    } else {
      Vector3d w;
      plane_basis(along, axis.normal, w);
      axis.depth = 0.0;
    }
    return axis;
  }
  for (std::size_t f = 0; f < P.shape().faces().size(); ++f) {
    const Vector3d n = P.face_normal(f);
    consider(P.face_offset(f) + segment_support(end, -n), n);
  }
  const Vector3d s = end[1] - end[0];
  if (s.squaredNorm() > 0.0) {
    const auto faces = edge_faces(P.shape());
    const auto& edges = P.shape().edges();
    for (std::size_t i = 0; i < edges.size(); ++i) {
      const Vector3d n1 = P.face_normal(faces[i][0]);
      const Vector3d n2 = P.face_normal(faces[i][1]);
      if (n1.dot(s) * n2.dot(s) > 1e-14 * s.squaredNorm()) continue;
      const Vector3d dir = P.vertices()[edges[i][1]] - P.vertices()[edges[i][0]];
      Vector3d axis = dir.cross(s);
      const double length = axis.norm();
      if (!(length > kParallelEdges * dir.norm() * s.norm())) continue;
      axis /= length;
      if (axis.dot(n1 + n2) < 0.0) axis = -axis;
      consider(support_value(P, axis) + segment_support(end, -axis), axis);
    }
  }
  return best;
}

// ---------------------------------------------------------------------------------------
// Features.

// The feature of P that faces direction n (unit). The support set S (vertices within
// `tight` of the supporting plane ⟂ n: one vertex, an edge or a face) contains the
// deepest points; only features containing all of S are candidates, so the feature
// always contains them: a face whose normal is within the angle tolerance of n, else an
// edge perpendicular to n within the tolerance, else the support vertex.
ContactFeature select_feature(const PosedShape& P, const Vector3d& n, double cos_tol,
                              double sin_tol, double tight) {
  // the support vertex v (the first of the largest n·x, as PosedShape::support_vertex) and
  // S from one pass of the dot products
  const int count = static_cast<int>(P.vertices().size());
  thread_local std::vector<double> heights;
  heights.resize(count);
  int v = 0;
  double h = -kInf;
  for (int i = 0; i < count; ++i) {
    heights[i] = n.dot(P.vertices()[i]);
    if (heights[i] > h) {
      h = heights[i];
      v = i;
    }
  }
  // S: every candidate contains v, so only the faces and edges at v are looked at (in
  // ascending index, the tie order of a scan over all of them)
  thread_local std::vector<int> support_set;
  support_set.clear();
  std::uint64_t support_mask = 0;  // the same set as bits, when the core has ≤ 64 vertices
  for (int i = 0; i < count; ++i)
    if (heights[i] >= h - tight) {
      support_set.push_back(i);
      if (i < 64) support_mask |= std::uint64_t(1) << i;
    }

  const ConvexShape& shape = P.shape();
  const auto& faces = shape.faces();
  const auto& masks = shape.face_vertex_masks();
  const Vector3d body_n = P.rotation().transpose() * n;  // the faces' cosines in the body frame
  const auto best_face_at_v = [&](bool whole_support_set, double& best_cos) {
    int best = -1;
    best_cos = -2.0;
    for (const ConvexShape::IncidentFace& at : shape.incident_faces(v)) {
      bool contains = true;
      if (whole_support_set) {
        if (!masks.empty())
          contains = (support_mask & ~at.mask) == 0;
        else
          for (int i : support_set) contains = contains && face_has_vertex(faces[at.face], i);
      }
      if (!contains) continue;
      const double c = at.normal.dot(body_n);
      if (c > best_cos) {
        best_cos = c;
        best = at.face;
      }
    }
    return best;
  };
  double best_cos = -2.0;
  int face = best_face_at_v(true, best_cos);
  if (face < 0) face = best_face_at_v(false, best_cos);  // S spans no face: rounding
  if (face >= 0 && best_cos >= cos_tol) return {FeatureKind::face, face};

  if (support_set.size() <= 2) {
    const auto& edges = shape.edges();
    int best_edge = -1;
    double best_sin = kInf;
    for (int e : shape.edges_at_vertex(v)) {
      const bool is_s = support_set.size() == 2 &&
                        std::min(support_set[0], support_set[1]) == edges[e][0] &&
                        std::max(support_set[0], support_set[1]) == edges[e][1];
      if (support_set.size() == 2 && !is_s) continue;
      const Vector3d dir = P.vertices()[edges[e][1]] - P.vertices()[edges[e][0]];
      const double s = std::abs(dir.dot(n)) / dir.norm();
      if (s < best_sin) {
        best_sin = s;
        best_edge = e;
      }
    }
    if (best_edge >= 0 && best_sin <= sin_tol) return {FeatureKind::edge, best_edge};
  }
  return {FeatureKind::vertex, v};
}

// The contact plane: 2D coordinates ⟂ n about an origin.
struct ContactFrame {
  Vector3d origin, n, u, w;
  ContactFrame(const Vector3d& origin_, const Vector3d& n_) : origin(origin_), n(n_) {
    plane_basis(n, u, w);
  }
  Vector2d project(const Vector3d& x) const {
    const Vector3d d = x - origin;
    return Vector2d(u.dot(d), w.dot(d));
  }
  Vector3d lift(const Vector2d& p) const { return origin + p.x() * u + p.y() * w; }
  // The point of the plane {N·x = offset} on the line through x parallel to n.
  Vector3d onto_plane(const Vector3d& x, const Vector3d& N, double offset) const {
    return x + ((offset - N.dot(x)) / N.dot(n)) * n;
  }
};

// Closest points of segments [p0, p1] and [q0, q1]: parameters s, t in [0, 1], from the
// one segment–segment routine of the core (segment_distance.h: Sunday's algorithm on
// normalised directions; its accuracy and its parallel and degenerate choices are there).
void closest_segment_segment(const Vector3d& p0, const Vector3d& p1, const Vector3d& q0,
                             const Vector3d& q1, double& s, double& t) {
  const SegmentClosestPoints closest = segment_closest_points(p0, p1, q0, q1);
  s = closest.s;
  t = closest.t;
}

// The parameter s ∈ [0, 1] of the point of segment [b0, b1] nearest to the line through x
// with direction n (unit): minimises |P(b(s) − x)|, P the projector ⟂ n.
double segment_param_nearest_line(const Vector3d& b0, const Vector3d& b1, const Vector3d& x,
                                  const Vector3d& n) {
  const Vector3d e = b1 - b0, r = b0 - x;
  const Vector3d pe = e - n.dot(e) * n, pr = r - n.dot(r) * n;
  const double ee = pe.squaredNorm();
  return ee > 0.0 ? std::clamp(-pr.dot(pe) / ee, 0.0, 1.0) : 0.0;
}

// The point of a feature of P on (or nearest to) the line through x along n.
Vector3d feature_point_on_line(const PosedShape& P, const ContactFeature& f, const Vector3d& x,
                               const Vector3d& n) {
  switch (f.kind) {
    case FeatureKind::face: {
      const Vector3d N = P.face_normal(f.index);
      return x + ((P.face_offset(f.index) - N.dot(x)) / N.dot(n)) * n;
    }
    case FeatureKind::edge: {
      const auto& e = P.shape().edges()[f.index];
      const Vector3d& b0 = P.vertices()[e[0]];
      const Vector3d& b1 = P.vertices()[e[1]];
      return b0 + segment_param_nearest_line(b0, b1, x, n) * (b1 - b0);
    }
    case FeatureKind::vertex:
    default:
      return P.vertices()[f.index];
  }
}

// 2D polygon of a face, counter-clockwise about n (the face's loop is counter-clockwise
// about its outward normal; reversed when that points against n).
std::vector<Vector2d> face_polygon(const PosedShape& P, int face, const ContactFrame& frame) {
  const auto& loop = P.shape().faces()[face].vertices;
  std::vector<Vector2d> poly;
  poly.reserve(loop.size());
  for (int i : loop) poly.push_back(frame.project(P.vertices()[i]));
  if (P.face_normal(face).dot(frame.n) < 0.0) std::reverse(poly.begin(), poly.end());
  return poly;
}

// Sutherland–Hodgman: the part of `subject` inside the convex counter-clockwise `clip`.
// A point counts as inside an edge when at most `tol` outside it.
std::vector<Vector2d> clip_polygon(const std::vector<Vector2d>& subject,
                                   const std::vector<Vector2d>& clip, double tol) {
  std::vector<Vector2d> out = subject;
  const std::size_t m = clip.size();
  for (std::size_t k = 0; k < m && !out.empty(); ++k) {
    const Vector2d& c0 = clip[k];
    const Vector2d edge = clip[(k + 1) % m] - c0;
    const double length = edge.norm();
    if (!(length > 0.0)) continue;
    const auto side = [&](const Vector2d& p) { return cross2(edge, p - c0) / length; };
    std::vector<Vector2d> in = std::move(out);
    out.clear();
    const std::size_t q = in.size();
    for (std::size_t i = 0; i < q; ++i) {
      const Vector2d& S = in[(i + q - 1) % q];
      const Vector2d& E = in[i];
      const double fs = side(S), fe = side(E);
      const bool s_in = fs >= -tol, e_in = fe >= -tol;
      if (e_in != s_in) {
        const double t = std::clamp(fs / (fs - fe), 0.0, 1.0);
        out.push_back(S + t * (E - S));
      }
      if (e_in) out.push_back(E);
    }
  }
  return out;
}

// Cyrus–Beck: the parameter interval [lo, hi] of the segment p0 + s (p1 − p0), s ∈ [0, 1],
// inside the convex counter-clockwise polygon (tolerance as above). False if empty.
bool clip_segment(const Vector2d& p0, const Vector2d& p1, const std::vector<Vector2d>& poly,
                  double tol, double& lo, double& hi) {
  lo = 0.0;
  hi = 1.0;
  const std::size_t m = poly.size();
  for (std::size_t k = 0; k < m; ++k) {
    const Vector2d& c0 = poly[k];
    const Vector2d edge = poly[(k + 1) % m] - c0;
    const double length = edge.norm();
    if (!(length > 0.0)) continue;
    const double f0 = cross2(edge, p0 - c0) / length, f1 = cross2(edge, p1 - c0) / length;
    if (f0 < -tol && f1 < -tol) return false;
    if (f0 >= -tol && f1 >= -tol) continue;
    const double s = std::clamp(f0 / (f0 - f1), 0.0, 1.0);  // where f crosses 0
    if (f0 < -tol)
      lo = std::max(lo, s);
    else
      hi = std::min(hi, s);
  }
  return lo <= hi;
}

// Convex hull (Andrew's monotone chain), counter-clockwise, of a clipped polygon's
// vertices: merges vertices closer than tol and drops vertices within tol of the line
// through their neighbours. A degenerate polygon becomes its two extreme points (a line
// contact) or one point.
std::vector<Vector2d> convex_hull_2d(std::vector<Vector2d> points, double tol) {
  std::sort(points.begin(), points.end(), [](const Vector2d& a, const Vector2d& b) {
    return a.x() != b.x() ? a.x() < b.x() : a.y() < b.y();
  });
  if (points.size() < 2) return points;
  // b is a corner of the counter-clockwise chain a → b → c only if it lies more than tol
  // to the right of the line a → c (a strict left turn at b)
  const auto not_corner = [tol](const Vector2d& a, const Vector2d& b, const Vector2d& c) {
    const double length = (c - a).norm();
    return length <= tol || cross2(b - a, c - a) <= tol * length;
  };
  std::vector<Vector2d> hull(2 * points.size());
  std::size_t k = 0;
  for (const auto& p : points) {  // lower chain
    while (k >= 2 && not_corner(hull[k - 2], hull[k - 1], p)) --k;
    if (k == 1 && (p - hull[0]).norm() <= tol) continue;
    hull[k++] = p;
  }
  const std::size_t lower = k + 1;
  for (std::size_t i = points.size() - 1; i-- > 0;) {  // upper chain
    const Vector2d& p = points[i];
    while (k >= lower && not_corner(hull[k - 2], hull[k - 1], p)) --k;
    hull[k++] = p;
  }
  hull.resize(k - 1);  // the last point repeats the first
  // a chain that came back on itself: merge coincident ends
  while (hull.size() > 1 && (hull.back() - hull.front()).norm() <= tol) hull.pop_back();
  if (hull.size() == 2 && (hull[1] - hull[0]).norm() <= tol) hull.pop_back();
  return hull;
}

// Reduce a convex polygon (with a gap per vertex) to at most max_points vertices by
// repeatedly removing the vertex whose triangle with its neighbours has the smallest
// area, never the deepest vertex. Returns the kept indices in polygon order.
std::vector<int> reduce_polygon(const std::vector<Vector2d>& poly,
                                const std::vector<double>& gaps, int max_points) {
  std::vector<int> kept(poly.size());
  for (std::size_t i = 0; i < poly.size(); ++i) kept[i] = static_cast<int>(i);
  if (max_points <= 0 || static_cast<int>(poly.size()) <= max_points) return kept;
  const int deepest =
      static_cast<int>(std::min_element(gaps.begin(), gaps.end()) - gaps.begin());
  while (static_cast<int>(kept.size()) > max_points) {
    const std::size_t m = kept.size();
    std::size_t victim = m;
    double least = kInf;
    for (std::size_t i = 0; i < m; ++i) {
      if (kept[i] == deepest) continue;
      const Vector2d& a = poly[kept[(i + m - 1) % m]];
      const Vector2d& b = poly[kept[i]];
      const Vector2d& c = poly[kept[(i + 1) % m]];
      double area = std::abs(cross2(b - a, c - a));
      if (m <= 2) area = (b - poly[deepest]).norm();  // keep the farthest point
      if (area < least) {
        least = area;
        victim = i;
      }
    }
    if (victim == m) break;
    kept.erase(kept.begin() + static_cast<long>(victim));
  }
  return kept;
}

// Pairs of core points (on A, on B) making up a manifold, before the radii are applied.
struct CorePair {
  Vector3d a, b;
  Vector2d in_plane;  // position in the contact plane (for the polygon reduction)
};

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
std::vector<CorePair> feature_pairs(const PosedShape& A, const ContactFeature& fa,
                                    const PosedShape& B, const ContactFeature& fb,
                                    const ContactFrame& frame, double sin_tol, double tol) {
  std::vector<CorePair> out;
  const Vector3d& n = frame.n;
  if (fa.kind == FeatureKind::face && fb.kind == FeatureKind::face) {
    std::vector<Vector2d> poly =
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
    std::vector<double> params = {lo, hi};
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
    std::vector<double> at = {lo, hi};
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
    double s = 0.0, t = 0.0;
    closest_segment_segment(A.vertices()[ea[0]], A.vertices()[ea[1]], B.vertices()[eb[0]],
                            B.vertices()[eb[1]], s, t);
    out.a = A.vertices()[ea[0]] + s * (A.vertices()[ea[1]] - A.vertices()[ea[0]]);
    out.b = B.vertices()[eb[0]] + t * (B.vertices()[eb[1]] - B.vertices()[eb[0]]);
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
void keep_deepest(std::vector<ContactPoint>& points, int max_points) {
  if (max_points <= 0 || static_cast<int>(points.size()) <= max_points) return;
  std::stable_sort(points.begin(), points.end(),
                   [](const ContactPoint& x, const ContactPoint& y) { return x.gap < y.gap; });
  points.resize(max_points);
}

struct NearPoint {
  Vector3d a, b, normal;
};

void add_near_vertices(const PosedShape& P, const PosedShape& Q, bool p_is_a, const Vector3d& n,
                       double core_distance, double reach, double size, double tol,
                       const std::vector<Vector3d>& taken, std::vector<NearPoint>& out) {
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

double configuration_size(const PosedShape& a, const Vector3d& other_center,
                          double other_radius) {
  return std::max({a.core_radius(), other_radius, (a.position() - other_center).norm(),
                   std::numeric_limits<double>::min()});
}

}  // namespace

// ---------------------------------------------------------------------------------------
// PosedShape

PosedShape::PosedShape(const ConvexShape& shape, const Vector3d& position,
                       const Eigen::Quaterniond& orientation)
    : shape_(&shape), position_(position) {
  check_finite("position", position);
  const double norm = orientation.norm();
  if (!std::isfinite(norm) || !(norm > 0.0))
    throw InvalidArgument("orientation", "orientation must be a finite non-zero quaternion");
  orientation_ = orientation.normalized();
  rotation_ = orientation_.toRotationMatrix();
  vertices_.reserve(shape.vertices().size());
  for (const auto& v : shape.vertices()) {
    core_radius_ = std::max(core_radius_, v.norm());
    vertices_.push_back(rotation_ * v + position_);
  }
}

int PosedShape::support_vertex(const Vector3d& direction) const {
  int best = 0;
  double h = -kInf;
  for (int i = 0; i < static_cast<int>(vertices_.size()); ++i) {
    const double x = direction.dot(vertices_[i]);
    if (x > h) {
      h = x;
      best = i;
    }
  }
  return best;
}

// ---------------------------------------------------------------------------------------
// Core distance

double lowest_core_point(const ConvexShape& shape, const Vector3d& position, const Eigen::Quaterniond& orientation,
                         const Vector3d& n) {
  const Vector3d body_n = orientation.normalized().conjugate() * n;
  double lowest = kInf;
  for (const Vector3d& v : shape.vertices()) lowest = std::min(lowest, body_n.dot(v));
  return lowest + n.dot(position);
}

double height_above_faces(const PosedShape& shape, const Vector3d& x) {
  const Vector3d body = shape.rotation().transpose() * (x - shape.position());
  double height = -kInf;
  for (const auto& face : shape.shape().faces()) height = std::max(height, face.normal.dot(body) - face.offset);
  return height;
}

CoreDistance core_distance(const PosedShape& a, const PosedShape& b,
                           double early_exit_distance, GjkSimplex* simplex) {
  if (!(early_exit_distance >= 0.0))
    throw InvalidArgument("early_exit_distance",
                          "early_exit_distance must be >= 0, got " + number(early_exit_distance));
  if (std::isinf(early_exit_distance)) early_exit_distance = 0.0;  // never stop early
  const double size = configuration_size(a, b.position(), b.core_radius());
  const GjkResult g = gjk(PolytopeSet{&a}, PolytopeSet{&b}, a.position() - b.position(), size,
                          early_exit_distance, kGjkProgress, simplex);
  CoreDistance out;
  out.gjk_iterations = g.iterations;
  if (g.far) {
    out.method = DistanceMethod::gjk_far;
    out.distance = g.distance;
    const Vector3d d = b.position() - a.position();
    out.normal = d.squaredNorm() > 0.0 ? Vector3d(d.normalized()) : Vector3d::UnitX();
    out.point_a = a.position();
    out.point_b = b.position();
    return out;
  }
  if (!g.touching && g.distance > kNearTouching * size) {
    out.method = DistanceMethod::gjk;
    out.distance = g.distance;
    out.normal = (g.point_b - g.point_a) / g.distance;
    out.point_a = g.point_a;
    out.point_b = g.point_b;
    return out;
  }
  const SatAxis axis = sat_polytopes(a, b);
  out.normal = axis.normal;
  if (!g.touching && g.distance > 0.0) {
    // Disjoint but nearly touching: exact closest points. The normal is the direction
    // of largest separation: the SAT axis (exact when the contact involves a face or two
    // crossing edges), unless the GJK direction separates more (vertex–vertex,
    // vertex–edge, parallel edges: their normal is no SAT candidate).
    out.distance = g.distance;
    out.point_a = g.point_a;
    out.point_b = g.point_b;
    const Vector3d n_gjk = (g.point_b - g.point_a) / g.distance;
    const double separation_gjk = -(support_value(a, n_gjk) + support_value(b, -n_gjk));
    if (separation_gjk > -axis.depth + kGjkProgress * size) {
      out.method = DistanceMethod::gjk;
      out.normal = n_gjk;
    } else {
      out.method = DistanceMethod::gjk_sat;
    }
    return out;
  }
  // Overlapping, or touching with coincident closest points (GJK distance exactly 0: no
  // direction from the points; seen on stacked cubes tilted by 1e-13): the SAT.
  out.method = DistanceMethod::sat;
  out.distance = -axis.depth;
  const Vector3d& n = axis.normal;
  out.point_a = a.vertices()[a.support_vertex(n)];
  out.point_b = b.vertices()[b.support_vertex(-n)];
  return out;
}

// ---------------------------------------------------------------------------------------
// Contact manifold of two grains

ContactManifold contact_manifold(const PosedShape& a, const PosedShape& b,
                                 double activation_distance, const ContactOptions& options,
                                 GjkSimplex* simplex) {
  check_not_nan("activation_distance", activation_distance);
  check_options(options);
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
  std::vector<CorePair> pairs = feature_pairs(a, m.feature_a, b, m.feature_b, frame, sin_tol, tol);
  if (pairs.empty()) {
    if (cd.method == DistanceMethod::gjk || cd.method == DistanceMethod::gjk_sat)
      pairs.push_back({cd.point_a, cd.point_b, frame.project(cd.point_a)});
    else
      pairs.push_back(single_pair(a, m.feature_a, b, m.feature_b, frame, cd.distance));
  }

  std::vector<Vector2d> in_plane;
  std::vector<double> gaps;
  for (const auto& p : pairs) {
    in_plane.push_back(p.in_plane);
    gaps.push_back(n.dot(p.b - p.a));
  }
  for (int i : reduce_polygon(in_plane, gaps, options.max_points))
    m.points.push_back(make_point(pairs[i].a, pairs[i].b, n, r_a, r_b));

  if (options.near_vertices) {
    std::vector<Vector3d> taken_a, taken_b;
    for (const auto& p : pairs) {
      taken_a.push_back(p.a);
      taken_b.push_back(p.b);
    }
    std::vector<NearPoint> near;
    const double near_reach =
        std::min(activation_distance, kNearVertexSlab * (a.core_radius() + b.core_radius())) + r_a + r_b;
    add_near_vertices(a, b, true, n, cd.distance, near_reach, size, tol, taken_a, near);
    add_near_vertices(b, a, false, -n, cd.distance, near_reach, size, tol, taken_b, near);
    std::vector<ContactPoint> points;
    for (const NearPoint& p : near) points.push_back(make_point(p.a, p.b, p.normal, r_a, r_b));
    keep_deepest(points, options.max_points);
    m.points.insert(m.points.end(), points.begin(), points.end());
  }
  return m;
}

// ---------------------------------------------------------------------------------------
// Wall

ContactManifold plane_contact(const Plane& wall, const PosedShape& grain,
                              double activation_distance, const ContactOptions& options) {
  check_not_nan("activation_distance", activation_distance);
  check_options(options);
  check_finite("wall.point", wall.point);
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
  std::vector<int> vertices;
  switch (m.feature_b.kind) {
    case FeatureKind::face:
      vertices = grain.shape().faces()[m.feature_b.index].vertices;
      break;
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
  std::vector<Vector2d> in_plane;
  std::vector<double> gaps;
  for (int v : vertices) {
    in_plane.push_back(frame.project(grain.vertices()[v]));
    gaps.push_back(n.dot(grain.vertices()[v] - wall.point));
  }
  for (int i : reduce_polygon(in_plane, gaps, options.max_points)) {
    const Vector3d& v = grain.vertices()[vertices[i]];
    m.points.push_back(make_point(v - gaps[i] * n, v, n, 0.0, r));
  }
  if (options.near_vertices) {
    const double near_reach = std::min(activation_distance, kNearVertexSlab * grain.core_radius());
    std::vector<ContactPoint> points;
    for (int i = 0; i < static_cast<int>(grain.vertices().size()); ++i) {
      const Vector3d& v = grain.vertices()[i];
      const double core_gap = n.dot(v - wall.point);
      if (core_gap - r < near_reach && std::find(vertices.begin(), vertices.end(), i) == vertices.end())
        points.push_back(make_point(v - core_gap * n, v, n, 0.0, r));
    }
    keep_deepest(points, options.max_points);
    m.points.insert(m.points.end(), points.begin(), points.end());
  }
  return m;
}

// ---------------------------------------------------------------------------------------
// Wire segment

SegmentContact segment_contact(const PosedShape& grain, const Vector3d& end0,
                               const Vector3d& end1, double wire_radius,
                               const ContactOptions& options, GjkSimplex* simplex) {
  check_finite("end0", end0);
  check_finite("end1", end1);
  if (!(wire_radius >= 0.0) || !std::isfinite(wire_radius))
    throw InvalidArgument("wire_radius",
                          "wire_radius must be >= 0 and finite, got " + number(wire_radius));
  check_options(options);

  const SegmentSet S{{end0, end1}};
  const Vector3d mid = 0.5 * (end0 + end1);
  const Vector3d s = end1 - end0;
  const double length = s.norm();
  const double size = configuration_size(grain, mid, 0.5 * length);
  // the early exit on the cores' distance (0 to gjk: never)
  const double exit_distance = std::isinf(options.exit_gap) ? 0.0 : options.exit_gap + grain.sweep_radius() + wire_radius;
  const GjkResult g = gjk(PolytopeSet{&grain}, S, grain.position() - mid, size, exit_distance, kGjkProgress, simplex);

  SegmentContact out;
  out.gjk_iterations = g.iterations;
  if (g.far) {
    out.method = DistanceMethod::gjk_far;
    out.distance = g.distance;
    out.gap = g.distance - (grain.sweep_radius() + wire_radius);
    const Vector3d d = mid - grain.position();
    out.normal = d.squaredNorm() > 0.0 ? Vector3d(d.normalized()) : Vector3d::UnitX();
    out.point_on_core = grain.position();
    out.point_on_segment = mid;
    out.t = out.t_begin = out.t_end = 0.5;
    return out;
  }
  const auto param_of = [&](const Vector3d& x) {
    return length > 0.0 ? std::clamp((x - end0).dot(s) / (length * length), 0.0, 1.0) : 0.0;
  };

  Vector3d n;
  if (!g.touching && g.distance > kNearTouching * size) {
    out.method = DistanceMethod::gjk;
    out.distance = g.distance;
    n = (g.point_b - g.point_a) / g.distance;
  } else {
    const SatAxis axis = sat_segment(grain, S.end, size);
    n = axis.normal;
    if (g.touching || !(g.distance > 0.0)) {  // coincident closest points: no direction
      out.method = DistanceMethod::sat;
      out.distance = -axis.depth;
    } else {
      // nearly touching: the direction of largest separation (see core_distance)
      out.method = DistanceMethod::gjk_sat;
      out.distance = g.distance;
      const Vector3d n_gjk = (g.point_b - g.point_a) / g.distance;
      const double separation_gjk =
          -(support_value(grain, n_gjk) + segment_support(S.end, -n_gjk));
      if (separation_gjk > -axis.depth + kGjkProgress * size) {
        out.method = DistanceMethod::gjk;
        n = n_gjk;
      }
    }
  }
  out.normal = n;
  out.gap = out.distance - (grain.sweep_radius() + wire_radius);
  // GJK's closest points (t = the barycentric weight of end1)
  const auto gjk_points = [&]() {
    out.point_on_core = g.point_a;
    out.point_on_segment = g.point_b;
    out.t = out.t_begin = out.t_end = length > 0.0 ? std::clamp(g.weight_b1, 0.0, 1.0) : 0.0;
  };
  if (out.method == DistanceMethod::gjk && out.gap > options.feature_gap_limit) {
    gjk_points();
    return out;
  }

  // Single closest points: GJK's (t = the barycentric weight of end1), or for the SAT
  // the deepest end of the segment and its projection along n on the grain's feature
  // (for an edge axis the segment is ⟂ n: the closest points of edge and segment).
  // The feature is looked up only where it is used, the SAT's points and a segment ⟂ n
  // within the tolerance (the interval below): a segment touching with one of its ends
  // needs none.
  const double sin_tol = std::sin(options.angle_tolerance);
  const bool across = length > 0.0 && std::abs(s.dot(n)) <= sin_tol * length;
  if (out.method != DistanceMethod::sat && !across) {
    gjk_points();
    return out;
  }
  const ContactFeature feature = select_feature(grain, n, std::cos(options.angle_tolerance),
                                                sin_tol, kMergeTolerance * size);
  if (out.method == DistanceMethod::sat) {
    if (feature.kind == FeatureKind::vertex) {
      const Vector3d& v = grain.vertices()[feature.index];
      out.point_on_core = v;
      out.point_on_segment = end0 + segment_param_nearest_line(end0, end1, v, n) * s;
    } else if (feature.kind == FeatureKind::edge && std::abs(s.dot(n)) <= sin_tol * length) {
      const auto& e = grain.shape().edges()[feature.index];
      const Vector3d &e0 = grain.vertices()[e[0]], &e1 = grain.vertices()[e[1]];
      double p = 0.0, q = 0.0;
      closest_segment_segment(e0, e1, end0, end1, p, q);
      out.point_on_core = e0 + p * (e1 - e0);
      out.point_on_segment = end0 + q * s;
    } else {
      out.point_on_segment = n.dot(end1) < n.dot(end0) ? end1 : end0;
      out.point_on_core = feature_point_on_line(grain, feature, out.point_on_segment, n);
    }
    out.t = out.t_begin = out.t_end = param_of(out.point_on_segment);
  } else {
    gjk_points();
  }

  // A segment parallel to the contact face or edge: the closest points form an interval.
  if (across && feature.kind != FeatureKind::vertex) {
    const ContactFrame frame(out.point_on_core, n);
    const double tol = kMergeTolerance * size;
    double lo = 0.0, hi = 1.0;
    bool found = false;
    if (feature.kind == FeatureKind::face) {
      found = clip_segment(frame.project(end0), frame.project(end1),
                           face_polygon(grain, feature.index, frame), tol, lo, hi);
    } else {
      const auto& e = grain.shape().edges()[feature.index];
      const Vector3d &e0 = grain.vertices()[e[0]], &e1 = grain.vertices()[e[1]];
      const Vector3d de = e1 - e0;
      if (de.normalized().cross(s / length).norm() <= sin_tol) {
        Vector3d dir = s - n.dot(s) * n;
        dir.normalize();
        const double a0 = dir.dot(end0), a1 = dir.dot(end1);  // a1 > a0
        const double b_lo = std::min(dir.dot(e0), dir.dot(e1));
        const double b_hi = std::max(dir.dot(e0), dir.dot(e1));
        lo = std::clamp((b_lo - a0) / (a1 - a0), 0.0, 1.0);
        hi = std::clamp((b_hi - a0) / (a1 - a0), 0.0, 1.0);
        found = b_hi >= a0 - tol && b_lo <= a1 + tol && lo <= hi;
      }
    }
    if (found) {
      out.t_begin = lo;
      out.t_end = hi;
      out.t = 0.5 * (lo + hi);
      out.point_on_segment = end0 + out.t * s;
      out.point_on_core = feature_point_on_line(grain, feature, out.point_on_segment, n);
    }
  }
  return out;
}

namespace {

// Newton polish of the closest points of a segment and a smooth convex body, from GJK's.
// GJK's distance converges fast but its closest points and normal only as the square root
// of the distance's error (~1e-6 here). The optimality conditions in terms of the unit
// normal n and the segment parameter t, with c(n) the support point and p(t) = x0 + t s:
//   (p(t) − c(n)) ⟂ n's tangent plane  (2 equations: components on a basis u, w ⟂ n_k),
//   s · n = 0                          (t inside (0, 1); otherwise t stays at its end),
// in the unknowns n = normalise(n_k + α u + β w) and t, with a Jacobian by forward
// differences in α, β (the support point is closed-form but its derivative is not worth
// writing) and in closed form in t.
// A singular Jacobian (a segment parallel to a flat stretch: t is not unique) keeps t.
// The caller keeps the result only if its pair is not farther than the unpolished ones.
void polish_closest_points(const PosedSuperquadric& body, const Vector3d& end0, const Vector3d& end1,
                           Vector3d& n, double& t) {
  const Vector3d s = end1 - end0;
  const double length2 = s.squaredNorm();
  bool free_t = length2 > 0.0 && t > 1e-12 && t < 1.0 - 1e-12;
  const double h = 1e-7;
  // a residual below rounding of the configuration's size ends the polish before another
  // Jacobian (the warm start arrives converged or one step away)
  const double scale = std::max(std::sqrt(length2), (end0 - body.position()).norm());
  for (int iteration = 0; iteration < 8; ++iteration) {
    Vector3d u, w;
    plane_basis(n, u, w);
    const int m = free_t ? 3 : 2;
    const auto residual = [&](double a, double b, double tt) {
      const Vector3d nn = (n + a * u + b * w).normalized();
      const Vector3d diff = end0 + tt * s - body.support(nn);
      const Vector3d tangential = diff - nn.dot(diff) * nn;
      return Vector3d(u.dot(tangential), w.dot(tangential), free_t ? s.dot(nn) / std::sqrt(length2) : 0.0);
    };
    const Vector3d r0 = residual(0.0, 0.0, t);
    if (Vector3d(r0[0], r0[1], r0[2] * scale).norm() <= 1e-15 * scale) return;
    // the Jacobian: forward differences in the normal's two tilts (the Newton step's
    // accuracy does not depend on it, only its rate), in t in closed form (the support
    // point does not depend on t: ∂/∂t of the tangential part is s − (n·s) n)
    Eigen::Matrix3d J = Eigen::Matrix3d::Identity();
    J.col(0) = (residual(h, 0.0, t) - r0) / h;
    J.col(1) = (residual(0.0, h, t) - r0) / h;
    if (free_t) J.col(2) = Vector3d(u.dot(s), w.dot(s), 0.0);
    Vector3d step = Vector3d::Zero();
    bool singular;
    if (m == 3) {
      const Eigen::FullPivLU<Eigen::Matrix3d> solve(J);
      singular = !solve.isInvertible() || solve.rcond() < 1e-10;
      if (!singular) step = solve.solve(Vector3d(-r0));
    } else {
      const Eigen::FullPivLU<Eigen::Matrix2d> solve(J.topLeftCorner<2, 2>());
      singular = !solve.isInvertible() || solve.rcond() < 1e-10;
      if (!singular) step.head<2>() = solve.solve(Eigen::Vector2d(-r0.head<2>()));
    }
    if (singular) {
      if (free_t) {
        free_t = false;
        continue;
      }
      return;
    }
    n = (n + step[0] * u + step[1] * w).normalized();
    if (free_t) {
      t += step[2];
      if (t < 0.0 || t > 1.0) {
        t = std::clamp(t, 0.0, 1.0);
        free_t = false;
      }
    }
    if (step.head(m).norm() < 1e-15) return;
  }
}

}  // namespace

SegmentContact segment_contact(const PosedSuperquadric& grain, const Vector3d& end0, const Vector3d& end1,
                               double wire_radius, double early_exit_distance, const SmoothContactGuess* guess) {
  check_finite("end0", end0);
  check_finite("end1", end1);
  if (!(wire_radius >= 0.0) || !std::isfinite(wire_radius))
    throw InvalidArgument("wire_radius",
                          "wire_radius must be >= 0 and finite, got " + number(wire_radius));
  if (!(early_exit_distance >= 0.0))
    throw InvalidArgument("early_exit_distance",
                          "early_exit_distance must be >= 0, got " + number(early_exit_distance));
  if (std::isinf(early_exit_distance)) early_exit_distance = 0.0;  // never stop early
  const SegmentSet S{{end0, end1}};
  const Vector3d mid = 0.5 * (end0 + end1);
  const Vector3d s = end1 - end0;
  const double length = s.norm();
  const double size = std::max({superquadric_bounding_radius(grain.shape()), 0.5 * length,
                                (grain.position() - mid).norm(), std::numeric_limits<double>::min()});
  SegmentContact out;
  if (guess && guess->normal.allFinite() && guess->normal.squaredNorm() > 0.0 && guess->t >= 0.0 &&
      guess->t <= 1.0) {
    // the warm start, certified (see the header)
    Vector3d n = guess->normal.normalized();
    double t = length > 0.0 ? guess->t : 0.0;
    polish_closest_points(grain, end0, end1, n, t);
    const Vector3d core = grain.support(n), on_segment = end0 + t * s, diff = on_segment - core;
    const double d = n.dot(diff), sn = s.dot(n);
    const double outward = t <= 0.0 ? std::max(0.0, -sn) : t >= 1.0 ? std::max(0.0, sn) : std::abs(sn);
    const double upper = diff.norm(), lower = d - outward;
    if (d > kNearTouching * size && upper - lower <= 1e-12 * size) {
      out.method = DistanceMethod::gjk;
      out.distance = upper;
      out.normal = diff / upper;
      out.point_on_core = core;
      out.point_on_segment = on_segment;
      out.t = t;
      out.t_begin = out.t_end = t;
      out.gap = out.distance - wire_radius;
      return out;
    }
  }
  const GjkResult g =
      gjk(SuperquadricSet(grain), S, grain.position() - mid, size, early_exit_distance, kGjkSmoothProgress);

  out.gjk_iterations = g.iterations;
  if (g.far) {
    out.method = DistanceMethod::gjk_far;
    out.distance = g.distance;
    const Vector3d d = mid - grain.position();
    out.normal = d.squaredNorm() > 0.0 ? Vector3d(d.normalized()) : Vector3d::UnitX();
    out.point_on_core = grain.position();
    out.point_on_segment = mid;
    out.t = 0.5;
  } else if (!g.touching && g.distance > kNearTouching * size) {
    // apart: GJK's direction, polished. GJK's closest points themselves are barycentric
    // combinations over nearly coincident support points of the smooth body, whose
    // weights are ill-conditioned (seen: 1e-9 off the segment); so both candidates are
    // rebuilt as genuine pairs (the support point c(n) on the surface, its clamped
    // projection on the segment) and the nearer pair is kept.
    out.method = DistanceMethod::gjk;
    const auto pair_along = [&](const Vector3d& n, Vector3d& core, Vector3d& on_segment, double& t) {
      core = grain.support(n);
      t = length > 0.0 ? std::clamp((core - end0).dot(s) / (length * length), 0.0, 1.0) : 0.0;
      on_segment = end0 + t * s;
      return (on_segment - core).norm();
    };
    const Vector3d n_gjk = (g.point_b - g.point_a) / g.distance;
    // GJK's own body point and its projection on the segment: a second start. On a
    // nearly flat stretch of a blocky body c(n) jumps with n, so c(n_gjk) can be far
    // from GJK's point, which is not.
    const double t_a = length > 0.0 ? std::clamp((g.point_a - end0).dot(s) / (length * length), 0.0, 1.0) : 0.0;
    const Vector3d on_segment_a = end0 + t_a * s;
    const double distance_a = (on_segment_a - g.point_a).norm();
    out.distance = kInf;
    for (const Vector3d& start : {n_gjk, Vector3d((on_segment_a - g.point_a) / distance_a)}) {
      if (!start.allFinite()) continue;
      for (const bool polish : {true, false}) {
        Vector3d n = start, core, on_segment;
        double t = length > 0.0 ? std::clamp(g.weight_b1, 0.0, 1.0) : 0.0;
        if (polish) polish_closest_points(grain, end0, end1, n, t);
        const double d = pair_along(n, core, on_segment, t);
        // the first (polished) pair unless another is nearer beyond rounding: a direction
        // error δ changes the distance by ~δ², below rounding for δ ~ 1e-9, the normal by δ
        if (d < out.distance - 1e-12 * size) {
          out.distance = d;
          out.point_on_core = core;
          out.point_on_segment = on_segment;
          out.t = t;
        }
      }
    }
    // GJK's point itself, which can lie inside the body by its weights' rounding (~1e-9,
    // which would look nearer): only when every pair above missed by more than that
    if (distance_a < out.distance - 1e-7 * size) {
      out.distance = distance_a;
      out.point_on_core = g.point_a;
      out.point_on_segment = on_segment_a;
      out.t = t_a;
    }
    out.normal = (out.point_on_segment - out.point_on_core) / out.distance;
  } else if (!g.touching && g.distance > 0.0) {
    // nearly touching: the closest points' difference has no reliable direction; a smooth
    // body's closest point has the surface normal there
    out.method = DistanceMethod::gjk_sat;
    out.distance = g.distance;
    out.normal = grain.normal_at(g.point_a);
    out.point_on_core = g.point_a;
    out.point_on_segment = g.point_b;
    out.t = length > 0.0 ? std::clamp(g.weight_b1, 0.0, 1.0) : 0.0;
  } else {
    // the axis touches or crosses the body (an overlap beyond r_w): n = the body's normal
    // direction (∇F) at the segment point q nearest its centre, the distance minus the
    // overlap of body and segment along n, h(n) − min over the segment of n·x. A
    // separating-axis depth along one axis: at least the penetration depth, equal to it
    // where the axis just touches.
    out.method = DistanceMethod::sat;
    out.t = length > 0.0 ? std::clamp((grain.position() - end0).dot(s) / (length * length), 0.0, 1.0) : 0.0;
    out.point_on_segment = end0 + out.t * s;
    out.normal = grain.normal_at(out.point_on_segment);
    out.point_on_core = grain.support(out.normal);
    out.distance = -(out.normal.dot(out.point_on_core) + segment_support(S.end, -out.normal));
  }
  out.t_begin = out.t_end = out.t;
  out.gap = out.distance - wire_radius;
  return out;
}

}  // namespace wiregrain
