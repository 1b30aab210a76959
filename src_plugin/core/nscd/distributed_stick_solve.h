// The stick solve of method subspace (core/nscd/subspace_correction.h) on a step spread
// over workers (core/nscd/nscd_step.h, NscdStep::touching_copies): the same system,
//     (W_SS + ε D_S) Δr_S = −u_S,   D_S = diag(W_SS),
// over the closed contacts S of every worker, solved by conjugate gradients
// preconditioned block-Jacobi by worker (additive Schwarz without overlap): each worker
// factorises its own principal block of W_SS + ε D_S, the rows and columns of its own
// contacts with the bodies' true masses (sparse LDLᵀ, stick_solve_factors: kept while the
// block is the same, as on one worker), and applies its inverse to its part of the
// residual; the blocks between two workers' contacts (through a body both touch) are left
// to the iterations. Each iteration is one product W p, matrix-free on the bodies with
// their true masses and one exchange of the bodies' velocity changes among their copies
// (BodyContactOperator::delassus_product), and two sums over the workers. On one worker
// the preconditioner is W_SS + ε D_S itself and CG ends after one iteration; on P workers
// M⁻¹ A − I has rank at most 12 × (bodies touched by closed contacts of two workers), which
// bounds the iterations in exact arithmetic. It stops once the residual is below 1e-12 of
// the right-hand side, once it has not halved over 50 iterations (stalled: W_SS of a pile
// is singular and ε = 1e-9 leaves W_SS + ε D ill-conditioned, so CG there creeps for
// thousands of iterations to no gain; measured on the Table 1 column in
// docs/benchmarks.md), or after max(100, the closed components over all workers)
// iterations. Where a worker's factorisation fails, its contacts' own 3×3 blocks
// (W_cc + ε diag W_cc)⁻¹ precondition instead. CG from Δr = 0 leaves what W_SS does not
// see (the null directions, where ε D alone acts) near 0: the load split among the points
// of a face as the sweeps left it, as the factorisation does.
//
// The caller (core/nscd/gauss_seidel.cpp) projects the candidate r_S + Δr_S on the
// Coulomb cones, applies it on every worker and keeps it when it halves the Siconos error
// over all of them, as the serial stick solve does.
#pragma once

#include <Eigen/Dense>

#include <vector>

#include "core/common/worker_exchange.h"
#include "core/nscd/body_operator.h"
#include "core/nscd/gauss_seidel.h"

namespace wiregrain {

struct DistributedStickSolve {
  std::vector<Eigen::Vector3d> candidate;  // per contact of this worker: r_S + Δr_S (others: their r)
  int iterations = 0;                      // CG iterations
  double residual = 0.0;                   // its last relative residual
  bool any_closed = false;                 // a closed contact on some worker
};

// free_velocity_norm: ‖q‖ over all workers (the closing threshold of S as the serial
// stick solve has it). Collective.
DistributedStickSolve distributed_stick_solve(const BodyContactOperator& op, const std::vector<Eigen::Vector3d>& impulses,
                                              const std::vector<ContactState>& states, const SolverSettings& settings,
                                              double free_velocity_norm, WorkerExchange& exchange);

}  // namespace wiregrain
