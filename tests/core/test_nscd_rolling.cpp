// A sphere rolling and sliding under the Moreau–Jean step exactly as fix nscd/polyhedra
// runs it (core/nscd/grain_step.h: grain_step, then advance_grain_pose), against the
// rigid-body answers of a uniform sphere (I = 2/5 m r²) on a plane with Coulomb friction:
//  - on an incline of angle α with μ ≥ (2/7) tan α it rolls without slipping,
//        a = (5/7) g sin α,  ω = v / r;
//    below that friction it slides and spins up,
//        a = g (sin α − μ cos α),  dω/dt = (5/2) μ g cos α / r;
//  - launched on a level floor at v0 without spin it slides until v = (5/7) v0 (the
//    angular momentum about the contact point, m r v + I ω, is kept by the friction
//    impulse, which acts at that point), at t* = 2 v0 / (7 μ g), then rolls on at that v.
// Each is a linear update per step with the contact frame fixed, so the scheme reproduces
// them to round-off. Energy (θ-method algebra, one persistent sticking contact at zero gap,
// a sphere so the rotation is exact): E_{k+1} − E_k = h (θ − ½) m g·(v_k − v_{k+1}), i.e.
// conserved at θ = ½ and lost as −(h/2) m g·v(T) over the roll at θ = 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/common/errors.h"
#include "core/geometry/convex_shape.h"
#include "core/geometry/shape_library.h"
#include "core/nscd/grain_step.h"

using namespace wiregrain;
using Eigen::Vector3d;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius = 0.5, kDensity = 1.5;

struct Sphere {
  ShapeLibrary library;
  GrainState state;
  Sphere() {
    library.add(ConvexShape::sphere(kRadius));
    state.tag = 1;
    state.shape = 0;
    state.mass = kDensity * library[0].volume;
    state.inertia = kDensity * library[0].unit_inertia;
    state.position = Vector3d(0, 0, kRadius);  // resting on z = 0
  }
  double moment() const { return state.inertia.x(); }
  double energy(const Vector3d& gravity) const {
    return 0.5 * state.mass * state.velocity.squaredNorm() +
           0.5 * moment() * state.angular_velocity.squaredNorm() - state.mass * gravity.dot(state.position);
  }
};

// `steps` steps of the fix's scheme against the floor z = 0 under `gravity` (a tilted
// gravity is an incline), friction mu, rolling resistance mu_r, Siconos' error driven to
// 1e-14.
void run(Sphere& s, const Vector3d& gravity, double mu, double h, double theta, int steps, double mu_r = 0.0) {
  GrainStepOptions options;
  options.friction = mu;
  options.rolling_friction = mu_r;
  options.solver.tolerance = 1e-14;
  options.solver.max_iterations = 1000;
  options.law.theta = theta;
  std::vector<PlaneWall> walls(1);  // the floor: through 0, normal +z
  walls[0].friction = mu;
  GrainImpulseMemory memory;
  for (int k = 0; k < steps; ++k) {
    GrainState& g = s.state;
    g.force = g.mass * gravity;
    const GrainStepResult r = grain_step({g}, s.library, walls, h, options, (std::uint64_t)k, memory);
    ASSERT_FALSE(r.stats.hit_iteration_cap) << "step " << k;
    const Vector3d momentum_begin = s.moment() * g.angular_velocity;  // a sphere: L = I ω in any frame
    const Vector3d momentum_end = s.moment() * r.angular_velocities[0];
    const GrainPose pose = advance_grain_pose({g.position, g.orientation}, g.inertia, g.velocity, r.velocities[0],
                                              momentum_begin, momentum_end, h, theta);
    g.position = pose.position;
    g.orientation = pose.orientation;
    g.velocity = r.velocities[0];
    g.angular_velocity = r.angular_velocities[0];
  }
}

Vector3d incline_gravity(double alpha) { return Vector3d(std::sin(alpha), 0.0, -std::cos(alpha)); }

}  // namespace

TEST(NscdRolling, SphereRollsDownAnInclineAtFiveSeventhsOfGSinAlpha) {
  const double alpha = 30.0 * kPi / 180.0, h = 1e-3;
  const int steps = 2000;
  for (double theta : {1.0, 0.5}) {
    Sphere s;
    const Vector3d gravity = incline_gravity(alpha);
    const double E0 = s.energy(gravity);
    run(s, gravity, 0.5, h, theta, steps);  // μ = 0.5 > (2/7) tan 30° = 0.165
    const double T = steps * h, v = s.state.velocity.x();
    const double v_exact = 5.0 / 7.0 * std::sin(alpha) * T;
    const double energy_change = s.energy(gravity) - E0;
    const double theta_term = -(theta - 0.5) * h * s.state.mass * gravity.dot(s.state.velocity);
    std::printf("[rolling] theta %.1f: v/v_exact - 1 = %.1e, omega r/v - 1 = %.1e, z - r = %.1e, dE %.3e (theta term "
                "%.3e, difference / (m v^2) %.1e)\n",
                theta, v / v_exact - 1.0, s.state.angular_velocity.y() * kRadius / v - 1.0,
                s.state.position.z() - kRadius, energy_change, theta_term,
                (energy_change - theta_term) / (s.state.mass * v * v));
    // measured: 8.9e-16, 0, 0 and 1.1e-14 m v² (both θ)
    EXPECT_NEAR(v / v_exact, 1.0, 1e-14);
    EXPECT_NEAR(s.state.angular_velocity.y() * kRadius / v, 1.0, 1e-14);  // rolls: ω r = v
    EXPECT_NEAR(s.state.position.z(), kRadius, 1e-14);
    EXPECT_NEAR(energy_change, theta_term, 1e-13 * s.state.mass * v * v);
  }
}

TEST(NscdRolling, SphereSlidesAndSpinsUpBelowTheRollingFriction) {
  const double alpha = 30.0 * kPi / 180.0, mu = 0.1, h = 1e-3;  // μ < (2/7) tan α
  const int steps = 2000;
  Sphere s;
  run(s, incline_gravity(alpha), mu, h, 1.0, steps);
  const double T = steps * h;
  const double v_exact = (std::sin(alpha) - mu * std::cos(alpha)) * T;
  const double omega_exact = 2.5 * mu * std::cos(alpha) / kRadius * T;
  std::printf("[sliding] v/v_exact - 1 = %.1e, omega/omega_exact - 1 = %.1e\n", s.state.velocity.x() / v_exact - 1.0,
              s.state.angular_velocity.y() / omega_exact - 1.0);
  // measured: 2.2e-14 and 2.7e-14 (the round-off of 2000 increments)
  EXPECT_NEAR(s.state.velocity.x() / v_exact, 1.0, 2e-13);
  EXPECT_NEAR(s.state.angular_velocity.y() / omega_exact, 1.0, 2e-13);
}

TEST(NscdRolling, LaunchedSphereSlidesThenRollsAtFiveSeventhsOfItsSpeed) {
  const double v0 = 1.0, mu = 0.2, h = 1e-3;
  const double t_roll = 2.0 * v0 / (7.0 * mu);  // 1.43
  Sphere s;
  s.state.velocity = Vector3d(v0, 0, 0);
  const Vector3d gravity(0, 0, -1.0);
  run(s, gravity, mu, h, 1.0, 1000);  // t = 1 < t*: still sliding, v = v0 − μ g t
  std::printf("[launch] at t = 1 v - (v0 - mu g t) = %.1e\n", s.state.velocity.x() - (v0 - mu * 1.0));
  EXPECT_NEAR(s.state.velocity.x(), v0 - mu * 1.0, 2e-13);  // measured 2.2e-14
  run(s, gravity, mu, h, 1.0, 2000);  // t = 3 > t*: rolling
  const double v = s.state.velocity.x();
  std::printf("[launch] rolls at v/v0 = %.15f (5/7 = %.15f) after t* = %.3f, omega r - v = %.1e\n", v / v0, 5.0 / 7.0,
              t_roll, s.state.angular_velocity.y() * kRadius - v);
  EXPECT_NEAR(v / v0, 5.0 / 7.0, 2e-13);                          // measured 2.1e-14
  EXPECT_NEAR(s.state.angular_velocity.y() * kRadius, v, 1e-14);  // measured 0
}

// Rolling resistance (GrainStepOptions::rolling_friction μ_r; core/nscd/body_operator.h): a couple of
// at most μ_r R r_n with R = the sphere's radius (its sweep radius; the floor's is 0).
// Rolling without slip, m v' = F and I ω' = −r F − μ_r r m g with v = ω r, give
// v' = −μ_r r² m g / (I + m r²) = −(5/7) μ_r g: a sphere set rolling at v0 on a level
// floor slows down at that rate, each θ = 1 step by exactly h (5/7) μ_r g, and stops in
// the step where that would reverse it; it then stays (nothing drives it).
TEST(NscdRolling, RollingResistanceStopsARollingSphereAtFiveSeventhsOfMuRG) {
  const double v0 = 0.1, mu = 0.5, mu_r = 0.1, g = 1.0, h = 1e-3;
  const double deceleration = 5.0 / 7.0 * mu_r * g;
  const int steps_to_stop = static_cast<int>(std::ceil(v0 / (deceleration * h)));  // 1400
  Sphere s;
  s.state.velocity = Vector3d(v0, 0, 0);
  s.state.angular_velocity = Vector3d(0, v0 / kRadius, 0);  // rolling
  const Vector3d gravity(0, 0, -g);
  double x_expected = s.state.position.x();
  for (int k = 1; k <= steps_to_stop + 500; ++k) {
    run(s, gravity, mu, h, 1.0, 1, mu_r);
    const double v_expected = std::max(0.0, v0 - k * h * deceleration);
    x_expected += h * v_expected;  // θ = 1: x_{k+1} = x_k + h v_{k+1}
    ASSERT_NEAR(s.state.velocity.x(), v_expected, 1e-13 * v0) << "step " << k;
    ASSERT_NEAR(s.state.angular_velocity.y() * kRadius, s.state.velocity.x(), 1e-13 * v0) << "step " << k;
  }
  std::printf("[rolling resistance] stopped after %d steps at x = %.15f (expected %.15f; continuous "
              "v0^2 / (2 a) = %.6f)\n",
              steps_to_stop, s.state.position.x(), x_expected, v0 * v0 / (2.0 * deceleration));
  EXPECT_NEAR(s.state.position.x(), x_expected, 1e-12);
  EXPECT_LT(s.state.velocity.norm() + kRadius * s.state.angular_velocity.norm(), 1e-14);
}

// On an incline (μ ≥ tan α, so the contact sticks) the sphere stays at rest while the
// couple needed, r m g sin α, is within μ_r r m g cos α, i.e. tan α ≤ μ_r, and otherwise
// rolls down at (5/7) g (sin α − μ_r cos α).
TEST(NscdRolling, RollingResistanceHoldsASphereOnAnInclineUpToTanAlphaMuR) {
  const double mu = 0.5, mu_r = 0.2, h = 1e-3;
  const int steps = 1000;
  for (double tan_alpha : {0.1, 0.19, 0.21, 0.3}) {
    const double alpha = std::atan(tan_alpha);
    Sphere s;
    run(s, incline_gravity(alpha), mu, h, 1.0, steps, mu_r);
    const double v_expected =
        tan_alpha <= mu_r ? 0.0 : 5.0 / 7.0 * (std::sin(alpha) - mu_r * std::cos(alpha)) * steps * h;
    std::printf("[rolling resistance] tan alpha %.2f: v %.15f (expected %.15f), omega r - v %.1e\n", tan_alpha,
                s.state.velocity.x(), v_expected, s.state.angular_velocity.y() * kRadius - s.state.velocity.x());
    EXPECT_NEAR(s.state.velocity.x(), v_expected, 1e-13) << tan_alpha;
    EXPECT_NEAR(s.state.angular_velocity.y() * kRadius, s.state.velocity.x(), 1e-13) << tan_alpha;
    EXPECT_NEAR(s.state.position.z(), kRadius, 1e-13) << tan_alpha;
  }
}

// The rolling law where W_r is not a multiple of the identity (a body of unequal moments
// of inertia, so the couple on the disc's edge solves the 2×2 secular equation): a body
// spinning about a horizontal axis on a floor contact whose couple cannot stop it within
// one step ends the step with |m| = μ_r R r_n and its rolling velocity w opposed to m
// (Coulomb's law on the disc, checked from the returned velocities, not from the solver's
// own quantities); the same with a large bound sticks (w = 0).
TEST(NscdRolling, CoupleOnTheDiscEdgeOpposesTheRollingVelocity) {
  const double h = 1e-3, g = 1.0;
  for (double rolling : {1e-2, 1e3}) {
    NscdStep step;
    step.time_step = h;
    NscdBody body;
    body.inverse_mass = 1.0;
    body.inverse_inertia = Eigen::Vector3d(1.0, 4.0, 2.0).asDiagonal();
    body.velocity_free = Vector3d(0, 0, -g * h);
    body.angular_velocity_begin = body.angular_velocity_free = Vector3d(0.3, 0.2, 0.05);
    step.bodies.push_back(body);
    NscdContact contact;
    contact.body_b = 0;
    const Eigen::Matrix3d frame = contact_frame(Vector3d::UnitZ());
    contact.jacobian_b = contact_jacobian(frame, Vector3d(0, 0, -0.5), 1.0);
    contact.friction = 10.0;  // sticks
    contact.rolling_friction = rolling;  // μ_r R = rolling: R = 1
    contact.rolling_radius = 1.0;
    step.contacts.push_back(contact);
    SolverSettings options;
    options.tolerance = 1e-14;
    options.max_iterations = 10000;
    const NscdStepResult result = solve_nscd_step(step, options);
    ASSERT_FALSE(result.contacts.report.hit_iteration_cap);
    const double r_n = result.contacts.impulses[0][0];
    const Vector3d m = frame.rightCols<2>() * result.contacts.couples[0];
    const Vector3d w = result.angular_velocities[0] - result.angular_velocities[0].z() * Vector3d::UnitZ();
    std::printf("[rolling law] bound %g: r_n %.6e, |m| / (bound r_n) %.15f, |w| %.3e, w x m / (|w||m|) %.1e, "
                "w.m / (|w||m|) %.6f\n",
                rolling, r_n, m.norm() / (rolling * r_n), w.norm(), w.cross(m).z() / (w.norm() * m.norm()),
                w.dot(m) / (w.norm() * m.norm()));
    EXPECT_GT(r_n, 0.0);
    if (rolling < 1.0) {
      EXPECT_NEAR(m.norm() / (rolling * r_n), 1.0, 1e-12);
      EXPECT_GT(w.norm(), 0.1);
      EXPECT_NEAR(w.dot(m) / (w.norm() * m.norm()), -1.0, 1e-12);
    } else {
      EXPECT_LT(m.norm(), rolling * r_n);
      EXPECT_LT(w.norm(), 1e-13);
    }
  }
}

TEST(NscdRolling, RollingFrictionWithoutARadiusNamesTheContact) {
  NscdStep step;
  step.time_step = 1e-3;
  step.bodies.resize(1);
  step.bodies[0].inverse_mass = 1.0;
  step.bodies[0].inverse_inertia = Eigen::Matrix3d::Identity();
  NscdContact contact;
  contact.body_b = 0;
  contact.jacobian_b = contact_jacobian(contact_frame(Vector3d::UnitZ()), Vector3d(0, 0, -0.5), 1.0);
  contact.rolling_friction = 0.1;
  step.contacts.push_back(contact);
  try {
    solve_nscd_step(step, SolverSettings());
    ADD_FAILURE();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), "contacts");
    EXPECT_NE(std::string(e.what()).find("needs a rolling radius > 0"), std::string::npos) << e.what();
  }
}

TEST(NscdRolling, NegativeRollingFrictionNamesTheKeyword) {
  GrainStepOptions options;
  options.rolling_friction = -0.1;
  try {
    options.validate();
    ADD_FAILURE();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), "rolling_friction");
  }
}

// rolling_axes (core/nscd/grain_step.h): an axis e is left to the couples where the
// pair's points spread across it by a half-width w_e ≤ μ_r R (`arm`). Expected from the
// geometry: one point keeps both axes; an edge of length L along x (half-width across x
// 0, along x L/2) keeps x alone for L/2 > arm and both for L/2 ≤ arm; a square face of
// side 1 none; points along y within 0.01 of the line keep y for arm 0.02 and none for
// arm 0.005. The normal's sign does not matter.
TEST(NscdRolling, RollingAxesFollowTheSpreadOfThePairsPoints) {
  const Vector3d n = Vector3d::UnitZ();
  EXPECT_EQ(rolling_axes({Vector3d(1, 2, 3)}, n, 0.02).count, 2);
  for (const Vector3d& normal : {n, Vector3d(-n)}) {
    const RollingAxes edge = rolling_axes({Vector3d(-0.5, 0.3, 0), Vector3d(0.5, 0.3, 0)}, normal, 0.02);
    EXPECT_EQ(edge.count, 1);
    EXPECT_NEAR(std::abs(edge.axis.x()), 1.0, 1e-15);
    EXPECT_NEAR(edge.axis.norm(), 1.0, 1e-15);
  }
  EXPECT_EQ(rolling_axes({Vector3d(0, 0, 0), Vector3d(0.03, 0, 0)}, n, 0.02).count, 2);
  EXPECT_EQ(rolling_axes({Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(1, 1, 0), Vector3d(0, 1, 0)}, n, 0.02).count, 0);
  const std::vector<Vector3d> near_line = {Vector3d(0, 0, 0), Vector3d(0.01, 0.5, 0), Vector3d(-0.01, 1, 0)};
  const RollingAxes kept = rolling_axes(near_line, n, 0.02);
  EXPECT_EQ(kept.count, 1);
  EXPECT_GT(std::abs(kept.axis.y()), 0.999);
  EXPECT_EQ(rolling_axes(near_line, n, 0.005).count, 0);
}

// A rounded box resting face down on the floor: its four points hold it against rolling
// themselves, so it carries no couple, and every step after the first converges in one
// sweep to rest (with a couple at each of the four points, redundant with their normal
// impulses, every step hit the 1000-sweep cap).
TEST(NscdRolling, BoxRestingOnAFaceCarriesNoCoupleAndConvergesInOneSweep) {
  ShapeLibrary library;
  library.add(ConvexShape::box(1.0, 0.9, 0.8, 0.1));
  GrainState box;
  box.tag = 1;
  box.mass = library[0].volume;
  box.inertia = library[0].unit_inertia;
  box.position = Vector3d(0, 0, 0.4 + 0.1);
  std::vector<PlaneWall> walls(1);
  GrainStepOptions options;
  options.rolling_friction = 0.1;
  options.solver.tolerance = 1e-10;
  GrainImpulseMemory memory;
  for (int k = 0; k < 200; ++k) {
    box.force = Vector3d(0, 0, -box.mass);
    const GrainStepResult r = grain_step({box}, library, walls, 1e-3, options, (std::uint64_t)k, memory);
    ASSERT_EQ(r.stats.contact_points, 4);
    if (k > 0) ASSERT_EQ(r.stats.sweeps, 1) << "step " << k;
    ASSERT_LT(r.velocities[0].norm() + r.angular_velocities[0].norm(), 1e-14) << "step " << k;
    for (const auto& entry : memory.points()) ASSERT_EQ(entry.impulse.couple.norm(), 0.0) << "step " << k;
  }
}

// A couple restricted to one axis (NscdContact::rolling_axis): a body on two frictionless
// floor points along x (an edge), spinning about x (the edge: rolling) and about z (spin).
// The normal impulses have no moment about x or z, so only the couples act about x: each
// step takes μ_r R Σ r_n = μ_r R m g h off I_x ω_x until ω_x is 0; ω_z is untouched and
// the couples have no component along y (the axis the points hold themselves).
TEST(NscdRolling, OneAxisCoupleResistsOnlyRollingAboutTheEdge) {
  const double h = 1e-3, g = 1.0, arm = 0.05, inertia_x = 0.2, omega_x0 = 0.1, omega_z0 = 0.3;
  NscdBody body;
  body.inverse_mass = 1.0;
  body.inverse_inertia = Eigen::Vector3d(1.0 / inertia_x, 1.0 / 0.3, 1.0 / 0.4).asDiagonal();
  const Eigen::Matrix3d frame = contact_frame(Vector3d::UnitZ());
  NscdStep step;
  step.time_step = h;
  for (double x : {-0.5, 0.5}) {
    NscdContact contact;
    contact.body_b = 0;
    contact.jacobian_b = contact_jacobian(frame, Vector3d(x, 0, -0.5), 1.0);
    contact.rolling_friction = arm / 0.5;  // μ_r R = arm with R = 0.5
    contact.rolling_radius = 0.5;
    contact.rolling_axis = Vector3d::UnitX();
    step.contacts.push_back(contact);
  }
  SolverSettings options;
  options.tolerance = 1e-14;
  Vector3d omega(omega_x0, 0, omega_z0);
  const int steps_to_stop = static_cast<int>(std::ceil(omega_x0 * inertia_x / (arm * g * h)));  // 400
  for (int k = 1; k <= steps_to_stop + 10; ++k) {
    body.velocity_begin = Vector3d::Zero();
    body.velocity_free = Vector3d(0, 0, -g * h);
    body.angular_velocity_begin = body.angular_velocity_free = omega;
    step.bodies = {body};
    const NscdStepResult result = solve_nscd_step(step, options);
    ASSERT_FALSE(result.contacts.report.hit_iteration_cap);
    omega = result.angular_velocities[0];
    const double expected = std::max(0.0, omega_x0 - k * arm * g * h / inertia_x);
    ASSERT_NEAR(omega.x(), expected, 1e-14) << "step " << k;  // round-off of 400 steps
    ASSERT_NEAR(omega.z(), omega_z0, 1e-15) << "step " << k;
    ASSERT_NEAR(omega.y(), 0.0, 1e-15) << "step " << k;
    for (int c = 0; c < 2; ++c) ASSERT_EQ((frame.rightCols<2>() * result.contacts.couples[c]).y(), 0.0) << "step " << k;
  }
}

// Couples are warm-started as the impulses are (GrainImpulseMemory::Impulse::couple): a
// sphere resting on an incline with tan α ≤ μ_r needs the couple r m g h sin α against
// the moment of the friction that holds it; from the second step on it starts from last
// step's couple and one sweep settles both.
TEST(NscdRolling, WarmStartedCoupleHoldsASphereOnAnInclineInOneSweep) {
  const double alpha = std::atan(0.1), h = 1e-3;
  Sphere s;
  GrainStepOptions options;
  options.friction = 0.5;
  options.rolling_friction = 0.2;
  options.solver.tolerance = 1e-12;
  std::vector<PlaneWall> walls(1);
  walls[0].friction = 0.5;
  GrainImpulseMemory memory;
  for (int k = 0; k < 50; ++k) {
    s.state.force = s.state.mass * incline_gravity(alpha);
    const GrainStepResult r = grain_step({s.state}, s.library, walls, h, options, (std::uint64_t)k, memory);
    if (k > 1) ASSERT_EQ(r.stats.sweeps, 1) << "step " << k;
    s.state.velocity = r.velocities[0];
    s.state.angular_velocity = r.angular_velocities[0];
    ASSERT_EQ(memory.points().size(), 1u);
    const Vector3d couple = memory.points()[0].impulse.couple;
    ASSERT_NEAR(couple.norm(), kRadius * s.state.mass * h * std::sin(alpha), 1e-12 * s.state.mass * h) << "step " << k;
  }
  EXPECT_LT(s.state.velocity.norm() + kRadius * s.state.angular_velocity.norm(), 1e-12);
}
