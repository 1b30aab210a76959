#!/usr/bin/python3
# fix nscd/polyhedra's step Δt_NSCD = 3e-3 (N = 3 wire sub-steps of 1e-3) against the
# shipped 2e-3 (N = 2) on the reduced column with the paper's proportions (session 30): the
# shipped arm is session 28's runs of the defaults (early_end_s28/summary.csv, ke_relax
# 1e-6), which session 29's build repeated to the last digit (closest_s29/check.csv); the
# 3e-3 arm this session's (summary.csv here)
import os
import sys
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from paired_arms import compare, load
shipped = load(os.path.join(HERE, '..', 'early_end_s28', 'summary.csv'), '1e-6')
longer = load(os.path.join(HERE, 'summary.csv'), '3e-3')
seeds = compare(shipped, longer, '2e-3', '3e-3')
print("wall time per run: 2e-3", [round(float(shipped[s]['wall_s'])) for s in seeds],
      "3e-3", [round(float(longer[s]['wall_s'])) for s in seeds])
