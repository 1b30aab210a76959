#include "core/contact/wire_grain_pairs.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/errors.h"
#include "core/common/validation.h"
#include "core/geometry/motion_bound.h"

namespace wiregrain {

WireGrainPairCache::WireGrainPairCache(double skin) : skin_(skin) {
  if (!(skin > 0.0) || !std::isfinite(skin))
    throw InvalidArgument("skin", "skin must be finite and > 0, got " + format_number(skin));
}

void WireGrainPairCache::hold(const HeldGrains& held) {
  if (reference_.size() != static_cast<std::size_t>(held.size())) return reset(held);
  double bound = 0.0;
  grain_moved_.resize(held.size());
  for (int k = 0; k < held.size(); ++k) {
    const HeldGrain& g = held.grain(k);
    const auto it = reference_.find(g.tag);
    if (it == reference_.end() || it->second.shape != g.shape || it->second.bounding_radius != held.bounding_radius(k))
      return reset(held);
    const Pose& ref = it->second;
    grain_moved_[k] = rigid_motion_bound(held.box().minimum_image(g.position - ref.position), ref.orientation,
                                         g.orientation, ref.bounding_radius);
    bound = std::max(bound, grain_moved_[k]);
  }
  grain_bound_ = bound;
  if (!(bound < 0.5 * skin_)) reset(held);  // also a non-finite pose
}

void WireGrainPairCache::reset(const HeldGrains& held) {
  ++resets_;
  ++epoch_;
  grain_bound_ = 0.0;
  grain_moved_.assign(held.size(), 0.0);
  reference_.clear();
  entries_.clear();
  for (int k = 0; k < held.size(); ++k) {
    const HeldGrain& g = held.grain(k);
    reference_[g.tag] = Pose{g.shape, held.bounding_radius(k), g.position, g.orientation.normalized()};
  }
}

double WireGrainPairCache::motion_since_build(const Entry& e, const PeriodicBox& box, const Eigen::Vector3d& x0,
                                              const Eigen::Vector3d& x1, double radius) const {
  if (e.epoch != epoch_ || e.radius != radius) return std::numeric_limits<double>::infinity();
  const double moved = segment_motion(box, e, x0, x1) + grain_bound_ + e.grain_bound;
  return std::isnan(moved) ? std::numeric_limits<double>::infinity() : moved;
}

}  // namespace wiregrain
