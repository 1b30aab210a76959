// GJK's sub-simplex solver (core/geometry/nearest_simplex.h), which solves only the facets
// the origin lies beyond, against an independent reference: every non-degenerate subset of
// the points, the origin projected on its affine hull in long double (normal equations of
// the barycentric weights), kept when all weights are ≥ 0; the nearest of those. Families:
// random simplices around the origin, small ones far from it, nearly flat tetrahedra and
// triangles, the origin within 1e-13 of a facet's plane, and simplices whose nearest point
// is a shared edge or vertex. For every case: the solver's point is in the hull of the
// points it names (weights ≥ −1e-12, sum 1, v = Σ λ p to 1e-12 L) and not farther from
// the origin than the reference by more than 1e-12 L (L the largest coordinate).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "core/geometry/nearest_simplex.h"

using namespace wiregrain;
using Eigen::Vector3d;

namespace {

using Vector3l = Eigen::Matrix<long double, 3, 1>;

// The nearest point to the origin of the hull of pts (brute force over subsets).
long double reference_distance(const std::vector<Vector3d>& pts) {
  const int k = static_cast<int>(pts.size());
  long double best = INFINITY;
  for (int mask = 1; mask < (1 << k); ++mask) {
    std::vector<Vector3l> p;
    for (int i = 0; i < k; ++i)
      if (mask & (1 << i)) p.push_back(pts[i].cast<long double>());
    const int m = static_cast<int>(p.size());
    if (m == 1) {
      best = std::min(best, p[0].norm());
      continue;
    }
    // x = p0 + D μ, D = [p_i − p0]; minimise |x|²: (DᵀD) μ = −Dᵀ p0
    Eigen::Matrix<long double, 3, Eigen::Dynamic> D(3, m - 1);
    for (int i = 1; i < m; ++i) D.col(i - 1) = p[i] - p[0];
    const Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic> G = D.transpose() * D;
    const Eigen::FullPivLU<Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>> lu(G);
    // a degenerate subset's hull is covered by its smaller subsets
    if (lu.rank() < m - 1 || std::abs(G.determinant()) < 1e-24L * std::pow(G.norm(), m - 1)) continue;
    const Eigen::Matrix<long double, Eigen::Dynamic, 1> mu = lu.solve(-(D.transpose() * p[0]));
    const long double lambda0 = 1.0L - mu.sum();
    if (lambda0 < 0.0L || (mu.array() < 0.0L).any()) continue;
    best = std::min(best, (p[0] + D * mu).norm());
  }
  return best;
}

NearestSimplex solve(const std::vector<Vector3d>& pts) {
  if (pts.size() == 2) return nearest_on_segment(pts.data(), 0, 1);
  if (pts.size() == 3) return nearest_on_triangle(pts.data(), 0, 1, 2);
  return nearest_on_tetrahedron(pts.data());
}

struct Worst {
  double excess = 0.0;  // solver distance − reference, in L
  double hull = 0.0;    // |v − Σ λ p|, in L
  double weight = 0.0;  // most negative weight
  int inside = 0;       // cases with the origin inside (tetrahedra)
};

void check(const std::vector<Vector3d>& pts, Worst& worst) {
  double L = 0.0;
  for (const Vector3d& p : pts) L = std::max(L, p.cwiseAbs().maxCoeff());
  const NearestSimplex r = solve(pts);
  ASSERT_GE(r.n, 1);
  ASSERT_LE(r.n, static_cast<int>(pts.size()));
  Vector3d sum = Vector3d::Zero();
  double total = 0.0;
  for (int j = 0; j < r.n; ++j) {
    sum += r.lambda[j] * pts[r.index[j]];
    total += r.lambda[j];
    worst.weight = std::min(worst.weight, r.lambda[j]);
    ASSERT_GE(r.lambda[j], -1e-12);
  }
  ASSERT_NEAR(total, 1.0, 1e-12);
  if (r.n == 4) {  // the origin inside: v is zero by definition
    ++worst.inside;
    EXPECT_LE(reference_distance(pts), 1e-12L * L);
    return;
  }
  const double hull = (sum - r.v).norm() / L;
  worst.hull = std::max(worst.hull, hull);
  ASSERT_LE(hull, 1e-12);
  const long double ref = reference_distance(pts);
  const double excess = static_cast<double>((static_cast<long double>(r.v.norm()) - ref) / L);
  worst.excess = std::max(worst.excess, excess);
  ASSERT_LE(excess, 1e-12) << "points " << pts.size() << ", reference " << static_cast<double>(ref);
}

Vector3d random_point(std::mt19937_64& gen, double half) {
  std::uniform_real_distribution<double> u(-half, half);
  return Vector3d(u(gen), u(gen), u(gen));
}

void report(const char* family, const Worst& w) {
  std::printf("  %-28s worst excess %.2e L, hull %.2e L, weight %.2e, origin inside %d\n", family, w.excess,
              w.hull, w.weight, w.inside);
}

}  // namespace

TEST(NearestSimplex, RandomSimplicesAroundTheOrigin) {
  std::mt19937_64 gen(11);
  for (int k = 2; k <= 4; ++k) {
    Worst w;
    for (int n = 0; n < 20000; ++n) {
      std::vector<Vector3d> pts;
      for (int i = 0; i < k; ++i) pts.push_back(random_point(gen, 1.0));
      check(pts, w);
    }
    report(k == 2 ? "segments" : k == 3 ? "triangles" : "tetrahedra", w);
    if (k == 4) EXPECT_GT(w.inside, 100);  // the family does reach the inside case
  }
}

TEST(NearestSimplex, SmallSimplicesFarFromTheOrigin) {
  std::mt19937_64 gen(12);
  Worst w;
  for (int n = 0; n < 20000; ++n) {
    const Vector3d centre = random_point(gen, 10.0);
    std::vector<Vector3d> pts;
    for (int i = 0; i < 3 + n % 2; ++i) pts.push_back(centre + random_point(gen, 1e-3));
    check(pts, w);
  }
  report("small, far", w);
}

// Nearly flat: the fourth point within 1e-9 (relative) of the plane of the other three,
// and triangles whose third point is within 1e-9 of the line of the other two.
TEST(NearestSimplex, NearlyFlatSimplices) {
  std::mt19937_64 gen(13);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Worst w;
  for (int n = 0; n < 20000; ++n) {
    std::vector<Vector3d> pts;
    for (int i = 0; i < 3; ++i) pts.push_back(random_point(gen, 1.0));
    const Vector3d normal = (pts[1] - pts[0]).cross(pts[2] - pts[0]).normalized();
    const double a = u(gen), b = u(gen) * (1.0 - a);
    const Vector3d in_plane = pts[0] + a * (pts[1] - pts[0]) + b * (pts[2] - pts[0]) +
                              1.5 * (u(gen) - 0.5) * (pts[1] - pts[2]);
    pts.push_back(in_plane + (u(gen) - 0.5) * 2e-9 * normal);
    check(pts, w);
    std::vector<Vector3d> tri = {pts[0], pts[1], pts[0] + 1.7 * (u(gen) - 0.3) * (pts[1] - pts[0]) +
                                                     1e-9 * random_point(gen, 1.0)};
    check(tri, w);
  }
  report("nearly flat", w);
}

// The origin within 1e-13 of a facet's plane (signs near rounding), and simplices whose
// nearest point is a vertex or an edge shared by two facets.
TEST(NearestSimplex, OriginNearAFacetPlaneOrASharedFeature) {
  std::mt19937_64 gen(14);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Worst w;
  for (int n = 0; n < 20000; ++n) {
    std::vector<Vector3d> pts;
    for (int i = 0; i < 4; ++i) pts.push_back(random_point(gen, 1.0));
    // shift so that a point of the facet (0, 1, 2)'s plane, maybe outside the facet, is at
    // the origin give or take 1e-13
    const double a = 2.0 * u(gen) - 0.5, b = 2.0 * u(gen) - 0.5;
    const Vector3d on_plane = pts[0] + a * (pts[1] - pts[0]) + b * (pts[2] - pts[0]);
    const Vector3d shift = on_plane + 1e-13 * random_point(gen, 1.0);
    for (Vector3d& p : pts) p -= shift;
    check(pts, w);
    std::vector<Vector3d> tri(pts.begin(), pts.begin() + 3);
    check(tri, w);
    // nearest point on the edge (0, 1): the origin moved off that edge along the bisector
    // of the outward normals of its two facets
    std::vector<Vector3d> q;
    for (int i = 0; i < 4; ++i) q.push_back(random_point(gen, 1.0));
    const Vector3d centroid = 0.25 * (q[0] + q[1] + q[2] + q[3]);
    const Vector3d edge_point = q[0] + u(gen) * (q[1] - q[0]);
    const Vector3d away = (edge_point - centroid).normalized();
    const Vector3d e = (q[1] - q[0]).normalized();
    const Vector3d out = (away - away.dot(e) * e).normalized();
    const Vector3d origin = edge_point + (1e-12 + u(gen)) * out;
    for (Vector3d& p : q) p -= origin;
    check(q, w);
  }
  report("origin near a plane / edge", w);
}
