// Non-Smooth Contact Dynamics (Moreau–Jean) contact solver: nonlinear Gauss–Seidel over
// contact points with the exact local Signorini–Coulomb solution (core/coulomb_local.h).
//
// Moreau–Jean time stepping (Jean, Comput. Methods Appl. Mech. Engrg. 177 (1999) 235; the
// paper's Sec. 2.1): over a step h, with M the body mass matrix, H the contact Jacobian
// (local relative velocity u = H V, V = (v, ω) per body) and r the contact impulses,
//     M (V_{k+1} − V_k) = h f + Hᵀ r,            i.e.  V_{k+1} = V_free + M⁻¹ Hᵀ r,
//     X_{k+1} = X_k + h ((1 − θ) V_k + θ V_{k+1})      (θ-method position update),
// with V_free = V_k + h M⁻¹ f the free velocity after the external forces (f independent
// of the velocity: gravity, the wire forces averaged over the sub-steps). Substituting,
// u_{k+1} = W r + q with the Delassus operator W = H M⁻¹ Hᵀ and q = H V_free.
//
// Contact law, per contact point c (gap g_c ≥ 0 open, < 0 overlap, at the step start):
// the predicted end-of-step gap g_c + h((1 − θ) u_n^k + θ u_n^{k+1}) must be ≥ 0, i.e.
//     u_n^{k+1} + s_c ≥ 0,   s_c = (g_c / h + (1 − θ) u_n^k) / θ,
// (for θ = 1: g + h u_n ≥ 0, the gap anticipated at the step end). An overlap (g < 0) is
// removed only in part per step: g is replaced by max(β g, −v_o h), β = overlap_recovery
// ∈ [0, 1] (1: the whole overlap in one step; 0: overlaps are only kept from growing),
// v_o = overlap_speed ≥ 0 the largest push-out speed. The push-out speed is a real
// velocity: without the cap an overlap of 0.04 at h = 1e-3 (a grain created across a
// wall) would leave at 40. u_n^k = H V_k is the
// normal velocity at the step start. With restitution e > 0, a contact that would close
// within the step with its start velocity (u_n^k < 0 and g + h u_n^k ≤ 0) gets
// Newton's impact law u_n^{k+1} ≥ −e u_n^k on top: s_c = min(s_c, e u_n^k). e = 0 (the
// default) is perfectly inelastic. The shift s_c is added to q_n, so the local problem is
// the standard one with u_n ≥ 0 (core/coulomb_local.h). θ ∈ [1/2, 1]; default θ = 1
// (positions advanced with the end-of-step velocity, as core/rigid_body.h's Moreau–Jean
// step does). With θ < 1 an impacting contact is pushed out at (1 − θ)/θ |u_n^k|, an
// elastic-like bounce of the gap prediction, hence the default.
//
// The solver sees the problem only through a ContactOperator (the idea of Chrono's
// solver interface: a Delassus operator and a cone projector, not the engine): per
// contact its diagonal Delassus block W_cc, μ_c, the current local velocity
// u_c = (W r + q)_c, and a way to add an impulse increment. One Gauss–Seidel sweep:
//     for c in order:  q_loc = u_c − W_cc r_c   (velocity without the contact's own impulse)
//                      r_c ← ω solve_coulomb_local(W_cc, q_loc, μ_c) + (1 − ω) r_c
//                      apply Δr_c (the operator updates u of every contact it touches).
// Two operators share that sweep: BodyContactOperator (bodies, Jacobians; keeps the body
// velocities up to date, V += M⁻¹ Hᵀ Δr, never forms W) behind solve_nscd_step, and the
// reduced operator (W as 3×3 blocks, q, μ: the FCLib "local" problem) behind
// solve_reduced.
//
// Stopping: after each sweep, one of
//   increment         ‖Δr‖₂ / ‖r‖₂ over the sweep (absolute when r = 0) < tolerance;
//   natural_map       the Siconos error below < tolerance; its pass costs half a sweep, so
//                     it is made after each of the first 20 sweeps, then at doubling
//                     intervals of at most a twentieth of the sweeps done (the stop comes
//                     at most ~5 % late; on a 3×3×3 lattice pile 1042 sweeps at 68 µs
//                     instead of 1001 at 90 µs, fclib_nscd);
//   increment_then_natural_map   (default; after Siconos' default for fc3d_nsgs) once
//                     the increment is below the tolerance, the Siconos error must be too;
//                     while it is not, it is re-checked at doubling intervals (at most a
//                     twentieth of the sweeps done).
// or the iteration cap (hit_iteration_cap = true; both numbers are reported).
//
// Subspace correction (method subspace; the idea of the projected Gauss–Seidel subspace
// minimisation of Silcowitz, Niebe & Erleben, 2010). Gauss–Seidel settles which contacts
// are closed within a few sweeps but needs ~N² (a compressed chain) to ~N⁴ (welded
// interfaces: a bent beam) sweeps to carry a load through N bodies. So, between sweeps,
// the closed contacts S (loaded, r_n > 0 and not open in the last sweep, or closing or
// touching, u_n ≤ 1e-12 ‖q‖) are solved together as if they stuck, the impulses of the
// others held: the increment closest to the current impulses that brings u_S to 0,
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
// way. Schedule: a first solve after sweep 2, the next 2 sweeps after a solve that cut
// the error tenfold, else twice the last wait (2, 4, 8, …), and none after three dropped
// in a row. A solve that converges without a kept stick solve (a warm start already
// within the tolerance) gets one at the end: errors left within the tolerance otherwise
// add up step after step (a 20-box stack at tolerance 1e-4 drifts and falls; with it
// the loads stay exact to 1e-14) — unless its Siconos error is already at most
// subspace_closing × tolerance (default 0: always). Where something disturbs the
// contacts every step, the exactness does not last: a coupled column at rest comes out of
// its single sweep at an error of ~1e-6 each step (the wire's forces change), the closing
// solve takes it to 3e-18 and the next step is back at 1e-6; there the closing solve is
// most of the step's cost (in.column leaves it out in its relaxation, docs/design.md, "Subspace correction").
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
// Rolling resistance (NscdContact::rolling_friction μ_r > 0 and rolling_radius R; not in
// the paper, whose contacts have none; bodies only). A contact also carries a couple m (its tangential components
// t1, t2: a pure couple, +m on b and −m on a) against the rolling part of the relative
// angular velocity, w = Tᵀ (ω_b − ω_a), T = (t1 t2), w = W_r m + w_free with
// W_r = Tᵀ (I_a⁻¹ + I_b⁻¹) T; the law is Coulomb's on a disc:
//     |m| ≤ μ_r R r_n,  and w = 0, or w = −λ m with λ ≥ 0 and |m| = μ_r R r_n
// (the couple resists rolling as the tangential impulse resists sliding; the spin about
// n is not resisted). In a sweep, after a contact's 3×3 block, its couple is solved with
// the new r_n: m = −W_r⁻¹ w_free if that is in the disc, else the m on the disc's edge
// with m = −(W_r + σ I)⁻¹ w_free, σ ≥ 0 (a 2×2 secular equation, Newton on
// 1/|m(σ)| − 1/(μ_r R r_n) from σ = 0, monotone as for a trust region); a contact with a
// rolling axis a (NscdContact::rolling_axis) takes m = m_a a, the stick value
// −aᵀ w_free / aᵀ W_r a clamped to ± μ_r R r_n. Couples start from the caller's couple
// warm start (else 0). A solve is converged only once the couples satisfy their law too:
// with a measure that computes the Siconos error, the rolling law's natural-map residual
// written as the Siconos error writes Coulomb's (the couple as the impulse m / R at the
// rolling radius, the rolling velocity as the surface speed w R, ρ = 1),
//     sqrt(Σ_c |m_c/R_c − proj_{D_c}(m_c/R_c − R_c w_c)|²) ≤ tolerance × max(‖q‖, ‖r‖),
// D_c the disc of radius μ_r r_n; with `increment`, the couples' increment in the last
// sweep at most tolerance × the bounds' norm. (Measured against |m| itself the test
// never passes where the couples are ~0: a box at rest hits the sweep cap every step;
// relative to the bounds' norm it asks 1/μ_r times the accuracy of Coulomb's law: the
// 500-grain deposit takes 180–370 sweeps per step while it lands, against 8–15 with the
// form above; 2026-11-27, commit b774b66; docs/design.md, "Rolling resistance".) Stick
// solves hold couples as they are and would leave them one update behind, so method
// subspace makes none when any contact has a rolling resistance. A sphere (a point swept
// by r, R = r) on a plane decelerates at (5/7) μ_r g while it rolls and rests on an
// incline while tan α ≤ μ_r (core test NscdRolling).
// Siconos error (fc3d_compute_error of Siconos numerics 4.4 as fc3d_nsgs calls it, with
// the De Saxcé modified velocity, natural_map_residual in core/coulomb_local.h):
//     error = sqrt(Σ_c ‖r_c − proj_{K_μc}(r_c − u_c − μ_c ‖u_t,c‖ e_n)‖²)
//             / max(‖q‖, ‖r‖, ‖u‖)
// (no division when the maximum is ≤ DBL_EPSILON). The normalisation was measured on the
// installed library (Debian's 4.4; releases before 4.x divided by 1 + ‖q‖);
// bench/fclib_nscd prints both values for every solve.
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/nscd/coulomb_local.h"

namespace wiregrain {

using Vector6d = Eigen::Matrix<double, 6, 1>;
// Maps one body's (v, ω) to its part of the local relative velocity (u_n, u_t1, u_t2).
using ContactJacobian = Eigen::Matrix<double, 3, 6>;

enum class SweepOrder {
  forward,      // 0, 1, …, n−1 every sweep
  alternating,  // forward, then backward (n−1, …, 0), and so on (symmetric Gauss–Seidel)
  random        // a new random permutation every sweep (seeded, reproducible)
};

enum class ConvergenceMeasure { increment, natural_map, increment_then_natural_map };

// gauss_seidel: sweeps only. subspace: sweeps, and between them a direct solve on the
// closed contacts (see "Subspace correction" at the top of this file).
enum class SolverMethod { gauss_seidel, subspace };

// Defaults: random order and the increment-then-natural-map measure. Measured on a
// column of 20 frictional cubes (4 points per interface, docs/design.md, "The sweep"): to a Siconos
// error of 1e-6 the forward order needs ~230000 sweeps, alternating ~17000, random ~6500;
// with the forward order the increment sat near 4e-6 per sweep while the interface loads
// were still 2e-4 off, so the tolerance is checked on the Siconos error before stopping.
struct NscdOptions {
  double tolerance = 1e-4;  // relative residual (the fix's default; docs/design.md, "Convergence")
  int max_iterations = 1000;
  SweepOrder order = SweepOrder::random;
  std::uint64_t seed = 1;  // random order
  double relaxation = 1.0;  // ω in (0, 2): r ← ω r_local + (1 − ω) r
  ConvergenceMeasure measure = ConvergenceMeasure::increment_then_natural_map;
  SolverMethod method = SolverMethod::gauss_seidel;
  // subspace: Tikhonov weight ε of the stick solve, relative to each row's diagonal of W
  double subspace_regularization = 1e-9;
  // subspace: a solve that converged without a kept stick solve gets the closing one only
  // if its Siconos error is above subspace_closing × tolerance (0: always)
  double subspace_closing = 0.0;
  // Moreau–Jean law (solve_nscd_step and assemble_reduced only; see above).
  double theta = 1.0;        // [0.5, 1]
  double restitution = 0.0;  // [0, 1]
  double overlap_recovery = 1.0;  // β ∈ [0, 1]: fraction of an overlap removed per step
  double overlap_speed = 1e300;   // v_o ≥ 0: largest push-out speed (none by default here)
  // Freezing (the idea of Siconos' fc3d_nsgs "freezing contacts"): a contact whose impulse
  // changed by at most tolerance × |r_c| in a sweep is skipped in the next `freeze` sweeps
  // (its impulse held; the Siconos error, computed on every contact, still decides the
  // stop). 0: off. Needs a measure with the Siconos error (not `increment`).
  int freeze = 0;

  // InvalidArgument("tolerance" | "max_iterations" | "relaxation" | "theta" |
  // "restitution" | "overlap_recovery" | "overlap_speed" | "freeze" |
  // "subspace_regularization" | "subspace_closing", ...) on values outside
  // the ranges.
  void validate() const;
};

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
  int subspace_factorizations = 0;     // numerical LDLᵀ factorisations they made
  long frozen_updates = 0;             // contact updates skipped (freeze)
};

// n × n blocks of 3×3, stored by block row (each row sorted by column).
class BlockSparseMatrix3 {
 public:
  struct Entry {
    int column;
    Eigen::Matrix3d block;
  };

  BlockSparseMatrix3() = default;
  explicit BlockSparseMatrix3(int block_count);

  int block_count() const { return static_cast<int>(rows_.size()); }
  long stored_blocks() const;
  // Adds `block` to block (row, column), creating it if absent.
  void add(int row, int column, const Eigen::Matrix3d& block);
  // nullptr when the block is not stored.
  const Eigen::Matrix3d* find(int row, int column) const;
  const std::vector<Entry>& row(int row) const { return rows_[row]; }

  // Keeps the blocks with at least one non-zero entry. dense: 3n × 3n.
  static BlockSparseMatrix3 from_dense(const Eigen::MatrixXd& dense);
  Eigen::MatrixXd to_dense() const;
  Eigen::VectorXd multiply(const Eigen::VectorXd& x) const;

 private:
  std::vector<std::vector<Entry>> rows_;
};

// What the Gauss–Seidel solver needs from a problem. The operator starts in the state
// r = 0 (velocity(c) = q_c) and follows the increments given to add_impulse.
class ContactOperator {
 public:
  virtual ~ContactOperator() = default;
  virtual int contact_count() const = 0;
  virtual const LocalDelassus& delassus_block(int contact) const = 0;
  virtual double friction_coefficient(int contact) const = 0;
  // u_c = (W r + q)_c for the impulses added so far.
  virtual Eigen::Vector3d velocity(int contact) const = 0;
  // Its normal component alone, equal to velocity(contact)[0] to the bit: the sweep's test
  // of a contact without impulse that stays open (u_n ≥ 0: r = 0 is its local solution).
  virtual double normal_velocity(int contact) const { return velocity(contact)[0]; }
  // r_c += delta; updates what velocity() depends on.
  virtual void add_impulse(int contact, const Eigen::Vector3d& delta) = 0;
  // ‖q‖ (all contacts), the Siconos error's normalisation.
  virtual double free_velocity_norm() const = 0;
  // W itself (method subspace only; may be assembled on the first call).
  virtual const BlockSparseMatrix3& delassus_matrix() = 0;
};

// method subspace from one solve to the next (a time step to the next; header): after a
// solve whose stick solves did harm and none was kept, the next `wait` solves make none,
// wait doubling 1, 2, 4, … up to 1024 while that goes on; a kept one sets it back to 0.
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
// operator before the first sweep. InvalidArgument("warm_start", ...) on a size mismatch.
// backoff: the state carried between the solves of a run (method subspace), or nullptr.
// couple_warm_start: empty, or one rolling couple per contact (t1, t2 components),
// applied with the impulses; entries of contacts without rolling resistance (all of them
// on an operator other than solve_nscd_step's) are ignored.
ContactSolution solve_frictional_contact(ContactOperator& op, const NscdOptions& options,
                                         const std::vector<Eigen::Vector3d>& warm_start = {},
                                         StickSolveBackoff* backoff = nullptr,
                                         const std::vector<Eigen::Vector2d>& couple_warm_start = {});

// Siconos error of impulses r on an operator in the state r (see the top of this file).
double siconos_error(const ContactOperator& op, const std::vector<Eigen::Vector3d>& impulses);

// ---------------------------------------------------------------------------------------
// Bodies and contacts of one time step.

struct NscdBody {
  double inverse_mass = 0.0;                                    // 0: infinite mass
  Eigen::Matrix3d inverse_inertia = Eigen::Matrix3d::Zero();    // world frame
  Eigen::Vector3d velocity_begin = Eigen::Vector3d::Zero();     // v_k
  Eigen::Vector3d angular_velocity_begin = Eigen::Vector3d::Zero();  // ω_k
  Eigen::Vector3d velocity_free = Eigen::Vector3d::Zero();      // v_k + h f / m
  Eigen::Vector3d angular_velocity_free = Eigen::Vector3d::Zero();   // ω_k + h I⁻¹ T
};

struct NscdContact {
  int body_a = -1;  // index into NscdStep::bodies, −1 for none (a fixed wall)
  int body_b = -1;
  // u = H_a (v_a, ω_a) + H_b (v_b, ω_b) + velocity_offset, local frame (n, t1, t2).
  ContactJacobian jacobian_a = ContactJacobian::Zero();
  ContactJacobian jacobian_b = ContactJacobian::Zero();
  // Relative velocity from kinematically driven parts not in `bodies` (a moving wall),
  // the same at the start and end of the step.
  Eigen::Vector3d velocity_offset = Eigen::Vector3d::Zero();
  double friction = 0.0;  // μ ≥ 0
  double gap = 0.0;       // g at the step start (< 0: overlap)
  // Rolling resistance (not in the paper; solve_nscd_step only; "Rolling resistance"
  // above): the largest rolling couple is μ_r R r_n, with μ_r = rolling_friction ≥ 0
  // (0: none) and R = rolling_radius > 0 (a length: the radius the bodies roll on).
  double rolling_friction = 0.0;
  double rolling_radius = 0.0;
  // Zero: the couple may point anywhere in the tangent plane. Else a unit vector of the
  // tangent plane (world frame): the couple only along it, |m| ≤ μ_r R r_n (a pair whose
  // points resist rolling about the other axis themselves, e.g. an edge on a face; see
  // rolling_axes in core/nscd/grain_step.h).
  Eigen::Vector3d rolling_axis = Eigen::Vector3d::Zero();
};

struct NscdStep {
  double time_step = 0.0;  // h > 0
  std::vector<NscdBody> bodies;
  std::vector<NscdContact> contacts;
};

struct NscdStepResult {
  ContactSolution contacts;
  std::vector<Eigen::Vector3d> velocities;          // v_{k+1} per body
  std::vector<Eigen::Vector3d> angular_velocities;  // ω_{k+1} per body
  double max_overlap = 0.0;              // max(0, −min g_c) at the step start
  double max_predicted_penetration = 0.0;  // max(0, −min(g_c + h((1−θ)u_n^k + θ u_n^{k+1})))
};

// One Moreau–Jean contact solve: impulses and end-of-step velocities. Throws
// InvalidArgument("time_step" | "bodies" | "contacts" | options keywords, ...) on bad input
// (body index out of range, a contact whose Delassus block has W_nn ≤ 0, e.g. between two
// infinite masses; negative inverse mass; μ < 0; non-finite data).
NscdStepResult solve_nscd_step(const NscdStep& step, const NscdOptions& options,
                               const std::vector<Eigen::Vector3d>& warm_start = {},
                               StickSolveBackoff* backoff = nullptr,
                               const std::vector<Eigen::Vector2d>& couple_warm_start = {});

// The operator solve_nscd_step sweeps on (u_c = H_c V + s_c e_n from the bodies'
// velocities V, W never formed), for tests and benchmarks of the sweep itself; the same
// InvalidArgument as solve_nscd_step on bad input.
std::unique_ptr<ContactOperator> body_contact_operator(const NscdStep& step, const NscdOptions& options);

// Local frame from a unit normal n (normalised here): columns (n, t1, t2), right-handed,
// t1 ⟂ n chosen from the coordinate axis least aligned with n.
Eigen::Matrix3d contact_frame(const Eigen::Vector3d& normal);
// Jacobian block of a body for a contact point at lever arm p − x_body, frame columns
// (n, t1, t2): u += sign · frameᵀ (v + ω × arm), sign = +1 for body_b, −1 for body_a
// (u is the velocity of b relative to a; n points from a to b).
ContactJacobian contact_jacobian(const Eigen::Matrix3d& frame, const Eigen::Vector3d& arm,
                                 double sign);

// θ-method displacement over a step: h ((1 − θ) v_k + θ v_{k+1}).
inline Eigen::Vector3d theta_method_displacement(const Eigen::Vector3d& v_begin,
                                                 const Eigen::Vector3d& v_end, double h,
                                                 double theta) {
  return h * ((1.0 - theta) * v_begin + theta * v_end);
}

// ---------------------------------------------------------------------------------------
// Reduced ("local" in FCLib's words) problem: u = W r + q, W given as 3×3 blocks.

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
// options (θ, restitution). Its solution equals solve_nscd_step's (same sweep).
ReducedProblem assemble_reduced(const NscdStep& step, const NscdOptions& options);

ContactSolution solve_reduced(const ReducedProblem& problem, const NscdOptions& options,
                              const std::vector<Eigen::Vector3d>& warm_start = {});

// Siconos error of impulses r (one per contact) for a reduced problem.
double siconos_error(const ReducedProblem& problem, const std::vector<Eigen::Vector3d>& r);

}  // namespace wiregrain
