#!/bin/bash
# The tall column under a spring-driven plate (docs/results.md, "The column under a plate"):
# input_scripts/in.column_tall (20 layers of 13 grains, R = 3, mu_w 0.5) of seeds 1001, 2002,
# 3003 and 5005, with the wire (double loops) and without, brought to rest under the still
# plate (ke_settle 1e-6 for t_quiet 2, at most t_settle 40), then loaded by
# input_scripts/in.column_load -var plate spring (k_plate 100 W/a_max, the drive at v_plate
# 0.02, m_plate 0.01 W/g) to strain 0.3 or until the load fell to half its peak (seed 1001
# also to strain 0.3 whatever the drops: tall_full_*); the series
# every 0.1 time units, the contacts, grain stresses and beads every 5 time units (every 1
# without wire).
# Then a silo of the same grains (input_scripts/in.silo, D = 9, 20 layers of 13, mu_wall 0.5,
# the floor at rest) of seeds 1001, 2002 and 3003, for the vertical stress against the axis.
# Run from the repository root; JOBS runs at a time (default 2). Kept here: each run's
# post/load.txt and in.column_load lines (ARM_sSEED/), the force-network summaries, the
# silo's series. The standing columns (column.restart) are built in runs/ when missing.
set -e
ROOT=$(pwd)
D=docs/column/runs/column_load_tall_2026-12-07
W=${WORK:-runs}
JOBS=${JOBS:-2}
one() {  # seed wire [drop name]: the load run stops once F < (1 - drop) x its peak (0.5)
  seed=$1; wire=$2; drop=${3:-0.5}; name=${4:-tall_load}
  arm=$( [ $wire = 1 ] && echo wire || echo no_wire )
  tnet=$( [ $wire = 1 ] && echo 5 || echo 1 )   # the columns without wire fail within a few time units
  col=$W/tall_column_s${seed}_w$wire; mkdir -p $col
  [ -f $col/column.restart ] || (cd $col && $ROOT/build/liggghts -in $ROOT/input_scripts/in.column_tall \
      -var root $ROOT -var wire $wire -var seed $seed > out.txt)
  run=$W/${name}_${arm}_s$seed; mkdir -p $run; cp $col/column.restart $run/
  (cd $run && $ROOT/build/liggghts -in $ROOT/input_scripts/in.column_load -var root $ROOT -var R 3 \
      -var plate spring -var k_plate 100 -var v_plate 0.02 -var m_plate 0.01 \
      -var ke_settle 1e-6 -var t_quiet 2 -var t_settle 40 \
      -var strain_max 0.3 -var drop $drop -var t_out 0.1 -var t_net $tnet > out.txt)
  out=$D/$( [ $name = tall_load ] && echo "" || echo "${name}_" )${arm}_s$seed
  mkdir -p $out/post
  cp $run/post/load.txt $out/post/
  grep -E "^in.column_load" $run/out.txt > $out/out.txt || true
}
silo() {  # seed
  s=$W/tall_silo_s$1; mkdir -p $s
  (cd $s && $ROOT/build/liggghts -in $ROOT/input_scripts/in.silo -var root $ROOT -var seed $1 \
      -var nlayers 20 -var Np 260 -var mu_wall 0.5 -var dump_layers 0 > out.txt)
  mkdir -p $D/silo_s$1; cp $s/post/silo.txt $D/silo_s$1/
  grep "^in.silo" $s/out.txt > $D/silo_s$1/final.txt || true
}
for seed in 1001 2002 3003 5005; do for wire in 1 0; do
  one $seed $wire &
  while [ $(jobs -r | wc -l) -ge $JOBS ]; do sleep 5; done
done; done
# seed 1001 once more to strain 0.3 whatever the drops (drop 0.99: to a hundredth of the peak)
for wire in 1 0; do
  one 1001 $wire 0.99 tall_full &
  while [ $(jobs -r | wc -l) -ge $JOBS ]; do sleep 5; done
done
for seed in 1001 2002 3003; do
  silo $seed &
  while [ $(jobs -r | wc -l) -ge $JOBS ]; do sleep 5; done
done
wait
/usr/bin/python3 postprocess/load_curve.py $W/tall_load_* $W/tall_full_* > $D/summary.txt
/usr/bin/python3 $D/networks.py $W $D/networks > $D/networks.txt
cp $W/networks/networks.csv $D/
cp $W/networks/confinement.png docs/column/column_load_tall_confinement_2026-12-07.png
cp $W/networks/confinement_stress_r.png docs/column/column_load_tall_confinement_2026-12-07_stress_r.png
# the force network of seed 5005 in its most loaded snapshot, with the wire (step 70000) and without (14000)
/usr/bin/python3 postprocess/force_network.py $W/tall_load_wire_s5005 --step 70000 --R 3 --no-plots \
    --out $W/pictures/wire --size 1000 700 --bar-radius 0.25 > /dev/null
/usr/bin/python3 postprocess/force_network.py $W/tall_load_no_wire_s5005 --step 14000 --R 3 --no-plots \
    --out $W/pictures/no_wire --size 1000 700 --bar-radius 0.25 > /dev/null
/usr/bin/python3 - $W/pictures docs/column/column_load_tall_network_2026-12-07.png <<'PY'
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
folder, out = sys.argv[1], sys.argv[2]
fig, axes = plt.subplots(2, 1, figsize=(8, 11))
for ax, (name, step, title) in zip(axes, (("wire", 70000, "with wire, F/W = 0.53"),
                                          ("no_wire", 14000, "without wire, F/W = 0.16 (its peak)"))):
    ax.imshow(plt.imread(f"{folder}/{name}/network_{step}_picture.png")[60:520])
    ax.set_title(f"seed 5005, {title}", fontsize=10)
    ax.axis("off")
fig.tight_layout()
fig.savefig(out, dpi=100)
PY
