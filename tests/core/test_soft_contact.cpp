// Spring–dashpot contact with Coulomb friction against closed-form results.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/common/errors.h"
#include "core/contact/soft_contact.h"

using namespace wiregrain;
using Eigen::Vector3d;

TEST(SoftContact, RestitutionDampingRatioRoundTrip) {
  for (double e : {0.05, 0.3, 0.5, 0.9, 0.999}) {
    const double zeta = damping_ratio_from_restitution(e);
    EXPECT_NEAR(restitution_from_damping_ratio(zeta), e, 1e-14);
  }
  EXPECT_EQ(damping_ratio_from_restitution(0.0), 1.0);
  EXPECT_EQ(damping_ratio_from_restitution(1.0), 0.0);
  EXPECT_THROW(damping_ratio_from_restitution(1.5), InvalidArgument);
}

// Two bodies approaching head-on: the ratio of separation to approach speed equals
// e(ζ) = exp(−πζ/√(1−ζ²)) of the linear spring–dashpot (contact ends when ξ returns to 0).
TEST(SoftContact, HeadOnRestitutionMatchesFormula) {
  for (double e_target : {0.2, 0.5, 0.8}) {
    SoftContactLaw law;
    law.normal_stiffness = 1e4;
    law.damping_ratio = damping_ratio_from_restitution(e_target);
    const double m1 = 1.0, m2 = 3.0, m_eff = m1 * m2 / (m1 + m2), dt = 1e-6;
    double x1 = 0.0, x2 = 1.0, v1 = 0.5, v2 = -0.5;  // radii 0.5 each: touching at t=0
    TangentialHistory h;
    bool touched = false;
    for (int k = 0; k < 10000000; ++k) {
      const double overlap = 1.0 - (x2 - x1);
      if (overlap < 0.0 && touched) break;
      double f = 0.0;
      if (overlap >= 0.0) {
        touched = true;
        f = soft_contact_force(law, overlap, Vector3d::UnitX(), Vector3d(v2 - v1, 0, 0), dt, m_eff, h)
                .force.x();
      }
      // symplectic Euler is enough at this resolution (ω dt = 1.2e-4)
      v1 -= f / m1 * dt;
      v2 += f / m2 * dt;
      x1 += v1 * dt;
      x2 += v2 * dt;
    }
    const double e = (v2 - v1) / 1.0;
    EXPECT_NEAR(e, e_target, 1e-3) << "target " << e_target;
  }
}

// A block of mass m on a floor pushed by a horizontal force F, raised slowly from 0 (a
// sudden push overshoots and can break a contact below μ_s): it sticks (the spring
// stretches to F/k_t and stays) while F < μ_s m g, and slides with acceleration
// (F − μ_d m g)/m once F > μ_s m g.
TEST(SoftContact, StaticAndDynamicFriction) {
  SoftContactLaw law;
  law.normal_stiffness = 1e5;
  law.tangential_stiffness = 5e4;
  law.damping_ratio = 0.3;
  law.static_friction = 0.5;
  law.dynamic_friction = 0.3;
  const double m = 2.0, g = 1.0, dt = 1e-5;
  // the floor normal points up, from the floor (A) to the block (B); the block rests at
  // the overlap m g / k_n
  const Vector3d n = Vector3d::UnitZ();
  for (double push : {0.9 * 0.5 * m * g, 1.2 * 0.5 * m * g}) {
    TangentialHistory h;
    double x = 0.0, v = 0.0;
    const int steps = 200000;
    double v_mid = 0.0;
    for (int k = 0; k < steps; ++k) {
      const auto f = soft_contact_force(law, m * g / law.normal_stiffness, n, Vector3d(v, 0, 0), dt, m, h);
      const double ramp = std::min(1.0, 4.0 * k / steps);
      const double a = (ramp * push + f.force.x()) / m;
      v += a * dt;
      x += v * dt;
      if (k == steps / 2) v_mid = v;
    }
    if (push < 0.5 * m * g) {
      EXPECT_NEAR(x, push / law.tangential_stiffness, 1e-6) << "sticks with the spring at F/k_t";
      EXPECT_LT(std::abs(v), 1e-9);
    } else {
      const double a_measured = (v - v_mid) / ((steps - steps / 2 - 1) * dt);
      EXPECT_NEAR(a_measured, (push - 0.3 * m * g) / m, 1e-9 * 1e3) << "slides at mu_d";
      EXPECT_TRUE(h.sliding);
    }
  }
}

TEST(SoftContact, SpringFollowsTheNormal) {
  SoftContactLaw law;
  law.normal_stiffness = 1.0;
  law.tangential_stiffness = 1.0;
  law.static_friction = law.dynamic_friction = 10.0;
  TangentialHistory h;
  h.spring = Vector3d(0.3, 0.0, 0.0);
  const Vector3d n = Vector3d(1.0, 0.0, 1.0).normalized();  // tilted normal
  soft_contact_force(law, 1.0, n, Vector3d::Zero(), 1e-3, 1.0, h);
  EXPECT_NEAR(h.spring.dot(n), 0.0, 1e-15);
  EXPECT_NEAR(h.spring.norm(), 0.3, 1e-15);
}

TEST(SoftContact, RejectsBadParameters) {
  SoftContactLaw law;
  law.static_friction = 0.3;
  law.dynamic_friction = 0.5;
  try {
    law.validate();
    FAIL() << "mu_d > mu_s accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), "mu_d");
  }
  law.dynamic_friction = 0.3;
  law.normal_stiffness = -1.0;
  EXPECT_THROW(law.validate(), InvalidArgument);
}
