// Clipping, hull and reduction of convex polygons in the contact plane. See
// polygon_clipping.h.
#include "core/geometry/polygon_clipping.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace wiregrain {

using Eigen::Vector2d;

PlanePolygon clip_polygon(const PlanePolygon& subject, const PlanePolygon& clip, double tol) {
  PlanePolygon out = subject;
  const std::size_t m = clip.size();
  for (std::size_t k = 0; k < m && !out.empty(); ++k) {
    const Vector2d& c0 = clip[k];
    const Vector2d edge = clip[(k + 1) % m] - c0;
    const double length = edge.norm();
    if (!(length > 0.0)) continue;
    const auto side = [&](const Vector2d& p) { return cross2(edge, p - c0) / length; };
    const PlanePolygon in = out;
    out.clear();
    const std::size_t q = in.size();
    for (std::size_t i = 0; i < q; ++i) {
      const Vector2d& S = in[(i + q - 1) % q];
      const Vector2d& E = in[i];
      const double fs = side(S), fe = side(E);
      const bool s_in = fs >= -tol, e_in = fe >= -tol;
      if (e_in != s_in) {
        const double t = std::clamp(fs / (fs - fe), 0.0, 1.0);
        out.push_back(S + t * (E - S));
      }
      if (e_in) out.push_back(E);
    }
  }
  return out;
}

bool clip_segment(const Vector2d& p0, const Vector2d& p1, const PlanePolygon& poly, double tol, double& lo, double& hi) {
  lo = 0.0;
  hi = 1.0;
  const std::size_t m = poly.size();
  for (std::size_t k = 0; k < m; ++k) {
    const Vector2d& c0 = poly[k];
    const Vector2d edge = poly[(k + 1) % m] - c0;
    const double length = edge.norm();
    if (!(length > 0.0)) continue;
    const double f0 = cross2(edge, p0 - c0) / length, f1 = cross2(edge, p1 - c0) / length;
    if (f0 < -tol && f1 < -tol) return false;
    if (f0 >= -tol && f1 >= -tol) continue;
    const double s = std::clamp(f0 / (f0 - f1), 0.0, 1.0);  // where f crosses 0
    if (f0 < -tol)
      lo = std::max(lo, s);
    else
      hi = std::min(hi, s);
  }
  return lo <= hi;
}

PlanePolygon convex_hull_2d(PlanePolygon points, double tol) {
  std::sort(points.begin(), points.end(), [](const Vector2d& a, const Vector2d& b) {
    return a.x() != b.x() ? a.x() < b.x() : a.y() < b.y();
  });
  if (points.size() < 2) return points;
  // b is a corner of the counter-clockwise chain a → b → c only if it lies more than tol
  // to the right of the line a → c (a strict left turn at b)
  const auto not_corner = [tol](const Vector2d& a, const Vector2d& b, const Vector2d& c) {
    const double length = (c - a).norm();
    return length <= tol || cross2(b - a, c - a) <= tol * length;
  };
  // both chains, room for twice the points
  boost::container::small_vector<Vector2d, 32> hull(2 * points.size());
  std::size_t k = 0;
  for (const auto& p : points) {  // lower chain
    while (k >= 2 && not_corner(hull[k - 2], hull[k - 1], p)) --k;
    if (k == 1 && (p - hull[0]).norm() <= tol) continue;
    hull[k++] = p;
  }
  const std::size_t lower = k + 1;
  for (std::size_t i = points.size() - 1; i-- > 0;) {  // upper chain
    const Vector2d& p = points[i];
    while (k >= lower && not_corner(hull[k - 2], hull[k - 1], p)) --k;
    hull[k++] = p;
  }
  hull.resize(k - 1);  // the last point repeats the first
  // a chain that came back on itself: merge coincident ends
  while (hull.size() > 1 && (hull.back() - hull.front()).norm() <= tol) hull.pop_back();
  if (hull.size() == 2 && (hull[1] - hull[0]).norm() <= tol) hull.pop_back();
  return PlanePolygon(hull.begin(), hull.end());
}

PolygonIndices reduce_polygon(const PlanePolygon& poly, const PolygonValues& gaps, int max_points) {
  PolygonIndices kept(poly.size());
  for (std::size_t i = 0; i < poly.size(); ++i) kept[i] = static_cast<int>(i);
  if (max_points <= 0 || static_cast<int>(poly.size()) <= max_points) return kept;
  const int deepest =
      static_cast<int>(std::min_element(gaps.begin(), gaps.end()) - gaps.begin());
  while (static_cast<int>(kept.size()) > max_points) {
    const std::size_t m = kept.size();
    std::size_t victim = m;
    double least = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < m; ++i) {
      if (kept[i] == deepest) continue;
      const Vector2d& a = poly[kept[(i + m - 1) % m]];
      const Vector2d& b = poly[kept[i]];
      const Vector2d& c = poly[kept[(i + 1) % m]];
      double area = std::abs(cross2(b - a, c - a));
      if (m <= 2) area = (b - poly[deepest]).norm();  // keep the farthest point
      if (area < least) {
        least = area;
        victim = i;
      }
    }
    if (victim == m) break;
    kept.erase(kept.begin() + static_cast<long>(victim));
  }
  return kept;
}

}  // namespace wiregrain
