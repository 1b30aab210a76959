// Sleeping grains of a grain step (grain_sleep.h; the design: core/nscd/grain_step.h,
// "Sleeping").
#include "core/nscd/grain_sleep.h"

#include <algorithm>
#include <unordered_map>
#include <utility>

#include "core/geometry/contact_manifold.h"
#include "core/geometry/posed_shape.h"
#include "core/nscd/grain_assembly.h"

namespace wiregrain {
namespace grain_step_detail {

namespace {

// Whether a contact impulse on grain g supports it: it acts against g's external force
// (gravity, the wire, ...), or, with no external force, any impulse.
bool supports(const GrainState& g, const Eigen::Vector3d& impulse_on_g) {
  return g.force.isZero(0.0) ? !impulse_on_g.isZero(0.0) : impulse_on_g.dot(g.force) < 0.0;
}

// Every grain–grain point of the step after a solve (the solved ones and the frozen
// ones): (a, b, impulse on b).
struct GrainPairImpulse {
  int a, b;
  Eigen::Vector3d on_b;
};
std::vector<GrainPairImpulse> grain_pair_impulses(const GrainStepProblem& problem, const NscdStepResult& solved) {
  std::vector<GrainPairImpulse> out;
  for (size_t c = 0; c < problem.points.size(); c++) {
    const GrainContactPoint& p = problem.points[c];
    if (p.constraint.body_a >= 0)
      out.push_back({p.constraint.body_a, p.constraint.body_b, p.frame * solved.contacts.impulses[c]});
  }
  for (size_t f = 0; f < problem.frozen.size(); f++)
    if (problem.frozen_bodies[f].first >= 0)
      out.push_back({problem.frozen_bodies[f].first, problem.frozen_bodies[f].second, problem.frozen[f].second.impulse});
  return out;
}

// Per grain, the solved points on it (index, sign of the impulse on it: −1 on a, +1 on b)
// when it sleeps, and the frozen points on it.
struct PointsOnGrains {
  std::vector<std::vector<std::pair<int, double>>> solved_on;
  std::vector<std::vector<int>> frozen_on;
};
PointsOnGrains points_on_sleepers(const GrainStepProblem& problem, int n) {
  PointsOnGrains on;
  on.solved_on.resize(n);
  on.frozen_on.resize(n);
  for (size_t c = 0; c < problem.points.size(); c++) {
    const NscdContact& row = problem.points[c].constraint;
    if (row.body_a >= 0 && problem.asleep[row.body_a]) on.solved_on[row.body_a].emplace_back(int(c), -1.0);
    if (problem.asleep[row.body_b]) on.solved_on[row.body_b].emplace_back(int(c), 1.0);
  }
  for (size_t f = 0; f < problem.frozen.size(); f++) {
    const auto [a, b] = problem.frozen_bodies[f];
    if (a >= 0) on.frozen_on[a].push_back(int(f));
    on.frozen_on[b].push_back(int(f));
  }
  return on;
}

// grain j above grain k: a higher centre; ties: the higher index
bool above(const std::vector<GrainState>& grains, int j, int k) {
  return grains[j].position.z() > grains[k].position.z() ||
         (grains[j].position.z() == grains[k].position.z() && j > k);
}

// The net load of the step on sleeper k (impulse and moment about its centre): h F, the
// impulses and couples of the solved points on it and of the frozen points it does not
// own; `owned`: the frozen points it owns (the upper grain of a pair owns its points, a
// grain its wall points).
struct SleeperLoad {
  Eigen::Vector3d load, moment;
  std::vector<int> owned;
};
SleeperLoad sleeper_load(const GrainStepProblem& problem, const std::vector<GrainState>& grains,
                         const NscdStepResult& solved, const PointsOnGrains& on, int k) {
  const GrainState& g = grains[k];
  const double h = problem.step.time_step;
  const auto owner = [&](int f) {
    const auto [a, b] = problem.frozen_bodies[f];
    return a < 0 || above(grains, b, a) ? b : a;
  };
  SleeperLoad out;
  Eigen::Vector3d& load = out.load;
  Eigen::Vector3d& moment = out.moment;
  load = h * g.force;
  moment = h * g.torque;
  // an impulse at `position` and a rolling couple
  const auto add_load = [&](const Eigen::Vector3d& position, const Eigen::Vector3d& impulse, const Eigen::Vector3d& couple) {
    load += impulse;
    moment += problem.box.minimum_image(position - g.position).cross(impulse) + couple;
  };
  for (const auto& [c, sign] : on.solved_on[k]) {
    const GrainContactPoint& point = problem.points[c];
    const Eigen::Vector3d couple = solved.contacts.couples.empty()
                                       ? Eigen::Vector3d::Zero()
                                       : Eigen::Vector3d(point.frame.rightCols<2>() * solved.contacts.couples[c]);
    add_load(point.position, sign * (point.frame * solved.contacts.impulses[c]), sign * couple);
  }
  for (int f : on.frozen_on[k]) {
    if (owner(f) == k) {
      out.owned.push_back(f);
      continue;
    }
    const double sign = problem.frozen_bodies[f].second == k ? 1.0 : -1.0;
    add_load(problem.frozen[f].second.position, sign * problem.frozen[f].second.impulse, sign * problem.frozen[f].second.couple);
  }
  return out;
}

// Whether sleeper k's last solution still holds: its net load is what it was at its last
// check (to 1e-6 v_sleep in velocity) and the drift that check left is below 1e-3 v_sleep.
bool still_holds(const GrainStepProblem& problem, const GrainState& g, int k, const SleeperLoad& now, double v_sleep) {
  const double radius = problem.bounding_radius[k];
  const Eigen::Matrix3d r = g.orientation.toRotationMatrix();
  const Eigen::Matrix3d inverse_inertia = r * g.inertia.cwiseInverse().asDiagonal() * r.transpose();
  const double load_change =
      (now.load - problem.load[k]).norm() / g.mass + radius * (inverse_inertia * (now.moment - problem.load_moment[k])).norm();
  const double drift = problem.drift[k].norm() + radius * problem.drift_angular[k].norm();
  return load_change <= 1e-6 * v_sleep && drift <= 1e-3 * v_sleep;
}

// Sleeper k solved alone: a body of its mass starting at its drift, loaded by `now`, held
// by the frozen points it owns (all taken as touching, gap 0), its partners fixed.
// frames: the local frame of each owned point, from the partner to k.
NscdStepResult solve_sleeper_alone(const GrainStepProblem& problem, const GrainState& g, int k,
                                   const GrainStepOptions& options, const SolverSettings& settings,
                                   const SleeperLoad& now, std::vector<Eigen::Matrix3d>& frames) {
  const double h = problem.step.time_step;
  GrainState alone = g;
  alone.velocity = g.drift;  // at the step start (a second pass in the step starts there too)
  alone.angular_velocity = g.drift_angular;
  alone.force = now.load / h;
  alone.torque = now.moment / h;
  NscdStep local;
  local.time_step = h;
  local.law = options.law;
  local.bodies.push_back(free_body(alone, h, options.damping));
  std::vector<Eigen::Vector3d> warm;
  std::vector<Eigen::Vector2d> warm_couples;
  for (int f : now.owned) {
    const auto& [pair, stored] = problem.frozen[f];
    const double sign = problem.frozen_bodies[f].second == k ? 1.0 : -1.0;
    const Eigen::Matrix3d frame = contact_frame(sign * stored.normal);  // from the partner to k
    NscdContact row;
    row.body_b = 0;
    row.jacobian_b = contact_jacobian(frame, problem.box.minimum_image(stored.position - g.position), 1.0);
    row.friction = pair.first < 0 ? problem.walls[-pair.first - 1].friction : options.friction;
    set_rolling(row, problem, problem.frozen_bodies[f].first, problem.frozen_bodies[f].second);
    local.contacts.push_back(row);
    frames.push_back(frame);
    warm.push_back(frame.transpose() * (sign * stored.impulse));
    warm_couples.push_back(frame.rightCols<2>().transpose() * (sign * stored.couple));
  }
  const std::vector<int>& owned = now.owned;
  if (!problem.sweep_radius.empty())
    restrict_rolling(
        owned.size(), [&](size_t i) { return problem.frozen[owned[i]].first; },
        [&](size_t i) { return problem.frozen[owned[i]].second.position; },
        [&](size_t i) { return problem.frozen[owned[i]].second.normal; },
        [&](size_t i) -> NscdContact& { return local.contacts[i]; });
  return solve_nscd_step(local, settings, warm, nullptr, warm_couples);
}

// Sleeper k stays asleep: its drift, its checked load, and its owned points take the
// impulses `rest` found.
void keep_asleep(GrainStepProblem& problem, int k, const SleeperLoad& now, const NscdStepResult& rest,
                 const std::vector<Eigen::Matrix3d>& frames) {
  problem.drift[k] = rest.velocities[0];
  problem.drift_angular[k] = rest.angular_velocities[0];
  problem.load[k] = now.load;
  problem.load_moment[k] = now.moment;
  for (size_t i = 0; i < now.owned.size(); i++) {
    auto& stored = problem.frozen[now.owned[i]].second;
    const double sign = problem.frozen_bodies[now.owned[i]].second == k ? 1.0 : -1.0;
    stored.impulse = sign * (frames[i] * rest.contacts.impulses[i]);
    if (!rest.contacts.couples.empty()) stored.couple = sign * (frames[i].rightCols<2>() * rest.contacts.couples[i]);
    stored.status = static_cast<ContactStatus>(static_cast<int>(rest.contacts.states[i]));
  }
}

}  // namespace

void begin_sleeping_step(GrainStepProblem& problem, const std::vector<GrainState>& grains,
                         const ShapeLibrary& library, const std::vector<PlaneWall>& walls,
                         const GrainStepOptions& options) {
  const int n = static_cast<int>(grains.size());
  const double h = problem.step.time_step;
  problem.asleep.assign(n, 0);
  problem.quiet_time.assign(n, 0.0);
  for (const GrainState& g : grains) {
    problem.drift.push_back(g.drift);
    problem.drift_angular.push_back(g.drift_angular);
    problem.load.push_back(g.load);
    problem.load_moment.push_back(g.load_moment);
  }
  problem.bounding_radius.assign(n, 0.0);
  for (int k = 0; k < n; k++) {
    const GrainState& g = grains[k];
    const double radius = library[g.shape].bounding_radius;
    problem.bounding_radius[k] = radius;
    bool asleep = g.asleep && g.velocity.isZero(0.0) && g.angular_velocity.isZero(0.0);
    for (const PlaneWall& w : walls) {
      // a plate wakes the grains within its reach at rest too (grain_step.h, PlaneWall)
      if (!asleep || (w.velocity.isZero(0.0) && !w.plate())) continue;
      const double speed = w.plate() ? std::max(w.velocity.norm(), w.free_velocity(h).norm()) : w.velocity.norm();
      const double reach = options.margin + 4.0 * h * speed + 1e-12;
      if (w.normal.dot(g.position - w.point) > radius + reach) continue;  // beyond its bounding sphere
      const PosedShape shape(library[g.shape].shape, g.position, g.orientation);
      const Eigen::Vector3d& lowest = shape.vertices()[shape.support_vertex(-w.normal)];
      if (w.normal.dot(lowest - w.point) - shape.sweep_radius() <= reach) asleep = false;
    }
    if (g.asleep && !asleep) problem.woken++;
    problem.asleep[k] = asleep;
    problem.quiet_time[k] = g.asleep && !asleep ? 0.0 : g.quiet_time;
  }
}

void freeze_sleeping_pairs(GrainStepProblem& problem, const std::vector<GrainState>& grains,
                           const std::vector<PlaneWall>& walls, const GrainImpulseMemory& memory) {
  const int n = static_cast<int>(grains.size());
  std::unordered_map<long, int> index_of_tag;
  for (int k = 0; k < n; k++) index_of_tag[grains[k].tag] = k;
  const auto sleeping_tag = [&](long tag) {
    const auto it = index_of_tag.find(tag);
    return it != index_of_tag.end() && problem.asleep[it->second];
  };
  for (const auto& [pair, point] : memory.points())
    if (sleeping_tag(pair.second) && (pair.first < 0 || sleeping_tag(pair.first))) {
      problem.frozen.emplace_back(pair, point);
      problem.frozen_bodies.emplace_back(pair.first < 0 ? -1 : index_of_tag.at(pair.first),
                                         index_of_tag.at(pair.second));
    }
  problem.walls = walls;
}

// The sleepers' equilibrium check (core/nscd/grain_step.h, "Sleeping"), after a solve.
// Each sleeping grain k, from the top down (descending z of its centre, ties by index),
// is solved alone: a body of its mass starting at its drift, loaded by h F, the impulses
// of the awake grains just solved and the frozen points it does not own, held by the
// frozen points it owns (all taken as touching, gap 0: it does not move, so an overlap is
// not pushed out and a small gap does not close), its partners fixed. A frozen point
// between two sleepers is owned by the upper one (higher centre; ties: higher index), a
// wall point by its grain, so one top-down pass carries a new weight down a sleeping pile
// to the floor. The end velocities are its new drift; at most v_sleep (|v| + |ω| R), it
// stays asleep and its owned points take the solved impulses; above, it wakes. A sleeper
// is not solved when its net load (force and moment) is what it was at its last check (to
// 1e-6 v_sleep in velocity) and the drift that check left is below 1e-3 v_sleep: its last
// solution still holds.
std::vector<int> check_sleepers(GrainStepProblem& problem, const std::vector<GrainState>& grains,
                                const GrainStepOptions& options, const NscdStepResult& solved, int& checks) {
  const int n = static_cast<int>(grains.size());
  const double v_sleep = options.sleep.speed;
  const PointsOnGrains on = points_on_sleepers(problem, n);
  std::vector<int> order;
  for (int k = 0; k < n; k++)
    if (problem.asleep[k]) order.push_back(k);
  std::stable_sort(order.begin(), order.end(), [&](int j, int k) { return above(grains, j, k); });

  SolverSettings local_settings = options.solver;
  local_settings.method = SolverMethod::gauss_seidel;
  local_settings.order = SweepOrder::forward;
  std::vector<int> woken;
  for (int k : order) {
    const GrainState& g = grains[k];
    const SleeperLoad now = sleeper_load(problem, grains, solved, on, k);
    if (still_holds(problem, g, k, now, v_sleep)) continue;
    std::vector<Eigen::Matrix3d> frames;
    const NscdStepResult rest = solve_sleeper_alone(problem, g, k, options, local_settings, now, frames);
    checks++;
    if (rest.velocities[0].norm() + problem.bounding_radius[k] * rest.angular_velocities[0].norm() > v_sleep) {
      woken.push_back(k);  // its step starts again from its drift at the step start
      continue;
    }
    keep_asleep(problem, k, now, rest, frames);
  }
  return woken;
}

// Wakes `woken` within the step: finite mass and free velocities from their drift at the
// step start, and their frozen points become contact points of the problem, warm-started
// from their frozen impulse; the points already there start from `solved`.
//
// A sleeping grain resting on a woken one (a frozen point between them supports it) wakes
// with it, and so on up: held, it would no longer press on its support (a body of infinite
// mass does not push), and the woken grain would miss its weight.
// Returns the number of grains woken.
int wake_in_step(GrainStepProblem& problem, const std::vector<GrainState>& grains, std::vector<int> woken,
                 const GrainStepOptions& options, const NscdStepResult& solved) {
  const double h = problem.step.time_step;
  {
    std::vector<char> waking(grains.size(), 0);
    for (int k : woken) waking[k] = 1;
    for (size_t next = 0; next < woken.size(); next++) {
      const int k = woken[next];
      for (size_t f = 0; f < problem.frozen.size(); f++) {
        const auto [a, b] = problem.frozen_bodies[f];
        if (a < 0 || (a != k && b != k)) continue;
        const int other = a == k ? b : a;
        const Eigen::Vector3d on_other = other == b ? problem.frozen[f].second.impulse : Eigen::Vector3d(-problem.frozen[f].second.impulse);
        if (!waking[other] && problem.asleep[other] && supports(grains[other], on_other)) {
          waking[other] = 1;
          woken.push_back(other);
        }
      }
    }
  }
  problem.warm_start = solved.contacts.impulses;
  if (!problem.sweep_radius.empty())
    problem.couple_warm_start = solved.contacts.couples.empty()
                                    ? std::vector<Eigen::Vector2d>(problem.points.size(), Eigen::Vector2d::Zero())
                                    : solved.contacts.couples;
  const size_t first_woken_point = problem.points.size();
  for (int k : woken) {
    problem.asleep[k] = 0;
    problem.quiet_time[k] = 0.0;
    GrainState moving = grains[k];
    moving.velocity = grains[k].drift;
    moving.angular_velocity = grains[k].drift_angular;
    problem.step.bodies[k] = free_body(moving, h, options.damping);
  }
  std::vector<std::pair<GrainImpulseMemory::PairKey, GrainImpulseMemory::Impulse>> still_frozen;
  std::vector<std::pair<int, int>> still_frozen_bodies;
  for (size_t f = 0; f < problem.frozen.size(); f++) {
    const auto& [pair, stored] = problem.frozen[f];
    const auto [a, b] = problem.frozen_bodies[f];
    if (problem.asleep[b] && (a < 0 || problem.asleep[a])) {
      still_frozen.push_back(problem.frozen[f]);
      still_frozen_bodies.push_back(problem.frozen_bodies[f]);
      continue;
    }
    const PlaneWall* wall = a < 0 ? &problem.walls[-pair.first - 1] : nullptr;
    GrainContactPoint point = make_point(grains, a, b, stored.position, stored.normal, stored.gap,
                                         wall ? wall->friction : options.friction,
                                         wall ? wall->velocity : Eigen::Vector3d::Zero(), pair.first,
                                         problem);
    problem.warm_start.push_back(point.frame.transpose() * stored.impulse);
    if (!problem.sweep_radius.empty()) problem.couple_warm_start.push_back(point.frame.rightCols<2>().transpose() * stored.couple);
    problem.points.push_back(point);
  }
  if (!problem.sweep_radius.empty()) restrict_point_rolling(problem.points, first_woken_point);
  problem.frozen = std::move(still_frozen);
  problem.frozen_bodies = std::move(still_frozen_bodies);
  sort_top_down(problem);
  return static_cast<int>(woken.size());
}

// Sleeping (core/nscd/grain_step.h), after the step's last solve: the grains still asleep stay so
// with their drift and last checked load; an awake grain slower than v_sleep adds h to its
// quiet time, and falls asleep, stopped, once that reaches t_sleep (its load set to 0, so
// the next step checks it).
void update_sleep(const GrainStepProblem& problem, const std::vector<GrainState>& grains, const SleepOptions& sleep,
                  const NscdStepResult& solved, GrainStepResult& result) {
  const double h = problem.step.time_step;
  const size_t n = problem.asleep.size();
  result.asleep.assign(n, 0);
  result.quiet_time.assign(n, 0.0);
  result.drift.assign(n, Eigen::Vector3d::Zero());
  result.drift_angular.assign(n, Eigen::Vector3d::Zero());
  result.load.assign(n, Eigen::Vector3d::Zero());
  result.load_moment.assign(n, Eigen::Vector3d::Zero());
  for (size_t k = 0; k < n; k++) {
    if (problem.asleep[k]) {
      result.asleep[k] = 1;
      result.quiet_time[k] = problem.quiet_time[k];
      result.drift[k] = problem.drift[k];
      result.drift_angular[k] = problem.drift_angular[k];
      result.load[k] = problem.load[k];
      result.load_moment[k] = problem.load_moment[k];
      continue;
    }
    const double speed = result.velocities[k].norm() + result.angular_velocities[k].norm() * problem.bounding_radius[k];
    if (!(speed < sleep.speed)) continue;
    result.quiet_time[k] = problem.quiet_time[k] + h;
    if (result.quiet_time[k] >= sleep.time) result.asleep[k] = 2;  // a candidate
  }
  // a candidate falls asleep only if every grain that supports it sleeps or falls asleep
  // now (walls do): held, it would no longer press on an awake support
  const std::vector<GrainPairImpulse> pairs = grain_pair_impulses(problem, solved);
  for (bool removed = true; removed;) {
    removed = false;
    for (const GrainPairImpulse& p : pairs) {
      if (result.asleep[p.b] == 2 && !result.asleep[p.a] && supports(grains[p.b], p.on_b)) {
        result.asleep[p.b] = 0;
        removed = true;
      }
      if (result.asleep[p.a] == 2 && !result.asleep[p.b] && supports(grains[p.a], -p.on_b)) {
        result.asleep[p.a] = 0;
        removed = true;
      }
    }
  }
  for (size_t k = 0; k < n; k++) {
    if (result.asleep[k] != 2) continue;
    result.asleep[k] = 1;
    result.velocities[k].setZero();
    result.angular_velocities[k].setZero();
  }
  for (char a : result.asleep) result.stats.sleeping += a;
}

}  // namespace grain_step_detail
}  // namespace wiregrain
