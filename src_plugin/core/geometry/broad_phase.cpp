#include "core/geometry/broad_phase.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/common/errors.h"

namespace wiregrain {

namespace {
constexpr long kMaxCellsPerDimension = 100000;
}

BroadPhaseGrid BroadPhaseGrid::unbounded(double cell) {
  if (!(cell > 0.0) || !std::isfinite(cell))
    throw InvalidArgument("cell", "broad phase: the cell width must be > 0 and finite, got " + std::to_string(cell));
  BroadPhaseGrid grid;
  grid.cell_ = Eigen::Vector3d::Constant(cell);
  return grid;
}

BroadPhaseGrid BroadPhaseGrid::box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                                   const std::array<bool, 3>& periodic, double min_cell) {
  if (!(min_cell > 0.0))
    throw InvalidArgument("box", "broad phase: the smallest cell width must be > 0, got " + std::to_string(min_cell));
  BroadPhaseGrid grid;
  grid.lo_ = lo;
  for (int d = 0; d < 3; d++) {
    const double length = hi[d] - lo[d];
    if (!(length > 0.0)) throw InvalidArgument("box", "broad phase: the box must have hi > lo in every dimension");
    grid.count_[d] = std::max(1L, std::min(kMaxCellsPerDimension, static_cast<long>(std::floor(length / min_cell))));
    grid.cell_[d] = length / grid.count_[d];
    grid.period_[d] = periodic[d] ? length : 0.0;
    grid.wraps_onto_itself_ = grid.wraps_onto_itself_ || (periodic[d] && grid.count_[d] < 3);
  }
  return grid;
}

int BroadPhaseGrid::insert(const Eigen::Vector3d& x) {
  const int index = size();
  cells_[key(cell_of(x))].push_back(index);
  points_.push_back(x);
  indexed_ = false;
  return index;
}

void BroadPhaseGrid::assign(std::vector<Eigen::Vector3d> points) {
  points_ = std::move(points);
  cells_.clear();
  index();
  if (!indexed_)  // the hash, as insert() fills it
    for (int j = 0; j < size(); ++j) cells_[key(cell_of(points_[j]))].push_back(j);
}

void BroadPhaseGrid::index() {
  indexed_ = false;
  if (points_.empty()) return;
  std::vector<std::array<long, 3>> cell(points_.size());
  std::array<long, 3> lo = cell_of(points_[0]), hi = lo;
  for (std::size_t j = 0; j < points_.size(); j++) {
    cell[j] = cell_of(points_[j]);
    for (int d = 0; d < 3; d++) {
      lo[d] = std::min(lo[d], cell[j][d]);
      hi[d] = std::max(hi[d], cell[j][d]);
    }
  }
  const long limit = 8L * static_cast<long>(points_.size()) + 64;
  long slots = 1;
  for (int d = 0; d < 3; d++) {
    const long count = hi[d] - lo[d] + 1;  // ≥ 1; each factor ≤ limit, so no overflow
    if (count > limit || slots * count > limit) return;
    slots *= count;
    dense_lo_[d] = lo[d];
    dense_count_[d] = count;
  }
  dense_start_.assign(slots + 1, 0);
  for (const auto& c : cell) dense_start_[dense_slot(c) + 1]++;
  for (long s = 0; s < slots; s++) dense_start_[s + 1] += dense_start_[s];
  dense_points_.resize(points_.size());
  std::vector<int> next(dense_start_.begin(), dense_start_.end() - 1);
  for (std::size_t j = 0; j < points_.size(); j++) dense_points_[next[dense_slot(cell[j])]++] = static_cast<int>(j);
  indexed_ = true;
}

std::array<long, 3> BroadPhaseGrid::cell_of(const Eigen::Vector3d& x) const {
  std::array<long, 3> c;
  for (int d = 0; d < 3; d++) {
    const double f = std::floor((x[d] - lo_[d]) / cell_[d]);
    if (count_[d] == 0) {
      c[d] = static_cast<long>(f);
    } else if (period_[d] > 0.0) {  // a point outside the box: the cell of its image inside
      const long i = static_cast<long>(f) % count_[d];
      c[d] = i < 0 ? i + count_[d] : i;
    } else {
      c[d] = f < 0.0 ? 0 : (f >= count_[d] ? count_[d] - 1 : static_cast<long>(f));
    }
  }
  return c;
}

int BroadPhaseGrid::neighbour_cells(const Eigen::Vector3d& x, std::array<std::array<long, 3>, 27>& cells) const {
  const std::array<long, 3> home = cell_of(x);
  int count = 0;
  for (long i = -1; i <= 1; i++)
    for (long j = -1; j <= 1; j++)
      for (long k = -1; k <= 1; k++) {
        std::array<long, 3> c = {home[0] + i, home[1] + j, home[2] + k};
        bool exists = true;
        for (int d = 0; d < 3; d++) {
          if (count_[d] == 0 || (c[d] >= 0 && c[d] < count_[d])) continue;
          if (period_[d] > 0.0) c[d] = ((c[d] % count_[d]) + count_[d]) % count_[d];
          else exists = false;
        }
        if (!exists) continue;
        // with fewer than 3 cells a periodic dimension wraps onto a cell already listed
        if (!wraps_onto_itself_ || std::find(cells.begin(), cells.begin() + count, c) == cells.begin() + count)
          cells[count++] = c;
      }
  return count;
}

Eigen::Vector3d BroadPhaseGrid::image_shift(const Eigen::Vector3d& x, const Eigen::Vector3d& other) const {
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
  for (int d = 0; d < 3; d++) {
    if (period_[d] == 0.0) continue;
    const double delta = other[d] - x[d];
    if (std::fabs(delta) > 0.5 * period_[d]) shift[d] = delta < 0.0 ? period_[d] : -period_[d];
  }
  return shift;
}

// 21 bits per index (two's complement, so negative indices of an unbounded grid hash
// too; cells 2²¹ apart share a bucket, which only adds candidates the caller filters)
long BroadPhaseGrid::key(const std::array<long, 3>& c) {
  return ((c[0] & 0x1FFFFF) << 42) | ((c[1] & 0x1FFFFF) << 21) | (c[2] & 0x1FFFFF);
}

std::vector<BroadPhaseGrid::Pair> BroadPhaseGrid::candidate_pairs(double cutoff) const {
  std::vector<Pair> pairs;
  const double cutoff2 = cutoff * cutoff;
  for (int i = 0; i < size(); i++)
    for_each_near(points_[i], [&](int j, const Eigen::Vector3d& shift) {
      if (j <= i) return;
      if ((points_[j] - points_[i] + shift).squaredNorm() < cutoff2) pairs.push_back({i, j, shift});
    });
  return pairs;
}

}  // namespace wiregrain
