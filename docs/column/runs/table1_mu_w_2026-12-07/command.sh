#!/bin/sh
# The paper's Fig. 8 on its own column (docs/results.md, "Against the wire friction on the
# Table 1 column"): in.column at its defaults (the Table 1 column, seed 4242) at mu_w = 0.1,
# the tops dumped every 2 time units of the wall phase (-var t_tops 2), one core (the build
# and decks of commit 9b3459a, 104 min beside two other runs); mu_w = 0.5 and the column
# without wire are the pair of table1_readings_2026-12-06 (the build of commit 54600ba).
# mu_w = 0.6, 0.3, 0.2 and 0.4 ran with the build and decks of commit 4c76a88 and restart
# files (-var t_restart 25 -var layer_restart 1; 83, 92, 136 and 125 min of their own wall
# clock on one core beside one to four other runs, continued from their restarts where
# stopped). Run from the repository root; kept here per value: column.obs, final.json, the
# final VTK files, the four readings (readings.csv, with the mu_w = 0.5 and no-wire rows), what
# the wire held (hold.csv), and the final observables (summary.csv as sweep.py --collect
# writes it, with the mu_w = 0.5 row added from table1_readings_2026-12-06/final_wire.txt;
# summary_no_wire.csv from its final_nowire.txt) with their plot.
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
for v in 0.6 0.3 0.2 0.4; do
  s=sweeps/table1_mu_w/mu_w=$v/seed=4242
  postprocess/column_readings.py $s --radius 10 --label "wire mu_w $v" --csv mu_w_${v}_readings.csv
  postprocess/column_readings.py $D/readings.csv mu_w_${v}_readings.csv --csv $D/readings.csv
  postprocess/wire_hold.py $s --radius 10 --label "wire mu_w $v" --csv hold_$v.csv
  tail -n +2 hold_$v.csv >> $D/hold.csv
  mkdir -p $D/mu_w_$v/post
  cp $s/column.obs $s/final.json $D/mu_w_$v/
  cp $s/post/grains_final* $s/post/wire_final* $D/mu_w_$v/post/
done
postprocess/sweep.py mu_w 0.1 0.2 0.3 0.4 0.6 --seeds 4242 --out sweeps/table1_mu_w --collect
# the pair of table1_readings_2026-12-06 as rows of the same form (mu_w = 0.5; no wire)
python3 - "$D" docs/column/runs/table1_readings_2026-12-06 sweeps/table1_mu_w/summary.csv <<'PY'
import csv, re, sys
out, pair, collected = sys.argv[1:]
rows = list(csv.DictReader(open(collected)))
fields = list(rows[0])
def row(line, param, value):
    r = dict.fromkeys(fields, "")
    r.update(param=param, value=value, seed="4242")
    for k in ("H_n", "phi_p", "U_s/L", "z_wpc", "H0", "H", "H_c_n"):
        m = re.search(r"(?<![A-Za-z_])" + re.escape(k) + r" = ([-0-9.e]+)", line)
        r[k] = m.group(1) if m else ""
    return r
rows.append(row(open(pair + "/final_wire.txt").read(), "mu_w", "0.5"))
rows.sort(key=lambda r: float(r["value"]))
for name, table in (("summary.csv", rows), ("summary_no_wire.csv", [row(open(pair + "/final_nowire.txt").read(), "wire", "0")])):
    with open(out + "/" + name, "w", newline="") as f:
        w = csv.DictWriter(f, fields)
        w.writeheader()
        w.writerows(table)
PY
postprocess/plot_sweep.py $D/summary.csv -o docs/column/table1_mu_w_observables_2026-12-07.png --label "μ_w" \
    --legend "Table 1 column, with wire (seed 4242)" --baseline $D/summary_no_wire.csv \
    --baseline-label "no wire (seed 4242)"
