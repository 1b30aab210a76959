// The wire–wire contact (core/contact/wire_wire_contact.h) against forces worked by hand:
// closest points, overlap and normal of two segments, the relative velocity at the contact
// from the beads' velocities, and the lever rule that shares the force among four beads.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "core/contact/wire_wire_contact.h"

using namespace wiregrain;
using Eigen::Vector3d;

namespace {
constexpr double kTol = 1e-12;

// k_n = 100, k_t = 40, no damping, μ_s = 0.5, μ_d = 0.3
SoftContactLaw round_law() {
  SoftContactLaw law;
  law.normal_stiffness = 100.0;
  law.tangential_stiffness = 40.0;
  law.static_friction = 0.5;
  law.dynamic_friction = 0.3;
  return law;
}

// a segment of radius 0.1 at rest, its beads of mass 0.5
WireSegmentState segment(const Vector3d& x0, const Vector3d& x1) {
  WireSegmentState s;
  s.x0 = x0;
  s.x1 = x1;
  s.radius = 0.1;
  s.m0 = s.m1 = 0.5;
  return s;
}

void expect_vector(const Vector3d& actual, const Vector3d& expected, const char* what) {
  EXPECT_NEAR((actual - expected).norm(), 0.0, kTol) << what << ": " << actual.transpose() << " vs "
                                                      << expected.transpose();
}

// Σ F over the four beads and Σ x × F about the origin.
Vector3d net_force(const WireWireContact& c) { return c.force_a0 + c.force_a1 + c.force_b0 + c.force_b1; }
Vector3d net_torque(const WireWireContact& c, const WireSegmentState& a, const WireSegmentState& b) {
  return a.x0.cross(c.force_a0) + a.x1.cross(c.force_a1) + b.x0.cross(c.force_b0) + b.x1.cross(c.force_b1);
}
}  // namespace

// A along x from (−1, 0, 0) to (1, 0, 0); B along y at x = 0.5, z = 0.15. Closest points
// p = (0.5, 0, 0) (s = 0.75), q = (0.5, 0, 0.15) (t = 0.5), d = 0.15, ξ = 0.2 − 0.15 = 0.05,
// n = +z. At rest: F = k_n ξ n = 5 ẑ on B, shared by the lever rule: b0, b1 get 2.5 each;
// a0 gets −(1 − 0.75)·5 = −1.25, a1 −0.75·5 = −3.75. Net force and torque zero.
TEST(WireWireContact, CrossingSegmentsPressedTogether) {
  const WireSegmentState a = segment({-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0});
  const WireSegmentState b = segment({0.5, -1.0, 0.15}, {0.5, 1.0, 0.15});
  TangentialHistory h;
  const WireWireContact c = wire_wire_contact(round_law(), a, b, 0.01, h);
  ASSERT_TRUE(c.touching);
  EXPECT_NEAR(c.overlap, 0.05, kTol);
  EXPECT_NEAR(c.closest.s, 0.75, kTol);
  EXPECT_NEAR(c.closest.t, 0.5, kTol);
  expect_vector(c.normal, {0.0, 0.0, 1.0}, "normal");
  expect_vector(c.point, {0.5, 0.0, 0.075}, "point");  // p + (r_a − ξ/2) n
  expect_vector(c.force, {0.0, 0.0, 5.0}, "F");
  EXPECT_NEAR(c.normal_force, 5.0, kTol);
  expect_vector(c.force_b0, {0.0, 0.0, 2.5}, "b0");
  expect_vector(c.force_b1, {0.0, 0.0, 2.5}, "b1");
  expect_vector(c.force_a0, {0.0, 0.0, -1.25}, "a0");
  expect_vector(c.force_a1, {0.0, 0.0, -3.75}, "a1");
  expect_vector(net_force(c), Vector3d::Zero(), "net force");
  expect_vector(net_torque(c, a, b), Vector3d::Zero(), "net torque");
  EXPECT_NEAR(c.elastic_energy, 0.5 * 100.0 * 0.05 * 0.05, kTol);  // 0.125
  EXPECT_FALSE(c.sliding);
  expect_vector(h.spring, Vector3d::Zero(), "spring");
}

// The same pair approaching: a0 moves at +0.4 ẑ, b0 at −0.2 ẑ, a1 and b1 rest. At the
// contact v_A = (1 − 0.75)·0.4 = 0.1 ẑ, v_B = (1 − 0.5)·(−0.2) = −0.1 ẑ: u·n = −0.2.
// k_n = 200, ζ = 0.5, m_A = m_B = 1, m_eff = 0.5: γ_n = 2·0.5·√(200·0.5) = 10,
// f_n = 200·0.05 + 10·0.2 = 12.
TEST(WireWireContact, DampingSeesTheBeadVelocitiesAtTheContact) {
  WireSegmentState a = segment({-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0});
  WireSegmentState b = segment({0.5, -1.0, 0.15}, {0.5, 1.0, 0.15});
  a.v0 = {0.0, 0.0, 0.4};
  b.v0 = {0.0, 0.0, -0.2};
  SoftContactLaw law = round_law();
  law.normal_stiffness = 200.0;
  law.damping_ratio = 0.5;
  TangentialHistory h;
  const WireWireContact c = wire_wire_contact(law, a, b, 0.01, h);
  ASSERT_TRUE(c.touching);
  EXPECT_NEAR(c.normal_force, 12.0, kTol);
  expect_vector(c.force, {0.0, 0.0, 12.0}, "F");
  expect_vector(c.force_b0, {0.0, 0.0, 6.0}, "b0");
  expect_vector(c.force_a1, {0.0, 0.0, -9.0}, "a1");
  const SpringDashpot springs = contact_spring_dashpot(law, c.effective_mass);
  EXPECT_NEAR(springs.normal_stiffness, 200.0, kTol);
  EXPECT_NEAR(springs.normal_damping, 10.0, kTol);
}

// Parallel segments, B above A by d = 0.15 and shifted by 0.4 along x: A = [0, 1], B's
// projection [0.4, 1.4]; the contact is at the middle of the common stretch [0.4, 1],
// x = 0.7: s = 0.7, t = 0.3. ξ = 0.05, n = +z, f_n = k_n ξ = 5. A rests; B's beads move
// along x at 0.26 and 0.06: at the contact v_B = 0.7·0.26 + 0.3·0.06 = 0.2. Each step of
// dt = 0.01 stretches the spring by 0.002: after k steps f_t = −40·0.002 k = −0.08 k
// (sticks while 0.08 k ≤ μ_s f_n = 2.5, so through k = 31); at k = 32 (2.56) it slides:
// f_t = −μ_d f_n = −1.5 and the spring is set to 1.5/40 = 0.0375; and it keeps sliding
// at 1.5 (0.0375 + 0.002 gives 1.58 > μ_d f_n).
TEST(WireWireContact, ParallelSegmentsSlidingStickThenSlip) {
  const WireSegmentState a = segment({0.0, 0.0, 0.0}, {1.0, 0.0, 0.0});
  WireSegmentState b = segment({0.4, 0.0, 0.15}, {1.4, 0.0, 0.15});
  b.v0 = {0.26, 0.0, 0.0};
  b.v1 = {0.06, 0.0, 0.0};
  const double dt = 0.01;
  TangentialHistory h;
  WireWireContact c = wire_wire_contact(round_law(), a, b, dt, h);
  ASSERT_TRUE(c.touching);
  EXPECT_NEAR(c.closest.s, 0.7, kTol);
  EXPECT_NEAR(c.closest.t, 0.3, kTol);
  expect_vector(c.force, {-0.08, 0.0, 5.0}, "F, step 1");
  // lever rule: b0 0.7 F, b1 0.3 F, a0 −0.3 F, a1 −0.7 F
  expect_vector(c.force_b0, {-0.056, 0.0, 3.5}, "b0");
  expect_vector(c.force_b1, {-0.024, 0.0, 1.5}, "b1");
  expect_vector(c.force_a0, {0.024, 0.0, -1.5}, "a0");
  expect_vector(c.force_a1, {0.056, 0.0, -3.5}, "a1");
  expect_vector(h.spring, {0.002, 0.0, 0.0}, "spring, step 1");
  for (int k = 2; k <= 31; k++) c = wire_wire_contact(round_law(), a, b, dt, h);
  EXPECT_FALSE(c.sliding);
  expect_vector(c.force, {-2.48, 0.0, 5.0}, "F, step 31");
  c = wire_wire_contact(round_law(), a, b, dt, h);
  EXPECT_TRUE(c.sliding);
  expect_vector(c.force, {-1.5, 0.0, 5.0}, "F, step 32");
  expect_vector(h.spring, {0.0375, 0.0, 0.0}, "spring at the slip limit");
  EXPECT_NEAR(c.elastic_energy, 0.125 + 0.5 * 40.0 * 0.0375 * 0.0375, kTol);  // 0.153125
  expect_vector(net_force(c), Vector3d::Zero(), "net force");
  // the torque of the couple: (q − p) × F = 0.15 ẑ × (−1.5, 0, 5) = (0, −0.225, 0)
  expect_vector(net_torque(c, a, b), {0.0, -0.225, 0.0}, "net torque");
  c = wire_wire_contact(round_law(), a, b, dt, h);
  EXPECT_TRUE(c.sliding);
  expect_vector(c.force, {-1.5, 0.0, 5.0}, "F, step 33");
}

// B's end b0 = (0.4, 0.15, 0) pressed on the middle of A (B along +y): p = (0.4, 0, 0),
// s = 0.4, t = 0; n = +y, ξ = 0.05, F = 5 ŷ all on b0; a0 gets −0.6·5 = −3, a1 −0.4·5 = −2.
TEST(WireWireContact, SegmentEndOnAnotherSegment) {
  const WireSegmentState a = segment({0.0, 0.0, 0.0}, {1.0, 0.0, 0.0});
  const WireSegmentState b = segment({0.4, 0.15, 0.0}, {0.4, 1.15, 0.0});
  TangentialHistory h;
  const WireWireContact c = wire_wire_contact(round_law(), a, b, 0.01, h);
  ASSERT_TRUE(c.touching);
  EXPECT_NEAR(c.closest.s, 0.4, kTol);
  EXPECT_NEAR(c.closest.t, 0.0, kTol);
  expect_vector(c.normal, {0.0, 1.0, 0.0}, "normal");
  expect_vector(c.point, {0.4, 0.075, 0.0}, "point");
  expect_vector(c.force_b0, {0.0, 5.0, 0.0}, "b0");
  expect_vector(c.force_b1, Vector3d::Zero(), "b1");
  expect_vector(c.force_a0, {0.0, -3.0, 0.0}, "a0");
  expect_vector(c.force_a1, {0.0, -2.0, 0.0}, "a1");
  expect_vector(net_torque(c, a, b), Vector3d::Zero(), "net torque");
}

// Two collinear segments end to end, 0.15 apart: the ends a1 and b0 carry it all.
TEST(WireWireContact, EndToEnd) {
  const WireSegmentState a = segment({0.0, 0.0, 0.0}, {1.0, 0.0, 0.0});
  const WireSegmentState b = segment({1.15, 0.0, 0.0}, {2.15, 0.0, 0.0});
  TangentialHistory h;
  const WireWireContact c = wire_wire_contact(round_law(), a, b, 0.01, h);
  ASSERT_TRUE(c.touching);
  expect_vector(c.normal, {1.0, 0.0, 0.0}, "normal");
  expect_vector(c.force_a1, {-5.0, 0.0, 0.0}, "a1");
  expect_vector(c.force_b0, {5.0, 0.0, 0.0}, "b0");
  expect_vector(c.force_a0, Vector3d::Zero(), "a0");
  expect_vector(c.force_b1, Vector3d::Zero(), "b1");
}

// Axes that cross (d = 0): the normal is perpendicular to both, (a1 − a0) × (b1 − b0)
// = 2ŷ × 2ẑ → +x; ξ = r_a + r_b = 0.2, F = 20 x̂, shared half and half (s = t = 0.5).
TEST(WireWireContact, IntersectingAxes) {
  const WireSegmentState a = segment({0.0, -1.0, 0.0}, {0.0, 1.0, 0.0});
  const WireSegmentState b = segment({0.0, 0.0, -1.0}, {0.0, 0.0, 1.0});
  TangentialHistory h;
  const WireWireContact c = wire_wire_contact(round_law(), a, b, 0.01, h);
  ASSERT_TRUE(c.touching);
  EXPECT_NEAR(c.overlap, 0.2, kTol);
  expect_vector(c.normal, {1.0, 0.0, 0.0}, "normal");
  expect_vector(c.force_b0, {10.0, 0.0, 0.0}, "b0");
  expect_vector(c.force_a1, {-10.0, 0.0, 0.0}, "a1");
}

// Apart by a gap of 0.1: not touching, no force, the history untouched.
TEST(WireWireContact, ApartLeavesTheHistory) {
  const WireSegmentState a = segment({0.0, 0.0, 0.0}, {1.0, 0.0, 0.0});
  WireSegmentState b = segment({0.0, 0.0, 0.3}, {1.0, 0.0, 0.3});
  b.v0 = b.v1 = {1.0, 0.0, 0.0};
  TangentialHistory h;
  h.spring = {0.01, 0.0, 0.0};
  const WireWireContact c = wire_wire_contact(round_law(), a, b, 0.01, h);
  EXPECT_FALSE(c.touching);
  EXPECT_NEAR(c.overlap, -0.1, kTol);
  expect_vector(c.force_b0, Vector3d::Zero(), "b0");
  expect_vector(h.spring, {0.01, 0.0, 0.0}, "spring");
}
