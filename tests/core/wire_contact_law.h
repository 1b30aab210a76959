// The soft contact law the wire–grain core tests use (test_wire_grain_contact.cpp,
// test_superquadric.cpp): round numbers with distinct normal and tangential stiffness
// and distinct static and dynamic friction, so a mixed-up term shows; and what their
// early-exit tests share: a moving segment, and the check that two evaluations of one
// pair load wire and grain the same to the bit.
#pragma once

#include <gtest/gtest.h>

#include "core/contact/soft_contact.h"
#include "core/contact/wire_grain_contact.h"

namespace wiregrain_test {

inline wiregrain::SoftContactLaw wire_contact_law(double damping = 0.0) {
  wiregrain::SoftContactLaw l;
  l.normal_stiffness = 15.7;
  l.tangential_stiffness = 9.2;
  l.damping_ratio = damping;
  l.static_friction = 0.5;
  l.dynamic_friction = 0.4;
  return l;
}

// The segment [x0, x1] of radius r, its beads (mass 0.01 each) moving apart.
inline wiregrain::WireSegmentState moving_segment(const Eigen::Vector3d& x0, const Eigen::Vector3d& x1, double r) {
  wiregrain::WireSegmentState w;
  w.x0 = x0;
  w.x1 = x1;
  w.v0 = Eigen::Vector3d(0.1, 0.0, 0.0);
  w.v1 = Eigen::Vector3d(0.0, -0.2, 0.0);
  w.radius = r;
  w.m0 = w.m1 = 0.01;
  return w;
}

// a and b: the same pair evaluated with exact gaps wanted everywhere and only below 0.
inline void expect_same_load(const wiregrain::WireGrainContact& a, const wiregrain::WireGrainContact& b,
                             const wiregrain::TangentialHistory& ha, const wiregrain::TangentialHistory& hb) {
  ASSERT_EQ(a.touching, b.touching);
  EXPECT_EQ(a.force_bead0, b.force_bead0);
  EXPECT_EQ(a.force_bead1, b.force_bead1);
  EXPECT_EQ(a.torque_grain, b.torque_grain);
  EXPECT_EQ(ha.spring, hb.spring);
  if (!b.touching) EXPECT_GT(-b.overlap, 0.0);
}

}  // namespace wiregrain_test
