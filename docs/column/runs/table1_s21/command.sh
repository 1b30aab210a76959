#!/bin/sh
# session 21's Table 1 run at the shipped defaults: the repository at commit 6942cbe
# (the wire integrated by velocity Verlet, wire_scheme auto; Δt_NSCD 2e-3, Δt_SP 1e-3,
# ke_relax and ke_walls 1e-6), mpirun -np 2 on the idle 2-core machine, 2350 s = 0.65 h;
# the relaxation ended at t = 149, the wall phase at t = 341.5
mpirun -np 2 build/liggghts -in input_scripts/in.column -var root . -var t_restart 25 > log.out
bench/column_table1.py --log log.out > breakdown.txt
postprocess/plot_column.py . -o table1_s21_wall_removal.png --legend "Table 1, seed 4242 (session 21, wire by Verlet)"
postprocess/plot_columns.py . -o table1_s21_final_column.png --legend "Table 1 at t = 341.5 (walls 3.85 a_max out)"
