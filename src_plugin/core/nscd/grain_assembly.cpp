// Steps 1–4 of a grain step (core/nscd/grain_step.h): the bodies, the contact points from
// the top down and their warm start; and the pieces the sleeping grains share
// (grain_assembly.h).
#include "core/nscd/grain_assembly.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/common/errors.h"
#include "core/common/validation.h"
#include "core/nscd/grain_detection.h"
#include "core/nscd/grain_sleep.h"

namespace wiregrain {
namespace grain_step_detail {

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

void set_rolling(NscdContact& row, const GrainStepProblem& problem, int body_a, int body_b) {
  if (problem.sweep_radius.empty()) return;
  row.rolling_radius = problem.sweep_radius[body_b] + (body_a >= 0 ? problem.sweep_radius[body_a] : 0.0);
  row.rolling_friction = row.rolling_radius > 0.0 ? problem.rolling_friction : 0.0;
}

GrainContactPoint make_point(const std::vector<GrainState>& grains, int body_a, int body_b,
                             const Eigen::Vector3d& position, const Eigen::Vector3d& normal, double gap, double mu,
                             const Eigen::Vector3d& wall_velocity, long key_a, const GrainStepProblem& problem) {
  GrainContactPoint c;
  set_rolling(c.constraint, problem, body_a, body_b);
  c.frame = contact_frame(normal);
  c.constraint.body_a = body_a;
  c.constraint.body_b = body_b;
  const PeriodicBox& box = problem.box;  // the lever arms in the minimum image
  if (body_a >= 0)
    c.constraint.jacobian_a = contact_jacobian(c.frame, box.minimum_image(position - grains[body_a].position), -1.0);
  c.constraint.jacobian_b = contact_jacobian(c.frame, box.minimum_image(position - grains[body_b].position), 1.0);
  c.constraint.velocity_offset = -c.frame.transpose() * wall_velocity;
  c.constraint.friction = mu;
  c.constraint.gap = gap;
  c.pair = {key_a, grains[body_b].tag};
  c.position = position;
  return c;
}

void restrict_point_rolling(std::vector<GrainContactPoint>& points, size_t begin) {
  restrict_rolling(
      points.size() - begin, [&](size_t i) { return points[begin + i].pair; },
      [&](size_t i) { return points[begin + i].position; }, [&](size_t i) { return Eigen::Vector3d(points[begin + i].frame.col(0)); },
      [&](size_t i) -> NscdContact& { return points[begin + i].constraint; });
}

void set_step_contacts(GrainStepProblem& problem) {
  problem.step.contacts.clear();
  problem.step.contacts.reserve(problem.points.size());
  for (const GrainContactPoint& c : problem.points) {
    problem.step.contacts.push_back(c.constraint);
    const int wall = c.pair.first < 0 ? static_cast<int>(-c.pair.first - 1) : -1;
    if (wall < 0 || problem.wall_body.empty() || problem.wall_body[wall] < 0) continue;
    // a plate's point (PlaneWall): the plate is body a, moving along its normal n only,
    // H_a = −frameᵀ n nᵀ; its velocity is the body's, not an offset
    NscdContact& row = problem.step.contacts.back();
    const Eigen::Vector3d& n = problem.walls[wall].normal;
    row.body_a = problem.wall_body[wall];
    row.jacobian_a.setZero();
    row.jacobian_a.leftCols<3>() = -(c.frame.transpose() * n) * n.transpose();
    row.velocity_offset.setZero();
  }
}

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

namespace {

void check_inputs(const std::vector<GrainState>& grains, const ShapeLibrary& library,
                  const std::vector<PlaneWall>& walls, double h, const PeriodicBox& box) {
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
  for (std::size_t w = 0; w < walls.size(); w++) {
    const PlaneWall& wall = walls[w];
    if (!(wall.mass >= 0.0) || !std::isfinite(wall.mass) || !wall.force.allFinite())
      throw InvalidArgument("walls", "grain step: wall " + std::to_string(w + 1) +
                                         ": the mass must be >= 0 and finite and the force finite");
    // a plate moves along its normal only (a tangential part beyond round-off is an error)
    if (wall.plate() && !((wall.velocity - wall.normal.dot(wall.velocity) * wall.normal).norm() <=
                          1e-12 * wall.velocity.norm()))
      throw InvalidArgument("walls", "grain step: wall " + std::to_string(w + 1) +
                                         " is a plate (mass > 0): its velocity must be along its normal");
  }
  for (std::size_t w = 0; w < walls.size(); w++)
    for (int d = 0; d < 3; d++)
      if (box.periodic[d] && walls[w].normal[d] != 0.0)
        throw InvalidArgument("walls", "grain step: wall " + std::to_string(w + 1) +
                                           " is not parallel to the periodic dimension " + "xyz"[d] +
                                           " (its normal has a component along " + "xyz"[d] + ")");
}

// Each periodic length at least twice the reach of a pair, so that no grain is within
// reach of two images of one partner (or of its own image): the minimum image is then
// the only one that can touch.
void check_periodic_reach(const PeriodicBox& box, double reach) {
  for (int d = 0; d < 3; d++)
    if (box.periodic[d] && !(box.length(d) >= 2.0 * reach))
      throw InvalidArgument("box", std::string("grain step: the periodic box is ") + format_number(box.length(d)) +
                                       " long along " + "xyz"[d] + ", below twice the pair reach " +
                                       format_number(reach) +
                                       " (2 x the largest bounding radius + the activation distance + the skin)");
}


// A distributed step's partition (GrainPartition): InvalidArgument("sleep" | "exchange" |
// "rolling_friction" | "walls" | "grains", ...).
void check_partition(const GrainPartition& partition, const std::vector<GrainState>& grains,
                     const std::vector<PlaneWall>& walls, const GrainStepOptions& options, const WorkShare* share) {
  if (partition.exchange == nullptr || share != nullptr)
    throw InvalidArgument("exchange", "grain step: a distributed step needs the workers' exchange and no shared detection");
  if (options.sleep.on()) throw InvalidArgument("sleep", "grain step: sleeping grains are not solved distributed");
  if (options.rolling_friction > 0.0)
    throw InvalidArgument("rolling_friction", "grain step: rolling resistance is not solved distributed");
  for (const PlaneWall& w : walls)  // (a plate would be a body of every worker)
    if (w.plate()) throw InvalidArgument("walls", "grain step: a plate is not solved distributed");
  if (partition.owned < 0 || partition.owned > static_cast<int>(grains.size()))
    throw InvalidArgument("grains", "grain step: " + std::to_string(partition.owned) + " own grains of " +
                                        std::to_string(grains.size()));
  for (int k = 1; k < partition.owned; k++)
    if (!(grains[k - 1].tag < grains[k].tag))
      throw InvalidArgument("grains", "grain step: a worker's own grains must come first in ascending tag order");
}

// Mass splitting (core/nscd/nscd_step.h): per body, how many of its copies over all
// workers this step's contacts touch.
void count_touching_copies(GrainStepProblem& problem) {
  std::vector<double> touched(problem.step.bodies.size(), 0.0);
  for (const NscdContact& c : problem.step.contacts) {
    if (c.body_a >= 0) touched[c.body_a] = 1.0;
    touched[c.body_b] = 1.0;
  }
  problem.exchange->sum_over_copies(touched, 1);
  problem.step.distributed = true;
  problem.step.touching_copies = std::move(touched);
}

// Step 1: every grain a body with its free velocities and implicit damping (a sleeping
// grain: infinite mass and no velocity). largest_radius: the largest bounding radius R;
// fastest: the largest |v_free| + |ω_free| R.
struct BodyExtent {
  double largest_radius = 0.0, fastest = 0.0;
};
BodyExtent add_free_bodies(GrainStepProblem& problem, const std::vector<GrainState>& grains,
                           const ShapeLibrary& library, double damping) {
  const double h = problem.step.time_step;
  const auto asleep = [&](int k) { return !problem.asleep.empty() && problem.asleep[k]; };
  BodyExtent extent;
  for (const GrainState& g : grains) {
    const NscdBody b = asleep(static_cast<int>(problem.step.bodies.size())) ? NscdBody() : free_body(g, h, damping);
    problem.step.bodies.push_back(b);
    const double radius = library[g.shape].bounding_radius;
    extent.largest_radius = std::max(extent.largest_radius, radius);
    extent.fastest = std::max(extent.fastest, b.velocity_free.norm() + b.angular_velocity_free.norm() * radius);
  }
  return extent;
}

// Step 1 for the plates (PlaneWall::mass > 0): a body each, after the grains, of inverse
// mass 1/m_p and no rotation, at its free velocity (grain_step.h, PlaneWall).
void add_plate_bodies(GrainStepProblem& problem, const std::vector<PlaneWall>& walls) {
  const double h = problem.step.time_step;
  problem.wall_body.assign(walls.size(), -1);
  for (std::size_t w = 0; w < walls.size(); w++) {
    if (!walls[w].plate()) continue;
    NscdBody b;
    b.inverse_mass = 1.0 / walls[w].mass;
    b.velocity_begin = walls[w].velocity;
    b.velocity_free = walls[w].free_velocity(h);
    problem.wall_body[w] = static_cast<int>(problem.step.bodies.size());
    problem.step.bodies.push_back(b);
  }
}

// Step 3: the points made in top-down order (descending z, ties in detection order: the
// candidates' order, each one's points in the manifold's order), each written once in
// its place (they are large records, not to be copied by a sort after), with their
// rolling axes.
struct DetectionOrder {
  std::vector<std::pair<int, int>> detected;  // (candidate, point of its manifold), detection order
  std::vector<size_t> place;                  // detection index → top-down index
};
DetectionOrder add_points_top_down(GrainStepProblem& problem, const std::vector<GrainState>& grains,
                                   const std::vector<PlaneWall>& walls, const GrainStepOptions& options,
                                   const DetectedContacts& contacts) {
  const std::vector<NarrowPhaseCandidate>& candidates = contacts.candidates;
  const std::vector<NarrowPhaseResult>& found = contacts.found;
  DetectionOrder out;
  std::vector<std::pair<int, int>>& detected = out.detected;
  for (std::size_t i = 0; i < candidates.size(); i++)
    for (std::size_t k = 0; k < found[i].points.size(); k++) detected.emplace_back(static_cast<int>(i), static_cast<int>(k));
  const auto found_point = [&](std::size_t d) -> const ContactPoint& { return found[detected[d].first].points[detected[d].second]; };
  const std::vector<size_t> order = top_down_order(detected.size(), [&](size_t d) { return found_point(d).position.z(); });
  std::vector<size_t>& place = out.place;
  place.resize(detected.size());
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
  return out;
}

// Step 4: warm start from the nearest stored point of the same pair within R_max / 4,
// recalled in detection order (close to the memory's pair order)
void recall_warm_start(GrainStepProblem& problem, const GrainImpulseMemory& memory, const DetectionOrder& order,
                       double largest_radius) {
  std::vector<GrainContactPoint>& points = problem.points;
  problem.warm_start.assign(points.size(), Eigen::Vector3d::Zero());
  if (!problem.sweep_radius.empty()) problem.couple_warm_start.assign(points.size(), Eigen::Vector2d::Zero());
  const double near2 = std::pow(0.25 * largest_radius, 2);
  for (size_t d = 0; d < order.detected.size(); d++) {
    const size_t c = order.place[d];
    if (const GrainImpulseMemory::Impulse* stored = memory.recall(points[c].pair, points[c].position, near2, problem.box)) {
      problem.warm_start[c] = points[c].frame.transpose() * stored->impulse;
      if (!problem.couple_warm_start.empty())
        problem.couple_warm_start[c] = points[c].frame.rightCols<2>().transpose() * stored->couple;
    }
  }
}

}  // namespace
}  // namespace grain_step_detail

using namespace grain_step_detail;

GrainStepProblem assemble_grain_step(const std::vector<GrainState>& grains, const ShapeLibrary& library,
                                     const std::vector<PlaneWall>& walls, double h, const GrainStepOptions& options,
                                     const GrainImpulseMemory& memory, GrainPairCache* pairs,
                                     const WorkShare* share, const GrainPartition* partition) {
  options.validate();
  check_inputs(grains, library, walls, h, options.box);
  const int n = static_cast<int>(grains.size());
  if (partition) check_partition(*partition, grains, walls, options, share);
  GrainStepProblem problem;
  problem.wall_count = static_cast<int>(walls.size());
  problem.walls = walls;
  problem.step.time_step = h;
  problem.step.law = options.law;
  // distributed: the copies carry their image positions, pairs are taken as they are
  problem.box = partition ? PeriodicBox() : options.box;
  if (partition) {
    problem.exchange = partition->exchange;
    problem.owned = partition->owned;
  }
  if (options.rolling_friction > 0.0) {
    problem.rolling_friction = options.rolling_friction;
    problem.sweep_radius.resize(n);
    for (int k = 0; k < n; k++) problem.sweep_radius[k] = library[grains[k].shape].shape.sweep_radius();
  }
  // 0. sleeping: who sleeps in this step
  const bool sleep = options.sleep.on();
  if (sleep) begin_sleeping_step(problem, grains, library, walls, options);
  // 1. bodies
  BodyExtent extent = add_free_bodies(problem, grains, library, options.damping);
  add_plate_bodies(problem, walls);
  if (partition) {  // over every worker's grains
    extent.largest_radius = partition->exchange->max_over_workers(extent.largest_radius);
    extent.fastest = partition->exchange->max_over_workers(extent.fastest);
  }
  // 2. contact points of every pair whose gap may close within the step (grain_detection.h)
  double wall_speed = 0.0;
  for (const PlaneWall& w : walls) wall_speed = std::max(wall_speed, w.velocity.norm());
  for (const PlaneWall& w : walls)  // a plate: its start or free speed (contacts only slow its approach)
    if (w.plate()) wall_speed = std::max(wall_speed, w.free_velocity(h).norm());
  const double activation = options.margin + 2.0 * h * (2.0 * extent.fastest + wall_speed) + 1e-12;
  problem.activation = activation;
  problem.largest_radius = extent.largest_radius;
  if (options.box.any()) check_periodic_reach(options.box, 2.0 * extent.largest_radius + activation + (pairs ? pairs->skin() : 0.0));
  GrainStepOptions detection_options = options;
  detection_options.box = problem.box;
  const DetectedContacts contacts = detect_contacts(grains, library, walls, detection_options, problem.asleep,
                                                    activation, extent.largest_radius, pairs, share,
                                                    partition ? partition->owned : -1);
  // 3. the points from the top down
  const DetectionOrder order = add_points_top_down(problem, grains, walls, options, contacts);
  // 4. warm start
  if (options.warm_start) recall_warm_start(problem, memory, order, extent.largest_radius);
  set_step_contacts(problem);
  // the frozen points: last step's points of the pairs that sleep now
  if (sleep) freeze_sleeping_pairs(problem, grains, walls, memory);
  if (partition) count_touching_copies(problem);
  return problem;
}

}  // namespace wiregrain
