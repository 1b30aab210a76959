// The contact points of the last grain step with their impulses (core/nscd/grain_step.h):
// the next step's warm start (each new point starts from the impulse of the nearest stored
// point of its pair), the frozen points of sleeping pairs, and the stick solves' backoff
// carried from step to step.
#pragma once

#include <Eigen/Dense>

#include <utility>
#include <vector>

#include "core/contact/contact_list.h"
#include "core/geometry/periodic_box.h"
#include "core/nscd/gauss_seidel.h"

namespace wiregrain {

// Last step's impulses (world frame) at their contact points, by pair (a, b): a = tag of
// grain a or −(wall + 1), b = tag of grain b. One flat list sorted by pair (the step's
// points arrive top-down; `commit` sorts them once, recall is a binary search): a map of
// vectors rebuilt every step cost 3 % of a column's run in allocations and lookups.
class GrainImpulseMemory {
 public:
  using PairKey = std::pair<long, long>;
  // a point's position and impulse on b (world frame); normal, gap and status for a
  // frozen point (sleeping pair), which is reported without being detected again
  struct Impulse {
    Eigen::Vector3d position, impulse;
    Eigen::Vector3d couple = Eigen::Vector3d::Zero();  // rolling couple on b (world frame)
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
    double gap = 0.0;
    ContactStatus status = ContactStatus::open;
  };
  struct Entry {
    PairKey pair;
    Impulse impulse;
  };
  // the pair's stored point nearest to `position` if its squared distance (in the
  // minimum image of `box`: a grain that wrapped across a periodic face since keeps its
  // warm start) is below `radius2`, else nullptr; std::logic_error if points were added
  // since the last commit
  const Impulse* recall(const PairKey& pair, const Eigen::Vector3d& position, double radius2,
                        const PeriodicBox& box = PeriodicBox()) const;
  void clear() {  // the impulses; the backoff stays
    entries_.clear();
    keys_.clear();
    committed_ = true;
  }
  void add(const PairKey& pair, const Impulse& impulse) {
    committed_ = false;
    entries_.push_back({pair, impulse});
  }
  // sorts the points added by pair, a pair's points in the order they were added
  void commit();
  // every stored point, by pair ascending (committed: std::logic_error otherwise)
  const std::vector<Entry>& points() const;
  StickSolveBackoff backoff;  // method subspace, from step to step (core/nscd/gauss_seidel.h)

 private:
  std::vector<Entry> entries_;
  std::vector<PairKey> keys_;  // entries_[i].pair, packed for recall's binary search
  bool committed_ = true;
};

}  // namespace wiregrain
