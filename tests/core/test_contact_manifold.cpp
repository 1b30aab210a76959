// Contact manifolds of two grains and of a grain on a wall: points on the surfaces, the
// deepest at the pair gap, exact polygons for regular solids, near vertices.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/geometry/contact_manifold.h"
#include "core/geometry/posed_shape.h"
#include "core/geometry/convex_shape.h"
#include "contact_reference.h"

using namespace contact_reference;  // wiregrain and the Eigen types as well

namespace {

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

}  // namespace
