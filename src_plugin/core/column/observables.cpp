#include "core/column/observables.h"

#include <algorithm>
#include <cmath>

#include "core/common/errors.h"
#include "core/common/validation.h"

namespace wiregrain {

double grain_top(const PosedShape& grain) {
  const Eigen::Vector3d& top = grain.vertices()[grain.support_vertex(Eigen::Vector3d::UnitZ())];
  return top.z() + grain.sweep_radius();
}

double quantile(std::vector<double> values, double q) {
  if (values.empty()) throw InvalidArgument("values", "no values to take a quantile of");
  if (!(q >= 0.0 && q <= 1.0)) throw InvalidArgument("quantile", "quantile must be in [0, 1], got " + format_number(q));
  std::sort(values.begin(), values.end());
  const double position = q * double(values.size() - 1);
  const std::size_t below = static_cast<std::size_t>(std::floor(position));
  if (below + 1 >= values.size()) return values.back();
  const double weight = position - double(below);
  return values[below] + weight * (values[below + 1] - values[below]);
}

double mean_axis_distance(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector2d& axis) {
  if (points.empty()) throw InvalidArgument("points", "no points to measure from the axis");
  double sum = 0.0;
  for (const Eigen::Vector3d& p : points) sum += std::hypot(p.x() - axis.x(), p.y() - axis.y());
  return sum / double(points.size());
}

Retention retention(const std::vector<Eigen::Vector3d>& grain_centres, const Eigen::Vector2d& axis,
                    double radius) {
  Retention r;
  r.radius = radius;
  r.total = static_cast<long>(grain_centres.size());
  for (const Eigen::Vector3d& c : grain_centres)
    if (std::hypot(c.x() - axis.x(), c.y() - axis.y()) < radius) r.inside++;
  r.fraction = r.total > 0 ? double(r.inside) / double(r.total) : 0.0;
  return r;
}

}  // namespace wiregrain
