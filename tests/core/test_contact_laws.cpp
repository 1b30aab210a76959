// Materials → soft-contact laws (core/contact/contact_laws.h), numbers worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "core/common/errors.h"
#include "core/contact/contact_laws.h"

using namespace wiregrain;

namespace {
constexpr double kPi = 3.14159265358979323846;

ContactFriction some_friction() {
  ContactFriction f;
  f.damping_ratio = 0.2;
  f.static_friction = 0.5;
  f.dynamic_friction = 0.3;
  f.limit_force = true;
  return f;
}
}  // namespace

// Table 1: E_w = 100, ν_w = 0, E_p = 1000, ν_p = 0.3, l_w = 0.2, r_w = 0.1.
// 1/E_wp = 1/100 + 0.91/1000 = 0.01091, E_wp = 91.659028414...
TEST(ContactLaws, WireGrainTableOne) {
  ElasticMaterial wire, grain;
  grain.youngs_modulus = 1000.0;
  grain.poisson_ratio = 0.3;
  const double e_wp = 1.0 / 0.01091;
  EXPECT_NEAR(e_wp, 91.65902841429882, 1e-12);
  EXPECT_NEAR(wire_grain_modulus(wire, grain), e_wp, 1e-12);
  const SoftContactLaw law = segment_contact_law(wire_grain_modulus(wire, grain), 0.2, 0.1, some_friction());
  EXPECT_NEAR(law.normal_stiffness, e_wp * 0.2 * kPi / 4.0, 1e-12);  // 14.397767
  EXPECT_NEAR(law.normal_stiffness, 14.397767, 1e-6);
  EXPECT_NEAR(law.tangential_stiffness, e_wp * 0.1, 1e-12);  // 9.16590...
  EXPECT_EQ(law.damping_ratio, 0.2);
  EXPECT_EQ(law.static_friction, 0.5);
  EXPECT_EQ(law.dynamic_friction, 0.3);
  EXPECT_TRUE(law.limit_force);
}

// Wire–wire, one material: E_ww = E_w/(2(1−ν²)); E = 100, ν = 0.3 → 100/1.82 = 54.945...
// The value is the one pair_style wire/contact always used, to the last bit.
TEST(ContactLaws, WireWireOneMaterial) {
  ElasticMaterial w;
  w.youngs_modulus = 100.0;
  w.poisson_ratio = 0.3;
  const double e_ww = 100.0 / (2.0 * (1.0 - 0.3 * 0.3));
  EXPECT_EQ(wire_wire_modulus(w, w), e_ww);
  EXPECT_NEAR(e_ww, 54.94505494505494, 1e-12);
  const SoftContactLaw law = segment_contact_law(wire_wire_modulus(w, w), 0.2, 0.1, some_friction());
  EXPECT_EQ(law.normal_stiffness, e_ww * 0.2 * kPi / 4.0);
  EXPECT_EQ(law.tangential_stiffness, e_ww * 0.1);
  // Table 1 (ν = 0): E_ww = 50, k_n = 50·0.2·π/4 = 2.5π, k_t = 5
  const SoftContactLaw table = segment_contact_law(wire_wire_modulus(ElasticMaterial(), ElasticMaterial()), 0.2, 0.1, {});
  EXPECT_NEAR(table.normal_stiffness, 2.5 * kPi, 1e-14);
  EXPECT_NEAR(table.tangential_stiffness, 5.0, 1e-14);
}

// Two wire materials: the mixing rule. E_a = 100, E_b = 300, ν = 0:
// 1/E* = 1/100 + 1/300 = 4/300, E* = 75; and it is symmetric.
TEST(ContactLaws, WireWireTwoMaterials) {
  ElasticMaterial a, b;
  b.youngs_modulus = 300.0;
  EXPECT_NEAR(wire_wire_modulus(a, b), 75.0, 1e-12);
  EXPECT_EQ(wire_wire_modulus(a, b), wire_wire_modulus(b, a));
  // equal materials through the mixing rule agree with E/(2(1−ν²)) to round-off
  ElasticMaterial c;
  c.poisson_ratio = 0.25;
  EXPECT_NEAR(effective_modulus(100.0, 0.25, 100.0, 0.25), wire_wire_modulus(c, c), 1e-12);
}

// Wire–wall (rigid): E* = E_w/(1−ν_w²); E = 100, ν = 0.3 → 109.89...; k_n = E* l π/4, k_t = E* r.
TEST(ContactLaws, WireWall) {
  ElasticMaterial w;
  w.poisson_ratio = 0.3;
  const double e_star = 100.0 / 0.91;
  EXPECT_EQ(wire_wall_modulus(w), e_star);
  const SoftContactLaw law = segment_contact_law(wire_wall_modulus(w), 0.2, 0.1, some_friction());
  EXPECT_EQ(law.normal_stiffness, e_star * 0.2 * kPi / 4.0);
  EXPECT_EQ(law.tangential_stiffness, e_star * 0.1);
  EXPECT_NEAR(law.normal_stiffness, 17.261498, 1e-6);
}

// The segment a bead stands for: its own, else its previous bead's, else a sphere (2 r).
TEST(ContactLaws, BeadSegmentLength) {
  EXPECT_EQ(bead_segment_length(0.2, 0.3, 0.1), 0.2);
  EXPECT_EQ(bead_segment_length(0.0, 0.3, 0.1), 0.3);
  EXPECT_EQ(bead_segment_length(0.0, 0.0, 0.1), 0.2);
  EXPECT_EQ(bead_segment_length(0.0, -1.0, 0.05), 0.1);
}

TEST(ContactLaws, MaterialValidation) {
  ElasticMaterial m;
  EXPECT_NO_THROW(m.validate());
  m.youngs_modulus = -1.0;
  EXPECT_THROW(m.validate(), InvalidArgument);
  m.youngs_modulus = NAN;
  EXPECT_THROW(m.validate(), InvalidArgument);
  m.youngs_modulus = 100.0;
  m.poisson_ratio = 0.5;
  EXPECT_THROW(m.validate(), InvalidArgument);
  m.poisson_ratio = -0.1;
  EXPECT_THROW(m.validate(), InvalidArgument);
  m.poisson_ratio = 0.49;
  EXPECT_NO_THROW(m.validate());
}
