// Separating-axis test of two posed cores and of a core and a segment. See sat.h.
#include "core/geometry/sat.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/geometry/contact_frame.h"
#include "core/geometry/gjk.h"

namespace wiregrain {

namespace {

using Eigen::Vector3d;

// Edge pairs whose cross product is below this (relative to the edge lengths) are
// parallel: their separating axis coincides with a face normal (tested anyway).
constexpr double kParallelEdges = 1e-12;

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

// Gauss-map test for edge pairs (Gregorius, GDC 2013): the great arcs a1→a2 of A's edge
// and c→d = −b1→−b2 of B's (each shorter than π) intersect iff c·(a2×a1) and d·(a2×a1)
// differ in sign, a1·(d×c) and a2·(d×c) differ in sign, and c·(a2×a1), a2·(d×c) agree
// (same hemisphere). Inclusive by a rounding margin: an extra candidate axis is harmless
// (it only gives an upper bound of the depth).

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

}  // namespace

SatAxis point_point_axis(const Vector3d& a, const Vector3d& b) {
  SatAxis axis;
  const Vector3d d = b - a;
  const double length = d.norm();
  axis.depth = -length;
  if (length > 0.0) axis.normal = d / length;
  return axis;
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

}  // namespace wiregrain
