#!/bin/sh
# The reduced column with and without a rolling resistance (fix nscd/polyhedra
# rolling_friction, in.column -var rolling_friction), mu_w 0.6, seeds 1001-7007, two runs
# at a time, the build of commit b774b66. Run from the repository's top.
postprocess/sweep.py rolling_friction 0 0.1 --seeds 1001 2002 3003 4004 5005 6006 7007 \
    --var mu_w 0.6 --deck input_scripts/in.column_reduced --out out --jobs 2
R=docs/column/runs/rolling_friction_2026-11-27
docs/column/runs/paired_arms.py $R/summary.csv 0 $R/summary.csv 0.1
