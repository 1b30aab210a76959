// A stack of boxes at rest on a frictional floor, integrated step after step with the core
// grain step (what fix nscd/polyhedra does each step), and the loads at every interface
// against the weights above it. Used by bench/nscd_stack and tests/core/test_box_stack.cpp.
//
// Boxes 1 × 1 × 1 of mass 1 (alternate: every second box 0.6 × 0.6 × 0.5 of mass 0.18,
// centred), g = 1 along −z, h = 1e-3, 4 corner points per interface; the stack starts
// exactly at rest and touching. The interface under box i must carry the weight of the
// boxes from i up, W_i = Σ_{j ≥ i} m_j g (statics, independent of the solver).
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/geometry/convex_shape.h"
#include "core/nscd/grain_step.h"

namespace wiregrain_bench {

struct BoxStackRun {
  double worst_load_error = 0.0;  // max over steps and interfaces of |F_i − W_i| / W_i
  int steps_over_1e4 = 0;         // steps whose worst relative load error is above 1e-4
  int capped_steps = 0;
  long sweeps = 0, subspace_solves = 0, subspace_kept = 0;
  int max_sweeps = 0;
  double largest_speed = 0.0;     // of any box at any step
};

// verbose: one line per step on stdout.
inline BoxStackRun run_box_stack(int n, bool alternate, int steps, const wiregrain::GrainStepOptions& options,
                                 bool verbose = false) {
  using namespace wiregrain;
  const double g = 1.0, h = 1e-3;
  ShapeLibrary library;
  library.add(ConvexShape::box(1.0, 1.0, 1.0));
  library.add(ConvexShape::box(0.6, 0.6, 0.5));
  std::vector<GrainState> grains;
  double z = 0.0;
  for (int i = 0; i < n; ++i) {  // bottom up
    const bool small = alternate && i % 2 == 1;
    GrainState s;
    s.tag = i + 1;
    s.shape = small ? 1 : 0;
    const Eigen::Vector3d size = small ? Eigen::Vector3d(0.6, 0.6, 0.5) : Eigen::Vector3d(1, 1, 1);
    s.mass = small ? 0.18 : 1.0;
    s.inertia = s.mass / 12.0 * Eigen::Vector3d(size.y() * size.y() + size.z() * size.z(),
                                                size.x() * size.x() + size.z() * size.z(),
                                                size.x() * size.x() + size.y() * size.y());
    s.position = Eigen::Vector3d(0, 0, z + 0.5 * size.z());
    s.force = Eigen::Vector3d(0, 0, -s.mass * g);
    z += size.z();
    grains.push_back(s);
  }
  std::vector<double> load(n, 0.0);
  for (int i = n - 1; i >= 0; --i) load[i] = grains[i].mass * g + (i + 1 < n ? load[i + 1] : 0.0);

  PlaneWall floor;
  floor.friction = options.friction;
  GrainImpulseMemory memory;
  BoxStackRun run;
  for (int step = 0; step < steps; ++step) {
    const GrainStepResult r = grain_step(grains, library, {floor}, h, options, step, memory);
    // the force on box i from below: records with b = tag i (a = the floor or box i − 1)
    std::vector<double> carried(n, 0.0);
    for (const ContactRecord& c : r.contacts.records()) carried[c.b - 1] += c.force.z();
    double worst = 0.0;
    for (int i = 0; i < n; ++i) worst = std::max(worst, std::fabs(carried[i] - load[i]) / load[i]);
    run.worst_load_error = std::max(run.worst_load_error, worst);
    if (worst > 1e-4) ++run.steps_over_1e4;
    if (r.stats.hit_iteration_cap) ++run.capped_steps;
    run.sweeps += r.stats.sweeps;
    run.max_sweeps = std::max(run.max_sweeps, r.stats.sweeps);
    run.subspace_solves += r.stats.subspace_solves;
    run.subspace_kept += r.stats.subspace_accepted;
    if (verbose)
      std::printf("step %d: sweeps %d residual %.3e load error %.3e stick solves %d kept %d\n", step, r.stats.sweeps,
                  r.stats.residual, worst, r.stats.subspace_solves, r.stats.subspace_accepted);
    for (int i = 0; i < n; ++i) {
      GrainState& s = grains[i];
      const Eigen::Matrix3d rot = s.orientation.toRotationMatrix();
      const Eigen::Matrix3d inertia_world = rot * s.inertia.asDiagonal() * rot.transpose();
      const GrainPose pose = advance_grain_pose({s.position, s.orientation}, s.inertia, s.velocity, r.velocities[i],
                                                inertia_world * s.angular_velocity,
                                                inertia_world * r.angular_velocities[i], h, options.law.theta);
      s.position = pose.position;
      s.orientation = pose.orientation;
      s.velocity = r.velocities[i];
      s.angular_velocity = r.angular_velocities[i];
      run.largest_speed = std::max(run.largest_speed, s.velocity.norm());
    }
  }
  return run;
}

}  // namespace wiregrain_bench
