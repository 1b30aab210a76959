// The contact solver: nonlinear Gauss–Seidel over the contacts of a ContactOperator
// (core/nscd/contact_operator.h) with the exact local Signorini–Coulomb solution
// (core/nscd/coulomb_local.h), driven by SolverSettings (core/nscd/solver_settings.h).
//
// One sweep:
//     for c in order:  q_loc = u_c − W_cc r_c   (velocity without the contact's own impulse)
//                      r_c ← ω solve_coulomb_local(W_cc, q_loc, μ_c) + (1 − ω) r_c
//                      apply Δr_c (the operator updates u of every contact it touches).
// On the body operator, a contact's rolling couple is solved after its 3×3 block with the
// new r_n (core/nscd/body_operator.h, "Rolling resistance").
//
// Stopping: after each sweep, one of
//   increment         ‖Δr‖₂ / ‖r‖₂ over the sweep (absolute when r = 0) < tolerance;
//   natural_map       the Siconos error (core/nscd/contact_operator.h) < tolerance; its pass
//                     costs half a sweep, so it is made after each of the first 20 sweeps,
//                     then at doubling intervals of at most a twentieth of the sweeps done
//                     (the stop comes at most ~5 % late; on a 3×3×3 lattice pile 1042
//                     sweeps at 68 µs instead of 1001 at 90 µs, fclib_nscd);
//   increment_then_natural_map   (default; after Siconos' default for fc3d_nsgs) once
//                     the increment is below the tolerance, the Siconos error must be too;
//                     while it is not, it is re-checked at doubling intervals (at most a
//                     twentieth of the sweeps done).
// or the iteration cap (hit_iteration_cap = true; both numbers are reported). With
// rolling couples, a solve is converged only once the couples satisfy their law too
// (core/nscd/body_operator.h, "Rolling resistance").
//
// Method subspace adds stick solves between the sweeps (core/nscd/subspace_correction.h).
#pragma once

#include <Eigen/Dense>

#include <vector>

#include "core/common/worker_exchange.h"
#include "core/nscd/contact_operator.h"
#include "core/nscd/coulomb_local.h"
#include "core/nscd/solver_settings.h"

namespace wiregrain {

struct NscdReport {
  int iterations = 0;         // sweeps done
  double residual = 0.0;      // last value of the stopping measure
  double increment = 0.0;     // last ‖Δr‖/‖r‖
  double siconos_error = 0.0; // Siconos error of the returned impulses
  bool hit_iteration_cap = false;
  int open = 0, stick = 0, slide = 0;  // contact states in the last sweep
  long newton_iterations = 0;          // all local slide Newton steps
  long slide_fallbacks = 0;            // local slide solves that needed the scan
  int subspace_solves = 0;             // stick solves tried (method subspace)
  int subspace_accepted = 0;           // of which halved the Siconos error and were kept
  int subspace_factorizations = 0;     // numerical LDLᵀ factorisations they made (distributed: CG iterations)
  long frozen_updates = 0;             // contact updates skipped (freeze)
  int colours = 0;                     // order coloured: colours of the contact graph
};

// method subspace from one solve to the next (a time step to the next;
// core/nscd/subspace_correction.h, "Across solves"): after a solve whose stick solves did
// harm and none was kept, the next `wait` solves make none, wait doubling 1, 2, 4, … up to
// 1024 while that goes on; a kept one sets it back to 0.
struct StickSolveBackoff {
  int skip = 0;  // solves left to make without stick solves
  int wait = 0;  // the last skip
};

struct ContactSolution {
  std::vector<Eigen::Vector3d> impulses;  // r_c in the local frame
  std::vector<ContactState> states;
  // rolling couples (t1, t2 components, on body b; −m on a), one per contact when any
  // contact has a rolling resistance, else empty
  std::vector<Eigen::Vector2d> couples;
  NscdReport report;
};

// The Gauss–Seidel solver on any operator. warm_start: empty, or one impulse per contact
// (e.g. the last step's impulses on persistent contacts, zero on new ones), applied to the
// operator before the first sweep. InvalidArgument("warm_start", ...) on a size mismatch,
// and SolverSettings::validate's.
// backoff: the state carried between the solves of a run (method subspace), or nullptr.
// couple_warm_start: empty, or one rolling couple per contact (t1, t2 components),
// applied with the impulses; entries of contacts without rolling resistance (all of them
// on an operator other than solve_nscd_step's) are ignored.
// exchange: the workers of a distributed step (core/nscd/nscd_step.h, NscdStep::
// touching_copies), on the body operator only (InvalidArgument("exchange", ...) on another
// operator or with rolling resistance); null: one worker.
ContactSolution solve_frictional_contact(ContactOperator& op, const SolverSettings& settings,
                                         const std::vector<Eigen::Vector3d>& warm_start = {},
                                         StickSolveBackoff* backoff = nullptr,
                                         const std::vector<Eigen::Vector2d>& couple_warm_start = {},
                                         WorkerExchange* exchange = nullptr);

}  // namespace wiregrain
