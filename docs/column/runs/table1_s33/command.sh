#!/bin/sh
# session 33's Table 1 run at the shipped defaults, measured whole: the repository at
# commit 8af8a67 (the code of session 29's run, 9198562, plus exact changes only: session
# 29's run repeated to the last digit), mpirun -np 2 on an otherwise idle machine
# (nscd_body_sweep 10 10 9 --sweeps 1042: 576-585 µs per forward sweep, against 909-971 in
# session 29 and ~550 in session 25). Wall clock 18:14:00 -> 18:51:35 = 2255 s = 0.626 h;
# the loops' time 0.62 h (breakdown.txt). The deck and its data were read from a snapshot
# of the commit (git archive), so that edits of the working tree could not reach the run.
echo "started $(date)"
mpirun -np 2 ./liggghts -in snap/input_scripts/in.column -var root snap -var t_restart 25 -log log.liggghts > log.out
echo "ended $(date)"
bench/column_table1.py --log log.out > breakdown.txt
