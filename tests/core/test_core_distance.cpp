// Signed distance of two cores (GJK apart, the SAT overlapping) against independent
// references: brute-force feature-pair distances, the convex hull of the Minkowski
// difference, closed-form answers for regular solids.
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
#include "core/geometry/core_distance.h"
#include "core/geometry/posed_shape.h"
#include "core/geometry/convex_shape.h"
#include "contact_reference.h"

using namespace contact_reference;  // wiregrain and the Eigen types as well

namespace {

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
    const std::vector<Vector3d> va(a.vertices().begin(), a.vertices().end());
    const std::vector<Vector3d> vb(b.vertices().begin(), b.vertices().end());
    if (!penetration_from_minkowski_hull(va, vb, depth, normal, second))
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

}  // namespace
