#!/bin/sh
# session 24: the paper's relaxation (ke_relax 0, the new default) of session 22's Table 1
# deposit (its column_deposited.restart, t = 140) to t = 300 with this session's code
# (commit 18168af's build), then 1 time unit of wall motion; mpirun -np 2, the machine idle.
# 2018 s for the 160 000 relaxation steps (12.6 ms per step); log_excerpt.txt
OMPI_MCA_btl_vader_single_copy_mechanism=none mpirun --allow-run-as-root -np 2 build/liggghts \
    -in input_scripts/in.column -var root . -var resume 2 -var t_end 301 > log.out
