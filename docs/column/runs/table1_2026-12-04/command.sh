#!/bin/sh
# The Table 1 column at in.column's defaults, measured whole: the repository at commit
# 8af8a67, mpirun -np 2 on an otherwise idle 2-core machine (build/bench/nscd_body_sweep 10
# 10 9 --sweeps 1042: 576-585 µs per forward sweep). Wall clock 18:14:00 -> 18:51:35 =
# 2255 s = 0.626 h; the loops' time 0.62 h (breakdown.txt). The deck and its data were read
# from a snapshot of the commit (git archive) in snap/. The same column to the last digit
# as the run of commit 9198562 (2026-11-27).
echo "started $(date)"
mpirun -np 2 ./liggghts -in snap/input_scripts/in.column -var root snap -var t_restart 25 -log log.liggghts > log.out
echo "ended $(date)"
bench/column_table1.py --log log.out > breakdown.txt
postprocess/plot_column.py . -o table1_wall_removal_2026-12-04.png --legend "Table 1 at the defaults, seed 4242"
