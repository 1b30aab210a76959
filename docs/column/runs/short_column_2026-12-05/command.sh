#!/bin/sh
# A short column that sees the wire (docs/results.md, "A short column that sees the wire";
# the deck of tests/regression/test_column.py, WireKeepsTheColumnUp): the same seed with and
# without the wire, seeds 1001-10010, one core per run, two runs at a time. summary.csv is
# the deck of the test (10 layers of 5 grains, mu_p 0.1, mu_w 1, E_w 1000);
# nine_layers.csv the same with 9 layers (t_relax 34.5, t_end 44.5); mu_p_0.2.csv with
# mu_p 0.2, mu_w 0.8, seeds 1001-5005. Run from the repository root.
V="--var R 2 --var t_layer 2.5 --var t_wire 1 --var E_w 1000 --var dt_SP 1e-3 --var box_half 12"
V="$V --var v_wall 1 --var ke_relax 0 --var ke_walls 0 --var t_obs 1 --var timing 0 --jobs 2"
S="1001 2002 3003 4004 5005 6006 7007 8008 9009 10010"
postprocess/sweep.py wire 0 1 --seeds $S $V --var nlayers 10 --var Np 50 --var mu_w 1.0 --var mu_p 0.1 \
    --var t_relax 38 --var t_end 48 --out sweeps/short_column
postprocess/sweep.py wire 0 1 --seeds $S $V --var nlayers 9 --var Np 45 --var mu_w 1.0 --var mu_p 0.1 \
    --var t_relax 34.5 --var t_end 44.5 --out sweeps/short_column_nine_layers
postprocess/sweep.py wire 0 1 --seeds 1001 2002 3003 4004 5005 $V --var nlayers 10 --var Np 50 --var mu_w 0.8 \
    --var mu_p 0.2 --var t_relax 38 --var t_end 48 --out sweeps/short_column_mu_p_0.2
D=docs/column/runs/short_column_2026-12-05
for f in summary nine_layers mu_p_0.2; do
  echo "== $f.csv"; docs/column/runs/paired_arms.py $D/$f.csv 0 $D/$f.csv 1 --labels "no wire" wire 2>/dev/null
done > $D/paired.txt
