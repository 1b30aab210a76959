// The grains as the wire sees them during one NSCD step (paper Sec. 2.4, Fig. 5): posed
// once, held in place for the N wire sub-steps, with the velocity of the last NSCD step.
// Stock granular spheres (shape kSphere, integrated by LIGGGHTS every step) are held for
// one step and touched through the closed form wire_sphere_contact; stock superquadrics
// (kSuperquadric, LIGGGHTS' atom_style superquadric) likewise, through
// wire_superquadric_contact (GJK with their closed-form support point).
// A broad-phase grid over their centres finds the grains within reach of a wire segment;
// wire_grain_contact (wire_grain_contact.h) then gives the exact contact.
//
// Reach: a segment of half-length ℓ/2 and radius r_w centred at m can touch grain g only
// if |m − x_g| < R_g + ℓ/2 + r_w, with R_g the grain's bounding radius (core + sweep). The
// grid cells are at least R_max + s wide, s the largest ℓ/2 + r_w a segment may have
// (given at construction), so every such grain is among the 27 cells around m
// (broad_phase.h); a segment longer than allowed is an error, never a missed contact.
// Periodic dimensions: the grain's image nearest to m, as LIGGGHTS' minimum image.
// The grains are kept in the order of their tags and the candidates of a segment are
// visited in that order, so that forces summed over them do not depend on how the ranks
// gathered the grains or on the grid's cells (the pair cache, wire_grain_pairs.h, visits
// the same pairs in the same order).
#pragma once

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/contact/wire_grain_contact.h"
#include "core/geometry/broad_phase.h"
#include "core/geometry/gjk.h"
#include "core/geometry/periodic_box.h"
#include "core/geometry/posed_shape.h"
#include "core/geometry/superquadric_contact.h"
#include "core/geometry/shape_library.h"
#include "core/geometry/superquadric.h"

namespace wiregrain {

struct HeldGrain {
  static constexpr int kSphere = -1;        // `shape` of a stock granular sphere (no library shape)
  static constexpr int kSuperquadric = -2;  // `shape` of a stock LIGGGHTS superquadric
  long tag = 0;
  int shape = 0;     // index in the shape library, kSphere or kSuperquadric
  double sphere_radius = 0.0;  // shape == kSphere: its radius (wire_sphere_contact)
  Superquadric superquadric;   // shape == kSuperquadric: its half-axes and blockiness
  int material = 0;  // the caller's material index (the atom type), carried along
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // centre of mass
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  GrainMotion motion;
};

class HeldGrains {
 public:
  // segment_reach: the largest ℓ/2 + r_w of a segment that will be queried (> 0).
  // Throws InvalidArgument: a grain's shape not in the library ("shape"), a sphere whose
  // radius is not finite and > 0 ("sphere_radius"), a superquadric with bad half-axes or
  // blockiness ("half_axes", "blockiness"), a non-finite pose or motion or a tag given
  // twice ("grains"), segment_reach ≤ 0 ("segment_reach"), a periodic box shorter than
  // twice the interaction distance ("box").
  // box: the simulation box the grains live in (core/geometry/periodic_box.h).
  HeldGrains(std::vector<HeldGrain> grains, const ShapeLibrary& library, const PeriodicBox& box,
             double segment_reach);

  int size() const { return static_cast<int>(grains_.size()); }
  const HeldGrain& grain(int k) const { return grains_[k]; }
  // grain k posed (a library shape, not a sphere), made on first use: the wire reaches few of the grains, and posing all
  // of them every NSCD step was a fixed cost of the coupling (bench/column_table1.py at N = 1)
  const PosedShape& posed(int k) const {
    if (!posed_[k]) posed_[k].emplace((*library_)[grains_[k].shape].shape, grains_[k].position, grains_[k].orientation);
    return *posed_[k];
  }
  double bounding_radius(int k) const { return bounding_radius_[k]; }  // core + sweep, about the centre of mass
  // index of the grain with this tag, −1 if none
  int index_of(long tag) const;
  double segment_reach() const { return segment_reach_; }
  const PeriodicBox& box() const { return box_; }
  // the shift of grain k's image nearest to `point` (as for_each_candidate gives it)
  Eigen::Vector3d image_shift(int k, const Eigen::Vector3d& point) const {
    return box_.image_shift(point, grains_[k].position);
  }

  // Calls visit(k, shift) for every grain k whose bounding sphere, moved by the periodic
  // image shift and grown by `margin` ≥ 0, meets the segment's bounding sphere (centre
  // (x0+x1)/2, radius ℓ/2 + r_w): every grain within `margin` of the segment. In the order
  // of k (the tags), then of the shift. Throws InvalidArgument("segment", ...) when
  // ℓ/2 + r_w + margin exceeds segment_reach().
  template <class Visit>
  void for_each_candidate(const Eigen::Vector3d& x0, const Eigen::Vector3d& x1, double wire_radius, double margin,
                          Visit visit) const {
    const Eigen::Vector3d middle = 0.5 * (x0 + x1);
    const double reach = 0.5 * (x1 - x0).norm() + wire_radius + margin;
    check_reach(reach);
    std::vector<Candidate>& found = candidates_;
    found.clear();
    grid_.for_each_near(middle, [&](int k, const Eigen::Vector3d& shift) {
      const double limit = bounding_radius_[k] + reach;
      if ((grains_[k].position + shift - middle).squaredNorm() < limit * limit) found.push_back({k, shift});
    });
    if (found.size() > 1) std::sort(found.begin(), found.end(), candidate_order);
    for (const Candidate& c : found) visit(c.k, c.shift);
  }

  // The contact of segment `segment` with grain k seen at its image position + shift:
  // evaluated with the segment moved by −shift, the contact point moved back by +shift
  // (forces and torque arms do not depend on the image). The returned gap is exact while
  // below exact_gap_below, else possibly a lower bound (polyhedra and superquadrics: see
  // wire_grain_contact, wire_superquadric_contact; a sphere's gap is always exact). guess: a
  // superquadric's warm start, in and out (wire_superquadric_contact); ignored otherwise.
  // simplex: a polyhedron's GJK warm start, in and out (wire_grain_contact); ignored
  // otherwise.
  WireGrainContact contact(int k, const Eigen::Vector3d& shift, const SoftContactLaw& law,
                           const WireSegmentState& segment, double dt, TangentialHistory& history,
                           double exact_gap_below = std::numeric_limits<double>::infinity(),
                           SmoothContactGuess* guess = nullptr, GjkSimplex* simplex = nullptr) const;

 private:
  std::vector<HeldGrain> grains_;
  const ShapeLibrary* library_;
  mutable std::vector<std::optional<PosedShape>> posed_;
  std::vector<double> bounding_radius_;
  double segment_reach_;
  PeriodicBox box_;
  BroadPhaseGrid grid_;
  struct Candidate {
    int k;
    Eigen::Vector3d shift;
  };
  mutable std::vector<Candidate> candidates_;  // scratch of for_each_candidate
  static bool candidate_order(const Candidate& a, const Candidate& b);
  void check_reach(double reach) const;
};

// Per-grain sums of the wire's forces and torques over the sub-steps of one NSCD step,
// kept by grain tag so that they survive a rebuilt HeldGrains (a new run, restart).
class GrainLoadSums {
 public:
  void add(long tag, const Eigen::Vector3d& force, const Eigen::Vector3d& torque);
  void clear() { sums_.clear(); }
  bool empty() const { return sums_.empty(); }
  // flat image [tag, Fx, Fy, Fz, Tx, Ty, Tz]... in tag order, for MPI and restart files
  std::vector<double> flatten() const;
  void add_flat(const std::vector<double>& flat);
  struct Load {
    Eigen::Vector3d force = Eigen::Vector3d::Zero(), torque = Eigen::Vector3d::Zero();
  };
  const std::unordered_map<long, Load>& loads() const { return sums_; }

 private:
  std::unordered_map<long, Load> sums_;
};

}  // namespace wiregrain
