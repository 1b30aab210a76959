#!/usr/bin/python3
# warm_geometry (GJK from each cached pair's last simplex) on the reduced column with the
# paper's proportions. 1: seeds 8008-14014, the warm arm (summary.csv) against the default
# runs of ../early_end_paired_2026-11-27/summary.csv (ke_relax 1e-6; the warm arm's build
# repeats them with warm_geometry no to the last digit: check.csv, seed 8008). 2: seeds
# from 15015, the three arms run side by side (new_seeds.csv): no against yes, and
# dt_NSCD 3e-3 (warm) against no, over the seeds each pair of arms finished.
import os
import sys
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from paired_arms import compare, load
shipped = load(os.path.join(HERE, '..', 'early_end_paired_2026-11-27', 'summary.csv'), '1e-6')
warm = load(os.path.join(HERE, 'summary.csv'), 'yes')
print("1. seeds 8008-14014: the default runs (cold) against warm_geometry yes")
seeds = compare(shipped, warm, 'cold', 'warm')
print("   wall time per run: cold", [round(float(shipped[s]['wall_s'])) for s in seeds],
      "warm", [round(float(warm[s]['wall_s'])) for s in seeds])
new = os.path.join(HERE, 'new_seeds.csv')
cold_new, warm_new, dt3_new = load(new, 'no'), load(new, 'yes'), load(new, '3e-3')
print("2. new seeds: warm_geometry no against yes (side by side)")
seeds = compare(cold_new, warm_new, 'cold', 'warm')
print("   wall time per run: cold", [round(float(cold_new[s]['wall_s'])) for s in seeds],
      "warm", [round(float(warm_new[s]['wall_s'])) for s in seeds])
print("   new seeds: warm_geometry no against dt_NSCD 3e-3 with warm_geometry yes")
compare(cold_new, dt3_new, 'cold 2e-3', 'warm 3e-3')
print("3. every seed with both arms: the warm arm against the cold one")
compare({**shipped, **cold_new}, {**warm, **warm_new}, 'cold', 'warm')
