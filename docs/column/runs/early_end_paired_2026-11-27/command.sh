#!/bin/sh
# The relaxation's early end over 7 more seeds of the reduced column with the paper's
# proportions (seeds 1001-7007: ../early_end_2026-11-27/), both arms with the build of
# commit 832e6ee, the walls' early end on in both (ke_walls 1e-6, which
# ../early_end_2026-11-27 shows changes nothing); paired.py joins the 14 seeds. The
# ke_relax 1e-6 arm here (in.column's defaults) is the default arm of the later studies
# (manifold_closest, dt_NSCD_3e-3, warm_geometry, warm_split). Run from the repository's top.
S="--seeds 8008 9009 10010 11011 12012 13013 14014"
V="--var mu_w 0.6 --var t_relax 75 --var t_end 145 --var v_wall 0.1 --deck input_scripts/in.column_reduced --jobs 2"
postprocess/sweep.py ke_relax 0 1e-6 $S $V --out ke_study
docs/column/runs/early_end_paired_2026-11-27/paired.py
