// Text files of reduced problems: exact round trip (same bits, same solution) and the
// line-numbered messages for malformed files.
#include <gtest/gtest.h>

#include <random>
#include <sstream>

#include "core/common/errors.h"
#include "core/nscd/reduced_problem_io.h"

using namespace wiregrain;

namespace {

// n contacts, W = A Aᵀ + diag (SPD) with some zero blocks, q and μ random.
ReducedProblem random_problem(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::MatrixXd a(3 * n, 3 * n);
  for (int i = 0; i < 3 * n; ++i)
    for (int j = 0; j < 3 * n; ++j) a(i, j) = (i / 3 + j / 3) % 3 == 1 ? 0.0 : unit(rng) / 3.0;
  Eigen::MatrixXd w = a * a.transpose() + Eigen::MatrixXd::Identity(3 * n, 3 * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (std::abs(i - j) == 2) w.block<3, 3>(3 * i, 3 * j).setZero();
  ReducedProblem p;
  p.W = BlockSparseMatrix3::from_dense(w);
  p.q = Eigen::VectorXd::NullaryExpr(3 * n, [&]() { return unit(rng) * 1e-3 / 7.0; });
  for (int c = 0; c < n; ++c) p.mu.push_back(0.5 + 0.1 * unit(rng));
  return p;
}

std::string message_of(const std::string& text) {
  std::istringstream in(text);
  try {
    read_reduced_problem(in);
  } catch (const InvalidArgument& e) {
    return e.argument() + ": " + e.what();
  }
  return "no error";
}

}  // namespace

TEST(ReducedProblemIo, RoundTripIsExact) {
  const ReducedProblem p = random_problem(12, 3);
  std::stringstream file;
  write_reduced_problem(file, p, "twelve contacts\nsecond line");
  std::string title;
  const ReducedProblem back = read_reduced_problem(file, &title);
  EXPECT_EQ(title, "twelve contacts second line");
  ASSERT_EQ(back.contact_count(), 12);
  EXPECT_EQ(back.W.stored_blocks(), p.W.stored_blocks());
  EXPECT_LT(p.W.stored_blocks(), 144);  // the zero blocks are not written
  EXPECT_EQ((back.W.to_dense() - p.W.to_dense()).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((back.q - p.q).cwiseAbs().maxCoeff(), 0.0);
  for (int c = 0; c < 12; ++c) EXPECT_EQ(back.mu[c], p.mu[c]);
  SolverSettings options;
  options.order = SweepOrder::forward;
  options.tolerance = 1e-10;
  const ContactSolution a = solve_reduced(p, options), b = solve_reduced(back, options);
  EXPECT_EQ(a.report.iterations, b.report.iterations);
  for (int c = 0; c < 12; ++c) EXPECT_EQ((a.impulses[c] - b.impulses[c]).norm(), 0.0);
}

TEST(ReducedProblemIo, MalformedFilesNameTheLine) {
  std::stringstream file;
  write_reduced_problem(file, random_problem(2, 5), "two");
  const std::string good = file.str();
  EXPECT_EQ(message_of("fclib\n"),
            "file: line 1: not a wiregrain reduced problem (expected 'wiregrain_reduced_problem 1')");
  EXPECT_EQ(message_of(good.substr(0, good.find("W\n"))), "file: line 9: ended early, expected 'W'");
  std::string bad = good;
  bad.replace(bad.find("contacts 2"), 10, "contacts -2");
  EXPECT_EQ(message_of(bad), "file: line 3: expected 'contacts N blocks B' with N, B >= 0");
  bad = good;
  const size_t w = bad.find("W\n") + 2;
  bad.replace(w, 3, "0 7");
  EXPECT_EQ(message_of(bad), "file: line 11: block indices out of range 0..1");
  bad = good;
  const size_t row_end = bad.find('\n', w);
  bad.insert(row_end + 1, bad.substr(w, row_end + 1 - w));
  EXPECT_EQ(message_of(bad), "file: line 12: W block (0, 0) given twice");
  bad = good;
  bad.replace(bad.find("mu\n") + 3, 1, "x");
  EXPECT_EQ(message_of(bad).substr(0, 34), "file: line 5: expected mu of conta");
}
