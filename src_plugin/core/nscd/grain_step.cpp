// The grain step (grain_step.h): its defaults and checks, the solve with the sleepers'
// checks, the forces, the memory and the contact list it leaves, and the pose update.
#include "core/nscd/grain_step.h"

#include <cmath>
#include <string>

#include "core/common/errors.h"
#include "core/nscd/grain_sleep.h"
#include "core/nscd/rigid_body.h"

namespace wiregrain {

SolverSettings grain_solver_defaults() {
  SolverSettings settings;
  settings.order = SweepOrder::forward;
  settings.measure = ConvergenceMeasure::natural_map;
  settings.method = SolverMethod::subspace;
  return settings;
}

MoreauJeanLaw grain_law_defaults() {
  MoreauJeanLaw law;
  // Overlaps are kept from growing, not pushed out by a velocity: a push-out speed is
  // real kinetic energy, and at rest it keeps a pile creeping. Each step leaves
  // overlaps of 1e-7–1e-6 a_max (the gap is linearised at the step start); pushed out at
  // |g|/h they gave the grains of the undamped 500-grain deposit speeds of ~4e-4 and a
  // kinetic energy of 1e-7 m g a_max per grain, the pile sinking 8.6e-5 a_max per time
  // unit (4.8 times that at h = 5e-4) for as long as it ran; with β = 0 the same pile
  // came to rest within 2 time units (kinetic energy 3e-37; 2026-11-26, commit 4a7021c;
  // docs/design.md, "Position update and overlap projection"). Deeper overlaps are removed by the fix's position projection (`project`).
  law.overlap_recovery = 0.0;
  law.overlap_speed = 0.1;
  return law;
}

SolverSettings GrainStepOptions::solver_for_step(std::uint64_t step_number) const {
  SolverSettings step_settings = solver;
  step_settings.seed = solver.seed + step_number;
  return step_settings;
}

void GrainStepOptions::validate() const {
  solver.validate();
  law.validate();
  box.validate();
  if (!(friction >= 0.0)) throw InvalidArgument("friction", "grain step: friction must be >= 0, got " + std::to_string(friction));
  if (!(damping >= 0.0)) throw InvalidArgument("damping", "grain step: damping must be >= 0, got " + std::to_string(damping));
  if (!(margin >= 0.0)) throw InvalidArgument("margin", "grain step: margin must be >= 0, got " + std::to_string(margin));
  if (!(rolling_friction >= 0.0) || !std::isfinite(rolling_friction))
    throw InvalidArgument("rolling_friction", "grain step: rolling_friction must be >= 0, got " + std::to_string(rolling_friction));
  if (!(sleep.speed >= 0.0) || !std::isfinite(sleep.speed) || !(sleep.time > 0.0) || !std::isfinite(sleep.time))
    throw InvalidArgument("sleep", "grain step: sleep needs a speed >= 0 and a time > 0, got " +
                                       std::to_string(sleep.speed) + " and " + std::to_string(sleep.time));
}

namespace {

// Per grain, the impulse of every contact point on it (the solved ones and the frozen
// ones) and its moment about the centre; on each wall, the grains' impulse.
struct ContactImpulses {
  std::vector<Eigen::Vector3d> on_grain, moment, on_wall;
};
void sum_over_workers(const GrainStepProblem& problem, ContactImpulses& out);
ContactImpulses contact_impulses(const GrainStepProblem& problem, const std::vector<GrainState>& grains,
                                 const NscdStepResult& solved) {
  const int n = static_cast<int>(grains.size());
  ContactImpulses out;
  out.on_grain.assign(n, Eigen::Vector3d::Zero());
  out.moment.assign(n, Eigen::Vector3d::Zero());
  out.on_wall.assign(problem.wall_count, Eigen::Vector3d::Zero());
  const PeriodicBox& box = problem.box;
  const auto add = [&](int a, int b, long wall_key, const Eigen::Vector3d& position, const Eigen::Vector3d& impulse) {
    out.on_grain[b] += impulse;
    out.moment[b] += box.minimum_image(position - grains[b].position).cross(impulse);
    if (a >= 0) {
      out.on_grain[a] -= impulse;
      out.moment[a] -= box.minimum_image(position - grains[a].position).cross(impulse);
    } else {
      out.on_wall[-wall_key - 1] -= impulse;
    }
  };
  for (size_t c = 0; c < problem.points.size(); c++) {
    const GrainContactPoint& point = problem.points[c];
    add(point.constraint.body_a, point.constraint.body_b, point.pair.first, point.position,
        point.frame * solved.contacts.impulses[c]);
    if (solved.contacts.couples.empty()) continue;
    // rolling resistance: the couple, +m on b, −m on a
    const Eigen::Vector3d couple = point.frame.rightCols<2>() * solved.contacts.couples[c];
    out.moment[point.constraint.body_b] += couple;
    if (point.constraint.body_a >= 0) out.moment[point.constraint.body_a] -= couple;
  }
  for (size_t f = 0; f < problem.frozen.size(); f++)
    add(problem.frozen_bodies[f].first, problem.frozen_bodies[f].second, problem.frozen[f].first.first,
        problem.frozen[f].second.position, problem.frozen[f].second.impulse);
  if (problem.exchange != nullptr) sum_over_workers(problem, out);
  return out;
}

// Distributed: each grain's impulse and moment summed over every worker's contacts on its
// copies (the moments about the copy's own centre, the same vector for every image), the
// walls' over the workers.
void sum_over_workers(const GrainStepProblem& problem, ContactImpulses& out) {
  const std::size_t n = out.on_grain.size();
  std::vector<double> per_grain(6 * n);
  for (std::size_t k = 0; k < n; k++)
    for (int d = 0; d < 3; d++) {
      per_grain[6 * k + d] = out.on_grain[k][d];
      per_grain[6 * k + 3 + d] = out.moment[k][d];
    }
  problem.exchange->sum_over_copies(per_grain, 6);
  for (std::size_t k = 0; k < n; k++)
    for (int d = 0; d < 3; d++) {
      out.on_grain[k][d] = per_grain[6 * k + d];
      out.moment[k][d] = per_grain[6 * k + 3 + d];
    }
  std::vector<double> walls(3 * out.on_wall.size());
  for (std::size_t w = 0; w < out.on_wall.size(); w++)
    for (int d = 0; d < 3; d++) walls[3 * w + d] = out.on_wall[w][d];
  if (!walls.empty()) problem.exchange->sum_over_workers(walls.data(), static_cast<int>(walls.size()));
  for (std::size_t w = 0; w < out.on_wall.size(); w++)
    for (int d = 0; d < 3; d++) out.on_wall[w][d] = walls[3 * w + d];
}

// The solve of the step; with sleeping on, the sleepers that cannot stay at rest wake
// within the step, and the step is solved again with them, until every grain still asleep
// can (grain_step.h, "Sleeping"). woken_in_step, sleeper_checks: as GrainStepStats'.
NscdStepResult solve_with_sleepers(GrainStepProblem& problem, const std::vector<GrainState>& grains,
                                   const GrainStepOptions& options, std::uint64_t step_number,
                                   GrainImpulseMemory& memory, int& woken_in_step, int& sleeper_checks) {
  using namespace grain_step_detail;
  const SolverSettings solver = options.solver_for_step(step_number);
  NscdStepResult solved = solve_nscd_step(problem.step, solver, problem.warm_start, &memory.backoff,
                                          problem.couple_warm_start, problem.exchange);
  if (options.sleep.on()) {
    for (std::vector<int> woken = check_sleepers(problem, grains, options, solved, sleeper_checks); !woken.empty();
         woken = check_sleepers(problem, grains, options, solved, sleeper_checks)) {
      woken_in_step += wake_in_step(problem, grains, woken, options, solved);
      solved = solve_nscd_step(problem.step, solver, problem.warm_start, &memory.backoff, problem.couple_warm_start);
    }
  }
  return solved;
}

// The memory (warm start, frozen points) and the contact list: the solved points, then
// the frozen ones (their last impulse taken as this step's).
void record_points(const GrainStepProblem& problem, const NscdStepResult& solved, GrainImpulseMemory& memory,
                   ContactList& contacts) {
  const double h = problem.step.time_step;
  memory.clear();
  const auto add_point = [&](const GrainImpulseMemory::PairKey& pair, bool wall, const GrainImpulseMemory::Impulse& point) {
    memory.add(pair, point);
    ContactRecord record;
    record.kind = wall ? ContactKind::grain_wall : ContactKind::grain_grain;
    record.a = pair.first;
    record.b = pair.second;
    record.point = point.position;
    record.normal = point.normal;
    record.force = point.impulse / h;
    record.overlap = -point.gap;
    record.status = point.status;
    contacts.add(record);
  };
  for (size_t c = 0; c < problem.points.size(); c++) {
    const GrainContactPoint& point = problem.points[c];
    GrainImpulseMemory::Impulse stored{point.position, point.frame * solved.contacts.impulses[c]};
    if (!solved.contacts.couples.empty()) stored.couple = point.frame.rightCols<2>() * solved.contacts.couples[c];
    stored.normal = point.frame.col(0);
    stored.gap = point.constraint.gap;
    stored.status = static_cast<ContactStatus>(static_cast<int>(solved.contacts.states[c]));
    add_point(point.pair, point.constraint.body_a < 0, stored);
  }
  for (const auto& [pair, stored] : problem.frozen) add_point(pair, pair.first < 0, stored);
  memory.commit();
}

// The solver's figures of the step.
void report_solve(const GrainStepProblem& problem, const NscdStepResult& solved, GrainStepStats& stats) {
  const NscdReport& report = solved.contacts.report;
  stats.sweeps = report.iterations;
  stats.residual = report.residual;
  stats.contact_points = static_cast<int>(problem.points.size());
  stats.max_overlap = solved.max_overlap;
  stats.max_predicted_penetration = solved.max_predicted_penetration;
  stats.hit_iteration_cap = report.hit_iteration_cap;
  stats.subspace_solves = report.subspace_solves;
  stats.subspace_accepted = report.subspace_accepted;
  stats.subspace_factorizations = report.subspace_factorizations;
  stats.colours = report.colours;
  stats.frozen_points = static_cast<int>(problem.frozen.size());
  if (problem.exchange != nullptr) {  // over the workers
    double counts = stats.contact_points;
    problem.exchange->sum_over_workers(&counts, 1);
    stats.contact_points = static_cast<int>(counts);
    stats.max_overlap = problem.exchange->max_over_workers(stats.max_overlap);
    stats.max_predicted_penetration = problem.exchange->max_over_workers(stats.max_predicted_penetration);
  }
}

}  // namespace

GrainStepResult solve_grain_step(GrainStepProblem& problem, const std::vector<GrainState>& grains,
                                 const GrainStepOptions& options, std::uint64_t step_number,
                                 GrainImpulseMemory& memory) {
  int woken_in_step = 0, sleeper_checks = 0;
  const NscdStepResult solved =
      solve_with_sleepers(problem, grains, options, step_number, memory, woken_in_step, sleeper_checks);
  const ContactImpulses impulses = contact_impulses(problem, grains, solved);
  const double h = problem.step.time_step;
  const int n = static_cast<int>(grains.size());
  GrainStepResult result;
  result.velocities.assign(solved.velocities.begin(), solved.velocities.begin() + n);  // the plates after them
  result.angular_velocities.assign(solved.angular_velocities.begin(), solved.angular_velocities.begin() + n);
  result.wall_velocities.resize(problem.wall_count);
  for (int w = 0; w < problem.wall_count; w++) {
    const int body = problem.wall_body.empty() ? -1 : problem.wall_body[w];
    result.wall_velocities[w] = body >= 0 ? solved.velocities[body] : problem.walls[w].velocity;
  }
  result.contact_forces.resize(n);
  result.contact_torques.resize(n);
  for (int k = 0; k < n; k++) {
    result.contact_forces[k] = impulses.on_grain[k] / h;
    result.contact_torques[k] = impulses.moment[k] / h;
  }
  result.wall_forces.resize(problem.wall_count);
  for (int w = 0; w < problem.wall_count; w++) result.wall_forces[w] = impulses.on_wall[w] / h;
  record_points(problem, solved, memory, result.contacts);
  if (options.sleep.on()) {
    grain_step_detail::update_sleep(problem, grains, options.sleep, solved, result);
    result.stats.woken = problem.woken + woken_in_step;
    result.stats.sleeper_checks = sleeper_checks;
  }
  report_solve(problem, solved, result.stats);
  return result;
}

GrainStepResult grain_step(const std::vector<GrainState>& grains, const ShapeLibrary& library,
                           const std::vector<PlaneWall>& walls, double time_step, const GrainStepOptions& options,
                           std::uint64_t step_number, GrainImpulseMemory& memory) {
  GrainStepProblem problem = assemble_grain_step(grains, library, walls, time_step, options, memory);
  return solve_grain_step(problem, grains, options, step_number, memory);
}

Eigen::Vector3d wall_step_displacement(const PlaneWall& wall, const Eigen::Vector3d& velocity_end, double h,
                                       double theta) {
  return wall.plate() ? theta_method_displacement(wall.velocity, velocity_end, h, theta) : h * wall.velocity;
}

GrainPose advance_grain_pose(const GrainPose& pose, const Eigen::Vector3d& inertia,
                             const Eigen::Vector3d& velocity_begin, const Eigen::Vector3d& velocity_end,
                             const Eigen::Vector3d& momentum_begin, const Eigen::Vector3d& momentum_end,
                             double h, double theta) {
  GrainPose next;
  next.position = pose.position + theta_method_displacement(velocity_begin, velocity_end, h, theta);
  RigidRotation rotation(inertia, pose.orientation, (1.0 - theta) * momentum_begin + theta * momentum_end);
  rotation.rotate_free(h);
  next.orientation = rotation.orientation();
  return next;
}

}  // namespace wiregrain
