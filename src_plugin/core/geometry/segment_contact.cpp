// Contact of a posed core and a wire segment: GJK apart, the SAT overlapping, the closest
// feature for the interval of a parallel segment. See segment_contact.h and
// docs/design.md, "Contact geometry".
#include "core/geometry/segment_contact.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/common/errors.h"
#include "core/common/validation.h"
#include "core/geometry/contact_features.h"
#include "core/geometry/contact_frame.h"
#include "core/geometry/polygon_clipping.h"
#include "core/geometry/sat.h"
#include "core/geometry/segment_distance.h"

namespace wiregrain {

namespace {

using Eigen::Vector3d;

// The wire segment of a query: its ends, s = end1 − end0 and length = |s|.
struct Segment {
  const Vector3d& end0;
  const Vector3d& end1;
  Vector3d s;
  double length;
};

// GJK stopped early (method gjk_far): its lower bound, the normal along the centres,
// t = ½ at the segment's middle `mid`.
void take_far(const PosedShape& grain, const GjkResult& g, const Vector3d& mid, double wire_radius,
              SegmentContact& out) {
  out.method = DistanceMethod::gjk_far;
  out.distance = g.distance;
  out.gap = g.distance - (grain.sweep_radius() + wire_radius);
  const Vector3d d = mid - grain.position();
  out.normal = d.squaredNorm() > 0.0 ? Vector3d(d.normalized()) : Vector3d::UnitX();
  out.point_on_core = grain.position();
  out.point_on_segment = mid;
  out.t = out.t_begin = out.t_end = 0.5;
}

// The signed distance (out.distance, out.method) and the returned normal from the grain
// to the segment: GJK's direction apart, the SAT's when the closest points coincide, and
// when nearly touching the direction of largest separation (as core_distance).
Vector3d distance_and_normal(const PosedShape& grain, const std::array<Vector3d, 2>& end, const GjkResult& g,
                             double size, SegmentContact& out) {
  Vector3d n;
  if (!g.touching && g.distance > kNearTouching * size) {
    out.method = DistanceMethod::gjk;
    out.distance = g.distance;
    n = (g.point_b - g.point_a) / g.distance;
  } else {
    const SatAxis axis = sat_segment(grain, end, size);
    n = axis.normal;
    if (g.touching || !(g.distance > 0.0)) {  // coincident closest points: no direction
      out.method = DistanceMethod::sat;
      out.distance = -axis.depth;
    } else {
      // nearly touching: the direction of largest separation (see core_distance)
      out.method = DistanceMethod::gjk_sat;
      out.distance = g.distance;
      const Vector3d n_gjk = (g.point_b - g.point_a) / g.distance;
      const double separation_gjk =
          -(support_value(grain, n_gjk) + segment_support(end, -n_gjk));
      if (separation_gjk > -axis.depth + kGjkProgress * size) {
        out.method = DistanceMethod::gjk;
        n = n_gjk;
      }
    }
  }
  return n;
}

// GJK's closest points (t = the barycentric weight of end1).
void take_gjk_points(const GjkResult& g, double length, SegmentContact& out) {
  out.point_on_core = g.point_a;
  out.point_on_segment = g.point_b;
  out.t = out.t_begin = out.t_end = length > 0.0 ? std::clamp(g.weight_b1, 0.0, 1.0) : 0.0;
}

// The SAT's closest points: the grain's vertex and the segment point nearest its line
// along n; for an edge ⟂ n (the segment ⟂ n within the tolerance) the closest points of
// edge and segment; otherwise the deepest end of the segment and its projection along n
// on the grain's feature.
void take_sat_points(const PosedShape& grain, const ContactFeature& feature, const Segment& seg,
                     const Vector3d& n, double sin_tol, SegmentContact& out) {
  const Vector3d &end0 = seg.end0, &end1 = seg.end1, &s = seg.s;
  const double length = seg.length;
  const auto param_of = [&](const Vector3d& x) {
    return length > 0.0 ? std::clamp((x - end0).dot(s) / (length * length), 0.0, 1.0) : 0.0;
  };
  if (feature.kind == FeatureKind::vertex) {
    const Vector3d& v = grain.vertices()[feature.index];
    out.point_on_core = v;
    out.point_on_segment = end0 + segment_param_nearest_line(end0, end1, v, n) * s;
  } else if (feature.kind == FeatureKind::edge && std::abs(s.dot(n)) <= sin_tol * length) {
    const auto& e = grain.shape().edges()[feature.index];
    const Vector3d &e0 = grain.vertices()[e[0]], &e1 = grain.vertices()[e[1]];
    const SegmentClosestPoints closest = segment_closest_points(e0, e1, end0, end1);  // segment_distance.h
    out.point_on_core = e0 + closest.s * (e1 - e0);
    out.point_on_segment = end0 + closest.t * s;
  } else {
    out.point_on_segment = n.dot(end1) < n.dot(end0) ? end1 : end0;
    out.point_on_core = feature_point_on_line(grain, feature, out.point_on_segment, n);
  }
  out.t = out.t_begin = out.t_end = param_of(out.point_on_segment);
}

// A segment parallel to the contact face or edge (within sin_tol): the closest points
// form an interval [t_begin, t_end], the face's polygon clipping the segment or the
// overlap with a parallel edge (tol: the clipping tolerance); t its middle. Nothing
// changes when the interval is empty.
void take_parallel_interval(const PosedShape& grain, const ContactFeature& feature, const Segment& seg,
                            const Vector3d& n, double sin_tol, double tol, SegmentContact& out) {
  const Vector3d &end0 = seg.end0, &end1 = seg.end1, &s = seg.s;
  const ContactFrame frame(out.point_on_core, n);
  double lo = 0.0, hi = 1.0;
  bool found = false;
  if (feature.kind == FeatureKind::face) {
    found = clip_segment(frame.project(end0), frame.project(end1),
                         face_polygon(grain, feature.index, frame), tol, lo, hi);
  } else {
    const auto& e = grain.shape().edges()[feature.index];
    const Vector3d &e0 = grain.vertices()[e[0]], &e1 = grain.vertices()[e[1]];
    const Vector3d de = e1 - e0;
    if (de.normalized().cross(s / seg.length).norm() <= sin_tol) {
      Vector3d dir = s - n.dot(s) * n;
      dir.normalize();
      const double a0 = dir.dot(end0), a1 = dir.dot(end1);  // a1 > a0
      const double b_lo = std::min(dir.dot(e0), dir.dot(e1));
      const double b_hi = std::max(dir.dot(e0), dir.dot(e1));
      lo = std::clamp((b_lo - a0) / (a1 - a0), 0.0, 1.0);
      hi = std::clamp((b_hi - a0) / (a1 - a0), 0.0, 1.0);
      found = b_hi >= a0 - tol && b_lo <= a1 + tol && lo <= hi;
    }
  }
  if (found) {
    out.t_begin = lo;
    out.t_end = hi;
    out.t = 0.5 * (lo + hi);
    out.point_on_segment = end0 + out.t * s;
    out.point_on_core = feature_point_on_line(grain, feature, out.point_on_segment, n);
  }
}

}  // namespace

void check_segment_inputs(const Vector3d& end0, const Vector3d& end1, double wire_radius) {
  require_finite_vector("end0", end0);
  require_finite_vector("end1", end1);
  if (!(wire_radius >= 0.0) || !std::isfinite(wire_radius))
    throw InvalidArgument("wire_radius",
                          "wire_radius must be >= 0 and finite, got " + format_number(wire_radius));
}

SegmentContact segment_contact(const PosedShape& grain, const Vector3d& end0,
                               const Vector3d& end1, double wire_radius,
                               const ContactOptions& options, GjkSimplex* simplex) {
  check_segment_inputs(end0, end1, wire_radius);
  check_contact_options(options);

  const SegmentSet S{{end0, end1}};
  const Vector3d mid = 0.5 * (end0 + end1);
  const Vector3d s = end1 - end0;
  const double length = s.norm();
  const Segment seg{end0, end1, s, length};
  const double size = configuration_size(grain, mid, 0.5 * length);
  // the early exit on the cores' distance (0 to gjk: never)
  const double exit_distance = std::isinf(options.exit_gap) ? 0.0 : options.exit_gap + grain.sweep_radius() + wire_radius;
  const GjkResult g = gjk(PolytopeSet{&grain}, S, grain.position() - mid, size, exit_distance, kGjkProgress, simplex);

  SegmentContact out;
  out.gjk_iterations = g.iterations;
  if (g.far) {
    take_far(grain, g, mid, wire_radius, out);
    return out;
  }
  const Vector3d n = distance_and_normal(grain, S.end, g, size, out);
  out.normal = n;
  out.gap = out.distance - (grain.sweep_radius() + wire_radius);
  if (out.method == DistanceMethod::gjk && out.gap > options.feature_gap_limit) {
    take_gjk_points(g, length, out);
    return out;
  }

  // Single closest points: GJK's (t = the barycentric weight of end1), or for the SAT
  // the deepest end of the segment and its projection along n on the grain's feature
  // (for an edge axis the segment is ⟂ n: the closest points of edge and segment).
  // The feature is looked up only where it is used, the SAT's points and a segment ⟂ n
  // within the tolerance (the interval below): a segment touching with one of its ends
  // needs none.
  const double sin_tol = std::sin(options.angle_tolerance);
  const bool across = length > 0.0 && std::abs(s.dot(n)) <= sin_tol * length;
  if (out.method != DistanceMethod::sat && !across) {
    take_gjk_points(g, length, out);
    return out;
  }
  const ContactFeature feature = select_feature(grain, n, std::cos(options.angle_tolerance),
                                                sin_tol, kMergeTolerance * size);
  if (out.method == DistanceMethod::sat)
    take_sat_points(grain, feature, seg, n, sin_tol, out);
  else
    take_gjk_points(g, length, out);

  // A segment parallel to the contact face or edge: the closest points form an interval.
  if (across && feature.kind != FeatureKind::vertex)
    take_parallel_interval(grain, feature, seg, n, sin_tol, kMergeTolerance * size, out);
  return out;
}

}  // namespace wiregrain
