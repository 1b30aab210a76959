#!/bin/sh
# The Table 1 column at in.column's defaults (seed 4242) with its wire and without it
# (-var wire 0: the same grain layers), one core each, side by side, the grains' centres and
# tops dumped every 2 time units of the wall phase (-var t_tops 2); the deck and its data
# from a snapshot of commit 54600ba (git archive) in snap/, the binary built from it.
# docs/results.md, "The paper's own column (Table 1)". Run from the repository's top
# directory after ./build.sh build.
set -e
D=docs/column/runs/table1_readings_2026-12-06
mkdir -p runs/wire runs/nowire
(cd runs/wire && ../../build/liggghts -in ../../input_scripts/in.column -var root ../.. \
    -var t_tops 2 -var t_restart 25 > log.out) &
(cd runs/nowire && ../../build/liggghts -in ../../input_scripts/in.column -var root ../.. \
    -var wire 0 -var t_tops 2 -var t_restart 25 > log.out) &
wait
for r in wire nowire; do
  grep "in.column final" runs/$r/log.out > $D/final_$r.txt
  cp runs/$r/column.obs $D/column_$r.obs
done
postprocess/column_readings.py runs/wire runs/nowire --radius 10 --label wire nowire --csv $D/readings.csv
