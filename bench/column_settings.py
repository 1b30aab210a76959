#!/usr/bin/python3
"""Benchmark: the same column deck with several settings, one after the other on the same
ranks: wall time, its ratio to the first setting, the final observables and how many NSCD
grains slept.

    bench/column_settings.py [--liggghts build/liggghts] [--np 2] [--deck examples/column/in.column_small]
        [--seed 4242] [--var NAME VALUE ...] --settings "v_sleep=0" "v_sleep=1e-2 t_sleep=0.5" "wire_cache=no" ...

Each setting is a list of NAME=VALUE deck variables (input_scripts/in.column: v_sleep and
t_sleep for `fix nscd/polyhedra sleep`, wire_cache for `pair_style wire/contact cache`,
ke_stop for the early end of the phases, ...), given on top of --var; the first setting
is the reference. Prints per setting the wall time of the liggghts process, LIGGGHTS' loop
time, the final H_n, φ_p, U_s/L and z_wpc, the largest and the last number of grains
asleep in the thermo output, and the ratio of each setting's times to the reference's.
Run it on an otherwise idle machine (or read only the ratios)."""

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


def parse_setting(text):
    """'NAME=VALUE NAME=VALUE' -> [(NAME, VALUE), ...]"""
    pairs = []
    for word in text.split():
        name, sep, value = word.partition("=")
        if not sep or not name or not value:
            raise SystemExit(f"a setting is NAME=VALUE words, got '{word}' in '{text}'")
        pairs.append((name, value))
    return pairs


def main():
    parser = column_arguments(__doc__.splitlines()[0], 2)
    parser.add_argument("--settings", nargs="+", required=True)
    args = parser.parse_args()
    results = {}
    for k, setting in enumerate(args.settings):
        variables = [("seed", args.seed)] + args.var + parse_setting(setting)
        wall, loop, obs, out = run_column(args.liggghts, args.np, args.deck, variables, f"setting-{k}")
        counts = asleep_counts(out)
        results[setting] = (wall, loop, obs, max(counts, default=0), counts[-1] if counts else 0)
    print(f"# {os.path.relpath(args.deck, ROOT)}, seed {args.seed}, {args.np} rank(s), --var {args.var}")
    width = max(len(s) for s in args.settings)
    print(f"{'setting':{width}s} {'wall [s]':>9s} {'loops [s]':>9s} {'H_n':>8s} {'phi_p':>7s} {'U_s/L':>10s} {'z_wpc':>7s}"
          f" {'most asleep':>11s} {'asleep at end':>13s}")
    for setting, (wall, loop, obs, most, last) in results.items():
        print(f"{setting:{width}s} {wall:9.1f} {loop:9.1f} {obs[0]:8.4f} {obs[1]:7.4f} {obs[2]:10.3e} {obs[3]:7.4f}"
              f" {most:11.0f} {last:13.0f}")
    reference = results[args.settings[0]]
    for setting in args.settings[1:]:
        print(f"{setting} / {args.settings[0]}: wall {results[setting][0] / reference[0]:.2f}, "
              f"loops {results[setting][1] / reference[1]:.2f}")


if __name__ == "__main__":
    main()
