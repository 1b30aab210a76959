// Pieces of the grain step (core/nscd/grain_step.h) shared by its assembly
// (grain_assembly.cpp), its contact detection (grain_detection.cpp) and its sleeping
// grains (grain_sleep.cpp): a grain as a body of the solve, a contact point as a row of
// it, and the top-down order of the points.
#pragma once

#include <Eigen/Dense>

#include <cstddef>
#include <vector>

#include "core/common/stable_order.h"
#include "core/nscd/grain_step.h"

namespace wiregrain {
namespace grain_step_detail {

// Step 1 for one grain: free velocities with implicit damping (core/nscd/grain_step.h).
NscdBody free_body(const GrainState& g, double h, double damping);

// Rolling resistance of a point between grain body_b and grain body_a (−1: a wall), if on:
// μ_r, and R the sum of the sweep radii (sharp grains on a wall: none).
void set_rolling(NscdContact& row, const GrainStepProblem& problem, int body_a, int body_b);

// A contact point between grain body_b and grain body_a (or wall −(key_a + 1) when
// body_a < 0) at `position`, normal from a to b.
GrainContactPoint make_point(const std::vector<GrainState>& grains, int body_a, int body_b,
                             const Eigen::Vector3d& position, const Eigen::Vector3d& normal, double gap, double mu,
                             const Eigen::Vector3d& wall_velocity, long key_a, const GrainStepProblem& problem);

// restrict_rolling (core/nscd/rolling_axes.h) on points[begin, end)
void restrict_point_rolling(std::vector<GrainContactPoint>& points, std::size_t begin);

// Step 3: the top-down order of `count` points (descending z, ties in the order given)
template <class Height>
std::vector<std::size_t> top_down_order(std::size_t count, const Height& z_of) {
  return stable_order(count, [&](std::size_t c) { return -z_of(c); });
}

// The solver's rows, parallel to the points
void set_step_contacts(GrainStepProblem& problem);

// Step 3 on points already made (grains woken within the step): the points from the top
// down, with their rows and warm starts.
void sort_top_down(GrainStepProblem& problem);

}  // namespace grain_step_detail
}  // namespace wiregrain
