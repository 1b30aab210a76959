// slide_root_in_bracket (core/nscd/coulomb_local.h): the slide-case fallback, Brent's method
// from GSL on a sign change of g(φ) found by the 24-angle scan; chosen over a safeguarded
// Newton–bisection by bench/local_slide_gsl (docs/design.md, "The local solve").
#include <gsl/gsl_errno.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/nscd/coulomb_local.h"

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using wiregrain::SlideEquation;

// Reference root by plain bisection of [lo, hi] down to 1e-15 rad (g(lo) g(hi) < 0).
double bisection_root(const SlideEquation& equation, double lo, double hi) {
  double g_lo = equation.at(lo).g;
  while (hi - lo > 1e-15) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    const double g_mid = equation.at(mid).g;
    if (g_mid == 0.0) return mid;
    if ((g_mid < 0.0) == (g_lo < 0.0)) {
      lo = mid;
      g_lo = g_mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

void record_handler_call(const char*, const char*, int, int) {}

}  // namespace

// Every sign change of g among 24 angles (as the fallback scans) of random SPD W, q and μ:
// the root is inside the bracket, a root of g to round-off (SlideEquation::is_root), equal
// to the bisection root to 1e-11 rad, found in few iterations; GSL's error handler is the
// caller's again afterwards.
TEST(SlideRootInBracket, ScanBracketsOfRandomProblems) {
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), friction(0.1, 2.0);
  gsl_error_handler_t* const caller_handler = gsl_set_error_handler(&record_handler_call);
  constexpr double kTwoPi = 6.283185307179586;
  int brackets = 0;
  long iterations = 0;
  for (int k = 0; k < 3000; ++k) {
    Matrix3d A;
    for (int i = 0; i < 9; ++i) A(i / 3, i % 3) = unit(rng);
    const Matrix3d W = A * A.transpose() + 0.05 * Matrix3d::Identity();
    const Vector3d q(-0.1 - std::abs(unit(rng)), 3.0 * unit(rng), 3.0 * unit(rng));
    const SlideEquation equation(W, q, friction(rng));
    const double phi0 = 3.0 * unit(rng);
    double angle[25], g[25];
    for (int j = 0; j <= 24; ++j) {
      angle[j] = phi0 + kTwoPi * j / 24;
      g[j] = j < 24 ? equation.at(angle[j]).g : g[0];
    }
    for (int j = 0; j < 24; ++j) {
      if (g[j] == 0.0 || g[j + 1] == 0.0 || (g[j] < 0.0) == (g[j + 1] < 0.0)) continue;
      int count = 0;
      const double phi = wiregrain::slide_root_in_bracket(equation, angle[j], angle[j + 1], count);
      ASSERT_GE(phi, angle[j]) << "case " << k;
      ASSERT_LE(phi, angle[j + 1]) << "case " << k;
      ASSERT_TRUE(equation.is_root(equation.at(phi))) << "case " << k << " g " << equation.at(phi).g;
      ASSERT_NEAR(phi, bisection_root(equation, angle[j], angle[j + 1]), 1e-11) << "case " << k;
      ASSERT_LE(count, 40) << "case " << k;
      iterations += count;
      ++brackets;
    }
  }
  EXPECT_EQ(gsl_set_error_handler(caller_handler), &record_handler_call);
  EXPECT_GT(brackets, 3000);
  EXPECT_LT(static_cast<double>(iterations) / brackets, 8.0);
}
