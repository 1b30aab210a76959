// Subspace correction (method subspace; the idea of the projected Gauss–Seidel subspace
// minimisation of Silcowitz, Niebe & Erleben, 2010), used by solve_frictional_contact
// (core/nscd/gauss_seidel.h) between its sweeps.
//
// Gauss–Seidel settles which contacts are closed within a few sweeps but needs ~N² (a
// compressed chain) to ~N⁴ (welded interfaces: a bent beam) sweeps to carry a load through
// N bodies. So, between sweeps, the closed contacts S (loaded, r_n > 0 and not open in the
// last sweep, or closing or touching, u_n ≤ 1e-12 ‖q‖) are solved together as if they
// stuck, the impulses of the others held: the increment closest to the current impulses
// that brings u_S to 0,
//     (W_SS + ε D_S) Δr_S = −u_S,   D_S = diag(W_SS),
// ε = subspace_regularization, by a sparse LDLᵀ factorisation (Eigen's SimplicialLDLT,
// AMD ordering, kept while the pattern of W_SS does not change; the factors too while
// its values are the same to the bit, as at rest) and two steps of
// iterative refinement on W_SS. A frictionless contact enters with its normal row only
// (its tangential impulse is 0). W_SS is singular where a face touches at more than three
// points or a pile closes loops of contacts; ε keeps the part of r_S that W_SS does not
// see (the split of a load among the points of a face, which Gauss–Seidel has already
// put inside the cones) as it is. [Solving for r_S itself, (W_SS + ε D) r_S = W_SS r_S −
// u_S, drops that part instead: on the 100-box stack the loads were exact to 8e-13
// instead of 6e-14.] The candidate, projected on the Coulomb cones (a contact that slides
// comes out of the stick solve outside its cone), is kept if it at least halves the
// Siconos error, else dropped (a kept solve that lowers the error only a little disturbs
// the sweeps: on lattice piles it doubled the sweeps needed); the sweeps go on either
// way.
//
// Schedule within a solve: a first solve after sweep 2, the next 2 sweeps after a solve
// that cut the error tenfold, else twice the last wait (2, 4, 8, …), and none after three
// dropped in a row. A solve that converges without a kept stick solve (a warm start
// already within the tolerance) gets one at the end: errors left within the tolerance
// otherwise add up step after step (a 20-box stack at tolerance 1e-4 drifts and falls;
// with it the loads stay exact to 1e-14) — unless its Siconos error is already at most
// subspace_closing × tolerance (default 0: always). Where something disturbs the contacts
// every step, the exactness does not last: a coupled column at rest comes out of its
// single sweep at an error of ~1e-6 each step (the wire's forces change), the closing
// solve takes it to 3e-18 and the next step is back at 1e-6; there the closing solve is
// most of the step's cost (in.column leaves it out in its relaxation, docs/design.md,
// "Subspace correction").
//
// Across solves (StickSolveBackoff, carried by the caller from one time step to the
// next): a pile whose contacts slide and creep is not a structure that sticks, and its
// stick solves make the error worse (9e-7 → 6e-5 on a 500-grain pile; W_SS of a pile is
// singular and a creeping contact cannot be held). A solve whose stick solves were
// dropped with the error more than doubled, none kept, makes the next 1, 2, 4, …, 1024
// solves without any; one kept sets the wait back to 0. Dropped solves that did no harm
// (a stack already exact to round-off) do not count. Without the backoff that pile took
// 3.6× Gauss–Seidel's time (four factorisations per step). The cap is high because a
// factorisation grows fast with a pile's size (3000 contacts of a 915-grain pile: ~50 ms,
// about 100 sweeps; the 10 080 of a 10×10×9 lattice pile: ~6 s, about 2300 sweeps); a
// structure that forms later (walls taken away) gets its stick solves back within 1024
// steps.
//
// Stick solves hold rolling couples as they are and would leave them one update behind,
// so none is made when any contact has a rolling resistance.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <vector>

#include "core/nscd/block_sparse_matrix.h"
#include "core/nscd/gauss_seidel.h"

namespace wiregrain {

// The unknowns of a stick solve: the three components of each closed contact (loaded:
// not open and r_n > 0; or closing or touching: u_n ≤ 1e-12 free_velocity_norm), only the
// normal one of a frictionless contact (its tangential impulse is 0 and stays so).
// components: the unknowns as 3 c + a (contact c, component a), ascending; unknown[3 c + a]:
// its index among them, −1 for a component left out.
struct ClosedComponents {
  std::vector<int> unknown, components;
};
ClosedComponents closed_components(const ContactOperator& op, const std::vector<Eigen::Vector3d>& impulses,
                                   const std::vector<ContactState>& states, double free_velocity_norm);

// W_SS: the rows and columns of W of the closed components.
Eigen::SparseMatrix<double> closed_block(const BlockSparseMatrix3& W, const ClosedComponents& closed);

// The LDLᵀ factors of `regularized` (W_SS + ε D_S, compressed), nullptr when the
// factorisation fails. The fill-reducing ordering (AMD) costs ~20 times the numerical
// factorisation; it is kept from the last solve of this thread while the pattern of W_SS
// is unchanged (a resting stack or pile: the same contacts step after step), and the
// factorisation too while its values are the same to the bit (a pile at rest: the same
// poses; the same factors as a new factorisation would give, so the results do not
// change). Kept factors of a W_SS that changed are not kept, even refined on the current
// one: a coupled column at rest changes W_SS by 5e-8 of its largest entry per step, and
// factors 1e-6 or 1e-4 old make some stick solves harmful (the near-null directions that
// ε holds move). report counts the numerical factorisations.
const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>* stick_solve_factors(
    const Eigen::SparseMatrix<double>& regularized, NscdReport& report);

// What one subspace correction did: kept (halved the Siconos error), dropped as
// harmless (the error neither halved nor doubled: a stack already exact to round-off),
// or dropped as harmful (the error more than doubled: a pile where contacts slide).
enum class StickSolveOutcome { kept, harmless, harmful };

// One subspace correction: solve the closed contacts together, keep the result if it
// halves the Siconos error `error_before`; error_after: the Siconos error of the impulses
// it leaves when kept. `impulses` and the operator follow a kept correction; report counts
// the factorisations.
StickSolveOutcome subspace_correction(ContactOperator& op, std::vector<Eigen::Vector3d>& impulses,
                                      const std::vector<ContactState>& states, const SolverSettings& settings,
                                      double error_before, double& error_after, NscdReport& report);

// The schedule of the stick solves within one solve (see "Schedule" above).
class StickSolveSchedule {
 public:
  explicit StickSolveSchedule(int max_iterations) : max_iterations_(max_iterations) {}
  // a stick solve after sweep `iteration` (none after the last sweep)
  bool due(int iteration) const { return iteration >= next_ && iteration < max_iterations_; }
  // after a kept stick solve that took the Siconos error from error_before to error
  void kept(int iteration, double error_before, double error) {
    wait_ = error <= 0.1 * error_before ? 2 : 2 * wait_;
    dropped_ = 0;
    plan_next(iteration);
  }
  // after a dropped one
  void dropped(int iteration) {
    wait_ *= 2;
    ++dropped_;
    plan_next(iteration);
  }

 private:
  // after three dropped solves in a row, none for the rest of the solve
  void plan_next(int iteration) { next_ = dropped_ >= 3 ? max_iterations_ : iteration + wait_; }
  int max_iterations_;
  int wait_ = 2, next_ = 2, dropped_ = 0;
};

// The backoff after a solve that made stick solves: a kept one sets the wait back to 0,
// harmful ones with none kept double it (1, 2, 4, …, 1024) and skip that many solves.
void update_backoff(StickSolveBackoff& backoff, bool any_kept, bool harmed);

}  // namespace wiregrain
