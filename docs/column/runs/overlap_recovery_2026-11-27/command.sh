#!/bin/sh
# fix nscd/polyhedra overlap_recovery 1 (overlaps pushed out at the solver's velocity)
# against 0 (kept from growing, removed by the projection) on the reduced column, at the
# grain step 2e-3 (summary_dt2e-3.csv) and the paper's 1e-3 (summary_dt1e-3.csv), seven
# seeds, one build (commit 34825a1). Run from the repository's top.
S="--seeds 1001 2002 3003 4004 5005 6006 7007"
postprocess/sweep.py overlap_recovery 1 0 $S --var mu_w 0.6 --deck input_scripts/in.column_reduced --out dt2e-3
postprocess/sweep.py overlap_recovery 1 0 $S --var mu_w 0.6 --var dt_NSCD 1e-3 --deck input_scripts/in.column_reduced --out dt1e-3
R=docs/column/runs/overlap_recovery_2026-11-27
docs/column/runs/paired_arms.py $R/summary_dt2e-3.csv 1 $R/summary_dt2e-3.csv 0
docs/column/runs/paired_arms.py $R/summary_dt1e-3.csv 1 $R/summary_dt1e-3.csv 0
