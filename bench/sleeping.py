#!/usr/bin/python3
"""Benchmark: the column deck with and without sleeping NSCD grains, one after the other
on the same ranks: wall time, its ratio, the final observables and how many grains slept.

    bench/sleeping.py [--liggghts build/liggghts] [--np 2] [--deck examples/column/in.column_small]
        [--seed 4242] [--sleep 1e-3 1e-2] [--t-sleep 0.5] [--var NAME VALUE ...]

Runs DECK with -var v_sleep 0 (off: the reference) and then with each --sleep value
(`fix nscd/polyhedra sleep v_sleep t_sleep`, input_scripts/in.column), and prints per
setting the wall time of the liggghts process, LIGGGHTS' loop time, the final H_n, φ_p,
U_s/L and z_wpc, the largest and the last number of grains asleep in the thermo output,
and the ratio of each setting's times to the reference's. Run it on an otherwise idle
machine (or read only the ratios)."""

import os
import re

from column_runs import ROOT, column_arguments, run_column


def asleep_counts(stdout):
    """The v_solver_asleep column of every thermo table of the run."""
    counts = []
    header = None
    for line in stdout.splitlines():
        words = line.split()
        if words[:1] == ["Step"]:
            header = words.index("v_solver_asleep") if "v_solver_asleep" in words else None
            continue
        if header is not None and len(words) > header and re.fullmatch(r"-?\d+", words[0] or ""):
            try:
                counts.append(float(words[header]))
            except ValueError:
                header = None
        elif header is not None:
            header = None
    return counts


def main():
    parser = column_arguments(__doc__.splitlines()[0], 2)
    parser.add_argument("--sleep", type=float, nargs="+", default=[1e-3, 1e-2])
    parser.add_argument("--t-sleep", type=float, default=0.5)
    args = parser.parse_args()
    results = {}
    for v_sleep in [0.0] + args.sleep:
        variables = [("seed", args.seed), ("v_sleep", v_sleep), ("t_sleep", args.t_sleep)] + args.var
        wall, loop, obs, out = run_column(args.liggghts, args.np, args.deck, variables, f"sleep-{v_sleep:g}")
        counts = asleep_counts(out)
        results[v_sleep] = (wall, loop, obs, max(counts, default=0), counts[-1] if counts else 0)
    print(f"# {os.path.relpath(args.deck, ROOT)}, seed {args.seed}, {args.np} rank(s), t_sleep {args.t_sleep}")
    print(f"{'v_sleep':>8s} {'wall [s]':>9s} {'loops [s]':>9s} {'H_n':>8s} {'phi_p':>7s} {'U_s/L':>10s} {'z_wpc':>7s}"
          f" {'most asleep':>11s} {'asleep at end':>13s}")
    for v_sleep, (wall, loop, obs, most, last) in results.items():
        print(f"{v_sleep:8g} {wall:9.1f} {loop:9.1f} {obs[0]:8.4f} {obs[1]:7.4f} {obs[2]:10.3e} {obs[3]:7.4f}"
              f" {most:11.0f} {last:13.0f}")
    reference = results[0.0]
    for v_sleep in args.sleep:
        print(f"v_sleep {v_sleep:g} / off: wall {results[v_sleep][0] / reference[0]:.2f}, "
              f"loops {results[v_sleep][1] / reference[1]:.2f}")


if __name__ == "__main__":
    main()
