#include "core/nscd/grain_step.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>

#include "core/common/errors.h"
#include "core/common/stable_order.h"
#include "core/geometry/broad_phase.h"
#include "core/geometry/contact_geometry.h"
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
  if (!(friction >= 0.0)) throw InvalidArgument("friction", "grain step: friction must be >= 0, got " + std::to_string(friction));
  if (!(damping >= 0.0)) throw InvalidArgument("damping", "grain step: damping must be >= 0, got " + std::to_string(damping));
  if (!(margin >= 0.0)) throw InvalidArgument("margin", "grain step: margin must be >= 0, got " + std::to_string(margin));
  if (!(rolling_friction >= 0.0) || !std::isfinite(rolling_friction))
    throw InvalidArgument("rolling_friction", "grain step: rolling_friction must be >= 0, got " + std::to_string(rolling_friction));
  if (!(sleep.speed >= 0.0) || !std::isfinite(sleep.speed) || !(sleep.time > 0.0) || !std::isfinite(sleep.time))
    throw InvalidArgument("sleep", "grain step: sleep needs a speed >= 0 and a time > 0, got " +
                                       std::to_string(sleep.speed) + " and " + std::to_string(sleep.time));
}

RollingAxes rolling_axes(const std::vector<Eigen::Vector3d>& positions, const Eigen::Vector3d& normal, double arm) {
  RollingAxes axes;
  if (positions.size() < 2) return axes;
  const Eigen::Matrix3d frame = contact_frame(normal);
  const Eigen::Matrix<double, 3, 2> tangents = frame.rightCols<2>();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : positions) centroid += p;
  centroid /= static_cast<double>(positions.size());
  std::vector<Eigen::Vector2d> spread;  // in the tangent plane (t1, t2)
  Eigen::Matrix2d second_moment = Eigen::Matrix2d::Zero();
  for (const Eigen::Vector3d& p : positions) {
    spread.push_back(tangents.transpose() * (p - centroid));
    second_moment += spread.back() * spread.back().transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> principal(second_moment);
  const Eigen::Vector2d along = principal.eigenvectors().col(1);  // the larger spread
  const Eigen::Vector2d across = principal.eigenvectors().col(0);
  // half the points' extent along `direction`
  const auto half_width = [&](const Eigen::Vector2d& direction) {
    double low = 0.0, high = 0.0;
    for (const Eigen::Vector2d& d : spread) {
      low = std::min(low, d.dot(direction));
      high = std::max(high, d.dot(direction));
    }
    return 0.5 * (high - low);
  };
  // rolling about `along` is resisted by the spread across it, and conversely
  const bool free_along = half_width(across) <= arm, free_across = half_width(along) <= arm;
  axes.count = int(free_along) + int(free_across);
  if (axes.count == 1) axes.axis = tangents * (free_along ? along : across);
  return axes;
}

void GrainImpulseMemory::commit() {
  if (committed_) return;
  const std::vector<std::size_t> order = stable_order(entries_.size(), [&](std::size_t i) { return entries_[i].pair; });
  std::vector<Entry> by_pair;
  by_pair.reserve(entries_.size());
  for (std::size_t i : order) by_pair.push_back(entries_[i]);
  entries_ = std::move(by_pair);
  keys_.resize(entries_.size());
  for (std::size_t i = 0; i < entries_.size(); i++) keys_[i] = entries_[i].pair;
  committed_ = true;
}

const std::vector<GrainImpulseMemory::Entry>& GrainImpulseMemory::points() const {
  if (!committed_) throw std::logic_error("GrainImpulseMemory: points added since the last commit");
  return entries_;
}

const GrainImpulseMemory::Impulse* GrainImpulseMemory::recall(const PairKey& pair, const Eigen::Vector3d& position,
                                                               double radius2) const {
  const std::vector<Entry>& all = points();
  const Impulse* nearest = nullptr;
  double best = radius2;
  for (auto it = all.begin() + (std::lower_bound(keys_.begin(), keys_.end(), pair) - keys_.begin());
       it != all.end() && it->pair == pair; ++it) {
    const double d2 = (it->impulse.position - position).squaredNorm();
    if (d2 < best) {
      best = d2;
      nearest = &it->impulse;
    }
  }
  return nearest;
}

namespace {

// Step 1 for one grain: free velocities with implicit damping (the header).
NscdBody free_body(const GrainState& g, double h, double damping) {
  const double damped = 1.0 / (1.0 + h * damping);
  const Eigen::Matrix3d r = g.orientation.toRotationMatrix();
  NscdBody b;
  b.inverse_mass = damped / g.mass;
  b.inverse_inertia = damped * (r * g.inertia.cwiseInverse().asDiagonal() * r.transpose());
  const Eigen::Matrix3d inertia_world = r * g.inertia.asDiagonal() * r.transpose();
  b.velocity_begin = g.velocity;
  b.angular_velocity_begin = g.angular_velocity;
  b.velocity_free = damped * (g.velocity + h * g.force / g.mass);
  b.angular_velocity_free = b.inverse_inertia * (inertia_world * g.angular_velocity + h * g.torque);
  return b;
}

// Rolling resistance of a point between grain body_b and grain body_a (−1: a wall), if on:
// μ_r, and R the sum of the sweep radii (sharp grains on a wall: none).
void set_rolling(NscdContact& row, const GrainStepProblem& problem, int body_a, int body_b) {
  if (problem.sweep_radius.empty()) return;
  row.rolling_radius = problem.sweep_radius[body_b] + (body_a >= 0 ? problem.sweep_radius[body_a] : 0.0);
  row.rolling_friction = row.rolling_radius > 0.0 ? problem.rolling_friction : 0.0;
}

// A contact point between grain body_b and grain body_a (or wall −(key_a + 1) when
// body_a < 0) at `position`, normal from a to b.
GrainContactPoint make_point(const std::vector<GrainState>& grains, int body_a, int body_b,
                             const Eigen::Vector3d& position, const Eigen::Vector3d& normal, double gap, double mu,
                             const Eigen::Vector3d& wall_velocity, long key_a, const GrainStepProblem& problem) {
  GrainContactPoint c;
  set_rolling(c.constraint, problem, body_a, body_b);
  c.frame = contact_frame(normal);
  c.constraint.body_a = body_a;
  c.constraint.body_b = body_b;
  if (body_a >= 0) c.constraint.jacobian_a = contact_jacobian(c.frame, position - grains[body_a].position, -1.0);
  c.constraint.jacobian_b = contact_jacobian(c.frame, position - grains[body_b].position, 1.0);
  c.constraint.velocity_offset = -c.frame.transpose() * wall_velocity;
  c.constraint.friction = mu;
  c.constraint.gap = gap;
  c.pair = {key_a, grains[body_b].tag};
  c.position = position;
  return c;
}

// rolling_axes on each run of consecutive rows of one pair among `count` rows: key(i),
// position(i), normal(i) of row i, and its NscdContact& row(i) (rolling and rolling_axis
// set; rows without rolling resistance are left alone)
template <class Key, class Position, class Normal, class Row>
void restrict_rolling(size_t count, const Key& key, const Position& position, const Normal& normal, const Row& row) {
  std::vector<Eigen::Vector3d> positions;
  for (size_t first = 0, last = 0; first < count; first = last) {
    positions.clear();
    for (last = first; last < count && key(last) == key(first); last++) positions.push_back(position(last));
    const double arm = row(first).rolling_friction * row(first).rolling_radius;  // μ_r R
    if (arm == 0.0) continue;
    const RollingAxes axes = rolling_axes(positions, normal(first), arm);
    for (size_t i = first; i < last; i++) {
      if (axes.count == 0) row(i).rolling_friction = 0.0;
      if (axes.count == 1) row(i).rolling_axis = axes.axis;
    }
  }
}

// restrict_rolling on points[begin, end)
void restrict_rolling(std::vector<GrainContactPoint>& points, size_t begin) {
  restrict_rolling(
      points.size() - begin, [&](size_t i) { return points[begin + i].pair; },
      [&](size_t i) { return points[begin + i].position; }, [&](size_t i) { return Eigen::Vector3d(points[begin + i].frame.col(0)); },
      [&](size_t i) -> NscdContact& { return points[begin + i].constraint; });
}

// Step 3: the top-down order of `count` points (descending z, ties in the order given)
template <class Height>
std::vector<size_t> top_down_order(size_t count, const Height& z_of) {
  return stable_order(count, [&](size_t c) { return -z_of(c); });
}

// The solver's rows, parallel to the points
void set_step_contacts(GrainStepProblem& problem) {
  problem.step.contacts.clear();
  problem.step.contacts.reserve(problem.points.size());
  for (const GrainContactPoint& c : problem.points) problem.step.contacts.push_back(c.constraint);
}

// Step 3 on points already made (grains woken within the step): the points from the top
// down, with their rows and warm starts.
void sort_top_down(GrainStepProblem& problem) {
  const std::vector<size_t> order =
      top_down_order(problem.points.size(), [&](size_t c) { return problem.points[c].position.z(); });
  std::vector<GrainContactPoint> points;
  std::vector<Eigen::Vector3d> warm;
  std::vector<Eigen::Vector2d> warm_couples;
  points.reserve(order.size());
  warm.reserve(problem.warm_start.size());
  warm_couples.reserve(problem.couple_warm_start.size());
  for (size_t c : order) {
    points.push_back(problem.points[c]);
    if (!problem.warm_start.empty()) warm.push_back(problem.warm_start[c]);
    if (!problem.couple_warm_start.empty()) warm_couples.push_back(problem.couple_warm_start[c]);
  }
  problem.points = std::move(points);
  problem.warm_start = std::move(warm);
  problem.couple_warm_start = std::move(warm_couples);
  set_step_contacts(problem);
}

// Per grain, the impulse of every contact point on it (the solved ones and the frozen
// ones) and its moment about the centre; on each wall, the grains' impulse.
struct ContactImpulses {
  std::vector<Eigen::Vector3d> on_grain, moment, on_wall;
};
ContactImpulses contact_impulses(const GrainStepProblem& problem, const std::vector<GrainState>& grains,
                                 const NscdStepResult& solved) {
  const int n = static_cast<int>(grains.size());
  ContactImpulses out;
  out.on_grain.assign(n, Eigen::Vector3d::Zero());
  out.moment.assign(n, Eigen::Vector3d::Zero());
  out.on_wall.assign(problem.wall_count, Eigen::Vector3d::Zero());
  const auto add = [&](int a, int b, long wall_key, const Eigen::Vector3d& position, const Eigen::Vector3d& impulse) {
    out.on_grain[b] += impulse;
    out.moment[b] += (position - grains[b].position).cross(impulse);
    if (a >= 0) {
      out.on_grain[a] -= impulse;
      out.moment[a] -= (position - grains[a].position).cross(impulse);
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
  return out;
}

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

// The sleepers' equilibrium check (the header), after a solve. Each sleeping grain k,
// from the top down (descending z of its centre, ties by index), is solved alone: a
// body of its mass starting at its drift, loaded by h F, the impulses of the awake grains
// just solved and the frozen points it does not own, held by the frozen points it owns
// (all taken as touching, gap 0: it does not move, so an overlap is not pushed out and a
// small gap does not close), its partners fixed. A frozen point between two sleepers is
// owned by the upper one (higher centre; ties: higher index), a wall point by its grain,
// so one top-down pass carries a new weight down a sleeping pile to the floor. The end
// velocities are its new drift; at most v_sleep (|v| + |ω| R), it stays asleep and its
// owned points take the solved impulses; above, it wakes. A sleeper is not solved when
// its net load (force and moment) is what it was at its last check (to 1e-6 v_sleep in
// velocity) and the drift that check left is below 1e-3 v_sleep: its last solution
// still holds.
// Returns the grains that wake; `checks` counts the solves made.
std::vector<int> check_sleepers(GrainStepProblem& problem, const std::vector<GrainState>& grains,
                                const GrainStepOptions& options, const NscdStepResult& solved, int& checks) {
  const int n = static_cast<int>(grains.size());
  const double h = problem.step.time_step;
  const double v_sleep = options.sleep.speed;
  // per sleeper: the solved points (index, sign of the impulse on it) and frozen points on it
  std::vector<std::vector<std::pair<int, double>>> solved_on(n);
  std::vector<std::vector<int>> frozen_on(n);
  for (size_t c = 0; c < problem.points.size(); c++) {
    const NscdContact& row = problem.points[c].constraint;
    if (row.body_a >= 0 && problem.asleep[row.body_a]) solved_on[row.body_a].emplace_back(int(c), -1.0);
    if (problem.asleep[row.body_b]) solved_on[row.body_b].emplace_back(int(c), 1.0);
  }
  for (size_t f = 0; f < problem.frozen.size(); f++) {
    const auto [a, b] = problem.frozen_bodies[f];
    if (a >= 0) frozen_on[a].push_back(int(f));
    frozen_on[b].push_back(int(f));
  }
  const auto above = [&](int j, int k) {  // j above k
    return grains[j].position.z() > grains[k].position.z() ||
           (grains[j].position.z() == grains[k].position.z() && j > k);
  };
  const auto owner = [&](int f) {
    const auto [a, b] = problem.frozen_bodies[f];
    return a < 0 || above(b, a) ? b : a;
  };
  std::vector<int> order;
  for (int k = 0; k < n; k++)
    if (problem.asleep[k]) order.push_back(k);
  std::stable_sort(order.begin(), order.end(), [&](int j, int k) { return above(j, k); });

  SolverSettings local_options = options.solver;
  local_options.method = SolverMethod::gauss_seidel;
  local_options.order = SweepOrder::forward;
  std::vector<int> woken;
  for (int k : order) {
    const GrainState& g = grains[k];
    const double radius = problem.bounding_radius[k];
    Eigen::Vector3d load = h * g.force, moment = h * g.torque;
    // an impulse at `position` and a rolling couple
    const auto add_load = [&](const Eigen::Vector3d& position, const Eigen::Vector3d& impulse, const Eigen::Vector3d& couple) {
      load += impulse;
      moment += (position - g.position).cross(impulse) + couple;
    };
    for (const auto& [c, sign] : solved_on[k]) {
      const GrainContactPoint& point = problem.points[c];
      const Eigen::Vector3d couple = solved.contacts.couples.empty()
                                         ? Eigen::Vector3d::Zero()
                                         : Eigen::Vector3d(point.frame.rightCols<2>() * solved.contacts.couples[c]);
      add_load(point.position, sign * (point.frame * solved.contacts.impulses[c]), sign * couple);
    }
    std::vector<int> owned;
    for (int f : frozen_on[k]) {
      if (owner(f) == k) {
        owned.push_back(f);
        continue;
      }
      const double sign = problem.frozen_bodies[f].second == k ? 1.0 : -1.0;
      add_load(problem.frozen[f].second.position, sign * problem.frozen[f].second.impulse, sign * problem.frozen[f].second.couple);
    }
    const Eigen::Matrix3d r = g.orientation.toRotationMatrix();
    const Eigen::Matrix3d inverse_inertia = r * g.inertia.cwiseInverse().asDiagonal() * r.transpose();
    const double load_change =
        (load - problem.load[k]).norm() / g.mass + radius * (inverse_inertia * (moment - problem.load_moment[k])).norm();
    const double drift = problem.drift[k].norm() + radius * problem.drift_angular[k].norm();
    if (load_change <= 1e-6 * v_sleep && drift <= 1e-3 * v_sleep) continue;

    GrainState alone = g;
    alone.velocity = g.drift;  // at the step start (a second pass in the step starts there too)
    alone.angular_velocity = g.drift_angular;
    alone.force = load / h;
    alone.torque = moment / h;
    NscdStep local;
    local.time_step = h;
    local.law = options.law;
    local.bodies.push_back(free_body(alone, h, options.damping));
    std::vector<Eigen::Vector3d> warm;
    std::vector<Eigen::Vector2d> warm_couples;
    std::vector<Eigen::Matrix3d> frames;
    for (int f : owned) {
      const auto& [pair, stored] = problem.frozen[f];
      const double sign = problem.frozen_bodies[f].second == k ? 1.0 : -1.0;
      const Eigen::Matrix3d frame = contact_frame(sign * stored.normal);  // from the partner to k
      NscdContact row;
      row.body_b = 0;
      row.jacobian_b = contact_jacobian(frame, stored.position - g.position, 1.0);
      row.friction = pair.first < 0 ? problem.walls[-pair.first - 1].friction : options.friction;
      set_rolling(row, problem, problem.frozen_bodies[f].first, problem.frozen_bodies[f].second);
      local.contacts.push_back(row);
      frames.push_back(frame);
      warm.push_back(frame.transpose() * (sign * stored.impulse));
      warm_couples.push_back(frame.rightCols<2>().transpose() * (sign * stored.couple));
    }
    if (!problem.sweep_radius.empty())
      restrict_rolling(
          owned.size(), [&](size_t i) { return problem.frozen[owned[i]].first; },
          [&](size_t i) { return problem.frozen[owned[i]].second.position; },
          [&](size_t i) { return problem.frozen[owned[i]].second.normal; },
          [&](size_t i) -> NscdContact& { return local.contacts[i]; });
    const NscdStepResult rest = solve_nscd_step(local, local_options, warm, nullptr, warm_couples);
    checks++;
    if (rest.velocities[0].norm() + radius * rest.angular_velocities[0].norm() > v_sleep) {
      woken.push_back(k);  // its step starts again from its drift at the step start
      continue;
    }
    problem.drift[k] = rest.velocities[0];
    problem.drift_angular[k] = rest.angular_velocities[0];
    problem.load[k] = load;
    problem.load_moment[k] = moment;
    for (size_t i = 0; i < owned.size(); i++) {
      auto& stored = problem.frozen[owned[i]].second;
      const double sign = problem.frozen_bodies[owned[i]].second == k ? 1.0 : -1.0;
      stored.impulse = sign * (frames[i] * rest.contacts.impulses[i]);
      if (!rest.contacts.couples.empty()) stored.couple = sign * (frames[i].rightCols<2>() * rest.contacts.couples[i]);
      stored.status = static_cast<ContactStatus>(static_cast<int>(rest.contacts.states[i]));
    }
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
  if (!problem.sweep_radius.empty()) restrict_rolling(problem.points, first_woken_point);
  problem.frozen = std::move(still_frozen);
  problem.frozen_bodies = std::move(still_frozen_bodies);
  sort_top_down(problem);
  return static_cast<int>(woken.size());
}

// Sleeping (the header), after the step's last solve: the grains still asleep stay so
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

// A candidate of the narrow phase: grains a < b (wall < 0), or wall `wall` and grain b
// (a = −1); a frozen pair (two sleepers) is not computed.
struct NarrowPhaseCandidate {
  int a = -1, b = -1, wall = -1;
  bool frozen = false;
  int kept = -1;        // its index in the pair cache's pairs() when it comes from there
  GjkSimplex simplex;   // GJK's warm start (empty: cold)
};

struct NarrowPhaseResult {
  double gap = std::numeric_limits<double>::infinity();  // the manifold's (a lower bound when far)
  std::vector<ContactPoint> points;                      // position, normal and gap are used
  GjkSimplex simplex;                                    // GJK's last (with `simplices`)
};

// The contact manifolds of the candidates, shared out (share_out, core/common/work_share.h):
// `compute(candidate, simplex)` (simplex: null, or GJK's warm start from the candidate's,
// left with its last). The numbers of a candidate: its gap, its point count and 7 numbers
// per point, and with `simplices` the simplex's size and its index pairs (every worker
// then holds every pair's simplex, whoever computed it: the next step's warm start is the
// same on any number of workers).
template <class Compute>
std::vector<NarrowPhaseResult> narrow_phase(const std::vector<NarrowPhaseCandidate>& candidates,
                                            const WorkShare* share, bool simplices, const Compute& compute) {
  std::vector<NarrowPhaseResult> found(candidates.size());
  const auto compute_one = [&](std::size_t i, std::vector<double>& out) {
    if (candidates[i].frozen) {
      out.insert(out.end(), {found[i].gap, 0.0});
      if (simplices) out.push_back(0.0);
      return;
    }
    found[i].simplex = candidates[i].simplex;
    ContactManifold m = compute(candidates[i], simplices ? &found[i].simplex : nullptr);
    found[i].gap = m.gap;
    found[i].points = std::move(m.points);
    out.push_back(found[i].gap);
    out.push_back(static_cast<double>(found[i].points.size()));
    for (const ContactPoint& p : found[i].points)
      out.insert(out.end(), {p.position.x(), p.position.y(), p.position.z(), p.normal.x(), p.normal.y(), p.normal.z(), p.gap});
    if (simplices) {
      const GjkSimplex& s = found[i].simplex;
      out.push_back(s.size);
      for (int k = 0; k < s.size; k++) out.insert(out.end(), {double(s.a[k]), double(s.b[k])});
    }
  };
  const auto read_one = [&](std::size_t i, SharedNumbers& in) {
    NarrowPhaseResult& r = found[i];
    r.gap = in.next();
    const double points = in.next();
    for (int k = 0; k < static_cast<int>(points); k++) {
      ContactPoint p;
      p.position.x() = in.next();
      p.position.y() = in.next();
      p.position.z() = in.next();
      p.normal.x() = in.next();
      p.normal.y() = in.next();
      p.normal.z() = in.next();
      p.gap = in.next();
      // (the step uses position, normal and gap only: the surface points are not sent)
      p.point_a = p.point_b = p.position;
      r.points.push_back(p);
    }
    if (simplices) {
      r.simplex.size = static_cast<int>(in.next());
      if (r.simplex.size < 0 || r.simplex.size > 4)
        throw NumericalFailure("grain step: the joined narrow phase has a simplex of size " + std::to_string(r.simplex.size));
      for (int k = 0; k < r.simplex.size; k++) {
        r.simplex.a[k] = static_cast<int>(in.next());
        r.simplex.b[k] = static_cast<int>(in.next());
      }
    }
  };
  share_out(candidates.size(), share, compute_one, read_one);
  return found;
}

void check_inputs(const std::vector<GrainState>& grains, const ShapeLibrary& library,
                  const std::vector<PlaneWall>& walls, double h) {
  if (!(h > 0.0) || !std::isfinite(h)) throw InvalidArgument("time_step", "grain step: h must be > 0 and finite");
  for (const GrainState& g : grains) {
    if (!(g.quiet_time >= 0.0) || !std::isfinite(g.quiet_time) || !g.drift.allFinite() || !g.drift_angular.allFinite() ||
        !g.load.allFinite() || !g.load_moment.allFinite())
      throw InvalidArgument("grains", "grain step: grain " + std::to_string(g.tag) +
                                          ": quiet time must be >= 0 and finite, the drift and load finite");
    const auto name = [&g] { return "grain step: grain " + std::to_string(g.tag) + ": "; };  // on failure only
    if (g.shape < 0 || g.shape >= library.size())
      throw InvalidArgument("grains", name() + "shape index " + std::to_string(g.shape) + " not in the library");
    if (!(g.mass > 0.0) || !std::isfinite(g.mass) || !(g.inertia.minCoeff() > 0.0) || !g.inertia.allFinite())
      throw InvalidArgument("grains", name() + "mass and principal moments must be > 0 and finite");
    if (!(g.position.allFinite() && g.orientation.coeffs().allFinite() && g.velocity.allFinite() &&
          g.angular_velocity.allFinite() && g.force.allFinite() && g.torque.allFinite()))
      throw InvalidArgument("grains", name() + "non-finite state");
    if (std::fabs(g.orientation.norm() - 1.0) > 1e-9) throw InvalidArgument("grains", name() + "orientation is not a unit quaternion");
  }
  for (const PlaneWall& w : walls)
    if (!(w.point.allFinite() && w.velocity.allFinite()) || !(std::fabs(w.normal.norm() - 1.0) <= 1e-9) ||
        !(w.friction >= 0.0))
      throw InvalidArgument("walls", "grain step: a wall needs a finite point and velocity, a unit normal and friction >= 0");
}

}  // namespace

GrainStepProblem assemble_grain_step(const std::vector<GrainState>& grains, const ShapeLibrary& library,
                                     const std::vector<PlaneWall>& walls, double h, const GrainStepOptions& options,
                                     const GrainImpulseMemory& memory, GrainPairCache* pairs,
                                     const WorkShare* share) {
  options.validate();
  check_inputs(grains, library, walls, h);
  const int n = static_cast<int>(grains.size());
  GrainStepProblem problem;
  problem.wall_count = static_cast<int>(walls.size());
  problem.step.time_step = h;
  problem.step.law = options.law;
  if (options.rolling_friction > 0.0) {
    problem.rolling_friction = options.rolling_friction;
    problem.sweep_radius.resize(n);
    for (int k = 0; k < n; k++) problem.sweep_radius[k] = library[grains[k].shape].shape.sweep_radius();
  }

  // 0. sleeping: who sleeps in this step. A sleeping grain wakes now if the deck gave it
  // a velocity or a moving wall can reach it within the step (relative speed |v_wall|).
  const bool sleep = options.sleep.on();
  if (sleep) {
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
        if (!asleep || w.velocity.isZero(0.0)) continue;
        const double reach = options.margin + 4.0 * h * w.velocity.norm() + 1e-12;
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
  const auto asleep = [&](int k) { return sleep && problem.asleep[k]; };

  // 1. bodies: free velocities with implicit damping (see the header); a sleeping grain
  // has infinite mass and no velocity
  double largest_radius = 0.0, fastest = 0.0;
  for (const GrainState& g : grains) {
    const NscdBody b = asleep(static_cast<int>(problem.step.bodies.size())) ? NscdBody() : free_body(g, h, options.damping);
    problem.step.bodies.push_back(b);
    const double radius = library[g.shape].bounding_radius;
    largest_radius = std::max(largest_radius, radius);
    fastest = std::max(fastest, b.velocity_free.norm() + b.angular_velocity_free.norm() * radius);
  }

  // 2. contact points of every pair whose gap may close within the step: the candidates
  // in a fixed order (grain pairs a < b, b ascending for each a, grains in tag order: the
  // same whether they come from the broad phase or from the pair cache, grain_pairs.h;
  // then each wall's grains), their narrow phase (shared out when `share` is given), then
  // their points in that order
  double wall_speed = 0.0;
  for (const PlaneWall& w : walls) wall_speed = std::max(wall_speed, w.velocity.norm());
  const double activation = options.margin + 2.0 * h * (2.0 * fastest + wall_speed) + 1e-12;
  ContactOptions contact_options;
  contact_options.near_vertices = options.near_vertices;
  std::vector<NarrowPhaseCandidate> candidates;
  const bool reuse = n > 0 && pairs && pairs->valid(grains, library, activation);
  const double skin = pairs && !reuse ? pairs->skin() : 0.0;
  const bool warm_geometry = options.warm_geometry && pairs;
  if (reuse) {
    pairs->count_reuse();
    const std::vector<GrainPairCache::KeptPair>& kept = pairs->pairs();
    for (std::size_t i = 0; i < kept.size(); i++) {
      const GrainPairCache::KeptPair& p = kept[i];
      if (!(asleep(p.a) && asleep(p.b)) && !pairs->still_apart(p, activation))
        candidates.push_back({p.a, p.b, -1, false, static_cast<int>(i), warm_geometry ? p.simplex : GjkSimplex()});
    }
  } else if (n > 0) {
    BroadPhaseGrid grid = BroadPhaseGrid::unbounded(2.0 * largest_radius + activation + skin);
    for (const GrainState& g : grains) grid.insert(g.position);
    grid.index();
    std::vector<int> near;
    for (int a = 0; a < n; a++) {
      const double ra = library[grains[a].shape].bounding_radius;
      near.clear();
      grid.for_each_near(grains[a].position, [&](int b, const Eigen::Vector3d&) {
        if (b <= a) return;
        const double reach = ra + library[grains[b].shape].bounding_radius + activation + skin;
        if ((grains[b].position - grains[a].position).squaredNorm() < reach * reach) near.push_back(b);
      });
      std::sort(near.begin(), near.end());
      // a pair of sleepers is frozen: not computed, kept in the cache for when one wakes
      for (int b : near) candidates.push_back({a, b, -1, asleep(a) && asleep(b), -1, GjkSimplex()});
    }
  }
  for (int w = 0; w < (int)walls.size(); w++)
    for (int b = 0; b < n; b++) {
      if (asleep(b)) continue;  // frozen (a moving wall within reach woke it above)
      if (walls[w].normal.dot(grains[b].position - walls[w].point) > library[grains[b].shape].bounding_radius + activation)
        continue;
      candidates.push_back({-1, b, w, false, -1, GjkSimplex()});
    }
  ContactOptions build_options = contact_options;  // a cache build learns which pairs lie beyond activation + skin
  build_options.exit_beyond_activation = skin;
  std::vector<std::optional<PosedShape>> posed(n);  // the grains of this worker's candidates
  const auto posed_grain = [&](int k) -> const PosedShape& {
    if (!posed[k]) posed[k].emplace(library[grains[k].shape].shape, grains[k].position, grains[k].orientation);
    return *posed[k];
  };
  const auto compute = [&](const NarrowPhaseCandidate& c, GjkSimplex* simplex) {
    if (c.wall >= 0) {
      Plane plane;
      plane.point = walls[c.wall].point;
      plane.normal = walls[c.wall].normal;
      return plane_contact(plane, posed_grain(c.b), activation, contact_options);
    }
    return contact_manifold(posed_grain(c.a), posed_grain(c.b), activation, reuse ? contact_options : build_options,
                            simplex);
  };
  const std::vector<NarrowPhaseResult> found = narrow_phase(candidates, share, warm_geometry, compute);

  if (pairs && !reuse && n > 0) {
    pairs->begin_build();
    for (std::size_t i = 0; i < candidates.size(); i++) {
      const NarrowPhaseCandidate& c = candidates[i];
      if (c.wall < 0 && (c.frozen || found[i].gap < activation + skin))
        pairs->keep(c.a, c.b, c.frozen ? -std::numeric_limits<double>::infinity() : found[i].gap, found[i].simplex);
    }
    pairs->end_build(grains, library, activation);
  } else if (warm_geometry && reuse) {
    for (std::size_t i = 0; i < candidates.size(); i++)
      if (candidates[i].kept >= 0) pairs->set_simplex(static_cast<std::size_t>(candidates[i].kept), found[i].simplex);
  }

  // 3. the points made in top-down order (descending z, ties in detection order: the
  // candidates' order, each one's points in the manifold's order), each written once in
  // its place (they are large records, not to be copied by a sort after)
  std::vector<std::pair<int, int>> detected;  // (candidate, point of its manifold), detection order
  for (std::size_t i = 0; i < candidates.size(); i++)
    for (std::size_t k = 0; k < found[i].points.size(); k++) detected.emplace_back(static_cast<int>(i), static_cast<int>(k));
  const auto found_point = [&](std::size_t d) -> const ContactPoint& { return found[detected[d].first].points[detected[d].second]; };
  const std::vector<size_t> order = top_down_order(detected.size(), [&](size_t d) { return found_point(d).position.z(); });
  std::vector<size_t> place(detected.size());  // detection index → top-down index
  std::vector<GrainContactPoint>& points = problem.points;
  points.reserve(detected.size());
  for (size_t d : order) {
    place[d] = points.size();
    const NarrowPhaseCandidate& c = candidates[detected[d].first];
    const ContactPoint& p = found_point(d);
    if (c.wall >= 0)
      points.push_back(make_point(grains, -1, c.b, p.position, p.normal, p.gap, walls[c.wall].friction,
                                  walls[c.wall].velocity, -c.wall - 1, problem));
    else
      points.push_back(make_point(grains, c.a, c.b, p.position, p.normal, p.gap, options.friction,
                                  Eigen::Vector3d::Zero(), grains[c.a].tag, problem));
  }
  if (!problem.sweep_radius.empty())  // each pair's points are consecutive in detection order
    restrict_rolling(
        detected.size(), [&](size_t d) { return points[place[d]].pair; }, [&](size_t d) { return points[place[d]].position; },
        [&](size_t d) { return Eigen::Vector3d(points[place[d]].frame.col(0)); },
        [&](size_t d) -> NscdContact& { return points[place[d]].constraint; });

  // 4. warm start from the nearest stored point of the same pair within R_max / 4,
  // recalled in detection order (close to the memory's pair order)
  if (options.warm_start) {
    problem.warm_start.assign(points.size(), Eigen::Vector3d::Zero());
    if (!problem.sweep_radius.empty()) problem.couple_warm_start.assign(points.size(), Eigen::Vector2d::Zero());
    const double near2 = std::pow(0.25 * largest_radius, 2);
    for (size_t d = 0; d < detected.size(); d++) {
      const size_t c = place[d];
      if (const GrainImpulseMemory::Impulse* stored = memory.recall(points[c].pair, points[c].position, near2)) {
        problem.warm_start[c] = points[c].frame.transpose() * stored->impulse;
        if (!problem.couple_warm_start.empty())
          problem.couple_warm_start[c] = points[c].frame.rightCols<2>().transpose() * stored->couple;
      }
    }
  }
  set_step_contacts(problem);

  // the frozen points: last step's points of the pairs that sleep now
  if (sleep) {
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

  return problem;
}

GrainStepResult solve_grain_step(GrainStepProblem& problem, const std::vector<GrainState>& grains,
                                 const GrainStepOptions& options, std::uint64_t step_number,
                                 GrainImpulseMemory& memory) {
  const SolverSettings solver = options.solver_for_step(step_number);
  NscdStepResult solved = solve_nscd_step(problem.step, solver, problem.warm_start, &memory.backoff, problem.couple_warm_start);
  // sleeping grains that cannot stay at rest wake within the step, and the step is
  // solved again with them, until every grain still asleep can (the header)
  int woken_in_step = 0, sleeper_checks = 0;
  if (options.sleep.on()) {
    for (std::vector<int> woken = check_sleepers(problem, grains, options, solved, sleeper_checks); !woken.empty();
         woken = check_sleepers(problem, grains, options, solved, sleeper_checks)) {
      woken_in_step += wake_in_step(problem, grains, woken, options, solved);
      solved = solve_nscd_step(problem.step, solver, problem.warm_start, &memory.backoff, problem.couple_warm_start);
    }
  }
  const ContactImpulses impulses = contact_impulses(problem, grains, solved);
  const double h = problem.step.time_step;
  const int n = static_cast<int>(grains.size());
  GrainStepResult result;
  result.velocities = solved.velocities;
  result.angular_velocities = solved.angular_velocities;
  result.contact_forces.resize(n);
  result.contact_torques.resize(n);
  for (int k = 0; k < n; k++) {
    result.contact_forces[k] = impulses.on_grain[k] / h;
    result.contact_torques[k] = impulses.moment[k] / h;
  }
  result.wall_forces.resize(problem.wall_count);
  for (int w = 0; w < problem.wall_count; w++) result.wall_forces[w] = impulses.on_wall[w] / h;
  // the memory (warm start, frozen points) and the contact list: the solved points, then
  // the frozen ones (their last impulse taken as this step's)
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
    result.contacts.add(record);
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
  if (options.sleep.on()) {
    update_sleep(problem, grains, options.sleep, solved, result);
    result.stats.woken = problem.woken + woken_in_step;
    result.stats.sleeper_checks = sleeper_checks;
  }
  const NscdReport& report = solved.contacts.report;
  result.stats.sweeps = report.iterations;
  result.stats.residual = report.residual;
  result.stats.contact_points = static_cast<int>(problem.points.size());
  result.stats.max_overlap = solved.max_overlap;
  result.stats.max_predicted_penetration = solved.max_predicted_penetration;
  result.stats.hit_iteration_cap = report.hit_iteration_cap;
  result.stats.subspace_solves = report.subspace_solves;
  result.stats.subspace_accepted = report.subspace_accepted;
  result.stats.subspace_factorizations = report.subspace_factorizations;
  result.stats.frozen_points = static_cast<int>(problem.frozen.size());
  return result;
}

GrainStepResult grain_step(const std::vector<GrainState>& grains, const ShapeLibrary& library,
                           const std::vector<PlaneWall>& walls, double time_step, const GrainStepOptions& options,
                           std::uint64_t step_number, GrainImpulseMemory& memory) {
  GrainStepProblem problem = assemble_grain_step(grains, library, walls, time_step, options, memory);
  return solve_grain_step(problem, grains, options, step_number, memory);
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
