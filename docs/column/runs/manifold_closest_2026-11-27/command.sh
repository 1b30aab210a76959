#!/bin/sh
# fix nscd/polyhedra `manifold closest` (the closest features' points only) against the
# default near_vertices on the reduced column with the paper's proportions, seeds
# 8008-14014, the build of commit f25d440, two runs at a time. The near_vertices arm is the
# default runs of ../early_end_paired_2026-11-27/summary.csv (ke_relax 1e-6), which this
# build repeats to the last digit (seed 8008: check.csv). Run from the repository's top.
S="--seeds 8008 9009 10010 11011 12012 13013 14014"
V="--var mu_w 0.6 --var t_relax 75 --var t_end 145 --var v_wall 0.1 --deck input_scripts/in.column_reduced"
postprocess/sweep.py manifold closest $S $V --jobs 2 --out closest_study
postprocess/sweep.py manifold near_vertices --seeds 8008 $V --out closest_check
docs/column/runs/manifold_closest_2026-11-27/paired.py
