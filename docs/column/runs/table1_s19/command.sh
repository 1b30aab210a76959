#!/bin/sh
# session 19's Table 1 run: the repository at commit 3d6e471 (in.column's defaults, with
# ke_relax 1e-6), mpirun -np 2 on the idle 2-core machine, 5139 s
mpirun -np 2 build/liggghts -in input_scripts/in.column -var root . -var t_restart 25 > log.out
bench/column_table1.py --log log.out > breakdown.txt
postprocess/plot_column.py . -o table1_s19_wall_removal.png --legend "Table 1, seed 4242 (session 19)"
postprocess/plot_columns.py . -o table1_s19_final_column.png --legend "Table 1 at t = 451.5 (walls 6 a_max out)"
