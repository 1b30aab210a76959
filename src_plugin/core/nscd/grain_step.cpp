#include "core/nscd/grain_step.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

#include "core/common/errors.h"
#include "core/geometry/broad_phase.h"
#include "core/geometry/contact_geometry.h"
#include "core/nscd/rigid_body.h"

namespace wiregrain {

NscdOptions grain_solver_defaults() {
  NscdOptions options;
  options.order = SweepOrder::forward;
  options.measure = ConvergenceMeasure::natural_map;
  options.method = SolverMethod::subspace;
  options.overlap_speed = 0.1;
  return options;
}

NscdOptions GrainStepOptions::solver_for_step(std::uint64_t step_number) const {
  NscdOptions step_options = solver;
  step_options.seed = solver.seed + step_number;
  return step_options;
}

void GrainStepOptions::validate() const {
  solver.validate();
  if (!(friction >= 0.0)) throw InvalidArgument("friction", "grain step: friction must be >= 0, got " + std::to_string(friction));
  if (!(damping >= 0.0)) throw InvalidArgument("damping", "grain step: damping must be >= 0, got " + std::to_string(damping));
  if (!(margin >= 0.0)) throw InvalidArgument("margin", "grain step: margin must be >= 0, got " + std::to_string(margin));
  if (!(sleep.speed >= 0.0) || !std::isfinite(sleep.speed) || !(sleep.time > 0.0) || !std::isfinite(sleep.time))
    throw InvalidArgument("sleep", "grain step: sleep needs a speed >= 0 and a time > 0, got " +
                                       std::to_string(sleep.speed) + " and " + std::to_string(sleep.time));
}

const GrainImpulseMemory::Impulse* GrainImpulseMemory::recall(const PairKey& pair, const Eigen::Vector3d& position,
                                                               double radius2) const {
  const auto it = pairs_.find(pair);
  if (it == pairs_.end()) return nullptr;
  const Impulse* nearest = nullptr;
  double best = radius2;
  for (const Impulse& stored : it->second) {
    const double d2 = (stored.position - position).squaredNorm();
    if (d2 < best) {
      best = d2;
      nearest = &stored;
    }
  }
  return nearest;
}

namespace {

// Sleeping (the header): the balance of each sleeping grain and the quiet time of each
// awake one after the solve; a grain that falls asleep stops.
void update_sleep(const GrainStepProblem& problem, const std::vector<GrainState>& grains, const SleepOptions& sleep,
                  GrainStepResult& result) {
  const double h = problem.step.time_step;
  const int n = static_cast<int>(grains.size());
  result.asleep.assign(n, 0);
  result.quiet_time.assign(n, 0.0);
  result.stats.woken = problem.woken;
  const double wake_speed_change = sleep.speed * h / sleep.time;
  for (int k = 0; k < n; k++) {
    const GrainState& g = grains[k];
    const double radius = problem.bounding_radius[k];
    if (problem.asleep[k]) {
      // |Δv| + |Δω| R of the net impulse, h (F + contact forces), were the grain free
      const Eigen::Matrix3d r = g.orientation.toRotationMatrix();
      const Eigen::Matrix3d inverse_inertia = r * g.inertia.cwiseInverse().asDiagonal() * r.transpose();
      const double change = h * ((g.force + result.contact_forces[k]).norm() / g.mass +
                                 radius * (inverse_inertia * (g.torque + result.contact_torques[k])).norm());
      if (change > wake_speed_change) {
        result.stats.woken++;
        continue;  // awake from the next step, quiet time 0
      }
      result.asleep[k] = 1;
      result.quiet_time[k] = problem.quiet_time[k];
    } else {
      const double speed = result.velocities[k].norm() + result.angular_velocities[k].norm() * radius;
      if (!(speed < sleep.speed)) continue;
      result.quiet_time[k] = problem.quiet_time[k] + h;
      if (result.quiet_time[k] < sleep.time) continue;
      result.asleep[k] = 1;
      result.velocities[k].setZero();
      result.angular_velocities[k].setZero();
    }
  }
  for (char a : result.asleep) result.stats.sleeping += a;
}

void check_inputs(const std::vector<GrainState>& grains, const ShapeLibrary& library,
                  const std::vector<PlaneWall>& walls, double h) {
  if (!(h > 0.0) || !std::isfinite(h)) throw InvalidArgument("time_step", "grain step: h must be > 0 and finite");
  for (const GrainState& g : grains) {
    if (!(g.quiet_time >= 0.0) || !std::isfinite(g.quiet_time))
      throw InvalidArgument("grains", "grain step: grain " + std::to_string(g.tag) + ": quiet time must be >= 0 and finite");
    const std::string name = "grain step: grain " + std::to_string(g.tag) + ": ";
    if (g.shape < 0 || g.shape >= library.size())
      throw InvalidArgument("grains", name + "shape index " + std::to_string(g.shape) + " not in the library");
    if (!(g.mass > 0.0) || !std::isfinite(g.mass) || !(g.inertia.minCoeff() > 0.0) || !g.inertia.allFinite())
      throw InvalidArgument("grains", name + "mass and principal moments must be > 0 and finite");
    if (!(g.position.allFinite() && g.orientation.coeffs().allFinite() && g.velocity.allFinite() &&
          g.angular_velocity.allFinite() && g.force.allFinite() && g.torque.allFinite()))
      throw InvalidArgument("grains", name + "non-finite state");
    if (std::fabs(g.orientation.norm() - 1.0) > 1e-9) throw InvalidArgument("grains", name + "orientation is not a unit quaternion");
  }
  for (const PlaneWall& w : walls)
    if (!(w.point.allFinite() && w.velocity.allFinite()) || !(std::fabs(w.normal.norm() - 1.0) <= 1e-9) ||
        !(w.friction >= 0.0))
      throw InvalidArgument("walls", "grain step: a wall needs a finite point and velocity, a unit normal and friction >= 0");
}

}  // namespace

GrainStepProblem assemble_grain_step(const std::vector<GrainState>& grains, const ShapeLibrary& library,
                                     const std::vector<PlaneWall>& walls, double h, const GrainStepOptions& options,
                                     const GrainImpulseMemory& memory, GrainPairCache* pairs) {
  options.validate();
  check_inputs(grains, library, walls, h);
  const int n = static_cast<int>(grains.size());
  GrainStepProblem problem;
  problem.wall_count = static_cast<int>(walls.size());
  problem.step.time_step = h;

  // 0. sleeping: who sleeps in this step. A sleeping grain wakes now if the deck gave it
  // a velocity or a moving wall can reach it within the step (relative speed |v_wall|).
  const bool sleep = options.sleep.on();
  if (sleep) {
    problem.asleep.assign(n, 0);
    problem.quiet_time.assign(n, 0.0);
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
  std::vector<PosedShape> posed;
  posed.reserve(n);
  double largest_radius = 0.0, fastest = 0.0;
  const double damped = 1.0 / (1.0 + h * options.damping);
  for (const GrainState& g : grains) {
    posed.emplace_back(library[g.shape].shape, g.position, g.orientation);
    const Eigen::Matrix3d r = g.orientation.toRotationMatrix();
    NscdBody b;
    b.inverse_mass = damped / g.mass;
    b.inverse_inertia = damped * (r * g.inertia.cwiseInverse().asDiagonal() * r.transpose());
    const Eigen::Matrix3d inertia_world = r * g.inertia.asDiagonal() * r.transpose();
    b.velocity_begin = g.velocity;
    b.angular_velocity_begin = g.angular_velocity;
    b.velocity_free = damped * (g.velocity + h * g.force / g.mass);
    b.angular_velocity_free = b.inverse_inertia * (inertia_world * g.angular_velocity + h * g.torque);
    if (asleep(static_cast<int>(problem.step.bodies.size()))) b = NscdBody();
    problem.step.bodies.push_back(b);
    const double radius = library[g.shape].bounding_radius;
    largest_radius = std::max(largest_radius, radius);
    fastest = std::max(fastest, b.velocity_free.norm() + b.angular_velocity_free.norm() * radius);
  }

  // 2. contact points of every pair whose gap may close within the step
  double wall_speed = 0.0;
  for (const PlaneWall& w : walls) wall_speed = std::max(wall_speed, w.velocity.norm());
  const double activation = options.margin + 2.0 * h * (2.0 * fastest + wall_speed) + 1e-12;
  ContactOptions contact_options;
  contact_options.near_vertices = options.near_vertices;
  std::vector<GrainContactPoint>& points = problem.points;
  const auto add_point = [&](int body_a, int body_b, const ContactPoint& p, double mu,
                             const Eigen::Vector3d& wall_velocity, long key_a) {
    GrainContactPoint c;
    c.frame = contact_frame(p.normal);
    c.constraint.body_a = body_a;
    c.constraint.body_b = body_b;
    if (body_a >= 0) c.constraint.jacobian_a = contact_jacobian(c.frame, p.position - grains[body_a].position, -1.0);
    c.constraint.jacobian_b = contact_jacobian(c.frame, p.position - grains[body_b].position, 1.0);
    c.constraint.velocity_offset = -c.frame.transpose() * wall_velocity;
    c.constraint.friction = mu;
    c.constraint.gap = p.gap;
    c.pair = {key_a, grains[body_b].tag};
    c.position = p.position;
    points.push_back(c);
  };
  // pairs a < b, b ascending for each a (grains in tag order): the same order whether the
  // pairs come from the broad phase or from the pair cache (grain_pairs.h)
  const auto add_pair_points = [&](int a, int b, const ContactManifold& m) {
    for (const ContactPoint& p : m.points) add_point(a, b, p, options.friction, Eigen::Vector3d::Zero(), grains[a].tag);
  };
  if (n > 0 && pairs && pairs->valid(grains, library, activation)) {
    pairs->count_reuse();
    for (const auto& [a, b] : pairs->pairs())
      if (!(asleep(a) && asleep(b))) add_pair_points(a, b, contact_manifold(posed[a], posed[b], activation, contact_options));
  } else if (n > 0) {
    const double skin = pairs ? pairs->skin() : 0.0;
    ContactOptions build_options = contact_options;
    build_options.exit_beyond_activation = skin;
    if (pairs) pairs->begin_build();
    BroadPhaseGrid grid = BroadPhaseGrid::unbounded(2.0 * largest_radius + activation + skin);
    for (const GrainState& g : grains) grid.insert(g.position);
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
      for (int b : near) {
        if (asleep(a) && asleep(b)) {  // frozen; kept in the cache for when one wakes
          if (pairs) pairs->keep(a, b);
          continue;
        }
        const ContactManifold m = contact_manifold(posed[a], posed[b], activation, build_options);
        add_pair_points(a, b, m);
        if (pairs && m.gap < activation + skin) pairs->keep(a, b);
      }
    }
    if (pairs) pairs->end_build(grains, library, activation);
  }
  for (int w = 0; w < (int)walls.size(); w++) {
    Plane plane;
    plane.point = walls[w].point;
    plane.normal = walls[w].normal;
    for (int b = 0; b < n; b++) {
      if (asleep(b)) continue;  // frozen (a moving wall within reach woke it above)
      if (plane.normal.dot(grains[b].position - plane.point) > library[grains[b].shape].bounding_radius + activation)
        continue;
      for (const ContactPoint& p : plane_contact(plane, posed[b], activation, contact_options).points)
        add_point(-1, b, p, walls[w].friction, walls[w].velocity, -w - 1);
    }
  }

  // 3. top-down order (descending z of the point, ties in detection order)
  std::stable_sort(points.begin(), points.end(), [](const GrainContactPoint& a, const GrainContactPoint& b) {
    return a.position.z() > b.position.z();
  });
  problem.step.contacts.reserve(points.size());
  for (const GrainContactPoint& c : points) problem.step.contacts.push_back(c.constraint);

  // the frozen points: last step's points of the pairs that sleep now
  if (sleep) {
    std::unordered_map<long, int> index_of_tag;
    for (int k = 0; k < n; k++) index_of_tag[grains[k].tag] = k;
    const auto sleeping_tag = [&](long tag) {
      const auto it = index_of_tag.find(tag);
      return it != index_of_tag.end() && problem.asleep[it->second];
    };
    for (const auto& [pair, stored] : memory.pairs())
      if (sleeping_tag(pair.second) && (pair.first < 0 || sleeping_tag(pair.first)))
        for (const GrainImpulseMemory::Impulse& point : stored) problem.frozen.emplace_back(pair, point);
  }

  // 4. warm start from the nearest stored point of the same pair within R_max / 4
  if (options.warm_start) {
    problem.warm_start.assign(points.size(), Eigen::Vector3d::Zero());
    const double near2 = std::pow(0.25 * largest_radius, 2);
    for (size_t c = 0; c < points.size(); c++)
      if (const GrainImpulseMemory::Impulse* stored = memory.recall(points[c].pair, points[c].position, near2))
        problem.warm_start[c] = points[c].frame.transpose() * stored->impulse;
  }
  return problem;
}

GrainStepResult solve_grain_step(const GrainStepProblem& problem, const std::vector<GrainState>& grains,
                                 const GrainStepOptions& options, std::uint64_t step_number,
                                 GrainImpulseMemory& memory) {
  const NscdStepResult solved =
      solve_nscd_step(problem.step, options.solver_for_step(step_number), problem.warm_start, &memory.backoff);
  const double h = problem.step.time_step;
  const int n = static_cast<int>(grains.size());
  GrainStepResult result;
  result.velocities = solved.velocities;
  result.angular_velocities = solved.angular_velocities;
  result.contact_forces.assign(n, Eigen::Vector3d::Zero());
  result.contact_torques.assign(n, Eigen::Vector3d::Zero());
  result.wall_forces.assign(problem.wall_count, Eigen::Vector3d::Zero());
  memory.clear();
  // Hᵀ r per grain: the force r (world frame) on b at the point, −r on a; the solved
  // points, then the frozen ones (their last impulse taken as this step's)
  const auto add_point = [&](const GrainImpulseMemory::PairKey& pair, int body_a, int body_b,
                             const GrainImpulseMemory::Impulse& point) {
    memory.add(pair, point);
    const Eigen::Vector3d on_b = point.impulse / h;
    result.contact_forces[body_b] += on_b;
    result.contact_torques[body_b] += (point.position - grains[body_b].position).cross(on_b);
    if (body_a >= 0) {
      result.contact_forces[body_a] -= on_b;
      result.contact_torques[body_a] -= (point.position - grains[body_a].position).cross(on_b);
    } else {
      result.wall_forces[-pair.first - 1] -= on_b;
    }
    ContactRecord record;
    record.kind = body_a >= 0 ? ContactKind::grain_grain : ContactKind::grain_wall;
    record.a = pair.first;
    record.b = pair.second;
    record.point = point.position;
    record.normal = point.normal;
    record.force = on_b;
    record.overlap = -point.gap;
    record.status = point.status;
    result.contacts.add(record);
  };
  for (size_t c = 0; c < problem.points.size(); c++) {
    const GrainContactPoint& point = problem.points[c];
    const NscdContact& con = point.constraint;
    GrainImpulseMemory::Impulse stored{point.position, point.frame * solved.contacts.impulses[c]};
    stored.normal = point.frame.col(0);
    stored.gap = con.gap;
    stored.status = static_cast<ContactStatus>(static_cast<int>(solved.contacts.states[c]));
    add_point(point.pair, con.body_a, con.body_b, stored);
  }
  if (!problem.frozen.empty()) {
    std::unordered_map<long, int> index_of_tag;
    for (int k = 0; k < n; k++) index_of_tag[grains[k].tag] = k;
    for (const auto& [pair, stored] : problem.frozen)
      add_point(pair, pair.first < 0 ? -1 : index_of_tag.at(pair.first), index_of_tag.at(pair.second), stored);
  }
  if (options.sleep.on()) update_sleep(problem, grains, options.sleep, result);
  const NscdReport& report = solved.contacts.report;
  result.stats.sweeps = report.iterations;
  result.stats.residual = report.residual;
  result.stats.contact_points = static_cast<int>(problem.points.size());
  result.stats.max_overlap = solved.max_overlap;
  result.stats.max_predicted_penetration = solved.max_predicted_penetration;
  result.stats.hit_iteration_cap = report.hit_iteration_cap;
  result.stats.subspace_solves = report.subspace_solves;
  result.stats.subspace_accepted = report.subspace_accepted;
  result.stats.frozen_points = static_cast<int>(problem.frozen.size());
  return result;
}

GrainStepResult grain_step(const std::vector<GrainState>& grains, const ShapeLibrary& library,
                           const std::vector<PlaneWall>& walls, double time_step, const GrainStepOptions& options,
                           std::uint64_t step_number, GrainImpulseMemory& memory) {
  const GrainStepProblem problem = assemble_grain_step(grains, library, walls, time_step, options, memory);
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
