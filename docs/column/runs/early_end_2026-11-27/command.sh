#!/bin/sh
# The two early ends of in.column over 7 seeds of the reduced column with the paper's
# proportions (40 time units of relaxation, the walls moving 7 a_max in 70), the build of
# commit 37c9c32. Run from the repository's top.
S="--seeds 1001 2002 3003 4004 5005 6006 7007"
V="--var mu_w 0.6 --var t_relax 75 --var t_end 145 --var v_wall 0.1 --deck input_scripts/in.column_reduced"
postprocess/sweep.py ke_relax 0 --var ke_walls 0 $S $V --out early/paper      # paper.csv (the paper's procedure)
postprocess/sweep.py ke_relax 1e-6 $S $V --out early/shipped                  # shipped.csv (both early ends)
postprocess/sweep.py ke_walls 1e-30 --var ke_relax 1e-6 $S $V --out early/walls_full   # walls_full.csv
# walls_full_vs_shipped.txt: each seed's run with both early ends against the same run
# whose wall phase never ends early (column.obs identical up to the early end: True)
