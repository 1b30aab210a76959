// Contact features of a posed core. See contact_features.h.
#include "core/geometry/contact_features.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace wiregrain {

using Eigen::Vector2d;
using Eigen::Vector3d;

namespace {

bool face_has_vertex(const ConvexShape::Face& face, int vertex) {
  return std::find(face.vertices.begin(), face.vertices.end(), vertex) != face.vertices.end();
}

}  // namespace

ContactFeature select_feature(const PosedShape& P, const Vector3d& n, double cos_tol,
                              double sin_tol, double tight) {
  // the support vertex v (the first of the largest n·x, as PosedShape::support_vertex) and
  // S from one pass of the dot products
  const int count = static_cast<int>(P.vertices().size());
  thread_local std::vector<double> heights;
  heights.resize(count);
  int v = 0;
  double h = -std::numeric_limits<double>::infinity();
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
    double best_sin = std::numeric_limits<double>::infinity();
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

double segment_param_nearest_line(const Vector3d& b0, const Vector3d& b1, const Vector3d& x,
                                  const Vector3d& n) {
  const Vector3d e = b1 - b0, r = b0 - x;
  const Vector3d pe = e - n.dot(e) * n, pr = r - n.dot(r) * n;
  const double ee = pe.squaredNorm();
  return ee > 0.0 ? std::clamp(-pr.dot(pe) / ee, 0.0, 1.0) : 0.0;
}

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

PlanePolygon face_polygon(const PosedShape& P, int face, const ContactFrame& frame) {
  const auto& loop = P.shape().faces()[face].vertices;
  PlanePolygon poly;
  for (int i : loop) poly.push_back(frame.project(P.vertices()[i]));
  if (P.face_normal(face).dot(frame.n) < 0.0) std::reverse(poly.begin(), poly.end());
  return poly;
}

}  // namespace wiregrain
