// Stacks of boxes at rest (bench/box_stack.h) over 1000 grain steps with method subspace
// and the grain solver's other defaults (tolerance 1e-4): every interface carries the
// weight of the boxes above it, W_i = Σ_{j ≥ i} m_j g, within 1e-4 on every step (in
// fact to ~1e-12: the closing stick solve makes it exact), without hitting the sweep cap
// (issue 13's bar). The weights are statics, computed apart from the solver. With the
// default method (Gauss–Seidel) the 20-box stack is off by 17 % and every step hits the
// cap (bench/nscd_stack, README).
#include <gtest/gtest.h>

#include <cstdio>

#include "box_stack.h"

using namespace wiregrain;

namespace {

void expect_stack_holds(int n, bool alternate) {
  GrainStepOptions options;
  options.solver.method = SolverMethod::subspace;
  const wiregrain_bench::BoxStackRun r = wiregrain_bench::run_box_stack(n, alternate, 1000, options);
  std::printf("  %d boxes%s: worst load error %.2e, sweeps mean %.2f max %d, stick solves %ld (kept %ld), "
              "largest speed %.1e\n",
              n, alternate ? " (alternating sizes)" : "", r.worst_load_error, double(r.sweeps) / 1000, r.max_sweeps,
              r.subspace_solves, r.subspace_kept, r.largest_speed);
  EXPECT_EQ(r.steps_over_1e4, 0);
  EXPECT_LT(r.worst_load_error, 1e-9);
  EXPECT_EQ(r.capped_steps, 0);
  EXPECT_LT(r.largest_speed, 1e-10);  // at rest: g h = 1e-3 would be one step of free fall
}

}  // namespace

TEST(BoxStack, TwentyBoxesHoldTheirWeightsEveryStep) { expect_stack_holds(20, false); }
TEST(BoxStack, TwentyAlternatingBoxesHoldTheirWeightsEveryStep) { expect_stack_holds(20, true); }
TEST(BoxStack, HundredBoxesHoldTheirWeightsEveryStep) { expect_stack_holds(100, false); }
