#!/bin/sh
# The tall column (input_scripts/in.column_tall: 20 layers of 13 grains, R = 3, mu_w 0.5) with
# the paper's separate double loops and with one continuous wire (docs/results.md, "One
# continuous wire"), seeds 1001, 2002, 3003, 5005, one core per run (14-25 min each), the wire's
# state dumped every 2 time units of the wall phase; the build and decks of commit dab6008.
# Run from the repository root; summary.csv is the sweep's table, along.csv the tension and
# sliding along the wire (postprocess/wire_along.py, 10 bins of u).
postprocess/sweep.py wire_layout loops continuous --deck input_scripts/in.column_tall \
    --seeds 1001 2002 3003 5005 --var t_wire_state 2 --out sweeps/tall_layouts
postprocess/wire_along.py sweeps/tall_layouts/wire_layout=*/seed=* --bins 10 --csv along.csv
