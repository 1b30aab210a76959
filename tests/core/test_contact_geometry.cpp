// Contact geometry of spheropolyhedra, walls and wire segments, against independent
// references: brute-force feature-pair distances, the convex hull of the Minkowski
// difference, sampling of the segment, and closed-form answers for regular solids.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "core/geometry/contact_geometry.h"
#include "core/geometry/convex_shape.h"
#include "core/common/errors.h"

using namespace wiregrain;
using Eigen::AngleAxisd;
using Eigen::Matrix3d;
using Eigen::Quaterniond;
using Eigen::Vector2d;
using Eigen::Vector3d;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------------------
// Reference geometry, written independently of the code under test.

// Closest point of triangle abc to p (Voronoi regions of vertices, edges, face).
Vector3d closest_on_triangle(const Vector3d& p, const Vector3d& a, const Vector3d& b,
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

Vector3d closest_on_segment(const Vector3d& p, const Vector3d& a, const Vector3d& b) {
  const Vector3d d = b - a;
  const double dd = d.squaredNorm();
  if (dd == 0.0) return a;
  return a + std::clamp((p - a).dot(d) / dd, 0.0, 1.0) * d;
}

// Distance of two segments: the smallest of the four end-to-segment distances and, for
// non-parallel lines, the distance at the stationary point if it lies inside both.
double segment_distance(const Vector3d& p0, const Vector3d& p1, const Vector3d& q0,
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

WorldCore world_core(const ConvexShape& shape, const Vector3d& x, const Quaterniond& q) {
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
double plane_excess(const WorldCore& c, const Vector3d& p) {
  double e = -kInf;
  for (std::size_t f = 0; f < c.normals.size(); ++f)
    e = std::max(e, c.normals[f].dot(p) - c.offsets[f]);
  return e;
}

// Exact distance from a point to a core (0 inside): nearest point of the surface
// triangles when outside.
double point_core_distance(const WorldCore& c, const Vector3d& p) {
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
bool core_distance_brute_force(const WorldCore& A, const WorldCore& B, double& distance,
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
bool penetration_from_minkowski_hull(const std::vector<Vector3d>& a,
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

Quaterniond random_orientation(std::mt19937_64& rng) {
  std::normal_distribution<double> gauss;
  return Quaterniond(gauss(rng), gauss(rng), gauss(rng), gauss(rng)).normalized();
}

Vector3d random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> gauss;
  return Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
}

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

ConvexShape random_grain(std::mt19937_64& rng, double sweep_radius) {
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
bool place_at_distance(const ConvexShape& a, const Pose& pa, const ConvexShape& b, Pose& pb,
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
// Core distance of random grains

// Checks one disjoint pair against the brute-force reference; returns the distance error.
double check_distance_case(const ConvexShape& sa, const Pose& pa, const ConvexShape& sb,
                           const Pose& pb, ErrorStats& witness_err, int& checked) {
  const WorldCore A = world_core(sa, pa.x, pa.q), B = world_core(sb, pb.x, pb.q);
  double d_ref;
  Vector3d xa, xb;
  if (!core_distance_brute_force(A, B, d_ref, xa, xb)) return -1.0;  // overlapping
  ++checked;
  const PosedShape a(sa, pa.x, pa.q), b(sb, pb.x, pb.q);
  const CoreDistance cd = core_distance(a, b);
  EXPECT_GT(cd.distance, 0.0);
  // the witnesses lie on the two surfaces, their distance is the distance, the normal
  // joins them
  const double on_a = std::abs(plane_excess(A, cd.point_a));
  const double on_b = std::abs(plane_excess(B, cd.point_b));
  const double span = std::abs((cd.point_b - cd.point_a).norm() - d_ref);
  witness_err.add(std::max({on_a, on_b, span}));
  EXPECT_LT(on_a, 1e-9);
  EXPECT_LT(on_b, 1e-9);
  EXPECT_LT(span, 1e-9);
  EXPECT_NEAR(cd.normal.norm(), 1.0, 1e-12);
  EXPECT_LT((cd.normal - (xb - xa) / d_ref).norm(), d_ref > 1e-6 ? 1e-6 : 2.0);
  // and the spheropolyhedra's gap
  const ContactManifold m = contact_manifold(a, b, kInf);
  EXPECT_NEAR(m.gap, d_ref - sa.sweep_radius() - sb.sweep_radius(), 1e-9);
  return std::abs(cd.distance - d_ref);
}

TEST(ContactDistance, RandomEllipsoidHullsMatchBruteForce) {
  std::mt19937_64 rng(20240611);
  ErrorStats dist_err, witness_err;
  int checked = 0, iterations = 0;
  while (checked < 1000) {
    const ConvexShape sa = random_grain(rng, 0.1), sb = random_grain(rng, 0.1);
    const Pose pa{Vector3d(uniform(rng, -2, 2), uniform(rng, -2, 2), uniform(rng, -2, 2)),
                  random_orientation(rng)};
    Pose pb{pa.x + uniform(rng, 0.6, 3.0) * random_unit(rng), random_orientation(rng)};
    const double e = check_distance_case(sa, pa, sb, pb, witness_err, checked);
    if (e < 0.0) continue;
    dist_err.add(e);
    EXPECT_LT(e, 1e-9);
    iterations += core_distance(PosedShape(sa, pa.x, pa.q), PosedShape(sb, pb.x, pb.q))
                      .gjk_iterations;
  }
  std::printf("  %d random disjoint pairs: max |d - d_ref| = %.2e, witnesses %.2e, "
              "mean GJK iterations %.1f\n",
              checked, dist_err.max, witness_err.max, iterations / double(checked));
}

// Regular solids, disjoint, equally oriented or turned by quarter turns (parallel faces
// and edges: degenerate simplices for GJK).
TEST(ContactDistance, AlignedRegularSolidsMatchBruteForce) {
  std::mt19937_64 rng(606);
  const std::vector<ConvexShape> solids = {
      ConvexShape::cube(1.0, 0.1), ConvexShape::box(1.2, 0.7, 0.4, 0.1),
      ConvexShape::regular_tetrahedron(1.3, 0.1), ConvexShape::regular_octahedron(1.0, 0.1)};
  ErrorStats dist_err, witness_err;
  int checked = 0;
  while (checked < 300) {
    const ConvexShape& sa = solids[rng() % 4];
    const ConvexShape& sb = solids[rng() % 4];
    const Quaterniond qa = random_orientation(rng);
    const Quaterniond qb =
        qa * Quaterniond(AngleAxisd(kPi / 2 * double(rng() % 4), Vector3d::UnitY()));
    // along a body axis of A, sideways by a random amount, at a random distance
    const Vector3d local(uniform(rng, -0.6, 0.6), uniform(rng, -0.6, 0.6),
                         (rng() % 2 ? 1.0 : -1.0) * uniform(rng, 1.0, 2.0));
    const Pose pa{Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)), qa};
    const Pose pb{pa.x + qa * local, qb};
    const double e = check_distance_case(sa, pa, sb, pb, witness_err, checked);
    if (e < 0.0) continue;
    dist_err.add(e);
    EXPECT_LT(e, 1e-9);
  }
  std::printf("  %d aligned regular-solid pairs: max |d - d_ref| = %.2e, witnesses %.2e\n",
              checked, dist_err.max, witness_err.max);
}

// Pairs placed (by Newton on the brute-force distance) at a prescribed core distance:
// dilated grains touching (d = r_A + r_B), and cores nearly touching (1e-3 … 1e-10, the
// last two below the GJK normal's conditioning limit, where the normal comes from SAT).
TEST(ContactDistance, TouchingAndNearlyTouchingPairs) {
  std::mt19937_64 rng(77);
  const std::array<double, 5> targets = {0.2, 1e-3, 1e-6, 1e-9, 1e-10};
  ErrorStats dist_err, witness_err;
  int checked = 0;
  for (int k = 0; k < 250; ++k) {
    const double target = targets[k % targets.size()];
    const ConvexShape sa = random_grain(rng, 0.1), sb = random_grain(rng, 0.1);
    const Pose pa{Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)),
                  random_orientation(rng)};
    Pose pb{Vector3d::Zero(), random_orientation(rng)};
    if (!place_at_distance(sa, pa, sb, pb, random_unit(rng), target)) continue;
    const double e = check_distance_case(sa, pa, sb, pb, witness_err, checked);
    ASSERT_GE(e, 0.0);
    dist_err.add(e);
    EXPECT_LT(e, 1e-9) << "target " << target;
    if (target == 0.2) {
      const ContactManifold m =
          contact_manifold(PosedShape(sa, pa.x, pa.q), PosedShape(sb, pb.x, pb.q), 0.0);
      EXPECT_NEAR(m.gap, 0.0, 1e-9);
    }
  }
  EXPECT_GE(checked, 240);
  std::printf("  %d touching / nearly touching pairs: max |d - d_ref| = %.2e, witnesses "
              "%.2e\n",
              checked, dist_err.max, witness_err.max);
}

// Overlapping cores: penetration depth and normal against the hull of the Minkowski
// difference.
TEST(ContactPenetration, RandomOverlapsMatchMinkowskiHull) {
  std::mt19937_64 rng(4242);
  const std::vector<ConvexShape> solids = {
      ConvexShape::cube(1.0, 0.1), ConvexShape::box(1.2, 0.7, 0.4, 0.1),
      ConvexShape::regular_tetrahedron(1.3, 0.1), ConvexShape::regular_octahedron(1.0, 0.1)};
  ErrorStats depth_err, normal_err;
  int checked = 0;
  while (checked < 500) {
    // 300 random grains, then regular solids: randomly oriented, equally oriented, or
    // turned by quarter turns (many parallel faces and edges)
    const bool regular = checked >= 300;
    const ConvexShape sa = regular ? solids[rng() % 4] : random_grain(rng, 0.1);
    const ConvexShape sb = regular ? solids[rng() % 4] : random_grain(rng, 0.1);
    const Quaterniond qa = random_orientation(rng);
    Quaterniond qb = random_orientation(rng);
    if (regular && checked % 3 == 1) qb = qa;
    if (regular && checked % 3 == 2)
      qb = qa * Quaterniond(AngleAxisd(kPi / 2 * double(rng() % 4), Vector3d::UnitX())) *
           Quaterniond(AngleAxisd(kPi / 2 * double(rng() % 4), Vector3d::UnitZ()));
    const Pose pa{Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)), qa};
    const Pose pb{pa.x + uniform(rng, 0.0, 0.9) * random_unit(rng), qb};
    const PosedShape a(sa, pa.x, pa.q), b(sb, pb.x, pb.q);
    double depth, second;
    Vector3d normal;
    if (!penetration_from_minkowski_hull(a.vertices(), b.vertices(), depth, normal, second))
      continue;
    ++checked;
    const CoreDistance cd = core_distance(a, b);
    EXPECT_EQ(cd.method, DistanceMethod::sat);
    depth_err.add(std::abs(cd.distance + depth));
    EXPECT_NEAR(cd.distance, -depth, 1e-9);
    if (second - depth > 1e-6) {
      normal_err.add((cd.normal - normal).norm());
      EXPECT_LT((cd.normal - normal).norm(), 1e-9);
    }
    // the manifold's deepest point has the pair's gap
    const ContactManifold m = contact_manifold(a, b, 0.0);
    ASSERT_FALSE(m.points.empty());
    double deepest = kInf;
    for (const auto& p : m.points) deepest = std::min(deepest, p.gap);
    EXPECT_NEAR(deepest, -depth - 0.2, 1e-9);
  }
  std::printf("  %d overlapping pairs: max depth error %.2e, normal error %.2e (%d unique)\n",
              checked, depth_err.max, normal_err.max, normal_err.count);
}

// height_above_faces, the bound add_near_vertices leaves a vertex out by: never above the
// point's distance to the core (brute force over the surface triangles), <= 0 inside, and
// equal to it above a face's centroid.
TEST(ContactGeometry, HeightAboveFacesBoundsThePointDistanceFromBelow) {
  std::mt19937_64 rng(29);
  int outside = 0, inside = 0, equal = 0;
  for (int k = 0; k < 200; ++k) {
    const ConvexShape shape = random_grain(rng, 0.05);
    const Pose pose{Vector3d(uniform(rng, -5, 5), uniform(rng, -5, 5), uniform(rng, 0, 10)), random_orientation(rng)};
    const PosedShape posed(shape, pose.x, pose.q);
    const WorldCore core = world_core(shape, pose.x, pose.q);
    for (int j = 0; j < 20; ++j) {
      const Vector3d x = pose.x + uniform(rng, 0.0, 2.5) * random_unit(rng);
      const double height = height_above_faces(posed, x), distance = point_core_distance(core, x);
      if (distance > 0.0) {
        ++outside;
        EXPECT_LE(height, distance + 1e-12);
        equal += std::abs(height - distance) < 1e-12;
      } else {
        ++inside;
        EXPECT_LE(height, 1e-12);
      }
    }
    for (int f = 0; f < static_cast<int>(shape.faces().size()); ++f) {
      Vector3d centroid = Vector3d::Zero();
      for (int v : shape.faces()[f].vertices) centroid += core.vertices[v];
      centroid /= static_cast<double>(shape.faces()[f].vertices.size());
      const double above = uniform(rng, 1e-3, 1.0);
      const Vector3d x = centroid + above * core.normals[f];
      EXPECT_NEAR(height_above_faces(posed, x), above, 1e-12);
      EXPECT_NEAR(point_core_distance(core, x), above, 1e-12);
    }
  }
  EXPECT_GT(outside, 1000);
  EXPECT_GT(inside, 100);
  EXPECT_GT(equal, 100);  // the foot in a face: the bound is the distance
  std::printf("  %d points outside (%d at their bound), %d inside\n", outside, equal, inside);
}

// Manifolds of random grains in contact: every point's core points lie on the cores, the
// smallest point gap is the pair's gap, no point is deeper.
TEST(ContactManifold, RandomGrainsPointsOnSurfacesAndDeepestIsPairGap) {
  std::mt19937_64 rng(9);
  ErrorStats surface_err, gap_err;
  int multi = 0;
  for (int k = 0; k < 300; ++k) {
    const ConvexShape sa = random_grain(rng, 0.1), sb = random_grain(rng, 0.05);
    const Pose pa{Vector3d::Zero(), random_orientation(rng)};
    Pose pb{Vector3d::Zero(), random_orientation(rng)};
    if (!place_at_distance(sa, pa, sb, pb, random_unit(rng), uniform(rng, 0.05, 0.2)))
      continue;
    const PosedShape a(sa, pa.x, pa.q), b(sb, pb.x, pb.q);
    const WorldCore A = world_core(sa, pa.x, pa.q), B = world_core(sb, pb.x, pb.q);
    ContactOptions options;
    options.angle_tolerance = 0.3;  // large, to get many multi-point manifolds
    const ContactManifold m = contact_manifold(a, b, 0.1, options);
    ASSERT_FALSE(m.points.empty());
    multi += m.points.size() > 1;
    double deepest = kInf;
    for (const auto& p : m.points) {
      deepest = std::min(deepest, p.gap);
      EXPECT_GE(p.gap, m.gap - 1e-12);
      const Vector3d core_a = p.point_a - 0.1 * m.normal, core_b = p.point_b + 0.05 * m.normal;
      const double e = std::max(std::abs(plane_excess(A, core_a)),
                                std::abs(plane_excess(B, core_b)));
      surface_err.add(e);
      EXPECT_LT(e, 1e-9);
      EXPECT_NEAR(p.gap, m.normal.dot(p.point_b - p.point_a), 1e-14);
      EXPECT_LT((p.position - 0.5 * (p.point_a + p.point_b)).norm(), 1e-14);
    }
    gap_err.add(std::abs(deepest - m.gap));
    EXPECT_NEAR(deepest, m.gap, 1e-9);
  }
  EXPECT_GT(multi, 20);
  std::printf("  %d manifolds (%d multi-point): points off the cores %.2e, deepest - gap "
              "%.2e\n",
              surface_err.count > 0 ? gap_err.count : 0, multi, surface_err.max, gap_err.max);
}

// ---------------------------------------------------------------------------------------
// Regular solids: exact manifolds

// A rigid motion applied to a whole configuration (checks frame independence).
struct Motion {
  Quaterniond q = Quaterniond::Identity();
  Vector3d t = Vector3d::Zero();
  Vector3d point(const Vector3d& x) const { return q * x + t; }
  Vector3d vector(const Vector3d& v) const { return q * v; }
  Quaterniond orientation(const Quaterniond& o) const { return q * o; }
};

std::vector<Motion> motions() {
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
void expect_points(const ContactManifold& m, const std::vector<Vector3d>& expected,
                   double tol, const char* label) {
  ASSERT_EQ(m.points.size(), expected.size()) << label;
  for (const auto& e : expected) {
    double best = kInf;
    for (const auto& p : m.points) best = std::min(best, (p.position - e).norm());
    EXPECT_LT(best, tol) << label << " expected point " << e.transpose();
  }
}

const Quaterniond kIdentity = Quaterniond::Identity();

TEST(ContactManifold, CubeOnCubeFaceToFaceOffsetLaterally) {
  const ConvexShape lower = ConvexShape::cube(1.0, 0.1), upper = ConvexShape::cube(1.0, 0.05);
  const double g = 0.013;
  for (const Motion& M : motions()) {
    for (const Vector2d& off : {Vector2d(0.3, 0.2), Vector2d(-0.45, 0.1), Vector2d(0, 0)}) {
      const Vector3d xb(off.x(), off.y(), 1.0 + 0.15 + g);
      const PosedShape a(lower, M.point(Vector3d::Zero()), M.orientation(kIdentity));
      const PosedShape b(upper, M.point(xb), M.orientation(kIdentity));
      const ContactManifold m = contact_manifold(a, b, 0.05);
      EXPECT_NEAR(m.gap, g, 1e-12);
      EXPECT_LT((m.normal - M.vector(Vector3d::UnitZ())).norm(), 1e-12);
      EXPECT_EQ(m.feature_a.kind, FeatureKind::face);
      EXPECT_EQ(m.feature_b.kind, FeatureKind::face);
      // the overlap rectangle of the two unit squares, at mid-height of the gap
      const double x0 = std::max(-0.5, off.x() - 0.5), x1 = std::min(0.5, off.x() + 0.5);
      const double y0 = std::max(-0.5, off.y() - 0.5), y1 = std::min(0.5, off.y() + 0.5);
      const double z = 0.5 + 0.1 + 0.5 * g;
      expect_points(m,
                    {M.point({x0, y0, z}), M.point({x1, y0, z}), M.point({x1, y1, z}),
                     M.point({x0, y1, z})},
                    1e-12, "rectangle");
      for (const auto& p : m.points) EXPECT_NEAR(p.gap, g, 1e-12);
    }
  }
}

// Square faces overlapping in a triangle (corner of the upper square's diamond), in an
// octagon (diamond centred), and the octagon reduced to 4 points.
TEST(ContactManifold, CubeOnRotatedCubePartialOverlapPolygons) {
  const ConvexShape cube = ConvexShape::cube(1.0, 0.0);
  const Quaterniond diamond(AngleAxisd(kPi / 4, Vector3d::UnitZ()));
  const double g = 0.02, h = std::sqrt(0.5);  // diamond: |x| + |y| <= h about its centre
  for (const Motion& M : motions()) {
    {  // diamond centred at (0.8, 0.8): the square's corner (0.5, 0.5) is inside it
      const PosedShape a(cube, M.point(Vector3d::Zero()), M.orientation(kIdentity));
      const PosedShape b(cube, M.point({0.8, 0.8, 1.0 + g}), M.orientation(diamond));
      const ContactManifold m = contact_manifold(a, b, 0.05);
      const double c = 1.6 - h;  // the diamond's edge x + y = c
      expect_points(m,
                    {M.point({0.5, 0.5, 0.5 + g / 2}), M.point({0.5, c - 0.5, 0.5 + g / 2}),
                     M.point({c - 0.5, 0.5, 0.5 + g / 2})},
                    1e-12, "triangle");
      for (const auto& p : m.points) EXPECT_NEAR(p.gap, g, 1e-12);
    }
    {  // centred: an octagon with corners (±0.5, ±(h − 0.5)), (±(h − 0.5), ±0.5)
      const PosedShape a(cube, M.point(Vector3d::Zero()), M.orientation(kIdentity));
      const PosedShape b(cube, M.point({0, 0, 1.0 + g}), M.orientation(diamond));
      std::vector<Vector3d> octagon;
      for (double sx : {-1.0, 1.0})
        for (double sy : {-1.0, 1.0}) {
          octagon.push_back(M.point({sx * 0.5, sy * (h - 0.5), 0.5 + g / 2}));
          octagon.push_back(M.point({sx * (h - 0.5), sy * 0.5, 0.5 + g / 2}));
        }
      const ContactManifold m = contact_manifold(a, b, 0.05);
      expect_points(m, octagon, 1e-12, "octagon");
      for (const auto& p : m.points) EXPECT_NEAR(p.gap, g, 1e-12);
      ContactOptions four;
      four.max_points = 4;
      const ContactManifold r = contact_manifold(a, b, 0.05, four);
      ASSERT_EQ(r.points.size(), 4u);
      // the kept points are corners of the octagon, spanning a quadrilateral of area
      // 2 (h − 0.5)·1 + ... at least that of the best inscribed rectangle 1 × 2(h − 0.5)
      for (const auto& p : r.points) {
        double best = kInf;
        for (const auto& o : octagon) best = std::min(best, (p.position - o).norm());
        EXPECT_LT(best, 1e-12);
      }
      std::vector<Vector2d> local;
      for (const auto& p : r.points) {
        const Vector3d x = M.q.conjugate() * (p.position - M.t);
        local.emplace_back(x.x(), x.y());
      }
      // area of the kept quadrilateral (the points come out in polygon order)
      double area = 0.0;
      for (std::size_t i = 0; i < local.size(); ++i) {
        const Vector2d& p = local[i];
        const Vector2d& q = local[(i + 1) % local.size()];
        area += 0.5 * (p.x() * q.y() - p.y() * q.x());
      }
      EXPECT_GE(std::abs(area), 2.0 * (h - 0.5) - 1e-12);
    }
  }
}

TEST(ContactManifold, EdgeOnFaceGivesTwoPoints) {
  const ConvexShape lower = ConvexShape::cube(1.0, 0.1), upper = ConvexShape::cube(1.0, 0.05);
  const Quaterniond on_edge(AngleAxisd(kPi / 4, Vector3d::UnitX()));  // lowest edge along x
  const double g = 0.004;
  for (const Motion& M : motions()) {
    for (double dx : {0.0, 0.3, -0.7}) {
      const Vector3d xb(dx, 0.1, 0.5 + 0.15 + g + std::sqrt(0.5));
      const PosedShape a(lower, M.point(Vector3d::Zero()), M.orientation(kIdentity));
      const PosedShape b(upper, M.point(xb), M.orientation(on_edge));
      const ContactManifold m = contact_manifold(a, b, 0.05);
      EXPECT_NEAR(m.gap, g, 1e-12);
      EXPECT_EQ(m.feature_a.kind, FeatureKind::face);
      EXPECT_EQ(m.feature_b.kind, FeatureKind::edge);
      const double x0 = std::max(-0.5, dx - 0.5), x1 = std::min(0.5, dx + 0.5);
      const double z = 0.5 + 0.1 + g / 2;
      expect_points(m, {M.point({x0, 0.1, z}), M.point({x1, 0.1, z})}, 1e-12, "edge");
      for (const auto& p : m.points) EXPECT_NEAR(p.gap, g, 1e-12);
    }
  }
}

TEST(ContactManifold, VertexOnFaceGivesOnePoint) {
  const ConvexShape cube = ConvexShape::cube(1.0, 0.1);
  // turns the diagonal (1,1,1) to +z: the corner (−½,−½,−½) is lowest, √3/2 below the centre
  const Quaterniond corner_down =
      Quaterniond::FromTwoVectors(Vector3d(1, 1, 1), Vector3d::UnitZ());
  const double g = -0.003;  // slightly interpenetrating dilated grains, cores disjoint
  for (const Motion& M : motions()) {
    const Vector3d xb(0.2, -0.3, 0.5 + 0.2 + g + std::sqrt(3.0) / 2);
    const PosedShape a(cube, M.point(Vector3d::Zero()), M.orientation(kIdentity));
    const PosedShape b(cube, M.point(xb), M.orientation(corner_down));
    const ContactManifold m = contact_manifold(a, b, 0.0);
    EXPECT_NEAR(m.gap, g, 1e-12);
    EXPECT_EQ(m.feature_b.kind, FeatureKind::vertex);
    expect_points(m, {M.point({0.2, -0.3, 0.5 + 0.1 + g / 2})}, 1e-12, "vertex");
    EXPECT_NEAR(m.points[0].gap, g, 1e-12);
  }
}

// Crossed edges (1 point) and parallel edges (2 points), disjoint and penetrating cores.
TEST(ContactManifold, EdgeOnEdgeCrossedAndParallel) {
  const ConvexShape cube = ConvexShape::cube(1.0, 0.0);
  const Quaterniond ridge_x(AngleAxisd(kPi / 4, Vector3d::UnitX()));  // top/bottom edges ∥ x
  const Quaterniond ridge_y(AngleAxisd(kPi / 4, Vector3d::UnitY()));  // ∥ y
  const double e = std::sqrt(0.5);  // centre to ridge
  for (const Motion& M : motions()) {
    for (double g : {0.01, -0.01}) {
      const PosedShape a(cube, M.point(Vector3d::Zero()), M.orientation(ridge_x));
      const PosedShape crossed(cube, M.point({0.1, -0.2, 2 * e + g}), M.orientation(ridge_y));
      const ContactManifold m = contact_manifold(a, crossed, 0.05);
      EXPECT_NEAR(m.gap, g, 1e-12);
      EXPECT_EQ(m.method, g > 0 ? DistanceMethod::gjk : DistanceMethod::sat);
      EXPECT_LT((m.normal - M.vector(Vector3d::UnitZ())).norm(), 1e-12);
      expect_points(m, {M.point({0.1, 0.0, e + g / 2})}, 1e-12, "crossed");
      EXPECT_NEAR(m.points[0].gap, g, 1e-12);

      const PosedShape parallel(cube, M.point({0.4, 0.0, 2 * e + g}), M.orientation(ridge_x));
      const ContactManifold p = contact_manifold(a, parallel, 0.05);
      if (g > 0) {
        EXPECT_NEAR(p.gap, g, 1e-12);
        EXPECT_EQ(p.feature_a.kind, FeatureKind::edge);
        EXPECT_EQ(p.feature_b.kind, FeatureKind::edge);
        expect_points(p, {M.point({-0.1, 0, e + g / 2}), M.point({0.5, 0, e + g / 2})}, 1e-12,
                      "parallel");
        for (const auto& q : p.points) EXPECT_NEAR(q.gap, g, 1e-12);
      } else {
        // interpenetrating wedges separate faster sideways, along a 45° face normal
        // (0, ±1, 1)/√2, by |g|/√2
        EXPECT_NEAR(p.gap, g / std::sqrt(2.0), 1e-12);
        const Vector3d n = M.q.conjugate() * p.normal;
        EXPECT_NEAR(std::abs(n.y()), std::sqrt(0.5), 1e-12);
        EXPECT_NEAR(n.z(), std::sqrt(0.5), 1e-12);
        double deepest = kInf;
        for (const auto& q : p.points) deepest = std::min(deepest, q.gap);
        EXPECT_NEAR(deepest, g / std::sqrt(2.0), 1e-12);
      }
    }
  }
}

TEST(ContactPenetration, OverlappingCubesDepthNormalAndPoints) {
  const ConvexShape lower = ConvexShape::cube(1.0, 0.1), upper = ConvexShape::cube(1.0, 0.05);
  for (const Motion& M : motions()) {
    for (double depth : {1e-6, 0.01, 0.15}) {
      const PosedShape a(lower, M.point(Vector3d::Zero()), M.orientation(kIdentity));
      const PosedShape b(upper, M.point({0.3, -0.2, 1.0 - depth}), M.orientation(kIdentity));
      const ContactManifold m = contact_manifold(a, b, 0.0);
      EXPECT_EQ(m.method, DistanceMethod::sat);
      EXPECT_NEAR(m.core_distance, -depth, 1e-12);
      EXPECT_NEAR(m.gap, -depth - 0.15, 1e-12);
      EXPECT_LT((m.normal - M.vector(Vector3d::UnitZ())).norm(), 1e-12);
      const double z = 0.5 + 0.1 + 0.5 * (-depth - 0.15);
      expect_points(m,
                    {M.point({-0.2, -0.5, z}), M.point({0.5, -0.5, z}), M.point({0.5, 0.3, z}),
                     M.point({-0.2, 0.3, z})},
                    1e-12, "overlap");
      for (const auto& p : m.points) EXPECT_NEAR(p.gap, -depth - 0.15, 1e-12);
    }
    // sideways: the shallowest direction is x, not the centre line
    const PosedShape a(lower, M.point(Vector3d::Zero()), M.orientation(kIdentity));
    const PosedShape b(upper, M.point({0.95, 0.0, 0.3}), M.orientation(kIdentity));
    const CoreDistance cd = core_distance(a, b);
    EXPECT_NEAR(cd.distance, -0.05, 1e-12);
    EXPECT_LT((cd.normal - M.vector(Vector3d::UnitX())).norm(), 1e-12);
  }
}

// Cores touching exactly (distance 0, method sat) or nearly (1e-11, below the GJK
// normal's conditioning limit): the face–face manifold stays exact.
TEST(ContactManifold, CubesWithTouchingAndNearlyTouchingCores) {
  const ConvexShape cube = ConvexShape::cube(1.0, 0.1);
  for (const Motion& M : motions()) {
    for (double d : {0.0, 1e-11}) {
      const PosedShape a(cube, M.point(Vector3d::Zero()), M.orientation(kIdentity));
      const PosedShape b(cube, M.point({0.25, 0.5, 1.0 + d}), M.orientation(kIdentity));
      const ContactManifold m = contact_manifold(a, b, 0.0);
      EXPECT_EQ(m.method, d == 0.0 ? DistanceMethod::sat : DistanceMethod::gjk_sat);
      EXPECT_NEAR(m.gap, d - 0.2, 1e-12);
      EXPECT_LT((m.normal - M.vector(Vector3d::UnitZ())).norm(), 1e-12);
      const double z = 0.5 + d / 2;
      expect_points(m,
                    {M.point({-0.25, 0.0, z}), M.point({0.5, 0.0, z}), M.point({0.5, 0.5, z}),
                     M.point({-0.25, 0.5, z})},
                    1e-12, "touching");
      for (const auto& p : m.points) EXPECT_NEAR(p.gap, d - 0.2, 1e-12);
    }
  }
}

// Corner above corner: the normal (the line of the corners) is no SAT axis; for nearly
// touching cores the GJK direction is kept because it separates more.
TEST(ContactManifold, VertexOnVertexNormalAlongTheCorners) {
  const ConvexShape cube = ConvexShape::cube(1.0, 0.05);
  const Quaterniond corner_up = Quaterniond::FromTwoVectors(Vector3d(1, 1, 1), Vector3d::UnitZ());
  const Quaterniond twisted = Quaterniond(AngleAxisd(0.4, Vector3d::UnitZ())) * corner_up;
  for (const Motion& M : motions()) {
    for (double d : {0.05, 1e-9}) {
      const PosedShape a(cube, M.point(Vector3d::Zero()), M.orientation(corner_up));
      const PosedShape b(cube, M.point({0, 0, std::sqrt(3.0) + d}), M.orientation(twisted));
      const ContactManifold m = contact_manifold(a, b, 0.0);
      EXPECT_EQ(m.method, DistanceMethod::gjk);
      EXPECT_NEAR(m.gap, d - 0.1, 1e-12);
      // the direction of the closest-point difference: rounding ~1e-16 × |x| / d
      EXPECT_LT((m.normal - M.vector(Vector3d::UnitZ())).norm(), 1e-14 / d);
      EXPECT_EQ(m.feature_a.kind, FeatureKind::vertex);
      EXPECT_EQ(m.feature_b.kind, FeatureKind::vertex);
      expect_points(m, {M.point({0, 0, std::sqrt(0.75) + d / 2})}, 1e-12, "vertex-vertex");
    }
  }
}

// Far pairs: GJK stops on its lower bound, no points; the reported gap is a lower bound.
TEST(ContactManifold, FarPairsStopEarlyWithALowerBound) {
  std::mt19937_64 rng(3);
  int early = 0;
  for (int k = 0; k < 200; ++k) {
    const ConvexShape sa = random_grain(rng, 0.1), sb = random_grain(rng, 0.1);
    const Pose pa{Vector3d::Zero(), random_orientation(rng)};
    const Pose pb{uniform(rng, 2.5, 4.0) * random_unit(rng), random_orientation(rng)};
    const PosedShape a(sa, pa.x, pa.q), b(sb, pb.x, pb.q);
    const ContactManifold m = contact_manifold(a, b, 0.05);
    const CoreDistance full = core_distance(a, b);
    EXPECT_TRUE(m.points.empty());
    EXPECT_GE(m.gap, 0.05);
    EXPECT_LE(m.gap, full.distance - 0.2 + 1e-12);
    early += m.method == DistanceMethod::gjk_far;
  }
  EXPECT_GT(early, 100);
}

// lowest_core_point: the separation of two cores along any unit axis n,
//     s(n) = lowest_core_point(B, n) + lowest_core_point(A, −n),
// never exceeds their signed distance and equals it along the optimal axis: the
// brute-force closest points' direction for disjoint cores, core_distance's SAT normal
// for overlapping ones (the overlap projection skips GJK on this bound).
TEST(ContactDistance, SeparationAlongAnAxisBoundsTheSignedDistance) {
  std::mt19937_64 rng(1123);
  int disjoint = 0, overlapping = 0;
  const auto separation = [](const ConvexShape& sa, const Pose& pa, const ConvexShape& sb, const Pose& pb,
                             const Vector3d& n) {
    return lowest_core_point(sb, pb.x, pb.q, n) + lowest_core_point(sa, pa.x, pa.q, -n);
  };
  for (int k = 0; k < 300; ++k) {
    const ConvexShape sa = random_grain(rng, 0.1), sb = random_grain(rng, 0.1);
    const Pose pa{Vector3d(1.0, -2.0, 3.0), random_orientation(rng)};
    const Pose pb{pa.x + uniform(rng, 0.2, 2.5) * random_unit(rng), random_orientation(rng)};
    const PosedShape a(sa, pa.x, pa.q), b(sb, pb.x, pb.q);
    const CoreDistance cd = core_distance(a, b);
    for (int j = 0; j < 20; ++j) EXPECT_LE(separation(sa, pa, sb, pb, random_unit(rng)), cd.distance + 1e-12);
    const WorldCore A = world_core(sa, pa.x, pa.q), B = world_core(sb, pb.x, pb.q);
    double d_ref;
    Vector3d xa, xb;
    if (core_distance_brute_force(A, B, d_ref, xa, xb)) {
      if (d_ref < 1e-6) continue;  // the direction of nearly touching points is ill-conditioned
      ++disjoint;
      EXPECT_NEAR(separation(sa, pa, sb, pb, (xb - xa) / d_ref), d_ref, 1e-9);
    } else if (cd.method == DistanceMethod::sat) {
      ++overlapping;
      EXPECT_NEAR(separation(sa, pa, sb, pb, cd.normal), cd.distance, 1e-12);
    }
  }
  EXPECT_GT(disjoint, 50);
  EXPECT_GT(overlapping, 50);
}

// Far from the origin the world coordinates carry absolute rounding ~1e-16 × |x|.
TEST(ContactManifold, AccuracyFarFromTheOrigin) {
  const ConvexShape cube = ConvexShape::cube(1.0, 0.1);
  Motion M;
  M.q = Quaterniond(AngleAxisd(0.7, Vector3d(1, 2, 3).normalized()));
  double worst = 0.0;
  for (double far : {1.0, 100.0, 1e4}) {
    M.t = Vector3d(far, -far, 0.5 * far);
    const double g = 0.003;
    const PosedShape a(cube, M.point(Vector3d::Zero()), M.orientation(kIdentity));
    const PosedShape b(cube, M.point({0.2, 0.1, 1.2 + g}), M.orientation(kIdentity));
    const ContactManifold m = contact_manifold(a, b, 0.05);
    ASSERT_EQ(m.points.size(), 4u);
    for (const auto& p : m.points) {
      EXPECT_NEAR(p.gap, g, 1e-14 * far);
      worst = std::max(worst, std::abs(p.gap - g) / far);
    }
  }
  std::printf("  cube pair at |x| up to 1e4: max gap error / |x| = %.2e\n", worst);
}

// A face tilted by less than the angle tolerance still gives the face manifold, with the
// exact gap at every point; tilted by more, the edge or the vertex.
TEST(ContactManifold, TiltedFacesWithinAndBeyondTheAngleTolerance) {
  const ConvexShape cube = ConvexShape::cube(1.0, 0.0);
  const double g = 0.01;
  for (double tilt : {1e-4, 5e-3, 2e-2}) {
    const Quaterniond q(AngleAxisd(tilt, Vector3d::UnitX()));
    // the upper cube's lowest corners: y = −½ side at height zc − (½ cos + ½ sin)
    const double zc = 0.5 + g + 0.5 * (std::cos(tilt) + std::sin(tilt));
    const PosedShape a(cube, Vector3d::Zero(), kIdentity);
    const PosedShape b(cube, Vector3d(0.1, 0.0, zc), q);
    const ContactManifold m = contact_manifold(a, b, 0.05);
    EXPECT_NEAR(m.gap, g, 1e-12);
    if (tilt < 1e-2) {
      ASSERT_EQ(m.points.size(), 4u) << tilt;
      const Matrix3d R = q.toRotationMatrix();
      for (const auto& p : m.points) {
        // the point lies below one of b's bottom corners; its gap is that corner's height
        // above z = ½ if the corner is inside the lower square (x < 0.5 side: clipped)
        const Vector3d x = p.point_b;
        const Vector3d bottom_normal = R * Vector3d(0, 0, -1);
        const double plane = bottom_normal.dot(Vector3d(0.1, 0, zc)) + 0.5;
        // point_b on b's bottom face plane, point_a on z = ½, gap = vertical distance
        EXPECT_NEAR(bottom_normal.dot(x), plane, 1e-12);
        EXPECT_NEAR(p.point_a.z(), 0.5, 1e-12);
        EXPECT_NEAR(p.gap, x.z() - 0.5, 1e-12);
      }
    } else {
      EXPECT_EQ(m.points.size(), 2u) << tilt;
      for (const auto& p : m.points) EXPECT_NEAR(p.gap, g, 1e-12);
    }
  }
}

// ---------------------------------------------------------------------------------------
// Walls

TEST(ContactPlane, CubeOnFloorFlatTiltedAndOnCorner) {
  const ConvexShape cube = ConvexShape::cube(1.0, 0.1);
  const double g = 0.007;
  for (const Motion& M : motions()) {
    const Plane floor{M.point(Vector3d::Zero()), M.vector(Vector3d::UnitZ())};
    {
      const Vector3d c(0.2, -0.1, 0.5 + 0.1 + g);
      const ContactManifold m =
          plane_contact(floor, PosedShape(cube, M.point(c), M.orientation(kIdentity)), 0.05);
      EXPECT_NEAR(m.gap, g, 1e-12);
      std::vector<Vector3d> corners;
      for (double sx : {-0.5, 0.5})
        for (double sy : {-0.5, 0.5}) corners.push_back(M.point({0.2 + sx, -0.1 + sy, g / 2}));
      expect_points(m, corners, 1e-12, "flat");
      for (const auto& p : m.points) EXPECT_NEAR(p.gap, g, 1e-12);
    }
    {  // 30° about x: the edge y = z = −½ is lowest
      const double t = kPi / 6;
      const Quaterniond q(AngleAxisd(t, Vector3d::UnitX()));
      const Vector3d c(0.0, 0.0, 0.5 * (std::cos(t) + std::sin(t)) + 0.1 + g);
      const Vector3d edge_mid = c + q * Vector3d(0, -0.5, -0.5);
      const ContactManifold m =
          plane_contact(floor, PosedShape(cube, M.point(c), M.orientation(q)), 0.05);
      expect_points(m,
                    {M.point(Vector3d(-0.5, edge_mid.y(), g / 2)),
                     M.point(Vector3d(0.5, edge_mid.y(), g / 2))},
                    1e-12, "edge");
      for (const auto& p : m.points) EXPECT_NEAR(p.gap, g, 1e-12);
    }
    {  // on a corner
      const Quaterniond q = Quaterniond::FromTwoVectors(Vector3d(1, 1, 1), Vector3d::UnitZ());
      const Vector3d c(0.3, 0.3, std::sqrt(3.0) / 2 + 0.1 + g);
      const ContactManifold m =
          plane_contact(floor, PosedShape(cube, M.point(c), M.orientation(q)), 0.05);
      expect_points(m, {M.point({0.3, 0.3, g / 2})}, 1e-12, "corner");
      EXPECT_NEAR(m.points[0].gap, g, 1e-12);
    }
    {  // slightly tilted (1e-4 rad, within the tolerance): 4 points, each its own gap
      const Quaterniond q(AngleAxisd(1e-4, Vector3d(1, 2, 0).normalized()));
      const Vector3d c(0.0, 0.0, 0.7);
      const ContactManifold m =
          plane_contact(floor, PosedShape(cube, M.point(c), M.orientation(q)), 0.5);
      ASSERT_EQ(m.points.size(), 4u);
      std::vector<double> expected;
      for (double sx : {-0.5, 0.5})
        for (double sy : {-0.5, 0.5}) expected.push_back((c + q * Vector3d(sx, sy, -0.5)).z() - 0.1);
      std::sort(expected.begin(), expected.end());
      std::vector<double> got;
      for (const auto& p : m.points) got.push_back(p.gap);
      std::sort(got.begin(), got.end());
      for (int i = 0; i < 4; ++i) EXPECT_NEAR(got[i], expected[i], 1e-12);
      EXPECT_NEAR(m.gap, expected[0], 1e-12);
    }
    {  // far away: no points, and the gap
      const ContactManifold m = plane_contact(
          floor, PosedShape(cube, M.point({0, 0, 2.0}), M.orientation(kIdentity)), 0.05);
      EXPECT_TRUE(m.points.empty());
      EXPECT_NEAR(m.gap, 1.4, 1e-12);
    }
  }
}

// ContactOptions::near_vertices on a tumbling cube over a wall: besides the lowest edge,
// every vertex whose own gap n·(v − p) − r is below the activation distance and within
// the near-vertex slab (a tenth of the core radius, √3/2 here), none other.
TEST(ContactPlane, NearVerticesOfATumblingCube) {
  const ConvexShape cube = ConvexShape::cube(1.0, 0.1);
  const double g = 0.007, t = 0.05;  // tilt about x: edge y = z = −½ lowest, the other
                                     // bottom edge sin t = 0.05 higher, the top ones ~1
  const double slab = 0.1 * std::sqrt(3.0) / 2;
  const Quaterniond q(AngleAxisd(t, Vector3d::UnitX()));
  ContactOptions near;
  near.near_vertices = true;
  for (const Motion& M : motions()) {
    const Plane floor{M.point(Vector3d::Zero()), M.vector(Vector3d::UnitZ())};
    const Vector3d c(0.1, 0.2, 0.5 * (std::cos(t) + std::sin(t)) + 0.1 + g);
    const PosedShape posed(cube, M.point(c), M.orientation(q));
    for (double activation : {0.03, 0.07, 1.2}) {
      std::vector<double> expected;
      for (double sx : {-0.5, 0.5})
        for (double sy : {-0.5, 0.5})
          for (double sz : {-0.5, 0.5}) {
            const double gap = (c + q * Vector3d(sx, sy, sz)).z() - 0.1;
            const bool lowest_edge = sy < 0 && sz < 0;
            if (gap < activation && (lowest_edge || gap < slab)) expected.push_back(gap);
          }
      std::sort(expected.begin(), expected.end());
      const ContactManifold m = plane_contact(floor, posed, activation, near);
      std::vector<double> got;
      for (const auto& p : m.points) {
        got.push_back(p.gap);
        EXPECT_LT((p.normal - M.vector(Vector3d::UnitZ())).norm(), 1e-12);
      }
      std::sort(got.begin(), got.end());
      ASSERT_EQ(got.size(), expected.size()) << "activation " << activation;
      for (size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], expected[i], 1e-12);
      EXPECT_EQ(plane_contact(floor, posed, activation).points.size(), 2u);  // option off
    }
  }
}

// ContactOptions::near_vertices between grains: a cube B tumbling onto a slab A, over its
// face, over its edge and with two vertices inside it. Reference: the distance of each
// vertex of B to the slab's core, a box, by clamping the coordinates (inside: the
// nearest face), minus the radii. Every vertex of B whose gap is below the activation
// distance has a point at that vertex with that gap and the normal along the closest
// points; no point has a gap below the pair's.
TEST(ContactManifold, NearVerticesOfACubeTumblingOntoASlab) {
  const ConvexShape slab = ConvexShape::box(10.0, 10.0, 1.0, 0.1), cube = ConvexShape::cube(1.0, 0.05);
  const Vector3d half(5.0, 5.0, 0.5);
  ContactOptions near;
  near.near_vertices = true;
  struct Case {
    Quaterniond q;
    double x;        // of the cube's centre: 0 over the face, 4.9 across the edge x = 5
    double lowest;   // core height of the cube's lowest vertex above the slab's core
    double activation;
  };
  const Quaterniond tumble(AngleAxisd(0.35, Vector3d::UnitX()));
  const Quaterniond twisted = Quaterniond(AngleAxisd(0.05, Vector3d::UnitY())) * tumble;
  for (const Case& k : {Case{tumble, 0.0, 0.16, 0.4}, Case{tumble, 4.9, 0.16, 0.6},
                        Case{twisted, 0.0, -0.08, 0.2}}) {
    for (const Motion& M : motions()) {
      double lowest = kInf;
      for (double sx : {-0.5, 0.5})
        for (double sy : {-0.5, 0.5})
          for (double sz : {-0.5, 0.5}) lowest = std::min(lowest, (k.q * Vector3d(sx, sy, sz)).z());
      const Vector3d c(k.x, 0.0, 0.5 + k.lowest - lowest);
      const PosedShape a(slab, M.point(Vector3d::Zero()), M.orientation(kIdentity));
      const PosedShape b(cube, M.point(c), M.orientation(k.q));
      const ContactManifold m = contact_manifold(a, b, k.activation, near);
      ASSERT_FALSE(m.points.empty());
      for (const auto& p : m.points) EXPECT_GE(p.gap, m.gap - 1e-12);
      int near_count = 0;
      for (double sx : {-0.5, 0.5})
        for (double sy : {-0.5, 0.5})
          for (double sz : {-0.5, 0.5}) {
            const Vector3d v = c + k.q * Vector3d(sx, sy, sz);
            const Vector3d clamped = v.cwiseMax(-half).cwiseMin(half);
            double core_gap;
            Vector3d normal;
            if ((v - clamped).norm() > 0.0) {
              core_gap = (v - clamped).norm();
              normal = (v - clamped) / core_gap;
            } else {  // inside: the nearest face (here the top one)
              core_gap = -(half.z() - v.z());
              normal = Vector3d::UnitZ();
            }
            const double gap = core_gap - 0.15;
            if (!(gap < k.activation)) continue;
            ++near_count;
            const Vector3d on_b = M.point(v - 0.05 * normal);
            double best = kInf;
            const ContactPoint* found = nullptr;
            for (const auto& p : m.points)
              if ((p.point_b - on_b).norm() < best) {
                best = (p.point_b - on_b).norm();
                found = &p;
              }
            ASSERT_LT(best, 1e-12) << "vertex " << v.transpose() << " x " << k.x;
            EXPECT_NEAR(found->gap, gap, 1e-12);
            EXPECT_LT((found->normal - M.vector(normal)).norm(), 1e-9);
          }
      EXPECT_GE(near_count, 3) << "x " << k.x;  // the case reaches beyond the closest feature
    }
  }
}

TEST(ContactPlane, RandomGrainLowestVertexGap) {
  std::mt19937_64 rng(31);
  for (int k = 0; k < 200; ++k) {
    const ConvexShape s = random_grain(rng, 0.1);
    const Pose p{Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)),
                 random_orientation(rng)};
    const Plane wall{Vector3d(uniform(rng, -1, 1), 0, 0), random_unit(rng)};
    const WorldCore c = world_core(s, p.x, p.q);
    double lowest = kInf;
    for (const auto& v : c.vertices) lowest = std::min(lowest, wall.normal.dot(v - wall.point));
    const ContactManifold m = plane_contact(wall, PosedShape(s, p.x, p.q), kInf);
    EXPECT_NEAR(m.gap, lowest - 0.1, 1e-12);
    ASSERT_FALSE(m.points.empty());
    double deepest = kInf;
    for (const auto& q : m.points) deepest = std::min(deepest, q.gap);
    EXPECT_NEAR(deepest, lowest - 0.1, 1e-12);
  }
}

// ---------------------------------------------------------------------------------------
// Wire segments

// Minimum over the segment of the exact point–core distance: dense sampling, then a
// golden-section search on the bracket of the best sample (the distance to a convex set
// is convex along a line). Returns the distance and the parameter.
double segment_core_reference(const WorldCore& c, const Vector3d& p0, const Vector3d& p1,
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

// Random segments around random grains: general, parallel to a face, parallel to an
// edge, touching the core (distance 0), at gap 0, and penetrating.
TEST(SegmentPolyhedron, RandomSegmentsMatchSampling) {
  std::mt19937_64 rng(1234);
  const double r_w = 0.1;
  ErrorStats dist_err, point_err, depth_err;
  std::array<int, 6> kinds{};
  for (int k = 0; k < 1500; ++k) {
    const ConvexShape s = random_grain(rng, 0.1);
    const Pose pose{Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)),
                    random_orientation(rng)};
    const WorldCore c = world_core(s, pose.x, pose.q);
    const PosedShape grain(s, pose.x, pose.q);
    const int kind = k % 6;
    Vector3d p0, p1;
    const double length = uniform(rng, 0.05, 0.6);
    const double height = kind == 3 ? 0.0 : (kind == 4 ? 0.1 + r_w : uniform(rng, 1e-4, 0.8));
    if (kind == 0) {  // anywhere around
      p0 = pose.x + uniform(rng, 0.5, 2.0) * random_unit(rng);
      p1 = p0 + length * random_unit(rng);
    } else if (kind == 1 || kind == 3 || kind == 4) {  // parallel to a face, above it
      const auto& f = s.faces()[std::uniform_int_distribution<int>(
          0, static_cast<int>(s.faces().size()) - 1)(rng)];
      Vector3d inside = Vector3d::Zero();
      double wsum = 0.0;
      for (int v : f.vertices) {
        const double w = uniform(rng, 0.1, 1.0);
        inside += w * c.vertices[v];
        wsum += w;
      }
      inside /= wsum;
      const Vector3d n = pose.q * f.normal;
      const Vector3d along = (random_unit(rng).cross(n)).normalized();
      const Vector3d mid = inside + height * n + uniform(rng, -0.2, 0.2) * along;
      p0 = mid - 0.5 * length * along;
      p1 = mid + 0.5 * length * along;
    } else if (kind == 2) {  // parallel to an edge, in its normal cone
      const auto& e = s.edges()[std::uniform_int_distribution<int>(
          0, static_cast<int>(s.edges().size()) - 1)(rng)];
      const Vector3d a = c.vertices[e[0]], b = c.vertices[e[1]];
      // the two faces of the edge
      std::vector<Vector3d> normals;
      for (std::size_t f = 0; f < s.faces().size(); ++f) {
        const auto& loop = s.faces()[f].vertices;
        const bool has0 = std::find(loop.begin(), loop.end(), e[0]) != loop.end();
        const bool has1 = std::find(loop.begin(), loop.end(), e[1]) != loop.end();
        if (has0 && has1) normals.push_back(c.normals[f]);
      }
      ASSERT_EQ(normals.size(), 2u);
      const double w = uniform(rng, 0.0, 1.0);
      const Vector3d out = (w * normals[0] + (1 - w) * normals[1]).normalized();
      const Vector3d dir = (b - a).normalized();
      const Vector3d mid = a + uniform(rng, -0.2, 1.2) * (b - a) + height * out;
      p0 = mid - 0.5 * length * dir;
      p1 = mid + 0.5 * length * dir;
    } else {  // kind 5: through the core
      p0 = pose.x + uniform(rng, 0.0, 0.3) * random_unit(rng);
      p1 = p0 + length * random_unit(rng);
    }
    if (k % 2 == 1) std::swap(p0, p1);
    ++kinds[kind];

    const SegmentContact sc = segment_contact(grain, p0, p1, r_w);
    double t_ref;
    const double d_ref = segment_core_reference(c, p0, p1, t_ref);
    EXPECT_NEAR(sc.gap, sc.distance - 0.1 - r_w, 1e-15);
    EXPECT_NEAR(sc.normal.norm(), 1.0, 1e-12);
    EXPECT_GE(sc.t, 0.0);
    EXPECT_LE(sc.t, 1.0);
    EXPECT_LT((sc.point_on_segment - (p0 + sc.t * (p1 - p0))).norm(), 1e-12);
    if (d_ref > 0.0) {
      dist_err.add(std::abs(sc.distance - d_ref));
      EXPECT_NEAR(sc.distance, d_ref, 1e-10 * d_ref + 1e-14) << "kind " << kind;  // 1e-10 relative
      // the reported points: on the core, and (unless the interval rule moved them along
      // a parallel face or edge) at the distance; the segment point is at least as far
      const double on_core = std::abs(plane_excess(c, sc.point_on_core));
      EXPECT_LT(on_core, 1e-9);
      const double at = point_core_distance(c, sc.point_on_segment);
      const double slack = (sc.t_end - sc.t_begin) * length * std::sin(1e-2);
      point_err.add(std::max(on_core, at - d_ref - slack));
      EXPECT_LE(at, d_ref + slack + 1e-9);
    } else {
      // the axis touches or enters the core: minus the depth of P − S's hull
      std::vector<Vector3d> ends = {p0, p1};
      double depth, second;
      Vector3d normal;
      if (penetration_from_minkowski_hull(c.vertices, ends, depth, normal, second)) {
        depth_err.add(std::abs(sc.distance + depth));
        EXPECT_NEAR(sc.distance, -depth, 1e-9);
      } else {
        EXPECT_NEAR(sc.distance, 0.0, 1e-9);  // touching the surface
      }
    }
  }
  std::printf("  segments (general %d, face-parallel %d, edge-parallel %d, on the surface %d, "
              "gap 0 %d, through %d): distance error %.2e (%d disjoint), points %.2e, depth "
              "error %.2e (%d)\n",
              kinds[0], kinds[1], kinds[2], kinds[3], kinds[4], kinds[5], dist_err.max,
              dist_err.count, point_err.max, depth_err.max, depth_err.count);
  EXPECT_GE(dist_err.count, 1000);
}

TEST(SegmentPolyhedron, CubeAnalyticCases) {
  const ConvexShape cube = ConvexShape::cube(1.0, 0.1);
  const double r_w = 0.05;
  for (const Motion& M : motions()) {
    const PosedShape grain(cube, M.point(Vector3d::Zero()), M.orientation(kIdentity));
    {  // parallel to the top face, overhanging its edge x = ½: interval [0, 0.75]
      const Vector3d p0(0.2, 0.1, 0.8), p1(1.0, 0.1, 0.8);
      const SegmentContact sc = segment_contact(grain, M.point(p0), M.point(p1), r_w);
      EXPECT_NEAR(sc.distance, 0.3, 1e-12);
      EXPECT_NEAR(sc.gap, 0.3 - 0.15, 1e-12);
      EXPECT_LT((sc.normal - M.vector(Vector3d::UnitZ())).norm(), 1e-12);
      EXPECT_NEAR(sc.t_begin, 0.0, 1e-12);
      EXPECT_NEAR(sc.t_end, 0.375, 1e-12);
      EXPECT_NEAR(sc.t, 0.1875, 1e-12);
      EXPECT_LT((sc.point_on_core - M.point({0.35, 0.1, 0.5})).norm(), 1e-12);
    }
    {  // parallel to the edge (x = ½, z = ½) along y, offset diagonally: interval [0, 0.8]
      const Vector3d p0(0.5 + 0.2, -0.3, 0.5 + 0.2), p1(0.5 + 0.2, 0.7, 0.5 + 0.2);
      const SegmentContact sc = segment_contact(grain, M.point(p0), M.point(p1), r_w);
      EXPECT_NEAR(sc.distance, 0.2 * std::sqrt(2.0), 1e-12);
      EXPECT_LT((sc.normal - M.vector(Vector3d(1, 0, 1).normalized())).norm(), 1e-12);
      EXPECT_NEAR(sc.t_begin, 0.0, 1e-12);
      EXPECT_NEAR(sc.t_end, 0.8, 1e-12);
    }
    {  // crossing over the edge (x = ½, z = ½) at right angles: one point, t = 0.25
      // the line x + z = 1.2 (y = 0.2) is nearest to the edge point (½, 0.2, ½) at
      // x = z = 0.6
      const Vector3d p0(0.3, 0.2, 0.9), p1(1.1, 0.2, 0.1);
      const SegmentContact sc = segment_contact(grain, M.point(p0), M.point(p1), r_w);
      EXPECT_NEAR(sc.distance, 0.1 * std::sqrt(2.0), 1e-12);
      EXPECT_NEAR(sc.t, 0.375, 1e-12);
      EXPECT_EQ(sc.t_begin, sc.t_end);
      EXPECT_LT((sc.point_on_core - M.point({0.5, 0.2, 0.5})).norm(), 1e-12);
    }
    {  // end on the face centre line, vertical: t at the lower end
      const SegmentContact sc =
          segment_contact(grain, M.point({0.1, 0.1, 1.0}), M.point({0.1, 0.1, 0.6}), r_w);
      EXPECT_NEAR(sc.distance, 0.1, 1e-12);
      EXPECT_NEAR(sc.t, 1.0, 1e-12);
    }
    {  // inside the core, parallel to the top face at depth 0.1: penetration
      const SegmentContact sc =
          segment_contact(grain, M.point({-0.2, 0.0, 0.4}), M.point({0.2, 0.0, 0.4}), r_w);
      EXPECT_EQ(sc.method, DistanceMethod::sat);
      EXPECT_NEAR(sc.distance, -0.1, 1e-12);
      EXPECT_LT((sc.normal - M.vector(Vector3d::UnitZ())).norm(), 1e-12);
      EXPECT_NEAR(sc.t, 0.5, 1e-12);
      EXPECT_LT((sc.point_on_core - M.point({0.0, 0.0, 0.5})).norm(), 1e-12);
    }
    {  // a point (zero-length segment) above a corner
      const Vector3d x(0.6, 0.7, 0.8);
      const SegmentContact sc = segment_contact(grain, M.point(x), M.point(x), r_w);
      EXPECT_NEAR(sc.distance, Vector3d(0.1, 0.2, 0.3).norm(), 1e-12);
      EXPECT_EQ(sc.t, 0.0);
    }
  }
}

// ---------------------------------------------------------------------------------------
// Spheres: the one-vertex core, against closed forms

// Two spheres: core distance |c2 − c1| along (c2 − c1)/|c2 − c1|, one contact point
// with the surface points c1 + r1 n and c2 − r2 n; random centres and radii, gaps of
// both signs (cores disjoint), and coincident centres (depth 0, normal +x).
TEST(ContactSphere, SphereSphereClosedForm) {
  std::mt19937_64 rng(41);
  for (int k = 0; k < 300; ++k) {
    const double r1 = uniform(rng, 0.05, 1.0), r2 = uniform(rng, 0.05, 1.0);
    const ConvexShape s1 = ConvexShape::sphere(r1), s2 = ConvexShape::sphere(r2);
    const Vector3d c1(uniform(rng, -3, 3), uniform(rng, -3, 3), uniform(rng, -3, 3));
    const Vector3d d = uniform(rng, 0.01, 3.0) * random_unit(rng);
    const Vector3d c2 = c1 + d;
    const PosedShape a(s1, c1, random_orientation(rng)), b(s2, c2, random_orientation(rng));
    const double distance = d.norm();
    const Vector3d n = d / distance;
    const CoreDistance cd = core_distance(a, b);
    EXPECT_EQ(cd.method, DistanceMethod::gjk);
    EXPECT_NEAR(cd.distance, distance, 1e-14);
    EXPECT_LT((cd.normal - n).norm(), 1e-12);
    const ContactManifold m = contact_manifold(a, b, kInf);
    EXPECT_NEAR(m.gap, distance - r1 - r2, 1e-14);
    EXPECT_EQ(m.feature_a.kind, FeatureKind::vertex);
    EXPECT_EQ(m.feature_b.kind, FeatureKind::vertex);
    ASSERT_EQ(m.points.size(), 1u);
    EXPECT_NEAR(m.points[0].gap, distance - r1 - r2, 1e-14);
    EXPECT_LT((m.points[0].point_a - (c1 + r1 * n)).norm(), 1e-13);
    EXPECT_LT((m.points[0].point_b - (c2 - r2 * n)).norm(), 1e-13);
    // swapped: the same distance, the normal reversed
    EXPECT_LT((core_distance(b, a).normal + n).norm(), 1e-12);
    // not within reach: no point
    EXPECT_EQ(contact_manifold(a, b, distance - r1 - r2 - 1e-3).points.size(), 0u);
  }
  const ConvexShape s1 = ConvexShape::sphere(0.3), s2 = ConvexShape::sphere(0.5);
  const Vector3d c(1.0, -2.0, 0.25);
  const PosedShape a(s1, c, kIdentity), b(s2, c, kIdentity);
  const CoreDistance cd = core_distance(a, b);
  EXPECT_EQ(cd.method, DistanceMethod::sat);
  EXPECT_EQ(cd.distance, 0.0);
  EXPECT_EQ(cd.normal, Vector3d::UnitX());
  const ContactManifold m = contact_manifold(a, b, 0.0);
  EXPECT_EQ(m.gap, -0.8);
  ASSERT_EQ(m.points.size(), 1u);
  EXPECT_EQ(m.points[0].point_a, c + Vector3d(0.3, 0, 0));
  EXPECT_EQ(m.points[0].point_b, c - Vector3d(0.5, 0, 0));
}

// A sphere (radius 0.3) by a unit cube (sweep 0.1): the distance from the centre to the
// nearest face, edge or corner of the cube, in closed form, in both orders and under
// rigid motions; inside the core, the depth below the nearest face.
TEST(ContactSphere, SphereCubeFaceEdgeCornerAndInside) {
  const ConvexShape cube = ConvexShape::cube(1.0, 0.1);
  const ConvexShape ball = ConvexShape::sphere(0.3);
  struct Case {
    const char* name;
    Vector3d centre;     // cube frame
    double distance;     // signed core distance
    Vector3d normal;     // from the cube to the sphere
    Vector3d on_cube;    // nearest (deepest) core point of the cube
  };
  const double s = std::sqrt(0.2 * 0.2 + 0.3 * 0.3 + 0.6 * 0.6);  // = 0.7
  const std::vector<Case> cases = {
      {"face", {0.2, -0.1, 0.9}, 0.4, Vector3d::UnitZ(), {0.2, -0.1, 0.5}},
      {"edge", {0.8, 0.1, 0.9}, 0.5, Vector3d(0.6, 0, 0.8), {0.5, 0.1, 0.5}},
      {"corner", {0.7, 0.8, 1.1}, s, Vector3d(0.2, 0.3, 0.6) / s, {0.5, 0.5, 0.5}},
      {"on the face", {0.1, 0.2, 0.5}, 0.0, Vector3d::UnitZ(), {0.1, 0.2, 0.5}},
      {"inside", {0.1, 0.2, 0.4}, -0.1, Vector3d::UnitZ(), {0.1, 0.2, 0.5}},
      {"inside, near -y", {0.05, -0.35, -0.2}, -0.15, -Vector3d::UnitY(), {0.05, -0.5, -0.2}},
  };
  for (const Motion& M : motions()) {
    for (const Case& c : cases) {
      const PosedShape box(cube, M.point(Vector3d::Zero()), M.orientation(kIdentity));
      const PosedShape sphere(ball, M.point(c.centre), M.orientation(kIdentity));
      const Vector3d n = M.vector(c.normal);
      const double gap = c.distance - 0.4;
      {  // cube as A
        const CoreDistance cd = core_distance(box, sphere);
        EXPECT_NEAR(cd.distance, c.distance, 1e-12) << c.name;
        EXPECT_LT((cd.normal - n).norm(), 1e-12) << c.name;
        if (c.distance != 0.0) EXPECT_EQ(cd.overlapping(), c.distance < 0.0) << c.name;
        const ContactManifold m = contact_manifold(box, sphere, kInf);
        EXPECT_NEAR(m.gap, gap, 1e-12) << c.name;
        EXPECT_EQ(m.feature_b.kind, FeatureKind::vertex) << c.name;
        ASSERT_EQ(m.points.size(), 1u) << c.name;
        EXPECT_NEAR(m.points[0].gap, gap, 1e-12) << c.name;
        EXPECT_LT((m.points[0].point_a - M.point(c.on_cube + 0.1 * c.normal)).norm(), 1e-12) << c.name;
        EXPECT_LT((m.points[0].point_b - M.point(c.centre - 0.3 * c.normal)).norm(), 1e-12) << c.name;
      }
      {  // sphere as A: the same distance, the normal reversed
        const CoreDistance cd = core_distance(sphere, box);
        EXPECT_NEAR(cd.distance, c.distance, 1e-12) << c.name;
        EXPECT_LT((cd.normal + n).norm(), 1e-12) << c.name;
        const ContactManifold m = contact_manifold(sphere, box, kInf);
        EXPECT_NEAR(m.gap, gap, 1e-12) << c.name;
        EXPECT_EQ(m.feature_a.kind, FeatureKind::vertex) << c.name;
        ASSERT_EQ(m.points.size(), 1u) << c.name;
        EXPECT_LT((m.points[0].point_a - M.point(c.centre - 0.3 * c.normal)).norm(), 1e-12) << c.name;
        EXPECT_LT((m.points[0].point_b - M.point(c.on_cube + 0.1 * c.normal)).norm(), 1e-12) << c.name;
      }
    }
  }
}

// A sphere and a wall: gap = height of the centre − radius, one point below the centre.
TEST(ContactSphere, SphereOnAPlane) {
  const ConvexShape ball = ConvexShape::sphere(0.4);
  const Quaterniond turned(AngleAxisd(0.7, Vector3d(1, 2, 3).normalized()));  // irrelevant for a sphere
  for (const Motion& M : motions()) {
    const Plane floor{M.point(Vector3d::Zero()), M.vector(Vector3d::UnitZ())};
    for (double h : {0.45, 0.4, 0.3, -0.1}) {
      const Vector3d c(0.2, -0.7, h);
      const ContactManifold m = plane_contact(floor, PosedShape(ball, M.point(c), turned), 0.1);
      EXPECT_NEAR(m.core_distance, h, 1e-12);
      EXPECT_NEAR(m.gap, h - 0.4, 1e-12);
      EXPECT_EQ(m.feature_b.kind, FeatureKind::vertex);
      ASSERT_EQ(m.points.size(), 1u);
      EXPECT_LT((m.points[0].point_a - M.point({0.2, -0.7, 0.0})).norm(), 1e-12);
      EXPECT_LT((m.points[0].point_b - M.point({0.2, -0.7, h - 0.4})).norm(), 1e-12);
      EXPECT_LT((m.points[0].normal - floor.normal).norm(), 1e-15);
    }
    EXPECT_TRUE(plane_contact(floor, PosedShape(ball, M.point({0, 0, 0.6}), kIdentity), 0.1).points.empty());
  }
}

// A wire segment by a sphere: the distance from the centre to the segment (closed form:
// the foot of the perpendicular, clamped to the ends), its point and parameter.
TEST(ContactSphere, SegmentSphereMatchesPointSegmentDistance) {
  std::mt19937_64 rng(43);
  const double r_w = 0.05;
  int checked = 0;
  for (int k = 0; k < 500; ++k) {
    const double R = uniform(rng, 0.1, 1.0);
    const ConvexShape ball = ConvexShape::sphere(R);
    const Vector3d c(uniform(rng, -2, 2), uniform(rng, -2, 2), uniform(rng, -2, 2));
    const Vector3d e0 = c + uniform(rng, 0.0, 2.0) * random_unit(rng);
    const Vector3d e1 = e0 + uniform(rng, 0.05, 1.0) * random_unit(rng);
    const Vector3d foot = closest_on_segment(c, e0, e1);
    const double distance = (foot - c).norm();
    if (distance < 1e-3) continue;
    ++checked;
    const SegmentContact sc = segment_contact(PosedShape(ball, c, random_orientation(rng)), e0, e1, r_w);
    EXPECT_NEAR(sc.distance, distance, 1e-13);
    EXPECT_NEAR(sc.gap, distance - R - r_w, 1e-13);
    EXPECT_LT((sc.normal - (foot - c) / distance).norm(), 1e-11);
    EXPECT_LT((sc.point_on_core - c).norm(), 1e-14);
    EXPECT_LT((sc.point_on_segment - foot).norm(), 1e-12);
    EXPECT_LT((e0 + sc.t * (e1 - e0) - foot).norm(), 1e-12);
    EXPECT_EQ(sc.t_begin, sc.t);
    EXPECT_EQ(sc.t_end, sc.t);
  }
  EXPECT_GT(checked, 450);
}

// A segment whose axis passes through the centre: distance 0, overlap R + r_w, a unit
// normal ⟂ the segment: for exactly representable cases the documented one, e_k × ŝ
// normalised with e_k the axis least aligned with ŝ (the first of ties); for random
// directions (the centre on the line only to rounding) any unit vector ⟂ ŝ.
TEST(ContactSphere, SegmentThroughTheCentre) {
  const double R = 0.4, r_w = 0.05;
  const ConvexShape ball = ConvexShape::sphere(R);
  const Vector3d c(1.0, 2.0, 3.0);
  const PosedShape sphere(ball, c, kIdentity);
  {  // along x, t = 0.25: e_y is the first least aligned axis, e_y × e_x = −e_z
    const SegmentContact sc = segment_contact(sphere, c - Vector3d(0.5, 0, 0), c + Vector3d(1.5, 0, 0), r_w);
    EXPECT_EQ(sc.method, DistanceMethod::sat);
    EXPECT_EQ(sc.distance, 0.0);
    EXPECT_EQ(sc.gap, -(R + r_w));
    EXPECT_EQ(sc.normal, -Vector3d::UnitZ());
    EXPECT_EQ(sc.point_on_core, c);
    EXPECT_LT((sc.point_on_segment - c).norm(), 1e-15);
    EXPECT_NEAR(sc.t, 0.25, 1e-15);
  }
  {  // downwards, ŝ = −e_z: e_x × (−e_z) = e_y
    const SegmentContact sc = segment_contact(sphere, c + Vector3d(0, 0, 0.5), c - Vector3d(0, 0, 0.5), r_w);
    EXPECT_EQ(sc.distance, 0.0);
    EXPECT_EQ(sc.normal, Vector3d::UnitY());
    EXPECT_NEAR(sc.t, 0.5, 1e-15);
  }
  {  // along (0, 3, 4)/5: e_x × ŝ = (0, −4, 3)/5
    const SegmentContact sc = segment_contact(sphere, c - Vector3d(0, 0.3, 0.4), c + Vector3d(0, 0.6, 0.8), r_w);
    EXPECT_NEAR(sc.distance, 0.0, 1e-15);
    EXPECT_NEAR(sc.gap, -(R + r_w), 1e-15);
    EXPECT_LT((sc.normal - Vector3d(0, -0.8, 0.6)).norm(), 1e-15);
    EXPECT_NEAR(sc.t, 1.0 / 3.0, 1e-15);
  }
  std::mt19937_64 rng(44);
  for (int k = 0; k < 200; ++k) {
    const Vector3d centre(uniform(rng, -3, 3), uniform(rng, -3, 3), uniform(rng, -3, 3));
    const Vector3d u = random_unit(rng);
    const double before = uniform(rng, 0.01, 1.0), after = uniform(rng, 0.01, 1.0);
    const SegmentContact sc =
        segment_contact(PosedShape(ball, centre, kIdentity), centre - before * u, centre + after * u, r_w);
    EXPECT_NEAR(sc.distance, 0.0, 1e-14);
    EXPECT_NEAR(sc.gap, -(R + r_w), 1e-14);
    EXPECT_NEAR(sc.normal.norm(), 1.0, 1e-15);
    EXPECT_LT(std::abs(sc.normal.dot(u)), 1e-12);
    EXPECT_LT((sc.point_on_segment - centre).norm(), 1e-14);
    EXPECT_NEAR(sc.t, before / (before + after), 1e-13);
  }
  {  // on the axis line beyond an end: the distance to that end, along the axis
    const SegmentContact sc = segment_contact(sphere, c + Vector3d(0.2, 0, 0), c + Vector3d(1.2, 0, 0), r_w);
    EXPECT_NEAR(sc.distance, 0.2, 1e-15);
    EXPECT_LT((sc.normal - Vector3d::UnitX()).norm(), 1e-15);
    EXPECT_EQ(sc.t, 0.0);
  }
  {  // a zero-length segment at the centre: a point, normal +x
    const SegmentContact sc = segment_contact(sphere, c, c, r_w);
    EXPECT_EQ(sc.distance, 0.0);
    EXPECT_EQ(sc.normal, Vector3d::UnitX());
    EXPECT_EQ(sc.gap, -(R + r_w));
  }
}

// ---------------------------------------------------------------------------------------
// Input checks

TEST(ContactGeometryErrors, BadInputsNameTheArgument) {
  const ConvexShape cube = ConvexShape::cube(1.0, 0.1);
  const auto argument_of = [](auto&& call) {
    try {
      call();
    } catch (const InvalidArgument& e) {
      return e.argument();
    }
    return std::string("(none)");
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const PosedShape a(cube, Vector3d::Zero(), kIdentity);
  const PosedShape b(cube, Vector3d(0, 0, 1.3), kIdentity);
  EXPECT_EQ(argument_of([&] { PosedShape(cube, Vector3d(nan, 0, 0), kIdentity); }), "position");
  EXPECT_EQ(argument_of([&] { PosedShape(cube, Vector3d::Zero(), Quaterniond(0, 0, 0, 0)); }),
            "orientation");
  EXPECT_EQ(argument_of([&] { contact_manifold(a, b, nan); }), "activation_distance");
  EXPECT_EQ(argument_of([&] { core_distance(a, b, -1.0); }), "early_exit_distance");
  ContactOptions bad;
  bad.angle_tolerance = -1;
  EXPECT_EQ(argument_of([&] { contact_manifold(a, b, 0.1, bad); }), "angle_tolerance");
  bad = ContactOptions();
  bad.max_points = -2;
  EXPECT_EQ(argument_of([&] { contact_manifold(a, b, 0.1, bad); }), "max_points");
  EXPECT_EQ(argument_of([&] { plane_contact(Plane{Vector3d::Zero(), Vector3d::Zero()}, a, 0.1); }),
            "wall.normal");
  EXPECT_EQ(argument_of([&] { segment_contact(a, Vector3d::Zero(), Vector3d::UnitX(), -0.1); }),
            "wire_radius");
  EXPECT_EQ(argument_of([&] { segment_contact(a, Vector3d(nan, 0, 0), Vector3d::UnitX(), 0.1); }),
            "end0");
  // a non-unit quaternion is normalised
  const PosedShape scaled(cube, Vector3d(0, 0, 1.3), Quaterniond(2, 0, 0, 0));
  EXPECT_NEAR(contact_manifold(a, scaled, 0.1).gap, 0.1, 1e-12);
}

}  // namespace

// feature_gap_limit: pairs farther apart than the limit keep the exact distance, normal
// and GJK's closest points (the same as with the full lookup, for a segment crossing
// over an edge: a single closest point), and lose only the parallel interval.
TEST(SegmentPolyhedron, FeatureGapLimitKeepsDistancesAndClosestPoints) {
  const ConvexShape cube = ConvexShape::cube(1.0, 0.1);
  const PosedShape grain(cube, Vector3d::Zero(), Eigen::Quaterniond::Identity());
  ContactOptions gap_only;
  gap_only.feature_gap_limit = 0.0;
  const double r_w = 0.02;
  {  // crossing over the edge (x = ½, z = ½) at right angles, apart
    const Vector3d p0(0.3, 0.2, 0.9), p1(1.1, 0.2, 0.1);
    const SegmentContact full = segment_contact(grain, p0, p1, r_w);
    const SegmentContact fast = segment_contact(grain, p0, p1, r_w, gap_only);
    EXPECT_GT(full.gap, 0.0);
    EXPECT_NEAR(fast.distance, 0.1 * std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(fast.gap, full.gap, 1e-15);
    EXPECT_LT((fast.normal - full.normal).norm(), 1e-12);
    EXPECT_NEAR(fast.t, 0.375, 1e-12);
    EXPECT_LT((fast.point_on_core - Vector3d(0.5, 0.2, 0.5)).norm(), 1e-12);
  }
  {  // parallel to the top face, apart: the interval [0, 0.375] only with the full lookup
    const Vector3d p0(0.2, 0.1, 0.8), p1(1.0, 0.1, 0.8);
    const SegmentContact full = segment_contact(grain, p0, p1, r_w);
    const SegmentContact fast = segment_contact(grain, p0, p1, r_w, gap_only);
    EXPECT_NEAR(fast.distance, 0.3, 1e-12);
    EXPECT_NEAR(full.t_end, 0.375, 1e-12);
    EXPECT_EQ(fast.t_begin, fast.t_end);
  }
  {  // touching (gap < 0): the limit does not apply, the interval is there
    const Vector3d p0(0.2, 0.1, 0.6), p1(1.0, 0.1, 0.6);
    const SegmentContact fast = segment_contact(grain, p0, p1, r_w, gap_only);
    EXPECT_LT(fast.gap, 0.0);
    EXPECT_NEAR(fast.t_end, 0.375, 1e-12);
  }
}

// Two unit cubes stacked face on face, tilted by ~1e-13 rad (the pose reached by the 79th
// and 80th boxes of a 100-box stack after 377 steps, bench/nscd_stack): the manifold is
// the four corners of the common face with the vertical normal, and every normal is
// finite (it was NaN: parallel vertical edges of the two cubes along the normal).
TEST(ContactManifold, NearlyAlignedStackedCubesGiveFiniteNormals) {
  const ConvexShape cube = ConvexShape::cube(1.0);
  const PosedShape a(cube, Vector3d(-1.116220222764176e-11, 3.9193682649784572e-12, 78.500000000000412),
                     Quaterniond(1, 4.9932801647295658e-13, -1.3124828810540053e-13, -3.3622917882442687e-15).normalized());
  const PosedShape b(cube, Vector3d(-1.1198556209923648e-11, 4.5188922851255296e-12, 79.500000000000426),
                     Quaterniond(1, 3.2661069140543906e-13, -2.34396231224576e-13, -1.3164640659096194e-14).normalized());
  const ContactManifold m = contact_manifold(a, b, 1e-3);
  ASSERT_EQ(m.points.size(), 4u);
  for (const ContactPoint& p : m.points) {
    EXPECT_TRUE(p.normal.allFinite());
    EXPECT_NEAR((p.normal - Vector3d::UnitZ()).norm(), 0.0, 1e-9);
    EXPECT_NEAR(p.gap, 0.0, 1e-9);
    EXPECT_NEAR(std::fabs(p.position.x()), 0.5, 1e-9);
    EXPECT_NEAR(std::fabs(p.position.y()), 0.5, 1e-9);
  }
}

// GJK's warm start (GjkSimplex): pairs moving slowly, each queried every step with the
// simplex of its last query, against a cold query of the same poses. Apart, nearly
// touching and overlapping pairs of random grains, and cubes resting face on face (the
// closest point on a face of the difference with more than three vertices, where the
// simplex depends on the path). The answers agree to rounding (distance to 1e-12 of the
// size, normal to 1e-9, the same method and manifold point count); an empty or unusable
// simplex gives the cold answer to the bit; warm queries take less than half the GJK
// iterations (measured: 4.07 → 0.02 per query; segments 3.46 → 0.00).
TEST(ContactDistance, WarmStartedGjkAgreesWithColdAlongSlowMotions) {
  std::mt19937_64 rng(20261127);
  const ConvexShape cube = ConvexShape::cube(1.0);
  int cold_iterations = 0, warm_iterations = 0, queries = 0, overlapping = 0;
  double worst_distance = 0.0, worst_normal = 0.0;
  for (int pair = 0; pair < 120; ++pair) {
    const bool cubes = pair % 4 == 3;
    const ConvexShape sa = cubes ? cube : random_grain(rng, 0.05), sb = cubes ? cube : random_grain(rng, 0.05);
    Pose pa{Vector3d::Zero(), cubes ? Quaterniond::Identity() : random_orientation(rng)};
    Pose pb{cubes ? Vector3d(uniform(rng, -0.3, 0.3), uniform(rng, -0.3, 0.3), 1.0 + uniform(rng, -1e-3, 1e-3))
                  : Vector3d(uniform(rng, 0.9, 1.6) * random_unit(rng)),
            cubes ? Quaterniond(AngleAxisd(1e-4, random_unit(rng))) : random_orientation(rng)};
    const Vector3d drift = 1e-4 * random_unit(rng), spin_axis = random_unit(rng);
    GjkSimplex simplex;
    for (int step = 0; step < 30; ++step) {
      pb.x += drift;
      pb.q = (Quaterniond(AngleAxisd(2e-4, spin_axis)) * pb.q).normalized();
      const PosedShape a(sa, pa.x, pa.q), b(sb, pb.x, pb.q);
      const CoreDistance cold = core_distance(a, b);
      const CoreDistance warm = core_distance(a, b, 0.0, &simplex);
      const double size = 2.0;
      worst_distance = std::max(worst_distance, std::fabs(warm.distance - cold.distance) / size);
      worst_normal = std::max(worst_normal, (warm.normal - cold.normal).norm());
      EXPECT_NEAR(warm.distance, cold.distance, 1e-12 * size) << "pair " << pair << " step " << step;
      EXPECT_LT((warm.normal - cold.normal).norm(), 1e-9) << "pair " << pair << " step " << step;
      EXPECT_EQ(warm.method, cold.method) << "pair " << pair << " step " << step;
      EXPECT_GE(simplex.size, 1);
      EXPECT_LE(simplex.size, 4);
      overlapping += cold.distance < 0.0;
      if (step > 0) {
        cold_iterations += cold.gjk_iterations;
        warm_iterations += warm.gjk_iterations;
        ++queries;
      }
      // the manifold from the same simplex: the same points
      GjkSimplex copy = simplex;
      const ContactManifold m_cold = contact_manifold(a, b, 0.2);
      const ContactManifold m_warm = contact_manifold(a, b, 0.2, ContactOptions(), &copy);
      // (as sets: the witness points of a face–face contact depend on the simplex, and
      // with them the polygon's first vertex)
      ASSERT_EQ(m_warm.points.size(), m_cold.points.size()) << "pair " << pair << " step " << step;
      for (const ContactPoint& p : m_cold.points) {
        const ContactPoint* match = nullptr;
        for (const ContactPoint& q : m_warm.points)
          if (!match || (q.position - p.position).norm() < (match->position - p.position).norm()) match = &q;
        EXPECT_LT((match->position - p.position).norm(), 1e-9 * size) << "pair " << pair << " step " << step;
        EXPECT_NEAR(match->gap, p.gap, 1e-12 * size);
        EXPECT_LT((match->normal - p.normal).norm(), 1e-9);
      }
    }
    // an empty simplex, or one naming vertices the shapes do not have: the cold answer, bit for bit
    const PosedShape a(sa, pa.x, pa.q), b(sb, pb.x, pb.q);
    const CoreDistance cold = core_distance(a, b);
    GjkSimplex empty, foreign;
    foreign.size = 2;
    foreign.a = {0, 1000, 0, 0};
    for (GjkSimplex* s : {&empty, &foreign}) {
      const CoreDistance d = core_distance(a, b, 0.0, s);
      EXPECT_EQ(d.distance, cold.distance);
      EXPECT_EQ(d.normal, cold.normal);
      EXPECT_EQ(d.point_a, cold.point_a);
      EXPECT_EQ(d.gjk_iterations, cold.gjk_iterations);
    }
  }
  std::printf("  %d queries (%d overlapping): GJK iterations per query cold %.2f, warm %.2f; "
              "max |d_warm - d_cold| / size %.1e, max |n_warm - n_cold| %.1e\n",
              queries, overlapping, cold_iterations / double(queries), warm_iterations / double(queries),
              worst_distance, worst_normal);
  EXPECT_GT(overlapping, 100);
  EXPECT_LT(warm_iterations, 0.5 * cold_iterations);
}

// The same for wire segments sliding slowly along random grains (touching, grazing, apart).
TEST(SegmentPolyhedron, WarmStartedGjkAgreesWithColdAlongSlowMotions) {
  std::mt19937_64 rng(27112026);
  const double r_w = 0.1;
  int cold_iterations = 0, warm_iterations = 0, queries = 0, touching = 0;
  for (int pair = 0; pair < 150; ++pair) {
    const ConvexShape s = random_grain(rng, 0.05);
    const PosedShape grain(s, Vector3d::Zero(), random_orientation(rng));
    const Vector3d u = random_unit(rng);
    // a segment ⟂ u, its middle at the grain's support height along u plus an offset
    const double height = grain.vertices()[grain.support_vertex(u)].dot(u) + uniform(rng, -0.1, 0.3);
    Vector3d along = u.unitOrthogonal();
    along = Eigen::AngleAxisd(uniform(rng, 0, 2 * kPi), u) * along;
    Vector3d mid = height * u + uniform(rng, -0.3, 0.3) * along;
    const double half = uniform(rng, 0.05, 0.3);
    const Vector3d drift = 2e-4 * random_unit(rng);
    GjkSimplex simplex;
    for (int step = 0; step < 30; ++step) {
      mid += drift;
      const Vector3d p0 = mid - half * along, p1 = mid + half * along;
      const SegmentContact cold = segment_contact(grain, p0, p1, r_w);
      const SegmentContact warm = segment_contact(grain, p0, p1, r_w, ContactOptions(), &simplex);
      EXPECT_NEAR(warm.distance, cold.distance, 1e-12) << "pair " << pair << " step " << step;
      EXPECT_LT((warm.normal - cold.normal).norm(), 1e-9) << "pair " << pair << " step " << step;
      EXPECT_EQ(warm.method, cold.method);
      EXPECT_NEAR(warm.t_begin, cold.t_begin, 1e-9);
      EXPECT_NEAR(warm.t_end, cold.t_end, 1e-9);
      touching += cold.gap < 0.0;
      if (step > 0) {
        cold_iterations += cold.gjk_iterations;
        warm_iterations += warm.gjk_iterations;
        ++queries;
      }
    }
  }
  std::printf("  %d segment queries (%d touching): GJK iterations per query cold %.2f, warm %.2f\n", queries,
              touching, cold_iterations / double(queries), warm_iterations / double(queries));
  EXPECT_GT(touching, 300);
  EXPECT_LT(warm_iterations, 0.5 * cold_iterations);
}
