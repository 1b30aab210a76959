// Wire–grain soft contact (core/contact/wire_grain_contact.h) against forces worked out
// by hand for a segment lying on the top face of a rounded cube, and against the statics
// of a segment at rest on that face under a known load.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "core/common/errors.h"
#include "core/contact/wire_grain_contact.h"
#include "wire_contact_law.h"

using namespace wiregrain;
using Eigen::Vector3d;

namespace {

constexpr double kEdge = 2.0, kSweep = 0.1, kWireRadius = 0.1;
constexpr double kOverlap = 0.01;
// top of the rounded cube at z = 1 + r_p; the wire axis r_w above it, less the overlap
constexpr double kAxisHeight = 0.5 * kEdge + kSweep + kWireRadius - kOverlap;

SoftContactLaw law(double damping = 0.0) { return wiregrain_test::wire_contact_law(damping); }

WireSegmentState lying_segment() {
  WireSegmentState s;
  s.x0 = Vector3d(-0.3, 0.2, kAxisHeight);
  s.x1 = Vector3d(0.5, 0.2, kAxisHeight);
  s.m0 = s.m1 = 0.01;
  s.radius = kWireRadius;
  return s;
}

// A rounded cube (edge 2, sweep radius r_p) of mass 8 at rest at the origin.
class WireOnRoundedCube : public ::testing::Test {
 protected:
  WireOnRoundedCube() { motion.mass = 8.0; }
  const ConvexShape cube = ConvexShape::cube(kEdge, kSweep);
  const PosedShape grain{cube, Vector3d::Zero(), Eigen::Quaterniond::Identity()};
  GrainMotion motion;
};

}  // namespace

TEST_F(WireOnRoundedCube, SegmentOnAFaceIsPushedOutWithKnTimesTheOverlapSharedByItsBeads) {
  TangentialHistory history;
  const WireGrainContact c = wire_grain_contact(law(), grain, motion, lying_segment(), 1e-4, history);
  ASSERT_TRUE(c.touching);
  EXPECT_NEAR(c.overlap, kOverlap, 1e-14);
  EXPECT_NEAR((c.normal - Vector3d::UnitZ()).norm(), 0.0, 1e-14);
  const double fn = 15.7 * kOverlap;
  // parallel to the face: the closest points are the whole segment, t = 1/2
  EXPECT_NEAR((c.force_bead0 - Vector3d(0, 0, 0.5 * fn)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((c.force_bead1 - Vector3d(0, 0, 0.5 * fn)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((c.force_grain - Vector3d(0, 0, -fn)).norm(), 0.0, 1e-14);
  // p = (0.1, 0.2, 1 + r_p − ξ/2); torque = p × (0, 0, −f_n) = (−0.2 f_n, 0.1 f_n, 0)
  EXPECT_NEAR((c.point - Vector3d(0.1, 0.2, 1.0 + kSweep - 0.5 * kOverlap)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((c.torque_grain - Vector3d(-0.2 * fn, 0.1 * fn, 0.0)).norm(), 0.0, 1e-14);
  EXPECT_FALSE(c.sliding);
}

TEST_F(WireOnRoundedCube, TangentialSpringGrowsWithTheSlipOfTheWireOverTheSpinningGrain) {
  motion.angular_velocity = Vector3d(0.0, 0.0, 0.3);  // surface at p moves with ω × p
  WireSegmentState s = lying_segment();
  s.v0 = s.v1 = Vector3d(0.02, 0.0, 0.0);
  const double dt = 1e-3;
  TangentialHistory history;
  const WireGrainContact c = wire_grain_contact(law(), grain, motion, s, dt, history);
  ASSERT_TRUE(c.touching);
  // ω × (0.1, 0.2, ·) = (−0.06, 0.03, 0); u_t = (0.02, 0, 0) − (−0.06, 0.03, 0) = (0.08, −0.03, 0)
  const Vector3d slip(0.08, -0.03, 0.0);
  EXPECT_NEAR((history.spring - slip * dt).norm(), 0.0, 1e-16);
  const Vector3d total = c.force_bead0 + c.force_bead1;
  EXPECT_NEAR((total - (Vector3d(0, 0, 15.7 * kOverlap) - 9.2 * dt * slip)).norm(), 0.0, 1e-14);
  EXPECT_FALSE(c.sliding);
}

TEST_F(WireOnRoundedCube, SlidesAtTheDynamicCoulombLimit) {
  WireSegmentState s = lying_segment();
  s.v0 = s.v1 = Vector3d(0.0, 30.0, 0.0);  // k_t |u| dt = 0.276 > μ_s f_n = 0.0785
  TangentialHistory history;
  const WireGrainContact c = wire_grain_contact(law(), grain, motion, s, 1e-3, history);
  ASSERT_TRUE(c.sliding);
  const double fn = 15.7 * kOverlap;
  const Vector3d total = c.force_bead0 + c.force_bead1;
  EXPECT_NEAR(total.z(), fn, 1e-14);
  EXPECT_NEAR(total.y(), -0.4 * fn, 1e-14);  // μ_d f_n against the slip
  EXPECT_NEAR(total.x(), 0.0, 1e-15);
  EXPECT_NEAR(history.spring.y(), 0.4 * fn / 9.2, 1e-15);  // reset to the slip limit
}

TEST_F(WireOnRoundedCube, NormalDampingUsesTheReducedMassOfSegmentAndGrain) {
  motion.velocity = Vector3d(0.0, 0.0, 0.5);  // grain rising into the wire: ξ̇ = 0.5
  TangentialHistory history;
  const WireGrainContact c = wire_grain_contact(law(0.3), grain, motion, lying_segment(), 1e-4, history);
  const double m = 0.02 * 8.0 / 8.02;
  const double gamma_n = 2.0 * 0.3 * std::sqrt(15.7 * m);
  EXPECT_NEAR(c.normal_force, 15.7 * kOverlap + gamma_n * 0.5, 1e-13);
}

TEST_F(WireOnRoundedCube, ApartPairsReportTheGapAndNoForce) {
  WireSegmentState s = lying_segment();
  s.x0.z() += 0.05;
  s.x1.z() += 0.05;
  TangentialHistory history;
  history.spring = Vector3d(1e-3, 0, 0);
  const WireGrainContact c = wire_grain_contact(law(), grain, motion, s, 1e-4, history);
  EXPECT_FALSE(c.touching);
  EXPECT_NEAR(c.overlap, kOverlap - 0.05, 1e-14);
  EXPECT_EQ(c.force_grain, Vector3d::Zero());
  EXPECT_EQ(history.spring, Vector3d(1e-3, 0, 0));  // untouched: the caller drops it
}

TEST_F(WireOnRoundedCube, ASegmentThroughTheCoreGetsAFiniteForceAlongTheShortestWayOut) {
  WireSegmentState s = lying_segment();
  s.x0 = Vector3d(-2.0, 0.1, 0.8);  // axis 0.2 below the top face, crossing the core
  s.x1 = Vector3d(2.0, 0.1, 0.8);
  TangentialHistory history;
  const WireGrainContact c = wire_grain_contact(law(), grain, motion, s, 1e-4, history);
  ASSERT_TRUE(c.touching);
  // penetration depth of the axis 0.2 (out through the top face), plus r_p + r_w
  EXPECT_NEAR(c.overlap, 0.2 + kSweep + kWireRadius, 1e-12);
  EXPECT_NEAR((c.normal - Vector3d::UnitZ()).norm(), 0.0, 1e-12);
  EXPECT_TRUE(c.force_grain.allFinite());
  EXPECT_NEAR(c.force_grain.z(), -15.7 * c.overlap, 1e-12);
}

// A segment of length 1 over the top face, tilted by θ in the xz plane about its deeper
// end (overlap ξ there), which is bead `deeper` (0 or 1); the other end is sin θ higher.
// The two choices of `deeper` are mirror images of each other about the plane x = 0, a
// symmetry plane of the cube.
WireSegmentState tilted_segment(double overlap, double angle, int deeper = 0) {
  WireSegmentState s;
  const double z = 0.5 * kEdge + kSweep + kWireRadius - overlap;
  const Vector3d low(deeper == 0 ? -0.5 : 0.5, 0.2, z);
  const Vector3d high = low + Vector3d(deeper == 0 ? std::cos(angle) : -std::cos(angle), 0.0, std::sin(angle));
  s.x0 = deeper == 0 ? low : high;
  s.x1 = deeper == 0 ? high : low;
  s.m0 = s.m1 = 0.01;
  s.radius = kWireRadius;
  return s;
}

// The moment about the grain's centre c of the forces the contact puts on the beads.
Vector3d bead_moment(const WireGrainContact& c, const WireSegmentState& s, const Vector3d& centre) {
  return (s.x0 - centre).cross(c.force_bead0) + (s.x1 - centre).cross(c.force_bead1);
}

TEST_F(WireOnRoundedCube, TheBeadsShareChangesContinuouslyAsTheSegmentTiltsPastTheParallelTolerance) {
  // ξ = 0.02: the higher end still overlaps at the parallel tolerance θ_tol (0.01 rad),
  // where the geometry switches from the parallel interval to the single closest point.
  // Expected, whatever the rule that shares the load among the beads of a lying segment:
  // - flat (θ = 0), the segment is symmetric about its middle: each bead carries half;
  // - the share of the deeper end never falls as the segment tilts (else a lying segment
  //   is unstable: the end pressed deeper loses support and sinks further), stays in
  //   [1/2, 1], and beyond θ_tol it is 1 (the segment's closest point to the face is its
  //   deeper end);
  // - the mirror image of the scene gives the mirrored shares;
  // - no jump: a share that followed the geometry's switch made resting wires chatter;
  // - the force is normal (no tangential spring at dt = 0), so the torque on the grain is
  //   minus the moment of the bead forces about its centre, and its force minus their sum.
  const double overlap = 0.02, tolerance = ContactOptions().angle_tolerance;
  const double fn = law().normal_stiffness * overlap;
  double largest_jump = 0.0, largest_fall = 0.0, largest_mirror = 0.0, largest_torque = 0.0;
  double previous = 0.5;
  for (int k = 0; k <= 300; ++k) {
    const double angle = 1e-4 * k;
    double share[2];
    for (const int deeper : {0, 1}) {
      const WireSegmentState s = tilted_segment(overlap, angle, deeper);
      TangentialHistory history;
      const WireGrainContact c = wire_grain_contact(law(), grain, motion, s, 0.0, history);
      ASSERT_TRUE(c.touching);
      EXPECT_NEAR(c.overlap, overlap, 1e-15);
      const Vector3d total = c.force_bead0 + c.force_bead1;
      EXPECT_NEAR((total - Vector3d(0, 0, fn)).norm(), 0.0, 1e-14) << "angle " << angle;
      EXPECT_NEAR((c.force_grain + total).norm(), 0.0, 1e-16);
      largest_torque = std::max(largest_torque, (c.torque_grain + bead_moment(c, s, grain.position())).norm());
      share[deeper] = (deeper == 0 ? c.force_bead0.z() : c.force_bead1.z()) / total.z();
    }
    const double deeper_share = share[0];
    largest_mirror = std::max(largest_mirror, std::abs(share[1] - share[0]));
    if (k == 0) EXPECT_NEAR(deeper_share, 0.5, 1e-15);
    EXPECT_GE(deeper_share, 0.5 - 1e-15) << "angle " << angle;
    EXPECT_LE(deeper_share, 1.0 + 1e-15) << "angle " << angle;
    if (angle > 1.01 * tolerance) EXPECT_NEAR(deeper_share, 1.0, 1e-15) << "angle " << angle;
    largest_fall = std::max(largest_fall, previous - deeper_share);
    largest_jump = std::max(largest_jump, std::abs(deeper_share - previous));
    previous = deeper_share;
  }
  std::printf("tilt sweep: largest step of the share %.3g, largest fall %.3g, mirror difference %.3g, "
              "torque + bead moment %.3g (f_n %.3g)\n",
              largest_jump, largest_fall, largest_mirror, largest_torque, fn);
  // measured: no fall, mirror difference 2.2e-16 (one ulp of 1), torque + bead moment
  // 3.3e-17 (1e-16 f_n)
  EXPECT_LE(largest_fall, 1e-15);
  EXPECT_LE(largest_mirror, 1e-15);
  EXPECT_LE(largest_torque, 5e-16 * fn);
  // steps of 1e-4 rad: measured 0.0102 (the blend's slope); a share switched at the
  // tolerance would jump by 0.5 − 0.25
  EXPECT_LT(largest_jump, 0.03);
}

// A segment of length 1 lying on the top face, loaded with W at the fraction s of its
// length (its beads carry (1 − s)W and sW downwards), sinks from touching and, with
// viscous damping on its beads, comes to rest. At rest, whatever the rule that shares the
// load among the beads:
// - force balance: the contact's forces on the beads sum to −W;
// - moment balance about the load point x_s: their moment about x_s is zero, i.e. the
//   resultant acts where the load does;
// - the grain receives W and the torque (x_s − x_g) × W about its centre x_g;
// - the contact pushes with k_n ξ_n, ξ_n the overlap of the deeper end (paper Sec. 2.3),
//   which is the more heavily loaded one, and the segment still lies on the face (tilt
//   within the parallel tolerance).
struct LoadedRest {
  WireSegmentState segment;
  WireGrainContact contact;
  double speed = 0.0;
};

LoadedRest rest_under_load(const PosedShape& grain, const GrainMotion& motion, double load, double s) {
  const Vector3d w0(0.0, 0.0, -(1.0 - s) * load), w1(0.0, 0.0, -s * load);
  LoadedRest r;
  r.segment = tilted_segment(0.0, 0.0);  // flat, touching
  const double dt = 1e-3, damping = 0.5;  // k_n/2 per bead on 0.01: critical damping 0.56
  Vector3d v0 = Vector3d::Zero(), v1 = Vector3d::Zero();
  for (int step = 0; step < 20000; ++step) {
    TangentialHistory history;
    r.contact = wire_grain_contact(law(), grain, motion, r.segment, 0.0, history);
    v0 += dt / r.segment.m0 * (r.contact.force_bead0 + w0 - damping * v0);
    v1 += dt / r.segment.m1 * (r.contact.force_bead1 + w1 - damping * v1);
    r.segment.x0 += dt * v0;
    r.segment.x1 += dt * v1;
  }
  TangentialHistory history;
  r.contact = wire_grain_contact(law(), grain, motion, r.segment, 0.0, history);
  r.speed = std::max(v0.norm(), v1.norm());
  return r;
}

TEST_F(WireOnRoundedCube, ASegmentUnderAKnownLoadRestsOnAFaceInForceAndMomentBalance) {
  const double load = 0.1;  // ξ_n = W/k_n = 0.0064
  for (const double s : {0.5, 0.35, 0.8, 0.1}) {
    const LoadedRest r = rest_under_load(grain, motion, load, s);
    const WireGrainContact& c = r.contact;
    ASSERT_TRUE(c.touching) << "s " << s;
    const Vector3d W(0.0, 0.0, -load);
    const Vector3d x_s = (1.0 - s) * r.segment.x0 + s * r.segment.x1;
    const Vector3d on_beads = c.force_bead0 + c.force_bead1;
    const Vector3d moment = (r.segment.x0 - x_s).cross(c.force_bead0) + (r.segment.x1 - x_s).cross(c.force_bead1);
    const Vector3d load_moment = (x_s - grain.position()).cross(W);
    const double z0 = r.segment.x0.z(), z1 = r.segment.x1.z();
    const double deepest = 0.5 * kEdge + kSweep + kWireRadius - std::min(z0, z1);
    const double tilt = std::atan2(std::abs(z1 - z0), std::abs(r.segment.x1.x() - r.segment.x0.x()));
    std::printf("s = %.2f: speed %.2g, |force + W| %.2g, |moment about x_s| %.2g, |grain force - W| %.2g, "
                "|grain torque - (x_s - x_g) x W| %.2g, k_n xi_n / W - 1 = %.2g, tilt %.4f\n",
                s, r.speed, (on_beads + W).norm(), moment.norm(), (c.force_grain - W).norm(),
                (c.torque_grain - load_moment).norm(), law().normal_stiffness * deepest / load - 1.0, tilt);
    // measured over the four loads: speeds ≤ 1e-13, force, moment and torque residuals ≤ 5e-14
    // (5e-13 W), k_n ξ_n / W − 1 ≤ 4.5e-13: the round-off of the damped beads' positions
    // (an ulp of z ≈ 1.2 is 2e-16, k_n times it 3.5e-15). Tolerances 4–5× above.
    EXPECT_LT(r.speed, 5e-13) << "s " << s;
    EXPECT_LT((on_beads + W).norm(), 2e-12 * load) << "s " << s;
    EXPECT_LT(moment.norm(), 2e-12 * load * (r.segment.x1 - r.segment.x0).norm()) << "s " << s;
    EXPECT_LE((c.force_grain + on_beads).norm(), 1e-16 * load) << "s " << s;  // exactly opposite
    EXPECT_LT((c.force_grain - W).norm(), 2e-12 * load) << "s " << s;
    EXPECT_LT((c.torque_grain - load_moment).norm(), 2e-12 * load) << "s " << s;
    EXPECT_NEAR(law().normal_stiffness * deepest / load, 1.0, 2e-12) << "s " << s;
    EXPECT_NEAR(c.normal_force / load, 1.0, 2e-12) << "s " << s;
    if (s < 0.5) EXPECT_LT(z0, z1) << "s " << s;
    if (s > 0.5) EXPECT_LT(z1, z0) << "s " << s;
    if (s == 0.5) EXPECT_NEAR(z0, z1, 1e-15);
    EXPECT_LT(tilt, ContactOptions().angle_tolerance) << "s " << s;
  }
}

// A segment lying across the top of a sphere (radius 1 at the origin, a one-vertex
// grain): the foot of the centre on the axis is x = 0, i.e. t = 0.3/0.8; the normal is
// +z, the beads share k_n ξ as (1 − t, t), and the force on the grain passes through
// its centre (no torque).
TEST(WireOnSphere, SegmentAcrossTheTopIsPushedOutThroughTheCentre) {
  const double radius = 1.0;
  const ConvexShape ball = ConvexShape::sphere(radius);
  const PosedShape grain{ball, Vector3d::Zero(), Eigen::Quaterniond::Identity()};
  GrainMotion motion;
  motion.mass = 4.0;
  WireSegmentState s;
  const double height = radius + kWireRadius - kOverlap;
  s.x0 = Vector3d(-0.3, 0.0, height);
  s.x1 = Vector3d(0.5, 0.0, height);
  s.m0 = s.m1 = 0.01;
  s.radius = kWireRadius;
  TangentialHistory history;
  const WireGrainContact c = wire_grain_contact(law(), grain, motion, s, 1e-4, history);
  ASSERT_TRUE(c.touching);
  EXPECT_NEAR(c.overlap, kOverlap, 1e-14);
  EXPECT_NEAR((c.normal - Vector3d::UnitZ()).norm(), 0.0, 1e-14);
  const double fn = 15.7 * kOverlap, t = 0.3 / 0.8;
  EXPECT_NEAR(c.geometry.t, t, 1e-14);
  EXPECT_NEAR((c.force_bead0 - Vector3d(0, 0, (1.0 - t) * fn)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((c.force_bead1 - Vector3d(0, 0, t * fn)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((c.force_grain - Vector3d(0, 0, -fn)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((c.point - Vector3d(0, 0, radius - 0.5 * kOverlap)).norm(), 0.0, 1e-14);
  EXPECT_NEAR(c.torque_grain.norm(), 0.0, 1e-16);
}

// wire_sphere_contact, the closed form for stock spheres, against the general path on a
// one-vertex grain (ConvexShape::sphere: GJK geometry, a different code): random
// segments around spheres of several radii, moving and spinning, friction and damping on,
// the tangential springs of both carried over 20 steps.
TEST(WireOnStockSphere, ClosedFormEqualsTheGeneralPathOnAOneVertexGrain) {
  std::mt19937 rng(7);
  const auto uniform = [&rng](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  const auto random_vector = [&](double scale) {
    return Vector3d(uniform(-scale, scale), uniform(-scale, scale), uniform(-scale, scale));
  };
  int touching = 0, clamped = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const double radius = uniform(0.3, 1.5);
    const Vector3d centre = random_vector(1.0);
    const ConvexShape ball = ConvexShape::sphere(radius);
    GrainMotion motion;
    motion.mass = uniform(1.0, 10.0);
    motion.velocity = random_vector(0.2);
    motion.angular_velocity = random_vector(0.5);
    WireSegmentState s;
    s.radius = kWireRadius;
    s.m0 = s.m1 = 0.01;
    // a segment of length 0.2–0.8 whose foot is 0.9–1.0 of contact distance from the centre
    const Vector3d direction = random_vector(1.0).normalized();
    const Vector3d across = direction.unitOrthogonal();
    const double length = uniform(0.2, 0.8), foot = uniform(-0.6, 1.4);
    const double distance = (radius + kWireRadius) * uniform(0.9, 1.02);
    s.x0 = centre + distance * across - foot * length * direction;
    s.x1 = s.x0 + length * direction;
    s.v0 = random_vector(0.3);
    s.v1 = random_vector(0.3);
    TangentialHistory closed, general;
    for (int step = 0; step < 20; ++step) {
      const PosedShape grain{ball, centre, Eigen::Quaterniond::Identity()};
      const WireGrainContact a = wire_sphere_contact(law(0.3), centre, radius, motion, s, 1e-3, closed);
      const WireGrainContact b = wire_grain_contact(law(0.3), grain, motion, s, 1e-3, general);
      ASSERT_EQ(a.touching, b.touching) << "trial " << trial << " step " << step;
      EXPECT_NEAR(a.overlap, b.overlap, 1e-12);
      if (a.touching) {
        ++touching;
        if (a.load_parameter == 0.0 || a.load_parameter == 1.0) ++clamped;
        EXPECT_NEAR(a.load_parameter, b.load_parameter, 1e-10);
        EXPECT_NEAR((a.force_bead0 - b.force_bead0).norm(), 0.0, 1e-11);
        EXPECT_NEAR((a.force_bead1 - b.force_bead1).norm(), 0.0, 1e-11);
        EXPECT_NEAR((a.torque_grain - b.torque_grain).norm(), 0.0, 1e-11);
        EXPECT_EQ(a.sliding, b.sliding);
      }
      s.x0 += 1e-3 * s.v0;
      s.x1 += 1e-3 * s.v1;
    }
  }
  EXPECT_GT(touching, 1000);  // most pairs touch, some at a clamped end
  EXPECT_GT(clamped, 100);
}

// Beyond the end x1 the foot is clamped to t = 1: bead 1 takes the whole force, along
// x1 − c, of magnitude k_n (R + r_w − |x1 − c|).
TEST(WireOnStockSphere, PastTheEndOfTheSegmentTheLastBeadTakesTheWholeForce) {
  const double radius = 1.0;
  GrainMotion motion;
  motion.mass = 4.0;
  WireSegmentState s;
  s.radius = kWireRadius;
  s.m0 = s.m1 = 0.01;
  const Vector3d out = Vector3d(1.0, 2.0, 2.0) / 3.0;
  s.x1 = (radius + kWireRadius - kOverlap) * out;
  s.x0 = s.x1 + 0.4 * out.unitOrthogonal() + 0.3 * out;  // leaning away: the foot beyond x1
  TangentialHistory history;
  const WireGrainContact c = wire_sphere_contact(law(), Vector3d::Zero(), radius, motion, s, 1e-4, history);
  ASSERT_TRUE(c.touching);
  EXPECT_EQ(c.load_parameter, 1.0);
  EXPECT_NEAR(c.overlap, kOverlap, 1e-14);
  EXPECT_NEAR(c.force_bead0.norm(), 0.0, 1e-16);
  EXPECT_NEAR((c.force_bead1 - 15.7 * kOverlap * out).norm(), 0.0, 1e-14);
  EXPECT_NEAR(c.torque_grain.norm(), 0.0, 1e-15);
}

// An axis through the centre (a wire pushed through a sphere): a finite force k_n (R + r_w)
// across the segment, never NaN.
TEST(WireOnStockSphere, AnAxisThroughTheCentreGetsAFiniteForceAcrossTheSegment) {
  GrainMotion motion;
  motion.mass = 4.0;
  WireSegmentState s;
  s.radius = kWireRadius;
  s.m0 = s.m1 = 0.01;
  s.x0 = Vector3d(-0.2, 0.0, 0.0);
  s.x1 = Vector3d(0.2, 0.0, 0.0);
  TangentialHistory history;
  const WireGrainContact c = wire_sphere_contact(law(), Vector3d::Zero(), 1.0, motion, s, 1e-4, history);
  ASSERT_TRUE(c.touching);
  EXPECT_NEAR(c.normal.norm(), 1.0, 1e-15);
  EXPECT_NEAR(c.normal.dot(s.x1 - s.x0), 0.0, 1e-15);
  EXPECT_NEAR(c.normal_force, 15.7 * (1.0 + kWireRadius), 1e-12);
  EXPECT_TRUE((c.force_bead0 + c.force_bead1).allFinite());
}

// GJK's early exit for polyhedra (ContactOptions::exit_gap): with exit gap g,
// a segment whose gap is at most g gets exactly the full query's answer (every field,
// the same bits); a farther one either that answer or a lower bound of its gap above g
// (method gjk_far), never above the true gap. The wire contact's force and spring do not
// depend on exact_gap_below. Negative and NaN exit gaps are rejected.
TEST(WireOnRandomHull, EarlyExitChangesOnlyPairsApartAndBoundsTheirGap) {
  std::mt19937_64 rng(28);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto unit = [&] {
    Vector3d d;
    do d = Vector3d(u(rng), u(rng), u(rng));
    while (d.squaredNorm() > 1.0 || d.squaredNorm() < 1e-4);
    return Vector3d(d.normalized());
  };
  int exits = 0, exact = 0, touching = 0;
  for (int shape = 0; shape < 20; ++shape) {
    const ConvexShape hull = ConvexShape::random_ellipsoid(rng, 20, 0.5, 0.8, 0.6, 0.05);
    for (int trial = 0; trial < 50; ++trial) {
      const Eigen::Quaterniond q(u(rng), u(rng), u(rng), u(rng) + 1.5);
      const PosedShape grain(hull, Vector3d(u(rng), u(rng), u(rng)), q.normalized());
      const Vector3d dir = unit();
      const Vector3d mid = grain.position() + (0.3 + 0.5 * (u(rng) + 1.0)) * unit();
      const double length = 0.2 + 0.2 * (u(rng) + 1.0), r_w = 0.05;
      const Vector3d x0 = mid - 0.5 * length * dir, x1 = mid + 0.5 * length * dir;
      for (const double exit_gap : {0.0, 0.1}) {
        ContactOptions full_options, early_options;
        full_options.feature_gap_limit = early_options.feature_gap_limit = 0.0;  // as the wire contact asks
        early_options.exit_gap = exit_gap;
        const SegmentContact full = segment_contact(grain, x0, x1, r_w, full_options);
        const SegmentContact early = segment_contact(grain, x0, x1, r_w, early_options);
        if (early.method == DistanceMethod::gjk_far) {
          ++exits;
          EXPECT_GT(early.gap, exit_gap);
          EXPECT_LE(early.gap, full.gap + 1e-12);
          EXPECT_GT(full.gap, exit_gap);
        } else {
          ++exact;
          EXPECT_EQ(early.method, full.method);
          EXPECT_EQ(early.distance, full.distance);
          EXPECT_EQ(early.gap, full.gap);
          EXPECT_EQ(early.normal, full.normal);
          EXPECT_EQ(early.point_on_core, full.point_on_core);
          EXPECT_EQ(early.point_on_segment, full.point_on_segment);
          EXPECT_EQ(early.t, full.t);
          EXPECT_EQ(early.t_begin, full.t_begin);
          EXPECT_EQ(early.t_end, full.t_end);
          EXPECT_EQ(early.gjk_iterations, full.gjk_iterations);
        }
        if (full.gap <= exit_gap) EXPECT_NE(early.method, DistanceMethod::gjk_far);
      }
      const WireSegmentState w = wiregrain_test::moving_segment(x0, x1, r_w);
      GrainMotion motion;
      motion.mass = 2.0;
      TangentialHistory h1, h2;
      const WireGrainContact a = wire_grain_contact(law(0.3), grain, motion, w, 1e-3, h1);
      const WireGrainContact b = wire_grain_contact(law(0.3), grain, motion, w, 1e-3, h2, 0.0);
      wiregrain_test::expect_same_load(a, b, h1, h2);
      touching += a.touching;
    }
  }
  std::printf("early exits %d, exact answers %d, touching pairs %d\n", exits, exact, touching);
  EXPECT_GT(exits, 200);  // every branch seen
  EXPECT_GT(exact, 200);
  EXPECT_GT(touching, 50);
  const ConvexShape cube = ConvexShape::cube(1.0, 0.1);
  const PosedShape grain(cube, Vector3d::Zero(), Eigen::Quaterniond::Identity());
  for (const double bad : {-1.0, std::nan("")}) {
    ContactOptions options;
    options.exit_gap = bad;
    try {
      segment_contact(grain, Vector3d(2, 0, 0), Vector3d(3, 0, 0), 0.1, options);
      FAIL() << "accepted exit_gap " << bad;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(std::string(e.argument()), "exit_gap");
    }
  }
}
