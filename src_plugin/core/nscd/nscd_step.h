// One Moreau–Jean contact solve of rigid bodies: the bodies, the contacts, the
// time-stepping law (MoreauJeanLaw) and solve_nscd_step.
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
// the standard one with u_n ≥ 0 (core/nscd/coulomb_local.h). θ ∈ [1/2, 1]; default θ = 1
// (positions advanced with the end-of-step velocity, as core/nscd/rigid_body.h's
// Moreau–Jean step does). With θ < 1 an impacting contact is pushed out at
// (1 − θ)/θ |u_n^k|, an elastic-like bounce of the gap prediction, hence the default.
//
// The solve: the body operator (core/nscd/body_operator.h: u_c = H_c V + s_c e_n from the
// bodies' velocities, W never formed) swept by solve_frictional_contact
// (core/nscd/gauss_seidel.h) with the caller's SolverSettings.
#pragma once

#include <Eigen/Dense>

#include <memory>
#include <vector>

#include "core/common/worker_exchange.h"
#include "core/nscd/gauss_seidel.h"

namespace wiregrain {

using Vector6d = Eigen::Matrix<double, 6, 1>;
// Maps one body's (v, ω) to its part of the local relative velocity (u_n, u_t1, u_t2).
using ContactJacobian = Eigen::Matrix<double, 3, 6>;

// The time-stepping law of a step (see the top of this file): what the contacts must
// satisfy at its end, which the solver's settings do not change. The defaults are the
// core's: θ = 1, perfectly inelastic, the whole overlap removed in one step with no cap
// on the push-out speed. fix nscd/polyhedra starts from grain_law_defaults()
// (core/nscd/grain_step.h) instead: β = 0 and v_o = 0.1.
struct MoreauJeanLaw {
  double theta = 1.0;             // θ ∈ [0.5, 1]
  double restitution = 0.0;       // e ∈ [0, 1]
  double overlap_recovery = 1.0;  // β ∈ [0, 1]: fraction of an overlap removed per step
  double overlap_speed = 1e300;   // v_o ≥ 0: largest push-out speed (none by default here)

  // InvalidArgument("theta" | "restitution" | "overlap_speed" | "overlap_recovery", ...)
  // on values outside the ranges.
  void validate() const;
};

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
  // Rolling resistance (not in the paper; solve_nscd_step only; core/nscd/body_operator.h,
  // "Rolling resistance"): the largest rolling couple is μ_r R r_n, with
  // μ_r = rolling_friction ≥ 0 (0: none) and R = rolling_radius > 0 (a length: the radius
  // the bodies roll on).
  double rolling_friction = 0.0;
  double rolling_radius = 0.0;
  // Zero: the couple may point anywhere in the tangent plane. Else a unit vector of the
  // tangent plane (world frame): the couple only along it, |m| ≤ μ_r R r_n (a pair whose
  // points resist rolling about the other axis themselves, e.g. an edge on a face; see
  // rolling_axes in core/nscd/rolling_axes.h).
  Eigen::Vector3d rolling_axis = Eigen::Vector3d::Zero();
};

struct NscdStep {
  double time_step = 0.0;  // h > 0
  MoreauJeanLaw law;
  std::vector<NscdBody> bodies;
  std::vector<NscdContact> contacts;
  // A step spread over workers (solve_nscd_step with a WorkerExchange; fix nscd/polyhedra's
  // `solve distributed`): each worker holds the contacts it owns and, as bodies, the
  // bodies they touch, its own and copies of other workers'. Mass splitting (Tonge,
  // Benevolenski & Voroshilov, "Mass splitting for jitter-free parallel rigid body
  // simulation", ACM Trans. Graph. 31(4):105, 2012): a body whose copies on k workers are
  // touched by contacts is swept on each with the mass m / k (inertia I / k), and after
  // each sweep every copy takes
  //     V = V_sync + (1/k) Σ_copies (V_copy − V_sync),
  // V_sync its velocity after the last exchange: the mean of the copies, i.e. all the
  // copies' impulse increments applied to the true mass. It is a Gauss–Seidel sweep
  // within a worker and a Jacobi step across workers that cannot overshoot where several
  // workers push one body (each sees it k times lighter). touching_copies: per body, k
  // (0: no contact of any worker touches it). distributed: the step is one worker's part
  // (touching_copies then has one entry per body; a worker may hold no body at all).
  bool distributed = false;
  std::vector<double> touching_copies;
};

struct NscdStepResult {
  ContactSolution contacts;
  std::vector<Eigen::Vector3d> velocities;          // v_{k+1} per body
  std::vector<Eigen::Vector3d> angular_velocities;  // ω_{k+1} per body
  double max_overlap = 0.0;              // max(0, −min g_c) at the step start
  double max_predicted_penetration = 0.0;  // max(0, −min(g_c + h((1−θ)u_n^k + θ u_n^{k+1})))
};

// One Moreau–Jean contact solve: impulses and end-of-step velocities. Throws
// InvalidArgument(settings' keywords | law keywords | "time_step" | "bodies" |
// "contacts", ...) on bad input (body index out of range, a contact whose Delassus block
// has W_nn ≤ 0, e.g. between two infinite masses; negative inverse mass; μ < 0; non-finite
// data). warm_start, backoff, couple_warm_start: as solve_frictional_contact's.
// exchange: the workers' communication of a distributed step (NscdStep::touching_copies;
// core/common/worker_exchange.h), null for a step held by one worker. Distributed, the
// sweeps alternate with exchanges of the copies' velocities, the stopping measures are
// summed over the workers (every worker stops after the same sweep), method subspace's
// stick solves are solved by conjugate gradients over all workers
// (core/nscd/distributed_stick_solve.h), and rolling resistance is refused
// (InvalidArgument("exchange", ...)).
NscdStepResult solve_nscd_step(const NscdStep& step, const SolverSettings& settings,
                               const std::vector<Eigen::Vector3d>& warm_start = {},
                               StickSolveBackoff* backoff = nullptr,
                               const std::vector<Eigen::Vector2d>& couple_warm_start = {},
                               WorkerExchange* exchange = nullptr);

// The operator solve_nscd_step sweeps on, for tests and benchmarks of the sweep itself;
// the same InvalidArgument as solve_nscd_step on a bad step.
std::unique_ptr<ContactOperator> body_contact_operator(const NscdStep& step);

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

}  // namespace wiregrain
