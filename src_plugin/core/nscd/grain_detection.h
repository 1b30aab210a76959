// Contact detection of a grain step (step 2 of core/nscd/grain_step.h): the candidate
// pairs whose gap may close within the step, in a fixed order (grain pairs a < b, b
// ascending for each a, grains in tag order: the same whether they come from the broad
// phase or from the pair cache, core/nscd/grain_pairs.h; then each wall's grains), and
// their contact manifolds, computed by one worker or shared out among several
// (core/common/work_share.h) with the same result to the bit.
#pragma once

#include <limits>
#include <vector>

#include "core/common/work_share.h"
#include "core/geometry/contact_manifold.h"
#include "core/geometry/posed_shape.h"
#include "core/nscd/grain_step.h"

namespace wiregrain {
namespace grain_step_detail {

// A candidate of the narrow phase: grains a < b (wall < 0), or wall `wall` and grain b
// (a = −1); a frozen pair (two sleepers) is not computed.
struct NarrowPhaseCandidate {
  int a = -1, b = -1, wall = -1;
  bool frozen = false;
  int kept = -1;        // its index in the pair cache's pairs() when it comes from there
  GjkSimplex simplex;   // GJK's warm start (empty: cold)
};

struct NarrowPhaseResult {
  double gap = std::numeric_limits<double>::infinity();  // the manifold's (a lower bound when far)
  std::vector<ContactPoint> points;                      // position, normal and gap are used
  GjkSimplex simplex;                                    // GJK's last (with `simplices`)
};

// The candidates and their manifolds, parallel.
struct DetectedContacts {
  std::vector<NarrowPhaseCandidate> candidates;
  std::vector<NarrowPhaseResult> found;
};

// The contact manifolds of every pair within `activation` (grains of bounding radius at
// most largest_radius): from the pair cache's pairs when it is still valid, else from a
// broad-phase grid (and the cache is built again, with its skin). A pair of two sleeping
// grains (asleep: per grain, empty when sleeping is off) is frozen: a candidate not
// computed, kept in the cache for when one wakes; a sleeping grain has no wall pairs.
DetectedContacts detect_contacts(const std::vector<GrainState>& grains, const ShapeLibrary& library,
                                 const std::vector<PlaneWall>& walls, const GrainStepOptions& options,
                                 const std::vector<char>& asleep, double activation, double largest_radius,
                                 GrainPairCache* pairs, const WorkShare* share, int owned = -1);
// owned ≥ 0: a worker of a distributed step (core/nscd/grain_step.h, GrainPartition): only
// the pairs it owns (the grain of the smaller tag among its first `owned`; a wall pair's
// grain among them).

}  // namespace grain_step_detail
}  // namespace wiregrain
