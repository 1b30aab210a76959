// The order that sorts items stably by a key, computed on packed (key, index) pairs: the
// comparisons read a contiguous array instead of the (large) items themselves, so a sort
// of contact points or grains costs cache misses on 16–24 bytes per item, not on their
// records; the caller then moves each item once. Ties keep the items' order (the index
// breaks them), as std::stable_sort would.
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace wiregrain {

// key_of(i) for i in [0, count): a value with operator< (a strict weak order)
template <class KeyOf>
std::vector<std::size_t> stable_order(std::size_t count, KeyOf key_of) {
  using Key = decltype(key_of(std::size_t(0)));
  std::vector<std::pair<Key, std::size_t>> keyed(count);
  bool sorted = true;
  for (std::size_t i = 0; i < count; i++) {
    keyed[i] = {key_of(i), i};
    sorted = sorted && (i == 0 || !(keyed[i].first < keyed[i - 1].first));
  }
  if (!sorted)
    std::sort(keyed.begin(), keyed.end(), [](const std::pair<Key, std::size_t>& x, const std::pair<Key, std::size_t>& y) {
      return x.first < y.first || (!(y.first < x.first) && x.second < y.second);
    });
  std::vector<std::size_t> order(count);
  for (std::size_t i = 0; i < count; i++) order[i] = keyed[i].second;
  return order;
}

}  // namespace wiregrain
