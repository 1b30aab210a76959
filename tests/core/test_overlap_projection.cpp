// core/nscd/overlap_projection: the post-step projection of overlaps, against geometry
// worked out by hand (spheres: the gap is linear in the centres; a wall that moved into a
// sphere; a tilted cube's corner below a floor, checked on its vertices) and against
// the conservation it promises (the centre of mass of a free pair stays put).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/common/errors.h"
#include "core/geometry/contact_manifold.h"
#include "core/geometry/posed_shape.h"
#include "core/geometry/convex_shape.h"
#include "core/nscd/overlap_projection.h"

using namespace wiregrain;
using Eigen::Vector3d;

namespace {

constexpr double kH = 1e-3;

GrainState grain_at(long tag, int shape, const Vector3d& position, double mass, double moment) {
  GrainState g;
  g.tag = tag;
  g.shape = shape;
  g.position = position;
  g.mass = mass;
  g.inertia = Vector3d::Constant(moment);
  return g;
}

// A problem listing one (open) point for each pair (a, b) given: only the pairs, the body
// indices, the normal and h matter to the projection.
GrainStepProblem problem_of(const std::vector<GrainState>& grains, const std::vector<std::pair<int, int>>& pairs) {
  GrainStepProblem p;
  p.step.time_step = kH;
  for (const auto& [a, b] : pairs) {
    GrainContactPoint c;
    c.constraint.body_a = a >= 0 ? a : -1;
    c.constraint.body_b = b;
    c.pair = {a >= 0 ? grains[a].tag : long(a), grains[b].tag};  // a < 0: −(wall + 1)
    // the normal: along the centres (a wall: its own normal, not read)
    c.frame = Eigen::Matrix3d::Identity();
    if (a >= 0) c.frame.col(0) = (grains[b].position - grains[a].position).normalized();
    p.points.push_back(c);
  }
  return p;
}

// the step's result: the grains keep their velocities
GrainStepResult at_rest(const std::vector<GrainState>& grains) {
  GrainStepResult r;
  for (const GrainState& g : grains) {
    r.velocities.push_back(g.velocity);
    r.angular_velocities.push_back(g.angular_velocity);
  }
  return r;
}

}  // namespace

// Two spheres of radii 0.5 (masses 1 and 3) overlapping by 0.01 along x: the pair is
// pushed apart along x to the overlap ½ τ R (the gap of spheres is linear in their
// centres: one pass does it), inversely to the masses (the centre of mass stays), no turn.
TEST(OverlapProjection, TwoSpheresApartToHalfTheToleranceWithTheCentreOfMassKept) {
  ShapeLibrary library;
  library.add(ConvexShape::sphere(0.5));
  const double overlap = 0.01, tolerance = 1e-4;
  std::vector<GrainState> grains = {grain_at(1, 0, Vector3d::Zero(), 1.0, 0.1),
                                    grain_at(2, 0, Vector3d(1.0 - overlap, 0, 0), 3.0, 0.3)};
  OverlapProjectionStats stats;
  const std::vector<Vector3d> c =
      project_overlaps(grains, library, {}, problem_of(grains, {{0, 1}}), at_rest(grains), 0.5, tolerance, 10, &stats);
  const double target = 0.5 * tolerance * 0.5;  // ½ τ × bounding radius
  const double push = overlap - target;
  EXPECT_NEAR(c[1].x(), push * 1.0 / 4.0, 1e-15);
  EXPECT_NEAR(c[0].x(), -push * 3.0 / 4.0, 1e-15);
  EXPECT_NEAR((1.0 * c[0] + 3.0 * c[1]).norm(), 0.0, 1e-16);
  EXPECT_NEAR(c[0].tail<2>().norm() + c[1].tail<2>().norm(), 0.0, 1e-16);
  const double distance = (grains[1].position + c[1] - grains[0].position - c[0]).norm();
  EXPECT_NEAR(1.0 - distance, target, 1e-14);
  EXPECT_NEAR(stats.max_overlap_before, overlap / 0.5, 1e-12);
  EXPECT_NEAR(stats.max_overlap_after, target / 0.5, 1e-12);
  EXPECT_EQ(stats.pairs, 1);
  EXPECT_EQ(stats.projections, 1);
}

// An overlap within the tolerance is left alone (corrections exactly zero), and
// tolerance 0 projects nothing at all.
TEST(OverlapProjection, OverlapsWithinTheToleranceAreLeftAlone) {
  ShapeLibrary library;
  library.add(ConvexShape::sphere(0.5));
  std::vector<GrainState> grains = {grain_at(1, 0, Vector3d::Zero(), 1.0, 0.1),
                                    grain_at(2, 0, Vector3d(1.0 - 4e-5, 0, 0), 1.0, 0.1)};
  for (const double tolerance : {1e-4, 0.0}) {
    OverlapProjectionStats stats;
    const std::vector<Vector3d> c = project_overlaps(grains, library, {}, problem_of(grains, {{0, 1}}),
                                                           at_rest(grains), 0.5, tolerance, 10, &stats);
    for (const Vector3d& k : c) EXPECT_EQ(k, Vector3d::Zero());
    EXPECT_EQ(stats.projections, 0);
  }
}

// The poses are those the step leads to: a sphere falling at 2 onto a floor that rises at
// 1, resting on it at the step start, ends the step h·3 inside it; the projection lifts
// it to ½ τ R inside, the floor (infinite mass) does not move.
TEST(OverlapProjection, AWallAndAGrainThatMovedIntoEachOtherWithinTheStep) {
  ShapeLibrary library;
  library.add(ConvexShape::sphere(0.5));
  std::vector<GrainState> grains = {grain_at(1, 0, Vector3d(0, 0, 0.5), 1.0, 0.1)};
  grains[0].velocity = Vector3d(0, 0, -2.0);
  PlaneWall floor;
  floor.velocity = Vector3d(0, 0, 1.0);
  const double tolerance = 1e-4;
  OverlapProjectionStats stats;
  const std::vector<Vector3d> c = project_overlaps(grains, library, {floor}, problem_of(grains, {{-1, 0}}),
                                                         at_rest(grains), 0.5, tolerance, 10, &stats);
  const double end_height = 0.5 - 2.0 * kH + c[0].z(), floor_height = kH;
  EXPECT_NEAR(end_height - 0.5 - floor_height, -0.5 * tolerance * 0.5, 1e-14);
  EXPECT_NEAR(stats.max_overlap_before, 3.0 * kH / 0.5, 1e-12);
  EXPECT_NEAR(c[0].head<2>().norm(), 0.0, 1e-16);
}

// A unit cube (rounded by 0.01) turned by 5° about x and y with one corner 0.02 below the
// floor is lifted straight up (translation only) to ½ τ R inside: every vertex is then
// above −τ R − r (τ R: the tolerance in length, r the sweep), checked on the vertices of
// the corrected pose, not on the projection's own gap.
TEST(OverlapProjection, ATiltedCubesCornerIsLiftedWithinTheTolerance) {
  ShapeLibrary library;
  const int shape = library.add(ConvexShape::cube(1.0, 0.01));
  const Eigen::Quaterniond tilt = Eigen::Quaterniond(Eigen::AngleAxisd(0.087, Vector3d::UnitX())) *
                                  Eigen::Quaterniond(Eigen::AngleAxisd(0.087, Vector3d::UnitY()));
  GrainState g = grain_at(1, shape, Vector3d::Zero(), 2.0, 2.0 / 6.0);
  g.orientation = tilt;
  const PosedShape at_origin(library[shape].shape, g.position, g.orientation);
  double lowest = 1e300;
  for (const Vector3d& v : at_origin.vertices()) lowest = std::min(lowest, v.z());
  g.position.z() = -(lowest - 0.01) - 0.02;  // the lowest surface point at z = −0.02
  std::vector<GrainState> grains = {g};
  const double tolerance = 1e-4, size = library[shape].bounding_radius;
  OverlapProjectionStats stats;
  const std::vector<Vector3d> c = project_overlaps(grains, library, {PlaneWall()}, problem_of(grains, {{-1, 0}}),
                                                   at_rest(grains), 0.5, tolerance, 20, &stats);
  const PosedShape corrected(library[shape].shape, g.position + c[0], g.orientation);
  double lowest_after = 1e300;
  for (const Vector3d& v : corrected.vertices()) lowest_after = std::min(lowest_after, v.z() - 0.01);
  EXPECT_NEAR(lowest_after, -0.5 * tolerance * size, 1e-15);
  EXPECT_NEAR(c[0].head<2>().norm(), 0.0, 1e-16);
  EXPECT_NEAR(stats.max_overlap_before, 0.02 / size, 1e-12);
  EXPECT_NEAR(stats.max_overlap_after, 0.5 * tolerance, 1e-12);
}

// A cube 0.03 inside a sphere-grain above it, both free (masses 2 and 1): pushed apart
// along the normal of their contact (the face's, z) inversely to the masses until the
// overlap is ½ τ R (R the smaller bounding radius, the sphere's), checked by the distance
// of the sphere's centre from the cube's top face; the centre of mass stays.
TEST(OverlapProjection, ASphereSunkInACubesFaceIsPushedOutAlongTheFaceNormal) {
  ShapeLibrary library;
  const int cube = library.add(ConvexShape::cube(1.0, 0.0));
  const int ball = library.add(ConvexShape::sphere(0.3));
  std::vector<GrainState> grains = {grain_at(1, cube, Vector3d::Zero(), 2.0, 2.0 / 6.0),
                                    grain_at(2, ball, Vector3d(0.1, -0.2, 0.5 + 0.3 - 0.03), 1.0, 0.036)};
  const double tolerance = 1e-4;
  OverlapProjectionStats stats;
  const std::vector<Vector3d> c =
      project_overlaps(grains, library, {}, problem_of(grains, {{0, 1}}), at_rest(grains), 0.5, tolerance, 20, &stats);
  const double top = 0.5 + c[0].z(), centre = grains[1].position.z() + c[1].z();
  EXPECT_NEAR(centre - 0.3 - top, -0.5 * tolerance * 0.3, 1e-13);
  EXPECT_NEAR(c[0].head<2>().norm() + c[1].head<2>().norm(), 0.0, 1e-13);
  EXPECT_NEAR((2.0 * c[0] + 1.0 * c[1]).norm(), 0.0, 1e-15);
}

// Three spheres in a column on a floor, each overlapping the next by 0.005: the passes
// push the whole column up until no pair is deeper than τ R, checked on the centres.
TEST(OverlapProjection, AColumnOfOverlappingSpheresIsResolvedByThePasses) {
  ShapeLibrary library;
  library.add(ConvexShape::sphere(0.5));
  std::vector<GrainState> grains;
  for (int k = 0; k < 3; ++k) grains.push_back(grain_at(k + 1, 0, Vector3d(0, 0, 0.495 + 0.995 * k), 1.0, 0.1));
  const double tolerance = 1e-4;
  OverlapProjectionStats stats;
  const std::vector<Vector3d> c =
      project_overlaps(grains, library, {PlaneWall()}, problem_of(grains, {{-1, 0}, {0, 1}, {1, 2}}),
                       at_rest(grains), 0.5, tolerance, 100, &stats);
  std::vector<double> z;
  for (int k = 0; k < 3; ++k) z.push_back(grains[k].position.z() + c[k].z());
  EXPECT_GE(z[0] - 0.5, -tolerance * 0.5 * (1 + 1e-9));
  EXPECT_GE(z[1] - z[0] - 1.0, -tolerance * 0.5 * (1 + 1e-9));
  EXPECT_GE(z[2] - z[1] - 1.0, -tolerance * 0.5 * (1 + 1e-9));
  EXPECT_LE(stats.max_overlap_after, tolerance);
  EXPECT_GT(stats.passes, 1);
}

// A cube resting face on face 1e-5 inside the cube below it (τ = 1e-4), turning about the
// vertical by 1e-3 in the step: the separation along the start normal z settles the pair
// without GJK, and its overlap is the exact one, 1e-5 / R; a cube turning about x by 0.01
// dips an edge 0.5 (cos + sin − 1) ≈ 5e-3 deep: the bound cannot settle it, GJK does and
// the pair is pushed to ½ τ R (then the bound settles it).
TEST(OverlapProjection, PairsWithinTheToleranceAreSettledByTheSeparationAlongTheirNormal) {
  ShapeLibrary library;
  const int cube = library.add(ConvexShape::cube(1.0, 0.0));
  const double size = library[cube].bounding_radius, tolerance = 1e-4;
  std::vector<GrainState> grains = {grain_at(1, cube, Vector3d::Zero(), 1.0, 1.0 / 6.0),
                                    grain_at(2, cube, Vector3d(0.2, 0.1, 1.0 - 1e-5), 1.0, 1.0 / 6.0)};
  GrainStepResult turning = at_rest(grains);
  turning.angular_velocities[1] = Vector3d(0, 0, 1.0);  // 1e-3 rad in the step
  GrainStepProblem problem = problem_of(grains, {{0, 1}});
  problem.points[0].frame.col(0) = Vector3d::UnitZ();  // the faces' normal
  OverlapProjectionStats stats;
  std::vector<Vector3d> c = project_overlaps(grains, library, {}, problem, turning, 1.0, tolerance, 10, &stats);
  EXPECT_EQ(stats.bounded, 1);
  EXPECT_EQ(stats.projections, 0);
  EXPECT_NEAR(stats.max_overlap_before, 1e-5 / size, 1e-12);
  for (const Vector3d& k : c) EXPECT_EQ(k, Vector3d::Zero());

  grains[1].position = Vector3d(0.0, 0.0, 1.0);
  turning.angular_velocities[1] = Vector3d(10.0, 0, 0);  // 0.01 rad
  c = project_overlaps(grains, library, {}, problem_of(grains, {{0, 1}}), turning, 1.0, tolerance, 10, &stats);
  const double dip = 0.5 * (std::cos(0.01) + std::sin(0.01) - 1.0);
  EXPECT_EQ(stats.projections, 1);
  EXPECT_EQ(stats.bounded, 1);  // the check after the push, in the second pass
  EXPECT_NEAR(stats.max_overlap_before, dip / size, 1e-9);
  EXPECT_NEAR(c[1].z() - c[0].z(), dip - 0.5 * tolerance * size, 1e-9);
}

TEST(OverlapProjection, BadArgumentsAreRejected) {
  ShapeLibrary library;
  library.add(ConvexShape::sphere(0.5));
  std::vector<GrainState> grains = {grain_at(1, 0, Vector3d::Zero(), 1.0, 0.1)};
  const auto expect_rejected = [&](double tolerance, int passes, const std::string& argument) {
    try {
      project_overlaps(grains, library, {}, problem_of(grains, {}), at_rest(grains), 0.5, tolerance, passes);
      FAIL() << "accepted tolerance " << tolerance << " passes " << passes;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(std::string(e.argument()), argument);
    }
  };
  expect_rejected(-1e-4, 10, "tolerance");
  expect_rejected(std::nan(""), 10, "tolerance");
  expect_rejected(INFINITY, 10, "tolerance");
  expect_rejected(1e-4, 0, "max_passes");
}
