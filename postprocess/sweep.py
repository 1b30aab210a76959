#!/usr/bin/python3
"""Run a column deck over the values of one parameter × several seeds, several runs side by
side, resumable; collect the final observables in a table.

    postprocess/sweep.py PARAM VALUE [VALUE ...] [--seeds 1001 2002 3003]
        [--deck input_scripts/in.column] [--var NAME VALUE ...] [--out sweeps/PARAM]
        [--jobs N] [--np 1] [--liggghts build/liggghts] [--summary-only]

Each run goes to OUT/PARAM=VALUE/seed=S/ (its log, column.obs, restart files, post/) and is
run as `liggghts -in DECK -var PARAM VALUE -var seed S -var root REPOSITORY [--var ...]`,
with `mpirun -np NP` when NP > 1. A run is finished when its directory holds final.json
(written here once the deck printed its "in.column final: ..." line and exited cleanly):
finished runs are not repeated, so an interrupted sweep continues where it stopped, and a
failed run is tried again. --summary-only runs nothing and tabulates the finished runs. --jobs runs that many at once (default: cores / NP).

OUT/summary.csv: one row per finished run (param, value, seed, H_n, phi_p, U_s/L, z_wpc,
H0, H, wall time in s), rewritten after every run, read by postprocess/plot_sweep.py. The observables: see
docs/results.md, "Observables". Uses only Python's standard library."""

import argparse
import concurrent.futures
import csv
import json
import os
import re
import subprocess
import sys
import time

REPOSITORY = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FINAL = re.compile(r"^in\.column final: H_n = (\S+) phi_p = (\S+) U_s/L = (\S+) z_wpc = (\S+) "
                   r"\(H0 = (\S+), H = (\S+)\)", re.M)
COLUMNS = ["param", "value", "seed", "H_n", "phi_p", "U_s/L", "z_wpc", "H0", "H", "wall_s"]


def parse_final(log_text):
    """The observables of the deck's final line as a dict, or None when it is missing."""
    found = FINAL.findall(log_text)
    if not found:
        return None
    values = [float(v) for v in found[-1]]
    return dict(zip(["H_n", "phi_p", "U_s/L", "z_wpc", "H0", "H"], values))


def run_directory(out, param, value, seed):
    return os.path.join(out, f"{param}={value}", f"seed={seed}")


def command(args, value, seed):
    deck = os.path.abspath(args.deck)
    cmd = [] if args.np == 1 else ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(args.np)]
    cmd += [os.path.abspath(args.liggghts), "-in", deck, "-log", "log.liggghts",
            "-var", args.param, str(value), "-var", "seed", str(seed), "-var", "root", REPOSITORY]
    for name, val in args.var:
        cmd += ["-var", name, val]
    return cmd


def run_one(args, value, seed):
    """Runs one (value, seed) unless finished; returns its row or an error text."""
    where = run_directory(args.out, args.param, value, seed)
    done = os.path.join(where, "final.json")
    if os.path.exists(done):
        with open(done) as f:
            return json.load(f), None
    os.makedirs(os.path.join(where, "post"), exist_ok=True)
    cmd = command(args, value, seed)
    with open(os.path.join(where, "command.txt"), "w") as f:
        f.write(" ".join(cmd) + "\n")
    start = time.time()
    with open(os.path.join(where, "stdout.txt"), "w") as out:
        status = subprocess.call(cmd, cwd=where, stdout=out, stderr=subprocess.STDOUT)
    wall = time.time() - start
    texts = []  # the log, and the screen output (error->one writes its ERROR only there)
    for name in ("log.liggghts", "stdout.txt"):
        path = os.path.join(where, name)
        texts.append(open(path, errors="replace").read() if os.path.exists(path) else "")
    final = parse_final(texts[0])
    if status != 0 or final is None:
        errors = [line for line in "\n".join(texts).splitlines() if line.startswith("ERROR")]
        return None, f"{where}: exit {status}; " + (errors[-1] if errors else "no final line in log.liggghts")
    row = {"param": args.param, "value": value, "seed": seed, **final, "wall_s": round(wall, 1)}
    with open(done, "w") as f:
        json.dump(row, f)
    return row, None


def write_summary(path, rows):
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        for row in rows:
            writer.writerow({k: row[k] for k in COLUMNS})


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("param")
    parser.add_argument("values", nargs="+")
    parser.add_argument("--seeds", nargs="+", type=int, default=[1001, 2002, 3003])
    parser.add_argument("--deck", default=os.path.join(REPOSITORY, "input_scripts", "in.column"))
    parser.add_argument("--var", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"))
    parser.add_argument("--out", default=None)
    parser.add_argument("--np", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=None)
    parser.add_argument("--liggghts", default=os.path.join(REPOSITORY, "build", "liggghts"))
    parser.add_argument("--summary-only", action="store_true",
                        help="run nothing: tabulate the finished runs under --out into summary.csv")
    args = parser.parse_args()
    if args.np < 1:
        parser.error(f"--np must be >= 1, got {args.np}")
    if args.param == "seed" or any(name in (args.param, "seed") for name, _ in args.var):
        parser.error("the swept parameter and seed are set by the sweep; do not give them with --var")
    for path, what in ((args.deck, "--deck"), (args.liggghts, "--liggghts")):
        if not os.path.exists(path):
            parser.error(f"{what}: {path} does not exist")
    args.out = args.out or os.path.join("sweeps", args.param)
    jobs = args.jobs or max(1, (os.cpu_count() or 1) // args.np)

    todo = [(v, s) for v in args.values for s in args.seeds]
    if args.summary_only:
        todo = [(v, s) for v, s in todo if os.path.exists(os.path.join(run_directory(args.out, args.param, v, s), "final.json"))]
    rows, failures = {}, []
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = {pool.submit(run_one, args, v, s): (v, s) for v, s in todo}
        for future in concurrent.futures.as_completed(futures):
            row, error = future.result()
            v, s = futures[future]
            if error:
                failures.append(error)
                print(f"FAILED {args.param}={v} seed={s}: {error}", flush=True)
            else:
                rows[(v, s)] = row
                print(f"{args.param}={v} seed={s}: H_n {row['H_n']:.4f} phi_p {row['phi_p']:.4f} "
                      f"U_s/L {row['U_s/L']:.4g} z_wpc {row['z_wpc']:.4f} ({row['wall_s']:.0f} s)", flush=True)
                # rewritten after every run: a sweep cut short still leaves the table of what finished
                ordered = [rows[k] for k in todo if k in rows]
                write_summary(os.path.join(args.out, "summary.csv"), ordered)
    ordered = [rows[k] for k in todo if k in rows]
    os.makedirs(args.out, exist_ok=True)
    write_summary(os.path.join(args.out, "summary.csv"), ordered)
    print(f"{len(ordered)} of {len(todo)} runs finished; table in {os.path.join(args.out, 'summary.csv')}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
