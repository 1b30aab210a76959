// Text files of reduced frictional contact problems (core/nscd/reduced_problem.h: u = W r + q, W in
// 3×3 blocks, one μ per contact), written by fix nscd/polyhedra for chosen steps and
// turned into FCLib HDF5 files by bench/fclib_nscd (which needs libfclib; the core does not).
//
// Format (numbers with 17 significant digits, so a round trip is exact):
//     wiregrain_reduced_problem 1
//     title <text to the end of the line>
//     contacts N blocks B
//     mu                     then N lines: μ_c
//     q                      then N lines: q_n q_t1 q_t2 (contact c's local frame)
//     W                      then B lines: row column and the 9 entries of the block, row by row
// Lines starting with '#' are comments.
#pragma once

#include <iosfwd>
#include <string>

#include "core/nscd/reduced_problem.h"

namespace wiregrain {

void write_reduced_problem(std::ostream& out, const ReducedProblem& problem,
                           const std::string& title = "");

// Throws InvalidArgument("file", "line K: ...") on a malformed file, and whatever
// ReducedProblem::validate throws on a problem that is not one (e.g. W_nn ≤ 0).
ReducedProblem read_reduced_problem(std::istream& in, std::string* title = nullptr);

}  // namespace wiregrain
