#!/bin/sh
# fix nscd/polyhedra's closing stick solve on the reduced column, 7 seeds, paired; the
# builds of commits 1c17848 (arm 1) and c4c5c53 (arm 2). Run from the repository's top.
# 1. summary_all_phases.csv: kept in every phase (0) against left out in every phase (1),
#    with the in.column of commit 1c17848, whose subspace_closing applied to all phases
#    (today's in.column: -var relax_closing 0, and -var subspace_closing 1)
postprocess/sweep.py subspace_closing 0 1 --seeds 1001 2002 3003 4004 5005 6006 7007 --var mu_w 0.6 \
    --deck input_scripts/in.column_reduced --out closing_study --jobs 2
# 2. summary_relax.csv: left out in the relaxation only (in.column's default: relax_closing 1,
#    subspace_closing 0), against arm 0 of summary_all_phases.csv
postprocess/sweep.py relax_closing 1 --seeds 1001 2002 3003 4004 5005 6006 7007 --var mu_w 0.6 \
    --deck input_scripts/in.column_reduced --out relax_closing_study --jobs 2
# the paired shifts
R=docs/column/runs/closing_solve_2026-11-27
docs/column/runs/paired_arms.py $R/summary_all_phases.csv 0 $R/summary_all_phases.csv 1
docs/column/runs/paired_arms.py $R/summary_all_phases.csv 0 $R/summary_relax.csv 1
