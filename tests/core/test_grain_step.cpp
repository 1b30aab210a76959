// core/nscd/grain_step: one Moreau–Jean step of grains and walls, against numbers worked
// out by hand (statics of resting cubes, the free and the damped free velocity, the warm
// start, the θ-method pose update).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/common/errors.h"
#include "core/geometry/convex_shape.h"
#include "core/nscd/grain_step.h"
#include "grain_scenes.h"

using namespace wiregrain;

namespace {

constexpr double kG = 9.81, kMass = 2.0, kH = 1e-3;

using test_scenes::floor_wall;
using test_scenes::unit_cube_library;

// a unit cube (m = 2, I = m/6) at rest at height z under gravity g along −z
GrainState resting_cube(long tag, double z) { return test_scenes::unit_cube(tag, Eigen::Vector3d(0, 0, z), kMass, kG); }

GrainStepOptions tight() { return test_scenes::tight_options(1e-15); }

Eigen::Vector3d sum_of_forces(const ContactList& list, ContactKind kind, long a, long b) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const ContactRecord& r : list.records())
    if (r.kind == kind && r.a == a && r.b == b) sum += r.force;
  return sum;
}

// A sphere (one-vertex grain) of radius r, mass m_s, inertia 2/5 m_s r², at rest at
// `centre` under gravity.
GrainState resting_sphere(long tag, int shape, const Eigen::Vector3d& centre, double mass, double radius) {
  return test_scenes::grain_under_gravity(tag, shape, centre, mass, 0.4 * mass * radius * radius, kG);
}

}  // namespace

TEST(GrainStep, CubeOnTheFloorCarriesItsWeight) {
  const ShapeLibrary library = unit_cube_library();
  GrainImpulseMemory memory;
  const GrainStepResult r = grain_step({resting_cube(5, 0.5)}, library, {floor_wall()}, kH, tight(), 0, memory);
  EXPECT_NEAR(r.wall_forces[0].z(), -kMass * kG, 1e-12);          // the grains press on the wall with m g
  EXPECT_NEAR(r.wall_forces[0].head<2>().norm(), 0.0, 1e-12);
  EXPECT_LT(r.velocities[0].norm(), 1e-12);                         // and stay at rest
  EXPECT_LT(r.angular_velocities[0].norm(), 1e-12);
  EXPECT_NEAR(r.contact_forces[0].z(), kMass * kG, 1e-12);
  EXPECT_EQ(r.stats.contact_points, 4);                             // a face on the floor: 4 corners
  EXPECT_FALSE(r.stats.hit_iteration_cap);
  ASSERT_EQ(r.contacts.size(), 4u);
  for (const ContactRecord& c : r.contacts.records()) {
    EXPECT_EQ(c.kind, ContactKind::grain_wall);
    EXPECT_EQ(c.a, -1);
    EXPECT_EQ(c.b, 5);
    EXPECT_NEAR((c.normal - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-12);
    EXPECT_NEAR(c.point.z(), 0.0, 1e-12);
    EXPECT_NEAR(c.overlap, 0.0, 1e-12);
  }
  EXPECT_NEAR((sum_of_forces(r.contacts, ContactKind::grain_wall, -1, 5) - Eigen::Vector3d(0, 0, kMass * kG)).norm(),
              0.0, 1e-12);
}

TEST(GrainStep, TwoStackedCubesCarryOneAndTwoWeights) {
  const ShapeLibrary library = unit_cube_library();
  GrainImpulseMemory memory;
  const GrainStepResult r =
      grain_step({resting_cube(7, 0.5), resting_cube(9, 1.5)}, library, {floor_wall()}, kH, tight(), 0, memory);
  EXPECT_NEAR(r.wall_forces[0].z(), -2.0 * kMass * kG, 1e-11);
  EXPECT_LT(r.velocities[0].norm() + r.velocities[1].norm(), 1e-12);
  // the top cube gets m g from the bottom one; the bottom one 2 m g from the floor − m g from the top
  EXPECT_NEAR(r.contact_forces[1].z(), kMass * kG, 1e-11);
  EXPECT_NEAR(r.contact_forces[0].z(), kMass * kG, 1e-11);
  const Eigen::Vector3d between = sum_of_forces(r.contacts, ContactKind::grain_grain, 7, 9);
  const Eigen::Vector3d floor = sum_of_forces(r.contacts, ContactKind::grain_wall, -1, 7);
  EXPECT_NEAR((between - Eigen::Vector3d(0, 0, kMass * kG)).norm(), 0.0, 1e-11);
  EXPECT_NEAR((floor - Eigen::Vector3d(0, 0, 2.0 * kMass * kG)).norm(), 0.0, 1e-11);
  EXPECT_EQ(r.contacts.size(), 8u);
  // listed from the top down: the interface (z = 1) before the floor (z = 0)
  EXPECT_EQ(r.contacts.records().front().kind, ContactKind::grain_grain);
  EXPECT_EQ(r.contacts.records().back().kind, ContactKind::grain_wall);
}

TEST(GrainStep, SphereOnTheFloorCarriesItsWeight) {
  ShapeLibrary library;
  library.add(ConvexShape::sphere(0.4));
  const double m = 1.3;
  GrainImpulseMemory memory;
  const GrainStepResult r = grain_step({resting_sphere(4, 0, Eigen::Vector3d(0.2, -0.3, 0.4), m, 0.4)}, library,
                                       {floor_wall()}, kH, tight(), 0, memory);
  EXPECT_NEAR(r.wall_forces[0].z(), -m * kG, 1e-12);
  EXPECT_NEAR(r.wall_forces[0].head<2>().norm(), 0.0, 1e-12);
  EXPECT_LT(r.velocities[0].norm(), 1e-12);
  EXPECT_LT(r.angular_velocities[0].norm(), 1e-12);
  EXPECT_LT(r.contact_torques[0].norm(), 1e-12);  // the force goes through the centre
  ASSERT_EQ(r.contacts.size(), 1u);                // one point, below the centre
  const ContactRecord& c = r.contacts.records()[0];
  EXPECT_EQ(c.kind, ContactKind::grain_wall);
  EXPECT_NEAR((c.point - Eigen::Vector3d(0.2, -0.3, 0.0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(c.overlap, 0.0, 1e-15);
  EXPECT_NEAR((c.force - Eigen::Vector3d(0, 0, m * kG)).norm(), 0.0, 1e-12);
}

// A sphere (r = 0.3, m_s = 0.7) resting off-centre on a unit cube on the floor: the cube
// presses on the floor with (m + m_s) g, the sphere on the cube with m_s g.
TEST(GrainStep, SphereOnACubeOnTheFloor) {
  ShapeLibrary library;
  library.add(ConvexShape::cube(1.0, 0.0));
  library.add(ConvexShape::sphere(0.3));
  const double m_s = 0.7;
  GrainImpulseMemory memory;
  const GrainStepResult r =
      grain_step({resting_cube(1, 0.5), resting_sphere(2, 1, Eigen::Vector3d(0.1, -0.2, 1.3), m_s, 0.3)}, library,
                 {floor_wall()}, kH, tight(), 0, memory);
  EXPECT_NEAR(r.wall_forces[0].z(), -(kMass + m_s) * kG, 1e-11);
  EXPECT_NEAR(r.wall_forces[0].head<2>().norm(), 0.0, 1e-11);
  EXPECT_LT(r.velocities[0].norm() + r.velocities[1].norm(), 1e-12);
  EXPECT_LT(r.angular_velocities[0].norm() + r.angular_velocities[1].norm(), 1e-12);
  EXPECT_NEAR(r.contact_forces[1].z(), m_s * kG, 1e-11);
  EXPECT_NEAR(r.contact_forces[0].z(), kMass * kG, 1e-11);
  const Eigen::Vector3d between = sum_of_forces(r.contacts, ContactKind::grain_grain, 1, 2);
  EXPECT_NEAR((between - Eigen::Vector3d(0, 0, m_s * kG)).norm(), 0.0, 1e-11);
  EXPECT_EQ(r.contacts.size(), 5u);  // the sphere's point on the top face, the cube's 4 corners
  const ContactRecord& top = r.contacts.records().front();
  EXPECT_EQ(top.kind, ContactKind::grain_grain);
  EXPECT_NEAR((top.point - Eigen::Vector3d(0.1, -0.2, 1.0)).norm(), 0.0, 1e-14);
}

TEST(GrainStep, FreeGrainGetsTheFreeVelocity) {
  const ShapeLibrary library = unit_cube_library();
  GrainState g = resting_cube(1, 10.0);
  g.velocity = Eigen::Vector3d(1.0, -2.0, 0.3);
  g.force = Eigen::Vector3d(0.5, -1.0, 2.0);
  g.angular_velocity = Eigen::Vector3d(0.2, 0.1, -0.4);
  g.torque = Eigen::Vector3d(0.3, 0.0, 0.1);
  const double h = 0.01;
  GrainImpulseMemory memory;
  const GrainStepResult r = grain_step({g}, library, {floor_wall()}, h, GrainStepOptions(), 0, memory);
  EXPECT_EQ(r.stats.contact_points, 0);
  EXPECT_EQ(r.contacts.size(), 0u);
  const Eigen::Vector3d expected = g.velocity + h * g.force / g.mass;  // v + h F/m, exactly
  for (int d = 0; d < 3; d++) EXPECT_EQ(r.velocities[0][d], expected[d]);
  const Eigen::Vector3d spin = g.angular_velocity + h * g.torque / (kMass / 6.0);  // ω + h T/I (isotropic)
  EXPECT_NEAR((r.angular_velocities[0] - spin).norm(), 0.0, 1e-15);
  EXPECT_EQ(r.contact_forces[0], Eigen::Vector3d::Zero());
  EXPECT_EQ(r.wall_forces[0], Eigen::Vector3d::Zero());
}

TEST(GrainStep, DampingDividesTheFreeVelocity) {
  const ShapeLibrary library = unit_cube_library();
  GrainState g = resting_cube(1, 10.0);
  g.velocity = Eigen::Vector3d(1.0, -2.0, 0.3);
  GrainStepOptions options;
  options.damping = 3.0;
  const double h = 0.01;
  GrainImpulseMemory memory;
  const GrainStepResult r = grain_step({g}, library, {}, h, options, 0, memory);
  const Eigen::Vector3d expected = (g.velocity + h * g.force / g.mass) / (1.0 + h * 3.0);  // (v + hF/m)/(1 + hγ)
  EXPECT_NEAR((r.velocities[0] - expected).norm(), 0.0, 1e-15);
}

TEST(GrainStep, DampedCubeOnTheFloorStillCarriesItsWeight) {
  const ShapeLibrary library = unit_cube_library();
  GrainStepOptions options = tight();
  options.damping = 1000.0;  // h γ = 1
  GrainImpulseMemory memory;
  const GrainStepResult r = grain_step({resting_cube(1, 0.5)}, library, {floor_wall()}, kH, options, 0, memory);
  EXPECT_NEAR(r.wall_forces[0].z(), -kMass * kG, 1e-12);
}

TEST(GrainStep, WarmStartReproducesTheStoredImpulse) {
  const ShapeLibrary library = unit_cube_library();
  const std::vector<GrainState> grains = {resting_cube(3, 0.5)};
  const std::vector<PlaneWall> walls = {floor_wall()};
  GrainImpulseMemory memory;
  const GrainStepResult first = grain_step(grains, library, walls, kH, tight(), 0, memory);
  ASSERT_EQ(memory.points().size(), 4u);  // the four corners of one pair
  for (const GrainImpulseMemory::Entry& e : memory.points()) ASSERT_EQ(e.pair, GrainImpulseMemory::PairKey(-1, 3));
  // the same configuration again: every point starts from its own last impulse (local frame)
  GrainStepProblem problem = assemble_grain_step(grains, library, walls, kH, tight(), memory);
  ASSERT_EQ(problem.warm_start.size(), 4u);
  for (size_t c = 0; c < 4; c++) {
    const ContactRecord& last = first.contacts.records()[c];
    EXPECT_NEAR((problem.points[c].position - last.point).norm(), 0.0, 1e-15);
    const Eigen::Vector3d expected = problem.points[c].frame.transpose() * (last.force * kH);
    EXPECT_NEAR((problem.warm_start[c] - expected).norm(), 0.0, 1e-15);
  }
  const GrainStepResult second = solve_grain_step(problem, grains, tight(), 1, memory);
  EXPECT_LE(second.stats.sweeps, 2);  // starts converged
  EXPECT_NEAR(second.wall_forces[0].z(), -kMass * kG, 1e-12);
  // a stored point farther than R_max/4 from every new point is not used
  GrainImpulseMemory far;
  far.add({-1, 3}, {Eigen::Vector3d(5, 5, 0), Eigen::Vector3d(0, 0, 1)});
  far.commit();
  const GrainStepProblem cold = assemble_grain_step(grains, library, walls, kH, tight(), far);
  for (const Eigen::Vector3d& w : cold.warm_start) EXPECT_EQ(w, Eigen::Vector3d::Zero());
  // warm_start off: no start vector
  GrainStepOptions off = tight();
  off.warm_start = false;
  EXPECT_TRUE(assemble_grain_step(grains, library, walls, kH, off, memory).warm_start.empty());
}

TEST(GrainStep, ThetaMethodPoseUpdate) {
  const Eigen::Vector3d v0(1, 0, -1), v1(3, 2, 1), inertia = Eigen::Vector3d::Ones();
  const GrainPose start{Eigen::Vector3d(0.5, 0, 2), Eigen::Quaterniond::Identity()};
  const double h = 0.1, theta = 0.5, spin = 2.0;
  // L about z, isotropic body: a rotation by the angle spin·h about z
  const GrainPose next = advance_grain_pose(start, inertia, v0, v1, Eigen::Vector3d(0, 0, spin),
                                            Eigen::Vector3d(0, 0, spin), h, theta);
  const Eigen::Vector3d expected = start.position + h * (0.5 * v0 + 0.5 * v1);  // x + h((1 − θ) v_k + θ v_{k+1})
  EXPECT_NEAR((next.position - expected).norm(), 0.0, 1e-15);
  const Eigen::Quaterniond turned(Eigen::AngleAxisd(spin * h, Eigen::Vector3d::UnitZ()));
  EXPECT_NEAR(next.orientation.angularDistance(turned), 0.0, 1e-12);
}

TEST(GrainStep, BadInputIsRejected) {
  const ShapeLibrary library = unit_cube_library();
  GrainImpulseMemory memory;
  GrainState massless = resting_cube(1, 2.0);
  massless.mass = 0.0;
  EXPECT_THROW(grain_step({massless}, library, {}, kH, GrainStepOptions(), 0, memory), InvalidArgument);
  GrainState unknown = resting_cube(1, 2.0);
  unknown.shape = 4;
  EXPECT_THROW(grain_step({unknown}, library, {}, kH, GrainStepOptions(), 0, memory), InvalidArgument);
  EXPECT_THROW(grain_step({resting_cube(1, 2.0)}, library, {}, 0.0, GrainStepOptions(), 0, memory), InvalidArgument);
  GrainStepOptions negative;
  negative.friction = -1.0;
  EXPECT_THROW(grain_step({resting_cube(1, 2.0)}, library, {}, kH, negative, 0, memory), InvalidArgument);
}

// The impulse memory: points added in any order are found by pair after commit (the
// nearest within the radius, none beyond it, none of another pair), a pair's points keep
// the order they were added in, and a recall before the commit is refused.
TEST(GrainImpulseMemory, RecallsTheNearestPointOfThePairAfterCommit) {
  GrainImpulseMemory memory;
  const auto impulse_at = [](double x, double j) {
    return GrainImpulseMemory::Impulse{Eigen::Vector3d(x, 0, 0), Eigen::Vector3d(0, 0, j)};
  };
  memory.add({4, 9}, impulse_at(0.0, 1.0));
  memory.add({-1, 9}, impulse_at(0.0, 2.0));
  memory.add({4, 9}, impulse_at(1.0, 3.0));
  memory.add({2, 4}, impulse_at(0.0, 4.0));
  EXPECT_THROW(memory.recall({4, 9}, Eigen::Vector3d::Zero(), 1.0), std::logic_error);
  memory.commit();
  ASSERT_EQ(memory.points().size(), 4u);
  EXPECT_EQ(memory.points()[0].pair, GrainImpulseMemory::PairKey(-1, 9));
  EXPECT_EQ(memory.points()[1].pair, GrainImpulseMemory::PairKey(2, 4));
  EXPECT_EQ(memory.points()[2].impulse.impulse.z(), 1.0);  // (4, 9) in the order added
  EXPECT_EQ(memory.points()[3].impulse.impulse.z(), 3.0);
  const GrainImpulseMemory::Impulse* near = memory.recall({4, 9}, Eigen::Vector3d(0.8, 0, 0), 1.0);
  ASSERT_NE(near, nullptr);
  EXPECT_EQ(near->impulse.z(), 3.0);
  EXPECT_EQ(memory.recall({4, 9}, Eigen::Vector3d(3.0, 0, 0), 1.0), nullptr);  // beyond the radius
  EXPECT_EQ(memory.recall({4, 8}, Eigen::Vector3d::Zero(), 1.0), nullptr);     // no such pair
  EXPECT_EQ(memory.recall({-1, 9}, Eigen::Vector3d::Zero(), 1.0)->impulse.z(), 2.0);
}
