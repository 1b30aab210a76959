// GJK (Gilbert, Johnson & Keerthi, IEEE J. Robot. Autom. 4 (1988) 193): the distance of
// two convex sets A and B as the distance of their Minkowski difference A − B from the
// origin, from the support points of A and B alone.
//
// Each iteration adds the support point p = s_A(−v) − s_B(v) of the difference along the
// current nearest point v and keeps the sub-simplex nearest to the origin
// (nearest_simplex.h: the signed-volumes solver of Montanari, Petrinic & Barbieri, ACM
// Trans. Graph. 36 (2017) 32, made exhaustive). v·p/|v| is a lower bound of the distance
// and |v| an upper bound. It stops when
//   - |v| < kGjkOrigin × size: the origin is reached, the sets touch or overlap;
//   - the support point repeats a simplex vertex: v is optimal (exact for polytopes);
//   - |v|² − v·p ≤ progress × max(|v|², |v| size): the bound gains less than `progress`
//     (1e-15 for polytopes; a smooth body never repeats a support point);
//   - the lower bound exceeds early_exit_distance (if > 0): the caller needs no more;
//   - the new simplex is no nearer (rounding), or after kGjkMaxIterations.
// The sets are seen through indices: a set has count() (indices a warm simplex may name;
// 0: none), support(d) (an index maximising d·x) and point(i). docs/design.md,
// "Contact geometry".
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>

#include "core/geometry/nearest_simplex.h"
#include "core/geometry/posed_shape.h"

namespace wiregrain {

// GJK's simplex of a pair: the support indices of its 1–4 points of the Minkowski
// difference A − B (a: A's vertex, b: B's vertex or the segment's end 0/1). A query given
// one starts GJK from it (reduced to its nearest sub-simplex first) instead of from the
// support along the centres, and leaves its own last simplex there (the tetrahedron when
// the cores overlap): the warm start of a pair queried again a step later, whose closest
// features rarely change. GJK converges to the closest point from any simplex of the
// difference (Gilbert, Johnson & Keerthi 1988) with the same stopping rules, so the
// answer is the same to GJK's tolerance, not to the bit: where the closest point lies on
// a face of the difference with more than three vertices (face–face, edge–edge) the
// simplex that holds it depends on the path. size 0 (or indices out of range): a cold
// start, the same result to the bit as without a simplex. docs/design.md, "Contact geometry".
struct GjkSimplex {
  std::array<int, 4> a{}, b{};
  int size = 0;
};

// GJK: the origin counts as reached (cores touch or overlap) when |v| is below this
// times the size; the iteration stops when the support point improves the bound by less
// than this (relative to |v| and to the size).
constexpr double kGjkOrigin = 1e-14;
constexpr double kGjkProgress = 1e-15;
constexpr int kGjkMaxIterations = 200;

// A posed core seen by GJK: its world vertices.
struct PolytopeSet {
  const PosedShape* shape;
  int count() const { return static_cast<int>(shape->vertices().size()); }
  int support(const Eigen::Vector3d& d) const { return shape->support_vertex(d); }
  const Eigen::Vector3d& point(int i) const { return shape->vertices()[i]; }
};

// A segment (or, with equal ends, a point) seen by GJK: its two ends.
struct SegmentSet {
  std::array<Eigen::Vector3d, 2> end;
  int count() const { return 2; }
  int support(const Eigen::Vector3d& d) const { return d.dot(end[1]) > d.dot(end[0]) ? 1 : 0; }
  const Eigen::Vector3d& point(int i) const { return end[i]; }
};

struct GjkResult {
  bool touching = false;   // |v| reached ~0: the cores touch or overlap
  bool far = false;        // stopped by the early-exit bound
  double distance = 0.0;   // |v| (far: the lower bound)
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero(), point_b = Eigen::Vector3d::Zero();
  double weight_b1 = 0.0;  // total barycentric weight of B's support index 1 (segments)
  int iterations = 0;
};

// A warm simplex a set can take: 1–4 distinct index pairs within the sets' counts.
template <class SetA, class SetB>
bool usable_simplex(const GjkSimplex& s, const SetA& A, const SetB& B) {
  if (s.size < 1 || s.size > 4) return false;
  for (int j = 0; j < s.size; j++) {
    if (s.a[j] < 0 || s.a[j] >= A.count() || s.b[j] < 0 || s.b[j] >= B.count()) return false;
    for (int k = 0; k < j; k++)
      if (s.a[k] == s.a[j] && s.b[k] == s.b[j]) return false;
  }
  return true;
}

namespace gjk_detail {

// GJK's current simplex: its points w_j = a(ia_j) − b(ib_j), j < n, their barycentric
// weights λ_j and the point v = Σ λ_j w_j of the simplex nearest to the origin.
struct Simplex {
  std::array<Eigen::Vector3d, 4> w;
  std::array<int, 4> ia{}, ib{};
  std::array<double, 4> lambda{};
  int n = 0;
  Eigen::Vector3d v;

  // Becomes the sub-simplex r of `points` (whose support indices are a, b); the arrays
  // must not be this simplex's own (pass copies).
  void reduce_to(const NearestSimplex& r, const std::array<Eigen::Vector3d, 4>& points,
                 const std::array<int, 4>& a, const std::array<int, 4>& b) {
    for (int j = 0; j < r.n; ++j) {
      w[j] = points[r.index[j]];
      ia[j] = a[r.index[j]];
      ib[j] = b[r.index[j]];
      lambda[j] = r.lambda[j];
    }
    n = r.n;
    v = r.v;
  }
};

// The sub-simplex of points[0..m) nearest to the origin, m in 1..4.
inline NearestSimplex nearest_sub_simplex(const std::array<Eigen::Vector3d, 4>& points, int m) {
  return m == 1   ? nearest_simplex_detail::single(points.data(), 0)
         : m == 2 ? nearest_on_segment(points.data(), 0, 1)
         : m == 3 ? nearest_on_triangle(points.data(), 0, 1, 2)
                  : nearest_on_tetrahedron(points.data());
}

// The support point of A − B along v: A's along −v minus B's along v, with their indices.
template <class SetA, class SetB>
Eigen::Vector3d support_point(const SetA& A, const SetB& B, const Eigen::Vector3d& v, int& i_a, int& i_b) {
  i_a = A.support(-v);
  i_b = B.support(v);
  return Eigen::Vector3d(A.point(i_a) - B.point(i_b));
}

// Cold start: the support point along initial_direction (+x if it is zero).
template <class SetA, class SetB>
void start_cold(const SetA& A, const SetB& B, const Eigen::Vector3d& initial_direction, Simplex& s) {
  Eigen::Vector3d dir = initial_direction;
  if (!(dir.squaredNorm() > 0.0)) dir = Eigen::Vector3d::UnitX();
  int a0 = 0, b0 = 0;
  s.w[0] = support_point(A, B, dir, a0, b0);
  s.ia[0] = a0;
  s.ib[0] = b0;
  s.lambda[0] = 1.0;
  s.n = 1;
  s.v = s.w[0];
}

// Warm start: the old simplex's points now, reduced to the sub-simplex nearest the
// origin. False when the origin is inside it (the cores overlap; s is then undefined).
template <class SetA, class SetB>
bool start_warm(const SetA& A, const SetB& B, const GjkSimplex& warm, Simplex& s) {
  const int m = warm.size;
  for (int j = 0; j < m; j++) s.w[j] = A.point(warm.a[j]) - B.point(warm.b[j]);
  const NearestSimplex r = nearest_sub_simplex(s.w, m);
  if (r.n == 4) return false;
  const std::array<Eigen::Vector3d, 4> start = s.w;
  s.reduce_to(r, start, warm.a, warm.b);
  return true;
}

// The closest points of A and B as the simplex's weights combine its support points,
// their distance (0 when touching) and the weight of B's index 1.
template <class SetA, class SetB>
void closest_points(const SetA& A, const SetB& B, const Simplex& s, GjkResult& result) {
  for (int j = 0; j < s.n; ++j) {
    result.point_a += s.lambda[j] * A.point(s.ia[j]);
    result.point_b += s.lambda[j] * B.point(s.ib[j]);
    if (s.ib[j] == 1) result.weight_b1 += s.lambda[j];
  }
  result.distance = result.touching ? 0.0 : (result.point_b - result.point_a).norm();
}

}  // namespace gjk_detail

// The distance of A and B (see the top of this file). initial_direction: the first
// support direction of a cold start; size: the configuration's length for the relative
// tolerances; early_exit_distance > 0: stop (far) once the lower bound exceeds it;
// simplex (SetA and SetB with count()): the warm start and last simplex (GjkSimplex), or
// null.
template <class SetA, class SetB>
GjkResult gjk(const SetA& A, const SetB& B, const Eigen::Vector3d& initial_direction, double size,
              double early_exit_distance, double progress = kGjkProgress, GjkSimplex* simplex = nullptr) {
  gjk_detail::Simplex s;
  // the simplex kept for the next query: the last one, or the tetrahedron that holds the
  // origin
  bool kept = false;
  const auto keep_simplex = [&](int size_kept, const std::array<int, 4>& a, const std::array<int, 4>& b) {
    kept = true;
    if (!simplex) return;
    simplex->size = size_kept;
    simplex->a = a;
    simplex->b = b;
  };

  GjkResult result;
  const double origin_tol = kGjkOrigin * size;
  if (simplex && usable_simplex(*simplex, A, B)) {
    if (!gjk_detail::start_warm(A, B, *simplex, s)) {  // the origin inside: the cores overlap
      result.touching = true;
      keep_simplex(4, simplex->a, simplex->b);
      return result;
    }
  } else {
    gjk_detail::start_cold(A, B, initial_direction, s);
  }

  int iteration = 0;
  for (; iteration < kGjkMaxIterations; ++iteration) {
    const double vv = s.v.squaredNorm();
    if (vv <= origin_tol * origin_tol) {
      result.touching = true;
      break;
    }
    int i_a = 0, i_b = 0;
    const Eigen::Vector3d p = gjk_detail::support_point(A, B, s.v, i_a, i_b);
    const double vp = s.v.dot(p);
    // v·p/|v| is a lower bound of the distance, |v| an upper bound
    if (early_exit_distance > 0.0 && vp > 0.0 &&
        vp * vp > early_exit_distance * early_exit_distance * vv) {
      result.far = true;
      result.distance = vp / std::sqrt(vv);
      break;
    }
    bool repeated = false;
    for (int j = 0; j < s.n; ++j) repeated = repeated || (s.ia[j] == i_a && s.ib[j] == i_b);
    if (repeated) break;  // the support is already a simplex vertex: v is optimal
    const double norm_v = std::sqrt(vv);
    if (vv - vp <= progress * std::max(vv, norm_v * size)) break;

    std::array<Eigen::Vector3d, 4> trial = s.w;
    trial[s.n] = p;
    const NearestSimplex r = gjk_detail::nearest_sub_simplex(trial, s.n + 1);
    std::array<int, 4> trial_ia = s.ia, trial_ib = s.ib;
    trial_ia[s.n] = i_a;
    trial_ib[s.n] = i_b;
    if (r.n == 4) {
      result.touching = true;
      ++iteration;
      keep_simplex(4, trial_ia, trial_ib);
      break;
    }
    if (!(r.v.squaredNorm() < vv)) break;  // no progress (rounding): keep the last simplex
    s.reduce_to(r, trial, trial_ia, trial_ib);
  }
  result.iterations = iteration;
  if (!kept) keep_simplex(s.n, s.ia, s.ib);
  if (result.far) return result;
  gjk_detail::closest_points(A, B, s, result);
  return result;
}

}  // namespace wiregrain
