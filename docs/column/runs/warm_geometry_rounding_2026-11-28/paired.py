#!/usr/bin/python3
# warm_geometry on new seeds and two rounding-only controls. 1: seeds 20020-25025,
# warm_geometry no and yes run side by side (new_seeds.csv; seed 20020's warm run is in
# ../warm_geometry_2026-11-28/new_seeds.csv). 2: every seed with both arms. 3: a
# rounding-only control: a -march=native build (the same code, FMA's last bits) against the
# portable build's default runs of the same seeds (control.csv). 4: the cold build with a
# rounding-size noise that changes from call to call (jitter.csv).
import os
import sys
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from paired_arms import compare, load
RUNS = os.path.dirname(HERE)
shipped = load(os.path.join(RUNS, 'early_end_paired_2026-11-27', 'summary.csv'), '1e-6')
first = os.path.join(RUNS, 'warm_geometry_2026-11-28')
warm1, cold1, warm1_new = (load(os.path.join(first, 'summary.csv'), 'yes'), load(os.path.join(first, 'new_seeds.csv'), 'no'),
                           load(os.path.join(first, 'new_seeds.csv'), 'yes'))
new = os.path.join(HERE, 'new_seeds.csv')
cold2, warm2 = load(new, 'no'), load(new, 'yes')
print("1. seeds 20020-25025 (new): warm_geometry no against yes")
compare(cold2, {**warm1_new, **warm2}, 'cold', 'warm')
print("2. every seed with both arms")
cold_all, warm_all = {**shipped, **cold1, **cold2}, {**warm1, **warm1_new, **warm2}
seeds = compare(cold_all, warm_all, 'cold', 'warm')
up = sum(float(warm_all[s]['H_n']) > float(cold_all[s]['H_n']) for s in seeds)
print(f"   H_n higher warm than cold in {up} of {len(seeds)} seeds")
control = os.path.join(HERE, 'control.csv')
if os.path.exists(control):
    print("3. rounding-only control: the portable build's default runs against -march=native")
    compare(shipped, load(control, '1e-6'), 'portable', 'native')
jitter = os.path.join(HERE, 'jitter.csv')
if os.path.exists(jitter):
    print("4. the cold build with a rounding-size noise that changes from call to call (jitter.patch,")
    print("   WG_JITTER=3e-17) against the cold runs of the same seeds")
    noisy = load(jitter, 'no')
    seeds = compare(cold_all, noisy, 'cold', 'jitter')
    up = sum(float(noisy[s]['H_n']) > float(cold_all[s]['H_n']) for s in seeds)
    print(f"   H_n higher with the noise in {up} of {len(seeds)} seeds")
    print("   the warm start on the same seeds")
    compare(cold_all, {s: warm_all[s] for s in seeds}, 'cold', 'warm')
