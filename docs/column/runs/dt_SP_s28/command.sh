#!/bin/sh
# session 28: the wire's step at N = 1 (dt_SP = dt_NSCD = 2e-3, velocity Verlet) against the
# shipped N = 2 (dt_SP 1e-3) on the reduced column, 7 seeds, paired. The N = 2 arm is session
# 25's relax_closing run (docs/column/runs/closing_s25/summary_relax.csv, the shipped defaults
# since): this session's build repeated its seeds 1001-4004 to the last digit, then the arm was
# stopped. summary.csv: the N = 1 arm (commit 832e6ee's build).
postprocess/sweep.py dt_SP 2e-3 --seeds 1001 2002 3003 4004 5005 6006 7007 --var mu_w 0.6 \
    --deck input_scripts/in.column_reduced --out dt_SP_study --jobs 2
postprocess/plot_sweep.py dt_SP_study/summary.csv --baseline docs/column/runs/closing_s25/summary_relax.csv \
    --baseline-label "dt_SP 1e-3 (N = 2)" --paired -o dt_sp_n1.png
