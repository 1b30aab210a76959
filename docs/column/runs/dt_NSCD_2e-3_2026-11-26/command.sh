#!/bin/sh
# fix nscd/polyhedra's step Δt_NSCD = 2e-3 (N = 2, the wire's step staying 1e-3) against
# the paper's 1e-3 (N = 1) on the reduced column, seven seeds at both steps, and 2e-3 with
# `manifold closest`; one build (commit ff3aec9 made 2e-3 the default), the wire by Gear-5
# and the overlaps pushed out (the deck's settings then: -var wire_scheme gear5
# -var overlap_recovery 1 today), two runs at a time.
# Run from the repository's top.
S="--seeds 1001 2002 3003 4004 5005 6006 7007"
postprocess/sweep.py dt_NSCD 1e-3 2e-3 $S --var mu_w 0.6 --var wire_scheme gear5 --var overlap_recovery 1 \
    --deck input_scripts/in.column_reduced --out dt --jobs 2
postprocess/sweep.py dt_NSCD 2e-3 $S --var mu_w 0.6 --var wire_scheme gear5 --var overlap_recovery 1 --var manifold closest \
    --deck input_scripts/in.column_reduced --out dt_closest --jobs 2
R=docs/column/runs/dt_NSCD_2e-3_2026-11-26
docs/column/runs/paired_arms.py $R/dt_1e-3.csv 1e-3 $R/dt_2e-3.csv 2e-3
docs/column/runs/paired_arms.py $R/dt_1e-3.csv 1e-3 $R/dt_2e-3_closest.csv 2e-3 --labels 1e-3 "2e-3 closest"
postprocess/plot_sweep.py $R/dt_2e-3.csv $R/dt_2e-3_closest.csv --legend 2e-3 "2e-3, manifold closest" \
    --baseline $R/dt_1e-3.csv --baseline-label "1e-3 (paper)" --paired \
    --work-precision work_precision_dt_nscd.png -o dt_nscd_column.png
