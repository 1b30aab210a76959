#!/bin/sh
# session 29: fix nscd/polyhedra `manifold closest` on the reduced column with the paper's
# proportions, seeds 8008-14014, this session's build (f25d440), two runs at a time; the
# shipped arm is session 28's runs of the defaults (../early_end_s28/summary.csv,
# ke_relax 1e-6), which this build repeats to the last digit (seed 8008: check.csv)
S="--seeds 8008 9009 10010 11011 12012 13013 14014"
V="--var mu_w 0.6 --var t_relax 75 --var t_end 145 --var v_wall 0.1 --deck input_scripts/in.column_reduced"
postprocess/sweep.py manifold closest $S $V --jobs 2 --out closest_study
postprocess/sweep.py manifold near_vertices --seeds 8008 $V --out closest_check
docs/column/runs/closest_s29/paired.py
