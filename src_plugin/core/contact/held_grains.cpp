#include "core/contact/held_grains.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/common/errors.h"
#include "core/common/stable_order.h"
#include "core/common/validation.h"

namespace wiregrain {

HeldGrains::HeldGrains(std::vector<HeldGrain> grains, const ShapeLibrary& library, const PeriodicBox& box,
                       double segment_reach)
    : grains_(std::move(grains)), library_(&library), segment_reach_(segment_reach), box_(box),
      grid_(BroadPhaseGrid::unbounded(1.0)) {
  {  // in tag order
    const std::vector<std::size_t> order = stable_order(grains_.size(), [&](std::size_t k) { return grains_[k].tag; });
    std::vector<HeldGrain> by_tag;
    by_tag.reserve(grains_.size());
    for (std::size_t k : order) by_tag.push_back(std::move(grains_[k]));
    grains_ = std::move(by_tag);
  }
  for (std::size_t k = 1; k < grains_.size(); ++k)
    if (grains_[k].tag == grains_[k - 1].tag)
      throw InvalidArgument("grains", "grain " + std::to_string(grains_[k].tag) + " is held twice (one copy per tag)");
  if (!(segment_reach > 0.0) || !std::isfinite(segment_reach))
    throw InvalidArgument("segment_reach", "segment_reach must be finite and > 0, got " + format_number(segment_reach));
  double largest = 0.0;
  posed_.resize(grains_.size());
  bounding_radius_.reserve(grains_.size());
  for (std::size_t k = 0; k < grains_.size(); ++k) {
    const HeldGrain& g = grains_[k];
    if (g.shape == HeldGrain::kSphere) {
      if (!(g.sphere_radius > 0.0) || !std::isfinite(g.sphere_radius))
        throw InvalidArgument("sphere_radius", "sphere " + std::to_string(g.tag) + " has radius " +
                                                   format_number(g.sphere_radius) + " (finite and > 0 expected)");
    } else if (g.shape == HeldGrain::kSuperquadric) {
      check_superquadric(g.superquadric);
    } else if (g.shape < 0 || g.shape >= library.size())
      throw InvalidArgument("shape", "grain " + std::to_string(g.tag) + " has shape " + std::to_string(g.shape) +
                                         ", not one of the " + std::to_string(library.size()) + " library shapes");
    if (!(g.position.allFinite() && g.orientation.coeffs().allFinite() && g.motion.velocity.allFinite() &&
          g.motion.angular_velocity.allFinite() && std::isfinite(g.motion.mass)))
      throw InvalidArgument("grains", "grain " + std::to_string(g.tag) + " has a non-finite pose or velocity");
    if (!(g.orientation.norm() > 0.0))
      throw InvalidArgument("grains", "grain " + std::to_string(g.tag) + " has a zero orientation quaternion");
    const double bounding = g.shape == HeldGrain::kSphere         ? g.sphere_radius
                            : g.shape == HeldGrain::kSuperquadric ? superquadric_bounding_radius(g.superquadric)
                                                                  : library[g.shape].bounding_radius;
    bounding_radius_.push_back(bounding);
    largest = std::max(largest, bounding);
  }
  const double cell = largest + segment_reach;
  box.validate();
  for (int d = 0; d < 3; ++d)
    if (box.periodic[d] && 2.0 * cell > box.length(d))
      throw InvalidArgument("box", std::string("the periodic box is ") + format_number(box.length(d)) + " long along " +
                                       "xyz"[d] + ", below twice the wire-grain reach " + format_number(cell) +
                                       " (the largest bounding radius + half the longest segment + the wire radius + the skin)");
  grid_ = box.periodic[0] || box.periodic[1] || box.periodic[2]
              ? BroadPhaseGrid::box(box.lo, box.hi, box.periodic, cell)
              : BroadPhaseGrid::unbounded(cell);
  std::vector<Eigen::Vector3d> centres;
  centres.reserve(grains_.size());
  for (const HeldGrain& g : grains_) centres.push_back(g.position);
  grid_.assign(std::move(centres));
}

int HeldGrains::index_of(long tag) const {
  // the grains are in tag order
  const auto it = std::lower_bound(grains_.begin(), grains_.end(), tag,
                                   [](const HeldGrain& g, long t) { return g.tag < t; });
  return it != grains_.end() && it->tag == tag ? static_cast<int>(it - grains_.begin()) : -1;
}

bool HeldGrains::candidate_order(const Candidate& a, const Candidate& b) {
  if (a.k != b.k) return a.k < b.k;
  for (int d = 0; d < 3; ++d)
    if (a.shift[d] != b.shift[d]) return a.shift[d] < b.shift[d];
  return false;
}

void HeldGrains::check_reach(double reach) const {
  if (!(reach <= segment_reach_))
    throw InvalidArgument("segment", "a segment reaches " + format_number(reach) +
                                         " (half its length + its radius), beyond the allowed " +
                                         format_number(segment_reach_));
}

WireGrainContact HeldGrains::contact(int k, const Eigen::Vector3d& shift, const SoftContactLaw& law,
                                     const WireSegmentState& segment, double dt, TangentialHistory& history,
                                     double exact_gap_below, SmoothContactGuess* guess, GjkSimplex* simplex) const {
  WireSegmentState moved = segment;
  moved.x0 -= shift;
  moved.x1 -= shift;
  const HeldGrain& g = grains_[k];
  WireGrainContact c =
      g.shape == HeldGrain::kSphere
          ? wire_sphere_contact(law, g.position, g.sphere_radius, g.motion, moved, dt, history)
      : g.shape == HeldGrain::kSuperquadric
          ? wire_superquadric_contact(law, PosedSuperquadric(g.superquadric, g.position, g.orientation), g.motion,
                                      moved, dt, history, exact_gap_below, guess)
          : wire_grain_contact(law, posed(k), g.motion, moved, dt, history, exact_gap_below, simplex);
  c.point += shift;
  return c;
}

void GrainLoadSums::add(long tag, const Eigen::Vector3d& force, const Eigen::Vector3d& torque) {
  Load& load = sums_[tag];
  load.force += force;
  load.torque += torque;
}

std::vector<double> GrainLoadSums::flatten() const {
  std::vector<long> tags;
  tags.reserve(sums_.size());
  for (const auto& entry : sums_) tags.push_back(entry.first);
  std::sort(tags.begin(), tags.end());
  std::vector<double> flat;
  flat.reserve(7 * tags.size());
  for (long tag : tags) {
    const Load& load = sums_.at(tag);
    flat.push_back(double(tag));
    flat.insert(flat.end(), load.force.data(), load.force.data() + 3);
    flat.insert(flat.end(), load.torque.data(), load.torque.data() + 3);
  }
  return flat;
}

void GrainLoadSums::add_flat(const std::vector<double>& flat) {
  if (flat.size() % 7 != 0)
    throw InvalidArgument("flat", "grain load records come in sevens, got " + std::to_string(flat.size()) + " values");
  for (std::size_t k = 0; k < flat.size(); k += 7)
    add(static_cast<long>(flat[k]), Eigen::Vector3d(flat[k + 1], flat[k + 2], flat[k + 3]),
        Eigen::Vector3d(flat[k + 4], flat[k + 5], flat[k + 6]));
}

}  // namespace wiregrain
