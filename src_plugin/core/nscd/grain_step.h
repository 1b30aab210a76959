// One Moreau–Jean step of rigid spheropolyhedral grains against each other and against
// plane walls (the paper's Sec. 2.1; docs/design.md, "The NSCD step and its solver"): what
// fix nscd/polyhedra does each step, without LIGGGHTS.
//
//  1. free velocities with implicit viscous damping at rate γ (not in the paper; for
//     relaxing a deposit): m (v_{k+1} − v_k) = h F − h γ m v_{k+1} + Hᵀ r, i.e.
//         v_free = (v_k + h F/m) / (1 + hγ),  the impulses see the mass (1 + hγ) m,
//     and for the rotation, with I_w = R diag(I) Rᵀ the world inertia,
//         ω_free = I_w⁻¹ (I_w ω_k + h T) / (1 + hγ)
//     (so a grain at rest still presses with its full weight);
//  2. contact points (core/geometry/contact_manifold.h) of every grain pair and every
//     grain–wall pair whose gap may close within the step: activation distance
//         d_act = margin + 2h (2 max_i(|v_free,i| + |ω_free,i| R_i) + max wall speed),
//     pairs from a broad-phase grid (core/geometry/broad_phase.h) of cell 2 R_max + d_act;
//  3. the points listed from the top down (descending z of the point, ties in detection
//     order: grain pairs by grain index, then walls): a forward Gauss–Seidel sweep then
//     carries the weight of a pile under gravity along −z to the floor in one pass (the
//     order changes the sweeps needed, not the solution);
//  4. warm start: each point starts from last step's impulse of the nearest stored point
//     of the same pair within R_max / 4 (GrainImpulseMemory);
//  5. solve_nscd_step (core/nscd/nscd_step.h), then per grain the contact force and
//     torque Hᵀ r / h, the force of the grains on each wall, and the contact list.
// The position update that follows the step is advance_grain_pose, then the projection of
// the overlaps it leaves (core/nscd/overlap_projection.h).
//
// Sleeping (not in the paper; off unless SleepOptions::speed > 0; the design and
// its measurements: docs/design.md, "Sleeping grains"). A grain whose speed
// |v| + |ω| R (R its bounding radius) stays below v_sleep for t_sleep falls asleep once
// every grain supporting it (a contact impulse on it against its external force) sleeps
// or falls asleep in the same step: its velocities are set to zero and it is held. A
// sleeping grain
//  - is a body of infinite mass in the solve (it takes the impulses of awake grains
//    touching it and does not move);
//  - has no contact detection with other sleeping grains or with walls: those contacts
//    are frozen, kept with their impulses, and still reported and counted in the grain's
//    contact force and the walls' forces;
//  - after each solve, is checked for equilibrium: solved alone, from the top of the pile
//    down, as a body starting at its drift velocity, loaded by h F, the awake grains'
//    impulses and the frozen points of the sleepers above it, held by its other frozen
//    points (partners fixed). Its end velocity is its new drift; up to v_sleep it stays
//    asleep and its frozen points take the impulses found, so a new load is carried
//    down to the floor in the step; above v_sleep it wakes (with the sleepers resting on
//    it: a frozen point supporting them) from its drift at the step start, its frozen points
//    become contact points and the step is solved again, until every sleeper stays;
//  - wakes at the start of a step when the deck gave it a velocity or a moving wall can
//    reach it within the step.
// What sleeping changes: a grain's velocity below v_sleep is dropped when it falls
// asleep; a sleeper moves only once its drift passes v_sleep (an unbalanced load f m g
// within v_sleep / (f g h) steps); the load sharing in a sleeping pile is the one the
// top-down checks give (the same statics; the split among redundant supports may
// differ); a pair of sleeping grains whose gap exceeded the activation distance when they
// fell asleep is not looked at until one wakes, and a frozen point counts as touching.
// Identities are grain tags; a wall w is −(w + 1) (as in core/contact/contact_list.h).
#pragma once

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "core/common/work_share.h"
#include "core/common/worker_exchange.h"
#include "core/contact/contact_list.h"
#include "core/geometry/periodic_box.h"
#include "core/geometry/shape_library.h"
#include "core/nscd/grain_impulse_memory.h"
#include "core/nscd/grain_pairs.h"
#include "core/nscd/nscd_solver.h"
#include "core/nscd/rolling_axes.h"

namespace wiregrain {

struct GrainState {
  long tag = 0;
  int shape = 0;                                                      // ShapeLibrary index
  Eigen::Vector3d position = Eigen::Vector3d::Zero();                 // centre of mass
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();    // body → world, unit
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();         // world frame
  Eigen::Vector3d force = Eigen::Vector3d::Zero();                    // external, this step
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();                   // external, about the centre
  double mass = 1.0;
  Eigen::Vector3d inertia = Eigen::Vector3d::Ones();                  // principal moments (body axes)
  // sleeping (SleepOptions; the caller keeps these from step to step): asleep, the time it
  // has been below the sleep speed, and while asleep its drift (v, ω) and the net load
  // impulse and moment on it at its last equilibrium check (the header)
  bool asleep = false;
  double quiet_time = 0.0;
  Eigen::Vector3d drift = Eigen::Vector3d::Zero(), drift_angular = Eigen::Vector3d::Zero();
  Eigen::Vector3d load = Eigen::Vector3d::Zero(), load_moment = Eigen::Vector3d::Zero();
};

// A plane through `point`, unit `normal` into the grains, moving at `velocity` (the
// caller moves `point`).
//
// mass = 0 (the default): a wall of infinite mass, its motion prescribed.
// mass m_p > 0: a plate, a body of the step that translates along its normal only (one
// degree of freedom, no rotation). `velocity` is then its velocity v_k at the step start,
// along the normal, and `force` the external force on it over the step (an applied load,
// its weight, a spring; only the normal component acts). In the Moreau–Jean step it is
// an unknown like the grains' velocities:
//     v_free = v_k + h (n·F) n / m_p,    v_{k+1} = v_free + M_p⁻¹ Σ_c H_cᵀ r_c,
// with the inverse mass matrix M_p⁻¹ = n nᵀ / m_p: the plate is an NscdBody of inverse
// mass 1/m_p and zero inverse inertia, appended after the grains, and each of its
// contact rows has body_a = the plate and the Jacobian block H_a = −frameᵀ n nᵀ (linear
// part; angular part 0), so that H_a M⁻¹ H_aᵀ = frameᵀ n nᵀ frame / m_p and every
// impulse moves it along n only. GrainStepResult::wall_velocities gives v_{k+1}; the
// caller moves `point` by the θ-method displacement h ((1 − θ) v_k + θ v_{k+1}) (as
// the grains: wall_step_displacement). It is not damped (GrainStepOptions::damping is
// the grains'). The grains' contact points with it are wall points (pair key
// −(w + 1), grain_wall records, its force in GrainStepResult::wall_forces); the overlap
// projection (core/nscd/overlap_projection.h) moves it by its θ-method displacement and
// treats it as immovable when it pushes a grain out of it. Sleeping: at each step
// start a plate wakes every sleeping grain within its reach, margin + 4 h max(|v_k|,
// |v_free|), at rest too (a sleeping grain's frozen point would not push the plate back).
struct PlaneWall {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  double friction = 0.5;
  double mass = 0.0;                                 // m_p ≥ 0; 0: infinite (prescribed motion)
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // on a plate, over the step
  bool plate() const { return mass > 0.0; }
  // a plate's free velocity v_k + h (n·F) n / m_p
  Eigen::Vector3d free_velocity(double h) const {
    return (normal.dot(velocity) + h * normal.dot(force) / mass) * normal;
  }
};

// A wall's displacement over a step: h ((1 − θ) v_k + θ v_{k+1}) for a plate
// (v_{k+1} = velocity_end, its solved velocity), h v for a wall of infinite mass.
Eigen::Vector3d wall_step_displacement(const PlaneWall& wall, const Eigen::Vector3d& velocity_end, double h,
                                       double theta);

// fix nscd/polyhedra's defaults (docs/commands/fix_nscd_polyhedra.md), which differ from
// the core's (SolverSettings(), MoreauJeanLaw()): the solver sweeps in the forward order
// with Siconos' natural-map residual and method subspace (the tolerance and the cap are
// SolverSettings'); the law keeps overlaps from growing (β = 0) and pushes them out at
// most at 0.1 (the rest of it, θ = 1 and e = 0, as the core's).
SolverSettings grain_solver_defaults();
MoreauJeanLaw grain_law_defaults();

// See the header comment; fix keyword `sleep v_sleep t_sleep`.
struct SleepOptions {
  double speed = 0.0;  // v_sleep ≥ 0; 0: nothing sleeps
  double time = 0.5;   // t_sleep > 0
  bool on() const { return speed > 0.0; }
};

// What a grain step solves and how: the solver's settings, the time-stepping law, the
// grains' coefficients and the contact detection's options. The defaults are fix
// nscd/polyhedra's.
struct GrainStepOptions {
  SolverSettings solver = grain_solver_defaults();  // solver.seed: base of the per-step seed
  MoreauJeanLaw law = grain_law_defaults();         // θ (also the pose update's), e, β, v_o
  double friction = 0.5;   // μ between grains
  double damping = 0.0;    // γ ≥ 0
  double margin = 0.0;     // extra activation distance ≥ 0
  bool warm_start = true;
  // contact points: the closest features plus every vertex within the activation
  // distance (ContactOptions::near_vertices; fix keyword `manifold near_vertices`), or the
  // closest features only (`manifold closest`)
  bool near_vertices = true;
  // GJK of a pair kept by the pair cache starts from the simplex of the pair's last
  // narrow phase (GjkSimplex, core/geometry/gjk.h; fix keyword
  // `warm_geometry`): the same contacts to GJK's tolerance, not to the bit. Without the
  // cache (skin 0) every GJK starts cold. Off by default: over 18 paired seeds of the
  // reduced column it moved H_n by +2.85 and φ_p by +2.40 standard errors (2026-11-28,
  // commit a5dadca).
  bool warm_geometry = false;
  // rolling resistance μ_r ≥ 0 (not in the paper; fix keyword `rolling_friction`): each
  // contact point resists rolling with a couple of at most μ_r R r_n, R the sum of the
  // two sweep radii (a wall's is 0): the radius of the rounded edges the grains roll on,
  // so sharp grains (R = 0) get none (core/nscd/body_operator.h, "Rolling resistance"),
  // about the axes its pair's points leave free (core/nscd/rolling_axes.h). 0: none. The
  // couples are warm-started as the impulses are.
  double rolling_friction = 0.0;
  SleepOptions sleep;
  // the simulation box (core/geometry/periodic_box.h): along its periodic dimensions
  // every grain pair is taken in its minimum image (the contact points lie by grain a,
  // the lever arms, warm starts, pair cache and overlap projection use minimum-image
  // displacements), walls must be parallel to them, and each periodic length must be at
  // least twice the pair reach 2 R_max + d_act + skin (InvalidArgument("box", ...) at the
  // step that exceeds it); no periodic dimension by default
  PeriodicBox box;
  // the solver's settings of a step: seed = solver.seed + step_number (a new random order
  // per step)
  SolverSettings solver_for_step(std::uint64_t step_number) const;
  // InvalidArgument(solver keywords | law keywords | "friction" | "damping" | "margin" |
  // "rolling_friction" | "sleep", ...)
  void validate() const;
};

// A grain step spread over workers that each own a part of the grains (fix
// nscd/polyhedra's `solve distributed`: the MPI ranks and their subdomains;
// core/common/worker_exchange.h). A worker's grains are its own, grains[0, owned) in
// ascending tag order, followed by copies of other workers' grains within the contact
// reach of its own (and periodic images of its own: along periodic dimensions the copies
// carry their image positions, and pairs are taken as the positions are, not in the
// minimum image). Ownership: a grain pair is detected and solved by the worker that owns
// the grain of the smaller tag, a grain–wall pair by the grain's owner, so every pair is
// found by exactly one worker when each worker holds copies of every grain within reach
// of its own. The activation distance is the largest over the workers (the same as one
// worker holding every grain would use), the solve exchanges the copies' velocities after
// each sweep (mass splitting, NscdStep::touching_copies), and the contact forces and
// torques of each grain are summed over the workers' contacts on its copies.
struct GrainPartition {
  int owned = 0;
  WorkerExchange* exchange = nullptr;  // required
};

// A contact point of the step: the solver's row and where it came from.
struct GrainContactPoint {
  NscdContact constraint;             // body indices into the grain list, Jacobians, μ, gap
  GrainImpulseMemory::PairKey pair;   // (tag a or −(wall + 1), tag b)
  Eigen::Vector3d position;           // world frame
  Eigen::Matrix3d frame;              // columns (n, t1, t2); n from a to b
};

// Steps 1–4: the problem to solve.
struct GrainStepProblem {
  NscdStep step;  // h, the law of the options, bodies = grains (same order), contacts top-down
  std::vector<GrainContactPoint> points;      // parallel to step.contacts
  std::vector<Eigen::Vector3d> warm_start;    // local frames; empty without warm start
  // rolling couples (t1, t2), parallel to warm_start; empty without rolling resistance
  std::vector<Eigen::Vector2d> couple_warm_start;
  int wall_count = 0;
  // sleeping: per grain, asleep during this step (after the start-of-step wake-ups; empty
  // when sleeping is off), and the frozen points of sleeping pairs (not in `step`)
  std::vector<char> asleep;
  std::vector<double> quiet_time, bounding_radius;  // per grain, sleeping on
  std::vector<Eigen::Vector3d> drift, drift_angular, load, load_moment;  // per grain, as in GrainState
  int woken = 0;                                    // at the start of the step
  std::vector<std::pair<GrainImpulseMemory::PairKey, GrainImpulseMemory::Impulse>> frozen;
  std::vector<std::pair<int, int>> frozen_bodies;   // (body a or −1 for a wall, body b) of each
  std::vector<PlaneWall> walls;                     // the walls of the step (as given)
  // per wall: the index of its body in step.bodies when it is a plate (PlaneWall::mass > 0:
  // after the grains), else −1. The points (`points`) keep a plate's points as wall
  // points (body_a −1, the plate's start velocity as offset); their solver rows
  // (step.contacts) have the plate as body a (set_step_contacts).
  std::vector<int> wall_body;
  // rolling resistance on (μ_r = rolling_friction > 0): per grain, its sweep radius (a
  // point's rolling radius R is the sum of its two grains'; a wall's is 0); else empty
  double rolling_friction = 0.0;
  std::vector<double> sweep_radius;
  PeriodicBox box;  // the options' (lever arms in the minimum image); none when distributed
  // distributed (GrainPartition): the workers' exchange, and how many grains are this
  // worker's own; null and all
  WorkerExchange* exchange = nullptr;
  int owned = 0;
  double activation = 0.0;      // the activation distance of the step
  double largest_radius = 0.0;  // the largest bounding radius (over every worker's grains)
};

struct GrainStepStats {
  int sweeps = 0;
  double residual = 0.0;
  int contact_points = 0;
  double max_overlap = 0.0;                // at the step start
  double max_predicted_penetration = 0.0;
  bool hit_iteration_cap = false;
  int subspace_solves = 0, subspace_accepted = 0;  // method subspace (core/nscd/subspace_correction.h)
  int subspace_factorizations = 0;                 // the LDLᵀ factorisations those made
  int colours = 0;                                 // order coloured: colours of the contact graph
  int sleeping = 0;        // grains asleep after the step
  int woken = 0;           // grains woken in the step (at its start or end)
  int frozen_points = 0;   // contact points of sleeping pairs, not solved
  int sleeper_checks = 0;  // sleepers solved alone in the equilibrium check
};

struct GrainStepResult {
  std::vector<Eigen::Vector3d> velocities, angular_velocities;   // v_{k+1}, ω_{k+1} per grain
  std::vector<Eigen::Vector3d> contact_forces, contact_torques;  // Hᵀ r / h per grain
  std::vector<Eigen::Vector3d> wall_forces;                      // of the grains on each wall
  // per wall: a plate's end-of-step velocity v_{k+1}; a wall of infinite mass its own
  std::vector<Eigen::Vector3d> wall_velocities;
  // per grain after the step; empty when sleeping is off
  std::vector<char> asleep;
  std::vector<double> quiet_time;
  std::vector<Eigen::Vector3d> drift, drift_angular, load, load_moment;
  GrainStepStats stats;
  ContactList contacts;  // every point (open ones too), force = impulse / h on b
};

// InvalidArgument("time_step" | "grains" | "walls" | "box" | options keywords, ...) on bad
// input (shape index out of range, mass or inertia ≤ 0, non-finite or non-unit data, a
// wall not parallel to a periodic dimension, a periodic length below twice the reach, a
// wall's mass < 0, a plate's velocity not along its normal).
// With `share` (several workers holding the same grains: fix nscd/polyhedra's MPI ranks)
// the narrow phase is shared out (core/common/work_share.h): the candidate pairs (grain
// pairs in their fixed order, then the wall pairs) in one block per worker, the contact
// points joined, and every worker assembles the same problem from them: the same points,
// to the bit, as one worker computing every pair.
// With `partition` (a worker of a distributed step, GrainPartition): the pairs this worker
// owns, the activation distance over all workers, NscdStep::touching_copies; collective.
// Sleeping is refused then (InvalidArgument("sleep", ...)), and `share` must be null.
GrainStepProblem assemble_grain_step(const std::vector<GrainState>& grains, const ShapeLibrary& library,
                                     const std::vector<PlaneWall>& walls, double time_step,
                                     const GrainStepOptions& options, const GrainImpulseMemory& memory,
                                     GrainPairCache* pairs = nullptr, const WorkShare* share = nullptr,
                                     const GrainPartition* partition = nullptr);
// Step 5; replaces `memory` by this step's impulses. Distributed (problem.exchange): the
// velocities of every grain of the worker (its own and the copies), each grain's contact
// force and torque summed over all workers' contacts, the walls' forces and the stats'
// counts summed over the workers, the contact list and the memory this worker's. Sleeping grains that wake within
// the step join `problem` (their frozen points become its contact points). NumericalFailure
// or InvalidArgument from the solver.
GrainStepResult solve_grain_step(GrainStepProblem& problem, const std::vector<GrainState>& grains,
                                 const GrainStepOptions& options, std::uint64_t step_number,
                                 GrainImpulseMemory& memory);
// Both.
GrainStepResult grain_step(const std::vector<GrainState>& grains, const ShapeLibrary& library,
                           const std::vector<PlaneWall>& walls, double time_step,
                           const GrainStepOptions& options, std::uint64_t step_number,
                           GrainImpulseMemory& memory);

// θ-method pose update after a step (core/nscd/nscd_step.h):
//     x += h ((1 − θ) v_k + θ v_{k+1})   (theta_method_displacement),
// the orientation by the torque-free rotation (RigidRotation::rotate_free) over h with the
// angular momentum (1 − θ) L_k + θ L_{k+1} (world frame).
struct GrainPose {
  Eigen::Vector3d position;
  Eigen::Quaterniond orientation;
};
GrainPose advance_grain_pose(const GrainPose& pose, const Eigen::Vector3d& inertia,
                             const Eigen::Vector3d& velocity_begin, const Eigen::Vector3d& velocity_end,
                             const Eigen::Vector3d& momentum_begin, const Eigen::Vector3d& momentum_end,
                             double time_step, double theta);

}  // namespace wiregrain
