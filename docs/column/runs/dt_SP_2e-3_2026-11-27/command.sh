#!/bin/sh
# The wire's step at N = 1 (dt_SP = dt_NSCD = 2e-3, velocity Verlet) against the default
# N = 2 (dt_SP 1e-3) on the reduced column, 7 seeds, paired; summary.csv: the N = 1 arm
# (the build of commit 832e6ee). The N = 2 arm is the relax_closing 1 arm of
# ../closing_solve_2026-11-27/summary_relax.csv (in.column's defaults), whose seeds
# 1001-4004 the N = 1 arm's build repeated to the last digit. Run from the repository's top.
postprocess/sweep.py dt_SP 2e-3 --seeds 1001 2002 3003 4004 5005 6006 7007 --var mu_w 0.6 \
    --deck input_scripts/in.column_reduced --out dt_SP_study --jobs 2
docs/column/runs/paired_arms.py docs/column/runs/closing_solve_2026-11-27/summary_relax.csv 1 \
    docs/column/runs/dt_SP_2e-3_2026-11-27/summary.csv 2e-3 --labels "N = 2" "N = 1"
