// The greedy colouring of the contact graph (contact_colouring.h).
#include "core/nscd/contact_colouring.h"

#include <algorithm>

#include "core/common/errors.h"

namespace wiregrain {

ContactColouring colour_contacts(const std::vector<std::pair<int, int>>& bodies, int body_count) {
  const int n = static_cast<int>(bodies.size());
  ContactColouring out;
  out.colour.assign(n, 0);
  // the colours each body's contacts took so far (a body holds few: a grain's points)
  std::vector<std::vector<int>> taken(body_count);
  std::vector<int> seen_at;  // seen_at[k] == c: colour k is taken on a body of contact c
  for (int c = 0; c < n; ++c) {
    const int ends[2] = {bodies[c].first, bodies[c].second};
    for (const int b : ends)
      if (b >= body_count) throw InvalidArgument("bodies", "contact " + std::to_string(c) + " names body " +
                                                                 std::to_string(b) + " of " + std::to_string(body_count));
    for (const int b : ends) {
      if (b < 0) continue;
      for (const int k : taken[b]) {
        if (k >= static_cast<int>(seen_at.size())) seen_at.resize(k + 1, -1);
        seen_at[k] = c;
      }
    }
    int k = 0;
    while (k < static_cast<int>(seen_at.size()) && seen_at[k] == c) ++k;
    out.colour[c] = k;
    out.colours = std::max(out.colours, k + 1);
    if (ends[0] >= 0) taken[ends[0]].push_back(k);
    if (ends[1] >= 0 && ends[1] != ends[0]) taken[ends[1]].push_back(k);
  }
  out.order.resize(n);
  for (int c = 0; c < n; ++c) out.order[c] = c;
  std::stable_sort(out.order.begin(), out.order.end(), [&](int x, int y) { return out.colour[x] < out.colour[y]; });
  return out;
}

}  // namespace wiregrain
