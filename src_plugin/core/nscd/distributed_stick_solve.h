// The stick solve of method subspace (core/nscd/subspace_correction.h) on a step spread
// over workers (core/nscd/nscd_step.h, NscdStep::touching_copies): the same system,
//     (W_SS + ε D_S) Δr_S = −u_S,   D_S = diag(W_SS),
// over the closed contacts S of every worker, solved by conjugate gradients
// preconditioned by the contacts' own 3×3 blocks (W_cc + ε diag(W_cc))⁻¹ instead of a
// sparse factorisation (W_SS is spread over the workers): each iteration one product
// W p, matrix-free on the bodies with their true masses and one exchange of the bodies'
// velocity changes among their copies (BodyContactOperator::delassus_product), and two
// sums over the workers. It stops once the residual is below 1e-12 of the right-hand
// side, or after max(100, the closed components over all workers) iterations. CG from
// Δr = 0 leaves what W_SS does not see (the null directions, where ε D alone acts) near
// 0: the load split among the points of a face as the sweeps left it, as the
// factorisation does.
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
