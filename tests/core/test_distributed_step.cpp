// A grain step spread over workers (core/nscd/grain_step.h, GrainPartition), the workers
// on threads: each owns part of the grains and holds copies of its neighbours', the
// exchange sums per grain tag over all workers (as LIGGGHTS' reverse + forward
// communication does over the ranks). Against statics (a stack cut into 2 and 3 parts
// carries its weight exactly: the stick solve by conjugate gradients) and against one
// worker holding every grain (an oblique collision across the cut).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <condition_variable>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

#include "core/common/worker_exchange.h"
#include "core/geometry/convex_shape.h"
#include "core/nscd/grain_step.h"
#include "grain_scenes.h"

using namespace wiregrain;

namespace {

constexpr double kG = 1.0, kH = 1e-3;

// The workers' meeting point: each collective call waits for every worker, then each
// reads the sums it asked for.
class ThreadedExchange {
 public:
  explicit ThreadedExchange(int workers) : workers_(workers), posted_(workers) {}

  // worker w's values per local body (tags: its bodies' grain tags), summed per tag over
  // all workers' entries
  void sum_over_copies(int w, const std::vector<long>& tags, std::vector<double>& values, int width) {
    meet(w, [&] { posted_[w] = {tags, values, width}; }, [&] {
      std::map<long, std::vector<double>> sums;
      for (const Posted& p : posted_)
        for (std::size_t k = 0; k < p.tags.size(); k++) {
          std::vector<double>& s = sums[p.tags[k]];
          s.resize(p.width, 0.0);
          for (int j = 0; j < p.width; j++) s[j] += p.values[k * p.width + j];
        }
      for (std::size_t k = 0; k < tags.size(); k++)
        for (int j = 0; j < width; j++) values[k * width + j] = sums[tags[k]][j];
    });
  }
  void sum_over_workers(int w, double* values, int count) {
    meet(w, [&] { posted_[w] = {{}, std::vector<double>(values, values + count), count}; }, [&] {
      for (int j = 0; j < count; j++) {
        values[j] = 0.0;
        for (const Posted& p : posted_) values[j] += p.values[j];
      }
    });
  }

 private:
  struct Posted {
    std::vector<long> tags;
    std::vector<double> values;
    int width = 0;
  };
  // post, wait for all, read, wait for all to have read
  template <class Post, class Read>
  void meet(int, const Post& post, const Read& read) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return left_ == 0; });
    const long round = round_;
    post();
    if (++arrived_ == workers_) {
      ++round_;
      changed_.notify_all();
    }
    changed_.wait(lock, [&] { return round_ > round; });
    read();
    if (++left_ == workers_) {
      arrived_ = left_ = 0;
      changed_.notify_all();
    }
  }
  int workers_;
  std::vector<Posted> posted_;
  std::mutex mutex_;
  std::condition_variable changed_;
  int arrived_ = 0, left_ = 0;
  long round_ = 0;
};

// One worker's view of the exchange.
class WorkerView : public WorkerExchange {
 public:
  WorkerView(ThreadedExchange& all, int worker, std::vector<long> tags) : all_(all), worker_(worker), tags_(std::move(tags)) {}
  void sum_over_copies(std::vector<double>& values, int width) override { all_.sum_over_copies(worker_, tags_, values, width); }
  void sum_over_workers(double* values, int count) override { all_.sum_over_workers(worker_, values, count); }
  double max_over_workers(double value) override {
    // every worker's value in its own slot, the slots summed
    std::vector<double> slots(kMaxWorkers, 0.0);
    slots[worker_] = value;
    all_.sum_over_workers(worker_, slots.data(), kMaxWorkers);
    return *std::max_element(slots.begin(), slots.end());
  }

 private:
  static constexpr int kMaxWorkers = 8;
  ThreadedExchange& all_;
  int worker_;
  std::vector<long> tags_;
};

// a unit cube of mass 1 under gravity
GrainState cube(long tag, const Eigen::Vector3d& position, const Eigen::Vector3d& velocity = Eigen::Vector3d::Zero()) {
  return test_scenes::unit_cube(tag, position, 1.0, kG, velocity);
}
using test_scenes::floor_wall;

// Worker w's grains: those `owner` gives it (ascending tags), then copies of the others
// within `reach` (centre distance) of one of them.
std::vector<GrainState> worker_grains(const std::vector<GrainState>& all, const std::vector<int>& owner, int w,
                                      double reach, int& owned) {
  std::vector<GrainState> mine;
  for (std::size_t k = 0; k < all.size(); k++)
    if (owner[k] == w) mine.push_back(all[k]);
  owned = static_cast<int>(mine.size());
  for (std::size_t k = 0; k < all.size(); k++) {
    if (owner[k] == w) continue;
    for (int j = 0; j < owned; j++)
      if ((all[k].position - mine[j].position).norm() < reach) {
        mine.push_back(all[k]);
        break;
      }
  }
  return mine;
}

// Every worker's step; per grain tag the owner's result (velocity, contact force).
struct Owned {
  Eigen::Vector3d velocity, angular_velocity, contact_force, contact_torque;
};
std::map<long, Owned> distributed_step(const std::vector<GrainState>& all, const std::vector<int>& owner, int workers,
                                       const GrainStepOptions& options, std::vector<Eigen::Vector3d>* wall_forces = nullptr,
                                       std::vector<GrainStepStats>* stats = nullptr) {
  const ShapeLibrary library = test_scenes::unit_cube_library();
  ThreadedExchange exchange(workers);
  std::map<long, Owned> out;
  std::mutex out_mutex;
  std::vector<std::thread> threads;
  if (stats) stats->assign(workers, GrainStepStats());
  for (int w = 0; w < workers; w++)
    threads.emplace_back([&, w] {
      int owned = 0;
      const std::vector<GrainState> grains = worker_grains(all, owner, w, 3.0, owned);
      std::vector<long> tags;
      for (const GrainState& g : grains) tags.push_back(g.tag);
      WorkerView view(exchange, w, tags);
      GrainPartition partition;
      partition.owned = owned;
      partition.exchange = &view;
      GrainImpulseMemory memory;
      GrainStepProblem problem = assemble_grain_step(grains, library, {floor_wall(options.friction)}, kH, options, memory, nullptr,
                                                     nullptr, &partition);
      const GrainStepResult result = solve_grain_step(problem, grains, options, 1, memory);
      std::lock_guard<std::mutex> lock(out_mutex);
      for (int k = 0; k < owned; k++)
        out[grains[k].tag] = {result.velocities[k], result.angular_velocities[k], result.contact_forces[k],
                              result.contact_torques[k]};
      if (wall_forces && w == 0) *wall_forces = result.wall_forces;
      if (stats) (*stats)[w] = result.stats;
    });
  for (std::thread& t : threads) t.join();
  return out;
}

GrainStepOptions tight() { return test_scenes::tight_options(1e-12); }

}  // namespace

// Eight unit cubes (m = 1) stacked on the floor, cut into 2 and 3 parts: after one step
// every cube has the contact force m g upwards, no torque, no velocity, and the floor
// carries 8 m g (statics), whatever the cut.
TEST(DistributedStep, StackCutIntoPartsCarriesItsWeight) {
  std::vector<GrainState> stack;
  for (int k = 0; k < 8; k++) stack.push_back(cube(k + 1, Eigen::Vector3d(0, 0, 0.5 + k)));
  for (const std::vector<int>& owner : {std::vector<int>{0, 0, 0, 0, 1, 1, 1, 1}, std::vector<int>{0, 0, 2, 2, 2, 1, 1, 1}}) {
    const int workers = *std::max_element(owner.begin(), owner.end()) + 1;
    std::vector<Eigen::Vector3d> walls;
    const std::map<long, Owned> result = distributed_step(stack, owner, workers, tight(), &walls);
    ASSERT_EQ(result.size(), 8u);
    for (const auto& [tag, r] : result) {
      EXPECT_NEAR(r.contact_force.z(), kG, 1e-12) << "cube " << tag << ", " << workers << " workers";
      EXPECT_LT(r.contact_force.head<2>().norm(), 1e-12);
      EXPECT_LT(r.contact_torque.norm(), 1e-12);
      EXPECT_LT(r.velocity.norm() + r.angular_velocity.norm(), 1e-12);
    }
    ASSERT_EQ(walls.size(), 1u);
    EXPECT_NEAR(walls[0].z(), -8 * kG, 1e-11);
  }
}

// The stick solve's conjugate gradients, preconditioned by each worker's own block of
// W_SS + ε D (core/nscd/distributed_stick_solve.h): on one worker that block is the whole
// matrix and each stick solve ends after one iteration; cut into parts, M⁻¹ A − I has rank
// at most 12 per body touched by closed contacts of two workers (its 6 velocities seen
// from either side), so in exact arithmetic CG ends within 1 + 12 s iterations, s such
// bodies: 1 at one cut of the stack of eight cubes, 2 at two cuts (round-off may add a
// few). The stack's interfaces are face contacts of 4 points each: 8 × 4 × 3 = 96 unknowns.
TEST(DistributedStep, StickSolveIterationsStayWithinTheCutsRank) {
  std::vector<GrainState> stack;
  for (int k = 0; k < 8; k++) stack.push_back(cube(k + 1, Eigen::Vector3d(0, 0, 0.5 + k)));
  for (const auto& [owner, shared] : {std::pair<std::vector<int>, int>{{0, 0, 0, 0, 0, 0, 0, 0}, 0},
                                      std::pair<std::vector<int>, int>{{0, 0, 0, 0, 1, 1, 1, 1}, 1},
                                      std::pair<std::vector<int>, int>{{0, 0, 2, 2, 2, 1, 1, 1}, 2}}) {
    const int workers = *std::max_element(owner.begin(), owner.end()) + 1;
    std::vector<GrainStepStats> stats;
    distributed_step(stack, owner, workers, tight(), nullptr, &stats);
    // every worker takes part in every stick solve and counts the same iterations
    const int solves = stats[0].subspace_solves, iterations = stats[0].subspace_factorizations;
    std::printf("%d worker(s): %d stick solves, %d CG iterations\n", workers, solves, iterations);
    ASSERT_GT(solves, 0);
    for (const GrainStepStats& s : stats) EXPECT_EQ(s.subspace_factorizations, iterations);
    EXPECT_LE(iterations, solves * (1 + 12 * shared + 2)) << workers << " workers";
    if (shared == 0) EXPECT_EQ(iterations, solves);
  }
}

// Three cubes in a row on a frictionless floor, the outer ones sliding in obliquely against
// the middle one, without friction (the end velocities are then unique: the frictionless
// step minimises a strictly convex kinetic energy; with friction 0.5 the face contacts
// leave them undetermined by ~1e-4 at the same tolerance), the middle cube's owner not the
// others': on 2 and 3 workers each cube gets the velocities and contact forces of one
// worker holding all three. Measured: velocities 4.5e-16, forces 1.3e-16 of the largest;
// held to 1e-14 and 1e-14.
TEST(DistributedStep, CollisionAcrossTheCutIsTheOneWorkersCollision) {
  // gaps of 0.001 and 0.0005, closed within the step (h v = 0.002 and 0.0015)
  const std::vector<GrainState> row = {cube(1, Eigen::Vector3d(-1.001, 0.2, 0.5), Eigen::Vector3d(2.0, 0.3, 0.0)),
                                       cube(2, Eigen::Vector3d(0.0, 0.0, 0.5)),
                                       cube(3, Eigen::Vector3d(1.0005, -0.1, 0.5), Eigen::Vector3d(-1.5, 0.2, 0.0))};
  GrainStepOptions options = tight();
  options.friction = 0.0;
  const std::map<long, Owned> one = distributed_step(row, {0, 0, 0}, 1, options);
  const std::map<long, Owned> two = distributed_step(row, {0, 1, 0}, 2, options);
  const std::map<long, Owned> three = distributed_step(row, {2, 1, 0}, 3, options);
  double moving = 0.0;
  for (const auto& [tag, r] : one) moving = std::max(moving, r.contact_force.head<2>().norm());
  EXPECT_GT(moving, 100.0);  // they collided: impulses of order m v / h
  for (const std::map<long, Owned>* other : {&two, &three})
    for (const auto& [tag, r] : one) {
      const Owned& s = other->at(tag);
      std::printf("cube %ld: velocity %.1e, angular velocity %.1e, contact force %.1e of %.3g\n", tag,
                  (s.velocity - r.velocity).norm(), (s.angular_velocity - r.angular_velocity).norm(),
                  (s.contact_force - r.contact_force).norm(), moving);
      EXPECT_LT((s.velocity - r.velocity).norm(), 1e-14) << "cube " << tag;
      EXPECT_LT((s.angular_velocity - r.angular_velocity).norm(), 1e-14) << "cube " << tag;
      EXPECT_LT((s.contact_force - r.contact_force).norm(), 1e-14 * moving) << "cube " << tag;
    }
}
