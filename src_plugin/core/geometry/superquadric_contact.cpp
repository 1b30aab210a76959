// Contact of a superquadric and a wire segment: GJK on the closed-form support point,
// a Newton polish of the closest points, a certified warm start. See
// superquadric_contact.h and docs/design.md, "Contact geometry".
#include "core/geometry/superquadric_contact.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/common/errors.h"
#include "core/common/validation.h"
#include "core/geometry/contact_frame.h"
#include "core/geometry/gjk.h"
#include "core/geometry/sat.h"

namespace wiregrain {

namespace {

using Eigen::Vector3d;

constexpr double kInf = std::numeric_limits<double>::infinity();
// GJK against a smooth body (a superquadric) approaches the closest points without ever
// repeating a support point: it stops when the distance bound improves by less than this
// (relative to the size): at most 58 iterations over tests/core's random segments.
constexpr double kGjkSmoothProgress = 1e-16;

// A superquadric: its support points are computed on demand and kept, so that an index
// names a point as for the polytopes (indices never repeat: GJK stops on progress alone).
struct SuperquadricSet {
  explicit SuperquadricSet(const PosedSuperquadric& b) : body(&b) { points.reserve(kGjkMaxIterations + 2); }
  const PosedSuperquadric* body;
  mutable std::vector<Vector3d> points;
  int count() const { return 0; }  // no warm simplex: its points are made anew by each query
  int support(const Vector3d& d) const {
    points.push_back(body->support(d));
    return static_cast<int>(points.size()) - 1;
  }
  const Vector3d& point(int i) const { return points[i]; }
};

// Newton polish of the closest points of a segment and a smooth convex body, from GJK's.
// GJK's distance converges fast but its closest points and normal only as the square root
// of the distance's error (~1e-6 here). The optimality conditions in terms of the unit
// normal n and the segment parameter t, with c(n) the support point and p(t) = x0 + t s:
//   (p(t) − c(n)) ⟂ n's tangent plane  (2 equations: components on a basis u, w ⟂ n_k),
//   s · n = 0                          (t inside (0, 1); otherwise t stays at its end),
// in the unknowns n = normalise(n_k + α u + β w) and t, with a Jacobian by forward
// differences in α, β (the support point is closed-form but its derivative is not worth
// writing) and in closed form in t.
// A singular Jacobian (a segment parallel to a flat stretch: t is not unique) keeps t.
// The caller keeps the result only if its pair is not farther than the unpolished ones.
void polish_closest_points(const PosedSuperquadric& body, const Vector3d& end0, const Vector3d& end1,
                           Vector3d& n, double& t) {
  const Vector3d s = end1 - end0;
  const double length2 = s.squaredNorm();
  bool free_t = length2 > 0.0 && t > 1e-12 && t < 1.0 - 1e-12;
  const double h = 1e-7;
  // a residual below rounding of the configuration's size ends the polish before another
  // Jacobian (the warm start arrives converged or one step away)
  const double scale = std::max(std::sqrt(length2), (end0 - body.position()).norm());
  for (int iteration = 0; iteration < 8; ++iteration) {
    Vector3d u, w;
    plane_basis(n, u, w);
    const int m = free_t ? 3 : 2;
    const auto residual = [&](double a, double b, double tt) {
      const Vector3d nn = (n + a * u + b * w).normalized();
      const Vector3d diff = end0 + tt * s - body.support(nn);
      const Vector3d tangential = diff - nn.dot(diff) * nn;
      return Vector3d(u.dot(tangential), w.dot(tangential), free_t ? s.dot(nn) / std::sqrt(length2) : 0.0);
    };
    const Vector3d r0 = residual(0.0, 0.0, t);
    if (Vector3d(r0[0], r0[1], r0[2] * scale).norm() <= 1e-15 * scale) return;
    // the Jacobian: forward differences in the normal's two tilts (the Newton step's
    // accuracy does not depend on it, only its rate), in t in closed form (the support
    // point does not depend on t: ∂/∂t of the tangential part is s − (n·s) n)
    Eigen::Matrix3d J = Eigen::Matrix3d::Identity();
    J.col(0) = (residual(h, 0.0, t) - r0) / h;
    J.col(1) = (residual(0.0, h, t) - r0) / h;
    if (free_t) J.col(2) = Vector3d(u.dot(s), w.dot(s), 0.0);
    Vector3d step = Vector3d::Zero();
    bool singular;
    if (m == 3) {
      const Eigen::FullPivLU<Eigen::Matrix3d> solve(J);
      singular = !solve.isInvertible() || solve.rcond() < 1e-10;
      if (!singular) step = solve.solve(Vector3d(-r0));
    } else {
      const Eigen::FullPivLU<Eigen::Matrix2d> solve(J.topLeftCorner<2, 2>());
      singular = !solve.isInvertible() || solve.rcond() < 1e-10;
      if (!singular) step.head<2>() = solve.solve(Eigen::Vector2d(-r0.head<2>()));
    }
    if (singular) {
      if (free_t) {
        free_t = false;
        continue;
      }
      return;
    }
    n = (n + step[0] * u + step[1] * w).normalized();
    if (free_t) {
      t += step[2];
      if (t < 0.0 || t > 1.0) {
        t = std::clamp(t, 0.0, 1.0);
        free_t = false;
      }
    }
    if (step.head(m).norm() < 1e-15) return;
  }
}

// The wire segment of a query: its ends, s = end1 − end0 and length = |s|.
struct Segment {
  const Vector3d& end0;
  const Vector3d& end1;
  Vector3d s;
  double length;
};

// The warm start (see the header): the polish from the guess, kept when its distance
// interval [d − |s| ε_s, |p − c|] is below 1e-12 of the size. True (and `out` filled, gap
// included) when it is.
bool take_certified_guess(const PosedSuperquadric& grain, const Segment& seg, double size, double wire_radius,
                          const SmoothContactGuess& guess, SegmentContact& out) {
  const Vector3d &end0 = seg.end0, &end1 = seg.end1, &s = seg.s;
  Vector3d n = guess.normal.normalized();
  double t = seg.length > 0.0 ? guess.t : 0.0;
  polish_closest_points(grain, end0, end1, n, t);
  const Vector3d core = grain.support(n), on_segment = end0 + t * s, diff = on_segment - core;
  const double d = n.dot(diff), sn = s.dot(n);
  const double outward = t <= 0.0 ? std::max(0.0, -sn) : t >= 1.0 ? std::max(0.0, sn) : std::abs(sn);
  const double upper = diff.norm(), lower = d - outward;
  if (!(d > kNearTouching * size && upper - lower <= 1e-12 * size)) return false;
  out.method = DistanceMethod::gjk;
  out.distance = upper;
  out.normal = diff / upper;
  out.point_on_core = core;
  out.point_on_segment = on_segment;
  out.t = t;
  out.t_begin = out.t_end = t;
  out.gap = out.distance - wire_radius;
  return true;
}

// Apart: GJK's direction, polished. GJK's closest points themselves are barycentric
// combinations over nearly coincident support points of the smooth body, whose
// weights are ill-conditioned (seen: 1e-9 off the segment); so both candidates are
// rebuilt as genuine pairs (the support point c(n) on the surface, its clamped
// projection on the segment) and the nearer pair is kept.
void take_polished_pair(const PosedSuperquadric& grain, const Segment& seg, const GjkResult& g, double size,
                        SegmentContact& out) {
  const Vector3d &end0 = seg.end0, &end1 = seg.end1, &s = seg.s;
  const double length = seg.length;
  out.method = DistanceMethod::gjk;
  const auto pair_along = [&](const Vector3d& n, Vector3d& core, Vector3d& on_segment, double& t) {
    core = grain.support(n);
    t = length > 0.0 ? std::clamp((core - end0).dot(s) / (length * length), 0.0, 1.0) : 0.0;
    on_segment = end0 + t * s;
    return (on_segment - core).norm();
  };
  const Vector3d n_gjk = (g.point_b - g.point_a) / g.distance;
  // GJK's own body point and its projection on the segment: a second start. On a
  // nearly flat stretch of a blocky body c(n) jumps with n, so c(n_gjk) can be far
  // from GJK's point, which is not.
  const double t_a = length > 0.0 ? std::clamp((g.point_a - end0).dot(s) / (length * length), 0.0, 1.0) : 0.0;
  const Vector3d on_segment_a = end0 + t_a * s;
  const double distance_a = (on_segment_a - g.point_a).norm();
  out.distance = kInf;
  for (const Vector3d& start : {n_gjk, Vector3d((on_segment_a - g.point_a) / distance_a)}) {
    if (!start.allFinite()) continue;
    for (const bool polish : {true, false}) {
      Vector3d n = start, core, on_segment;
      double t = length > 0.0 ? std::clamp(g.weight_b1, 0.0, 1.0) : 0.0;
      if (polish) polish_closest_points(grain, end0, end1, n, t);
      const double d = pair_along(n, core, on_segment, t);
      // the first (polished) pair unless another is nearer beyond rounding: a direction
      // error δ changes the distance by ~δ², below rounding for δ ~ 1e-9, the normal by δ
      if (d < out.distance - 1e-12 * size) {
        out.distance = d;
        out.point_on_core = core;
        out.point_on_segment = on_segment;
        out.t = t;
      }
    }
  }
  // GJK's point itself, which can lie inside the body by its weights' rounding (~1e-9,
  // which would look nearer): only when every pair above missed by more than that
  if (distance_a < out.distance - 1e-7 * size) {
    out.distance = distance_a;
    out.point_on_core = g.point_a;
    out.point_on_segment = on_segment_a;
    out.t = t_a;
  }
  out.normal = (out.point_on_segment - out.point_on_core) / out.distance;
}

// The axis touches or crosses the body (an overlap beyond r_w): n = the body's normal
// direction (∇F) at the segment point q nearest its centre, the distance minus the
// overlap of body and segment along n, h(n) − min over the segment of n·x. A
// separating-axis depth along one axis: at least the penetration depth, equal to it
// where the axis just touches.
void take_overlap_along_centre(const PosedSuperquadric& grain, const Segment& seg, SegmentContact& out) {
  const Vector3d &end0 = seg.end0, &end1 = seg.end1, &s = seg.s;
  const double length = seg.length;
  out.method = DistanceMethod::sat;
  out.t = length > 0.0 ? std::clamp((grain.position() - end0).dot(s) / (length * length), 0.0, 1.0) : 0.0;
  out.point_on_segment = end0 + out.t * s;
  out.normal = grain.normal_at(out.point_on_segment);
  out.point_on_core = grain.support(out.normal);
  out.distance = -(out.normal.dot(out.point_on_core) + segment_support({end0, end1}, -out.normal));
}

}  // namespace

SegmentContact segment_contact(const PosedSuperquadric& grain, const Vector3d& end0, const Vector3d& end1,
                               double wire_radius, double early_exit_distance, const SmoothContactGuess* guess) {
  check_segment_inputs(end0, end1, wire_radius);
  if (!(early_exit_distance >= 0.0))
    throw InvalidArgument("early_exit_distance",
                          "early_exit_distance must be >= 0, got " + format_number(early_exit_distance));
  if (std::isinf(early_exit_distance)) early_exit_distance = 0.0;  // never stop early
  const SegmentSet S{{end0, end1}};
  const Vector3d mid = 0.5 * (end0 + end1);
  const Vector3d s = end1 - end0;
  const double length = s.norm();
  const Segment seg{end0, end1, s, length};
  const double size = std::max({superquadric_bounding_radius(grain.shape()), 0.5 * length,
                                (grain.position() - mid).norm(), std::numeric_limits<double>::min()});
  SegmentContact out;
  if (guess && guess->normal.allFinite() && guess->normal.squaredNorm() > 0.0 && guess->t >= 0.0 &&
      guess->t <= 1.0 && take_certified_guess(grain, seg, size, wire_radius, *guess, out))
    return out;
  const GjkResult g =
      gjk(SuperquadricSet(grain), S, grain.position() - mid, size, early_exit_distance, kGjkSmoothProgress);

  out.gjk_iterations = g.iterations;
  if (g.far) {
    out.method = DistanceMethod::gjk_far;
    out.distance = g.distance;
    const Vector3d d = mid - grain.position();
    out.normal = d.squaredNorm() > 0.0 ? Vector3d(d.normalized()) : Vector3d::UnitX();
    out.point_on_core = grain.position();
    out.point_on_segment = mid;
    out.t = 0.5;
  } else if (!g.touching && g.distance > kNearTouching * size) {
    take_polished_pair(grain, seg, g, size, out);
  } else if (!g.touching && g.distance > 0.0) {
    // nearly touching: the closest points' difference has no reliable direction; a smooth
    // body's closest point has the surface normal there
    out.method = DistanceMethod::gjk_sat;
    out.distance = g.distance;
    out.normal = grain.normal_at(g.point_a);
    out.point_on_core = g.point_a;
    out.point_on_segment = g.point_b;
    out.t = length > 0.0 ? std::clamp(g.weight_b1, 0.0, 1.0) : 0.0;
  } else {
    take_overlap_along_centre(grain, seg, out);
  }
  out.t_begin = out.t_end = out.t;
  out.gap = out.distance - wire_radius;
  return out;
}

}  // namespace wiregrain
