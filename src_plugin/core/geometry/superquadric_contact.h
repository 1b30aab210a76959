// Contact of a superquadric grain (superquadric.h) and a wire element: the segment
// [end0, end1] dilated by the wire radius. No sweep radius: gap = distance − wire_radius.
// docs/design.md, "Contact geometry".
#pragma once

#include <Eigen/Dense>

#include "core/geometry/segment_contact.h"
#include "core/geometry/superquadric.h"

namespace wiregrain {

// Apart: GJK with the closed-form support point (stopped when
// the distance bound gains less than 1e-16 of the size), then a Newton polish of the
// closest points in the normal and the segment parameter; the nearest of the genuine
// pairs (support point c(n), its projection on the segment) built from GJK's direction,
// the polished one and GJK's own body point (docs/design.md, "Contact geometry"). Closer than 1e-8 of
// the size: the surface normal (∇F) at GJK's body point. An axis that touches or crosses
// the body (overlap ≥ r_w): the normal is ∇F at the segment point nearest the body's
// centre, the distance minus the overlap of body and segment along it (a
// separating-axis depth along that one axis: ≥ the penetration depth), t that point's
// parameter. No flat features: t_begin = t_end = t.
// early_exit_distance > 0 (0 or +inf: never; negative or NaN: InvalidArgument): GJK stops
// as soon as its lower bound v·w/|v| shows the distance exceeds it (method gjk_far; the
// distance is that lower bound, so the gap is one too; normal along the centres, t = ½).
// Callers that need only touching pairs (and the gaps below some bound) pass it: the
// Newton polish of pairs apart was 90 % of a superquadric column's run time.
//
// guess (optional): a previous solution of the same pair (normal from the body to the
// segment, segment parameter t), e.g. last step's. The Newton polish starts there; its
// result (n, t) is kept only if it certifies itself: with c = c(n), p = x0 + t s, d =
// n·(p − c) > 0, the plane n·x = n·c supports the body, and the segment lies beyond
// n·p − |s|·ε_s (ε_s = |s·n|/|s| for t inside, the outward part of it at an end), so the
// true distance lies in [d − |s| ε_s, |p − c|]; accepted when that interval is below 1e-12
// of the size (then method gjk, gjk_iterations 0). Otherwise the full query. The last
// step's pair moves ~1e-5 a step: the polish converges in one or two iterations, and GJK
// (≈20 support points and simplex solves) and the two cold polishes are skipped.
struct SmoothContactGuess {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double t = 0.0;
};
SegmentContact segment_contact(const PosedSuperquadric& grain, const Eigen::Vector3d& end0,
                               const Eigen::Vector3d& end1, double wire_radius,
                               double early_exit_distance = 0.0, const SmoothContactGuess* guess = nullptr);

}  // namespace wiregrain
