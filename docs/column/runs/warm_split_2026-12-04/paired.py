#!/usr/bin/python3
# warm_geometry's two halves apart on seeds 8008-19019 (command.sh): fix wire/grain's warm
# start alone (segments.csv: warm_segments yes, warm_geometry no) and fix nscd/polyhedra's
# alone (grains.csv: warm_geometry yes, warm_segments no), each against the cold runs of the
# same seeds (../early_end_paired_2026-11-27, ../warm_geometry_2026-11-28), beside both
# warm (../warm_geometry_2026-11-28).
import os
import sys
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from paired_arms import compare, load
RUNS = os.path.dirname(HERE)
first = os.path.join(RUNS, 'warm_geometry_2026-11-28')
cold = {**load(os.path.join(RUNS, 'early_end_paired_2026-11-27', 'summary.csv'), '1e-6'), **load(os.path.join(first, 'new_seeds.csv'), 'no')}
both = {**load(os.path.join(first, 'summary.csv'), 'yes'), **load(os.path.join(first, 'new_seeds.csv'), 'yes')}
arms = [('segments.csv', 'yes', 'warm segments only'), ('grains.csv', 'no', 'warm grains only')]
for name, value, label in arms:
    path = os.path.join(HERE, name)
    if not os.path.exists(path):
        continue
    arm = load(path, value)
    print(f"{label} against cold")
    seeds = compare(cold, arm, 'cold', 'warm')
    up = sum(float(arm[s]['H_n']) > float(cold[s]['H_n']) for s in seeds)
    print(f"   H_n higher than cold in {up} of {len(seeds)} seeds")
    print("   both warm on the same seeds")
    compare(cold, {s: both[s] for s in seeds if s in both}, 'cold', 'both')
