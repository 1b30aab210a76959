#!/usr/bin/python3
"""Two LIGGGHTS builds side by side on the standing benchmarks (for a refactor that must
not slow anything down): bench/nscd_scaling.py, bench/wire_contacts.py and
bench/wire_vs_spheres.py, each run with build A and build B alternately, `--repeat`
times, the best time of each kept; one table of figures and ratios B / A.

    bench/compare_builds.py --before OLD/liggghts --after NEW/liggghts [--repeat 2]
        [--grains 100 1000]

The benches are the ones of the checkout this script lives in, so both builds run the
same decks (the decks must be valid for both)."""

import argparse
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))

# (bench script, extra arguments, [(figure name, regex with one group)])
FIGURES = [
    ("wire_contacts.py", [], [
        ("wire contacts: ms per step with contacts", r"with contacts\s*:\s*([\d.]+) ms"),
        ("wire contacts: ms per step without contacts", r"without contacts:\s*([\d.]+) ms"),
    ]),
    ("wire_vs_spheres.py", [], [
        ("wire: ns per bead-step", r"wire\s*:.*?([\d.]+) ns per bead-step"),
        ("stock spheres: ns per sphere-step", r"spheres\s*:.*?([\d.]+) ns per sphere-step"),
    ]),
]


def nscd_figures(grains):
    # nscd_scaling prints one row per N: grains contacts sweeps detect_ms solve_ms ...
    rows = []
    for n in grains:
        rows.append((f"nscd {n} grains: detect ms per step", rf"^\s*{n}\s+\d+\s+[\d.]+\s+([\d.]+)\s+[\d.]+"))
        rows.append((f"nscd {n} grains: solve ms per step", rf"^\s*{n}\s+\d+\s+[\d.]+\s+[\d.]+\s+([\d.]+)"))
    return rows


def run(script, binary, extra):
    out = subprocess.run([sys.executable, os.path.join(HERE, script), "--liggghts", binary] + extra,
                         capture_output=True, text=True, check=True).stdout
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--before", required=True)
    p.add_argument("--after", required=True)
    p.add_argument("--repeat", type=int, default=2)
    p.add_argument("--grains", type=int, nargs="+", default=[100, 1000])
    args = p.parse_args()
    benches = FIGURES + [("nscd_scaling.py", ["--grains"] + [str(g) for g in args.grains], nscd_figures(args.grains))]
    table = []
    for script, extra, figures in benches:
        best = {"before": {}, "after": {}}
        for _ in range(args.repeat):
            for which, binary in (("before", args.before), ("after", args.after)):
                out = run(script, os.path.abspath(binary), extra)
                for name, rx in figures:
                    m = re.search(rx, out, re.M)
                    if not m:
                        raise SystemExit(f"{script}: no '{name}' in output:\n{out}")
                    value = float(m.group(1))
                    best[which][name] = min(value, best[which].get(name, value))
        for name, _ in figures:
            table.append((name, best["before"][name], best["after"][name]))
    width = max(len(n) for n, _, _ in table)
    print(f"{'figure':<{width}} {'before':>10} {'after':>10} {'after/before':>13}")
    for name, a, b in table:
        print(f"{name:<{width}} {a:10.4g} {b:10.4g} {b / a:13.3f}")


if __name__ == "__main__":
    main()
