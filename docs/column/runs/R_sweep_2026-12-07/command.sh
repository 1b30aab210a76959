#!/bin/sh
# The paper's Fig. 12 at R = 5 to 9 (docs/results.md, "The loop radius R at the paper's
# layer count"): in.column at its defaults (7 layers, N_p = 915 (R/10)^2: 448, 229, 586, 329
# and 741 grains), seed 4242, with the wire and without it (-var wire 0), the grains' tops
# dumped every 2 time units of the wall phase (-var t_tops 2); one core per run, two side by
# side; R = 7 and 5 with the build and decks of commit dab6008, R = 8, 6 and 9 with those of
# commit 96d69b8, R = 9 with the wire with those of commit 9b3459a (R = 6 with the wire was
# stopped in its wall phase and continued from its relaxed restart: the same command with
# -var resume 1 in its folder). R = 10 is the Table 1 pair of
# table1_readings_2026-12-06. Run from the repository root; kept here per run: column.obs,
# final.json and the final VTK files.
set -e
D=docs/column/runs/R_sweep_2026-12-07
postprocess/sweep.py R 7 5 8 6 9 --seeds 4242 --var t_tops 2 --out sweeps/R_wire
postprocess/sweep.py R 7 5 8 6 9 --seeds 4242 --var t_tops 2 --var wire 0 --out sweeps/R_nowire
# a second seed of R = 7 with and without wire (the build and decks of commit 309c1c9)
postprocess/sweep.py R 7 --seeds 1001 --var t_tops 2 --out sweeps/R_wire
postprocess/sweep.py R 7 --seeds 1001 --var t_tops 2 --var wire 0 --out sweeps/R_nowire
# a second seed of R = 9 with and without wire (the build and decks of commit 4c76a88, with
# restarts; the same commands again continue an interrupted run)
postprocess/sweep.py R 9 --seeds 1001 --var t_tops 2 --var t_restart 25 --var layer_restart 1 --out sweeps/R_wire
postprocess/sweep.py R 9 --seeds 1001 --var t_tops 2 --var t_restart 25 --var layer_restart 1 --var wire 0 \
    --out sweeps/R_nowire
for R in 7 5 8 6; do
  postprocess/column_readings.py sweeps/R_wire/R=$R/seed=4242 sweeps/R_nowire/R=$R/seed=4242 \
      --radius $R --label "wire R=$R" "no wire R=$R" --csv $D/readings_R$R.csv
done
for R in 9; do
  postprocess/column_readings.py sweeps/R_wire/R=$R/seed=4242 sweeps/R_nowire/R=$R/seed=4242 \
      --radius $R --label "wire R=$R" "no wire R=$R" --csv $D/readings_R$R.csv
done
postprocess/wire_hold.py sweeps/R_wire/R=9/seed=4242 --radius 9 --label "wire R=9" --csv $D/hold_R9.csv
postprocess/column_readings.py sweeps/R_wire/R=9/seed=1001 sweeps/R_nowire/R=9/seed=1001 --radius 9 \
    --label "wire R=9 seed=1001" "no wire R=9 seed=1001" --csv $D/readings_R9_seed1001.csv
postprocess/wire_hold.py sweeps/R_wire/R=9/seed=1001 --radius 9 --label "wire R=9 seed=1001" --csv hold_R9_1001.csv
tail -n +2 hold_R9_1001.csv >> $D/hold_R9.csv
for arm in R_wire R_nowire; do
  for run in R=7/seed=4242 R=5/seed=4242 R=8/seed=4242 R=6/seed=4242 R=9/seed=4242 R=7/seed=1001 R=9/seed=1001; do
    s=$arm/$run; [ -f sweeps/$s/final.json ] || continue
    mkdir -p $D/$s/post
    cp sweeps/$s/column.obs sweeps/$s/final.json $D/$s/
    cp sweeps/$s/post/grains_final* $D/$s/post/
    [ $arm = R_nowire ] || cp sweeps/$s/post/wire_final* $D/$s/post/
  done
done
postprocess/sweep.py R 5 6 7 8 9 --seeds 4242 1001 --summary-only --out $D/R_wire
postprocess/sweep.py R 5 6 7 8 9 --seeds 4242 1001 --summary-only --out $D/R_nowire
