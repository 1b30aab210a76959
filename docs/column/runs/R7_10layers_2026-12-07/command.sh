#!/bin/sh
# The Table 1 grains as a column taller than wide (docs/results.md, "The R = 7 column in 10
# layers"): in.column with R = 7 and the 915 grains of Table 1 in 10 layers (R x layers = 70,
# about Table 1's wire length), seed 4242, -var R 7 -var nlayers 10 -var Np 915 -var margin
# 2.5 -var layer_remainder spread, the tops dumped every 2 time units of the wall phase; with
# the wire (mu_w 0.5, in.column's default), with mu_w 0.1, and without it (-var wire 0); one
# core per run, two or three side by side (the build and decks of commit 309c1c9); the
# mu_w 0.1 run was stopped in its wall phase at t = 317 (its column.obs and readings up to
# there are kept, it has no final line or final VTK). Run from the repository root; kept
# here per run: column.obs, final.json and the final VTK files, and the four readings of
# each run in readings.csv.
set -e
D=docs/column/runs/R7_10layers_2026-12-07
V="--var nlayers 10 --var Np 915 --var margin 2.5 --var layer_remainder spread --var t_tops 2 --var t_restart 25"
postprocess/sweep.py R 7 --seeds 4242 $V --out sweeps/R7_10layers_wire
postprocess/sweep.py R 7 --seeds 4242 $V --var wire 0 --out sweeps/R7_10layers_nowire
postprocess/sweep.py mu_w 0.1 --seeds 4242 --var R 7 $V --out sweeps/R7_10layers_mu_w
postprocess/column_readings.py sweeps/R7_10layers_wire/R=7/seed=4242 sweeps/R7_10layers_mu_w/mu_w=0.1/seed=4242 \
    sweeps/R7_10layers_nowire/R=7/seed=4242 --radius 7 --label "wire" "wire mu_w 0.1" "no wire" \
    --csv $D/readings.csv
# what the wire holds: the grains inside and outside R = 7 (docs/results.md)
postprocess/wire_hold.py sweeps/R7_10layers_wire/R=7/seed=4242 sweeps/R7_10layers_nowire/R=7/seed=4242 \
    --radius 7 --label "wire" "no wire" --csv $D/hold.csv
for arm in wire:R7_10layers_wire/R=7 mu_w_0.1:R7_10layers_mu_w/mu_w=0.1 nowire:R7_10layers_nowire/R=7; do
  name=${arm%%:*}; s=sweeps/${arm#*:}/seed=4242
  mkdir -p $D/$name
  cp $s/column.obs $D/$name/
  [ -f $s/final.json ] || continue
  mkdir -p $D/$name/post
  cp $s/final.json $D/$name/
  cp $s/post/grains_final* $D/$name/post/
  [ $name = nowire ] || cp $s/post/wire_final* $D/$name/post/
done
