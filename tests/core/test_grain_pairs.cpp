// The grain pair cache of the NSCD detection (core/nscd/grain_pairs.h): while 24 random
// Table 1 grains are poured into a box and settle, the problem assembled with the cache
// must equal, point for point and to the last bit, the problem of a full search (with
// warm_geometry: to rounding, and to the bit on any number of workers); the
// cache must be reused on most steps once the pile is at rest, with the kept pairs still
// apart skipped; and the motion bound must account for turns about the centre.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "core/common/errors.h"
#include "core/geometry/convex_shape.h"
#include "core/nscd/grain_pairs.h"
#include "core/nscd/grain_step.h"
#include "threaded_workers.h"

using namespace wiregrain;
using Eigen::Quaterniond;
using Eigen::Vector3d;

namespace {

void expect_same_problem(const GrainStepProblem& a, const GrainStepProblem& b, int step) {
  ASSERT_EQ(a.points.size(), b.points.size()) << "step " << step;
  for (std::size_t c = 0; c < a.points.size(); ++c) {
    EXPECT_EQ(a.points[c].pair, b.points[c].pair) << "step " << step << " point " << c;
    EXPECT_EQ(a.points[c].position, b.points[c].position) << "step " << step << " point " << c;
    EXPECT_EQ(a.points[c].frame, b.points[c].frame) << "step " << step << " point " << c;
    EXPECT_EQ(a.step.contacts[c].gap, b.step.contacts[c].gap) << "step " << step << " point " << c;
  }
}

std::vector<PlaneWall> box_walls(double half) {
  std::vector<PlaneWall> walls;
  const Vector3d normals[5] = {Vector3d::UnitZ(), Vector3d::UnitX(), -Vector3d::UnitX(), Vector3d::UnitY(),
                               -Vector3d::UnitY()};
  for (const Vector3d& n : normals) {
    PlaneWall w;
    w.normal = n;
    w.point = n.z() > 0 ? Vector3d::Zero() : Vector3d(-half * n);
    w.friction = n.z() > 0 ? 0.5 : 0.0;
    walls.push_back(w);
  }
  return walls;
}

// `count` grains of shape 0, tags 1, 2, ..., centred on the z axis at z0, z0 + dz, ...
std::vector<GrainState> grain_column(int count, double z0, double dz) {
  std::vector<GrainState> grains(count);
  for (int k = 0; k < count; ++k) {
    grains[k].tag = k + 1;
    grains[k].position = Vector3d(0, 0, z0 + dz * k);
  }
  return grains;
}

// The step assembled by `workers` workers on threads with the detection shared
// (threaded_workers.h); each worker has its own pair cache, as each MPI rank has.
std::vector<GrainStepProblem> assemble_shared(int workers, const std::vector<GrainState>& grains,
                                              const ShapeLibrary& library, const std::vector<PlaneWall>& walls,
                                              double h, const GrainStepOptions& options,
                                              const GrainImpulseMemory& memory, std::vector<GrainPairCache>& caches) {
  std::vector<GrainStepProblem> problems(workers);
  run_threaded_workers(workers, [&](const WorkShare& share, int w) {
    problems[w] = assemble_grain_step(grains, library, walls, h, options, memory, &caches[w], &share);
  });
  return problems;
}

}  // namespace

// The same problem to rounding: the same pairs and point counts, each point of `a` in `b`
// within 1e-9 (position, normal) and 1e-12 (gap); the points' order may differ where their
// heights nearly tie, the polygon of a face–face contact may start at another vertex.
void expect_problem_within_rounding(const GrainStepProblem& a, const GrainStepProblem& b, int step) {
  ASSERT_EQ(a.points.size(), b.points.size()) << "step " << step;
  for (std::size_t c = 0; c < a.points.size(); ++c) {
    std::size_t match = b.points.size();
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t d = 0; d < b.points.size(); ++d)
      if (b.points[d].pair == a.points[c].pair && (b.points[d].position - a.points[c].position).norm() < nearest) {
        nearest = (b.points[d].position - a.points[c].position).norm();
        match = d;
      }
    ASSERT_LT(match, b.points.size()) << "step " << step << " point " << c << ": no point of its pair";
    EXPECT_LT(nearest, 1e-9) << "step " << step << " point " << c;
    EXPECT_LT((a.points[c].frame.col(0) - b.points[match].frame.col(0)).norm(), 1e-9) << "step " << step << " point " << c;
    EXPECT_NEAR(a.step.contacts[c].gap, b.step.contacts[match].gap, 1e-12) << "step " << step << " point " << c;
  }
}

// 24 random Table 1 grains poured into a box, the grains moved by the full search's
// solution. warm_geometry off: the cache's problem is the full search's to the bit, every
// step, and so is the detection shared by 3 workers (every 25th step: each worker's cache
// is built then, and reused when still valid). On: the cache's problem is the full
// search's to rounding, and the shared detection's (every step, each worker with its own
// cache) is the single cache's to the bit: every worker holds every pair's simplex. A
// cache restored from its restart record goes on as the one it was written from.
void pour_and_compare(bool warm_geometry) {
  std::mt19937_64 rng(915);
  ShapeLibrary library;
  std::vector<GrainState> grains;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int k = 0; k < 24; ++k) {
    const double a = 0.8 + 0.2 * u(rng);
    const int shape = library.add(ConvexShape::random_ellipsoid(rng, 20, a, 0.8, 0.6, 0.1));
    const MassProperties mass = library[shape].shape.mass_properties(1.5, MassModel::dilated);
    GrainState g;
    g.tag = 100 + 3 * k;
    g.shape = shape;
    g.position = Vector3d(-1.6 + 1.6 * (k % 3), -1.6 + 1.6 * ((k / 3) % 3), 1.2 + 1.9 * (k / 9));
    g.orientation = Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized();
    g.velocity = Vector3d(0.3 * normal(rng), 0.3 * normal(rng), 0.0);
    g.mass = mass.mass;
    g.inertia = Vector3d(mass.inertia(0, 0), mass.inertia(1, 1), mass.inertia(2, 2));
    grains.push_back(g);
  }
  const std::vector<PlaneWall> walls = box_walls(2.6);
  GrainStepOptions options;
  options.near_vertices = true;
  options.warm_geometry = warm_geometry;
  const double h = 2e-3;
  GrainImpulseMemory memory, memory_cached;
  GrainPairCache cache(0.1);
  std::vector<GrainPairCache> worker_caches(3, GrainPairCache(0.1));
  GrainPairCache restored(0.1);
  int shared_checks = 0;
  int with_points = 0;
  const int steps = 3000;
  for (int step = 0; step < steps; ++step) {
    for (GrainState& g : grains) g.force = Vector3d(0, 0, -g.mass);  // g = 1
    GrainStepProblem full = assemble_grain_step(grains, library, walls, h, options, memory);
    GrainStepProblem cached = assemble_grain_step(grains, library, walls, h, options, memory_cached, &cache);
    if (warm_geometry)
      expect_problem_within_rounding(full, cached, step);
    else
      expect_same_problem(full, cached, step);
    if (warm_geometry || step % 25 == 0) {
      for (const GrainStepProblem& shared : assemble_shared(3, grains, library, walls, h, options, memory, worker_caches))
        expect_same_problem(warm_geometry ? cached : full, shared, step);
      shared_checks += !full.points.empty();
    }
    // a cache restored from the numbers of a restart file at step 1500 goes on as the one
    // it was written from, to the bit (its simplices too)
    if (step == 1500) {
      const std::vector<double> record = cache.serialize();
      restored.restore(record.data(), record.size());
      EXPECT_EQ(restored.serialize(), record);
    }
    if (step >= 1500) {
      GrainImpulseMemory unused = memory_cached;
      expect_same_problem(cached, assemble_grain_step(grains, library, walls, h, options, unused, &restored), step);
    }
    if (::testing::Test::HasFailure()) return;
    with_points += !full.points.empty();
    const GrainStepResult r = solve_grain_step(full, grains, options, step, memory);
    solve_grain_step(cached, grains, options, step, memory_cached);
    for (std::size_t k = 0; k < grains.size(); ++k) {
      GrainState& g = grains[k];
      const Eigen::Matrix3d rot = g.orientation.toRotationMatrix();
      const Eigen::Matrix3d inertia = rot * g.inertia.asDiagonal() * rot.transpose();
      const GrainPose next = advance_grain_pose({g.position, g.orientation}, g.inertia, g.velocity, r.velocities[k],
                                                inertia * g.angular_velocity, inertia * r.angular_velocities[k], h, 1.0);
      g.position = next.position;
      g.orientation = next.orientation;
      g.velocity = r.velocities[k];
      g.angular_velocity = r.angular_velocities[k];
    }
  }
  double fastest = 0.0;
  for (const GrainState& g : grains) fastest = std::max(fastest, g.velocity.norm());
  std::printf("builds %ld, reuses %ld over %d steps, %ld kept pairs skipped as still apart; fastest grain at the end %.3g\n",
              cache.builds(), cache.reuses(), steps, cache.skipped(), fastest);
  EXPECT_GT(with_points, steps / 2);
  EXPECT_GT(shared_checks, 60);
  EXPECT_EQ(cache.builds() + cache.reuses(), steps);
  EXPECT_LT(cache.builds(), steps / 4);  // measured: see the printout
  EXPECT_GT(cache.skipped(), cache.reuses());  // more than one pair per reuse: the same problem without them
}

TEST(GrainPairCache, GivesTheProblemOfAFullSearchWhileGrainsArePouredAndSettle) { pour_and_compare(false); }

TEST(GrainPairCache, WithWarmGeometryGivesTheFullSearchToRoundingOnAnyNumberOfWorkers) { pour_and_compare(true); }

// Two unit cubes (tags 1, 2) on the z axis `dz` apart and a cache (skin 0.1) built over
// them at activation 0.01, keeping their pair with `simplex` when one is given.
struct TwoCubes {
  ShapeLibrary library;
  std::vector<GrainState> grains;
  GrainPairCache cache{0.1};
  explicit TwoCubes(double dz, const GjkSimplex* simplex = nullptr) {
    library.add(ConvexShape::cube(1.0, 0.0));
    grains = grain_column(2, 0.0, dz);
    cache.begin_build();
    if (simplex) cache.keep(0, 1, 0.05, *simplex);
    cache.end_build(grains, library, 0.01);
  }
};

TEST(GrainPairCache, RestoreRefusesABrokenRecordAndIgnoresAnotherSkin) {
  GjkSimplex simplex;
  simplex.size = 2;
  simplex.a = {3, 5, 0, 0};
  simplex.b = {1, 2, 0, 0};
  TwoCubes two(1.05, &simplex);
  ShapeLibrary& library = two.library;
  std::vector<GrainState>& grains = two.grains;
  GrainPairCache& cache = two.cache;
  const std::vector<double> record = cache.serialize();
  GrainPairCache same(0.1), other(0.2), broken(0.1);
  EXPECT_EQ(same.restore(record.data(), record.size()), record.size());
  ASSERT_EQ(same.pairs().size(), 1u);
  EXPECT_EQ(same.pairs()[0].simplex.size, 2);
  EXPECT_EQ(same.pairs()[0].simplex.a[1], 5);
  EXPECT_TRUE(same.valid(grains, library, 0.01));
  EXPECT_EQ(other.restore(record.data(), record.size()), record.size());  // read, not taken
  EXPECT_TRUE(other.pairs().empty());
  EXPECT_FALSE(other.valid(grains, library, 0.01));
  try {
    broken.restore(record.data(), record.size() - 1);
    FAIL() << "a record one number short was taken";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), "data");
    EXPECT_NE(std::string(e.what()).find("ends early"), std::string::npos) << e.what();
  }
}

TEST(GrainPairCache, ATurnAboutTheCentreInvalidatesIt) {
  // two cubes 0.3 apart face to face; turning one by 20° about the axis through both
  // centres moves no centre, but its corners sweep 2 R sin(10°) ≈ 0.3 > skin/2
  TwoCubes two(1.3);
  ShapeLibrary& library = two.library;
  std::vector<GrainState>& grains = two.grains;
  GrainPairCache& cache = two.cache;
  EXPECT_TRUE(cache.valid(grains, library, 0.01));
  EXPECT_FALSE(cache.valid(grains, library, 0.2));  // a larger activation distance
  grains[1].orientation = Quaterniond(Eigen::AngleAxisd(20.0 * M_PI / 180.0, Vector3d::UnitZ()));
  EXPECT_FALSE(cache.valid(grains, library, 0.01));
  grains[1].orientation = Quaterniond(Eigen::AngleAxisd(0.5 * M_PI / 180.0, Vector3d::UnitZ()));
  EXPECT_TRUE(cache.valid(grains, library, 0.01));  // 2 · 2 · 0.866 · sin(0.25°) = 0.015 < 0.1
  grains[1].tag = 7;
  EXPECT_FALSE(cache.valid(grains, library, 0.01));
}

// A join that does not hold every block, and a worker index outside [0, workers), are
// refused with a message instead of a problem made of missing points.
TEST(GrainPairCache, ASharedDetectionWithABadJoinIsRefused) {
  ShapeLibrary library;
  library.add(ConvexShape::cube(1.0, 0.1));
  const std::vector<GrainState> grains = grain_column(2, 0.6, 1.15);
  GrainStepOptions options;
  GrainImpulseMemory memory;
  WorkShare share;
  share.workers = 2;
  share.all_gather = [](const std::vector<double>& mine) { return mine; };  // the other block missing
  EXPECT_THROW(assemble_grain_step(grains, library, box_walls(3.0), 1e-3, options, memory, nullptr, &share),
               NumericalFailure);
  share.worker = 2;
  EXPECT_THROW(assemble_grain_step(grains, library, box_walls(3.0), 1e-3, options, memory, nullptr, &share),
               InvalidArgument);
}

TEST(GrainPairCache, SkinMustBePositiveAndFinite) {
  for (double bad : {0.0, -1.0, std::nan(""), double(INFINITY)}) {
    try {
      GrainPairCache cache(bad);
      FAIL() << "accepted skin " << bad;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.argument(), "skin");
    }
  }
}
