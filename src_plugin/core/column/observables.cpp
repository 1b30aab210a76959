#include "core/column/observables.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

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

namespace {

// A double's place in the order of the doubles as an unsigned integer: the sign bit
// flipped for x ≥ +0, every bit flipped for x ≤ −0 (IEEE 754 bit patterns of one sign
// are ordered as integers). from_order_key inverts it.
std::uint64_t order_key(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  constexpr std::uint64_t kSign = std::uint64_t(1) << 63;
  return (bits & kSign) ? ~bits : (bits | kSign);
}

double from_order_key(std::uint64_t key) {
  constexpr std::uint64_t kSign = std::uint64_t(1) << 63;
  const std::uint64_t bits = (key & kSign) ? (key & ~kSign) : ~key;
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

// The k-th smallest value (0-based): the smallest key whose value has at least k + 1
// values at or below it, which is the key of a value present.
double order_statistic(long k, double lowest, double highest, const std::function<long(double)>& count_at_most) {
  std::uint64_t below = order_key(lowest), above = order_key(highest);
  while (below < above) {
    const std::uint64_t middle = below + (above - below) / 2;
    if (count_at_most(from_order_key(middle)) >= k + 1)
      above = middle;
    else
      below = middle + 1;
  }
  return from_order_key(above);
}

}  // namespace

double quantile_of_parts(long n, double lowest, double highest, double q,
                         const std::function<long(double)>& count_at_most) {
  if (n < 1) throw InvalidArgument("n", "no values to take a quantile of");
  if (!(q >= 0.0 && q <= 1.0)) throw InvalidArgument("quantile", "quantile must be in [0, 1], got " + format_number(q));
  if (!(std::isfinite(lowest) && std::isfinite(highest) && lowest <= highest))
    throw InvalidArgument("lowest", "the extremes must be finite with lowest <= highest, got " + format_number(lowest) +
                                        " and " + format_number(highest));
  // as quantile(): position q (n − 1), between order statistics `below` and below + 1
  const double position = q * double(n - 1);
  const long below = static_cast<long>(std::floor(position));
  if (below + 1 >= n) return highest;
  const double weight = position - double(below);
  const double a = order_statistic(below, lowest, highest, count_at_most);
  const double b = order_statistic(below + 1, lowest, highest, count_at_most);
  return a + weight * (b - a);
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
