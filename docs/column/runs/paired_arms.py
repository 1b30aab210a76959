#!/usr/bin/python3
"""Two arms of a reduced-column study, seed by seed: the runs of VALUE_A in one
postprocess/sweep.py summary.csv and those of VALUE_B in another (or the same), each
observable's means (± standard error over the seeds) and the mean of the seed-by-seed
differences B − A in standard errors of that difference and of arm A's mean. The same seed
deposits the same grain layers, so the pairs compare best; a default of in.column is kept
when no observable's paired shift exceeds two standard errors of the difference
(docs/results.md, "How the defaults of in.column were chosen").

    docs/column/runs/paired_arms.py A.csv VALUE_A B.csv VALUE_B [--labels A B]

e.g. docs/column/runs/paired_arms.py docs/column/runs/tolerance_2026-11-27/summary.csv 1e-4 \\
         docs/column/runs/tolerance_2026-11-27/summary.csv 1e-6

The study folders' own paired.py scripts import load() and compare() from here.
Uses Debian's python3-numpy."""
import argparse
import csv

import numpy as np

OBSERVABLES = ["H0", "H_n", "phi_p", "U_s/L", "z_wpc"]


def load(path, value):
    """{seed: row} of the runs of `value` in a summary.csv."""
    with open(path, newline="") as f:
        return {int(r["seed"]): r for r in csv.DictReader(f) if r["value"] == value}


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


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("csv_a")
    parser.add_argument("value_a")
    parser.add_argument("csv_b")
    parser.add_argument("value_b")
    parser.add_argument("--labels", nargs=2, default=None, help="names of the two arms (default: their values)")
    args = parser.parse_args()
    label_a, label_b = args.labels or (args.value_a, args.value_b)
    arm_a, arm_b = load(args.csv_a, args.value_a), load(args.csv_b, args.value_b)
    if not arm_a or not arm_b:
        parser.error(f"no runs of {args.value_a!r} in {args.csv_a} or of {args.value_b!r} in {args.csv_b}")
    seeds = compare(arm_a, arm_b, label_a, label_b)
    higher = sum(float(arm_b[s]["H_n"]) > float(arm_a[s]["H_n"]) for s in seeds)
    print(f"  H_n higher in {label_b} than in {label_a} in {higher} of {len(seeds)} seeds")
    print("  wall time per run:", label_a, [round(float(arm_a[s]["wall_s"])) for s in seeds],
          label_b, [round(float(arm_b[s]["wall_s"])) for s in seeds])


if __name__ == "__main__":
    main()
