#!/usr/bin/python3
"""Two arms of a reduced-column study, seed by seed: the runs of `value_a` in one
postprocess/sweep.py summary.csv and those of `value_b` in another (or the same), each
observable's means (± standard error over the seeds) and the mean of the seed-by-seed
differences in standard errors of that difference and of arm A's mean (issue 14's rules).
Used by the runs' own paired.py scripts (closest_s29/, dt_NSCD_s30/)."""
import csv

import numpy as np

OBSERVABLES = ["H0", "H_n", "phi_p", "U_s/L", "z_wpc"]


def load(path, value):
    return {int(r["seed"]): r for r in csv.DictReader(open(path)) if r["value"] == value}


def compare(arm_a, arm_b, label_a, label_b):
    """arm_a, arm_b: {seed: row} (load()); prints the table over their common seeds."""
    seeds = sorted(set(arm_a) & set(arm_b))
    print(len(seeds), "seeds:", seeds)
    for k in OBSERVABLES:
        x = np.array([float(arm_a[s][k]) for s in seeds])
        y = np.array([float(arm_b[s][k]) for s in seeds])
        d = y - x
        se = d.std(ddof=1) / np.sqrt(len(d))
        sem = x.std(ddof=1) / np.sqrt(len(x))
        print(f"  {k:6s} {label_a} {x.mean():.4g}±{sem:.2g}  {label_b} {y.mean():.4g}±{y.std(ddof=1)/np.sqrt(len(y)):.2g}  "
              f"paired {d.mean():+.4g}±{se:.2g} ({d.mean()/se:+.2f} SE; {d.mean()/sem:+.2f} SE of the {label_a} mean)")
    return seeds
