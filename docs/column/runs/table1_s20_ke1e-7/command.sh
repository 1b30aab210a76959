#!/bin/sh
# session 20's first Table 1 run: the repository at commit 0c0f30c (Δt_NSCD 2e-3, the
# wall phase's early end by the kinetic energy alone, ke_walls 1e-7), mpirun -np 2 on the
# 2-core machine (a few minutes of tests niced beside it), 2484 s; ended at t = 348.5
mpirun -np 2 build/liggghts -in input_scripts/in.column -var root . -var t_restart 25 > log.out
bench/column_table1.py --log log.out > breakdown.txt
