#!/bin/sh
# session 25's Table 1 run at the shipped defaults: the repository at commit 3c631ed
# (in.column: subspace_closing 1, ke_relax 0 (the paper's relaxation to t = 300), ke_walls
# 1e-6, overlap_recovery 0; the wire by velocity Verlet, Δt_NSCD 2e-3, Δt_SP 1e-3),
# mpirun -np 2, 0.79 h; for about 10 of its first 20 minutes a compile or a short
# single-rank test ran beside it at nice 10. Relaxation to t = 300, the wall phase ended
# early at t = 463.
mpirun -np 2 build/liggghts -in input_scripts/in.column -var root . -var t_restart 25 > log.out
bench/column_table1.py --log log.out > breakdown.txt
