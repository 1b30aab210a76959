#!/usr/bin/python3
# fix nscd/polyhedra `manifold closest` against the shipped near_vertices on the reduced
# column with the paper's proportions (session 29): the shipped arm is session 28's runs of
# the default (early_end_s28/summary.csv, ke_relax 1e-6), the closest arm this session's
# (summary.csv here); check.csv: seed 8008 at the default with this session's build
import csv, os
import numpy as np
HERE = os.path.dirname(os.path.abspath(__file__))
def load(path, value):
    return {int(r['seed']): r for r in csv.DictReader(open(path)) if r['value'] == value}
shipped = load(os.path.join(HERE, '..', 'early_end_s28', 'summary.csv'), '1e-6')
closest = load(os.path.join(HERE, 'summary.csv'), 'closest')
check = os.path.join(HERE, 'check.csv')
if os.path.exists(check):
    for seed, r in load(check, 'near_vertices').items():
        same = all(r[k] == shipped[seed][k] for k in ('H_n', 'phi_p', 'U_s/L', 'z_wpc', 'H0'))
        print(f"seed {seed} at the default, this build: H_n {r['H_n']} (session 28: {shipped[seed]['H_n']}): "
              + ("the same to the last digit" if same else "DIFFERENT"))
seeds = sorted(set(shipped) & set(closest))
print(len(seeds), 'seeds:', seeds)
for k in ['H0', 'H_n', 'phi_p', 'U_s/L', 'z_wpc']:
    x = np.array([float(shipped[s][k]) for s in seeds]); y = np.array([float(closest[s][k]) for s in seeds]); d = y - x
    se = d.std(ddof=1) / np.sqrt(len(d)); sem = x.std(ddof=1) / np.sqrt(len(x))
    print(f"  {k:6s} near_vertices {x.mean():.4g}±{sem:.2g}  closest {y.mean():.4g}±{y.std(ddof=1)/np.sqrt(len(y)):.2g}  "
          f"paired {d.mean():+.4g}±{se:.2g} ({d.mean()/se:+.2f} SE; {d.mean()/sem:+.2f} SE of the shipped mean)")
print("wall time per run: shipped", [round(float(shipped[s]['wall_s'])) for s in seeds],
      "closest", [round(float(closest[s]['wall_s'])) for s in seeds])
