// The point of a simplex (1 to 4 points of a Minkowski difference) nearest to the origin:
// GJK's sub-simplex problem, by signed volumes (Montanari, Petrinic & Barbieri 2017).
// The barycentric coordinates of the origin's projection on the simplex's affine hull are
// ratios of signed lengths/areas/volumes, computed in the coordinate plane (line) where the
// simplex's projection is largest; if they all have the sign of the total, the projection
// is inside. Otherwise the origin lies beyond some facets (the sub-simplices opposite a
// vertex): the nearest point of the simplex lies on one of those (the normal cone argument:
// at the nearest point x*, −x* is a non-negative combination of the outward normals of the
// facets through x*, so the origin is strictly beyond at least one of them), and only
// those are solved, recursively; the nearest wins.
//
// Rounding: a facet is passed over only when the origin is beyond its plane by more than a
// bound on the rounding error of its signed volume (64 ε L^d, L the largest coordinate, d
// the dimension of the simplex); with the total's sign not that certain (a flat simplex)
// every facet is solved. So a misclassified sign cannot lose the minimum (core test
// NearestSimplex.*: against a brute-force enumeration of all sub-simplices).
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>

namespace wiregrain {

struct NearestSimplex {
  int n = 0;                          // points in the smallest sub-simplex holding v
  std::array<int, 4> index{};         // into the input points
  std::array<double, 4> lambda{};     // barycentric weights, sum 1
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
};

namespace nearest_simplex_detail {

inline bool same_sign(double a, double b) { return (a > 0.0 && b > 0.0) || (a < 0.0 && b < 0.0); }

// Whether the facet of signed volume c (total `total`) may hold the nearest point: the
// origin is not beyond its plane by more than the rounding bound.
inline bool may_hold_nearest(double total, double c, double bound) {
  return !same_sign(total, c) || std::abs(c) <= bound;
}

inline NearestSimplex single(const Eigen::Vector3d* s, int i) {
  NearestSimplex r;
  r.n = 1;
  r.index[0] = i;
  r.lambda[0] = 1.0;
  r.v = s[i];
  return r;
}

inline const NearestSimplex& nearer(const NearestSimplex& a, const NearestSimplex& b) {
  return b.v.squaredNorm() < a.v.squaredNorm() ? b : a;
}

}  // namespace nearest_simplex_detail

inline NearestSimplex nearest_on_segment(const Eigen::Vector3d* s, int i0, int i1) {
  using namespace nearest_simplex_detail;
  const Eigen::Vector3d& a = s[i0];
  const Eigen::Vector3d& b = s[i1];
  const Eigen::Vector3d t = b - a;
  const double tt = t.squaredNorm();
  if (tt > 0.0) {
    // projection of the origin on the line: p0 = a − (a·t / t·t) t
    const Eigen::Vector3d p0 = a - (a.dot(t) / tt) * t;
    int I = 0;
    t.cwiseAbs().maxCoeff(&I);
    const double mu = a[I] - b[I];
    const double c_a = p0[I] - b[I];  // weight of a times mu
    const double c_b = a[I] - p0[I];  // weight of b times mu
    if (same_sign(mu, c_a) && same_sign(mu, c_b)) {
      NearestSimplex r;
      r.n = 2;
      r.index = {i0, i1, 0, 0};
      r.lambda = {c_a / mu, c_b / mu, 0.0, 0.0};
      r.v = r.lambda[0] * a + r.lambda[1] * b;
      return r;
    }
  }
  return nearer(single(s, i0), single(s, i1));
}

inline NearestSimplex nearest_on_triangle(const Eigen::Vector3d* s, int i0, int i1, int i2) {
  using namespace nearest_simplex_detail;
  const Eigen::Vector3d& a = s[i0];
  const Eigen::Vector3d& b = s[i1];
  const Eigen::Vector3d& c = s[i2];
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double nn = n.squaredNorm();
  std::array<bool, 3> solve = {true, true, true};  // the edge opposite vertex m
  if (nn > 0.0) {
    const Eigen::Vector3d p0 = (a.dot(n) / nn) * n;  // origin projected on the plane
    int J = 0;
    n.cwiseAbs().maxCoeff(&J);
    const int k = (J + 1) % 3, l = (J + 2) % 3;  // signed area in (k, l) has the sign of n_J
    const auto area = [k, l](const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& r) {
      return (q[k] - p[k]) * (r[l] - p[l]) - (r[k] - p[k]) * (q[l] - p[l]);
    };
    const double mu = area(a, b, c);
    const std::array<double, 3> C = {area(p0, b, c), area(a, p0, c), area(a, b, p0)};
    if (same_sign(mu, C[0]) && same_sign(mu, C[1]) && same_sign(mu, C[2])) {
      NearestSimplex r;
      r.n = 3;
      r.index = {i0, i1, i2, 0};
      r.lambda = {C[0] / mu, C[1] / mu, C[2] / mu, 0.0};
      r.v = r.lambda[0] * a + r.lambda[1] * b + r.lambda[2] * c;
      return r;
    }
    double L = 0.0;
    for (const Eigen::Vector3d* p : {&a, &b, &c, &p0}) L = std::max({L, std::abs((*p)[k]), std::abs((*p)[l])});
    const double bound = 64.0 * DBL_EPSILON * L * L;
    if (std::abs(mu) > bound)
      for (int m = 0; m < 3; ++m) solve[m] = may_hold_nearest(mu, C[m], bound);
  }
  NearestSimplex best;
  bool found = false;
  const auto consider = [&](bool wanted, int p, int q) {
    if (!wanted) return;
    const NearestSimplex r = nearest_on_segment(s, p, q);
    best = found ? nearer(best, r) : r;
    found = true;
  };
  consider(solve[0], i1, i2);
  consider(solve[1], i0, i2);
  consider(solve[2], i0, i1);
  return best;
}

inline NearestSimplex nearest_on_tetrahedron(const Eigen::Vector3d* s) {
  using namespace nearest_simplex_detail;
  const Eigen::Vector3d &a = s[0], &b = s[1], &c = s[2], &d = s[3];
  // C_j = signed volume of the tetrahedron with vertex j replaced by the origin:
  // vol(0,b,c,d) = b·(c×d), vol(a,0,c,d) = −a·(c×d), vol(a,b,0,d) = a·(b×d),
  // vol(a,b,c,0) = −a·(b×c); their sum is vol(a,b,c,d).
  const Eigen::Vector3d cxd = c.cross(d);
  const std::array<double, 4> C = {b.dot(cxd), -a.dot(cxd), a.dot(b.cross(d)), -a.dot(b.cross(c))};
  const double det = C[0] + C[1] + C[2] + C[3];
  if (same_sign(det, C[0]) && same_sign(det, C[1]) && same_sign(det, C[2]) && same_sign(det, C[3])) {
    NearestSimplex r;
    r.n = 4;
    r.index = {0, 1, 2, 3};
    for (int j = 0; j < 4; ++j) r.lambda[j] = C[j] / det;
    r.v = Eigen::Vector3d::Zero();  // the origin is inside
    return r;
  }
  const double L = std::max({a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff(), c.cwiseAbs().maxCoeff(),
                             d.cwiseAbs().maxCoeff()});
  const double bound = 64.0 * DBL_EPSILON * L * L * L;
  std::array<bool, 4> solve = {true, true, true, true};  // the facet opposite vertex j
  if (std::abs(det) > bound)
    for (int j = 0; j < 4; ++j) solve[j] = may_hold_nearest(det, C[j], bound);
  NearestSimplex best;
  bool found = false;
  const auto consider = [&](bool wanted, int p, int q, int r) {
    if (!wanted) return;
    const NearestSimplex t = nearest_on_triangle(s, p, q, r);
    best = found ? nearer(best, t) : t;
    found = true;
  };
  consider(solve[0], 1, 2, 3);
  consider(solve[1], 0, 2, 3);
  consider(solve[2], 0, 1, 3);
  consider(solve[3], 0, 1, 2);
  return best;
}

}  // namespace wiregrain
