// Tolerances and limits of the contact queries (contact_manifold.h, segment_contact.h),
// and the input checks they share.
#pragma once

#include <Eigen/Dense>
#include <limits>

namespace wiregrain {

struct ContactOptions {
  // A face (edge) counts as parallel to the contact plane when its normal (direction) is
  // within this angle of n (of the plane). Radians, in [0, 0.5]. Larger values give
  // multi-point manifolds for more tilted resting contacts; the point gaps stay exact.
  double angle_tolerance = 1e-2;
  // At most this many points per manifold (0: no limit). Polygons with more vertices
  // are reduced by repeatedly dropping the vertex whose removal loses the least area,
  // never the deepest one.
  int max_points = 8;
  // segment_contact only: the closest feature and the parallel interval are looked up
  // only when the gap is at most this; a segment farther away gets GJK's closest points
  // and t_begin = t_end = t (callers that only need the gap of pairs apart pass 0: the
  // feature lookup was a quarter of the wire–grain contact time, bench/wire_grain_contacts.py).
  double feature_gap_limit = std::numeric_limits<double>::infinity();
  // contact_manifold and plane_contact: besides the closest features' points, a point for
  // every other vertex of a core whose own gap is below the activation distance (its
  // closest point on the other core, its own normal along the two; for a wall the wall
  // normal). Without them a grain tumbling onto another (or a wall) closes its next vertex
  // one step late: overlaps of ~1e-3 a_max in deposits (docs/design.md, "Contact geometry").
  bool near_vertices = false;
  // contact_manifold: GJK may stop once the gap is known to exceed activation_distance +
  // this (≥ 0, +inf: never early); the
  // manifold's gap is then a lower bound (method gjk_far). A pair within it gets its exact
  // gap, and the same points as with 0. The grain pair cache (core/nscd/grain_pairs.h)
  // passes its skin to learn which pairs lie beyond activation + skin.
  double exit_beyond_activation = 0.0;
  // segment_contact (polytope) only: GJK may stop once the gap (between the swept surfaces)
  // is known to exceed this (+inf: never, the default; negative or NaN: InvalidArgument);
  // the gap is then GJK's lower bound (method gjk_far, normal along the centres, t = ½).
  // A pair with gap ≤ exit_gap gets exactly the result it gets without it (its lower
  // bounds never exceed it). The wire–grain contact passes the gap below which it needs
  // exact values (0 for a touching test, the pair cache's skin at a build): most of its
  // evaluated pairs are apart.
  double exit_gap = std::numeric_limits<double>::infinity();
};

// InvalidArgument naming the option: angle_tolerance outside [0, 0.5], max_points < 0,
// feature_gap_limit NaN, exit_beyond_activation or exit_gap negative or NaN.
void check_contact_options(const ContactOptions& options);

// InvalidArgument(name) when value is NaN (±inf allowed).
void require_not_nan(const char* name, double value);

// InvalidArgument(name) when a coordinate of value is not finite.
void require_finite_vector(const char* name, const Eigen::Vector3d& value);

}  // namespace wiregrain
