// The post-step projection of the grains' overlaps (overlap_projection.h).
#include "core/nscd/overlap_projection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdint>
#include <optional>
#include <utility>

#include "core/common/errors.h"
#include "core/common/validation.h"
#include "core/geometry/contact_manifold.h"
#include "core/geometry/core_distance.h"
#include "core/geometry/posed_shape.h"

namespace wiregrain {

namespace {

// A pair to check: grain indices (a = −1: wall `wall`).
struct ProjectedPair {
  int a = -1, b = -1, wall = -1;
  double size = 0.0;  // the smaller bounding radius of its grains
  // the normal (a to b) of its deepest point at the step start: the axis of the
  // separation bound below
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  double deepest = std::numeric_limits<double>::infinity();
};

// The pair's gap at the current poses and its unit normal from a to b.
struct PairGap {
  bool near = false;  // false: the cores are farther apart than the sweeps: no overlap
  double gap = 0.0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

// 2. the pairs of the step's points, once each, in the order of their first point
std::vector<ProjectedPair> projected_pairs(const std::vector<GrainState>& grains, const ShapeLibrary& library,
                                           const GrainStepProblem& problem) {
  // the points by pair, (a or −(wall + 1), b) as one key, each pair's points in their order
  const int count = static_cast<int>(problem.points.size());
  std::vector<std::pair<std::uint64_t, int>> by_pair(count);
  for (int i = 0; i < count; ++i) {
    const GrainContactPoint& p = problem.points[i];
    const int first = p.constraint.body_a >= 0 ? p.constraint.body_a : p.pair.first;  // a wall: −(wall + 1)
    by_pair[i] = {(std::uint64_t(std::uint32_t(first)) << 32) | std::uint32_t(p.constraint.body_b), i};
  }
  std::sort(by_pair.begin(), by_pair.end());
  std::vector<std::pair<int, ProjectedPair>> found;  // (its first point, the pair)
  for (int g = 0; g < count;) {
    const GrainContactPoint& p0 = problem.points[by_pair[g].second];
    ProjectedPair pair;
    pair.a = p0.constraint.body_a;
    pair.b = p0.constraint.body_b;
    pair.wall = pair.a >= 0 ? -1 : static_cast<int>(-p0.pair.first - 1);
    pair.size = library[grains[pair.b].shape].bounding_radius;
    if (pair.a >= 0) pair.size = std::min(pair.size, library[grains[pair.a].shape].bounding_radius);
    int end = g;
    for (; end < count && by_pair[end].first == by_pair[g].first; ++end) {
      const GrainContactPoint& p = problem.points[by_pair[end].second];
      if (p.constraint.gap < pair.deepest && std::abs(p.frame.col(0).norm() - 1.0) < 1e-9) {  // a unit normal
        pair.deepest = p.constraint.gap;
        pair.axis = p.frame.col(0);
      }
    }
    found.push_back({by_pair[g].second, pair});
    g = end;
  }
  std::sort(found.begin(), found.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<ProjectedPair> pairs;
  pairs.reserve(found.size());
  for (const auto& f : found) pairs.push_back(f.second);
  return pairs;
}

// The grains at the poses the step leads to, moved by the projection: the pairs' gaps and
// their bounds at the current poses, and the moves.
class ProjectedGrains {
 public:
  // 1. the poses the step leads to
  ProjectedGrains(const std::vector<GrainState>& grains, const ShapeLibrary& library,
                  const std::vector<PlaneWall>& walls, const GrainStepProblem& problem,
                  const GrainStepResult& result, double theta)
      : grains_(grains), library_(library), walls_(walls), problem_(problem), h_(problem.step.time_step) {
    const int n = static_cast<int>(grains.size());
    // each wall's plane at the end of the step: moved by h v, a plate by its θ-method step
    for (std::size_t w = 0; w < walls.size(); w++)
      wall_shift_.push_back(walls[w].plate() ? wall_step_displacement(walls[w], result.wall_velocities[w], h_, theta)
                                             : Eigen::Vector3d(h_ * walls[w].velocity));
    corrections_.assign(n, Eigen::Vector3d::Zero());
    poses_.resize(n);
    posed_.resize(n);
    for (int k = 0; k < n; ++k) {
      const GrainState& g = grains[k];
      const Eigen::Matrix3d r0 = g.orientation.toRotationMatrix();
      const Eigen::Matrix3d inertia_begin = r0 * g.inertia.asDiagonal() * r0.transpose();
      poses_[k] = advance_grain_pose({g.position, g.orientation}, g.inertia, g.velocity, result.velocities[k],
                                     inertia_begin * g.angular_velocity, inertia_begin * result.angular_velocities[k],
                                     h_, theta);
    }
  }

  PairGap pair_gap(const ProjectedPair& pair) {
    PairGap out;
    const PosedShape& b = posed_grain(pair.b);
    if (pair.a < 0) {  // a wall: its plane at the end of the step
      const PlaneWall& w = walls_[pair.wall];
      const Eigen::Vector3d point = w.point + wall_shift_[pair.wall];
      const Eigen::Vector3d& v = b.vertices()[b.support_vertex(-w.normal)];
      out.near = true;
      out.gap = w.normal.dot(v - point) - b.sweep_radius();
      out.normal = w.normal;
      return out;
    }
    const PosedShape& a = posed_grain(pair.a);
    const double sweeps = a.sweep_radius() + b.sweep_radius();
    // grain b's image nearest to grain a
    const Eigen::Vector3d shift = image_shift(pair);
    std::optional<PosedShape> image;
    if (!shift.isZero(0.0))
      image.emplace(library_[grains_[pair.b].shape].shape, poses_[pair.b].position + shift, poses_[pair.b].orientation);
    const CoreDistance d = core_distance(a, image ? *image : b, sweeps);
    if (d.method == DistanceMethod::gjk_far) return out;
    out.near = true;
    out.gap = d.distance - sweeps;
    out.normal = d.normal;
    return out;
  }

  // A lower bound of the pair's gap at the current poses without GJK: the separation of
  // the cores along its start normal (lowest_core_point; for a wall the plane is the
  // other set and the bound is exact), so the grains need not be posed.
  double separation_bound(const ProjectedPair& pair) const {
    const ConvexShape& b = library_[grains_[pair.b].shape].shape;
    if (pair.a < 0) {
      const PlaneWall& w = walls_[pair.wall];
      return lowest_along(pair.b, w.normal) - w.normal.dot(w.point + wall_shift_[pair.wall]) - b.sweep_radius();
    }
    if (!(pair.deepest < std::numeric_limits<double>::infinity())) return -std::numeric_limits<double>::infinity();
    const ConvexShape& a = library_[grains_[pair.a].shape].shape;
    const double bound = lowest_along(pair.b, pair.axis) + lowest_along(pair.a, -pair.axis) - a.sweep_radius() - b.sweep_radius();
    const Eigen::Vector3d shift = image_shift(pair);  // grain b's image nearest to grain a
    return shift.isZero(0.0) ? bound : bound + pair.axis.dot(shift);
  }

  // the shift of grain b's image nearest to grain a at the current poses (zero without
  // periodic dimensions)
  Eigen::Vector3d image_shift(const ProjectedPair& pair) const {
    return problem_.box.image_shift(poses_[pair.a].position, poses_[pair.b].position);
  }

  // a sleeping grain (grain_step.h) is held, as a wall
  double inverse_mass(int k) const {
    return !problem_.asleep.empty() && problem_.asleep[k] ? 0.0 : 1.0 / grains_[k].mass;
  }

  void move(int k, const Eigen::Vector3d& impulse) {
    if (inverse_mass(k) == 0.0) return;
    const Eigen::Vector3d dx = impulse * inverse_mass(k);
    corrections_[k] += dx;
    poses_[k].position += dx;
    posed_[k].reset();
  }

  std::vector<Eigen::Vector3d>& corrections() { return corrections_; }

 private:
  const PosedShape& posed_grain(int k) {
    if (!posed_[k]) posed_[k].emplace(library_[grains_[k].shape].shape, poses_[k].position, poses_[k].orientation);
    return *posed_[k];
  }
  double lowest_along(int k, const Eigen::Vector3d& n) const {
    return lowest_core_point(library_[grains_[k].shape].shape, poses_[k].position, poses_[k].orientation, n);
  }

  const std::vector<GrainState>& grains_;
  const ShapeLibrary& library_;
  const std::vector<PlaneWall>& walls_;
  const GrainStepProblem& problem_;
  const double h_;
  std::vector<Eigen::Vector3d> wall_shift_;  // per wall, its displacement over the step
  std::vector<GrainPose> poses_;
  std::vector<std::optional<PosedShape>> posed_;
  std::vector<Eigen::Vector3d> corrections_;
};

// 3. Gauss–Seidel passes while a pair is deeper than the tolerance; a pass checks the
// pairs of grains moved since their last check (every pair in the first pass). Then the
// deepest overlap left (the pairs of grains moved in a last pass that still found deep
// pairs are checked once more).
void project_pairs(ProjectedGrains& grains, const std::vector<ProjectedPair>& pairs, int n, double tolerance,
                   int max_passes, OverlapProjectionStats& local) {
  std::vector<double> overlap_of(pairs.size(), 0.0);  // at its last check, relative
  std::vector<char> moved(n, 1);
  const auto touches_moved = [&](const ProjectedPair& pair) { return moved[pair.b] || (pair.a >= 0 && moved[pair.a]); };
  bool deep = true;
  for (int pass = 0; pass < max_passes && deep; ++pass) {
    std::vector<char> moved_now(n, 0);
    deep = false;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const ProjectedPair& pair = pairs[k];
      if (!touches_moved(pair) && !moved_now[pair.b] && (pair.a < 0 || !moved_now[pair.a])) continue;
      // proven shallower than the tolerance: no GJK (its overlap counts as the bound's)
      const double bound = grains.separation_bound(pair);
      if (std::isfinite(bound) && -bound / pair.size <= tolerance) {
        overlap_of[k] = std::max(0.0, -bound / pair.size);
        if (pass == 0) local.max_overlap_before = std::max(local.max_overlap_before, overlap_of[k]);
        ++local.bounded;
        continue;
      }
      const PairGap g = grains.pair_gap(pair);
      overlap_of[k] = g.near ? -g.gap / pair.size : 0.0;
      if (pass == 0) local.max_overlap_before = std::max(local.max_overlap_before, overlap_of[k]);
      if (!(overlap_of[k] > tolerance)) continue;
      deep = true;
      double w = grains.inverse_mass(pair.b);
      if (pair.a >= 0) w += grains.inverse_mass(pair.a);
      if (!(w > 0.0)) continue;  // not reached: a pair of sleeping grains has no points
      const double lambda = (-g.gap - 0.5 * tolerance * pair.size) / w;
      grains.move(pair.b, lambda * g.normal);
      moved_now[pair.b] = 1;
      if (pair.a >= 0) {
        grains.move(pair.a, -lambda * g.normal);
        moved_now[pair.a] = 1;
      }
      ++local.projections;
    }
    local.passes = pass + 1;
    moved = moved_now;
  }
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (deep && touches_moved(pairs[k])) {
      const PairGap g = grains.pair_gap(pairs[k]);
      overlap_of[k] = g.near ? -g.gap / pairs[k].size : 0.0;
    }
    local.max_overlap_after = std::max(local.max_overlap_after, overlap_of[k]);
  }
}

}  // namespace

std::vector<Eigen::Vector3d> project_overlaps(const std::vector<GrainState>& grains, const ShapeLibrary& library,
                                             const std::vector<PlaneWall>& walls, const GrainStepProblem& problem,
                                             const GrainStepResult& result, double theta, double tolerance,
                                             int max_passes, OverlapProjectionStats* stats) {
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance))
    throw InvalidArgument("tolerance", "overlap projection: tolerance must be >= 0 and finite, got " +
                                           format_number(tolerance));
  if (max_passes < 1)
    throw InvalidArgument("max_passes", "overlap projection: max_passes must be >= 1, got " + std::to_string(max_passes));
  const int n = static_cast<int>(grains.size());
  OverlapProjectionStats local;
  if (tolerance == 0.0 || problem.points.empty()) {
    if (stats) *stats = local;
    return std::vector<Eigen::Vector3d>(n, Eigen::Vector3d::Zero());
  }
  ProjectedGrains projected(grains, library, walls, problem, result, theta);
  const std::vector<ProjectedPair> pairs = projected_pairs(grains, library, problem);
  local.pairs = static_cast<int>(pairs.size());
  project_pairs(projected, pairs, n, tolerance, max_passes, local);
  if (stats) *stats = local;
  return std::move(projected.corrections());
}

}  // namespace wiregrain
