#!/bin/sh
# The wire's sub-step Δt_SP at Δt_NSCD = 1e-3: N = 10 (Table 1's 1e-4), N = 2 (5e-4) and
# N = 1 (1e-3) on the reduced column, seven seeds each, one build (commit 6d862f9), the
# wire by Gear-5 and the overlaps pushed out (the deck's settings then), one run at a time
# on one core.
# Run from the repository's top.
postprocess/sweep.py dt_SP 1e-3 1e-4 5e-4 --seeds 1001 2002 3003 4004 5005 6006 7007 \
    --var mu_w 0.6 --var dt_NSCD 1e-3 --var wire_scheme gear5 --var overlap_recovery 1 --deck input_scripts/in.column_reduced
R=docs/column/runs/dt_SP_2026-11-25
docs/column/runs/paired_arms.py $R/summary.csv 1e-4 $R/summary.csv 1e-3
docs/column/runs/paired_arms.py $R/summary.csv 1e-4 $R/summary.csv 5e-4
