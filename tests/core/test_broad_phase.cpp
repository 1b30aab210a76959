// core/geometry/broad_phase: the grid's candidate pairs against all pairs by brute force
// (minimum image in periodic dimensions), on random points.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <utility>

#include "core/common/errors.h"
#include "core/geometry/broad_phase.h"

using wiregrain::BroadPhaseGrid;

namespace {

// pair (i, j) → minimum-image displacement x_j − x_i, for every pair closer than cutoff
std::map<std::pair<int, int>, Eigen::Vector3d> brute_force(const std::vector<Eigen::Vector3d>& x,
                                                           const Eigen::Vector3d& period, double cutoff) {
  std::map<std::pair<int, int>, Eigen::Vector3d> pairs;
  for (int i = 0; i < (int)x.size(); i++)
    for (int j = i + 1; j < (int)x.size(); j++) {
      Eigen::Vector3d d = x[j] - x[i];
      for (int k = 0; k < 3; k++)
        if (period[k] > 0.0) d[k] -= period[k] * std::round(d[k] / period[k]);
      if (d.norm() < cutoff) pairs[{i, j}] = d;
    }
  return pairs;
}

std::vector<Eigen::Vector3d> random_points(int n, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Eigen::Vector3d> x(n);
  for (auto& p : x)
    for (int k = 0; k < 3; k++) p[k] = lo[k] + u(rng) * (hi[k] - lo[k]);
  return x;
}

void expect_same_pairs(const BroadPhaseGrid& grid, const std::vector<Eigen::Vector3d>& x,
                       const Eigen::Vector3d& period, double cutoff) {
  const auto expected = brute_force(x, period, cutoff);
  const auto found = grid.candidate_pairs(cutoff);
  ASSERT_EQ(found.size(), expected.size());
  for (const auto& p : found) {
    const auto it = expected.find({p.i, p.j});
    ASSERT_NE(it, expected.end()) << p.i << " " << p.j;
    EXPECT_LT(((x[p.j] + p.shift - x[p.i]) - it->second).norm(), 1e-12);
  }
}

}  // namespace

TEST(BroadPhase, UnboundedGridFindsEveryPairWithinTheCell) {
  const auto x = random_points(600, {-3, -2, 5}, {4, 3, 9}, 11);
  const double cutoff = 0.7;
  BroadPhaseGrid grid = BroadPhaseGrid::unbounded(cutoff);
  for (const auto& p : x) grid.insert(p);
  expect_same_pairs(grid, x, Eigen::Vector3d::Zero(), cutoff);
}

TEST(BroadPhase, BoxGridNonPeriodic) {
  const Eigen::Vector3d lo(0, 0, 0), hi(5, 4, 3);
  const auto x = random_points(500, lo, hi, 3);
  BroadPhaseGrid grid = BroadPhaseGrid::box(lo, hi, {false, false, false}, 0.6);
  for (const auto& p : x) grid.insert(p);
  EXPECT_DOUBLE_EQ(grid.cell_width()[0], 5.0 / 8);   // ⌊5/0.6⌋ = 8 cells
  expect_same_pairs(grid, x, Eigen::Vector3d::Zero(), 0.6);
}

TEST(BroadPhase, PeriodicPairsInTheirMinimumImage) {
  const Eigen::Vector3d lo(-1, 2, 0), hi(4, 6, 3);
  const auto x = random_points(500, lo, hi, 5);
  BroadPhaseGrid grid = BroadPhaseGrid::box(lo, hi, {true, false, true}, 0.6);
  for (const auto& p : x) grid.insert(p);
  const Eigen::Vector3d period(5, 0, 3);
  expect_same_pairs(grid, x, period, 0.6);
  // some pairs cross the periodic boundaries
  int shifted = 0;
  for (const auto& p : grid.candidate_pairs(0.6)) shifted += p.shift.norm() > 0.0;
  EXPECT_GT(shifted, 0);
}

TEST(BroadPhase, FewPeriodicCellsAreVisitedOnce) {
  // 2 cells along x: the wrapped neighbours coincide; every pair must still come once
  const Eigen::Vector3d lo(0, 0, 0), hi(2.5, 10, 10);
  const auto x = random_points(300, lo, hi, 9);
  BroadPhaseGrid grid = BroadPhaseGrid::box(lo, hi, {true, true, true}, 1.2);
  for (const auto& p : x) grid.insert(p);
  expect_same_pairs(grid, x, Eigen::Vector3d(2.5, 10, 10), 1.2);
}

TEST(BroadPhase, PointsOutsideTheBoxFallInTheEndCells) {
  BroadPhaseGrid grid = BroadPhaseGrid::box({0, 0, 0}, {10, 10, 10}, {false, false, false}, 1.0);
  grid.insert({-0.3, 5, 5});
  grid.insert({0.2, 5, 5});
  const auto pairs = grid.candidate_pairs(1.0);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].shift, Eigen::Vector3d::Zero());
}

TEST(BroadPhase, BadGridsAreRejected) {
  EXPECT_THROW(BroadPhaseGrid::unbounded(0.0), wiregrain::InvalidArgument);
  EXPECT_THROW(BroadPhaseGrid::box({0, 0, 0}, {1, 0, 1}, {false, false, false}, 0.5), wiregrain::InvalidArgument);
}

namespace {

// every (point, shift) a query visits, in visiting order
std::vector<std::pair<int, Eigen::Vector3d>> visits(const BroadPhaseGrid& grid, const Eigen::Vector3d& x) {
  std::vector<std::pair<int, Eigen::Vector3d>> seen;
  grid.for_each_near(x, [&](int j, const Eigen::Vector3d& shift) { seen.emplace_back(j, shift); });
  return seen;
}

// the same visits (points, shifts, order) of both grids for every query; returns how many
// points the queries visited
long expect_same_visits(const BroadPhaseGrid& one, const BroadPhaseGrid& other,
                        const std::vector<Eigen::Vector3d>& queries) {
  long total = 0;
  for (const auto& q : queries) {
    const auto a = visits(one, q), b = visits(other, q);
    EXPECT_EQ(a.size(), b.size());
    if (a.size() != b.size()) return total;
    for (std::size_t k = 0; k < a.size(); k++) {
      EXPECT_EQ(a[k].first, b[k].first);
      EXPECT_EQ(a[k].second, b[k].second);
    }
    total += static_cast<long>(a.size());
  }
  return total;
}

// the grid with and without its dense index: the same visits (points, shifts, order) for
// queries at the points and at random places in and around their range, and with the
// index every pair closer than the cell found (against brute force)
void expect_index_changes_nothing(BroadPhaseGrid hashed, const std::vector<Eigen::Vector3d>& x,
                                  const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                                  const Eigen::Vector3d& period, double cutoff) {
  for (const auto& p : x) hashed.insert(p);
  BroadPhaseGrid indexed = hashed;
  indexed.index();
  ASSERT_TRUE(indexed.indexed());
  ASSERT_FALSE(hashed.indexed());
  auto queries = x;
  const Eigen::Vector3d margin = Eigen::Vector3d::Constant(2.0 * cutoff);
  for (const auto& q : random_points(200, lo - margin, hi + margin, 17)) queries.push_back(q);
  EXPECT_GT(expect_same_visits(hashed, indexed, queries), static_cast<long>(x.size()));  // they did visit points
  expect_same_pairs(indexed, x, period, cutoff);
}

// assign(points) against insert of each point: the same visits, indexed or not (a point
// far away refuses the dense index)
void expect_assign_is_insert(BroadPhaseGrid empty, std::vector<Eigen::Vector3d> x, const Eigen::Vector3d& lo,
                             const Eigen::Vector3d& hi, bool far_point) {
  if (far_point) x.push_back(hi + Eigen::Vector3d(1e6, 0, 0));
  BroadPhaseGrid inserted = empty, assigned = empty;
  for (const auto& p : x) inserted.insert(p);
  inserted.index();
  assigned.assign(x);
  ASSERT_EQ(assigned.size(), inserted.size());
  ASSERT_EQ(assigned.indexed(), !far_point);
  ASSERT_EQ(inserted.indexed(), !far_point);
  EXPECT_GT(expect_same_visits(inserted, assigned, random_points(300, lo, hi, 23)), 300);
}

}  // namespace

TEST(BroadPhase, DenseIndexVisitsTheSamePointsInTheSameOrder) {
  {
    const Eigen::Vector3d lo(-3, -2, 5), hi(4, 3, 9);
    expect_index_changes_nothing(BroadPhaseGrid::unbounded(0.7), random_points(600, lo, hi, 11), lo, hi,
                                 Eigen::Vector3d::Zero(), 0.7);
  }
  {
    const Eigen::Vector3d lo(0, 0, 0), hi(5, 4, 3);
    expect_index_changes_nothing(BroadPhaseGrid::box(lo, hi, {false, false, false}, 0.6),
                                 random_points(500, lo, hi, 3), lo, hi, Eigen::Vector3d::Zero(), 0.6);
  }
  {
    const Eigen::Vector3d lo(-1, 2, 0), hi(4, 6, 3);
    expect_index_changes_nothing(BroadPhaseGrid::box(lo, hi, {true, false, true}, 0.6),
                                 random_points(500, lo, hi, 5), lo, hi, Eigen::Vector3d(5, 0, 3), 0.6);
  }
  {
    const Eigen::Vector3d lo(0, 0, 0), hi(2.5, 10, 10);  // 2 periodic cells along x
    expect_index_changes_nothing(BroadPhaseGrid::box(lo, hi, {true, true, true}, 1.2),
                                 random_points(300, lo, hi, 9), lo, hi, Eigen::Vector3d(2.5, 10, 10), 1.2);
  }
}

TEST(BroadPhase, DenseIndexIsNotBuiltForAFarPointAndDroppedByAnInsert) {
  auto x = random_points(50, {0, 0, 0}, {3, 3, 3}, 21);
  x.push_back({1e6, 0, 0});  // 1e6 cells away: the dense array would need 1e6 slots for 51 points
  BroadPhaseGrid grid = BroadPhaseGrid::unbounded(1.0);
  for (const auto& p : x) grid.insert(p);
  grid.index();
  EXPECT_FALSE(grid.indexed());
  expect_same_pairs(grid, x, Eigen::Vector3d::Zero(), 1.0);

  x.pop_back();
  BroadPhaseGrid near = BroadPhaseGrid::unbounded(1.0);
  for (const auto& p : x) near.insert(p);
  near.index();
  EXPECT_TRUE(near.indexed());
  x.push_back({1.5, 1.5, 1.5});  // an insert after index(): found, through the hash
  near.insert(x.back());
  EXPECT_FALSE(near.indexed());
  expect_same_pairs(near, x, Eigen::Vector3d::Zero(), 1.0);
}

TEST(BroadPhase, AssignedPointsAreVisitedAsInsertedOnes) {
  const Eigen::Vector3d lo(-1, 2, 0), hi(4, 6, 3);
  for (bool far_point : {false, true}) {
    expect_assign_is_insert(BroadPhaseGrid::unbounded(0.7), random_points(400, lo, hi, 7), lo, hi, far_point);
    expect_assign_is_insert(BroadPhaseGrid::box(lo, hi, {true, false, true}, 0.6), random_points(400, lo, hi, 9), lo, hi,
                            false);
  }
}
