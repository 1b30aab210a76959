#!/bin/sh
# The Table 1 column with the paper's relaxation to t = 300 (ke_relax 0), otherwise at
# in.column's defaults: the repository at commit adcfdc1, mpirun -np 2, 6533 s = 1.81 h on
# a machine about 2 times slower than that of ../table1_2026-12-04 (for about 12 of the
# deposition's 25.5 minutes compiles ran beside it). The same deposit as ../table1_2026-12-04
# (H0 6.34064 against 6.34069): the relaxation's early end against the paper's relaxation.
mpirun -np 2 build/liggghts -in input_scripts/in.column -var root . -var ke_relax 0 -var t_restart 25 > log.out
bench/column_table1.py --log log.out > breakdown.txt
