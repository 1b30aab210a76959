#!/bin/sh
# session 29's Table 1 run at the shipped defaults, measured whole: the repository at
# commit 9198562 (in.column: ke_relax 1e-6, the relaxation's early end, the default again
# since session 28; relax_closing 1, ke_walls 1e-6, overlap_recovery 0; the wire by velocity
# Verlet, Δt_NSCD 2e-3, Δt_SP 1e-3), mpirun -np 2, 4320 s = 1.20 h of the loops' time on a
# machine 1.6-1.8 times slower than session 25's (nscd_body_sweep 10 10 9 --sweeps 1042:
# 909-971 µs per forward sweep, against ~550). Beside it: a one-rank column run at nice 19
# (2-6 % of a core while the MPI ranks spun), from 18:35 to 18:56 a compile at nice 0 (one
# process) and about 3 minutes of short single-rank test runs. The relaxation ended at
# t = 151, the wall phase early at t = 327 (the walls carried grains until t ≈ 320).
echo "started $(date)"
mpirun -np 2 build/liggghts -in input_scripts/in.column -var root . -var t_restart 25 -log log.liggghts > log.out
echo "ended $(date)"
bench/column_table1.py --log log.out > breakdown.txt
