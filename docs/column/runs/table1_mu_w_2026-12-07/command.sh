#!/bin/sh
# The paper's Fig. 8 on its own column (docs/results.md, "Against the wire friction on the
# Table 1 column"): in.column at its defaults (the Table 1 column, seed 4242) at mu_w = 0.1,
# the tops dumped every 2 time units of the wall phase (-var t_tops 2), one core (the build
# and decks of commit 9b3459a, 104 min beside two other runs); mu_w = 0.5 and the column
# without wire are the pair of table1_readings_2026-12-06 (the build of commit 54600ba).
# mu_w = 0.6, 0.3, 0.2 and 0.4 were started with the build and decks of commit 4c76a88 and
# restart files (-var t_restart 25 -var layer_restart 1); 0.6, 0.3 and 0.2 finished (83, 92 and
# 136 min of their own wall clock on one core beside two to four other runs); the same commands
# again continue 0.4. Run from the repository root; kept here per finished value: column.obs,
# final.json, the final VTK files, the four readings (readings.csv, with the mu_w = 0.5 and
# no-wire rows) and what the wire held (hold.csv).
set -e
D=docs/column/runs/table1_mu_w_2026-12-07
postprocess/sweep.py mu_w 0.1 --seeds 4242 --var t_tops 2 --var t_restart 25 --out sweeps/table1_mu_w
postprocess/sweep.py mu_w 0.6 0.3 --seeds 4242 --var t_tops 2 --var t_restart 25 --var layer_restart 1 \
    --out sweeps/table1_mu_w
postprocess/sweep.py mu_w 0.2 0.4 --seeds 4242 --var t_tops 2 --var t_restart 25 --var layer_restart 1 \
    --out sweeps/table1_mu_w
s=sweeps/table1_mu_w/mu_w=0.1/seed=4242
postprocess/column_readings.py $s --radius 10 --label "wire mu_w 0.1" --csv mu_w_0.1_readings.csv
postprocess/column_readings.py mu_w_0.1_readings.csv docs/column/runs/table1_readings_2026-12-06/readings.csv \
    --csv $D/readings.csv
postprocess/wire_hold.py $s --radius 10 --label "wire mu_w 0.1" --csv $D/hold.csv
mkdir -p $D/mu_w_0.1/post
cp $s/column.obs $s/final.json $D/mu_w_0.1/
cp $s/post/grains_final* $s/post/wire_final* $D/mu_w_0.1/post/
for v in 0.6 0.3 0.2; do
  s=sweeps/table1_mu_w/mu_w=$v/seed=4242
  postprocess/column_readings.py $s --radius 10 --label "wire mu_w $v" --csv mu_w_${v}_readings.csv
  postprocess/column_readings.py $D/readings.csv mu_w_${v}_readings.csv --csv $D/readings.csv
  postprocess/wire_hold.py $s --radius 10 --label "wire mu_w $v" --csv hold_$v.csv
  tail -n +2 hold_$v.csv >> $D/hold.csv
  mkdir -p $D/mu_w_$v/post
  cp $s/column.obs $s/final.json $D/mu_w_$v/
  cp $s/post/grains_final* $s/post/wire_final* $D/mu_w_$v/post/
done
