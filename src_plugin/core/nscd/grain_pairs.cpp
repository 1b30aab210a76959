#include "core/nscd/grain_pairs.h"

#include <algorithm>
#include <cmath>

#include "core/common/errors.h"
#include "core/common/validation.h"
#include "core/geometry/motion_bound.h"
#include "core/nscd/grain_step.h"

namespace wiregrain {

GrainPairCache::GrainPairCache(double skin) : skin_(skin) {
  if (!(skin > 0.0) || !std::isfinite(skin))
    throw InvalidArgument("skin", "skin must be finite and > 0, got " + format_number(skin));
}

bool GrainPairCache::valid(const std::vector<GrainState>& grains, const ShapeLibrary& library,
                           double activation) {
  if (!built_ || grains.size() != reference_.size()) return false;
  moved_.resize(grains.size());
  double moved = 0.0;
  for (std::size_t k = 0; k < grains.size(); ++k) {
    const GrainState& g = grains[k];
    const Pose& ref = reference_[k];
    if (g.tag != ref.tag || g.shape != ref.shape || g.shape >= library.size()) return false;
    moved_[k] = rigid_motion_bound(ref.position, ref.orientation, g.position, g.orientation, ref.bounding_radius);
    moved = std::max(moved, moved_[k]);
  }
  return 2.0 * moved + (activation - activation_) < skin_;  // false for NaN
}

void GrainPairCache::begin_build() {
  pairs_.clear();
  built_ = false;
}

void GrainPairCache::end_build(const std::vector<GrainState>& grains, const ShapeLibrary& library, double activation) {
  ++builds_;
  activation_ = activation;
  reference_.clear();
  reference_.reserve(grains.size());
  for (const GrainState& g : grains)
    reference_.push_back({g.tag, g.shape, library[g.shape].bounding_radius, g.position, g.orientation.normalized()});
  built_ = true;
}

}  // namespace wiregrain
