// Reuse of the wire–grain pairs between sub-steps and NSCD steps, as LIGGGHTS reuses its
// neighbour lists while nothing moved more than a skin, but exact: the pairs evaluated are
// a superset of the touching ones, so the forces are those of a full search, to the last
// bit (the pairs are visited in the same order, HeldGrains' tag order).
//
// A segment's entry is built by the broad phase with the candidates grown by the skin s:
// every grain whose exact gap to the segment (between the surfaces, sweeps included) is
// below s is kept, in tag order. It stays valid while no excluded pair can have closed
// its gap:
//   d_seg + D_grains(now) + D_grains(build) < s,
// d_seg = max(|x0 − x0_build|, |x1 − x1_build|) (every point of the segment is a convex
// combination of its ends, so it moved at most that far), D_grains(t) the bound on how
// far any surface point of any grain has moved from the reference poses by time t
// (displacements in the minimum image of HeldGrains' box: a bead or a grain that wrapped
// across a periodic face keeps the entry; a kept pair takes the grain's image nearest
// to the segment at each evaluation),
//   D = max_g |c_g − c_g,ref| + 2 R_g |vec(q_g,ref⁻¹ q_g)|
// (a body point at distance ≤ R_g from the centre of mass moves by the translation plus
// at most 2 R_g sin(θ/2) for a rotation by θ; R_g the bounding radius); by the triangle
// inequality the grains moved at most D(now) + D(build) since the entry was built. The
// reference poses are reset (and every entry dropped) when D reaches s/2, when a grain
// appears, disappears or changes its shape or bounding radius (a sphere that grew). An entry whose segment changed its radius is
// rebuilt. Grains move only when fix nscd/polyhedra solves, so D is updated once per held
// grain set (hold()); segments are checked at every visit.
// Within a valid entry a pair is not evaluated while its gap at the build exceeds the
// motion bound since, taken for its own grain k, g_build > d_seg + D_k(now) + D_k(build)
// (D_k the bound above for grain k alone, ≤ D): it is still apart (its surfaces moved at
// most that far towards each other), as its evaluation would find. Superquadric pairs are
// always evaluated: their contact solve starts from the last evaluation's.
// Each kept pair holds the GJK simplex of its last evaluation (GjkSimplex,
// core/geometry/gjk.h), handed to evaluate as its warm start and left there
// with the next one (warm_geometry; null when off): the same contacts to GJK's tolerance,
// not to the bit. An entry built anew starts its pairs cold.
#pragma once

#include <algorithm>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/common/errors.h"
#include "core/contact/held_grains.h"
#include "core/geometry/gjk.h"

namespace wiregrain {

class WireGrainPairCache {
 public:
  // skin > 0 and finite, else InvalidArgument("skin", ...)
  explicit WireGrainPairCache(double skin);

  double skin() const { return skin_; }
  // whether evaluate gets the pairs' simplices (off by default: fix wire/grain's keyword)
  void set_warm_geometry(bool on) { warm_geometry_ = on; }
  // Drops every entry and the reference poses: the next hold() resets, every segment's
  // entry is built anew, its pairs' GJKs start cold (fix wire/grain at the start of each
  // run: a run continued from a restart file, which keeps no cache, then does what the
  // straight run does; the entries are per rank, not in the restart file).
  void clear() {
    reference_.clear();
    entries_.clear();
    grain_moved_.clear();
  }
  // The grains as held now (after every new HeldGrains): updates D, resets the reference
  // when the grains changed or D ≥ skin / 2.
  void hold(const HeldGrains& held);
  // D of the last hold()
  double grain_motion_bound() const { return grain_bound_; }

  // Calls evaluate(k, shift, exact_gap_below, simplex) for every grain of `held` (the set
  // of the last hold()) that may touch the segment [x0, x1] of radius r_w, in the order of
  // HeldGrains' for_each_candidate; evaluate returns the pair's gap (≤ 0 touching), which
  // must be exact while below exact_gap_below (0 for an entry's pairs, the skin while the
  // entry is being built; farther pairs may return a lower bound of their gap); simplex:
  // the pair's GJK warm start, in and out, or null. key: the segment's identity (its first bead's tag).
  // Throws what for_each_candidate throws when the entry is rebuilt.
  template <class Evaluate>
  void for_each_pair(long key, const HeldGrains& held, const Eigen::Vector3d& x0, const Eigen::Vector3d& x1,
                     double wire_radius, Evaluate evaluate) {
    if (static_cast<int>(grain_moved_.size()) != held.size())
      throw InvalidArgument("held", "the pair cache was not given this set of grains (hold()) before its pairs");
    Entry& entry = entries_[key];
    const double moved = motion_since_build(entry, held.box(), x0, x1, wire_radius);
    if (moved < skin_) {  // the entry is valid
      const double moved_segment = segment_motion(held.box(), entry, x0, x1);
      const Eigen::Vector3d middle = 0.5 * (x0 + x1);
      for (Pair& p : entry.pairs) {
        const int k = p.grain;
        if (p.gap > moved_segment + grain_moved_[k] + p.grain_moved && held.grain(k).shape != HeldGrain::kSuperquadric) {
          ++skipped_;
          continue;
        }
        // the grain's image nearest to the segment now (the segment or the grain may have
        // wrapped across a periodic face since the build)
        evaluate(k, held.image_shift(k, middle), 0.0, warm_geometry_ ? &p.simplex : nullptr);
      }
      return;
    }
    ++rebuilds_;
    entry.epoch = epoch_;
    entry.grain_bound = grain_bound_;
    entry.x0 = x0;
    entry.x1 = x1;
    entry.radius = wire_radius;
    entry.pairs.clear();
    held.for_each_candidate(x0, x1, wire_radius, skin_, [&](int k, const Eigen::Vector3d& shift) {
      GjkSimplex simplex;
      const double gap = evaluate(k, shift, skin_, warm_geometry_ ? &simplex : nullptr);
      if (gap < skin_) entry.pairs.push_back({k, gap, grain_moved_[k], simplex});
    });
  }

  // segment entries built since construction, reference resets, pair visits skipped as
  // still apart
  long rebuilds() const { return rebuilds_; }
  long resets() const { return resets_; }
  long skipped() const { return skipped_; }

 private:
  struct Pair {
    // the grain's index in HeldGrains: the same grain through the entry's epoch, whose held
    // sets have the same tags (hold() resets when one differs) in the same (tag) order
    int grain;
    double gap;          // exact, at the entry's build
    double grain_moved;  // D_k at the entry's build
    GjkSimplex simplex;  // of its last evaluation
  };
  struct Entry {
    long epoch = -1;           // the reference it was built against
    double grain_bound = 0.0;  // D at its build
    Eigen::Vector3d x0, x1;
    double radius = 0.0;
    std::vector<Pair> pairs;
  };
  struct Pose {
    int shape;
    double bounding_radius;
    Eigen::Vector3d position;
    Eigen::Quaterniond orientation;
  };
  double skin_;
  bool warm_geometry_ = false;
  long epoch_ = 0;
  double grain_bound_ = 0.0;
  std::vector<double> grain_moved_;           // D_k, in HeldGrains' order
  std::unordered_map<long, Pose> reference_;  // grain tag → pose at the last reset
  std::unordered_map<long, Entry> entries_;   // segment key → entry
  long rebuilds_ = 0, resets_ = 0, skipped_ = 0;

  // d_seg + D(now) + D(build) for an entry of the current reference with the same radius
  // (valid while below the skin), else infinity
  double motion_since_build(const Entry& e, const PeriodicBox& box, const Eigen::Vector3d& x0,
                            const Eigen::Vector3d& x1, double radius) const;
  // d_seg, the larger displacement of the segment's ends since the entry's build (in the
  // minimum image: a bead wrapped across a periodic face moved by its step)
  static double segment_motion(const PeriodicBox& box, const Entry& e, const Eigen::Vector3d& x0,
                               const Eigen::Vector3d& x1) {
    return std::max(box.minimum_image(x0 - e.x0).norm(), box.minimum_image(x1 - e.x1).norm());
  }
  void reset(const HeldGrains& held);
};

}  // namespace wiregrain
