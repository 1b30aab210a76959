// Reuse of the grain–grain pairs of the NSCD detection between steps, as LIGGGHTS keeps
// its neighbour lists while nothing moved more than a skin, and exact: the pairs evaluated
// always include every pair within the activation distance, so the contact points are
// those of a full search (the pairs are visited in the same order, a ascending then b
// ascending, grains in tag order).
//
// At a build the broad phase runs with its reach grown by the skin s, and every pair
// whose gap (contact_manifold with exit_beyond_activation = s: exact below a + s, a lower
// bound beyond) is below a_build + s is kept, a_build the activation distance of that
// step. A pair left out had a gap ≥ a_build + s; each of its grains has since moved at
// most D (every surface point), D = max_g |c_g − c_g,build| + 2 R_g |vec(q_g,build⁻¹ q_g)|
// (translation, plus 2 R_g sin(θ/2) for a turn by θ; R_g the bounding radius), so its gap
// is still ≥ a_build + s − 2D, beyond this step's activation a while
//     2 D + (a − a_build) < s.
// Otherwise, or when the grains changed (a grain added, removed, reshaped or reordered),
// the next detection is a build.
// Within a valid build a kept pair is not evaluated while it is still apart by the same
// bound taken grain by grain: its gap at the build g_build minus how far each of its two
// grains has moved since, g_build − D_a − D_b > a (+ 1e-9 (R_a + R_b) for rounding), its
// evaluation would find its gap beyond this step's activation and return no point, so
// skipping it leaves the problem the same to the last bit (in a settled pile most kept
// pairs are a skin apart, not touching).
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/geometry/gjk.h"
#include "core/geometry/periodic_box.h"
#include "core/geometry/shape_library.h"

namespace wiregrain {

struct GrainState;

class GrainPairCache {
 public:
  // skin > 0 and finite, else InvalidArgument("skin", ...)
  explicit GrainPairCache(double skin);
  double skin() const { return skin_; }

  struct KeptPair {
    int a, b;    // grain indices, a < b
    double gap;  // at the build (exact below a_build + s); −∞: always evaluated
    GjkSimplex simplex;  // of the pair's last narrow phase (GrainStepOptions::warm_geometry)
  };

  // Whether the pairs of the last build still hold every pair within `activation` of the
  // grains as they are now (see above); when they do, also each grain's motion bound D_k
  // for still_apart(). The translations are taken in the minimum image of `box`: a grain
  // that wrapped across a periodic face has moved by its step, not by the period.
  bool valid(const std::vector<GrainState>& grains, const ShapeLibrary& library, double activation,
             const PeriodicBox& box = PeriodicBox());
  // A build: start, keep each pair (a < b, grain indices) in visiting order with its gap,
  // end with the grains and the activation distance of the build.
  void begin_build();
  void keep(int a, int b, double gap, const GjkSimplex& simplex = GjkSimplex()) {
    pairs_.push_back({a, b, gap, simplex});
  }
  void end_build(const std::vector<GrainState>& grains, const ShapeLibrary& library, double activation);
  const std::vector<KeptPair>& pairs() const { return pairs_; }
  // the simplex of kept pair i (an index into pairs())
  void set_simplex(std::size_t i, const GjkSimplex& simplex) { pairs_.at(i).simplex = simplex; }
  // The state a run continued from a restart file needs to repeat the straight run to
  // the bit (the simplices are warm starts: a cache built anew would start them cold):
  // the skin, the build's activation distance, reference poses and kept pairs with their
  // simplices, as numbers (fix nscd/polyhedra's restart file). restore() takes them back
  // from `data` (`count` numbers available) and returns how many it read; a cache of
  // another skin, or not built, is left to build anew (still reading its numbers).
  // InvalidArgument("data", ...) when the numbers are not such a record.
  std::vector<double> serialize() const;
  std::size_t restore(const double* data, std::size_t count);
  // After valid() returned true: whether the kept pair cannot have come within
  // `activation` (counted in skipped())
  bool still_apart(const KeptPair& pair, double activation) {
    const double closest = pair.gap - moved_[pair.a] - moved_[pair.b];
    const double rounding = 1e-9 * (reference_[pair.a].bounding_radius + reference_[pair.b].bounding_radius);
    const bool apart = closest > activation + rounding;
    skipped_ += apart;
    return apart;
  }

  long builds() const { return builds_; }
  long reuses() const { return reuses_; }
  long skipped() const { return skipped_; }
  void count_reuse() { ++reuses_; }

 private:
  struct Pose {
    long tag;
    int shape;
    double bounding_radius;
    Eigen::Vector3d position;
    Eigen::Quaterniond orientation;
  };
  double skin_;
  double activation_ = 0.0;
  bool built_ = false;
  std::vector<Pose> reference_;
  std::vector<KeptPair> pairs_;
  std::vector<double> moved_;  // D_k of the last valid()
  long builds_ = 0, reuses_ = 0, skipped_ = 0;
};

}  // namespace wiregrain
