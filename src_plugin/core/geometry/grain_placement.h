// Placing new grains without overlaps (create_grains): where they may go (the sites of a
// layer lattice, or uniform positions in a box) and the exact overlap test against the
// bodies already there (grains, spheres, wire segments) and the grains placed before.
//
// Overlap: the signed core distance of the candidate and a body ≤ r_A + r_B (touching
// counts), with a sphere or a segment as the spherocylinder of its radius about a point or
// a segment (core/geometry/core_distance.h, core/geometry/segment_contact.h). Bodies are
// binned on the broad-phase grid over the box (core/geometry/broad_phase.h) with cells at
// least as large as the largest bounding diameter, so a candidate only meets the bodies of
// its own and the adjacent cells; periodic dimensions wrap (cells and minimum-image
// displacements).
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <functional>
#include <memory>
#include <random>
#include <vector>

#include "core/geometry/broad_phase.h"
#include "core/geometry/core_distance.h"
#include "core/geometry/posed_shape.h"
#include "core/geometry/segment_contact.h"
#include "core/geometry/shape_library.h"

namespace wiregrain {

// Something a new grain must not overlap.
struct PlacementObstacle {
  static constexpr int kSphere = -1, kSegment = -2;
  Eigen::Vector3d x;   // centre of mass, sphere centre, segment midpoint
  double bound = 0.0;  // bounding radius about x
  double sweep = 0.0;  // sweep radius of a grain, radius of a sphere or segment
  int shape = kSphere; // library index, kSphere or kSegment
  Eigen::Vector3d half = Eigen::Vector3d::Zero();  // segment: x ± half are its ends
  std::unique_ptr<PosedShape> posed;               // grain: posed at x

  // a grain of library shape `shape` at x with orientation q (body → world)
  static PlacementObstacle grain(const ShapeLibrary& library, int shape, const Eigen::Vector3d& x,
                                 const Eigen::Quaterniond& q);
  static PlacementObstacle sphere(const Eigen::Vector3d& centre, double radius);
  // the segment from `start` to start + to_end, of the given radius
  static PlacementObstacle segment(const Eigen::Vector3d& start, const Eigen::Vector3d& to_end, double radius);
};

class PlacementGrid {
 public:
  // the box [lo, hi), periodic per dimension; max_bound: the largest bounding radius of
  // any body and any grain to place (cells at least 2 max_bound wide)
  PlacementGrid(const ShapeLibrary& library, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                const std::array<bool, 3>& periodic, double max_bound);

  void add(PlacementObstacle body);

  // True if the grain `c` (bounding radius `bound`) overlaps a body. Otherwise `min_gap`
  // receives the smallest gap of the pairs whose bounding spheres meet (+inf if none) and
  // `pairs` their number.
  bool overlaps(const PosedShape& c, double bound, double& min_gap, long& pairs) const;

  const ShapeLibrary& library() const { return library_; }

 private:
  const ShapeLibrary& library_;
  BroadPhaseGrid grid_;
  std::vector<PlacementObstacle> bodies_;
};

// The paper's particle layer: two staggered square lattices of spacing s over the
// rectangle [x_lo, x_hi) × [y_lo, y_hi). Per dimension n = ⌊L/s + 1e−9⌋ cells of width s,
// centred (margin (L − n s)/2); lattice A has a site at every cell centre, lattice B at
// every inner cell corner (s/2 across, one row and column fewer).
class LayerLattice {
 public:
  LayerLattice(double x_lo, double x_hi, double y_lo, double y_hi, double spacing);
  // n_x n_y, the sites of lattice A
  double cells() const { return static_cast<double>(cells_[0]) * static_cast<double>(cells_[1]); }
  // The sites where inside(site) holds: lattice A at height z, then lattice B at z + rise;
  // rows along x, then y.
  std::vector<Eigen::Vector3d> sites(double z, double rise,
                                     const std::function<bool(const Eigen::Vector3d&)>& inside) const;

 private:
  double lo_[2], spacing_;
  long cells_[2];
  double margin_[2];
};

// Where grain k may go: layer, the site sites[k] (a new random orientation per attempt);
// else a uniform random position in [lo, hi) per attempt, taken where inside(p) holds.
struct GrainSites {
  bool layer = false;
  std::vector<Eigen::Vector3d> sites;
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
  std::function<bool(const Eigen::Vector3d&)> inside;
};

struct GrainPlacement {
  std::vector<Eigen::Vector3d> position;
  std::vector<Eigen::Quaterniond> orientation;  // unit, body → world
  double min_gap = 0.0;   // smallest gap of a close pair over all placements (+inf: none)
  long close_pairs = 0;   // pairs whose bounding spheres met, over all placements
  long tries = 0;         // attempts made
  int unplaced = -1;      // the first grain that no attempt placed (−1: all placed)
};

// Places the grains in order, each added to `grid` once placed. Per attempt: (random) the
// position, one draw per dimension in x, y, z order, then the orientation
// random_orientation(rng) · body_to_input[k], normalised (three draws); a random position
// outside `inside` is rejected after both, then the overlap test. At most `attempts`
// attempts per grain; the first grain that gets none stops the placement (unplaced).
GrainPlacement place_grains(PlacementGrid& grid, const std::vector<int>& shape_of,
                            const std::vector<Eigen::Quaterniond>& body_to_input, const GrainSites& where,
                            long attempts, std::mt19937_64& rng);

}  // namespace wiregrain
