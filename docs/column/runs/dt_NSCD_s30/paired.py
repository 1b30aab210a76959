#!/usr/bin/python3
# fix nscd/polyhedra's step Δt_NSCD = 3e-3 (N = 3 wire sub-steps of 1e-3) against the
# shipped 2e-3 (N = 2) on the reduced column with the paper's proportions (session 30): the
# shipped arm is session 28's runs of the defaults (early_end_s28/summary.csv, ke_relax
# 1e-6), which session 29's build repeated to the last digit (closest_s29/check.csv) and
# session 30's leaves unchanged (bits: the same wall-phase column), the 3e-3 arm this
# session's (summary.csv here)
import csv, os
import numpy as np
HERE = os.path.dirname(os.path.abspath(__file__))
def load(path, value):
    return {int(r['seed']): r for r in csv.DictReader(open(path)) if r['value'] == value}
shipped = load(os.path.join(HERE, '..', 'early_end_s28', 'summary.csv'), '1e-6')
longer = load(os.path.join(HERE, 'summary.csv'), '3e-3')
seeds = sorted(set(shipped) & set(longer))
print(len(seeds), 'seeds:', seeds)
for k in ['H0', 'H_n', 'phi_p', 'U_s/L', 'z_wpc']:
    x = np.array([float(shipped[s][k]) for s in seeds]); y = np.array([float(longer[s][k]) for s in seeds]); d = y - x
    se = d.std(ddof=1) / np.sqrt(len(d)); sem = x.std(ddof=1) / np.sqrt(len(x))
    print(f"  {k:6s} 2e-3 {x.mean():.4g}±{sem:.2g}  3e-3 {y.mean():.4g}±{y.std(ddof=1)/np.sqrt(len(y)):.2g}  "
          f"paired {d.mean():+.4g}±{se:.2g} ({d.mean()/se:+.2f} SE; {d.mean()/sem:+.2f} SE of the shipped mean)")
