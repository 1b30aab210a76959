// Signed distance of two posed cores: GJK apart, the SAT overlapping or nearly touching.
// See core_distance.h and docs/design.md, "Contact geometry".
#include "core/geometry/core_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/errors.h"
#include "core/common/validation.h"
#include "core/geometry/sat.h"

namespace wiregrain {

using Eigen::Vector3d;

double lowest_core_point(const ConvexShape& shape, const Vector3d& position, const Eigen::Quaterniond& orientation,
                         const Vector3d& n) {
  const Vector3d body_n = orientation.normalized().conjugate() * n;
  double lowest = std::numeric_limits<double>::infinity();
  for (const Vector3d& v : shape.vertices()) lowest = std::min(lowest, body_n.dot(v));
  return lowest + n.dot(position);
}

double height_above_faces(const PosedShape& shape, const Vector3d& x) {
  const Vector3d body = shape.rotation().transpose() * (x - shape.position());
  double height = -std::numeric_limits<double>::infinity();
  for (const auto& face : shape.shape().faces()) height = std::max(height, face.normal.dot(body) - face.offset);
  return height;
}

CoreDistance core_distance(const PosedShape& a, const PosedShape& b,
                           double early_exit_distance, GjkSimplex* simplex) {
  if (!(early_exit_distance >= 0.0))
    throw InvalidArgument("early_exit_distance",
                          "early_exit_distance must be >= 0, got " + format_number(early_exit_distance));
  if (std::isinf(early_exit_distance)) early_exit_distance = 0.0;  // never stop early
  const double size = configuration_size(a, b.position(), b.core_radius());
  const GjkResult g = gjk(PolytopeSet{&a}, PolytopeSet{&b}, a.position() - b.position(), size,
                          early_exit_distance, kGjkProgress, simplex);
  CoreDistance out;
  out.gjk_iterations = g.iterations;
  if (g.far) {
    out.method = DistanceMethod::gjk_far;
    out.distance = g.distance;
    const Vector3d d = b.position() - a.position();
    out.normal = d.squaredNorm() > 0.0 ? Vector3d(d.normalized()) : Vector3d::UnitX();
    out.point_a = a.position();
    out.point_b = b.position();
    return out;
  }
  if (!g.touching && g.distance > kNearTouching * size) {
    out.method = DistanceMethod::gjk;
    out.distance = g.distance;
    out.normal = (g.point_b - g.point_a) / g.distance;
    out.point_a = g.point_a;
    out.point_b = g.point_b;
    return out;
  }
  const SatAxis axis = sat_polytopes(a, b);
  out.normal = axis.normal;
  if (!g.touching && g.distance > 0.0) {
    // Disjoint but nearly touching: exact closest points. The normal is the direction
    // of largest separation: the SAT axis (exact when the contact involves a face or two
    // crossing edges), unless the GJK direction separates more (vertex–vertex,
    // vertex–edge, parallel edges: their normal is no SAT candidate).
    out.distance = g.distance;
    out.point_a = g.point_a;
    out.point_b = g.point_b;
    const Vector3d n_gjk = (g.point_b - g.point_a) / g.distance;
    const double separation_gjk = -(support_value(a, n_gjk) + support_value(b, -n_gjk));
    if (separation_gjk > -axis.depth + kGjkProgress * size) {
      out.method = DistanceMethod::gjk;
      out.normal = n_gjk;
    } else {
      out.method = DistanceMethod::gjk_sat;
    }
    return out;
  }
  // Overlapping, or touching with coincident closest points (GJK distance exactly 0: no
  // direction from the points; seen on stacked cubes tilted by 1e-13): the SAT.
  out.method = DistanceMethod::sat;
  out.distance = -axis.depth;
  const Vector3d& n = axis.normal;
  out.point_a = a.vertices()[a.support_vertex(n)];
  out.point_b = b.vertices()[b.support_vertex(-n)];
  return out;
}

}  // namespace wiregrain
