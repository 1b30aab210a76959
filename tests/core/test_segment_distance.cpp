// Segment–segment closest points (core/segment_distance.h) against an independent
// reference: for fixed s the exact distance from p(s) to segment B (projection with
// clamping), minimised over s ∈ [0, 1] by golden-section search to 1e-15 (the function
// is convex in s: a partial minimum of a convex function), with s = 0 and s = 1 checked;
// the same with the roles of A and B exchanged, and the smaller of the two. Evaluated in
// long double. Every pair of every family must satisfy
//   |distance − reference| < 1e-10 · max(|A|, |B|),
// s, t ∈ [0, 1], p = a0 + s (a1 − a0), q = b0 + t (b1 − b0), |q − p| = distance.
// The worst error of each family (in units of max(|A|, |B|)) is printed and recorded.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <sstream>
#include <string>

#include "core/geometry/segment_distance.h"

using namespace wiregrain;
using Eigen::Vector3d;

namespace {

using Vector3l = Eigen::Matrix<long double, 3, 1>;

constexpr int kPairsPerFamily = 20000;  // 12 families: 2.4e5 pairs
constexpr double kTolerance = 1e-10;     // of max(|A|, |B|)

// ---------------------------------------------------------------- reference

Vector3l to_long(const Vector3d& x) { return x.cast<long double>(); }

// exact distance from point x to segment [b0, b0 + v] (projection, clamped)
long double point_segment_distance(const Vector3l& x, const Vector3l& b0, const Vector3l& v) {
  const long double vv = v.squaredNorm();
  long double t = 0.0L;
  if (vv > 0.0L) t = std::clamp((x - b0).dot(v) / vv, 0.0L, 1.0L);
  return (b0 + t * v - x).norm();
}

// min over s ∈ [0, 1] of dist(a0 + s u, B): golden section to 1e-15, plus the ends
long double golden_reference(const Vector3d& a0d, const Vector3d& a1d, const Vector3d& b0d,
                             const Vector3d& b1d) {
  const Vector3l a0 = to_long(a0d), u = to_long(a1d) - to_long(a0d);
  const Vector3l b0 = to_long(b0d), v = to_long(b1d) - to_long(b0d);
  auto g = [&](long double s) { return point_segment_distance(a0 + s * u, b0, v); };
  const long double r = (std::sqrt(5.0L) - 1.0L) / 2.0L;
  long double lo = 0.0L, hi = 1.0L;
  long double x1 = hi - r * (hi - lo), x2 = lo + r * (hi - lo);
  long double f1 = g(x1), f2 = g(x2);
  while (hi - lo > 1e-15L) {
    if (f1 < f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - r * (hi - lo);
      f1 = g(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + r * (hi - lo);
      f2 = g(x2);
    }
  }
  return std::min({g(0.0L), g(1.0L), f1, f2, g(0.5L * (lo + hi))});
}

long double reference_distance(const Vector3d& a0, const Vector3d& a1, const Vector3d& b0,
                               const Vector3d& b1) {
  return std::min(golden_reference(a0, a1, b0, b1), golden_reference(b0, b1, a0, a1));
}

// ---------------------------------------------------------------- random cases

struct Case {
  Vector3d a0 = Vector3d::Zero(), a1 = Vector3d::Zero(), b0 = Vector3d::Zero(), b1 = Vector3d::Zero();
  // set for parallel / collinear families: the expected (overlap-midpoint) contact points
  bool has_expected = false;
  Vector3d p_expected = Vector3d::Zero(), q_expected = Vector3d::Zero();
};

class Rng {
 public:
  explicit Rng(unsigned long seed) : gen_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen_); }
  double log_uniform(double lo_exp, double hi_exp) { return std::pow(10.0, uniform(lo_exp, hi_exp)); }
  bool coin(double p = 0.5) { return uniform(0.0, 1.0) < p; }
  Vector3d in_cube(double half = 1.0) {
    return Vector3d(uniform(-half, half), uniform(-half, half), uniform(-half, half));
  }
  Vector3d unit() {
    for (;;) {
      const Vector3d x = in_cube();
      const double n = x.norm();
      if (n > 0.1 && n <= 1.0) return x / n;
    }
  }
  // a unit vector perpendicular to the unit vector a
  Vector3d perpendicular(const Vector3d& a) {
    for (;;) {
      const Vector3d x = unit().cross(a);
      const double n = x.norm();
      if (n > 0.1) return x / n;
    }
  }

 private:
  std::mt19937_64 gen_;
};

// Random overall scale 1e-3..1e3 and shift (of the order of the scale), applied to the
// points of a constructed case: the test is scale-free.
Case rescale(Rng& rng, Case c, double shift = 1.0) {
  const double k = rng.log_uniform(-3.0, 3.0);
  const Vector3d o = shift * k * rng.in_cube();
  for (Vector3d* x : {&c.a0, &c.a1, &c.b0, &c.b1, &c.p_expected, &c.q_expected}) *x = o + k * *x;
  return c;
}

Case swap_roles(Case c) {
  std::swap(c.a0, c.b0);
  std::swap(c.a1, c.b1);
  std::swap(c.p_expected, c.q_expected);
  return c;
}

// B on the line a0 + o + λ u, λ from α to β (o = 0: collinear). Expected contact: the
// midpoint of the overlap of [0, 1] and [min(α, β), max(α, β)], else the nearest ends.
Case parallel_case(const Vector3d& a0, const Vector3d& a1, const Vector3d& o, double alpha,
                   double beta) {
  Case c;
  const Vector3d u = a1 - a0;
  c.a0 = a0;
  c.a1 = a1;
  c.b0 = a0 + o + alpha * u;
  c.b1 = a0 + o + beta * u;
  const double lo = std::max(0.0, std::min(alpha, beta));
  const double hi = std::min(1.0, std::max(alpha, beta));
  const double s = std::clamp(0.5 * (lo + hi), 0.0, 1.0);
  const double lambda = std::clamp(s, std::min(alpha, beta), std::max(alpha, beta));
  c.has_expected = true;
  c.p_expected = a0 + s * u;
  c.q_expected = a0 + o + lambda * u;
  return c;
}

Case generic_case(Rng& rng) {
  Case c;
  c.a0 = rng.in_cube();
  c.a1 = rng.in_cube();
  c.b0 = rng.in_cube();
  c.b1 = rng.in_cube();
  return c;
}

Case parallel_family(Rng& rng) {
  const Vector3d a0 = rng.in_cube(), a1 = rng.in_cube();
  // the shift perpendicular to A, so that α, β below are B's ends along A
  const Vector3d uh = (a1 - a0).normalized();
  Vector3d o = rng.in_cube() * rng.log_uniform(-6.0, 0.0);
  o -= o.dot(uh) * uh;
  if (rng.coin()) return parallel_case(a0, a1, o, 0.0, 1.0);  // B = A shifted
  if (rng.coin()) return parallel_case(a0, a1, o, 1.0, 0.0);  // ... and reversed
  return parallel_case(a0, a1, o, rng.uniform(-1.5, 2.5), rng.uniform(-1.5, 2.5));
}

Case collinear_family(Rng& rng, bool overlapping) {
  const Vector3d a0 = rng.in_cube(), a1 = rng.in_cube();
  for (;;) {
    const double alpha = rng.uniform(-2.0, 3.0), beta = rng.uniform(-2.0, 3.0);
    const bool overlap = std::max(alpha, beta) > 0.0 && std::min(alpha, beta) < 1.0;
    if (overlap == overlapping) return parallel_case(a0, a1, Vector3d::Zero(), alpha, beta);
  }
}

// a segment of length l through x, x at fraction f of it
void segment_through(const Vector3d& x, const Vector3d& dir, double l, double f, Vector3d& e0,
                     Vector3d& e1) {
  e0 = x - f * l * dir;
  e1 = x + (1.0 - f) * l * dir;
}

Case crossing_family(Rng& rng) {
  Case c;
  const Vector3d x = rng.in_cube();
  segment_through(x, rng.unit(), rng.uniform(0.1, 2.0), rng.uniform(0.0, 1.0), c.a0, c.a1);
  segment_through(x, rng.unit(), rng.uniform(0.1, 2.0), rng.uniform(0.0, 1.0), c.b0, c.b1);
  return c;
}

Case touching_family(Rng& rng) {
  Case c;
  c.a0 = rng.in_cube();
  c.a1 = rng.in_cube();
  c.b0 = c.a0 + rng.uniform(0.0, 1.0) * (c.a1 - c.a0);
  c.b1 = c.b0 + rng.in_cube();
  if (rng.coin()) std::swap(c.b0, c.b1);
  return rng.coin() ? swap_roles(c) : c;
}

Case very_short_family(Rng& rng) {
  Case c;
  c.a0 = rng.in_cube();
  c.a1 = rng.in_cube();
  const Vector3d u = c.a1 - c.a0;
  const double l = rng.log_uniform(-9.0, -6.0) * u.norm();
  const double kind = rng.uniform(0.0, 1.0);
  Vector3d centre = c.a0 + rng.uniform(-0.3, 1.3) * u;
  if (kind < 0.3)
    centre += rng.in_cube(0.5);  // somewhere near A
  else if (kind < 0.6)
    centre += rng.in_cube(10.0 * l);  // within its own length of A's line
  // else: centred on A's line
  const Vector3d dir = rng.coin(0.3) ? Vector3d(u.normalized()) : rng.unit();
  segment_through(centre, dir, l, rng.uniform(0.0, 1.0), c.b0, c.b1);
  return rng.coin() ? swap_roles(c) : c;
}

// B at angle θ to A, passing at distance h from a point at fraction α of A's line
Case nearly_parallel_case(Rng& rng, double theta) {
  Case c;
  c.a0 = rng.in_cube();
  c.a1 = rng.in_cube();
  const Vector3d u = c.a1 - c.a0;
  const Vector3d uh = u.normalized();
  const Vector3d m = rng.perpendicular(uh);
  const Vector3d vh = std::cos(theta) * uh + std::sin(theta) * m;
  const double h = rng.coin(0.3) ? 0.0 : rng.log_uniform(-12.0, 0.0) * u.norm();
  const Vector3d x = c.a0 + rng.uniform(-0.5, 1.5) * u + h * rng.perpendicular(uh);
  segment_through(x, vh, rng.uniform(0.1, 2.0) * u.norm(), rng.uniform(-0.2, 1.2), c.b0, c.b1);
  if (rng.coin()) std::swap(c.b0, c.b1);
  return rng.coin() ? swap_roles(c) : c;
}

Case nearly_parallel_family(Rng& rng) { return nearly_parallel_case(rng, rng.log_uniform(-8.0, -3.0)); }
Case tiny_angle_family(Rng& rng) { return nearly_parallel_case(rng, rng.log_uniform(-14.0, -8.0)); }

Case t_family(Rng& rng) {
  Case c;
  c.a0 = rng.in_cube();
  c.a1 = rng.in_cube();
  const Vector3d u = c.a1 - c.a0;
  const Vector3d m = rng.perpendicular(u.normalized());
  const double h = rng.coin(0.3) ? 0.0 : rng.log_uniform(-6.0, 0.0) * u.norm();
  c.b0 = c.a0 + rng.uniform(-0.2, 1.2) * u + h * m;
  // the stem points away from A, or towards it (through it when longer than h)
  c.b1 = c.b0 + (rng.coin() ? 1.0 : -1.0) * rng.uniform(0.1, 2.0) * u.norm() * m;
  if (rng.coin()) std::swap(c.b0, c.b1);
  return rng.coin() ? swap_roles(c) : c;
}

Case degenerate_family(Rng& rng) {
  Case c = generic_case(rng);
  const int kind = static_cast<int>(rng.uniform(0.0, 6.0));
  switch (kind) {
    case 0:  // A a point
      c.a1 = c.a0;
      break;
    case 1:  // B a point
      c.b1 = c.b0;
      break;
    case 2:  // both points
      c.a1 = c.a0;
      c.b1 = c.b0;
      break;
    case 3:  // A a point on B
      c.a0 = c.b0 + rng.uniform(0.0, 1.0) * (c.b1 - c.b0);
      c.a1 = c.a0;
      break;
    case 4:  // A of length 1e-170 (below the point threshold 1.5e-154)
      c.a1 = c.a0 + 1e-170 * rng.unit();
      break;
    default:  // A of length 1e-150 (normalised; just above the threshold)
      c.a1 = c.a0 + 1e-150 * rng.unit();
      break;
  }
  return rng.coin() ? swap_roles(c) : c;
}

// A mix of the families far from the origin (shifted by ~1e3 lengths, as wire segments
// in a large domain): the inputs' own rounding (~1e-13 of a length) is all that may show.
// Parallel pairs are then parallel only to ~1e-13/|B| rad, so no expected contact point.
Case far_family(Rng& rng) {
  const int kind = static_cast<int>(rng.uniform(0.0, 5.0));
  Case c = kind == 0   ? generic_case(rng)
           : kind == 1 ? parallel_family(rng)
           : kind == 2 ? nearly_parallel_family(rng)
           : kind == 3 ? crossing_family(rng)
                       : very_short_family(rng);
  c.has_expected = false;
  return c;
}

// ---------------------------------------------------------------- the check

struct FamilyResult {
  double worst = 0.0;  // max |distance − reference| / max(|A|, |B|)
  double worst_point = 0.0;  // max |p − p_expected|, |q − q_expected| (same units)
  int failures = 0;
  std::string first_failure;
};

std::string describe(const Case& c, const SegmentClosestPoints& r, long double ref) {
  std::ostringstream os;
  os.precision(17);
  os << "a0 " << c.a0.transpose() << " a1 " << c.a1.transpose() << " b0 " << c.b0.transpose()
     << " b1 " << c.b1.transpose() << " -> s " << r.s << " t " << r.t << " distance "
     << r.distance << " reference " << static_cast<double>(ref);
  return os.str();
}

FamilyResult run_family(const char* name, unsigned long seed, const std::function<Case(Rng&)>& make,
                        double shift = 1.0) {
  Rng rng(seed);
  FamilyResult out;
  for (int k = 0; k < kPairsPerFamily; ++k) {
    const Case c = rescale(rng, make(rng), shift);
    const SegmentClosestPoints r = segment_closest_points(c.a0, c.a1, c.b0, c.b1);
    const long double ref = reference_distance(c.a0, c.a1, c.b0, c.b1);
    double scale = std::max((c.a1 - c.a0).norm(), (c.b1 - c.b0).norm());
    if (scale == 0.0) scale = std::max(static_cast<double>(ref), 1e-300);  // point–point: relative
    const double err = static_cast<double>(std::fabs(static_cast<long double>(r.distance) - ref)) / scale;
    out.worst = std::max(out.worst, err);
    // p, q on the segments, |q − p| = distance
    const double coord = std::max({c.a0.norm(), c.a1.norm(), c.b0.norm(), c.b1.norm()});
    const double on_a = (r.p - (c.a0 + r.s * (c.a1 - c.a0))).norm();
    const double on_b = (r.q - (c.b0 + r.t * (c.b1 - c.b0))).norm();
    const double gap = std::fabs((r.q - r.p).norm() - r.distance);
    double point_err = 0.0;
    if (c.has_expected)
      point_err = std::max((r.p - c.p_expected).norm(), (r.q - c.q_expected).norm()) / scale;
    out.worst_point = std::max(out.worst_point, point_err);
    const bool ok = err < kTolerance && r.s >= 0.0 && r.s <= 1.0 && r.t >= 0.0 && r.t <= 1.0 &&
                    on_a <= 1e-15 * coord && on_b <= 1e-15 * coord &&
                    gap <= 1e-15 * std::max(r.distance, 1e-300) && point_err < 1e-9 &&
                    std::isfinite(r.distance);
    if (!ok && out.failures++ == 0) {
      std::ostringstream why;
      why << describe(c, r, ref) << " [error " << err << ", on A " << on_a << ", on B " << on_b
          << ", |q - p| - distance " << gap << ", off the expected points " << point_err << "]";
      out.first_failure = why.str();
    }
  }
  std::printf("  %-34s %d pairs: worst |d - d_ref| / max(|A|,|B|) = %.2e", name, kPairsPerFamily,
              out.worst);
  if (out.worst_point > 0.0) std::printf(", contact points off the overlap midpoint %.2e", out.worst_point);
  std::printf("\n");
  return out;
}

#define SEGMENT_FAMILY_TEST_SHIFTED(TestName, label, seed, maker, shift)                    \
  TEST(SegmentDistance, TestName) {                                                        \
    const FamilyResult res = run_family(label, seed, maker, shift);                        \
    RecordProperty("worst_relative_error", std::to_string(res.worst));                     \
    EXPECT_LT(res.worst, kTolerance);                                                      \
    EXPECT_EQ(res.failures, 0) << "first failure: " << res.first_failure;                  \
  }
#define SEGMENT_FAMILY_TEST(TestName, label, seed, maker) \
  SEGMENT_FAMILY_TEST_SHIFTED(TestName, label, seed, maker, 1.0)

SEGMENT_FAMILY_TEST(RandomGeneric, "generic random", 11, generic_case)
SEGMENT_FAMILY_TEST(RandomParallel, "parallel (B = A shifted)", 12, parallel_family)
SEGMENT_FAMILY_TEST(RandomCollinearOverlapping, "collinear, overlapping", 13,
                    [](Rng& r) { return collinear_family(r, true); })
SEGMENT_FAMILY_TEST(RandomCollinearDisjoint, "collinear, disjoint", 14,
                    [](Rng& r) { return collinear_family(r, false); })
SEGMENT_FAMILY_TEST(RandomCrossing, "crossing (distance 0)", 15, crossing_family)
SEGMENT_FAMILY_TEST(RandomTouching, "touching (endpoint on segment)", 16, touching_family)
SEGMENT_FAMILY_TEST(RandomVeryShort, "very short (1e-9..1e-6 of other)", 17, very_short_family)
SEGMENT_FAMILY_TEST(RandomNearlyParallel, "nearly parallel (1e-8..1e-3 rad)", 18,
                    nearly_parallel_family)
SEGMENT_FAMILY_TEST(RandomTinyAngle, "nearly parallel (1e-14..1e-8 rad)", 19, tiny_angle_family)
SEGMENT_FAMILY_TEST(RandomTConfiguration, "T-configurations", 20, t_family)
SEGMENT_FAMILY_TEST(RandomDegenerate, "degenerate (zero-length)", 21, degenerate_family)
SEGMENT_FAMILY_TEST_SHIFTED(RandomFarFromOrigin, "mixed, 1e3 lengths from the origin", 22, far_family,
                            1e3)

// ---------------------------------------------------------------- closed forms

TEST(SegmentDistance, SkewPerpendicular) {
  const auto r = segment_closest_points(Vector3d(-1, 0, 0), Vector3d(1, 0, 0), Vector3d(0, -1, 2),
                                        Vector3d(0, 1, 2));
  EXPECT_DOUBLE_EQ(r.distance, 2.0);
  EXPECT_DOUBLE_EQ(r.s, 0.5);
  EXPECT_DOUBLE_EQ(r.t, 0.5);
  EXPECT_LT((r.p - Vector3d(0, 0, 0)).norm(), 1e-15);
  EXPECT_LT((r.q - Vector3d(0, 0, 2)).norm(), 1e-15);
}

TEST(SegmentDistance, SkewClampedToEndpoints) {
  // lines meet at x = 3 on A's line, beyond a1 = (2,0,0); B's line at y = 3 beyond b1
  const auto r = segment_closest_points(Vector3d(0, 0, 0), Vector3d(2, 0, 0), Vector3d(3, -3, 1),
                                        Vector3d(3, -1, 1));
  EXPECT_DOUBLE_EQ(r.s, 1.0);
  EXPECT_DOUBLE_EQ(r.t, 1.0);
  EXPECT_NEAR(r.distance, std::sqrt(1.0 + 1.0 + 1.0), 1e-15);
}

TEST(SegmentDistance, CollinearOverlapMidpoint) {
  // A = [0, 4], B = [7, 3] on the x axis: overlap [3, 4], contact at x = 3.5
  const auto r = segment_closest_points(Vector3d(0, 0, 0), Vector3d(4, 0, 0), Vector3d(7, 0, 0),
                                        Vector3d(3, 0, 0));
  EXPECT_EQ(r.distance, 0.0);
  EXPECT_DOUBLE_EQ(r.s, 0.875);
  EXPECT_DOUBLE_EQ(r.t, 0.875);
  EXPECT_DOUBLE_EQ(r.p.x(), 3.5);
  EXPECT_DOUBLE_EQ(r.q.x(), 3.5);
}

TEST(SegmentDistance, ContainedCollinearMidpoint) {
  // B = [1, 2] inside A = [0, 10]: contact at B's middle
  const auto r = segment_closest_points(Vector3d(0, 0, 0), Vector3d(10, 0, 0), Vector3d(1, 0, 0),
                                        Vector3d(2, 0, 0));
  EXPECT_EQ(r.distance, 0.0);
  EXPECT_DOUBLE_EQ(r.s, 0.15);
  EXPECT_DOUBLE_EQ(r.t, 0.5);
}

TEST(SegmentDistance, ParallelOverlapMidpoint) {
  // A = [0, 4], B = [2, 6] at y = 1: overlap [2, 4], contact at x = 3
  const auto r = segment_closest_points(Vector3d(0, 0, 0), Vector3d(4, 0, 0), Vector3d(2, 1, 0),
                                        Vector3d(6, 1, 0));
  EXPECT_DOUBLE_EQ(r.distance, 1.0);
  EXPECT_DOUBLE_EQ(r.s, 0.75);
  EXPECT_DOUBLE_EQ(r.t, 0.25);
}

TEST(SegmentDistance, ParallelDisjointNearestEnds) {
  const auto r = segment_closest_points(Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(5, 1, 0),
                                        Vector3d(3, 1, 0));
  EXPECT_DOUBLE_EQ(r.distance, std::sqrt(5.0));
  EXPECT_EQ(r.s, 1.0);
  EXPECT_EQ(r.t, 1.0);
}

TEST(SegmentDistance, ShortParallelSegments) {
  // the paper's motivating case: short parallel segments (1e-8 long, 1e-9 apart)
  const double l = 1e-8;
  const auto r = segment_closest_points(Vector3d(0.3, 0.3, 0.3), Vector3d(0.3 + l, 0.3, 0.3),
                                        Vector3d(0.3 + 0.5 * l, 0.3 + 1e-9, 0.3),
                                        Vector3d(0.3 + 1.5 * l, 0.3 + 1e-9, 0.3));
  EXPECT_NEAR(r.distance, 1e-9, 1e-9 * 1e-6);
  EXPECT_NEAR(r.s, 0.75, 1e-6);  // overlap [0.5 l, l]
  EXPECT_NEAR(r.t, 0.25, 1e-6);
}

TEST(SegmentDistance, PointCases) {
  const Vector3d x(0.5, 1.0, 0.0);
  auto r = segment_closest_points(x, x, Vector3d(0, 0, 0), Vector3d(1, 0, 0));
  EXPECT_DOUBLE_EQ(r.distance, 1.0);
  EXPECT_EQ(r.s, 0.0);
  EXPECT_DOUBLE_EQ(r.t, 0.5);
  r = segment_closest_points(Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(3, 4, 0), Vector3d(3, 4, 0));
  EXPECT_DOUBLE_EQ(r.distance, std::sqrt(4.0 + 16.0));
  EXPECT_EQ(r.s, 1.0);
  EXPECT_EQ(r.t, 0.0);
  r = segment_closest_points(Vector3d(1, 2, 3), Vector3d(1, 2, 3), Vector3d(4, 6, 3), Vector3d(4, 6, 3));
  EXPECT_DOUBLE_EQ(r.distance, 5.0);
  EXPECT_EQ(r.s, 0.0);
  EXPECT_EQ(r.t, 0.0);
}

TEST(SegmentDistance, CrossingInterior) {
  const auto r = segment_closest_points(Vector3d(-1, -1, 0), Vector3d(1, 1, 0), Vector3d(-1, 1, 0),
                                        Vector3d(3, -3, 0));
  EXPECT_LT(r.distance, 1e-15);
  EXPECT_DOUBLE_EQ(r.s, 0.5);
  EXPECT_DOUBLE_EQ(r.t, 0.25);
}

// Swapping A and B swaps (s, p) with (t, q); reversing a segment maps its parameter to
// 1 − it. For parallel and collinear pairs this holds for the overlap-midpoint choice too.
TEST(SegmentDistance, SymmetricUnderSwapAndReversal) {
  Rng rng(31);
  double worst = 0.0;
  for (int k = 0; k < kPairsPerFamily; ++k) {
    const int family = k % 4;
    const Case c = rescale(rng, family == 0   ? generic_case(rng)
                                : family == 1 ? parallel_family(rng)
                                : family == 2 ? collinear_family(rng, rng.coin())
                                              : t_family(rng));
    const double scale = std::max((c.a1 - c.a0).norm(), (c.b1 - c.b0).norm());
    const auto r = segment_closest_points(c.a0, c.a1, c.b0, c.b1);
    const auto swapped = segment_closest_points(c.b0, c.b1, c.a0, c.a1);
    const auto reversed = segment_closest_points(c.a1, c.a0, c.b1, c.b0);
    const double e = std::max({(swapped.p - r.q).norm(), (swapped.q - r.p).norm(),
                               (reversed.p - r.p).norm(), (reversed.q - r.q).norm(),
                               std::fabs(swapped.distance - r.distance),
                               std::fabs(reversed.distance - r.distance)}) / scale;
    worst = std::max(worst, e);
    ASSERT_LT(e, 1e-9) << "pair " << k << " family " << family;
  }
  std::printf("  swap / reversal: worst contact-point change %.2e of max(|A|,|B|)\n", worst);
  RecordProperty("worst_symmetry_error", std::to_string(worst));
}

}  // namespace
