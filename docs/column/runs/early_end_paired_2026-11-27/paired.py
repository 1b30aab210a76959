#!/usr/bin/python3
# The relaxation's early end over 14 seeds of the reduced column with the paper's
# proportions: seeds 1001-7007 (../early_end_2026-11-27: paper.csv ke_relax 0, ke_walls 0;
# shipped.csv ke_relax 1e-6, ke_walls 1e-6) and 8008-14014 (summary.csv here, ke_walls 1e-6
# in both arms).
import csv, numpy as np
def load(p, value=None):
    out = {}
    for r in csv.DictReader(open(p)):
        if value is None or r['value'] == value: out[int(r['seed'])] = r
    return out
import os
HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, '..', 'early_end_2026-11-27') + '/'
paper = load(D + 'paper.csv'); early = load(D + 'shipped.csv')
new = os.path.join(HERE, 'summary.csv')
paper.update(load(new, '0')); early.update(load(new, '1e-6'))
seeds = sorted(set(paper) & set(early))
print(len(seeds), 'seeds:', seeds)
for part, ss in (('seeds 1001-7007', [s for s in seeds if s <= 7007]), ('seeds 8008-14014', [s for s in seeds if s > 7007]), ('all', seeds)):
    if len(ss) < 2: continue
    print(part, len(ss))
    for k in ['H0', 'H_n', 'phi_p', 'U_s/L', 'z_wpc']:
        x = np.array([float(paper[s][k]) for s in ss]); y = np.array([float(early[s][k]) for s in ss]); d = y - x
        se = d.std(ddof=1) / np.sqrt(len(d)); sem = x.std(ddof=1) / np.sqrt(len(x))
        print(f"  {k:6s} paper {x.mean():.4g}±{sem:.2g}  early {y.mean():.4g}±{y.std(ddof=1)/np.sqrt(len(y)):.2g}  "
              f"paired {d.mean():+.4g}±{se:.2g} ({d.mean()/se:+.2f} SE; {d.mean()/sem:+.2f} SE of the paper mean)")
