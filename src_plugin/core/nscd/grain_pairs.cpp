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
                           double activation, const PeriodicBox& box) {
  if (!built_ || grains.size() != reference_.size()) return false;
  moved_.resize(grains.size());
  double moved = 0.0;
  for (std::size_t k = 0; k < grains.size(); ++k) {
    const GrainState& g = grains[k];
    const Pose& ref = reference_[k];
    if (g.tag != ref.tag || g.shape != ref.shape || g.shape >= library.size()) return false;
    moved_[k] = rigid_motion_bound(box.minimum_image(g.position - ref.position), ref.orientation, g.orientation,
                                   ref.bounding_radius);
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

// skin, built, activation, grain count, per grain (tag, shape, bounding radius, position,
// orientation w x y z), pair count, per pair (a, b, gap, simplex size, its index pairs)
std::vector<double> GrainPairCache::serialize() const {
  std::vector<double> data = {skin_, built_ ? 1.0 : 0.0, activation_, double(reference_.size())};
  for (const Pose& p : reference_) {
    data.insert(data.end(), {double(p.tag), double(p.shape), p.bounding_radius});
    data.insert(data.end(), p.position.data(), p.position.data() + 3);
    data.insert(data.end(), {p.orientation.w(), p.orientation.x(), p.orientation.y(), p.orientation.z()});
  }
  data.push_back(double(pairs_.size()));
  for (const KeptPair& p : pairs_) {
    data.insert(data.end(), {double(p.a), double(p.b), p.gap, double(p.simplex.size)});
    for (int k = 0; k < p.simplex.size; k++) data.insert(data.end(), {double(p.simplex.a[k]), double(p.simplex.b[k])});
  }
  return data;
}

std::size_t GrainPairCache::restore(const double* data, std::size_t count) {
  std::size_t at = 0;
  const auto next = [&]() {
    if (at >= count) throw InvalidArgument("data", "the pair cache's record ends early (" + std::to_string(count) + " numbers)");
    return data[at++];
  };
  const double skin = next();
  const bool built = next() != 0.0;
  const double activation = next();
  const double grains = next();
  if (!(grains >= 0.0) || grains != std::floor(grains)) throw InvalidArgument("data", "the pair cache's record has a bad grain count");
  std::vector<Pose> reference(static_cast<std::size_t>(grains));
  for (Pose& p : reference) {
    p.tag = static_cast<long>(next());
    p.shape = static_cast<int>(next());
    p.bounding_radius = next();
    for (int d = 0; d < 3; d++) p.position[d] = next();
    const double w = next(), x = next(), y = next(), z = next();
    p.orientation = Eigen::Quaterniond(w, x, y, z);
  }
  const double pairs = next();
  if (!(pairs >= 0.0) || pairs != std::floor(pairs)) throw InvalidArgument("data", "the pair cache's record has a bad pair count");
  std::vector<KeptPair> kept(static_cast<std::size_t>(pairs));
  for (KeptPair& p : kept) {
    p.a = static_cast<int>(next());
    p.b = static_cast<int>(next());
    p.gap = next();
    p.simplex.size = static_cast<int>(next());
    if (p.simplex.size < 0 || p.simplex.size > 4 || p.a < 0 || p.b <= p.a || p.b >= static_cast<int>(grains))
      throw InvalidArgument("data", "the pair cache's record has a bad pair");
    for (int k = 0; k < p.simplex.size; k++) {
      p.simplex.a[k] = static_cast<int>(next());
      p.simplex.b[k] = static_cast<int>(next());
    }
  }
  if (skin == skin_ && built) {
    built_ = true;
    activation_ = activation;
    reference_ = std::move(reference);
    pairs_ = std::move(kept);
  } else {
    built_ = false;
    pairs_.clear();
  }
  return at;
}

}  // namespace wiregrain
