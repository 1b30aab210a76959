#!/bin/sh
# session 25: the closing stick solve on the reduced column, 7 seeds, paired.
# 1. left out in every phase (commit 1c17848's in.column, where subspace_closing applied to
#    all phases): summary_all_phases.csv, subspace_closing 0 (kept everywhere) against 1
postprocess/sweep.py subspace_closing 0 1 --seeds 1001 2002 3003 4004 5005 6006 7007 --var mu_w 0.6 \
    --deck input_scripts/in.column_reduced --out closing_study --jobs 2
# 2. left out in the relaxation only (the shipped default since session 25: relax_closing 1,
#    subspace_closing 0), against the closing_study's subspace_closing 0 arm: summary_relax.csv
postprocess/sweep.py relax_closing 1 --seeds 1001 2002 3003 4004 5005 6006 7007 --var mu_w 0.6 \
    --deck input_scripts/in.column_reduced --out relax_closing_study --jobs 2
