#!/bin/sh
# session 25: session 24's relax300 run again (session 22's Table 1 deposit,
# column_deposited.restart at t = 140, relaxed to t = 300, then 1 time unit of wall motion),
# with the closing stick solve left out (fix nscd/polyhedra subspace_closing 1, in.column's
# default since session 25); mpirun -np 2, the machine idle. 1076 s for the 160 000
# relaxation steps against session 24's 2018 s; log_excerpt.txt. (Run with a study copy of
# in.column that took subspace_closing as -var closing; in.column now has it as
# -var subspace_closing.)
OMPI_MCA_btl_vader_single_copy_mechanism=none mpirun --allow-run-as-root -np 2 build/liggghts \
    -in input_scripts/in.column -var root . -var resume 2 -var t_end 301 > log.out
