// core/nscd/grain_step: a plate (PlaneWall with a mass) as a body of the Moreau–Jean step,
// against statics worked out by hand, the free motion under a constant force and the
// momentum balance of a perfectly inelastic impact.
#include <gtest/gtest.h>

#include <cmath>

#include "core/common/errors.h"
#include "core/geometry/convex_shape.h"
#include "core/nscd/grain_step.h"
#include "grain_scenes.h"

using namespace wiregrain;

namespace {

constexpr double kG = 9.81, kMass = 2.0, kH = 1e-3;

using test_scenes::floor_wall;
using test_scenes::unit_cube_library;

// a unit cube (m = 2, I = m/6) at rest with its centre at height z, its weight m g along −z
// when `weight`
GrainState cube(long tag, double z, bool weight) {
  return test_scenes::unit_cube(tag, Eigen::Vector3d(0, 0, z), kMass, weight ? kG : 0.0);
}

// a top plate at height z (normal −z, into the grains) of mass m_p
PlaneWall top_plate(double z, double mass) {
  PlaneWall w;
  w.point = Eigen::Vector3d(0, 0, z);
  w.normal = -Eigen::Vector3d::UnitZ();
  w.mass = mass;
  return w;
}

GrainStepOptions tight() { return test_scenes::tight_options(1e-15); }

}  // namespace

// A cube resting on the floor under a plate of mass m_p = 3 pressed by a load F = 10 and
// its own weight m_p g: at rest, the plate's contact impulse balances its external force,
// (F + m_p g) h, and the floor carries that plus the cube's weight (statics). Measured:
// errors up to 3.6e-16 of the largest force (m_p g + F + m g) at tolerance
// 1e-15, the impulse 1.2e-15 of its value; asserted to 2e-15 of that force.
TEST(GrainPlate, LoadedPlateOnACubeOnTheFloorIsStatics) {
  const ShapeLibrary library = unit_cube_library();
  const double m_p = 3.0, F = 10.0;
  PlaneWall plate = top_plate(1.0, m_p);
  plate.force = Eigen::Vector3d(0, 0, -F - m_p * kG);  // the load along n (down) and its weight
  GrainImpulseMemory memory;
  const GrainStepResult r = grain_step({cube(7, 0.5, true)}, library, {floor_wall(), plate}, kH, tight(), 0, memory);
  const double on_plate = F + m_p * kG, scale = on_plate + kMass * kG;
  // the grains push the plate up with F + m_p g, the floor down with that and m g
  EXPECT_NEAR(r.wall_forces[1].z(), on_plate, 2e-15 * scale);
  EXPECT_NEAR(r.wall_forces[0].z(), -(on_plate + kMass * kG), 2e-15 * scale);
  // laterally the cube is held by friction at both walls, which the statics leave
  // undetermined (a pair of opposite tangential forces, its moment balanced by the
  // normal forces' distribution): only their sum is zero
  EXPECT_NEAR((r.wall_forces[0].head<2>() + r.wall_forces[1].head<2>()).norm(), 0.0, 2e-15 * scale);
  // the plate–grain impulse: the contact records (force on the grain = impulse / h)
  double plate_impulse = 0.0;
  for (const ContactRecord& c : r.contacts.records())
    if (c.kind == ContactKind::grain_wall && c.a == -2) plate_impulse += -c.force.z() * kH;
  EXPECT_NEAR(plate_impulse, on_plate * kH, 2e-15 * scale * kH);
  // all at rest: the plate's end velocity and the cube's
  EXPECT_LT(r.wall_velocities[1].norm(), 1e-12);
  EXPECT_LT(r.velocities[0].norm(), 1e-12);
  EXPECT_EQ(r.wall_velocities[0], Eigen::Vector3d::Zero());  // the floor's own
}

// A plate alone under a constant force F along its normal accelerates at F/m_p: after N
// steps v = N h F/m_p, and with θ = 1/2 (the trapezoid rule, exact for a constant
// acceleration) its travel is ½ (F/m_p) t². The grain far below is never reached. Exact
// to round-off: measured 4.4e-16 (v) and 3.6e-16 (travel) relative; asserted to
// 2e-15 and 1e-15.
TEST(GrainPlate, FreePlateAcceleratesAtForceOverMass) {
  const ShapeLibrary library = unit_cube_library();
  const double m_p = 4.0, F = 2.0, h = 1e-2;
  GrainStepOptions options = tight();
  options.law.theta = 0.5;
  PlaneWall plate = top_plate(10.0, m_p);
  plate.force = F * plate.normal;
  GrainImpulseMemory memory;
  const int steps = 50;
  for (int k = 0; k < steps; k++) {
    const GrainStepResult r = grain_step({cube(1, 0.5, false)}, library, {plate}, h, options, k, memory);
    plate.point += wall_step_displacement(plate, r.wall_velocities[0], h, options.law.theta);
    plate.velocity = r.wall_velocities[0];
  }
  const double t = steps * h, a = F / m_p;
  EXPECT_NEAR(plate.velocity.z(), -a * t, 2e-15 * a * t);
  EXPECT_NEAR(plate.point.z(), 10.0 - 0.5 * a * t * t, 1e-15 * 10.0);
  EXPECT_EQ(plate.velocity.head<2>(), Eigen::Vector2d::Zero());  // along its normal only
}

// A plate of mass m_p at speed v0 meets a free cube at rest (touching, no gravity) with
// perfectly inelastic contact (e = 0): one step leaves both at the common velocity
// m_p v0 / (m_p + m), the momentum conserved. The momentum balance is exact (the same
// impulses on both) to round-off, measured 0, asserted to 1e-15 relative; the common
// velocity to the solver's tolerance (1e-15), measured 9e-17 of v0, asserted to 1e-15;
// the plate's force, its momentum change over h, measured 4e-17, asserted to 1e-16.
TEST(GrainPlate, InelasticImpactConservesMomentum) {
  const ShapeLibrary library = unit_cube_library();
  const double m_p = 5.0, v0 = 0.3;
  PlaneWall plate = top_plate(1.0, m_p);  // touching the cube's top face
  plate.velocity = Eigen::Vector3d(0, 0, -v0);
  GrainImpulseMemory memory;
  const GrainStepResult r = grain_step({cube(3, 0.5, false)}, library, {plate}, kH, tight(), 0, memory);
  const double momentum_before = -m_p * v0;
  const double momentum_after = m_p * r.wall_velocities[0].z() + kMass * r.velocities[0].z();
  EXPECT_NEAR(momentum_after, momentum_before, 1e-15 * m_p * v0);
  const double common = -m_p * v0 / (m_p + kMass);
  EXPECT_NEAR(r.wall_velocities[0].z(), common, 1e-15 * v0);
  EXPECT_NEAR(r.velocities[0].z(), common, 1e-15 * v0);
  EXPECT_LT(r.angular_velocities[0].norm(), 1e-15 * v0);
  // the grains' force on the plate: its momentum change over h
  EXPECT_NEAR(r.wall_forces[0].z(), m_p * (r.wall_velocities[0].z() + v0) / kH, 1e-16 * m_p * v0 / kH);
}

// A sleeping grain touching a plate at rest is woken at the step start (the plate could
// not feel a frozen point), a wall of infinite mass at rest leaves it asleep.
TEST(GrainPlate, PlateWakesTheSleepingGrainsItTouches) {
  const ShapeLibrary library = unit_cube_library();
  GrainStepOptions options = tight();
  options.sleep.speed = 1e-3;
  GrainState sleeper = cube(4, 0.5, true);
  sleeper.asleep = true;
  for (const double mass : {0.0, 3.0}) {
    PlaneWall plate = top_plate(1.0, mass);
    GrainImpulseMemory memory;
    const GrainStepProblem problem =
        assemble_grain_step({sleeper}, library, {floor_wall(), plate}, kH, options, memory);
    EXPECT_EQ(problem.asleep[0], mass > 0.0 ? 0 : 1) << "plate mass " << mass;
  }
}

// The plate's contact rows: body a is the plate (after the grains), its Jacobian moves it
// along its normal only, and its point keeps the wall's key.
TEST(GrainPlate, PlateRowsHaveThePlateAsBodyA) {
  const ShapeLibrary library = unit_cube_library();
  GrainImpulseMemory memory;
  const GrainStepProblem problem =
      assemble_grain_step({cube(1, 0.5, true)}, library, {floor_wall(), top_plate(1.0, 3.0)}, kH, tight(), memory);
  ASSERT_EQ(problem.step.bodies.size(), 2u);
  EXPECT_EQ(problem.step.bodies[1].inverse_mass, 1.0 / 3.0);
  EXPECT_EQ(problem.step.bodies[1].inverse_inertia, Eigen::Matrix3d::Zero());
  int plate_rows = 0;
  for (size_t c = 0; c < problem.points.size(); c++) {
    if (problem.points[c].pair.first != -2) continue;
    plate_rows++;
    const NscdContact& row = problem.step.contacts[c];
    EXPECT_EQ(row.body_a, 1);
    EXPECT_EQ(problem.points[c].constraint.body_a, -1);  // the point stays a wall point
    // H_a (v, ω) reads the normal velocity only: a tangential plate velocity does nothing
    Eigen::Matrix<double, 6, 1> lateral;
    lateral << 1.0, 2.0, 0.0, 3.0, 4.0, 5.0;
    EXPECT_EQ((row.jacobian_a * lateral).norm(), 0.0);
  }
  EXPECT_EQ(plate_rows, 4);  // the cube's top face: its four corners
}

TEST(GrainPlate, BadPlateIsRejected) {
  const ShapeLibrary library = unit_cube_library();
  GrainImpulseMemory memory;
  PlaneWall negative = top_plate(2.0, -1.0);
  EXPECT_THROW(grain_step({cube(1, 0.5, true)}, library, {negative}, kH, GrainStepOptions(), 0, memory), InvalidArgument);
  PlaneWall sideways = top_plate(2.0, 1.0);
  sideways.velocity = Eigen::Vector3d(0.1, 0, -1);
  EXPECT_THROW(grain_step({cube(1, 0.5, true)}, library, {sideways}, kH, GrainStepOptions(), 0, memory), InvalidArgument);
  PlaneWall infinite = top_plate(2.0, 1.0);
  infinite.force = Eigen::Vector3d(0, 0, INFINITY);
  EXPECT_THROW(grain_step({cube(1, 0.5, true)}, library, {infinite}, kH, GrainStepOptions(), 0, memory), InvalidArgument);
}
