// Column observables (core/column/observables.h) against values worked out by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/column/observables.h"
#include "core/common/errors.h"
#include "core/geometry/convex_shape.h"

using namespace wiregrain;
using Eigen::Vector2d;
using Eigen::Vector3d;

TEST(ColumnObservables, GrainTopIsTheHighestCoreVertexPlusTheSweep) {
  const ConvexShape cube = ConvexShape::cube(2.0, 0.1);
  // a cube turned by 45° about x: its top is an edge at √2 above the centre
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(M_PI / 4, Vector3d::UnitX()));
  const PosedShape grain(cube, Vector3d(0.3, -1.0, 5.0), turn);
  EXPECT_NEAR(grain_top(grain), 5.0 + std::sqrt(2.0) + 0.1, 1e-14);
  const ConvexShape sphere = ConvexShape::sphere(0.7);
  const PosedShape ball(sphere, Vector3d(1, 2, 3), Eigen::Quaterniond::Identity());
  EXPECT_NEAR(grain_top(ball), 3.7, 1e-15);
}

TEST(ColumnObservables, QuantileInterpolatesBetweenOrderStatistics) {
  // 0..100 in steps of 1 (shuffled): the q-quantile is 100 q
  std::vector<double> v;
  for (int k = 100; k >= 0; --k) v.push_back(double((k * 37) % 101));
  EXPECT_DOUBLE_EQ(quantile(v, 0.98), 98.0);
  EXPECT_DOUBLE_EQ(quantile(v, 0.985), 98.5);
  EXPECT_DOUBLE_EQ(quantile(v, 1.0), 100.0);
  EXPECT_DOUBLE_EQ(quantile(v, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(quantile({4.0}, 0.5), 4.0);
  // one stray value far above moves the 0.98-quantile by one order statistic only:
  // 102 values, position 0.98 · 101 = 98.98 between 98 and 99
  v.push_back(1e6);
  EXPECT_NEAR(quantile(v, 0.98), 98.98, 1e-12);
}

// quantile_of_parts against quantile() of all the values at once: the values spread
// over three "workers" (one of them empty), count_at_most summing the three counts
TEST(ColumnObservables, QuantileOfPartsEqualsTheQuantileOfAllValuesToTheBit) {
  std::mt19937_64 random(20261207);
  std::uniform_real_distribution<double> height(-2.0, 9.0);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 1 + trial * 7;
    std::vector<double> all;
    for (int k = 0; k < n; ++k) all.push_back(trial % 4 == 0 ? std::round(height(random)) : height(random));
    if (trial % 5 == 1) all.push_back(0.0), all.push_back(-0.0), all.push_back(all.front());  // ties and zeros
    std::vector<std::vector<double>> parts(3);
    for (std::size_t k = 0; k < all.size(); ++k) parts[k % 3 == 2 ? 0 : k % 3 + (trial % 2)].push_back(all[k]);
    long rounds = 0;
    const auto count_at_most = [&](double x) {
      ++rounds;
      long count = 0;
      for (const auto& part : parts)
        for (double v : part) count += v <= x ? 1 : 0;
      return count;
    };
    const double lowest = *std::min_element(all.begin(), all.end());
    const double highest = *std::max_element(all.begin(), all.end());
    for (double q : {0.0, 0.02, 0.5, 0.75, 0.98, 0.985, 1.0}) {
      rounds = 0;
      const double expected = quantile(all, q);
      const double got = quantile_of_parts(long(all.size()), lowest, highest, q, count_at_most);
      EXPECT_EQ(got, expected) << "trial " << trial << " q " << q;  // to the bit (±0 compare equal)
      EXPECT_LE(rounds, 128);
    }
  }
  const auto none = [](double) { return 0L; };
  EXPECT_THROW(quantile_of_parts(0, 0.0, 1.0, 0.5, none), InvalidArgument);
  EXPECT_THROW(quantile_of_parts(3, 0.0, 1.0, 1.5, none), InvalidArgument);
  EXPECT_THROW(quantile_of_parts(3, 2.0, 1.0, 0.5, none), InvalidArgument);
  EXPECT_THROW(quantile_of_parts(3, 0.0, HUGE_VAL, 0.5, none), InvalidArgument);
}

TEST(ColumnObservables, RetentionCountsCentresInsideTheWireCylinder) {
  // beads on two circles of radius 2 and 4 about (1, 1): mean distance 3
  std::vector<Vector3d> beads;
  for (int k = 0; k < 12; ++k) {
    const double a = 2 * M_PI * k / 12;
    beads.emplace_back(1 + 2 * std::cos(a), 1 + 2 * std::sin(a), 0.5 * k);
    beads.emplace_back(1 + 4 * std::cos(a), 1 + 4 * std::sin(a), 0.3 * k);
  }
  const Vector2d axis(1, 1);
  EXPECT_NEAR(mean_axis_distance(beads, axis), 3.0, 1e-14);
  // grains at distances 0, 1, 2.9, 3.1, 5 from the axis, at any height
  const std::vector<Vector3d> grains = {{1, 1, 9}, {2, 1, 0}, {1, 3.9, 4}, {1 - 3.1, 1, 2}, {4, 5, 1}};
  const Retention r = retention(grains, axis, 3.0);
  EXPECT_EQ(r.inside, 3);
  EXPECT_EQ(r.total, 5);
  EXPECT_DOUBLE_EQ(r.fraction, 0.6);
  EXPECT_EQ(retention({}, axis, 3.0).fraction, 0.0);
}

TEST(ColumnObservables, BadInputNamesTheArgument) {
  const auto argument_of = [](auto&& call) {
    try {
      call();
    } catch (const InvalidArgument& e) {
      return e.argument();
    }
    return std::string("none");
  };
  EXPECT_EQ(argument_of([] { quantile({}, 0.5); }), "values");
  EXPECT_EQ(argument_of([] { quantile({1.0}, 1.5); }), "quantile");
  EXPECT_EQ(argument_of([] { quantile({1.0}, std::nan("")); }), "quantile");
  EXPECT_EQ(argument_of([] { mean_axis_distance({}, Vector2d::Zero()); }), "points");
}
