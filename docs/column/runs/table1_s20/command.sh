#!/bin/sh
# session 20's Table 1 run at the shipped defaults: the repository at commit cb54877
# (Δt_NSCD 2e-3, ke_relax 1e-6, ke_walls 1e-6 with the walls free), mpirun -np 2 on the
# idle 2-core machine, 2470 s = 0.69 h; the relaxation ended at t = 188.5, the wall
# phase at t = 370 (walls free from t = 364)
mpirun -np 2 build/liggghts -in input_scripts/in.column -var root . -var t_restart 25 > log.out
bench/column_table1.py --log log.out > breakdown.txt
postprocess/plot_column.py . -o table1_s20_wall_removal.png --legend "Table 1, seed 4242 (session 20)"
postprocess/plot_columns.py . -o table1_s20_final_column.png --legend "Table 1 at t = 370 (walls 3.6 a_max out)"
