#!/bin/sh
# The Table 1 column at in.column's defaults, measured whole on 2 ranks with the grains'
# solve at its default, solve auto (distributed on 2 ranks): the repository at commit
# a1fb955 (a snapshot made by git archive in snap/, the binary built from it), mpirun -np 2
# on the 2-core machine with two study runs stopped (SIGSTOP) for its duration
# (build/bench/nscd_body_sweep 10 10 9 --sweeps 1042: 730 us per forward sweep that day).
# Wall clock 1984 s = 0.551 h.
echo "started $(date)"
mpirun -np 2 ./liggghts -in snap/input_scripts/in.column -var root snap -var t_restart 25 -log log.liggghts > log.out
echo "ended $(date)"
bench/column_table1.py --log log.out > breakdown.txt
