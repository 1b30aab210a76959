#!/bin/sh
# The reduced column under a plate (docs/results.md, "The column under a plate"): the
# reduced column (input_scripts/in.column_reduced) of seeds 4242, 1001 and 2002, with and
# without wire, loaded by input_scripts/in.column_load at v_plate 0.02 and 0.01 to strain
# 0.1 (or until the load dropped to half its peak), the series every 0.1 time units.
# Run from the repository root; one core per run. Each run's post/load.txt is kept here as
# ARM_sSEED_vV/post/load.txt.
set -e
ROOT=$(pwd)
D=docs/column/runs/column_load_2026-12-05
for seed in 4242 1001 2002; do for wire in 1 0; do
  arm=$( [ $wire = 1 ] && echo wire || echo no_wire )
  col=runs/column_s${seed}_w$wire; mkdir -p $col
  (cd $col && $ROOT/build/liggghts -in $ROOT/input_scripts/in.column_reduced -var root $ROOT \
      -var wire $wire -var seed $seed > out.txt)
  for v in 0.02 0.01; do
    run=runs/${arm}_s${seed}_v$v; mkdir -p $run; cp $col/column.restart $run/
    (cd $run && $ROOT/build/liggghts -in $ROOT/input_scripts/in.column_load -var root $ROOT -var R 3 \
        -var v_plate $v -var strain_max 0.1 -var t_out 0.1 > out.txt)
  done
done; done
postprocess/load_curve.py runs/*_v0.0[12] > $D/summary.txt
