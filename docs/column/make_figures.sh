#!/bin/sh
# The column figures of docs/results.md from the runs kept in docs/column/runs (final
# observables, column.obs and final VTK of the reduced and the tall column's runs;
# column.obs of the Table 1 run). Run from the repository's top directory:
#   docs/column/make_figures.sh
# To add runs: postprocess/sweep.py ... --out /some/dir, then copy each run's final.json,
# column.obs, command.txt and post/*_final* under docs/column/runs/SWEEP/ and tabulate them:
# postprocess/sweep.py PARAM VALUES --summary-only --out docs/column/runs/SWEEP
set -e
R=docs/column/runs
P=postprocess
/usr/bin/python3 $P/plot_sweep.py $R/mu_w/summary.csv -o docs/column/mu_w.png --label "μ_w" \
    --legend "with wire" --baseline $R/wire/summary.csv --baseline-label "no wire" --table
/usr/bin/python3 $P/plot_column.py "$R/wire/wire=0/seed=1001" "$R/mu_w/mu_w=0.1/seed=1001" \
    "$R/mu_w/mu_w=0.6/seed=1001" -o docs/column/wall_removal.png \
    --legend "no wire" "μ_w = 0.1" "μ_w = 0.6"
/usr/bin/python3 $P/plot_columns.py "$R/wire/wire=0/seed=1001" "$R/mu_w/mu_w=0.1/seed=1001" \
    "$R/mu_w/mu_w=0.6/seed=1001" -o docs/column/final_columns.png \
    --legend "no wire" "μ_w = 0.1" "μ_w = 0.6"
/usr/bin/python3 $P/plot_columns.py "$R/R5/wire=0/seed=1001" "$R/R5/wire=1/seed=1001" \
    -o docs/column/final_columns_R5.png --legend "R = 5, no wire" "R = 5, μ_w = 0.5"
/usr/bin/python3 $P/plot_columns.py "$R/wire/wire=0/seed=1001" "$R/mu_w/mu_w=0.6/seed=1001" \
    "$R/E_w/E_w=1000/seed=1001" "$R/E_w/E_w=10000/seed=1001" -o docs/column/final_columns_E_w.png \
    --legend "no wire" "E_w = 100" "E_w = 1000" "E_w = 10000"
# grain models side by side: NSCD spheropolyhedra against stock Hertz spheres
# and stock superquadrics (blockiness 3), the same deck, seeds, mu_w 0.6
G=$R/grains
/usr/bin/python3 $P/plot_column.py "$G/grains=nscd/seed=1001" "$G/grains=nscd/seed=2002" "$G/grains=nscd/seed=3003" \
    "$G/grains=spheres/seed=1001" "$G/grains=spheres/seed=2002" "$G/grains=spheres/seed=3003" \
    "$G/grains=superquadrics/seed=1001" "$G/grains=superquadrics/seed=2002" "$G/grains=superquadrics/seed=3003" \
    -o docs/column/grain_models.png --legend "NSCD 1001" "NSCD 2002" "NSCD 3003" \
    "spheres 1001" "spheres 2002" "spheres 3003" "superquadrics 1001" "superquadrics 2002" "superquadrics 3003" \
    --colors C0 C0 C0 C1 C1 C1 C2 C2 C2 --no-energy
/usr/bin/python3 $P/plot_columns.py "$G/grains=nscd/seed=1001" "$G/grains=spheres/seed=1001" \
    "$G/grains=superquadrics/seed=1001" \
    -o docs/column/final_columns_grain_models.png --legend "NSCD polyhedra" "stock spheres" "stock superquadrics"
# the tall column from rest to rest (input_scripts/in.column_tall): no wire
# against μ_w = 0.1, 0.3, 0.6 (the μ_w = 0.6 runs are the wire=1 runs of `sweep.py wire 0 1
# --var mu_w 0.6`, relabelled); H_n and the wire energy against time, the final columns
T=$R/tall_rest
/usr/bin/python3 $P/plot_sweep.py $T/mu_w/summary.csv -o docs/column/tall_mu_w.png --label "μ_w" \
    --legend "with wire" --baseline $T/wire/summary.csv --baseline-label "no wire" --table --paired
/usr/bin/python3 $P/plot_column.py "$T/wire/wire=0/seed=1001" "$T/wire/wire=0/seed=2002" "$T/wire/wire=0/seed=3003" \
    "$T/mu_w/mu_w=0.6/seed=1001" "$T/mu_w/mu_w=0.6/seed=2002" "$T/mu_w/mu_w=0.6/seed=3003" \
    -o docs/column/tall_wall_removal.png --legend "no wire 1001" "no wire 2002" "no wire 3003" \
    "μ_w 0.6 1001" "μ_w 0.6 2002" "μ_w 0.6 3003" --colors C0 C0 C0 C1 C1 C1
/usr/bin/python3 $P/plot_columns.py "$T/wire/wire=0/seed=1001" "$T/mu_w/mu_w=0.1/seed=1001" \
    "$T/mu_w/mu_w=0.3/seed=1001" "$T/mu_w/mu_w=0.6/seed=1001" -o docs/column/tall_final_columns.png \
    --legend "no wire" "μ_w = 0.1" "μ_w = 0.3" "μ_w = 0.6"
# the Table 1 column at in.column's defaults (input_scripts/in.column, seed 4242): H_n and
# the wire energy during wall removal
/usr/bin/python3 $P/plot_column.py $R/table1_2026-12-04 -o docs/column/table1_wall_removal_2026-12-04.png \
    --legend "Table 1 at the defaults, seed 4242"
# the reduced column under a plate (docs/results.md, "The column under a plate")
L=$R/column_load_2026-12-05
/usr/bin/python3 $P/load_curve.py $L/wire_s4242_v0.01 $L/wire_s1001_v0.01 $L/wire_s2002_v0.01 \
    $L/no_wire_s4242_v0.01 $L/no_wire_s1001_v0.01 $L/no_wire_s2002_v0.01 --plot docs/column/column_load.png
# the silo at rest and with the floor lowered (input_scripts/in.silo; docs/results.md, "A silo
# to compare with"): floor load over weight against the fill height, Janssen's fits
S=$R/silo_2026-12-06
/usr/bin/python3 $P/janssen.py $S/rest/seed* $S/mobilized/seed* --plot docs/figures/silo_janssen.png > $S/janssen.txt
# the Table 1 column with and without wire: four readings of its height through the wall phase
/usr/bin/python3 $P/column_readings.py $R/table1_readings_2026-12-06/readings.csv \
    --plot docs/column/table1_readings_2026-12-06.png
# the Table 1 column at mu_w 0.1, 0.5 and 0.6 and without wire: four readings of its height
/usr/bin/python3 $P/column_readings.py $R/table1_mu_w_2026-12-07/readings.csv \
    --plot docs/column/table1_mu_w_readings_2026-12-07.png
# the tall column's wire laid as separate loops and as one continuous wire: tension and
# sliding along each layer (docs/results.md, "One continuous wire")
/usr/bin/python3 $P/wire_along.py $R/wire_layouts_tall_2026-12-06/along.csv \
    --plot docs/column/wire_layouts_tall_along_2026-12-06.png
# the paper's Fig. 12 at R = 5 to 9, with and without wire: the final columns, and the
# observables against R
X=$R/R_sweep_2026-12-07
/usr/bin/python3 $P/plot_columns.py "$X/R_nowire/R=5/seed=4242" "$X/R_wire/R=5/seed=4242" \
    "$X/R_nowire/R=6/seed=4242" "$X/R_wire/R=6/seed=4242" \
    "$X/R_nowire/R=7/seed=4242" "$X/R_wire/R=7/seed=4242" "$X/R_nowire/R=8/seed=4242" "$X/R_wire/R=8/seed=4242" \
    "$X/R_nowire/R=9/seed=4242" "$X/R_wire/R=9/seed=4242" \
    -o docs/column/R_sweep_columns_2026-12-07.png \
    --legend "R = 5, no wire" "R = 5, wire" "R = 6, no wire" "R = 6, wire" "R = 7, no wire" "R = 7, wire" \
    "R = 8, no wire" "R = 8, wire" "R = 9, no wire" "R = 9, wire"
/usr/bin/python3 $P/plot_sweep.py "$X/R_wire/summary.csv" "$X/R_nowire/summary.csv" --label R \
    --legend "wire" "no wire" -o docs/column/R_sweep_observables_2026-12-07.png
# the Table 1 grains as an R = 7 column in 10 layers, with the wire (mu_w 0.5 and 0.1) and
# without: four readings of its height, and the final columns
/usr/bin/python3 $P/column_readings.py $R/R7_10layers_2026-12-07/readings.csv \
    --plot docs/column/R7_10layers_readings_2026-12-07.png
Y=$R/R7_10layers_2026-12-07
/usr/bin/python3 $P/plot_columns.py "$Y/nowire" "$Y/wire" -o docs/column/R7_10layers_columns_2026-12-07.png \
    --legend "R = 7, 10 layers, no wire" "R = 7, 10 layers, wire (mu_w 0.5)"
# the tall column under the spring-driven plate, with and without wire (docs/results.md, "The
# column under a plate"); the confinement and network figures need the runs' dumps: their
# command.sh draws them
/usr/bin/python3 $P/load_curve.py $R/column_load_tall_2026-12-07/wire_s* $R/column_load_tall_2026-12-07/no_wire_s* \
    --plot docs/column/column_load_tall_2026-12-07.png
/usr/bin/python3 $R/column_load_tall_2026-12-07/networks.py --plot $R/column_load_tall_2026-12-07/networks.csv \
    docs/column/column_load_tall_confinement_2026-12-07.png   # and its _stress_r.png
