#!/bin/sh
# fix nscd/polyhedra tolerance 1e-4 (the default), 1e-6 and 1e-8 on the reduced column,
# seven seeds, one build (commit bd5ebeb). Run from the repository's top.
postprocess/sweep.py nscd_tolerance 1e-4 1e-6 1e-8 --seeds 1001 2002 3003 4004 5005 6006 7007 \
    --var mu_w 0.6 --deck input_scripts/in.column_reduced
R=docs/column/runs/tolerance_2026-11-27
docs/column/runs/paired_arms.py $R/summary.csv 1e-4 $R/summary.csv 1e-6
docs/column/runs/paired_arms.py $R/summary.csv 1e-4 $R/summary.csv 1e-8
