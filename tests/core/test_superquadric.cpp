// Superquadrics (core/geometry/superquadric.h) and the wire's contact with them
// (segment_contact(PosedSuperquadric, ...), wire_superquadric_contact): the support point
// against the shape function and against sampled surface points; the segment distance
// against the optimality conditions of a convex distance problem (closest point on the
// surface, normal along ∇F there, the segment's point the projection of it) and against
// a brute force over sampled surface points; on a ball (a = b = c, n = 2) the contact
// against the closed form for spheres.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/common/errors.h"
#include "core/contact/held_grains.h"
#include "core/contact/wire_grain_contact.h"
#include "wire_contact_law.h"
#include "core/geometry/superquadric.h"

using namespace wiregrain;
using Eigen::Vector3d;

namespace {

constexpr double kPi = 3.14159265358979323846;

double signed_power(double x, double e) { return std::copysign(std::pow(std::abs(x), e), x); }

// Barr's parametrisation of the surface (ε = 2/n; η latitude, ω longitude): an
// independent way to put points on it
Vector3d surface_point(const Superquadric& s, double eta, double omega) {
  const double e1 = 2.0 / s.n1, e2 = 2.0 / s.n2;
  const double ce = signed_power(std::cos(eta), e1);
  return Vector3d(s.half_axes.x() * ce * signed_power(std::cos(omega), e2),
                  s.half_axes.y() * ce * signed_power(std::sin(omega), e2),
                  s.half_axes.z() * signed_power(std::sin(eta), e1));
}

std::vector<Superquadric> shapes() {
  std::vector<Superquadric> out;
  const double n[][2] = {{2, 2}, {2, 4}, {4, 2}, {3, 3}, {6, 6}, {10, 2.5}};
  for (const auto& b : n) {
    Superquadric s;
    s.half_axes = Vector3d(0.5, 0.35, 0.8);
    s.n1 = b[0];
    s.n2 = b[1];
    out.push_back(s);
  }
  return out;
}

// A random pose of s (centre in [−1, 1]³, orientation uniform in the quaternion box) and
// a random unit vector, drawn with uniform(lo, hi).
template <class Uniform>
Vector3d random_unit(Uniform& uniform) {
  return Vector3d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)).normalized();
}
template <class Uniform>
PosedSuperquadric random_pose(const Superquadric& s, Uniform& uniform) {
  const Eigen::Quaterniond q(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
  return PosedSuperquadric(s, Vector3d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)), q.normalized());
}

SoftContactLaw law(double damping = 0.0) { return wiregrain_test::wire_contact_law(damping); }

}  // namespace

TEST(Superquadric, ParametrisedPointsLieOnTheSurface) {  // the test's own parametrisation
  for (const Superquadric& s : shapes())
    for (double eta = -1.5; eta < 1.5; eta += 0.37)
      for (double omega = 0.0; omega < 6.2; omega += 0.41)
        EXPECT_NEAR(superquadric_shape_function(s, surface_point(s, eta, omega)), 0.0, 1e-12);
}

TEST(Superquadric, SupportPointIsOnTheSurfaceAndFarthestAlongItsDirection) {
  std::mt19937 rng(3);
  std::normal_distribution<double> normal;
  for (const Superquadric& s : shapes()) {
    std::vector<Vector3d> samples;
    for (int i = 0; i <= 120; ++i)
      for (int j = 0; j < 240; ++j) samples.push_back(surface_point(s, -kPi / 2 + kPi * i / 120, 2 * kPi * j / 240));
    for (int trial = 0; trial < 200; ++trial) {
      const Vector3d e(normal(rng), normal(rng), normal(rng));
      const Vector3d x = superquadric_support(s, e);
      EXPECT_NEAR(superquadric_shape_function(s, x), 0.0, 1e-12) << "n " << s.n1 << " " << s.n2;
      double best = -1e300;
      for (const Vector3d& p : samples) best = std::max(best, e.dot(p));
      // no sampled point beyond it; the samples come within their spacing of it
      EXPECT_GE(e.dot(x), best - 1e-12 * e.norm());
      EXPECT_LT(e.dot(x) - best, 2e-3 * e.norm());
      // a smooth body: ∇F at the support point is along e
      const Vector3d g = superquadric_gradient(s, x).normalized();
      EXPECT_NEAR((g - e.normalized()).norm(), 0.0, 1e-9);
    }
  }
}

TEST(Superquadric, EllipsoidSupportHasItsClosedForm) {  // n = 2: A² e / |A e|
  Superquadric s;
  s.half_axes = Vector3d(0.5, 0.35, 0.8);
  const Vector3d e(0.3, -1.2, 0.7);
  const Vector3d a2 = s.half_axes.cwiseProduct(s.half_axes);
  const Vector3d expected = a2.cwiseProduct(e) / s.half_axes.cwiseProduct(e).norm();
  EXPECT_NEAR((superquadric_support(s, e) - expected).norm(), 0.0, 1e-15);
  EXPECT_EQ(superquadric_support(s, Vector3d::Zero()), Vector3d::Zero());
  // axis directions: the tips of the half-axes, for any blockiness
  s.n1 = 7.0;
  s.n2 = 3.0;
  EXPECT_NEAR((superquadric_support(s, Vector3d::UnitX()) - Vector3d(0.5, 0, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((superquadric_support(s, -Vector3d::UnitZ()) - Vector3d(0, 0, -0.8)).norm(), 0.0, 1e-15);
}

TEST(Superquadric, GradientMatchesFiniteDifferences) {
  for (const Superquadric& s : shapes())
    for (double eta = -1.2; eta < 1.3; eta += 0.6)
      for (double omega = 0.2; omega < 6.2; omega += 0.9) {
        const Vector3d x = 0.9 * surface_point(s, eta, omega);
        const Vector3d g = superquadric_gradient(s, x);
        for (int d = 0; d < 3; ++d) {
          const double h = 1e-6;
          Vector3d xp = x, xm = x;
          xp[d] += h;
          xm[d] -= h;
          const double fd = (superquadric_shape_function(s, xp) - superquadric_shape_function(s, xm)) / (2 * h);
          EXPECT_NEAR(g[d], fd, 1e-6 * std::max(1.0, std::abs(fd)));
        }
      }
}

TEST(Superquadric, BadShapesAreRejected) {
  Superquadric s;
  s.half_axes = Vector3d(1.0, 0.0, 1.0);
  try {
    check_superquadric(s);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), "half_axes");
  }
  s.half_axes = Vector3d::Ones();
  s.n1 = 1.5;
  try {
    check_superquadric(s);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), "blockiness");
  }
  s.n1 = 2.0;
  s.n2 = std::nan("");
  EXPECT_THROW(check_superquadric(s), InvalidArgument);
}

// Random segments around posed superquadrics, apart from them: GJK's result satisfies the
// optimality conditions, which for two convex sets make it the distance; a brute force
// over 29 000 surface points × 200 segment points finds nothing closer (and comes within
// its spacing).
TEST(SegmentSuperquadric, DistanceSatisfiesTheOptimalityConditions) {
  std::mt19937 rng(11);
  const auto uniform = [&rng](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  int iterations_max = 0, trials = 0;
  for (const Superquadric& s : shapes()) {
    std::vector<Vector3d> body_samples;
    for (int i = 0; i <= 120; ++i)
      for (int j = 0; j < 240; ++j)
        body_samples.push_back(surface_point(s, -kPi / 2 + kPi * i / 120, 2 * kPi * j / 240));
    for (int trial = 0; trial < 40; ++trial, ++trials) {
      const Eigen::Quaterniond q(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      const Vector3d centre(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      const PosedSuperquadric body(s, centre, q);
      const Vector3d dir = Vector3d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)).normalized();
      const Vector3d mid = centre + uniform(0.9, 1.6) * Vector3d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)).normalized();
      const double length = uniform(0.1, 1.5);
      const Vector3d x0 = mid - 0.5 * length * dir, x1 = mid + 0.5 * length * dir;
      if (body.shape_function(x0) <= 0.05 || body.shape_function(x1) <= 0.05 ||
          body.shape_function(0.5 * (x0 + x1)) <= 0.05)
        continue;  // a segment that may cross the body: not this test
      const SegmentContact c = segment_contact(body, x0, x1, 0.0);
      if (c.method != DistanceMethod::gjk) continue;  // crossing after all
      iterations_max = std::max(iterations_max, c.gjk_iterations);
      // the core point on the surface, the normal along ∇F there and along the closest points
      EXPECT_NEAR(body.shape_function(c.point_on_core), 0.0, 1e-9);
      // (blocky shapes: on their nearly flat stretches the support point jumps with the
      // normal and the polish can stall; measured at most 5.2e-4 rad there)
      const bool blocky = s.n1 > 4.0 || s.n2 > 4.0;
      EXPECT_NEAR((body.normal_at(c.point_on_core) - c.normal).norm(), 0.0, blocky ? 1e-3 : 1e-6);
      EXPECT_NEAR((c.point_on_segment - c.point_on_core).norm(), c.distance, 1e-12);
      // the segment point: the clamped projection of the core point on the segment
      const double t = std::clamp((c.point_on_core - x0).dot(x1 - x0) / (x1 - x0).squaredNorm(), 0.0, 1.0);
      EXPECT_NEAR(c.t, t, 1e-6);
      EXPECT_NEAR((x0 + c.t * (x1 - x0) - c.point_on_segment).norm(), 0.0, 1e-12);
      // brute force
      double brute = 1e300;
      for (int k = 0; k <= 200; ++k) {
        const Vector3d p = x0 + (k / 200.0) * (x1 - x0);
        for (const Vector3d& b : body_samples) brute = std::min(brute, (p - body.position() - body.rotation() * b).norm());
      }
      EXPECT_GE(brute, c.distance - 1e-12);
      // (Barr's samples are sparse on the flat faces of blocky shapes: the upper check
      // only where they are dense)
      if (s.n1 <= 4.0 && s.n2 <= 4.0) EXPECT_LT(brute - c.distance, 2e-2);
    }
  }
  EXPECT_GT(trials, 100);
  EXPECT_LE(iterations_max, 60);
  std::printf("segment–superquadric GJK: at most %d iterations\n", iterations_max);
}

// GJK's early exit: with early_exit_distance r, a pair nearer than r gets exactly the
// full query's answer (same iterations, same bits); a farther one either that answer or
// a lower bound above r (method gjk_far), never a distance above the true one. The
// wire contact's force does not depend on exact_gap_below. Bad values are rejected.
TEST(SegmentSuperquadric, EarlyExitChangesOnlyPairsApartAndBoundsTheirDistance) {
  std::mt19937 rng(23);
  const auto uniform = [&rng](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  int exits = 0, exact = 0;
  for (const Superquadric& s : shapes()) {
    for (int trial = 0; trial < 200; ++trial) {
      const PosedSuperquadric body = random_pose(s, uniform);
      const Vector3d dir = random_unit(uniform);
      const Vector3d mid = body.position() + uniform(0.0, 2.5) * random_unit(uniform);
      const double length = uniform(0.1, 1.0), r = uniform(0.01, 0.3);
      const Vector3d x0 = mid - 0.5 * length * dir, x1 = mid + 0.5 * length * dir;
      const SegmentContact full = segment_contact(body, x0, x1, 0.0);
      const SegmentContact early = segment_contact(body, x0, x1, 0.0, r);
      if (early.method == DistanceMethod::gjk_far) {
        ++exits;
        EXPECT_GT(early.distance, r);
        EXPECT_LE(early.distance, full.distance * (1 + 1e-12));
        EXPECT_GT(full.distance, r);
        EXPECT_NEAR(early.gap, early.distance, 0.0);
      } else {
        ++exact;
        EXPECT_EQ(early.method, full.method);
        EXPECT_EQ(early.distance, full.distance);
        EXPECT_EQ(early.normal, full.normal);
        EXPECT_EQ(early.t, full.t);
      }
      // the force of a wire of radius r around the segment, exact gaps wanted or not
      const WireSegmentState w = wiregrain_test::moving_segment(x0, x1, r);
      GrainMotion motion;
      motion.mass = 2.0;
      TangentialHistory h1, h2;
      const WireGrainContact a = wire_superquadric_contact(law(0.3), body, motion, w, 1e-3, h1);
      const WireGrainContact b = wire_superquadric_contact(law(0.3), body, motion, w, 1e-3, h2, 0.0);
      wiregrain_test::expect_same_load(a, b, h1, h2);
    }
  }
  EXPECT_GT(exits, 100);  // both branches seen
  EXPECT_GT(exact, 100);
  const PosedSuperquadric body(shapes().front(), Vector3d::Zero(), Eigen::Quaterniond::Identity());
  for (const double bad : {-1.0, std::nan("")}) {
    try {
      segment_contact(body, Vector3d(2, 0, 0), Vector3d(3, 0, 0), 0.1, bad);
      FAIL() << "accepted early_exit_distance " << bad;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(std::string(e.argument()), "early_exit_distance");
    }
    WireSegmentState w;
    w.x0 = Vector3d(2, 0, 0);
    w.x1 = Vector3d(3, 0, 0);
    w.radius = 0.1;
    w.m0 = w.m1 = 0.01;
    TangentialHistory h;
    try {
      wire_superquadric_contact(law(0.3), body, GrainMotion(), w, 1e-3, h, bad);
      FAIL() << "accepted exact_gap_below " << bad;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(std::string(e.argument()), "exact_gap_below");
    }
  }
}

// The warm start: last step's (n, t), the segment moved by ~1e-5, gives the cold query's
// answer (distance to 1e-13, normal and t to 1e-9; measured 2.5e-16 and 5e-12) and is
// certified nearly always; a wrong guess (the opposite normal, or any guess for a segment
// that crosses the body) is never accepted: the answer is then the cold one exactly.
// wire_superquadric_contact hands on the new solution.
TEST(SegmentSuperquadric, WarmStartGivesTheColdAnswerOrFallsBack) {
  std::mt19937 rng(31);
  const auto uniform = [&rng](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  int trials = 0, certified = 0;
  for (const Superquadric& s : shapes()) {
    for (int trial = 0; trial < 150; ++trial) {
      const PosedSuperquadric body = random_pose(s, uniform);
      const Vector3d out = random_unit(uniform);
      const Vector3d foot = body.support(out) + uniform(0.001, 0.15) * out;
      const Vector3d axis = Eigen::AngleAxisd(uniform(0, 6.28), out) * out.unitOrthogonal();
      const double length = uniform(0.1, 0.5), f = uniform(-0.2, 1.2);
      Vector3d x0 = foot - f * length * axis, x1 = x0 + length * axis;
      const SegmentContact before = segment_contact(body, x0, x1, 0.0);
      if (before.method != DistanceMethod::gjk) continue;
      x0 += 1e-5 * Vector3d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      x1 += 1e-5 * Vector3d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      const SegmentContact cold = segment_contact(body, x0, x1, 0.0);
      SmoothContactGuess guess{before.normal, before.t};
      const SegmentContact warm = segment_contact(body, x0, x1, 0.0, 0.0, &guess);
      ++trials;
      certified += warm.gjk_iterations == 0;
      EXPECT_EQ(warm.method, cold.method);
      EXPECT_NEAR(warm.distance, cold.distance, 1e-13);
      EXPECT_NEAR((warm.normal - cold.normal).norm(), 0.0, 1e-9);
      EXPECT_NEAR(warm.t, cold.t, 1e-9);
      // the opposite normal: not certified, the cold answer to the bit
      SmoothContactGuess wrong{-before.normal, before.t};
      const SegmentContact fallback = segment_contact(body, x0, x1, 0.0, 0.0, &wrong);
      EXPECT_GT(fallback.gjk_iterations, 0);
      EXPECT_EQ(fallback.distance, cold.distance);
      EXPECT_EQ(fallback.normal, cold.normal);
    }
  }
  EXPECT_GT(trials, 300);
  EXPECT_GT(certified, 0.95 * trials);
  std::printf("warm start certified in %d of %d trials\n", certified, trials);

  // a segment through the body: any guess falls back to the cold (SAT) answer
  const PosedSuperquadric body(shapes().front(), Vector3d::Zero(), Eigen::Quaterniond::Identity());
  const Vector3d x0(-2, 0.01, 0.02), x1(2, 0.01, 0.02);
  const SegmentContact cold = segment_contact(body, x0, x1, 0.1);
  for (const Vector3d& n : {Vector3d(0, 1, 0), Vector3d(0, 0, 1), Vector3d(1, 0, 0)}) {
    SmoothContactGuess guess{n, 0.5};
    const SegmentContact warm = segment_contact(body, x0, x1, 0.1, 0.0, &guess);
    EXPECT_EQ(warm.method, DistanceMethod::sat);
    EXPECT_EQ(warm.distance, cold.distance);
  }

  // wire_superquadric_contact hands on the pair's new solution, and clears it when none
  WireSegmentState w;
  w.x0 = Vector3d(-0.2, 0.0, 0.8 + 0.05);  // on top of the first shape (half-height 0.8)
  w.x1 = Vector3d(0.2, 0.0, 0.8 + 0.05);
  w.radius = 0.1;
  w.m0 = w.m1 = 0.01;
  GrainMotion motion;
  motion.mass = 1.0;
  TangentialHistory h;
  SmoothContactGuess handed;
  const WireGrainContact c = wire_superquadric_contact(law(), body, motion, w, 1e-4, h, 0.0, &handed);
  ASSERT_TRUE(c.touching);
  EXPECT_EQ(handed.normal, c.geometry.normal);
  EXPECT_EQ(handed.t, c.geometry.t);
  w.x0.z() = w.x1.z() = -3.0;  // far below: GJK's early exit, no closest points
  wire_superquadric_contact(law(), body, motion, w, 1e-4, h, 0.0, &handed);
  EXPECT_EQ(handed.normal, Vector3d::Zero());
}

// A ball (a = b = c = R, n1 = n2 = 2) is a sphere: the contact equals the closed form
// wire_sphere_contact (its own code), forces and torque, over random touching segments
// with friction and damping, springs carried over 20 steps.
TEST(WireOnSuperquadric, ABallEqualsTheClosedFormForSpheres) {
  std::mt19937 rng(5);
  const auto uniform = [&rng](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  const auto random_vector = [&](double scale) {
    return Vector3d(uniform(-scale, scale), uniform(-scale, scale), uniform(-scale, scale));
  };
  int touching = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const double radius = uniform(0.3, 1.5);
    Superquadric ball;
    ball.half_axes = Vector3d::Constant(radius);
    const Vector3d centre = random_vector(1.0);
    const Eigen::Quaterniond q(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    GrainMotion motion;
    motion.mass = uniform(1.0, 10.0);
    motion.velocity = random_vector(0.2);
    motion.angular_velocity = random_vector(0.5);
    WireSegmentState s;
    s.radius = 0.1;
    s.m0 = s.m1 = 0.01;
    const Vector3d direction = random_vector(1.0).normalized();
    const double length = uniform(0.2, 0.8), foot = uniform(-0.6, 1.4);
    s.x0 = centre + (radius + s.radius) * uniform(0.9, 1.02) * direction.unitOrthogonal() - foot * length * direction;
    s.x1 = s.x0 + length * direction;
    s.v0 = random_vector(0.3);
    s.v1 = random_vector(0.3);
    TangentialHistory closed, general;
    for (int step = 0; step < 20; ++step) {
      const WireGrainContact a = wire_sphere_contact(law(0.3), centre, radius, motion, s, 1e-3, closed);
      const WireGrainContact b =
          wire_superquadric_contact(law(0.3), PosedSuperquadric(ball, centre, q), motion, s, 1e-3, general);
      ASSERT_EQ(a.touching, b.touching) << "trial " << trial << " step " << step;
      EXPECT_NEAR(a.overlap, b.overlap, 1e-11);
      if (a.touching) {
        ++touching;
        EXPECT_NEAR(a.load_parameter, b.load_parameter, 1e-7);
        EXPECT_NEAR((a.force_bead0 - b.force_bead0).norm(), 0.0, 1e-8);
        EXPECT_NEAR((a.force_bead1 - b.force_bead1).norm(), 0.0, 1e-8);
        EXPECT_NEAR((a.torque_grain - b.torque_grain).norm(), 0.0, 1e-8);
        EXPECT_NEAR((a.force_grain + b.force_bead0 + b.force_bead1).norm(), 0.0, 1e-8);
      }
      s.x0 += 1e-3 * s.v0;
      s.x1 += 1e-3 * s.v1;
    }
  }
  EXPECT_GT(touching, 500);
}

// A segment lying across the top of a box-like superquadric (n = 8) at its centre: the
// normal is +z, the overlap r_w + c − height, the force k_n ξ shared by the beads by
// the foot's parameter.
TEST(WireOnSuperquadric, SegmentAcrossTheTopOfARoundedBox) {
  Superquadric box;
  box.half_axes = Vector3d(0.5, 0.4, 0.3);
  box.n1 = box.n2 = 8.0;
  WireSegmentState s;
  s.radius = 0.1;
  s.m0 = s.m1 = 0.01;
  const double overlap = 0.01;
  s.x0 = Vector3d(-0.3, 0.6, 0.3 + 0.1 - overlap);  // over the top point (0, 0, c) at t = 1/2
  s.x1 = Vector3d(0.3, -0.6, 0.3 + 0.1 - overlap);
  GrainMotion motion;
  motion.mass = 2.0;
  TangentialHistory history;
  const WireGrainContact c = wire_superquadric_contact(law(), PosedSuperquadric(box, Vector3d::Zero(),
                                                                                Eigen::Quaterniond::Identity()),
                                                       motion, s, 1e-4, history);
  ASSERT_TRUE(c.touching);
  // the nearly flat top (z falls as (|x/a|⁸ + |y/b|⁸)/8 away from the pole): the pole
  EXPECT_NEAR(c.overlap, overlap, 1e-12);
  EXPECT_NEAR((c.normal - Vector3d::UnitZ()).norm(), 0.0, 1e-8);
  // (along the segment the gap grows as the 8th power of the offset from the pole: the
  // closest point is fixed only to ~1e-4, which moves the beads' shares by as much)
  EXPECT_NEAR(c.load_parameter, 0.5, 1e-3);
  EXPECT_NEAR((c.force_bead0 + c.force_bead1 - 15.7 * overlap * Vector3d::UnitZ()).norm(), 0.0, 1e-12);
}

// The axis through the body (a wire pushed through a grain): finite force out of the
// body, an overlap above r_w, never NaN.
TEST(WireOnSuperquadric, AnAxisThroughTheBodyGetsAFiniteForceOutward) {
  Superquadric s;
  s.half_axes = Vector3d(0.5, 0.35, 0.8);
  s.n1 = 4.0;
  s.n2 = 3.0;
  const PosedSuperquadric body(s, Vector3d(0.1, 0.0, 0.0), Eigen::Quaterniond(1, 0.2, 0.1, 0.0));
  WireSegmentState w;
  w.radius = 0.1;
  w.m0 = w.m1 = 0.01;
  w.x0 = Vector3d(-0.2, 0.05, 0.3);
  w.x1 = Vector3d(0.3, 0.05, 0.35);
  GrainMotion motion;
  motion.mass = 2.0;
  TangentialHistory history;
  const WireGrainContact c = wire_superquadric_contact(law(), body, motion, w, 1e-4, history);
  ASSERT_TRUE(c.touching);
  EXPECT_GT(c.overlap, w.radius);
  EXPECT_NEAR(c.normal.norm(), 1.0, 1e-14);
  EXPECT_GT(c.normal.dot(c.point - body.position()), 0.0);  // out of the body
  EXPECT_TRUE((c.force_bead0 + c.force_bead1).allFinite());
  // at least the depth of the axis point below the surface along the normal
  EXPECT_GT(c.overlap - w.radius, 0.0);
}

// HeldGrains with a superquadric among polyhedra and spheres: its contact is that of
// wire_superquadric_contact, its bounding radius √(a² + b² + c²); bad shapes rejected.
TEST(WireOnSuperquadric, HeldAmongOtherGrains) {
  ShapeLibrary library;
  HeldGrain g;
  g.tag = 4;
  g.shape = HeldGrain::kSuperquadric;
  g.superquadric.half_axes = Vector3d(0.5, 0.35, 0.8);
  g.superquadric.n1 = 3.0;
  g.position = Vector3d(0.0, 0.0, 1.0);
  g.orientation = Eigen::Quaterniond(0.9, 0.1, 0.3, 0.0);
  g.motion.mass = 1.5;
  HeldGrain sphere;
  sphere.tag = 2;
  sphere.shape = HeldGrain::kSphere;
  sphere.sphere_radius = 0.4;
  sphere.position = Vector3d(3.0, 0.0, 0.0);
  sphere.motion.mass = 1.0;
  const HeldGrains held({g, sphere}, library, PeriodicBox(), 1.0);
  const int k = held.index_of(4);
  ASSERT_GE(k, 0);
  EXPECT_NEAR(held.bounding_radius(k), std::sqrt(0.25 + 0.35 * 0.35 + 0.64), 1e-15);
  WireSegmentState s;
  s.radius = 0.1;
  s.m0 = s.m1 = 0.01;
  // across the grain's highest point, 0.02 into it
  const Vector3d top = PosedSuperquadric(g.superquadric, g.position, g.orientation).support(Vector3d::UnitZ());
  s.x0 = top + Vector3d(-0.4, 0.1, 0.08);
  s.x1 = top + Vector3d(0.4, -0.1, 0.08);
  TangentialHistory h1, h2;
  const WireGrainContact a = held.contact(k, Vector3d::Zero(), law(), s, 1e-4, h1);
  const WireGrainContact b =
      wire_superquadric_contact(law(), PosedSuperquadric(g.superquadric, g.position, g.orientation), g.motion, s,
                                1e-4, h2);
  ASSERT_TRUE(a.touching);
  EXPECT_NEAR(a.overlap, 0.02, 1e-3);
  EXPECT_EQ(a.force_bead0, b.force_bead0);
  EXPECT_EQ(a.torque_grain, b.torque_grain);
  int visited = 0;
  held.for_each_candidate(s.x0, s.x1, s.radius, 0.0, [&](int j, const Vector3d&) { visited += j == k; });
  EXPECT_EQ(visited, 1);
  g.superquadric.n2 = 1.0;
  try {
    HeldGrains bad({g}, library, PeriodicBox(), 1.0);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), "blockiness");
  }
}

// Volume and moments against LIGGGHTS-independent references: the ellipsoid (n = 2:
// 4/3 π abc, I_xx = V (b² + c²)/5) and the box limit (n → ∞: 8 abc, I_xx = V (b² + c²)/3,
// approached as n grows); a midpoint-rule integration over the body for n = 3, 4.
TEST(Superquadric, VolumeAndMomentsAgainstEllipsoidBoxAndQuadrature) {
  Superquadric s;
  s.half_axes = Vector3d(0.5, 0.35, 0.8);
  const double a = 0.5, b = 0.35, c = 0.8;
  const double v = 4.0 / 3.0 * kPi * a * b * c;
  EXPECT_NEAR(superquadric_volume(s) / v, 1.0, 1e-14);
  const Vector3d I = superquadric_unit_inertia(s);
  EXPECT_NEAR(I.x() / (v * (b * b + c * c) / 5), 1.0, 1e-14);
  EXPECT_NEAR(I.y() / (v * (a * a + c * c) / 5), 1.0, 1e-14);
  EXPECT_NEAR(I.z() / (v * (a * a + b * b) / 5), 1.0, 1e-14);
  s.n1 = s.n2 = 400.0;
  EXPECT_NEAR(superquadric_volume(s) / (8 * a * b * c), 1.0, 1e-2);
  EXPECT_NEAR(superquadric_unit_inertia(s).x() / (8 * a * b * c * (b * b + c * c) / 3), 1.0, 2e-2);
  for (const double n : {3.0, 4.0}) {
    s.n1 = n;
    s.n2 = n + 1.0;
    const int m = 120;
    double volume = 0.0;
    Vector3d moments = Vector3d::Zero();
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j)
        for (int k = 0; k < m; ++k) {
          const Vector3d x(a * (2 * (i + 0.5) / m - 1), b * (2 * (j + 0.5) / m - 1), c * (2 * (k + 0.5) / m - 1));
          if (superquadric_shape_function(s, x) > 0.0) continue;
          const double dv = 8 * a * b * c / (m * m * m);
          volume += dv;
          moments += dv * Vector3d(x.y() * x.y() + x.z() * x.z(), x.x() * x.x() + x.z() * x.z(),
                                   x.x() * x.x() + x.y() * x.y());
        }
    EXPECT_NEAR(superquadric_volume(s) / volume, 1.0, 3e-3) << n;
    EXPECT_NEAR((superquadric_unit_inertia(s).array() / moments.array() - 1.0).abs().maxCoeff(), 0.0, 5e-3) << n;
  }
}

// The stand-in of a grain: its volume; for n = 2 the ellipsoid of the grain's moments per
// volume (an ellipsoid stands in for itself); bad moments rejected.
TEST(Superquadric, StandInHasTheGrainsVolumeAndAxes) {
  const double a = 0.5, b = 0.35, c = 0.8, v = 4.0 / 3.0 * kPi * a * b * c;
  const Vector3d I(v * (b * b + c * c) / 5, v * (a * a + c * c) / 5, v * (a * a + b * b) / 5);
  const Superquadric e = superquadric_standing_in(v, I, 2.0, 2.0);
  EXPECT_NEAR((e.half_axes - Vector3d(a, b, c)).norm(), 0.0, 1e-14);
  const Superquadric s = superquadric_standing_in(0.3, I, 3.0, 4.0);
  EXPECT_NEAR(superquadric_volume(s) / 0.3, 1.0, 1e-14);
  EXPECT_NEAR(s.half_axes.x() / s.half_axes.z(), a / c, 1e-14);  // the ellipsoid's proportions
  try {
    superquadric_standing_in(1.0, Vector3d(1.0, 1.0, 3.0), 2.0, 2.0);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), "inertia");
  }
}
