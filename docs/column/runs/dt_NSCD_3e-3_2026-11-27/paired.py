#!/usr/bin/python3
# fix nscd/polyhedra's step Δt_NSCD = 3e-3 (N = 3 wire sub-steps of 1e-3) against the
# default 2e-3 (N = 2) on the reduced column with the paper's proportions: the 2e-3 arm is
# the default runs of ../early_end_paired_2026-11-27/summary.csv (ke_relax 1e-6), the 3e-3
# arm summary.csv here.
import os
import sys
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from paired_arms import compare, load
shipped = load(os.path.join(HERE, '..', 'early_end_paired_2026-11-27', 'summary.csv'), '1e-6')
longer = load(os.path.join(HERE, 'summary.csv'), '3e-3')
seeds = compare(shipped, longer, '2e-3', '3e-3')
print("wall time per run: 2e-3", [round(float(shipped[s]['wall_s'])) for s in seeds],
      "3e-3", [round(float(longer[s]['wall_s'])) for s in seeds])
