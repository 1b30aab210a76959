// Sunday's segment–segment distance with normalised directions; the equations, the
// parallel and degenerate choices are documented in segment_distance.h.
#include "core/geometry/segment_distance.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace wiregrain {

namespace {

// sin²θ below which the segments count as parallel (θ < 1e-12 rad).
constexpr double kParallelSin2 = 1e-24;
// |u|² below this (the smallest normal double) makes a segment a point: its length
// (< 1.5e-154) could not be normalised accurately.
constexpr double kPointLength2 = std::numeric_limits<double>::min();

inline double clamp(double x, double lo, double hi) { return x < lo ? lo : (x > hi ? hi : x); }

}  // namespace

SegmentClosestPoints segment_closest_points(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1,
                                            const Eigen::Vector3d& b0, const Eigen::Vector3d& b1) {
  const Eigen::Vector3d u = a1 - a0;
  const Eigen::Vector3d v = b1 - b0;
  const Eigen::Vector3d w = a0 - b0;
  const double la2 = u.squaredNorm();
  const double lb2 = v.squaredNorm();
  const bool a_point = !(la2 >= kPointLength2);
  const bool b_point = !(lb2 >= kPointLength2);

  SegmentClosestPoints r;
  if (a_point && b_point) {
    // point–point: s = t = 0
  } else if (a_point) {
    // point a0 against B: t = clamp(v·(a0 − b0) / |v|²)
    r.t = clamp(v.dot(w) / lb2, 0.0, 1.0);
  } else if (b_point) {
    // point b0 against A: s = clamp(u·(b0 − a0) / |u|²)
    r.s = clamp(-u.dot(w) / la2, 0.0, 1.0);
  } else {
    const double la = std::sqrt(la2);
    const double lb = std::sqrt(lb2);
    const Eigen::Vector3d uh = u / la;
    const Eigen::Vector3d vh = v / lb;
    const double b = uh.dot(vh);  // cos θ
    const double d = uh.dot(w);
    const double e = vh.dot(w);
    const Eigen::Vector3d n = uh.cross(vh);
    const double D = n.squaredNorm();  // = 1 − b² = sin²θ, without its cancellation
    double sigma;                      // σ ∈ [0, |A|]
    double tau;                        // τ ∈ [0, |B|]
    if (D < kParallelSin2) {
      // Parallel: projections of b0, b1 onto A's axis are −d and −d + |B| b; σ is the
      // midpoint of their interval's overlap with [0, |A|] (an empty overlap puts the
      // "midpoint" outside [0, |A|], and the clamp picks A's end nearest to B).
      const double pb0 = -d;
      const double pb1 = -d + lb * b;
      const double lo = std::max(0.0, std::min(pb0, pb1));
      const double hi = std::min(la, std::max(pb0, pb1));
      sigma = clamp(0.5 * (lo + hi), 0.0, la);
      tau = clamp(e + sigma * b, 0.0, lb);  // projection of p(σ) onto B
    } else {
      // Closest point on A's line to B's line, Sunday's sN/sD with a = c = 1, clamped to
      // [0, |A|]; then τ = e + σ b, the projection of p(σ) onto B's line (the second
      // normal equation; for σ = σ_c it is τ_c = (e − b d)/D). Sunday's separate
      // τ_c = (û×v̂)·(û×w)/D would carry its own rounding error, of order ε|w|/θ, off
      // the valley of |p − q| and straight into the distance for nearly parallel pairs;
      // τ from σ keeps the pair on the valley floor (distance error ~ θ δσ ~ ε|A|).
      const double sc = n.dot(vh.cross(w)) / D;  // (b e − d) / D
      sigma = clamp(sc, 0.0, la);  // σ_c outside: the s = 0 or s = 1 edge
      tau = e + sigma * b;
      if (tau < 0.0) {  // t = 0 edge: σ = projection of b0 onto A, clamped
        tau = 0.0;
        sigma = clamp(-d, 0.0, la);
      } else if (tau > lb) {  // t = 1 edge: σ = projection of b1 onto A, clamped
        tau = lb;
        sigma = clamp(-d + lb * b, 0.0, la);
      }
    }
    // σ ≤ |A| and correctly rounded division keep s, t within [0, 1].
    r.s = sigma / la;
    r.t = tau / lb;
  }
  r.p = a0 + r.s * u;
  r.q = b0 + r.t * v;
  r.distance = (r.q - r.p).norm();
  return r;
}

}  // namespace wiregrain
