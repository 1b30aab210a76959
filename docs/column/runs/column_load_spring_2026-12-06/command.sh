#!/bin/bash
# The reduced column under a spring-driven plate (docs/results.md, "The column under a
# plate"): the reduced column (input_scripts/in.column_reduced) of seeds 4242, 1001, 2002,
# 3003 and 5005, with and without wire, brought to rest under the still plate (ke_settle
# 1e-6 for t_quiet 2, at most t_settle 40), then loaded by input_scripts/in.column_load
# -var plate spring (k_plate 100 W/a_max, the drive at v_plate 0.01, m_plate 0.01 W/g) to
# strain 0.1 or until the load dropped to half its peak, the series every 0.1 time units.
# Run from the repository root; JOBS runs at a time (default 2). Each run's post/load.txt and
# out.txt are kept here as ARM_sSEED/.
set -e
ROOT=$(pwd)
D=docs/column/runs/column_load_spring_2026-12-06
JOBS=${JOBS:-2}
one() {  # seed wire
  seed=$1; wire=$2
  arm=$( [ $wire = 1 ] && echo wire || echo no_wire )
  col=runs/column_s${seed}_w$wire; mkdir -p $col
  [ -f $col/column.restart ] || (cd $col && $ROOT/build/liggghts -in $ROOT/input_scripts/in.column_reduced \
      -var root $ROOT -var wire $wire -var seed $seed > out.txt)
  run=runs/spring_${arm}_s$seed; mkdir -p $run; cp $col/column.restart $run/
  (cd $run && $ROOT/build/liggghts -in $ROOT/input_scripts/in.column_load -var root $ROOT -var R 3 \
      -var plate spring -var k_plate 100 -var v_plate 0.01 -var m_plate 0.01 \
      -var ke_settle 1e-6 -var t_quiet 2 -var t_settle 40 \
      -var strain_max 0.1 -var t_out 0.1 > out.txt)
  mkdir -p $D/${arm}_s$seed/post
  cp $run/post/load.txt $D/${arm}_s$seed/post/
  grep -E "^in.column_load" $run/out.txt > $D/${arm}_s$seed/out.txt || true
}
for seed in 4242 1001 2002 3003 5005; do for wire in 1 0; do
  one $seed $wire &
  while [ $(jobs -r | wc -l) -ge $JOBS ]; do sleep 5; done
done; done
wait
/usr/bin/python3 postprocess/load_curve.py runs/spring_* > $D/summary.txt
