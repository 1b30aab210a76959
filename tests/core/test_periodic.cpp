// Periodic boundaries (core/geometry/periodic_box.h) in the contact searches: the minimum
// image itself; two cubes colliding across a periodic face and the same pair shifted into
// the middle of the box give the same problem and the same velocities; a grain that wraps
// keeps its warm start and the pair cache; the overlap projection across a face moves the
// grains as in the middle; the wire–grain contact across a face loads as in the middle and
// its pair cache survives a bead and a grain wrapping; a box too short for the reach is
// refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/common/errors.h"
#include "core/contact/wire_grain_pairs.h"
#include "core/geometry/broad_phase.h"
#include "core/geometry/convex_shape.h"
#include "core/geometry/periodic_box.h"
#include "core/nscd/grain_pairs.h"
#include "core/nscd/grain_step.h"
#include "core/nscd/overlap_projection.h"
#include "wire_contact_law.h"

using namespace wiregrain;
using Eigen::Vector3d;

namespace {

constexpr double kL = 10.0;  // the periodic length along x

// [0, 10) × [−5, 5) × [−5, 5), periodic along x (and y when `xy`)
PeriodicBox periodic_x(bool xy = false) {
  PeriodicBox box;
  box.lo = Vector3d(0, -5, -5);
  box.hi = Vector3d(kL, 5, 5);
  box.periodic = {true, xy, false};
  return box;
}

ShapeLibrary cube_library() {
  ShapeLibrary library;
  library.add(ConvexShape::cube(1.0, 0.05));
  return library;
}

GrainState cube(long tag, const Vector3d& position, const Vector3d& velocity) {
  GrainState g;
  g.tag = tag;
  g.position = position;
  g.velocity = velocity;
  g.angular_velocity = Vector3d(0.0, 0.1, 0.4 * tag);
  g.mass = 1.1;
  g.inertia = Vector3d(0.2, 0.25, 0.3);
  return g;
}

GrainStepOptions tight(const PeriodicBox& box) {
  GrainStepOptions options;
  options.solver.tolerance = 1e-14;
  options.solver.max_iterations = 100000;
  options.box = box;
  return options;
}

// Two cubes (side 1, sweep 0.05) moving towards each other along x at 2.5, 0.001 apart
// between their surfaces (they touch within the step), grain 2 at x1 − 1.101 (a period
// further when `wrapped`: across the face at x = 0).
std::vector<GrainState> colliding_pair(double x1, bool wrapped) {
  const double x2 = x1 - 1.101 + (wrapped ? kL : 0.0);
  return {cube(1, Vector3d(x1, 0.2, 0.1), Vector3d(-1.0, 0.1, 0.0)), cube(2, Vector3d(x2, 0.0, 0.0), Vector3d(1.5, 0.0, 0.2))};
}

}  // namespace

TEST(PeriodicBox, MinimumImageKeepsShortDisplacementsToTheBitAndFoldsLongOnes) {
  const PeriodicBox box = periodic_x();
  const Vector3d short_one(4.999, -7.25, 123.0);  // x within L/2; y and z not periodic
  EXPECT_EQ(box.minimum_image(short_one), short_one);
  EXPECT_EQ(box.minimum_image(Vector3d(5.0, 0, 0)).x(), 5.0);  // exactly L/2: left as it is
  EXPECT_EQ(box.minimum_image(Vector3d(9.75, 1, 2)), Vector3d(-0.25, 1, 2));
  EXPECT_EQ(box.minimum_image(Vector3d(-9.75, 1, 2)), Vector3d(0.25, 1, 2));
  EXPECT_NEAR(box.minimum_image(Vector3d(23.5, 0, 0)).x(), 3.5, 1e-15);  // several periods
  EXPECT_EQ(box.image_shift(Vector3d(0.1, 0, 0), Vector3d(9.9, 4, 4)), Vector3d(-kL, 0, 0));
  EXPECT_EQ(box.image_shift(Vector3d(9.9, 0, 0), Vector3d(0.1, 4, 4)), Vector3d(kL, 0, 0));
  EXPECT_EQ(box.image_shift(Vector3d(3, 0, 0), Vector3d(7.5, 0, 0)), Vector3d::Zero());
  const PeriodicBox none;
  EXPECT_FALSE(none.any());
  EXPECT_EQ(none.minimum_image(Vector3d(99, -99, 7)), Vector3d(99, -99, 7));
  int dim = -1;
  EXPECT_EQ(periodic_x(true).shortest_period(&dim), kL);
  EXPECT_EQ(dim, 0);
  PeriodicBox bad = periodic_x();
  bad.hi.x() = bad.lo.x();
  EXPECT_THROW(bad.validate(), InvalidArgument);
}

// Points outside the box along a periodic dimension (a grain not yet wrapped) fall into
// the cell of their image: their pairs are found, each once, with the minimum-image shift.
TEST(PeriodicBox, BroadPhaseFindsPairsOfPointsOutsideThePeriodicBox) {
  BroadPhaseGrid grid = BroadPhaseGrid::box(Vector3d(0, -5, -5), Vector3d(kL, 5, 5), {true, false, false}, 2.5);
  grid.insert(Vector3d(10.2, 0, 0));  // image at 0.2
  grid.insert(Vector3d(1.0, 0, 0));   // 0.8 from it
  grid.insert(Vector3d(-0.3, 0, 0));  // image at 9.7: 0.5 from the first
  grid.insert(Vector3d(5.0, 0, 0));   // far from all
  grid.insert(Vector3d(12.6, 0, 0));  // image at 2.6, in the second cell (not the last)
  grid.insert(Vector3d(3.0, 0, 0));   // 0.4 from it
  for (int indexed = 0; indexed < 2; indexed++) {
    if (indexed) grid.index();
    std::vector<BroadPhaseGrid::Pair> pairs = grid.candidate_pairs(1.0);
    ASSERT_EQ(pairs.size(), 3u) << indexed;  // (0, 1), (0, 2) and (4, 5); (1, 2) are 1.3 apart
    std::sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
    EXPECT_EQ(pairs[0].i, 0);
    EXPECT_EQ(pairs[1].i, 0);
    EXPECT_EQ(pairs[0].j, 1);
    EXPECT_EQ(pairs[0].shift, Vector3d(kL, 0, 0));
    EXPECT_EQ(pairs[1].j, 2);
    EXPECT_EQ(pairs[1].shift, Vector3d(kL, 0, 0));
    EXPECT_EQ(pairs[2].i, 4);
    EXPECT_EQ(pairs[2].j, 5);
    EXPECT_EQ(pairs[2].shift, Vector3d(kL, 0, 0));
  }
}

// The same collision across the face at x = 0 and in the middle of the box: the same
// points (gaps, frames, lever arms), the positions a whole shift apart, and the same
// velocities after the step to rounding. Measured (tolerances 2-10 times that): gaps
// 9.2e-16 apart, frames 6e-30, Jacobians 1.3e-15, positions 0, velocities 1.1e-16 and
// 4.5e-16 (angular), contact torques (impulse / h) 2.0e-13, momentum kept to 2.8e-17.
TEST(PeriodicGrainStep, CollisionAcrossAFaceIsTheCollisionInTheMiddle) {
  const ShapeLibrary library = cube_library();
  const PeriodicBox box = periodic_x();
  const double h = 1e-3;
  GrainStepOptions options = tight(box);
  options.law.restitution = 0.5;
  const std::vector<GrainState> across = colliding_pair(0.6, true), middle = colliding_pair(5.6, false);
  GrainImpulseMemory m1, m2;
  GrainStepProblem p1 = assemble_grain_step(across, library, {}, h, options, m1);
  GrainStepProblem p2 = assemble_grain_step(middle, library, {}, h, options, m2);
  ASSERT_EQ(p1.points.size(), p2.points.size());
  ASSERT_GT(p1.points.size(), 0u);
  for (std::size_t c = 0; c < p1.points.size(); c++) {
    EXPECT_NEAR(p1.step.contacts[c].gap, p2.step.contacts[c].gap, 5e-15);
    EXPECT_LT((p1.points[c].frame - p2.points[c].frame).norm(), 1e-15);
    EXPECT_LT((p1.step.contacts[c].jacobian_a - p2.step.contacts[c].jacobian_a).norm(), 5e-15);
    EXPECT_LT((p1.step.contacts[c].jacobian_b - p2.step.contacts[c].jacobian_b).norm(), 5e-15);
    EXPECT_LT((p1.points[c].position + Vector3d(5.0, 0, 0) - p2.points[c].position).norm(), 1e-15);
  }
  const GrainStepResult r1 = solve_grain_step(p1, across, options, 0, m1);
  const GrainStepResult r2 = solve_grain_step(p2, middle, options, 0, m2);
  for (int k = 0; k < 2; k++) {
    EXPECT_LT((r1.velocities[k] - r2.velocities[k]).norm(), 1e-15) << k;
    EXPECT_LT((r1.angular_velocities[k] - r2.angular_velocities[k]).norm(), 2e-15) << k;
    EXPECT_LT((r1.contact_torques[k] - r2.contact_torques[k]).norm(), 1e-12) << k;
  }
  // they collided: the normal velocities changed, momentum is kept
  EXPECT_GT((r1.velocities[0] - across[0].velocity).norm(), 0.1);
  const Vector3d p_before = across[0].mass * across[0].velocity + across[1].mass * across[1].velocity;
  EXPECT_LT((across[0].mass * r1.velocities[0] + across[1].mass * r1.velocities[1] - p_before).norm(), 1e-15);
  // without the minimum image the pair is a period apart: no contact
  GrainImpulseMemory m3;
  EXPECT_EQ(assemble_grain_step(across, library, {}, h, tight(PeriodicBox()), m3).points.size(), 0u);
}

// The next step after grain 1 wrapped (its position a period on; the points lie by it): the
// warm start is recalled as if nothing wrapped, and the pair cache is reused, not rebuilt.
TEST(PeriodicGrainStep, AWrappedGrainKeepsItsWarmStartAndThePairCache) {
  const ShapeLibrary library = cube_library();
  const PeriodicBox box = periodic_x();
  GrainStepOptions options = tight(box);
  std::vector<GrainState> grains = colliding_pair(0.6, true);
  GrainImpulseMemory memory;
  GrainPairCache pairs(0.1);
  GrainStepProblem first = assemble_grain_step(grains, library, {}, 1e-3, options, memory, &pairs);
  solve_grain_step(first, grains, options, 0, memory);
  ASSERT_EQ(pairs.builds(), 1);
  grains[0].position.x() += kL;  // wrapped to the other side of the face, nothing else changed
  GrainStepProblem again = assemble_grain_step(grains, library, {}, 1e-3, options, memory, &pairs);
  EXPECT_EQ(pairs.builds(), 1);
  EXPECT_EQ(pairs.reuses(), 1);
  ASSERT_EQ(again.points.size(), first.points.size());
  double recalled = 0.0;
  for (std::size_t c = 0; c < again.points.size(); c++) recalled += again.warm_start[c].norm();
  EXPECT_GT(recalled, 0.0);
  // the stored points lie by grain 1 on one side; recalled across the face
  GrainImpulseMemory::Impulse stored;
  stored.position = Vector3d(9.98, 0, 0);
  stored.impulse = Vector3d(1, 2, 3);
  GrainImpulseMemory near;
  near.add({1, 2}, stored);
  near.commit();
  EXPECT_NE(near.recall({1, 2}, Vector3d(0.01, 0, 0), 1e-3, box), nullptr);
  EXPECT_EQ(near.recall({1, 2}, Vector3d(0.01, 0, 0), 1e-3), nullptr);
}

// Two cubes left 0.01 into each other across the face: the projection pushes them apart as
// it does in the middle of the box (to rounding: measured 4.2e-17).
TEST(PeriodicGrainStep, OverlapProjectionAcrossAFace) {
  const ShapeLibrary library = cube_library();
  const PeriodicBox box = periodic_x();
  const auto pair = [](double x1, bool wrapped) {
    return std::vector<GrainState>{cube(1, Vector3d(x1, 0, 0), Vector3d::Zero()),
                                   cube(2, Vector3d(x1 - 1.09 + (wrapped ? kL : 0.0), 0.05, 0), Vector3d::Zero())};
  };
  std::vector<Vector3d> corrections[2];
  for (int side = 0; side < 2; side++) {
    const std::vector<GrainState> grains = pair(side == 0 ? 0.5 : 5.5, side == 0);
    const GrainStepOptions options = tight(box);
    GrainImpulseMemory memory;
    GrainStepProblem problem = assemble_grain_step(grains, library, {}, 1e-3, options, memory);
    const GrainStepResult result = solve_grain_step(problem, grains, options, 0, memory);
    OverlapProjectionStats stats;
    corrections[side] = project_overlaps(grains, library, {}, problem, result, 1.0, 5e-5, 20, &stats);
    EXPECT_GT(stats.projections, 0) << side;
  }
  for (int k = 0; k < 2; k++) {
    EXPECT_GT(corrections[0][k].norm(), 1e-3);
    EXPECT_LT((corrections[0][k] - corrections[1][k]).norm(), 2e-16) << k;
  }
}

// Each periodic length must be at least twice the pair reach 2 R_max + d_act + skin, and a
// wall must be parallel to the periodic dimensions.
TEST(PeriodicGrainStep, ShortBoxAndCrossingWallAreRefused) {
  const ShapeLibrary library = cube_library();
  const double reach = 2.0 * library[0].bounding_radius;
  PeriodicBox box = periodic_x();
  box.hi.x() = 2.0 * reach - 1e-3;  // below 2 (2 R_max) already without activation
  GrainImpulseMemory memory;
  const std::vector<GrainState> one = {cube(1, Vector3d(1, 0, 0), Vector3d::Zero())};
  try {
    assemble_grain_step(one, library, {}, 1e-3, tight(box), memory);
    FAIL() << "a short periodic box was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), "box");
    EXPECT_NE(std::string(e.what()).find("long along x, below twice the pair reach"), std::string::npos) << e.what();
  }
  box.hi.x() = kL;
  EXPECT_NO_THROW(assemble_grain_step(one, library, {}, 1e-3, tight(box), memory));
  PlaneWall crossing;
  crossing.normal = Vector3d(1, 0, 0);
  EXPECT_THROW(assemble_grain_step(one, library, {crossing}, 1e-3, tight(box), memory), InvalidArgument);
  PlaneWall floor;  // normal z: parallel to x
  EXPECT_NO_THROW(assemble_grain_step(one, library, {floor}, 1e-3, tight(box), memory));
}

// A segment lying across the face at x = 0 on a cube: the same contact as the scene
// shifted into the middle (measured: overlap 9e-18 apart, bead forces 6.9e-16, torque
// 5.6e-16); the pair cache keeps its entry when the segment's first bead and then the
// grain wrap, and visits the grain's image nearest the segment.
TEST(PeriodicWireGrain, SegmentAcrossAFaceLoadsAsInTheMiddleAndTheCacheSurvivesWraps) {
  ShapeLibrary library;
  library.add(ConvexShape::cube(1.0, 0.05));
  const auto held_at = [&](double x, const PeriodicBox& box) {
    HeldGrain g;
    g.tag = 7;
    g.position = Vector3d(x, 0.1, 0.0);
    g.motion.mass = 2.0;
    g.motion.velocity = Vector3d(0.01, 0, 0);
    return HeldGrains({g}, library, box, 1.0);
  };
  const PeriodicBox box = periodic_x();
  const double z = 0.55 + 0.1 - 0.01;  // the axis 0.01 into the top face (sweep 0.05, r_w 0.1)
  const SoftContactLaw law = wiregrain_test::wire_contact_law(0.1);
  WireGrainContact contact[2];
  for (int side = 0; side < 2; side++) {
    const double dx = side == 0 ? 0.0 : 5.0;
    const HeldGrains held = held_at(0.3 + dx, box);
    const WireSegmentState s =
        wiregrain_test::moving_segment(Vector3d(9.8 + dx - (side ? kL : 0.0), 0, z), Vector3d(10.1 + dx - (side ? kL : 0.0), 0, z), 0.1);
    int visits = 0;
    held.for_each_candidate(s.x0, s.x1, s.radius, 0.0, [&](int k, const Vector3d& shift) {
      visits++;
      TangentialHistory history;
      contact[side] = held.contact(k, shift, law, s, 1e-4, history);
    });
    EXPECT_EQ(visits, 1) << side;
  }
  ASSERT_TRUE(contact[0].touching);
  EXPECT_NEAR(contact[0].overlap, 0.01, 1e-16);
  EXPECT_NEAR(contact[0].overlap, contact[1].overlap, 1e-16);
  EXPECT_LT((contact[0].force_bead0 - contact[1].force_bead0).norm(), 3e-15);
  EXPECT_LT((contact[0].force_bead1 - contact[1].force_bead1).norm(), 3e-15);
  EXPECT_LT((contact[0].torque_grain - contact[1].torque_grain).norm(), 3e-15);

  WireGrainPairCache cache(0.1);
  const auto visit = [&](const HeldGrains& held, const Vector3d& x0, const Vector3d& x1, Vector3d& shift_seen) {
    int visits = 0;
    cache.for_each_pair(3, held, x0, x1, 0.1, [&](int k, const Vector3d& shift, double, GjkSimplex*) {
      visits++;
      shift_seen = shift;
      (void)k;
      return -0.01;  // touching
    });
    return visits;
  };
  Vector3d shift;
  const HeldGrains held = held_at(0.3, box);
  cache.hold(held);
  EXPECT_EQ(visit(held, Vector3d(9.8, 0, z), Vector3d(10.1, 0, z), shift), 1);
  EXPECT_EQ(shift, Vector3d(kL, 0, 0));
  EXPECT_EQ(cache.rebuilds(), 1);
  // the first bead wrapped: the same segment a period back
  EXPECT_EQ(visit(held, Vector3d(-0.2, 0, z), Vector3d(0.1, 0, z), shift), 1);
  EXPECT_EQ(shift, Vector3d::Zero());
  EXPECT_EQ(cache.rebuilds(), 1);
  // the grain wrapped (a period on): the reference stays, the entry too
  const HeldGrains wrapped = held_at(0.3 + kL, box);
  cache.hold(wrapped);
  EXPECT_EQ(cache.resets(), 1);
  EXPECT_EQ(visit(wrapped, Vector3d(-0.2, 0, z), Vector3d(0.1, 0, z), shift), 1);
  EXPECT_EQ(shift, Vector3d(-kL, 0, 0));
  EXPECT_EQ(cache.rebuilds(), 1);
  // a box shorter than twice the wire-grain reach is refused
  PeriodicBox short_box = box;
  short_box.hi.x() = 2.0;
  EXPECT_THROW(held_at(0.3, short_box), InvalidArgument);
}
