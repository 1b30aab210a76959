#include "core/nscd/reduced_problem_io.h"

#include <iomanip>
#include <istream>
#include <ostream>
#include <sstream>

#include "core/common/errors.h"

namespace wiregrain {

void write_reduced_problem(std::ostream& out, const ReducedProblem& problem,
                           const std::string& title) {
  const int n = problem.contact_count();
  std::string one_line = title;
  for (char& ch : one_line)
    if (ch == '\n' || ch == '\r') ch = ' ';
  out << "wiregrain_reduced_problem 1\n"
      << "title " << one_line << "\n"
      << "contacts " << n << " blocks " << problem.W.stored_blocks() << "\n";
  out << std::setprecision(17);
  out << "mu\n";
  for (int c = 0; c < n; ++c) out << problem.mu[c] << "\n";
  out << "q\n";
  for (int c = 0; c < n; ++c)
    out << problem.q[3 * c] << " " << problem.q[3 * c + 1] << " " << problem.q[3 * c + 2] << "\n";
  out << "W\n";
  for (int row = 0; row < n; ++row) {
    for (const BlockSparseMatrix3::Entry& entry : problem.W.row(row)) {
      out << row << " " << entry.column;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out << " " << entry.block(i, j);
      out << "\n";
    }
  }
}

namespace {

// Reads the significant lines (no comments, no blank lines) and says where a fault is.
class LineReader {
 public:
  explicit LineReader(std::istream& in) : in_(in) {}
  std::string next(const std::string& expected) {
    std::string line;
    while (std::getline(in_, line)) {
      ++number_;
      const size_t start = line.find_first_not_of(" \t\r");
      if (start == std::string::npos || line[start] == '#') continue;
      return line.substr(start);
    }
    fail("ended early, expected " + expected);
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw InvalidArgument("file", "line " + std::to_string(number_) + ": " + what);
  }
  // `count` numbers from one line, nothing else on it
  template <class T>
  void numbers(const std::string& expected, T* values, int count) {
    std::istringstream words(next(expected));
    for (int k = 0; k < count; ++k)
      if (!(words >> values[k])) fail("expected " + expected);
    std::string extra;
    if (words >> extra) fail("unexpected '" + extra + "' after " + expected);
  }

 private:
  std::istream& in_;
  int number_ = 0;
};

}  // namespace

ReducedProblem read_reduced_problem(std::istream& in, std::string* title) {
  LineReader lines(in);
  if (lines.next("the header") != "wiregrain_reduced_problem 1")
    lines.fail("not a wiregrain reduced problem (expected 'wiregrain_reduced_problem 1')");
  const std::string title_line = lines.next("'title ...'");
  if (title_line.compare(0, 5, "title") != 0) lines.fail("expected 'title ...'");
  if (title) *title = title_line.size() > 6 ? title_line.substr(6) : "";
  std::istringstream sizes(lines.next("'contacts N blocks B'"));
  std::string word1, word2;
  long n = -1, blocks = -1;
  if (!(sizes >> word1 >> n >> word2 >> blocks) || word1 != "contacts" || word2 != "blocks" || n < 0 ||
      blocks < 0)
    lines.fail("expected 'contacts N blocks B' with N, B >= 0");
  ReducedProblem problem;
  problem.W = BlockSparseMatrix3(static_cast<int>(n));
  problem.q.resize(3 * n);
  problem.mu.resize(n);
  if (lines.next("'mu'") != "mu") lines.fail("expected 'mu'");
  for (long c = 0; c < n; ++c) lines.numbers("mu of contact " + std::to_string(c), &problem.mu[c], 1);
  if (lines.next("'q'") != "q") lines.fail("expected 'q'");
  for (long c = 0; c < n; ++c) lines.numbers("3 values of q for contact " + std::to_string(c), &problem.q[3 * c], 3);
  if (lines.next("'W'") != "W") lines.fail("expected 'W'");
  for (long b = 0; b < blocks; ++b) {
    double entry[11];
    lines.numbers("row, column and 9 entries of W block " + std::to_string(b), entry, 11);
    const long row = static_cast<long>(entry[0]), column = static_cast<long>(entry[1]);
    if (row != entry[0] || column != entry[1] || row < 0 || row >= n || column < 0 || column >= n)
      lines.fail("block indices out of range 0.." + std::to_string(n - 1));
    if (problem.W.find(static_cast<int>(row), static_cast<int>(column)) != nullptr)
      lines.fail("W block (" + std::to_string(row) + ", " + std::to_string(column) + ") given twice");
    Eigen::Matrix3d block;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) block(i, j) = entry[2 + 3 * i + j];
    problem.W.add(static_cast<int>(row), static_cast<int>(column), block);
  }
  problem.validate();
  return problem;
}

}  // namespace wiregrain
