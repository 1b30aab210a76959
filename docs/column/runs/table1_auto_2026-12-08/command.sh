#!/bin/sh
# The Table 1 column at in.column's defaults, measured whole on 2 ranks (solve auto:
# distributed): the repository at commit 08dedcd (a snapshot made by git archive in snap/,
# the binary built from it), mpirun -np 2 on the 2-core machine with two study runs stopped
# (SIGSTOP) for its duration (build/bench/nscd_body_sweep 10 10 9 --sweeps 1042: 731 us per
# forward sweep just before, 730 just after). Wall clock 1815 s = 0.504 h; the same final
# line, to the last digit, as table1_auto_2026-12-07 (commit a1fb955, 1984 s).
echo "started $(date)"
mpirun -np 2 ./liggghts -in snap/input_scripts/in.column -var root snap -var t_restart 25 -log log.liggghts > log.out
echo "ended $(date)"
bench/column_table1.py --log log.out > breakdown.txt
