#!/usr/bin/python3
"""Run a column deck over the values of one parameter × several seeds, several runs side by
side, resumable; collect the final observables in a table.

    postprocess/sweep.py PARAM VALUE [VALUE ...] [--seeds 1001 2002 3003]
        [--deck input_scripts/in.column] [--var NAME VALUE ...] [--out sweeps/PARAM]
        [--jobs N] [--np 1] [--liggghts build/liggghts] [--summary-only | --collect]
        [--scheduler local|slurm] [--ranks N] [--time T] [--partition P] [--account A]
        [--sbatch OPTION ...]

Each run goes to OUT/PARAM=VALUE/seed=S/ (its log, column.obs, restart files, post/) and is
run as `liggghts -in DECK -var PARAM VALUE -var seed S -var root REPOSITORY [--var ...]`,
with `mpirun -np NP` when NP > 1. A run is finished when its directory holds final.json
(written here once the deck printed its "in.column final: ..." line and exited cleanly):
finished runs are not repeated, so an interrupted sweep continues where it stopped, and a
failed run (one that printed an ERROR line; error.txt keeps it) is tried again from the start.
A run that was interrupted (killed, out of time, or ended without an ERROR line: no final.json
and no error.txt) continues from its latest restart file, as in.column's `resume` does: the
wall phase's column_walls.restart (resume 3, written with --var t_restart T), else the relaxed column (resume 1), the deposit (resume 2)
or the last layer's restart (resume 4, written with --var layer_restart 1); its earlier logs
are kept as log.liggghts.1, .2, ... and its wall time is the parts' sum. --summary-only runs nothing and tabulates the finished runs. --jobs runs that many at once (default: cores / NP).

--scheduler slurm submits the runs not yet finished as one Slurm job array (sbatch), each
task one (value, seed) run in its folder with --ranks MPI ranks (mpirun inside the task's
allocation, or srun with --launcher srun; --ranks is --np); --time, --partition, --account
and every --sbatch OPTION go to sbatch. The array's script, its list of runs and the tasks' output are in OUT/slurm/. A
second submit skips the finished runs (nothing is submitted when all are finished). A failed
run leaves error.txt in its folder (its log's last ERROR line). --collect (= --summary-only)
tabulates the finished runs and lists the failed ones with their ERROR line.

OUT/summary.csv: one row per finished run (param, value, seed, H_n, phi_p, U_s/L, z_wpc,
H0, H, wall time in s), rewritten after every run, read by postprocess/plot_sweep.py. The observables: see
docs/results.md, "Observables". Uses only Python's standard library."""

import argparse
import concurrent.futures
import csv
import glob
import json
import os
import re
import subprocess
import sys
import time

REPOSITORY = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FINAL = re.compile(r"^in\.column final: H_n = (\S+) phi_p = (\S+) U_s/L = (\S+) z_wpc = (\S+) "
                   r"\(H0 = (\S+), H = (\S+)\)", re.M)
# the centre reading H_c_n (twice the grains' mean centre height over its value when the
# walls started), on the same line; empty in the table for a deck that does not print it
CENTRE = re.compile(r"^in\.column final: .*; H_c_n = (\S+) ", re.M)
COLUMNS = ["param", "value", "seed", "H_n", "phi_p", "U_s/L", "z_wpc", "H0", "H", "H_c_n", "wall_s"]


def parse_final(log_text):
    """The observables of the deck's final line as a dict, or None when it is missing."""
    found = FINAL.findall(log_text)
    if not found:
        return None
    values = [float(v) for v in found[-1]]
    observables = dict(zip(["H_n", "phi_p", "U_s/L", "z_wpc", "H0", "H"], values))
    centre = CENTRE.findall(log_text)
    observables["H_c_n"] = float(centre[-1]) if centre else ""
    return observables


def run_directory(out, param, value, seed):
    return os.path.join(out, f"{param}={value}", f"seed={seed}")


def command(args, value, seed):
    deck = os.path.abspath(args.deck)
    if args.np == 1:
        cmd = []
    elif getattr(args, "launcher", "mpirun") == "srun":
        cmd = ["srun", "-n", str(args.np)]
    else:
        cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(args.np)]
    cmd += [os.path.abspath(args.liggghts), "-in", deck, "-log", "log.liggghts",
            "-var", args.param, str(value), "-var", "seed", str(seed), "-var", "root", REPOSITORY]
    for name, val in args.var:
        cmd += ["-var", name, val]
    return cmd


# in.column's restart files, the newest first: the file, the text file the deck reads with it,
# and the deck's `resume` that continues from them
RESTARTS = (("column_walls.restart", "column_walls.txt", 3), ("column_relaxed.restart", "column_deposited.txt", 1),
            ("column_deposited.restart", "column_deposited.txt", 2), (None, "column_layer.txt", 4))
ELAPSED = "elapsed_s.txt"  # the wall time of the parts run so far


def resume_point(where):
    """The `resume` that continues an interrupted run in `where` from its latest restart
    file (0: none, start over); a run that stopped with an ERROR (error.txt) starts over."""
    if os.path.exists(os.path.join(where, "error.txt")):
        return 0
    for restart, record, resume in RESTARTS:
        if os.path.exists(os.path.join(where, record)) and (restart is None or os.path.exists(os.path.join(where, restart))):
            return resume
    return 0


def start_over(where):
    """Removes what a run left that would make the next call resume it."""
    names = [record for _, record, _ in RESTARTS] + [restart for restart, _, _ in RESTARTS if restart] + [ELAPSED]
    names += [os.path.basename(p) for p in glob.glob(os.path.join(where, "column_layer_*"))]
    for name in set(names):
        if os.path.exists(os.path.join(where, name)):
            os.remove(os.path.join(where, name))


def run_one(args, value, seed):
    """Runs one (value, seed) unless finished, continuing an interrupted run from its latest
    restart; returns its row or an error text."""
    where = run_directory(args.out, args.param, value, seed)
    done = os.path.join(where, "final.json")
    if os.path.exists(done):
        with open(done) as f:
            return json.load(f), None
    os.makedirs(os.path.join(where, "post"), exist_ok=True)
    cmd = command(args, value, seed)
    resume = resume_point(where)
    elapsed = 0.0
    if resume:
        cmd += ["-var", "resume", str(resume)]
        part = 1
        while os.path.exists(os.path.join(where, f"log.liggghts.{part}")):
            part += 1
        for name in ("log.liggghts", "stdout.txt"):
            if os.path.exists(os.path.join(where, name)):
                os.replace(os.path.join(where, name), os.path.join(where, f"{name}.{part}"))
        if os.path.exists(os.path.join(where, ELAPSED)):
            with open(os.path.join(where, ELAPSED)) as f:
                elapsed = float(f.read().split()[0])
        print(f"{args.param}={value} seed={seed}: continues with resume {resume}", flush=True)
    else:
        start_over(where)
    with open(os.path.join(where, "command.txt"), "w") as f:
        f.write(" ".join(cmd) + "\n")
    start = time.time()
    try:
        with open(os.path.join(where, "stdout.txt"), "w") as out:
            status = subprocess.call(cmd, cwd=where, stdout=out, stderr=subprocess.STDOUT)
    finally:
        wall = elapsed + time.time() - start
        with open(os.path.join(where, ELAPSED), "w") as f:
            f.write(f"{wall:.1f}\n")
    texts = []  # the log, and the screen output (error->one writes its ERROR only there)
    for name in ("log.liggghts", "stdout.txt"):
        path = os.path.join(where, name)
        texts.append(open(path, errors="replace").read() if os.path.exists(path) else "")
    final = parse_final(texts[0])
    if status != 0 or final is None:
        errors = [line for line in "\n".join(texts).splitlines() if line.startswith("ERROR")]
        if not errors:
            # killed (a signal, out of memory, the machine stopped) or crashed: its restart
            # files are sound, so the next call continues it instead of starting over
            return None, (f"{where}: exit {status}, no ERROR line and no final line: interrupted; "
                          f"the next call continues it from its latest restart")
        error = f"{where}: exit {status}; {errors[-1]}"
        with open(os.path.join(where, "error.txt"), "w") as f:
            f.write(error + "\n")
        return None, error
    if os.path.exists(os.path.join(where, "error.txt")):
        os.remove(os.path.join(where, "error.txt"))
    row = {"param": args.param, "value": value, "seed": seed, **final, "wall_s": round(wall, 1)}
    with open(done, "w") as f:
        json.dump(row, f)
    return row, None


def write_summary(path, rows):
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        for row in rows:
            writer.writerow({k: row.get(k, "") for k in COLUMNS})


def finished(args, value, seed):
    return os.path.exists(os.path.join(run_directory(args.out, args.param, value, seed), "final.json"))


def submit_slurm(args, todo):
    """Writes OUT/slurm/array-<time>.{json,sh} and submits the script with sbatch."""
    todo = [(v, s) for v, s in todo if not finished(args, v, s)]
    if not todo:
        print("every run is finished: nothing submitted")
        return 0
    where = os.path.abspath(os.path.join(args.out, "slurm"))
    os.makedirs(where, exist_ok=True)
    stem = os.path.join(where, time.strftime("array-%Y%m%d-%H%M%S-") + str(os.getpid()))
    spec = {k: v for k, v in vars(args).items()}
    spec.update(out=os.path.abspath(args.out), deck=os.path.abspath(args.deck),
                liggghts=os.path.abspath(args.liggghts), runs=todo)
    with open(stem + ".json", "w") as f:
        json.dump(spec, f, indent=1)
    lines = ["#!/bin/sh", f"#SBATCH --job-name=sweep-{args.param}", f"#SBATCH --array=0-{len(todo) - 1}",
             f"#SBATCH --ntasks={args.np}", f"#SBATCH --output={where}/%A_%a.out"]
    for option, value in (("time", args.time), ("partition", args.partition), ("account", args.account)):
        if value:
            lines.append(f"#SBATCH --{option}={value}")
    lines.append(f'exec {sys.executable} {os.path.abspath(__file__)} --run-task {stem}.json "$SLURM_ARRAY_TASK_ID"')
    with open(stem + ".sh", "w") as f:
        f.write("\n".join(lines) + "\n")
    cmd = ["sbatch", "--parsable", *args.sbatch, stem + ".sh"]
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
    if proc.returncode != 0:
        print(f"sbatch failed (exit {proc.returncode}): {proc.stdout.strip()}")
        return 1
    job = proc.stdout.strip().split(";")[0]
    print(f"submitted job array {job}: {len(todo)} runs ({stem}.sh)")
    return 0


def run_task(spec_path, index):
    """One task of a job array: the run at INDEX of the array's list."""
    with open(spec_path) as f:
        spec = json.load(f)
    args = argparse.Namespace(**spec)
    value, seed = spec["runs"][int(index)]
    row, error = run_one(args, value, seed)
    if error:
        print(f"FAILED {args.param}={value} seed={seed}: {error}", flush=True)
        return 1
    print(f"{args.param}={value} seed={seed}: H_n {row['H_n']:.4f} ({row['wall_s']:.0f} s)", flush=True)
    return 0


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "--run-task":
        return run_task(sys.argv[2], sys.argv[3])
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
    parser.add_argument("--summary-only", "--collect", dest="summary_only", action="store_true",
                        help="run nothing: tabulate the finished runs under --out into summary.csv, "
                             "list the failed ones")
    parser.add_argument("--scheduler", choices=["local", "slurm"], default="local")
    parser.add_argument("--ranks", type=int, dest="np", help="MPI ranks per run (= --np)")
    parser.add_argument("--launcher", choices=["mpirun", "srun"], default="mpirun",
                        help="what starts the ranks of a run when --ranks > 1 (srun: inside a Slurm task)")
    parser.add_argument("--time", help="sbatch --time of each task")
    parser.add_argument("--partition", help="sbatch --partition")
    parser.add_argument("--account", help="sbatch --account")
    parser.add_argument("--sbatch", action="append", default=[], metavar="OPTION",
                        help="an extra sbatch option, e.g. --sbatch=--qos=short (repeatable)")
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
    if args.scheduler == "slurm" and not args.summary_only:
        return submit_slurm(args, todo)
    if args.summary_only:
        failed = []
        for v, s in todo:
            error = os.path.join(run_directory(args.out, args.param, v, s), "error.txt")
            if not finished(args, v, s) and os.path.exists(error):
                with open(error) as f:
                    failed.append(f.read().strip())
                print(f"FAILED {args.param}={v} seed={s}: {failed[-1]}", flush=True)
        missing = len(todo) - sum(finished(args, v, s) for v, s in todo)
        todo = [(v, s) for v, s in todo if finished(args, v, s)]
        os.makedirs(args.out, exist_ok=True)
        write_summary(os.path.join(args.out, "summary.csv"), [run_one(args, v, s)[0] for v, s in todo])
        print(f"{len(todo)} runs finished, {len(failed)} failed, {missing - len(failed)} not run, running or "
              f"interrupted; table in {os.path.join(args.out, 'summary.csv')}")
        return 1 if failed else 0
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
