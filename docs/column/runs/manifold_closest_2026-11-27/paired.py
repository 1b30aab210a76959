#!/usr/bin/python3
# fix nscd/polyhedra `manifold closest` against the default near_vertices on the reduced
# column with the paper's proportions: the near_vertices arm is the default runs of
# ../early_end_paired_2026-11-27/summary.csv (ke_relax 1e-6), the closest arm summary.csv
# here; check.csv: seed 8008 at the default with the closest arm's build.
import os
import sys
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from paired_arms import compare, load
shipped = load(os.path.join(HERE, '..', 'early_end_paired_2026-11-27', 'summary.csv'), '1e-6')
closest = load(os.path.join(HERE, 'summary.csv'), 'closest')
check = os.path.join(HERE, 'check.csv')
if os.path.exists(check):
    for seed, r in load(check, 'near_vertices').items():
        same = all(r[k] == shipped[seed][k] for k in ('H_n', 'phi_p', 'U_s/L', 'z_wpc', 'H0'))
        print(f"seed {seed} at the default, the closest arm's build: H_n {r['H_n']} (default arm: {shipped[seed]['H_n']}): "
              + ("the same to the last digit" if same else "DIFFERENT"))
seeds = compare(shipped, closest, 'near_vertices', 'closest')
print("wall time per run: near_vertices", [round(float(shipped[s]['wall_s'])) for s in seeds],
      "closest", [round(float(closest[s]['wall_s'])) for s in seeds])
