#!/bin/sh
# fix nscd/polyhedra's step Δt_NSCD = 3e-3 (in.column's dt_SP 0 keeps the wire's step
# 1e-3: N = 3) on the reduced column with the paper's proportions, seeds 8008-14014, the
# build of commit 08b47ea, two runs at a time. The 2e-3 arm (the default) is the default
# runs of ../early_end_paired_2026-11-27/summary.csv. Run from the repository's top.
S="--seeds 8008 9009 10010 11011 12012 13013 14014"
V="--var mu_w 0.6 --var t_relax 75 --var t_end 145 --var v_wall 0.1 --deck input_scripts/in.column_reduced"
postprocess/sweep.py dt_NSCD 3e-3 $S $V --jobs 2 --out dt3_study
docs/column/runs/dt_NSCD_3e-3_2026-11-27/paired.py
