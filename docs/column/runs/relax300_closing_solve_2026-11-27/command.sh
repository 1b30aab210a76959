#!/bin/sh
# The paper's relaxation (ke_relax 0) of a Table 1 deposit (its column_deposited.restart,
# t = 140) to t = 300, then 1 time unit of wall motion, with the closing stick solve in
# every phase (the build of commit 18168af); mpirun -np 2 on an otherwise idle machine.
# 2018 s for the 160 000 relaxation steps (12.6 ms per step); log_excerpt.txt.
# Run in the directory of the deposit's restart files.
mpirun -np 2 build/liggghts -in input_scripts/in.column -var root . -var resume 2 \
    -var ke_relax 0 -var relax_closing 0 -var t_end 301 > log.out
