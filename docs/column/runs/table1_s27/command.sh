#!/bin/sh
# session 27's Table 1 run at the shipped defaults, measured whole: the repository at
# commit adcfdc1 (in.column: closing stick solve left out in the relaxation only,
# relax_closing 1; ke_relax 0 (the paper's relaxation to t = 300), ke_walls 1e-6,
# overlap_recovery 0; the wire by velocity Verlet, Δt_NSCD 2e-3, Δt_SP 1e-3), mpirun -np 2,
# 6533 s = 1.81 h on a machine 1.7-2.2 times slower than session 25's (README); for about
# 12 of the deposition's 25.5 minutes compiles and single-rank example runs at nice 5 ran
# beside it. Relaxation to t = 300, the wall phase ended early at t = 463.5.
mpirun -np 2 build/liggghts -in input_scripts/in.column -var root . -var t_restart 25 > log.out
bench/column_table1.py --log log.out > breakdown.txt
