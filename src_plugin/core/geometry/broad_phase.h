// Broad phase: a uniform cell grid over points (grain centres, bead positions) so that a
// point meets only the points of its own cell and the 26 adjacent ones. With cells at
// least as wide as the largest interaction distance d_max, every pair closer than d_max
// is among the candidates (|x_j − x_i| < d_max ≤ cell ⇒ the cell indices differ by ≤ 1
// per dimension).
//
// Per dimension the grid is either
//   unbounded: cell index ⌊x / cell⌋ over all integers (hashed), never periodic, or
//   bounded over a box [lo, hi): n = clamp(⌊(hi − lo) / min_cell⌋, 1, 100000) cells of
//     width (hi − lo) / n; a point outside the box falls into the nearest end cell, or in a
//     periodic dimension into the cell of its image in the box. A periodic dimension
//     wraps the cell indices and gives each neighbour its minimum image:
//     with d = x_j − x and L = hi − lo, if |d| > L/2 the shift −sign(d) L is applied (the
//     rule of LIGGGHTS' Domain::minimum_image for orthogonal boxes), so the image of j is
//     x_j + shift and d + shift is the minimum-image displacement.
// Periodic pairs are found once, in their minimum image: the interaction distance must
// not exceed L/2.
#pragma once

#include <Eigen/Core>

#include <array>
#include <unordered_map>
#include <vector>

namespace wiregrain {

class BroadPhaseGrid {
 public:
  // Unbounded cells of width `cell` > 0 in all dimensions, no periodicity.
  static BroadPhaseGrid unbounded(double cell);
  // Cells over the box [lo, hi) at least `min_cell` wide (see above); periodic[d] wraps
  // dimension d. InvalidArgument("box", ...) when hi ≤ lo or min_cell ≤ 0.
  static BroadPhaseGrid box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                            const std::array<bool, 3>& periodic, double min_cell);

  // Adds a point; returns its index (0, 1, ... in insertion order). Drops the dense index.
  int insert(const Eigen::Vector3d& x);
  // Indexes the points inserted so far in a dense array of cells (a counting sort by cell,
  // insertion order kept within a cell), so that the queries that follow look their 27
  // cells up by address instead of hashing: the same points, visited in the same order.
  // For a grid filled once and then queried many times (a step's grains). Not built (the
  // hash stays in use) when the box of the points' cells holds more than 8 N + 64 cells
  // for N points, e.g. one point far from the others. The next insert drops it.
  void index();
  // The grid of exactly `points` (index j the j-th), indexed: the same grid as inserting
  // them in order and calling index(), without filling the hash when the dense index is
  // built (a grid rebuilt every step, e.g. a step's grains, then allocates nothing per
  // point).
  void assign(std::vector<Eigen::Vector3d> points);
  bool indexed() const { return indexed_; }
  int size() const { return static_cast<int>(points_.size()); }
  const Eigen::Vector3d& point(int index) const { return points_[index]; }
  // widths of the cells (for tests and callers that check the interaction distance)
  const Eigen::Vector3d& cell_width() const { return cell_; }

  // Calls visit(index, shift) for every point in the 27 cells around x, cells in the
  // order of the offsets (x outermost, then y, then z; a wrapped cell visited once),
  // points of a cell in insertion order. shift: the periodic image shift to add to the
  // point (zero in non-periodic dimensions). The caller filters by distance.
  template <class Visit>
  void for_each_near(const Eigen::Vector3d& x, Visit visit) const {
    std::array<std::array<long, 3>, 27> cells;
    const int count = neighbour_cells(x, cells);
    for (int c = 0; c < count; c++) {
      if (indexed_) {
        const long slot = dense_slot(cells[c]);
        if (slot < 0) continue;
        for (int s = dense_start_[slot]; s < dense_start_[slot + 1]; s++)
          visit(dense_points_[s], image_shift(x, points_[dense_points_[s]]));
        continue;
      }
      const auto it = cells_.find(key(cells[c]));
      if (it == cells_.end()) continue;
      for (int j : it->second) visit(j, image_shift(x, points_[j]));
    }
  }

  struct Pair {
    int i, j;               // i < j
    Eigen::Vector3d shift;  // the image of j nearest to i is point(j) + shift
  };
  // All pairs with |x_j + shift − x_i| < cutoff, for cutoff ≤ the cell widths; ordered
  // by i, then as for_each_near visits them.
  std::vector<Pair> candidate_pairs(double cutoff) const;

 private:
  Eigen::Vector3d lo_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d cell_ = Eigen::Vector3d::Ones();
  Eigen::Vector3d period_ = Eigen::Vector3d::Zero();  // L per periodic dimension, else 0
  std::array<long, 3> count_ = {0, 0, 0};             // 0: unbounded
  bool wraps_onto_itself_ = false;  // a periodic dimension of fewer than 3 cells
  std::vector<Eigen::Vector3d> points_;
  std::unordered_map<long, std::vector<int>> cells_;
  // dense index (index()): cells dense_lo_ + [0, dense_count_) per dimension, cell
  // ((i n_y + j) n_z + k) holding dense_points_[dense_start_[slot] .. dense_start_[slot + 1])
  bool indexed_ = false;
  std::array<long, 3> dense_lo_ = {0, 0, 0}, dense_count_ = {0, 0, 0};
  std::vector<int> dense_start_, dense_points_;

  std::array<long, 3> cell_of(const Eigen::Vector3d& x) const;
  // the distinct cells around x that exist (wrapped in periodic dimensions), in the order
  // of the offsets; returns their number
  int neighbour_cells(const Eigen::Vector3d& x, std::array<std::array<long, 3>, 27>& cells) const;
  // the dense index's slot of a cell, −1 outside the indexed range (no point there)
  long dense_slot(const std::array<long, 3>& c) const {
    long slot = 0;
    for (int d = 0; d < 3; d++) {
      const long i = c[d] - dense_lo_[d];
      if (i < 0 || i >= dense_count_[d]) return -1;
      slot = slot * dense_count_[d] + i;
    }
    return slot;
  }
  Eigen::Vector3d image_shift(const Eigen::Vector3d& x, const Eigen::Vector3d& other) const;
  static long key(const std::array<long, 3>& c);
};

}  // namespace wiregrain
