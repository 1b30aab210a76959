#!/usr/bin/python3
# fix nscd/polyhedra `manifold closest` against the shipped near_vertices on the reduced
# column with the paper's proportions (session 29): the shipped arm is session 28's runs of
# the default (early_end_s28/summary.csv, ke_relax 1e-6), the closest arm this session's
# (summary.csv here); check.csv: seed 8008 at the default with this session's build
import os
import sys
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from paired_arms import compare, load
shipped = load(os.path.join(HERE, '..', 'early_end_s28', 'summary.csv'), '1e-6')
closest = load(os.path.join(HERE, 'summary.csv'), 'closest')
check = os.path.join(HERE, 'check.csv')
if os.path.exists(check):
    for seed, r in load(check, 'near_vertices').items():
        same = all(r[k] == shipped[seed][k] for k in ('H_n', 'phi_p', 'U_s/L', 'z_wpc', 'H0'))
        print(f"seed {seed} at the default, this build: H_n {r['H_n']} (session 28: {shipped[seed]['H_n']}): "
              + ("the same to the last digit" if same else "DIFFERENT"))
seeds = compare(shipped, closest, 'near_vertices', 'closest')
print("wall time per run: shipped", [round(float(shipped[s]['wall_s'])) for s in seeds],
      "closest", [round(float(closest[s]['wall_s'])) for s in seeds])
