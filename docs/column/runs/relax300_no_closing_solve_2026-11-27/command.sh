#!/bin/sh
# The same relaxation as ../relax300_closing_solve_2026-11-27 (the same Table 1 deposit,
# t = 140 to 300, then 1 time unit of wall motion) with the closing stick solve left out
# in the relaxation (fix nscd/polyhedra subspace_closing 1; in.column's relax_closing 1,
# its default); the build of commit 3c631ed, mpirun -np 2 on an otherwise idle machine.
# 1076 s for the 160 000 relaxation steps; log_excerpt.txt. Run in the directory of the
# deposit's restart files.
mpirun -np 2 build/liggghts -in input_scripts/in.column -var root . -var resume 2 \
    -var ke_relax 0 -var relax_closing 1 -var t_end 301 > log.out
