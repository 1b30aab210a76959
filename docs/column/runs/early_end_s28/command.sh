#!/bin/sh
# session 28: the relaxation's early end over 7 more seeds of the reduced column with the paper's
# proportions (session 24 ran 1001-7007: ../early_end_s24/), both arms with this session's build
# (commit 832e6ee), the walls' early end on in both (ke_walls 1e-6, which session 24 showed
# changes nothing); paired.py joins the 14 seeds (session 24's paper.csv / shipped.csv and
# summary.csv here) and prints the paired shifts
S="--seeds 8008 9009 10010 11011 12012 13013 14014"
V="--var mu_w 0.6 --var t_relax 75 --var t_end 145 --var v_wall 0.1 --deck input_scripts/in.column_reduced --jobs 2"
postprocess/sweep.py ke_relax 0 1e-6 $S $V --out ke_study
