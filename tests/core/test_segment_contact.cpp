// Contact of a grain and a wire segment against sampling of the segment and closed-form
// answers for a cube; the feature-gap limit and the warm-started GJK.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/geometry/posed_shape.h"
#include "core/geometry/segment_contact.h"
#include "core/geometry/convex_shape.h"
#include "contact_reference.h"

using namespace contact_reference;  // wiregrain and the Eigen types as well

namespace {

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

}  // namespace
