#!/bin/sh
# warm_geometry (GJK of each cached pair from its last simplex) on the reduced column with
# the paper's proportions, the build of commit a8c11b1. Run from the repository's top.
V="--var mu_w 0.6 --var t_relax 75 --var t_end 145 --var v_wall 0.1 --deck input_scripts/in.column_reduced"
# 1. seeds 8008-14014, warm_geometry yes (summary.csv), two runs at a time, against the
#    default runs of ../early_end_paired_2026-11-27/summary.csv (ke_relax 1e-6); check.csv:
#    warm_geometry no, seed 8008, the default run to the last digit
postprocess/sweep.py warm_geometry yes --seeds 8008 9009 10010 11011 12012 13013 14014 $V --jobs 2 --out warm_study
postprocess/sweep.py warm_geometry no --seeds 8008 $V --jobs 1 --out cold_study
# 2. seeds 15015-21021, three arms side by side (one sweep each, one run at a time):
#    warm_geometry no, yes, and yes with dt_NSCD 3e-3 (new_seeds.csv; not every seed finished)
S="--seeds 15015 16016 17017 18018 19019 20020 21021"
postprocess/sweep.py warm_geometry no $S $V --jobs 1 --out new_no &
postprocess/sweep.py warm_geometry yes $S $V --jobs 1 --out new_yes &
postprocess/sweep.py dt_NSCD 3e-3 $S $V --var warm_geometry yes --jobs 1 --out new_dt3 &
wait
docs/column/runs/warm_geometry_2026-11-28/paired.py
