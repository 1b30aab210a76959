#!/bin/sh
# session 22's Table 1 run at the shipped defaults: the repository at commit da6637a
# (overlap_recovery 0, fix nve/gear check_every 10; otherwise session 21's: the wire by
# velocity Verlet, Δt_NSCD 2e-3, Δt_SP 1e-3, ke_relax and ke_walls 1e-6), mpirun -np 2,
# 2353 s = 0.65 h, its deposition beside a test run (the regression test of
# examples/grain_deposit, 8 min) and a one-core run of that example (5 min), so the
# deposition's 0.27 h is not an idle figure (session 21: 0.17 h); the relaxation and the
# wall phase ran on the idle machine. The relaxation ended at t = 149, the wall phase at t = 333
mpirun -np 2 build/liggghts -in input_scripts/in.column -var root . -var t_restart 25 > log.out
bench/column_table1.py --log log.out > breakdown.txt
postprocess/plot_column.py . -o table1_s22_wall_removal.png --legend "Table 1, seed 4242 (session 22, overlap_recovery 0)"
postprocess/plot_columns.py . -o table1_s22_final_column.png --legend "Table 1 at t = 333 (walls 3.68 a_max out)"
