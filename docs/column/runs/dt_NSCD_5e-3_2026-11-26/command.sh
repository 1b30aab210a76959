#!/bin/sh
# fix nscd/polyhedra's step Δt_NSCD at 1e-3 (N = 1), 2e-3 and 5e-3 on the reduced column,
# the wire's step staying 1e-3 (dt_SP 0 takes N = 2 and 5), one run at a time, the build
# of commit 1dbeb45; the wire by Gear-5 and the overlaps pushed out (the deck's settings
# then: -var wire_scheme gear5 -var overlap_recovery 1 today). Three of the seven 2e-3 runs
# stopped on a segment beyond the contact search's reach (fixed since), so dt_2e-3.csv has
# four seeds; ../dt_NSCD_2e-3_2026-11-26 repeats 2e-3 on all seven.
# Run from the repository's top.
postprocess/sweep.py dt_NSCD 1e-3 2e-3 5e-3 --seeds 1001 2002 3003 4004 5005 6006 7007 \
    --var mu_w 0.6 --var wire_scheme gear5 --var overlap_recovery 1 --deck input_scripts/in.column_reduced --out sweeps/dt_NSCD
R=docs/column/runs/dt_NSCD_5e-3_2026-11-26
docs/column/runs/paired_arms.py $R/dt_1e-3.csv 1e-3 $R/dt_5e-3.csv 5e-3
