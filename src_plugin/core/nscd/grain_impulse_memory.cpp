// GrainImpulseMemory (grain_impulse_memory.h).
#include "core/nscd/grain_impulse_memory.h"

#include <algorithm>
#include <stdexcept>

#include "core/common/stable_order.h"

namespace wiregrain {

void GrainImpulseMemory::commit() {
  if (committed_) return;
  const std::vector<std::size_t> order = stable_order(entries_.size(), [&](std::size_t i) { return entries_[i].pair; });
  std::vector<Entry> by_pair;
  by_pair.reserve(entries_.size());
  for (std::size_t i : order) by_pair.push_back(entries_[i]);
  entries_ = std::move(by_pair);
  keys_.resize(entries_.size());
  for (std::size_t i = 0; i < entries_.size(); i++) keys_[i] = entries_[i].pair;
  committed_ = true;
}

const std::vector<GrainImpulseMemory::Entry>& GrainImpulseMemory::points() const {
  if (!committed_) throw std::logic_error("GrainImpulseMemory: points added since the last commit");
  return entries_;
}

const GrainImpulseMemory::Impulse* GrainImpulseMemory::recall(const PairKey& pair, const Eigen::Vector3d& position,
                                                               double radius2, const PeriodicBox& box) const {
  const std::vector<Entry>& all = points();
  const Impulse* nearest = nullptr;
  double best = radius2;
  for (auto it = all.begin() + (std::lower_bound(keys_.begin(), keys_.end(), pair) - keys_.begin());
       it != all.end() && it->pair == pair; ++it) {
    const double d2 = box.minimum_image(it->impulse.position - position).squaredNorm();
    if (d2 < best) {
      best = d2;
      nearest = &it->impulse;
    }
  }
  return nearest;
}

}  // namespace wiregrain
