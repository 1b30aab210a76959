#!/bin/sh
# session 19: the Table 1 column's relaxation as the paper does it (to t = 300, ke_relax 0),
# continued from the deposit of /work/studies/s19/table1 (resume 2, t = 140); stopped by
# hand once the deck prints "relaxed at" (the walls phase is not needed)
cd /work/studies/s19/relax300
export OMPI_MCA_btl_vader_single_copy_mechanism=none
date +%s > start
mpirun --allow-run-as-root -np 2 /work/studies/s19/table1/liggghts -in /work/studies/s19/table1/repo/input_scripts/in.column \
  -var root /work/studies/s19/table1/repo -var resume 2 -var ke_relax 0 -var ke_stop 1e-30 -var t_check 2 -var t_quiet 5 > log.out 2> log.err
date +%s > end
