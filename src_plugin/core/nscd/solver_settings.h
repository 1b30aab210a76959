// The settings of the contact solver (solve_frictional_contact, core/nscd/gauss_seidel.h):
// how it sweeps, when it stops and what it adds to the sweeps; they do not change the
// problem it solves. The time-stepping law that makes the problem (θ, restitution,
// overlap recovery) is MoreauJeanLaw (core/nscd/nscd_step.h), the grains' coefficients
// (friction, damping, ...) GrainStepOptions (core/nscd/grain_step.h).
//
// The defaults below are the core's (a solve_nscd_step or solve_reduced called with
// SolverSettings()). fix nscd/polyhedra starts from grain_solver_defaults()
// (core/nscd/grain_step.h) instead: forward order, the natural_map measure and method
// subspace, the tolerance and the cap as here.
#pragma once

#include <cstdint>

namespace wiregrain {

enum class SweepOrder {
  forward,      // 0, 1, …, n−1 every sweep
  alternating,  // forward, then backward (n−1, …, 0), and so on (symmetric Gauss–Seidel)
  random,       // a new random permutation every sweep (seeded, reproducible)
  coloured      // colour by colour of a greedy colouring of the contact graph, each colour in
                // the forward order (core/nscd/contact_colouring.h; bodies only)
};

// The stopping measures (core/nscd/gauss_seidel.h, "Stopping").
enum class ConvergenceMeasure { increment, natural_map, increment_then_natural_map };

// gauss_seidel: sweeps only. subspace: sweeps, and between them a direct solve on the
// closed contacts (core/nscd/subspace_correction.h).
enum class SolverMethod { gauss_seidel, subspace };

// Defaults: random order and the increment-then-natural-map measure. Measured on a
// column of 20 frictional cubes (4 points per interface, docs/design.md, "The sweep"): to a Siconos
// error of 1e-6 the forward order needs ~230000 sweeps, alternating ~17000, random ~6500;
// with the forward order the increment sat near 4e-6 per sweep while the interface loads
// were still 2e-4 off, so the tolerance is checked on the Siconos error before stopping.
struct SolverSettings {
  double tolerance = 1e-4;  // relative residual (the fix's default too; docs/design.md, "Convergence")
  int max_iterations = 1000;  // the sweep cap (the fix's default too)
  SweepOrder order = SweepOrder::random;  // the fix's default: forward
  std::uint64_t seed = 1;  // random order
  double relaxation = 1.0;  // ω in (0, 2): r ← ω r_local + (1 − ω) r
  ConvergenceMeasure measure = ConvergenceMeasure::increment_then_natural_map;  // the fix's: natural_map
  SolverMethod method = SolverMethod::gauss_seidel;  // the fix's default: subspace
  // subspace: Tikhonov weight ε of the stick solve, relative to each row's diagonal of W
  double subspace_regularization = 1e-9;
  // subspace: a solve that converged without a kept stick solve gets the closing one only
  // if its Siconos error is above subspace_closing × tolerance (0: always)
  double subspace_closing = 0.0;
  // Freezing (the idea of Siconos' fc3d_nsgs "freezing contacts"): a contact whose impulse
  // changed by at most tolerance × |r_c| in a sweep is skipped in the next `freeze` sweeps
  // (its impulse held; the Siconos error, computed on every contact, still decides the
  // stop). 0: off. Needs a measure with the Siconos error (not `increment`).
  int freeze = 0;

  // InvalidArgument("tolerance" | "max_iterations" | "relaxation" |
  // "subspace_regularization" | "subspace_closing" | "freeze", ...) on values outside the
  // ranges.
  void validate() const;
};

}  // namespace wiregrain
