// Spheres (the one-vertex core) through every contact query, against closed forms.
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
#include "core/geometry/segment_contact.h"
#include "core/geometry/convex_shape.h"
#include "contact_reference.h"

using namespace contact_reference;  // wiregrain and the Eigen types as well

namespace {

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

}  // namespace
