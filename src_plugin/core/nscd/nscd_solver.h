// The Non-Smooth Contact Dynamics (Moreau–Jean) contact solver: nonlinear Gauss–Seidel
// over contact points with the exact local Signorini–Coulomb solution. Including this
// header gives all of it; its parts, one idea each:
//
//   nscd_step.h             the bodies and contacts of a time step, the time-stepping law
//                           (MoreauJeanLaw: θ, restitution, overlap recovery) and
//                           solve_nscd_step; the formulation and its equations
//   solver_settings.h       SolverSettings: order, seed, tolerance, measure, cap, method,
//                           freezing, the stick solves' regularisation and closing
//   contact_operator.h      what the solver sees of a problem (a Delassus operator and the
//                           cones) and the Siconos error
//   gauss_seidel.h          the solver: the sweep and the stopping measures
//   subspace_correction.h   method subspace: the stick solves between the sweeps, their
//                           schedule and the backoff across solves
//   body_operator.h         the operator on bodies (W never formed) and rolling resistance
//   reduced_problem.h       the operator on W given as 3×3 blocks (FCLib's local problem)
//   block_sparse_matrix.h   W as 3×3 blocks
//   coulomb_local.h         the local Signorini–Coulomb problem of one contact
#pragma once

#include "core/nscd/block_sparse_matrix.h"
#include "core/nscd/contact_operator.h"
#include "core/nscd/gauss_seidel.h"
#include "core/nscd/nscd_step.h"
#include "core/nscd/reduced_problem.h"
#include "core/nscd/solver_settings.h"
