// Reuse of the grain–grain pairs of the NSCD detection between steps (issue 14, "contact
// detection reuse"), as LIGGGHTS keeps its neighbour lists while nothing moved more than
// a skin, and exact: the pairs evaluated always include every pair within the activation
// distance, so the contact points are those of a full search (the pairs are visited in
// the same order, a ascending then b ascending, grains in tag order).
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
#pragma once

#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/geometry/shape_library.h"

namespace wiregrain {

struct GrainState;

class GrainPairCache {
 public:
  // skin > 0 and finite, else InvalidArgument("skin", ...)
  explicit GrainPairCache(double skin);
  double skin() const { return skin_; }

  // Whether the pairs of the last build still hold every pair within `activation` of the
  // grains as they are now (see above).
  bool valid(const std::vector<GrainState>& grains, const ShapeLibrary& library, double activation) const;
  // A build: start, keep each pair (a < b, grain indices) in visiting order, end with the
  // grains and the activation distance of the build.
  void begin_build();
  void keep(int a, int b) { pairs_.emplace_back(a, b); }
  void end_build(const std::vector<GrainState>& grains, const ShapeLibrary& library, double activation);
  const std::vector<std::pair<int, int>>& pairs() const { return pairs_; }

  long builds() const { return builds_; }
  long reuses() const { return reuses_; }
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
  std::vector<std::pair<int, int>> pairs_;
  long builds_ = 0, reuses_ = 0;
};

}  // namespace wiregrain
