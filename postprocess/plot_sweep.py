#!/usr/bin/python3
"""Plot the column's final observables against the swept parameter, mean ± standard
deviation over the seeds (the paper's Figs. 8–11).

    postprocess/plot_sweep.py sweeps/mu_w/summary.csv [more summary.csv ...] -o mu_w.png
        [--label "μ_w"] [--legend "with wire" ...] [--table]
        [--baseline sweeps/wire/summary.csv --baseline-label "no wire" [--paired]]

Input: the summary.csv of postprocess/sweep.py (one row per run). Output: one PNG with four
panels, H_n, φ_p, U_s/L (wire elastic energy per wire length, in ρ₁ g a_max³ where ρ₁ is
the density unit of Table 1, ρ_p = 1.5 ρ₁, and lengths are in a_max, g = 1) and z_wpc,
each against the parameter; one line per summary file. --table prints the means, standard deviations and seed counts. --baseline:
the runs of another summary (e.g. the same column without wire) as a horizontal line at
their mean with a band of ± one standard deviation. --paired (with --baseline): prints, for
every value, the seed-by-seed differences from the baseline run of the same seed (the same
seed deposits the same grain layers, so these pairs compare best) for H_n, the final
height H and the four observables: the mean difference ± its standard error (std ddof 1
over √n), n the seeds both have, and their ratio (|ratio| > 2: a difference beyond the
seeds' noise at about 95 %). --work-precision PNG (with --paired): the work–precision
plot of the sweep: for each value, its mean wall time per run (the summary's
wall_s) against |mean paired difference| / its standard error for H_n, φ_p, U_s/L and
z_wpc, the line at 2 the criterion; the baseline at 0; and a printed table of the same
with the speed-up over the baseline's mean wall time.
Uses Debian's python3-matplotlib and numpy."""

import argparse
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

OBSERVABLES = [("H_n", "H_n = H / H(t_relax)"),
               ("phi_p", "φ_p (grains inside the wire)"),
               ("U_s/L", "U_s / L  [ρ₁ g a_max³]"),
               ("z_wpc", "z_wpc (wire–grain contacts per segment)")]


def read_summary(path):
    """{value: {observable: [one number per seed]}} with values sorted numerically, and the
    parameter's name."""
    groups, param = defaultdict(lambda: defaultdict(list)), None
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            param = row["param"]
            for name, _ in OBSERVABLES:
                groups[float(row["value"])][name].append(float(row[name]))
    return param, dict(sorted(groups.items()))


def read_rows(path):
    """{(value, seed): row} of a summary.csv, numbers as floats."""
    with open(path, newline="") as f:
        return {(float(r["value"]), int(r["seed"])): {k: float(v) if v != "" else float("nan") for k, v in r.items()
                                                      if k not in ("param", "value", "seed")}
                for r in csv.DictReader(f)}


def paired_differences(rows, baseline_rows, name):
    """{value: (mean, standard error, n)} of rows[value, seed][name] − baseline[seed][name]
    over the seeds both have (the baseline's runs by seed, whatever its value); a value with
    fewer than two common seeds has no standard error (nan)."""
    base = {}
    for (_, seed), row in baseline_rows.items():
        if seed in base:
            sys.exit(f"plot_sweep.py: the baseline has two runs of seed {seed}")
        base[seed] = row[name]
    out = {}
    for value in sorted({v for v, _ in rows}):
        d = np.array([row[name] - base[seed] for (v, seed), row in sorted(rows.items()) if v == value and seed in base])
        if len(d):
            se = d.std(ddof=1) / np.sqrt(len(d)) if len(d) > 1 else float("nan")
            out[value] = (d.mean(), se, len(d))
    return out


def statistics(groups, name):
    """values, means, standard deviations (ddof 1; 0 for one seed), seed counts."""
    values = np.array(list(groups))
    samples = [np.array(groups[v][name]) for v in groups]
    means = np.array([s.mean() for s in samples])
    stds = np.array([s.std(ddof=1) if len(s) > 1 else 0.0 for s in samples])
    return values, means, stds, np.array([len(s) for s in samples])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("summaries", nargs="+")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--label", default=None, help="x axis label (default: the parameter's name)")
    parser.add_argument("--legend", nargs="+", default=None, help="one label per summary file")
    parser.add_argument("--table", action="store_true")
    parser.add_argument("--baseline", default=None, help="a summary.csv drawn as mean ± std across every panel")
    parser.add_argument("--baseline-label", default="baseline")
    parser.add_argument("--paired", action="store_true",
                        help="print each value's seed-by-seed differences from the baseline (mean ± standard error)")
    parser.add_argument("--work-precision", default=None, metavar="PNG",
                        help="with --paired: wall time per run against the paired shift in standard errors")
    args = parser.parse_args()
    if args.paired and not args.baseline:
        parser.error("--paired needs --baseline")
    if args.work_precision and not args.paired:
        parser.error("--work-precision needs --paired")
    if args.legend and len(args.legend) != len(args.summaries):
        parser.error(f"--legend needs one label per summary file ({len(args.summaries)})")

    fig, axes = plt.subplots(2, 2, figsize=(9, 7), constrained_layout=True)
    for k, path in enumerate(args.summaries):
        param, groups = read_summary(path)
        if not groups:
            sys.exit(f"plot_sweep.py: {path} has no runs")
        legend = args.legend[k] if args.legend else path
        for ax, (name, title) in zip(axes.flat, OBSERVABLES):
            values, means, stds, counts = statistics(groups, name)
            ax.errorbar(values, means, yerr=stds, marker="o", capsize=3, label=legend)
            ax.set_xlabel(args.label or param)
            ax.set_ylabel(title)
            if args.table:
                for v, m, s, n in zip(values, means, stds, counts):
                    print(f"{legend}\t{param} = {v:g}\t{name} = {m:.4g} ± {s:.2g} ({n} seeds)")
    if args.baseline:
        _, groups = read_summary(args.baseline)
        for ax, (name, _) in zip(axes.flat, OBSERVABLES):
            samples = np.concatenate([np.array(groups[v][name]) for v in groups])
            mean, std = samples.mean(), samples.std(ddof=1) if len(samples) > 1 else 0.0
            ax.axhline(mean, color="k", ls="--", lw=1, label=f"{args.baseline_label} ({len(samples)} runs)")
            ax.axhspan(mean - std, mean + std, color="k", alpha=0.1)
            if args.table:
                print(f"{args.baseline_label}\t{name} = {mean:.4g} ± {std:.2g} ({len(samples)} runs)")
    if args.paired:
        baseline_rows = read_rows(args.baseline)
        for k, path in enumerate(args.summaries):
            legend = args.legend[k] if args.legend else path
            rows = read_rows(path)
            for name in ("H_n", "H", "phi_p", "U_s/L", "z_wpc"):
                for value, (mean, se, n) in paired_differences(rows, baseline_rows, name).items():
                    ratio = f"; {mean / se:+.2f} standard errors" if se > 0 else ""
                    print(f"{legend} − {args.baseline_label}\t{value:g}\t{name}: {mean:+.4g} ± {se:.2g} ({n} seeds{ratio})")
    for ax in axes.flat:
        ax.grid(alpha=0.3)
    axes.flat[0].legend(fontsize=8)
    fig.savefig(args.output, dpi=120)
    print(f"wrote {args.output}")
    if args.work_precision:
        work_precision(args)


def work_precision(args):
    """Wall time per run against each observable's paired shift (in standard errors of the
    paired difference), one point per value of every summary; the table printed."""
    baseline_rows = read_rows(args.baseline)
    base_wall = np.mean([r["wall_s"] for r in baseline_rows.values()])
    fig, axes = plt.subplots(2, 2, figsize=(9, 7), constrained_layout=True)
    longest = base_wall
    print(f"work–precision: baseline {args.baseline_label}, {base_wall:.0f} s per run")
    print("summary\tvalue\ts per run\tspeed-up\t" + "\t".join(f"{n} shift/SE" for n, _ in OBSERVABLES))
    for k, path in enumerate(args.summaries):
        legend = args.legend[k] if args.legend else path
        rows = read_rows(path)
        shifts = {name: paired_differences(rows, baseline_rows, name) for name, _ in OBSERVABLES}
        values = sorted(shifts[OBSERVABLES[0][0]])
        wall = {v: np.mean([r["wall_s"] for (val, _), r in rows.items() if val == v]) for v in values}
        longest = max([longest] + list(wall.values()))
        for ax, (name, title) in zip(axes.flat, OBSERVABLES):
            ratio = [abs(shifts[name][v][0] / shifts[name][v][1]) if shifts[name][v][1] > 0 else np.nan
                     for v in values]
            ax.plot([wall[v] for v in values], ratio, marker="o", label=legend)
            for v, r in zip(values, ratio):
                ax.annotate(f"{v:g}", (wall[v], r), textcoords="offset points", xytext=(4, 4), fontsize=8)
        for v in values:
            cells = [shifts[n][v][0] / shifts[n][v][1] if shifts[n][v][1] > 0 else np.nan for n, _ in OBSERVABLES]
            print(f"{legend}\t{v:g}\t{wall[v]:.0f}\t{base_wall / wall[v]:.2f}\t" +
                  "\t".join("n/a" if np.isnan(c) else f"{c:+.2f}" for c in cells))
    for ax, (name, title) in zip(axes.flat, OBSERVABLES):
        ax.axhline(2.0, color="r", ls="--", lw=1, label="2 standard errors")
        ax.plot([base_wall], [0.0], marker="s", color="k", ls="none", label=args.baseline_label)
        ax.set_xlim(0.0, 1.1 * longest)
        ax.set_ylim(bottom=0.0)
        ax.set_xlabel("wall time per run (s)")
        ax.set_ylabel(f"|shift of {name}| / standard error")
        ax.set_title(title, fontsize=9)
        ax.grid(alpha=0.3)
    axes.flat[0].legend(fontsize=8)
    fig.savefig(args.work_precision, dpi=120)
    print(f"wrote {args.work_precision}")


if __name__ == "__main__":
    main()
