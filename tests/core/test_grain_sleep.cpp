// Sleeping grains (core/nscd/grain_step.h, SleepOptions): what sleeping must
// not change (the loads a pile carries once at rest, the motion of a grain a wall
// pushes, of a grain pulled off its rest), against hand-worked statics and kinematics,
// and what it must skip (no detection or solve among sleeping grains).
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "core/common/errors.h"
#include "core/geometry/convex_shape.h"
#include "core/nscd/grain_step.h"

using namespace wiregrain;

namespace {

constexpr double kG = 9.81, kMass = 2.0, kH = 1e-3;

// a unit cube (m = 2, I = m/6) at (x, 0, z) under gravity along −z
GrainState cube(long tag, double x, double z) {
  GrainState g;
  g.tag = tag;
  g.position = Eigen::Vector3d(x, 0, z);
  g.force = Eigen::Vector3d(0, 0, -kMass * kG);
  g.mass = kMass;
  g.inertia = Eigen::Vector3d::Constant(kMass / 6.0);
  return g;
}

PlaneWall wall(const Eigen::Vector3d& point, const Eigen::Vector3d& normal, double friction) {
  PlaneWall w;
  w.point = point;
  w.normal = normal;
  w.friction = friction;
  return w;
}

GrainStepOptions options_sleeping(double speed) {
  GrainStepOptions options;
  options.solver.tolerance = 1e-12;
  options.solver.max_iterations = 100000;
  options.sleep.speed = speed;
  options.sleep.time = 0.05;  // 50 steps
  return options;
}

// Grains, walls and the step's memory, advanced step by step as fix nscd/polyhedra does:
// the step, then the θ-method pose update, the walls moved, the sleep state carried.
struct Scene {
  std::vector<GrainState> grains;
  std::vector<PlaneWall> walls;
  GrainImpulseMemory memory;
  GrainStepResult last;
  std::uint64_t step = 0;
  int woken = 0;                 // over all steps
  int most_woken_in_a_step = 0;
  double largest_wall_force = 0.0;  // |force| on wall 0, over all steps

  void run(const ShapeLibrary& library, const GrainStepOptions& options, int steps) {
    for (int s = 0; s < steps; s++) {
      last = grain_step(grains, library, walls, kH, options, step++, memory);
      woken += last.stats.woken;
      most_woken_in_a_step = std::max(most_woken_in_a_step, last.stats.woken);
      if (!last.wall_forces.empty()) largest_wall_force = std::max(largest_wall_force, last.wall_forces[0].norm());
      for (size_t k = 0; k < grains.size(); k++) {
        GrainState& g = grains[k];
        const Eigen::Matrix3d r = g.orientation.toRotationMatrix();
        const Eigen::Matrix3d inertia = r * g.inertia.asDiagonal() * r.transpose();
        const GrainPose pose =
            advance_grain_pose({g.position, g.orientation}, g.inertia, g.velocity, last.velocities[k],
                               inertia * g.angular_velocity, inertia * last.angular_velocities[k], kH,
                               options.law.theta);
        g.position = pose.position;
        g.orientation = pose.orientation;
        g.velocity = last.velocities[k];
        g.angular_velocity = last.angular_velocities[k];
        g.asleep = !last.asleep.empty() && last.asleep[k];
        g.quiet_time = last.quiet_time.empty() ? 0.0 : last.quiet_time[k];
        g.drift = last.drift.empty() ? Eigen::Vector3d::Zero() : last.drift[k];
        g.drift_angular = last.drift_angular.empty() ? Eigen::Vector3d::Zero() : last.drift_angular[k];
        g.load = last.load.empty() ? Eigen::Vector3d::Zero() : last.load[k];
        g.load_moment = last.load_moment.empty() ? Eigen::Vector3d::Zero() : last.load_moment[k];
      }
      for (PlaneWall& w : walls) w.point += kH * w.velocity;
    }
  }
  // the normal load carried across the face between cubes a and b (sum of the points' forces)
  double load(long a, long b) const {
    double sum = 0.0;
    for (const ContactRecord& c : last.contacts.records())
      if (c.a == a && c.b == b) sum += c.force.z();
    return sum;
  }
};

ShapeLibrary cube_library() {
  ShapeLibrary library;
  library.add(ConvexShape::cube(1.0, 0.0));
  return library;
}

// Two cubes stacked on a frictionless floor, run for 60 steps (they fall asleep after 50).
Scene sleeping_pair(const ShapeLibrary& library, const GrainStepOptions& options) {
  Scene scene;
  scene.grains = {cube(1, 0.0, 0.5), cube(2, 0.0, 1.5)};
  scene.walls.push_back(wall(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 0.0));
  scene.run(library, options, 60);
  return scene;
}

}  // namespace

// Three cubes stacked on the floor fall asleep: nothing is detected or solved any more,
// yet the frozen contacts still carry k m g at each interface, and while nothing changes
// no sleeper is even checked. A fourth cube dropped on the stack: a perfectly inelastic
// impact on a stack standing on the floor moves none of it, so the stack stays asleep,
// the checks carry the impact down to the floor within the landing step (the same
// largest floor force as without sleeping, the falling cube's same trajectory), and once
// all sleep every interface carries k m g (statics) to 1e-9 relative.
TEST(GrainSleep, StackWakesUnderADroppedCubeAndCarriesTheNewWeights) {
  const ShapeLibrary library = cube_library();
  Scene scene;
  for (int k = 0; k < 3; k++) scene.grains.push_back(cube(k + 1, 0.0, 0.5 + k));
  scene.walls.push_back(wall(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 0.5));
  const GrainStepOptions options = options_sleeping(1e-3);
  scene.run(library, options, 60);
  ASSERT_EQ(scene.last.stats.sleeping, 3);
  EXPECT_EQ(scene.last.stats.contact_points, 0);  // nothing solved
  EXPECT_EQ(scene.last.stats.frozen_points, 12);  // 4 corners at each of 3 faces
  const double w = kMass * kG;
  EXPECT_NEAR(scene.load(-1, 1), 3 * w, 3 * w * 1e-9);
  EXPECT_NEAR(scene.load(1, 2), 2 * w, 2 * w * 1e-9);
  EXPECT_NEAR(scene.load(2, 3), w, w * 1e-9);
  EXPECT_NEAR(scene.last.wall_forces[0].z(), -3 * w, 3 * w * 1e-9);
  EXPECT_NEAR(scene.last.contact_forces[0].z(), w, w * 1e-9);  // frozen forces in the grain's sum
  const Eigen::Vector3d top = scene.grains[2].position;
  scene.run(library, options, 200);  // asleep all along: nothing moves, the loads stay
  EXPECT_EQ(scene.woken, 0);
  EXPECT_EQ(scene.last.stats.sleeper_checks, 0);
  EXPECT_EQ(scene.grains[2].position, top);
  EXPECT_NEAR(scene.load(-1, 1), 3 * w, 3 * w * 1e-9);

  scene.grains.push_back(cube(4, 0.0, 3.7));  // 0.2 above the stack: lands at t ≈ 0.2
  Scene awake = scene;
  GrainStepOptions off = options;
  off.sleep.speed = 0.0;
  for (GrainState& g : awake.grains) g.asleep = false;
  scene.largest_wall_force = awake.largest_wall_force = 0.0;
  scene.run(library, options, 150);
  EXPECT_EQ(scene.last.stats.sleeping, 3);  // still falling: the stack sleeps on
  scene.run(library, options, 850);
  awake.run(library, off, 1000);
  EXPECT_EQ(scene.woken, 0);
  EXPECT_EQ(scene.grains[2].position, top);
  EXPECT_GT(scene.largest_wall_force, 10 * 4 * w);  // the impact
  EXPECT_NEAR(scene.largest_wall_force, awake.largest_wall_force, 1e-9 * awake.largest_wall_force);
  EXPECT_NEAR((scene.grains[3].position - awake.grains[3].position).norm(), 0.0, 1e-12);
  ASSERT_EQ(scene.last.stats.sleeping, 4);
  EXPECT_NEAR(scene.load(-1, 1), 4 * w, 4 * w * 1e-9);
  EXPECT_NEAR(scene.load(1, 2), 3 * w, 3 * w * 1e-9);
  EXPECT_NEAR(scene.load(2, 3), 2 * w, 2 * w * 1e-9);
  EXPECT_NEAR(scene.load(3, 4), w, w * 1e-9);
  EXPECT_NEAR(scene.grains[3].position.z(), 3.5, 1e-9);
}

// A cube asleep on a frictionless floor; a frictionless side wall moving at 1 reaches it
// at t = 0.1: the cube wakes and goes on with the wall, its face on the wall's plane
// (kinematics), the same trajectory as without sleeping.
TEST(GrainSleep, MovingWallWakesTheCubeItReaches) {
  const ShapeLibrary library = cube_library();
  Scene scene, awake;
  scene.grains.push_back(cube(1, 0.0, 0.5));
  scene.walls.push_back(wall(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 0.0));
  scene.walls.push_back(wall(Eigen::Vector3d(-0.6, 0, 0), Eigen::Vector3d::UnitX(), 0.0));
  awake = scene;
  scene.run(library, options_sleeping(1e-3), 60);
  EXPECT_EQ(scene.last.stats.sleeping, 1);
  scene.walls[1].velocity = awake.walls[1].velocity = Eigen::Vector3d(1, 0, 0);
  scene.walls[1].point = awake.walls[1].point = Eigen::Vector3d(-0.6, 0, 0);
  awake.grains = scene.grains;
  scene.run(library, options_sleeping(1e-3), 300);
  GrainStepOptions off = options_sleeping(1e-3);
  off.sleep.speed = 0.0;
  awake.run(library, off, 300);
  EXPECT_EQ(scene.woken, 1);
  EXPECT_EQ(scene.last.stats.sleeping, 0);
  const double wall_x = -0.6 + 300 * kH;
  EXPECT_NEAR(scene.grains[0].position.x(), wall_x + 0.5, 1e-9);
  EXPECT_NEAR(scene.grains[0].velocity.x(), 1.0, 1e-9);
  EXPECT_NEAR((scene.grains[0].position - awake.grains[0].position).norm(), 0.0, 1e-12);
}

// A cube asleep on a floor of friction 0.5 is pulled sideways at its centre by a force
// (another style's, e.g. the wire's). Below the friction limit, 0.45 m g, the check finds
// it held: it stays asleep and unmoved, the floor's frozen friction carrying the pull from
// the first step (statics). Above it, 0.55 m g, the check finds it sliding, its drift
// growing by (0.55 − 0.5) g h per step: it wakes in step ⌈v_sleep / (0.05 g h)⌉ = 3,
// starting from its drift, so from then on it has the velocity of a cube awake all
// along, k · 0.05 g h after step k (dynamics).
TEST(GrainSleep, PullBelowFrictionIsHeldAboveItWakesTheCube) {
  const ShapeLibrary library = cube_library();
  const GrainStepOptions options = options_sleeping(1e-3);
  Scene scene;
  scene.grains.push_back(cube(1, 0.0, 0.5));
  scene.walls.push_back(wall(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 0.5));
  scene.run(library, options, 60);
  ASSERT_EQ(scene.last.stats.sleeping, 1);
  const Eigen::Vector3d rest = scene.grains[0].position;
  const double held = 0.45 * kMass * kG;
  scene.grains[0].force.x() = held;
  scene.run(library, options, 1);
  EXPECT_NEAR(scene.last.wall_forces[0].x(), held, 1e-9 * held);
  scene.run(library, options, 500);
  EXPECT_EQ(scene.woken, 0);
  EXPECT_EQ(scene.grains[0].position, rest);
  EXPECT_NEAR(scene.last.wall_forces[0].x(), held, 1e-9 * held);
  EXPECT_NEAR(scene.last.wall_forces[0].z(), -kMass * kG, 1e-9 * kMass * kG);

  const double excess = 0.05 * kG * kH;  // velocity gained per step sliding
  scene.grains[0].force.x() = 0.55 * kMass * kG;
  scene.run(library, options, 2);
  EXPECT_EQ(scene.woken, 0);
  EXPECT_EQ(scene.grains[0].position, rest);
  scene.run(library, options, 1);
  EXPECT_EQ(scene.woken, 1);
  EXPECT_NEAR(scene.grains[0].velocity.x(), 3 * excess, 1e-12);
  scene.run(library, options, 200);
  EXPECT_NEAR(scene.grains[0].velocity.x(), 203 * excess, 1e-9);
  EXPECT_EQ(scene.last.stats.sleeping, 0);
}

// Two cubes asleep side by side on a floor of friction 0.5, 0.1 apart; a third slides
// across both at 0.2 over frictionless faces (μ = 0 between grains), so the share of its
// weight each sleeper carries shifts step after step. Each sleeper can stay at rest under
// any share (the floor takes it), so neither wakes in 1000 steps, the sliding cube keeps
// its speed (kinematics), the floor carries the three weights (statics) and no
// sideways force.
TEST(GrainSleep, SleepersUnderASlidingGrainStayAsleep) {
  const ShapeLibrary library = cube_library();
  GrainStepOptions options = options_sleeping(1e-3);
  options.friction = 0.0;
  Scene scene;
  scene.grains = {cube(1, -0.55, 0.5), cube(2, 0.55, 0.5), cube(3, -0.1, 1.5)};
  scene.grains[2].velocity.x() = 0.2;
  scene.walls.push_back(wall(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 0.5));
  scene.run(library, options, 60);
  ASSERT_EQ(scene.last.stats.sleeping, 2);
  const Eigen::Vector3d left = scene.grains[0].position, right = scene.grains[1].position;
  scene.run(library, options, 1000);
  EXPECT_EQ(scene.woken, 0);
  EXPECT_EQ(scene.grains[0].position, left);
  EXPECT_EQ(scene.grains[1].position, right);
  EXPECT_NEAR(scene.grains[2].position.x(), -0.1 + 1060 * kH * 0.2, 1e-9);
  EXPECT_NEAR(scene.grains[2].velocity.x(), 0.2, 1e-12);
  const double w = kMass * kG;
  EXPECT_NEAR(scene.last.wall_forces[0].z(), -3 * w, 3 * w * 1e-9);
  EXPECT_NEAR(scene.last.wall_forces[0].x(), 0.0, 3 * w * 1e-9);
  EXPECT_GT(scene.last.stats.sleeper_checks, 0);
}

// A cube sliding on a frictionless floor at twice the sleep speed never sleeps and
// moves at its speed; one at half of it falls asleep after t_sleep and stops there.
TEST(GrainSleep, OnlyTheSlowSleep) {
  const ShapeLibrary library = cube_library();
  const GrainStepOptions options = options_sleeping(1e-3);
  Scene fast, slow;
  fast.grains.push_back(cube(1, 0.0, 0.5));
  fast.walls.push_back(wall(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 0.0));
  slow = fast;
  fast.grains[0].velocity.x() = 2e-3;
  slow.grains[0].velocity.x() = 0.5e-3;
  fast.run(library, options, 1000);
  slow.run(library, options, 1000);
  EXPECT_EQ(fast.last.stats.sleeping, 0);
  EXPECT_NEAR(fast.grains[0].position.x(), 1000 * kH * 2e-3, 1e-12);
  EXPECT_EQ(slow.last.stats.sleeping, 1);
  EXPECT_EQ(slow.grains[0].velocity.x(), 0.0);
  // asleep at the end of the step that completes t_sleep (50 steps), moving 49 of them at θ = 1
  EXPECT_NEAR(slow.grains[0].position.x(), 49 * kH * 0.5e-3, 1e-12);
}

// A cube falls asleep only when the grains that support it sleep or fall asleep in the
// same step: held, it would no longer press on an awake support. Two stacked cubes, the
// top one quiet for 0.04 already, the bottom one not: they fall asleep together, when the
// bottom one's quiet time reaches t_sleep.
TEST(GrainSleep, NoSleepOnAnAwakeSupport) {
  const ShapeLibrary library = cube_library();
  const GrainStepOptions options = options_sleeping(1e-3);
  Scene scene;
  scene.grains = {cube(1, 0.0, 0.5), cube(2, 0.0, 1.5)};
  scene.grains[1].quiet_time = 0.04;
  scene.walls.push_back(wall(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 0.5));
  scene.run(library, options, 49);
  EXPECT_EQ(scene.last.stats.sleeping, 0);
  scene.run(library, options, 1);
  EXPECT_EQ(scene.last.stats.sleeping, 2);
}

// A cube asleep on another asleep on a frictionless floor; the bottom one is pulled by
// 0.8 m g: it wakes, and the top one, resting on it, wakes with it in the same step; the
// interface (μ = 0.5) holds, so both move off together at a = 0.4 g (dynamics).
TEST(GrainSleep, GrainsRestingOnAWokenGrainWakeWithIt) {
  const ShapeLibrary library = cube_library();
  const GrainStepOptions options = options_sleeping(1e-3);
  Scene scene = sleeping_pair(library, options);
  ASSERT_EQ(scene.last.stats.sleeping, 2);
  scene.grains[0].force.x() = 0.8 * kMass * kG;
  scene.run(library, options, 1);
  EXPECT_EQ(scene.woken, 2);
  EXPECT_NEAR(scene.grains[0].velocity.x(), 0.4 * kG * kH, 1e-12);
  EXPECT_NEAR(scene.grains[1].velocity.x(), 0.4 * kG * kH, 1e-12);
  scene.run(library, options, 99);
  EXPECT_NEAR(scene.grains[1].velocity.x(), 100 * 0.4 * kG * kH, 1e-9);
}

// The same pair, now the top cube pulled by 0.3 m g. Checked first, it is held by the
// cube under it (the interface's friction, μ = 0.5); the bottom cube's check then gets
// that friction as a load, cannot stay on the frictionless floor and wakes, taking the
// top one along: both move off together at 0.15 g from that step (dynamics).
TEST(GrainSleep, PullOnTheTopCubeIsPassedDownAndWakesThePair) {
  const ShapeLibrary library = cube_library();
  const GrainStepOptions options = options_sleeping(1e-3);
  Scene scene = sleeping_pair(library, options);
  ASSERT_EQ(scene.last.stats.sleeping, 2);
  scene.grains[1].force.x() = 0.3 * kMass * kG;
  scene.run(library, options, 1);
  EXPECT_EQ(scene.woken, 2);
  EXPECT_NEAR(scene.grains[0].velocity.x(), 0.15 * kG * kH, 1e-12);
  EXPECT_NEAR(scene.grains[1].velocity.x(), 0.15 * kG * kH, 1e-12);
  scene.run(library, options, 99);
  EXPECT_NEAR(scene.grains[0].velocity.x(), 100 * 0.15 * kG * kH, 1e-9);
}

TEST(GrainSleep, BadOptionsAreRejected) {
  GrainStepOptions options;
  options.sleep.speed = -1e-3;
  try {
    options.validate();
    FAIL() << "a negative sleep speed passed";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), "sleep");
  }
  options.sleep.speed = 1e-3;
  options.sleep.time = 0.0;
  EXPECT_THROW(options.validate(), InvalidArgument);
  options.sleep.time = NAN;
  EXPECT_THROW(options.validate(), InvalidArgument);
}

// The stack of four cubes of StackWakesUnderADroppedCubeAndCarriesTheNewWeights across the
// periodic face x = 10 of a box [0, 10) periodic along x: the cubes stand 0.35, 0.25 and
// 0.15 off each other's axes, alternately on both sides of the face, the stack's tags (and
// grain order) from the top down, so that the points of a pair lie by its upper cube, a
// period away from the lower one's centre, and a sleeper's loads from above and its
// supports both need the minimum image. It falls asleep, the fourth cube lands on it, and
// everything is what the same stack does in the middle of the box (x − 5): nothing wakes,
// the same loads at every interface (statics, k m g) and the same impact on the floor, to
// rounding.
TEST(GrainSleep, StackAcrossAPeriodicFaceSleepsAsInTheMiddle) {
  const ShapeLibrary library = cube_library();
  PeriodicBox box;
  box.lo = Eigen::Vector3d(0, -5, -5);
  box.hi = Eigen::Vector3d(10, 5, 20);
  box.periodic = {true, false, false};
  GrainStepOptions options = options_sleeping(1e-3);
  options.box = box;
  const double across[4] = {9.8, 0.15, 9.9, 0.05};  // images 9.8, 10.15, 9.9, 10.05
  Scene scenes[2];
  for (int side = 0; side < 2; side++) {
    Scene& scene = scenes[side];
    const double shift = side == 0 ? 0.0 : -5.0;
    for (int k = 2; k >= 0; k--)  // tags 1, 2, 3 from the top down
      scene.grains.push_back(cube(3 - k, across[k] + (k % 2 && side ? 10.0 : 0.0) + shift, 0.5 + k));
    scene.walls.push_back(wall(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 0.5));
    scene.run(library, options, 60);
    ASSERT_EQ(scene.last.stats.sleeping, 3) << side;
    scene.grains.push_back(cube(4, across[3] + (side ? 10.0 : 0.0) + shift, 3.7));
    scene.largest_wall_force = 0.0;
    scene.run(library, options, 1000);
    ASSERT_EQ(scene.last.stats.sleeping, 4) << side;
    EXPECT_EQ(scene.woken, 0) << side;
  }
  const double w = kMass * kG;
  // the force on b of each pair (a, b): the dropped cube 4 on the top cube 1 carries w, cube
  // 2 carries 1 and 4 (2 w down), cube 3 1, 2 and 4 (3 w down), the floor all four
  EXPECT_NEAR(scenes[0].load(1, 4), w, 1e-9 * w);
  EXPECT_NEAR(scenes[0].load(1, 2), -2 * w, 2e-9 * w);
  EXPECT_NEAR(scenes[0].load(2, 3), -3 * w, 3e-9 * w);
  EXPECT_NEAR(scenes[0].load(-1, 3), 4 * w, 4e-9 * w);
  EXPECT_GT(scenes[0].largest_wall_force, 10 * 4 * w);  // the impact
  EXPECT_NEAR(scenes[0].largest_wall_force, scenes[1].largest_wall_force, 1e-12 * scenes[1].largest_wall_force);
  for (int k = 0; k < 4; k++)
    EXPECT_NEAR(box.minimum_image(scenes[0].grains[k].position - scenes[1].grains[k].position - Eigen::Vector3d(5, 0, 0))
                    .norm(), 0.0, 1e-12) << k;
  // the loads to the equilibrium checks' tolerance (1e-12): measured 4.4e-10 = 2.2e-11 w apart
  for (const auto& [a, b] : {std::pair<long, long>{1, 4}, {1, 2}, {2, 3}, {-1, 3}})
    EXPECT_NEAR(scenes[0].load(a, b), scenes[1].load(a, b), 1e-10 * w) << a << " " << b;
}
