// The reduced ("local" in FCLib's words) contact problem: u = W r + q, W given as 3×3
// blocks (core/nscd/block_sparse_matrix.h), one μ per contact. A time step's problem can be
// assembled into one (assemble_reduced: its solution is solve_nscd_step's, the same sweep)
// and written to a file (core/nscd/reduced_problem_io.h) for FCLib and Siconos
// (bench/fclib_nscd).
#pragma once

#include <Eigen/Dense>

#include <vector>

#include "core/nscd/block_sparse_matrix.h"
#include "core/nscd/gauss_seidel.h"
#include "core/nscd/nscd_step.h"

namespace wiregrain {

struct ReducedProblem {
  BlockSparseMatrix3 W;
  Eigen::VectorXd q;           // 3n
  std::vector<double> mu;      // n
  int contact_count() const { return W.block_count(); }
  // InvalidArgument("W" | "q" | "mu", ...): sizes, a missing or W_nn ≤ 0 diagonal block,
  // μ < 0, non-finite data.
  void validate() const;
};

// The reduced problem of a time step: W = H M⁻¹ Hᵀ (blocks between contacts sharing a
// body) and q = H V_free + velocity_offset + s e_n with the contact-law shift s of the
// step's law (θ, restitution, overlap recovery). Its solution equals solve_nscd_step's
// (same sweep). The InvalidArgument of solve_nscd_step on a bad step.
ReducedProblem assemble_reduced(const NscdStep& step);

ContactSolution solve_reduced(const ReducedProblem& problem, const SolverSettings& settings,
                              const std::vector<Eigen::Vector3d>& warm_start = {});

// Siconos error (core/nscd/contact_operator.h) of impulses r (one per contact) for a
// reduced problem.
double siconos_error(const ReducedProblem& problem, const std::vector<Eigen::Vector3d>& r);

}  // namespace wiregrain
