#!/bin/sh
# session 18's Table 1 run (the repository at commit 7563502, mpirun -np 2, 6009 s)
mpirun -np 2 build/liggghts -in input_scripts/in.column -var root . \
  -var ke_stop 1e-4 -var t_check 0.5 -var t_quiet 5 > log.out
bench/column_table1.py --log log.out > breakdown.txt
