// Sleeping grains of a grain step (core/nscd/grain_step.h, "Sleeping"): who sleeps at the
// start of a step, the frozen points of sleeping pairs, the sleepers' equilibrium check
// after each solve, the grains that wake within the step, and who falls asleep after it.
#pragma once

#include <vector>

#include "core/geometry/shape_library.h"
#include "core/nscd/grain_step.h"

namespace wiregrain {
namespace grain_step_detail {

// Step 0 (sleeping on): who sleeps in this step, with the state the grains carry
// (quiet time, drift, checked load) and their bounding radii. A sleeping grain wakes now
// if the deck gave it a velocity or a moving wall can reach it within the step (relative
// speed |v_wall|); problem.woken counts those.
void begin_sleeping_step(GrainStepProblem& problem, const std::vector<GrainState>& grains,
                         const ShapeLibrary& library, const std::vector<PlaneWall>& walls,
                         const GrainStepOptions& options);

// The frozen points (sleeping on): last step's points of the pairs that sleep now, kept
// with their impulses, and the walls (for frozen wall points that wake).
void freeze_sleeping_pairs(GrainStepProblem& problem, const std::vector<GrainState>& grains,
                           const std::vector<PlaneWall>& walls, const GrainImpulseMemory& memory);

// The sleepers' equilibrium check after a solve (grain_sleep.cpp). Returns the grains that
// wake; `checks` counts the sleepers solved alone.
std::vector<int> check_sleepers(GrainStepProblem& problem, const std::vector<GrainState>& grains,
                                const GrainStepOptions& options, const NscdStepResult& solved, int& checks);

// Wakes `woken` within the step (with the sleepers resting on them): they join the
// problem with their frozen points (grain_sleep.cpp). Returns the number of grains woken.
int wake_in_step(GrainStepProblem& problem, const std::vector<GrainState>& grains, std::vector<int> woken,
                 const GrainStepOptions& options, const NscdStepResult& solved);

// After the step's last solve: the sleep state of every grain in `result` (grain_sleep.cpp).
void update_sleep(const GrainStepProblem& problem, const std::vector<GrainState>& grains, const SleepOptions& sleep,
                  const NscdStepResult& solved, GrainStepResult& result);

}  // namespace grain_step_detail
}  // namespace wiregrain
