// Reference geometry for the contact-geometry tests, written independently of the code
// under test: brute-force feature-pair distances, the convex hull of the Minkowski
// difference, sampling of a segment, random grains and poses, rigid motions.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "core/geometry/contact_manifold.h"
#include "core/geometry/convex_shape.h"

namespace contact_reference {

// the names every contact-geometry test uses: a test file's `using namespace
// contact_reference;` brings these along
using namespace wiregrain;
using Eigen::AngleAxisd;
using Eigen::Matrix3d;
using Eigen::Quaterniond;
using Eigen::Vector2d;
using Eigen::Vector3d;

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------------------
// Reference geometry, written independently of the code under test.

// Closest point of triangle abc to p (Voronoi regions of vertices, edges, face).
inline Vector3d closest_on_triangle(const Vector3d& p, const Vector3d& a, const Vector3d& b,
                             const Vector3d& c) {
  const Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

inline Vector3d closest_on_segment(const Vector3d& p, const Vector3d& a, const Vector3d& b) {
  const Vector3d d = b - a;
  const double dd = d.squaredNorm();
  if (dd == 0.0) return a;
  return a + std::clamp((p - a).dot(d) / dd, 0.0, 1.0) * d;
}

// Distance of two segments: the smallest of the four end-to-segment distances and, for
// non-parallel lines, the distance at the stationary point if it lies inside both.
inline double segment_distance(const Vector3d& p0, const Vector3d& p1, const Vector3d& q0,
                        const Vector3d& q1, Vector3d& x, Vector3d& y) {
  double best = kInf;
  const auto take = [&](const Vector3d& a, const Vector3d& b) {
    const double d = (a - b).norm();
    if (d < best) {
      best = d;
      x = a;
      y = b;
    }
  };
  take(p0, closest_on_segment(p0, q0, q1));
  take(p1, closest_on_segment(p1, q0, q1));
  take(closest_on_segment(q0, p0, p1), q0);
  take(closest_on_segment(q1, p0, p1), q1);
  const Vector3d u = p1 - p0, v = q1 - q0, w = p0 - q0;
  const double a = u.dot(u), b = u.dot(v), c = v.dot(v), d = u.dot(w), e = v.dot(w);
  const double den = a * c - b * b;
  if (den > 1e-14 * a * c) {
    const double s = (b * e - c * d) / den, t = (a * e - b * d) / den;
    if (s > 0 && s < 1 && t > 0 && t < 1) take(p0 + s * u, q0 + t * v);
  }
  return best;
}

struct Triangle {
  std::array<Vector3d, 3> v;
  Vector3d center;
  double radius;
};

// A posed core in world coordinates, moved by the test itself.
struct WorldCore {
  std::vector<Vector3d> vertices;
  std::vector<Vector3d> normals;
  std::vector<double> offsets;
  std::vector<Triangle> triangles;  // fans of the faces
};

inline WorldCore world_core(const ConvexShape& shape, const Vector3d& x, const Quaterniond& q) {
  const Matrix3d R = q.normalized().toRotationMatrix();
  WorldCore w;
  for (const auto& v : shape.vertices()) w.vertices.push_back(R * v + x);
  for (const auto& f : shape.faces()) {
    const Vector3d n = R * f.normal;
    w.normals.push_back(n);
    w.offsets.push_back(n.dot(w.vertices[f.vertices[0]]));
    for (std::size_t k = 1; k + 1 < f.vertices.size(); ++k) {
      Triangle t;
      t.v = {w.vertices[f.vertices[0]], w.vertices[f.vertices[k]],
             w.vertices[f.vertices[k + 1]]};
      t.center = (t.v[0] + t.v[1] + t.v[2]) / 3.0;
      t.radius = 0.0;
      for (const auto& p : t.v) t.radius = std::max(t.radius, (p - t.center).norm());
      w.triangles.push_back(t);
    }
  }
  return w;
}

// Largest signed distance of p outside a face plane: 0 on the surface, < 0 inside.
inline double plane_excess(const WorldCore& c, const Vector3d& p) {
  double e = -kInf;
  for (std::size_t f = 0; f < c.normals.size(); ++f)
    e = std::max(e, c.normals[f].dot(p) - c.offsets[f]);
  return e;
}

// Exact distance from a point to a core (0 inside): nearest point of the surface
// triangles when outside.
inline double point_core_distance(const WorldCore& c, const Vector3d& p) {
  if (plane_excess(c, p) <= 0.0) return 0.0;
  double best = kInf;
  for (const auto& t : c.triangles) {
    if ((p - t.center).norm() - t.radius >= best) continue;
    best = std::min(best, (p - closest_on_triangle(p, t.v[0], t.v[1], t.v[2])).norm());
  }
  return best;
}

// Distance of two disjoint cores by brute force over all pairs of surface triangles
// (vertex–triangle and edge–edge distances), with its closest points. Returns false if
// the closest points do not certify disjointness: the planes through them ⟂ n = (pb −
// pa)/d must separate the cores, up to the rounding of n (~1e-16 × size / d).
inline bool core_distance_brute_force(const WorldCore& A, const WorldCore& B, double& distance,
                               Vector3d& pa, Vector3d& pb) {
  distance = kInf;
  const auto take = [&](const Vector3d& x, const Vector3d& y) {
    const double d = (x - y).norm();
    if (d < distance) {
      distance = d;
      pa = x;
      pb = y;
    }
  };
  for (const auto& ta : A.triangles) {
    for (const auto& tb : B.triangles) {
      if ((ta.center - tb.center).norm() - ta.radius - tb.radius >= distance) continue;
      for (const auto& v : ta.v) take(v, closest_on_triangle(v, tb.v[0], tb.v[1], tb.v[2]));
      for (const auto& v : tb.v) take(closest_on_triangle(v, ta.v[0], ta.v[1], ta.v[2]), v);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          Vector3d x, y;
          segment_distance(ta.v[i], ta.v[(i + 1) % 3], tb.v[j], tb.v[(j + 1) % 3], x, y);
          take(x, y);
        }
    }
  }
  if (!(distance > 0.0)) return false;
  const Vector3d n = (pb - pa) / distance;
  double ha = -kInf, hb = kInf;
  for (const auto& v : A.vertices) ha = std::max(ha, n.dot(v));
  for (const auto& v : B.vertices) hb = std::min(hb, n.dot(v));
  const double slack = 1e-13 + 1e-15 / distance;
  return ha <= n.dot(pa) + slack && hb >= n.dot(pb) - slack;
}

// Penetration depth and normal (from A to B) of overlapping cores: the origin is inside
// the Minkowski difference A − B, whose hull (CGAL, through ConvexShape) has faces
// n·x = h; the depth is the smallest h, its face normal the direction that separates B.
// Returns false if the origin is outside. second: the next smallest h (uniqueness).
inline bool penetration_from_minkowski_hull(const std::vector<Vector3d>& a,
                                     const std::vector<Vector3d>& b, double& depth,
                                     Vector3d& normal, double& second) {
  std::vector<Vector3d> diff;
  for (const auto& x : a)
    for (const auto& y : b) {
      const Vector3d z = x - y;  // aligned solids repeat differences: keep one
      bool repeated = false;
      for (const auto& w : diff) repeated = repeated || (w - z).norm() < 1e-9;
      if (!repeated) diff.push_back(z);
    }
  const ConvexShape hull = ConvexShape::from_points(diff, 0.0);
  depth = kInf;
  second = kInf;
  for (const auto& f : hull.faces()) {
    if (f.offset < depth) {
      second = depth;
      depth = f.offset;
      normal = f.normal;
    } else {
      second = std::min(second, f.offset);
    }
  }
  return depth > 0.0;
}

// ---------------------------------------------------------------------------------------

inline Quaterniond random_orientation(std::mt19937_64& rng) {
  std::normal_distribution<double> gauss;
  return Quaterniond(gauss(rng), gauss(rng), gauss(rng), gauss(rng)).normalized();
}

inline Vector3d random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> gauss;
  return Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
}

inline double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

inline ConvexShape random_grain(std::mt19937_64& rng, double sweep_radius) {
  const int n_v = std::uniform_int_distribution<int>(4, 40)(rng);
  const double a = uniform(rng, 0.8, 1.0);
  const double b = uniform(rng, 0.5, 1.0);
  const double c = uniform(rng, 0.3, 1.0) * b;
  return ConvexShape::random_ellipsoid(rng, n_v, a, b, c, sweep_radius);
}

struct Pose {
  Vector3d x;
  Quaterniond q;
};

// Moves B along u (from A's centre) until the brute-force core distance equals target.
// The distance is convex along the line, so Newton from the far side converges from
// above, monotonically. Returns false if it did not converge.
inline bool place_at_distance(const ConvexShape& a, const Pose& pa, const ConvexShape& b, Pose& pb,
                       const Vector3d& u, double target) {
  double s = a.bounding_radius() + b.bounding_radius() + target + 0.5;
  const WorldCore A = world_core(a, pa.x, pa.q);
  for (int it = 0; it < 60; ++it) {
    pb.x = pa.x + s * u;
    const WorldCore B = world_core(b, pb.x, pb.q);
    double d;
    Vector3d x, y;
    if (!core_distance_brute_force(A, B, d, x, y)) return false;
    if (std::abs(d - target) <= 1e-14) return true;
    const double slope = ((y - x) / d).dot(u);
    if (!(slope > 1e-3)) return false;
    s -= (d - target) / slope;
  }
  return false;
}

struct ErrorStats {
  double max = 0.0;
  int count = 0;
  void add(double e) {
    max = std::max(max, e);
    ++count;
  }
};

// ---------------------------------------------------------------------------------------
// Rigid motions and expected points

// A rigid motion applied to a whole configuration (checks frame independence).
struct Motion {
  Quaterniond q = Quaterniond::Identity();
  Vector3d t = Vector3d::Zero();
  Vector3d point(const Vector3d& x) const { return q * x + t; }
  Vector3d vector(const Vector3d& v) const { return q * v; }
  Quaterniond orientation(const Quaterniond& o) const { return q * o; }
};

inline std::vector<Motion> motions() {
  std::mt19937_64 rng(5);
  std::vector<Motion> m(1);
  for (int i = 0; i < 3; ++i) {
    Motion x;
    x.q = random_orientation(rng);
    x.t = Vector3d(uniform(rng, -3, 3), uniform(rng, -3, 3), uniform(rng, -3, 3));
    m.push_back(x);
  }
  return m;
}

// Every expected point is found (position within tol) and the counts agree.
inline void expect_points(const ContactManifold& m, const std::vector<Vector3d>& expected,
                   double tol, const char* label) {
  ASSERT_EQ(m.points.size(), expected.size()) << label;
  for (const auto& e : expected) {
    double best = kInf;
    for (const auto& p : m.points) best = std::min(best, (p.position - e).norm());
    EXPECT_LT(best, tol) << label << " expected point " << e.transpose();
  }
}

const Quaterniond kIdentity = Quaterniond::Identity();

// ---------------------------------------------------------------------------------------
// Wire segments

// Minimum over the segment of the exact point–core distance: dense sampling, then a
// golden-section search on the bracket of the best sample (the distance to a convex set
// is convex along a line). Returns the distance and the parameter.
inline double segment_core_reference(const WorldCore& c, const Vector3d& p0, const Vector3d& p1,
                              double& t_best) {
  const auto f = [&](double t) { return point_core_distance(c, p0 + t * (p1 - p0)); };
  constexpr int kSamples = 200;
  double best = kInf;
  int i_best = 0;
  for (int i = 0; i <= kSamples; ++i) {
    const double d = f(double(i) / kSamples);
    if (d < best) {
      best = d;
      i_best = i;
    }
  }
  double lo = std::max(0, i_best - 1) / double(kSamples);
  double hi = std::min(kSamples, i_best + 1) / double(kSamples);
  const double phi = (std::sqrt(5.0) - 1.0) / 2.0;
  double x1 = hi - phi * (hi - lo), x2 = lo + phi * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  for (int it = 0; it < 80 && hi - lo > 1e-15; ++it) {
    if (f1 <= f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - phi * (hi - lo);
      f1 = f(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + phi * (hi - lo);
      f2 = f(x2);
    }
  }
  t_best = i_best / double(kSamples);
  for (const double t : {x1, x2, 0.0, 1.0}) {
    const double d = f(t);
    if (d < best) {
      best = d;
      t_best = t;
    }
  }
  return best;
}

}  // namespace contact_reference
