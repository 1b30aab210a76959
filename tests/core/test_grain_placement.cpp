// core/geometry/grain_placement and grain_generation: the overlap test against spheres,
// segments and grains (gaps by hand from the cube's faces), its periodic images, the
// layer lattice's sites, the placement loop, the drawn shapes and orientations.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "core/geometry/convex_shape.h"
#include "core/geometry/grain_generation.h"
#include "core/geometry/grain_placement.h"
#include "core/geometry/shape_library.h"

using Eigen::Quaterniond;
using Eigen::Vector3d;
using wiregrain::ConvexShape;
using wiregrain::PlacementGrid;
using wiregrain::PlacementObstacle;
using wiregrain::PosedShape;
using wiregrain::ShapeLibrary;

namespace {

constexpr double kPi = 3.14159265358979323846;

// a library holding one sharp cube of the given edge (sweep 0), index 0
ShapeLibrary cube_library(double edge) {
  ShapeLibrary library;
  library.add(ConvexShape::cube(edge, 0.0));
  return library;
}

PlacementGrid open_grid(const ShapeLibrary& library, double max_bound) {
  return PlacementGrid(library, Vector3d(-5, -5, -5), Vector3d(5, 5, 5), {false, false, false}, max_bound);
}

}  // namespace

// A unit cube at the origin against a sphere beside its +x face: gap = x − ½ − r.
TEST(GrainPlacement, SphereGapFromTheFace) {
  const ShapeLibrary library = cube_library(1.0);
  const PosedShape cube(library[0].shape, Vector3d::Zero(), Quaterniond::Identity());
  const double bound = std::sqrt(3.0) / 2.0;
  {
    PlacementGrid grid = open_grid(library, bound);
    grid.add(PlacementObstacle::sphere(Vector3d(0.8, 0.0, 0.0), 0.25));
    double gap = 0.0;
    long pairs = 0;
    EXPECT_FALSE(grid.overlaps(cube, bound, gap, pairs));
    EXPECT_NEAR(gap, 0.05, 1e-12);
    EXPECT_EQ(pairs, 1);
  }
  {
    PlacementGrid grid = open_grid(library, bound);
    grid.add(PlacementObstacle::sphere(Vector3d(0.7, 0.0, 0.0), 0.25));
    double gap = 0.0;
    long pairs = 0;
    EXPECT_TRUE(grid.overlaps(cube, bound, gap, pairs));
  }
  {  // bounding spheres apart: no pair, gap +inf
    PlacementGrid grid = open_grid(library, bound);
    grid.add(PlacementObstacle::sphere(Vector3d(1.5, 0.0, 0.0), 0.25));
    double gap = 0.0;
    long pairs = -1;
    EXPECT_FALSE(grid.overlaps(cube, bound, gap, pairs));
    EXPECT_EQ(gap, std::numeric_limits<double>::infinity());
    EXPECT_EQ(pairs, 0);
  }
}

// A segment (radius 0.1) along y at height 0.9 above the unit cube: gap 0.9 − ½ − 0.1 = 0.3;
// lowered to 0.55 it overlaps (0.55 − ½ − 0.1 < 0).
TEST(GrainPlacement, SegmentGapAboveTheTopFace) {
  const ShapeLibrary library = cube_library(1.0);
  const PosedShape cube(library[0].shape, Vector3d::Zero(), Quaterniond::Identity());
  const double bound = std::sqrt(3.0) / 2.0;
  const PlacementObstacle above = PlacementObstacle::segment(Vector3d(0.0, -0.5, 0.9), Vector3d(0.0, 1.0, 0.0), 0.1);
  EXPECT_NEAR(above.bound, 0.6, 1e-15);  // half length + radius
  EXPECT_NEAR(above.x.y(), 0.0, 1e-15);  // the midpoint
  PlacementGrid grid = open_grid(library, bound);
  grid.add(PlacementObstacle::segment(Vector3d(0.0, -0.5, 0.9), Vector3d(0.0, 1.0, 0.0), 0.1));
  double gap = 0.0;
  long pairs = 0;
  EXPECT_FALSE(grid.overlaps(cube, bound, gap, pairs));
  EXPECT_NEAR(gap, 0.3, 1e-12);
  PlacementGrid low = open_grid(library, bound);
  low.add(PlacementObstacle::segment(Vector3d(0.0, -0.5, 0.55), Vector3d(0.0, 1.0, 0.0), 0.1));
  EXPECT_TRUE(low.overlaps(cube, bound, gap, pairs));
}

// Two unit cubes face to face: gap = distance of the centres − 1; a cube turned by 45°
// about z reaches √2/2 along x.
TEST(GrainPlacement, GrainGapFaceToFaceAndTurned) {
  const ShapeLibrary library = cube_library(1.0);
  const double bound = std::sqrt(3.0) / 2.0;
  const PosedShape cube(library[0].shape, Vector3d::Zero(), Quaterniond::Identity());
  PlacementGrid grid = open_grid(library, bound);
  grid.add(PlacementObstacle::grain(library, 0, Vector3d(1.25, 0.0, 0.0), Quaterniond::Identity()));
  double gap = 0.0;
  long pairs = 0;
  EXPECT_FALSE(grid.overlaps(cube, bound, gap, pairs));
  EXPECT_NEAR(gap, 0.25, 1e-12);
  const Quaterniond turned(Eigen::AngleAxisd(kPi / 4.0, Vector3d::UnitZ()));
  PlacementGrid turned_grid = open_grid(library, bound);
  turned_grid.add(PlacementObstacle::grain(library, 0, Vector3d(1.25, 0.0, 0.0), turned));
  EXPECT_FALSE(turned_grid.overlaps(cube, bound, gap, pairs));
  EXPECT_NEAR(gap, 1.25 - 0.5 - std::sqrt(0.5), 1e-12);
  PlacementGrid close = open_grid(library, bound);
  close.add(PlacementObstacle::grain(library, 0, Vector3d(1.15, 0.0, 0.0), turned));
  EXPECT_TRUE(close.overlaps(cube, bound, gap, pairs));  // 1.15 < ½ + √2/2
}

// Periodic in x over [−1.5, 1.5): a sphere at x = 1.35 is 0.35 from a cube (edge 0.4) at
// x = −1.3 through the boundary, not 2.65.
TEST(GrainPlacement, PeriodicImage) {
  const ShapeLibrary library = cube_library(0.4);
  const double bound = std::sqrt(3.0) * 0.2;
  const PosedShape cube(library[0].shape, Vector3d(-1.3, 0.0, 0.0), Quaterniond::Identity());
  for (const bool periodic : {false, true}) {
    PlacementGrid grid(library, Vector3d(-1.5, -1.5, -1.5), Vector3d(1.5, 1.5, 1.5), {periodic, false, false}, bound);
    grid.add(PlacementObstacle::sphere(Vector3d(1.3, 0.0, 0.0), 0.1));
    double gap = 0.0;
    long pairs = 0;
    EXPECT_FALSE(grid.overlaps(cube, bound, gap, pairs));
    if (periodic)
      EXPECT_NEAR(gap, 0.4 - 0.2 - 0.1, 1e-12);
    else
      EXPECT_EQ(pairs, 0);
    grid.add(PlacementObstacle::sphere(Vector3d(1.35, 0.0, 0.0), 0.2));
    EXPECT_EQ(grid.overlaps(cube, bound, gap, pairs), periodic);  // 0.35 − 0.2 − 0.2 < 0
  }
}

// [0, 4) × [0, 3) at spacing 1: 4 × 3 cell centres (lattice A), then 3 × 2 inner corners
// (lattice B) higher up; [0, 4.5) leaves a margin of 0.25 on each side.
TEST(LayerLattice, SitesOfBothLattices) {
  const wiregrain::LayerLattice lattice(0.0, 4.0, 0.0, 3.0, 1.0);
  EXPECT_EQ(lattice.cells(), 12.0);
  const auto all = [](const Vector3d&) { return true; };
  const std::vector<Vector3d> sites = lattice.sites(2.0, 1.5, all);
  ASSERT_EQ(sites.size(), 18u);
  EXPECT_TRUE(sites[0].isApprox(Vector3d(0.5, 0.5, 2.0)));
  EXPECT_TRUE(sites[1].isApprox(Vector3d(1.5, 0.5, 2.0)));
  EXPECT_TRUE(sites[4].isApprox(Vector3d(0.5, 1.5, 2.0)));
  EXPECT_TRUE(sites[12].isApprox(Vector3d(1.0, 1.0, 3.5)));
  EXPECT_TRUE(sites[17].isApprox(Vector3d(3.0, 2.0, 3.5)));
  const std::vector<Vector3d> left = lattice.sites(2.0, 1.5, [](const Vector3d& p) { return p.x() <= 2.0; });
  EXPECT_EQ(left.size(), 6u + 4u);
  const wiregrain::LayerLattice wide(0.0, 4.5, 0.0, 1.0, 1.0);
  EXPECT_EQ(wide.cells(), 4.0);
  EXPECT_NEAR(wide.sites(0.0, 1.0, all)[0].x(), 0.75, 1e-15);
}

// Layer: two sites 3 apart take two unit cubes at the first attempt; two grains on one
// site: the second never fits, after `attempts` orientations.
TEST(GrainPlacement, PlacesOnSitesOrStops) {
  const ShapeLibrary library = cube_library(1.0);
  const double bound = std::sqrt(3.0) / 2.0;
  wiregrain::GrainSites where;
  where.layer = true;
  where.sites = {Vector3d(-1.5, 0.0, 0.0), Vector3d(1.5, 0.0, 0.0)};
  const std::vector<int> shape_of = {0, 0};
  const std::vector<Quaterniond> body_to_input(2, Quaterniond::Identity());
  std::mt19937_64 rng(7);
  PlacementGrid grid = open_grid(library, bound);
  const wiregrain::GrainPlacement placed = wiregrain::place_grains(grid, shape_of, body_to_input, where, 5, rng);
  EXPECT_EQ(placed.unplaced, -1);
  EXPECT_EQ(placed.tries, 2);
  EXPECT_TRUE(placed.position[1].isApprox(Vector3d(1.5, 0.0, 0.0)));
  EXPECT_NEAR(placed.orientation[0].norm(), 1.0, 1e-15);
  EXPECT_EQ(placed.close_pairs, 0);  // 3 > 2 × bounding radius: bounding spheres apart
  EXPECT_EQ(placed.min_gap, std::numeric_limits<double>::infinity());

  where.sites = {Vector3d::Zero(), Vector3d::Zero()};
  PlacementGrid crowded = open_grid(library, bound);
  const wiregrain::GrainPlacement stopped = wiregrain::place_grains(crowded, shape_of, body_to_input, where, 5, rng);
  EXPECT_EQ(stopped.unplaced, 1);
  EXPECT_EQ(stopped.tries, 1 + 5);
}

// Random positions: only where `inside` holds, in [lo, hi).
TEST(GrainPlacement, RandomPositionsInside) {
  const ShapeLibrary library = cube_library(0.2);
  const double bound = std::sqrt(3.0) * 0.1;
  wiregrain::GrainSites where;
  where.lo = Vector3d(-4, -4, -4);
  where.hi = Vector3d(4, 4, 4);
  where.inside = [](const Vector3d& p) { return p.x() > 0.0; };
  const std::vector<int> shape_of(20, 0);
  const std::vector<Quaterniond> body_to_input(20, Quaterniond::Identity());
  std::mt19937_64 rng(11);
  PlacementGrid grid = open_grid(library, bound);
  const wiregrain::GrainPlacement placed = wiregrain::place_grains(grid, shape_of, body_to_input, where, 1000, rng);
  ASSERT_EQ(placed.unplaced, -1);
  for (const Vector3d& p : placed.position) {
    EXPECT_GT(p.x(), 0.0);
    EXPECT_LT(p.x(), 4.0);
    EXPECT_GE(p.y(), -4.0);
    EXPECT_LT(p.z(), 4.0);
  }
  EXPECT_GT(placed.tries, 20);  // about half the positions fall on the wrong side
}

// Uniform rotations: each component of the unit quaternion has ⟨q_i²⟩ = 1/4 (a uniform
// point on S³).
TEST(GrainGeneration, RandomOrientationIsUniform) {
  std::mt19937_64 rng(3);
  const int n = 40000;
  double w2 = 0.0, x2 = 0.0, z2 = 0.0;
  for (int k = 0; k < n; k++) {
    const Quaterniond q = wiregrain::random_orientation(rng);
    ASSERT_NEAR(q.norm(), 1.0, 1e-14);
    w2 += q.w() * q.w();
    x2 += q.x() * q.x();
    z2 += q.z() * q.z();
  }
  // standard deviation of the mean of q_i² on S³: √(1/8 − 1/16) / √n ≈ 0.0013
  EXPECT_NEAR(w2 / n, 0.25, 0.006);
  EXPECT_NEAR(x2 / n, 0.25, 0.006);
  EXPECT_NEAR(z2 / n, 0.25, 0.006);
  for (int k = 0; k < 1000; k++) {
    const double u = wiregrain::uniform01(rng);
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
  }
}

// Ellipsoids: one shape per grain, every hull vertex on the ellipsoid (x/a)² + (y/b)² +
// (z/c)² = 1 in the frame it was drawn in (a = 1 here); a given shape: added once.
TEST(GrainGeneration, DrawsOneShapePerGrainOrOneForAll) {
  wiregrain::GrainShapeRecipe recipe;
  recipe.a_min = recipe.a_max = 1.0;
  recipe.b_over_a = 0.8;
  recipe.c_over_a = 0.5;
  recipe.sweep = 0.0;
  std::vector<ConvexShape> added;
  const wiregrain::AddGrainShape add = [&](const ConvexShape& shape, Quaterniond& q) {
    added.push_back(shape);
    q = Quaterniond(Eigen::AngleAxisd(0.3, Vector3d::UnitY()));
    return static_cast<int>(added.size()) - 1;
  };
  std::mt19937_64 rng(5);
  const wiregrain::GrainShapeDraw draw = wiregrain::draw_grain_shapes(rng, recipe, 3, add);
  ASSERT_EQ(added.size(), 3u);
  EXPECT_EQ(draw.shape_of, (std::vector<int>{0, 1, 2}));
  for (const ConvexShape& s : added) {
    EXPECT_EQ(s.vertices().size(), 20u);
    for (const Vector3d& v : s.vertices())
      EXPECT_NEAR(std::pow(v.x(), 2) + std::pow(v.y() / 0.8, 2) + std::pow(v.z() / 0.5, 2), 1.0, 1e-12);
  }
  EXPECT_TRUE(draw.body_to_input[2].isApprox(Quaterniond(Eigen::AngleAxisd(0.3, Vector3d::UnitY()))));

  added.clear();
  recipe.kind = "cube";
  recipe.size[0] = 2.0;
  std::mt19937_64 untouched(5), reference(5);
  const wiregrain::GrainShapeDraw cubes = wiregrain::draw_grain_shapes(untouched, recipe, 4, add);
  ASSERT_EQ(added.size(), 1u);
  EXPECT_EQ(cubes.shape_of, (std::vector<int>{0, 0, 0, 0}));
  EXPECT_EQ(untouched(), reference());  // no number drawn
}

// A cube of volume 1 becomes the sphere of volume 1: r = (3 / 4π)^(1/3).
TEST(GrainGeneration, SpheresOfTheGrainsVolumes) {
  ShapeLibrary library = cube_library(1.0);
  library.add(ConvexShape::cube(2.0, 0.0));
  std::vector<int> shape_of = {1, 0, 1};
  wiregrain::replace_by_spheres_of_volume(library, shape_of);
  ASSERT_EQ(library.size(), 4);
  EXPECT_EQ(shape_of, (std::vector<int>{3, 2, 3}));
  EXPECT_NEAR(library[2].shape.sweep_radius(), std::cbrt(3.0 / (4.0 * kPi)), 1e-14);
  EXPECT_NEAR(library[3].volume, 8.0, 1e-12);
  EXPECT_NEAR(4.0 / 3.0 * kPi * std::pow(library[2].shape.sweep_radius(), 3), 1.0, 1e-13);
}
