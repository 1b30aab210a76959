"""One column deck run for the benchmarks (bench/grain_models.py, bench/column_settings.py): the
deck in a fresh directory with -var NAME VALUE pairs, timed; its final observables."""

import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FINAL = re.compile(r"^in\.column final: H_n = (\S+) phi_p = (\S+) U_s/L = (\S+) z_wpc = (\S+)", re.M)


def run_column(liggghts, np_ranks, deck, variables, label):
    """Run `deck` with -var root ROOT -var t_vtk 0 and `variables` [(name, value), ...];
    returns (wall seconds of the process, the sum of LIGGGHTS' "Loop time" lines,
    [H_n, phi_p, U_s/L, z_wpc], stdout). Exits naming `label` if the run fails."""
    work = tempfile.mkdtemp(prefix=f"wiregrain-bench-{label}-")
    cmd = [] if np_ranks == 1 else ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(np_ranks)]
    cmd += [os.path.abspath(liggghts), "-in", os.path.abspath(deck), "-var", "root", ROOT, "-var", "t_vtk", "0"]
    for name, value in variables:
        cmd += ["-var", name, str(value)]
    start = time.perf_counter()
    proc = subprocess.run(cmd, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.perf_counter() - start
    final = FINAL.findall(proc.stdout)
    if proc.returncode != 0 or not final:
        sys.exit(f"the {label} run failed in {work}:\n{proc.stdout[-3000:]}")
    loop = sum(float(t) for t in re.findall(r"^Loop time of (\S+)", proc.stdout, re.M))
    return wall, loop, [float(v) for v in final[-1]], proc.stdout


def column_arguments(description, np_ranks):
    """An argument parser with the options every column benchmark takes: --liggghts, --np
    (default `np_ranks`), --deck, --seed and --var NAME VALUE (repeatable)."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--liggghts", default=os.path.join(ROOT, "build", "liggghts"))
    parser.add_argument("--np", type=int, default=np_ranks)
    parser.add_argument("--deck", default=os.path.join(ROOT, "examples", "column", "in.column_small"))
    parser.add_argument("--seed", type=int, default=4242)
    parser.add_argument("--var", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"))
    return parser
