// Contact detection of a grain step (grain_detection.h).
#include "core/nscd/grain_detection.h"

#include <algorithm>
#include <optional>
#include <string>

#include "core/common/errors.h"
#include "core/geometry/broad_phase.h"

namespace wiregrain {
namespace grain_step_detail {

namespace {

// The contact manifolds of the candidates, shared out (share_out, core/common/work_share.h):
// `compute(candidate, simplex)` (simplex: null, or GJK's warm start from the candidate's,
// left with its last). The numbers of a candidate: its gap, its point count and 7 numbers
// per point, and with `simplices` the simplex's size and its index pairs (every worker
// then holds every pair's simplex, whoever computed it: the next step's warm start is the
// same on any number of workers).
template <class Compute>
std::vector<NarrowPhaseResult> narrow_phase(const std::vector<NarrowPhaseCandidate>& candidates,
                                            const WorkShare* share, bool simplices, const Compute& compute) {
  std::vector<NarrowPhaseResult> found(candidates.size());
  const auto compute_one = [&](std::size_t i, std::vector<double>& out) {
    if (candidates[i].frozen) {
      out.insert(out.end(), {found[i].gap, 0.0});
      if (simplices) out.push_back(0.0);
      return;
    }
    found[i].simplex = candidates[i].simplex;
    ContactManifold m = compute(candidates[i], simplices ? &found[i].simplex : nullptr);
    found[i].gap = m.gap;
    found[i].points = std::move(m.points);
    out.push_back(found[i].gap);
    out.push_back(static_cast<double>(found[i].points.size()));
    for (const ContactPoint& p : found[i].points)
      out.insert(out.end(), {p.position.x(), p.position.y(), p.position.z(), p.normal.x(), p.normal.y(), p.normal.z(), p.gap});
    if (simplices) {
      const GjkSimplex& s = found[i].simplex;
      out.push_back(s.size);
      for (int k = 0; k < s.size; k++) out.insert(out.end(), {double(s.a[k]), double(s.b[k])});
    }
  };
  const auto read_one = [&](std::size_t i, SharedNumbers& in) {
    NarrowPhaseResult& r = found[i];
    r.gap = in.next();
    const double points = in.next();
    for (int k = 0; k < static_cast<int>(points); k++) {
      ContactPoint p;
      p.position.x() = in.next();
      p.position.y() = in.next();
      p.position.z() = in.next();
      p.normal.x() = in.next();
      p.normal.y() = in.next();
      p.normal.z() = in.next();
      p.gap = in.next();
      // (the step uses position, normal and gap only: the surface points are not sent)
      p.point_a = p.point_b = p.position;
      r.points.push_back(p);
    }
    if (simplices) {
      r.simplex.size = static_cast<int>(in.next());
      if (r.simplex.size < 0 || r.simplex.size > 4)
        throw NumericalFailure("grain step: the joined narrow phase has a simplex of size " + std::to_string(r.simplex.size));
      for (int k = 0; k < r.simplex.size; k++) {
        r.simplex.a[k] = static_cast<int>(in.next());
        r.simplex.b[k] = static_cast<int>(in.next());
      }
    }
  };
  share_out(candidates.size(), share, compute_one, read_one);
  return found;
}

// The candidates of the pairs the cache keeps that may touch within `activation`, with
// GJK's simplices when `warm_geometry`.
void kept_pair_candidates(GrainPairCache& pairs, const std::vector<char>& asleep, double activation,
                          bool warm_geometry, std::vector<NarrowPhaseCandidate>& candidates) {
  const auto sleeping = [&](int k) { return !asleep.empty() && asleep[k]; };
  pairs.count_reuse();
  const std::vector<GrainPairCache::KeptPair>& kept = pairs.pairs();
  for (std::size_t i = 0; i < kept.size(); i++) {
    const GrainPairCache::KeptPair& p = kept[i];
    if (!(sleeping(p.a) && sleeping(p.b)) && !pairs.still_apart(p, activation))
      candidates.push_back({p.a, p.b, -1, false, static_cast<int>(i), warm_geometry ? p.simplex : GjkSimplex()});
  }
}

// The candidates of the broad-phase grid: the grain pairs whose bounding spheres come
// within activation + skin.
// owned ≥ 0: only the pairs of this worker (detect_contacts).
bool owns_pair(const std::vector<GrainState>& grains, int owned, int a, int b) {
  if (owned < 0) return true;
  if (grains[a].tag == grains[b].tag) return false;  // a grain and its own image
  return (grains[a].tag < grains[b].tag ? a : b) < owned;
}

void grid_candidates(const std::vector<GrainState>& grains, const ShapeLibrary& library,
                     const std::vector<char>& asleep, double activation, double skin, double largest_radius,
                     const PeriodicBox& box, int owned, std::vector<NarrowPhaseCandidate>& candidates) {
  const auto sleeping = [&](int k) { return !asleep.empty() && asleep[k]; };
  const int n = static_cast<int>(grains.size());
  const double cell = 2.0 * largest_radius + activation + skin;
  // periodic dimensions: the grid wraps its cells (its box's other dimensions only place
  // the cells; a grain outside them falls into the end cell)
  BroadPhaseGrid grid = box.any() ? BroadPhaseGrid::box(box.lo, box.hi, box.periodic, cell) : BroadPhaseGrid::unbounded(cell);
  std::vector<Eigen::Vector3d> centres;
  centres.reserve(grains.size());
  for (const GrainState& g : grains) centres.push_back(g.position);
  grid.assign(std::move(centres));
  std::vector<int> near;
  for (int a = 0; a < n; a++) {
    const double ra = library[grains[a].shape].bounding_radius;
    near.clear();
    grid.for_each_near(grains[a].position, [&](int b, const Eigen::Vector3d&) {
      if (b <= a || !owns_pair(grains, owned, a, b)) return;
      const double reach = ra + library[grains[b].shape].bounding_radius + activation + skin;
      if (box.minimum_image(grains[b].position - grains[a].position).squaredNorm() < reach * reach) near.push_back(b);
    });
    std::sort(near.begin(), near.end());
    // a pair of sleepers is frozen: not computed, kept in the cache for when one wakes
    for (int b : near) candidates.push_back({a, b, -1, sleeping(a) && sleeping(b), -1, GjkSimplex()});
  }
}

// The candidates of each wall: its awake grains within `activation` of its plane.
void wall_candidates(const std::vector<GrainState>& grains, const ShapeLibrary& library,
                     const std::vector<PlaneWall>& walls, const std::vector<char>& asleep, double activation,
                     int owned, std::vector<NarrowPhaseCandidate>& candidates) {
  const auto sleeping = [&](int k) { return !asleep.empty() && asleep[k]; };
  const int n = owned >= 0 ? owned : static_cast<int>(grains.size());
  for (int w = 0; w < (int)walls.size(); w++)
    for (int b = 0; b < n; b++) {
      if (sleeping(b)) continue;  // frozen (a moving wall within reach woke it)
      if (walls[w].normal.dot(grains[b].position - walls[w].point) > library[grains[b].shape].bounding_radius + activation)
        continue;
      candidates.push_back({-1, b, w, false, -1, GjkSimplex()});
    }
}

// After the narrow phase: a cache that was built again keeps the pairs within
// activation + skin (and the frozen ones); a reused cache keeps GJK's last simplices.
void update_pair_cache(GrainPairCache& pairs, bool reused, bool warm_geometry, const std::vector<GrainState>& grains,
                       const ShapeLibrary& library, double activation, double skin, const DetectedContacts& detected) {
  const std::vector<NarrowPhaseCandidate>& candidates = detected.candidates;
  const std::vector<NarrowPhaseResult>& found = detected.found;
  if (!reused && !grains.empty()) {
    pairs.begin_build();
    for (std::size_t i = 0; i < candidates.size(); i++) {
      const NarrowPhaseCandidate& c = candidates[i];
      if (c.wall < 0 && (c.frozen || found[i].gap < activation + skin))
        pairs.keep(c.a, c.b, c.frozen ? -std::numeric_limits<double>::infinity() : found[i].gap, found[i].simplex);
    }
    pairs.end_build(grains, library, activation);
  } else if (warm_geometry && reused) {
    for (std::size_t i = 0; i < candidates.size(); i++)
      if (candidates[i].kept >= 0) pairs.set_simplex(static_cast<std::size_t>(candidates[i].kept), found[i].simplex);
  }
}

}  // namespace

DetectedContacts detect_contacts(const std::vector<GrainState>& grains, const ShapeLibrary& library,
                                 const std::vector<PlaneWall>& walls, const GrainStepOptions& options,
                                 const std::vector<char>& asleep, double activation, double largest_radius,
                                 GrainPairCache* pairs, const WorkShare* share, int owned) {
  const int n = static_cast<int>(grains.size());
  ContactOptions contact_options;
  contact_options.near_vertices = options.near_vertices;
  DetectedContacts detected;
  std::vector<NarrowPhaseCandidate>& candidates = detected.candidates;
  const bool reuse = n > 0 && pairs && pairs->valid(grains, library, activation, options.box);
  const double skin = pairs && !reuse ? pairs->skin() : 0.0;
  const bool warm_geometry = options.warm_geometry && pairs;
  if (reuse)
    kept_pair_candidates(*pairs, asleep, activation, warm_geometry, candidates);
  else if (n > 0)
    grid_candidates(grains, library, asleep, activation, skin, largest_radius, options.box, owned, candidates);
  wall_candidates(grains, library, walls, asleep, activation, owned, candidates);
  ContactOptions build_options = contact_options;  // a cache build learns which pairs lie beyond activation + skin
  build_options.exit_beyond_activation = skin;
  std::vector<std::optional<PosedShape>> posed(n);  // the grains of this worker's candidates
  const auto posed_grain = [&](int k) -> const PosedShape& {
    if (!posed[k]) posed[k].emplace(library[grains[k].shape].shape, grains[k].position, grains[k].orientation);
    return *posed[k];
  };
  const auto compute = [&](const NarrowPhaseCandidate& c, GjkSimplex* simplex) {
    if (c.wall >= 0) {
      Plane plane;
      plane.point = walls[c.wall].point;
      plane.normal = walls[c.wall].normal;
      return plane_contact(plane, posed_grain(c.b), activation, contact_options);
    }
    const ContactOptions& pair_options = reuse ? contact_options : build_options;
    // grain b's image nearest to grain a: the points lie by a
    const Eigen::Vector3d shift = options.box.image_shift(grains[c.a].position, grains[c.b].position);
    if (!shift.isZero(0.0)) {
      const PosedShape image(library[grains[c.b].shape].shape, grains[c.b].position + shift, grains[c.b].orientation);
      return contact_manifold(posed_grain(c.a), image, activation, pair_options, simplex);
    }
    return contact_manifold(posed_grain(c.a), posed_grain(c.b), activation, pair_options, simplex);
  };
  detected.found = narrow_phase(candidates, share, warm_geometry, compute);
  if (pairs) update_pair_cache(*pairs, reuse, warm_geometry, grains, library, activation, skin, detected);
  return detected;
}

}  // namespace grain_step_detail
}  // namespace wiregrain
