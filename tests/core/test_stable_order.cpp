// stable_order (core/common/stable_order.h) against std::stable_sort on the items
// themselves: the same permutation for keys with many ties, -0.0 and 0.0 (equal keys),
// pair keys, an already sorted input and an empty one.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

#include "core/common/stable_order.h"

namespace wiregrain {
namespace {

template <class Key>
std::vector<std::size_t> by_stable_sort(const std::vector<Key>& keys) {
  std::vector<std::size_t> order(keys.size());
  for (std::size_t i = 0; i < order.size(); i++) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
  return order;
}

TEST(StableOrder, MatchesStableSortWithTies) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> small(-5, 5);
  std::vector<double> keys(5000);
  for (double& k : keys) k = 0.5 * small(random);
  keys[10] = -0.0;  // equal to 0.0: a tie, kept in input order
  keys[11] = 0.0;
  keys[12] = -0.0;
  EXPECT_EQ(stable_order(keys.size(), [&](std::size_t i) { return keys[i]; }), by_stable_sort(keys));
  std::vector<std::pair<long, long>> pairs(3000);
  for (auto& p : pairs) p = {small(random), small(random)};
  EXPECT_EQ(stable_order(pairs.size(), [&](std::size_t i) { return pairs[i]; }), by_stable_sort(pairs));
  std::sort(keys.begin(), keys.end());
  EXPECT_EQ(stable_order(keys.size(), [&](std::size_t i) { return keys[i]; }), by_stable_sort(keys));
  EXPECT_TRUE(stable_order(0, [](std::size_t) { return 0.0; }).empty());
}

}  // namespace
}  // namespace wiregrain
