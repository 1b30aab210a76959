#!/usr/bin/python3
"""Benchmark: every NSCD solver setting against Siconos numerics' fc3d_nsgs on the same
problems, one table: sweeps and time to reach Siconos' final error, ns per contact update,
the ratio to Siconos' time (bench/fclib_nscd does each problem; this script runs it on all
of them and gathers the rows).

    bench/nscd_methods.py [--build build] [--repeat 3] [--skip-pile] [--keep DIR]

(--keep DIR keeps the 915-grain pile's deck and problems there, and takes them from there
when an earlier run left them.)

Problems:
  - a column of 20 unit cubes at rest (fclib_nscd generate column 20: a tall stack),
  - a generated lattice pile of 10 x 10 x 9 cubes (fclib_nscd generate pile 10 10 9:
    10 080 contacts, random start velocities; also solved on the bodies),
  - the pile of 915 Table 1 grains (the paper's N_p) of bench/siconos_pile.py, its
    problems at step 7000 (still moving) and 14000 (settled), written by fix
    nscd/polyhedra, converted to FCLib files (4 minutes to make; --skip-pile leaves them
    out).
Each solver runs until its Siconos error is at most what Siconos reached (its tolerance
1e-4 when it converged, its final error at its 1000-iteration cap otherwise); rows that
stop at their own cap first are marked. ns per contact update = time / (sweeps x
contacts): a stick solve of method subspace is counted in the time, not in the sweeps."""

import argparse
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import siconos_pile  # noqa: E402

ROW = re.compile(r"^(siconos fc3d_nsgs.*?|wiregrain nscd.*?)\s+(\d+)\s+([0-9.eE+-]+)\s+([0-9.eE+-]+)\s+"
                 r"([0-9.eE+-]+)\s+([0-9.eE+-]+)\s+([0-9.eE+-]+)(\s+\(iteration cap\))?\s*$", re.M)


def solve(fclib_nscd, arguments, repeat):
    out = subprocess.run([fclib_nscd] + arguments + ["--repeat", str(repeat)], stdout=subprocess.PIPE,
                         check=True).stdout.decode()
    contacts = int(re.search(r"problem: .*?: (\d+) contacts", out).group(1))
    rows = []
    for name, sweeps, error, _, seconds, _, ratio, capped in ROW.findall(out):
        rows.append((name.strip(), int(sweeps), float(error), float(seconds), float(ratio), bool(capped)))
    return contacts, rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(HERE, "..", "build"))
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--skip-pile", action="store_true")
    parser.add_argument("--keep", help="directory for the 915-grain pile's deck and problems")
    args = parser.parse_args()
    fclib_nscd = os.path.join(args.build, "bench", "fclib_nscd")
    problems = [("column of 20 cubes", ["generate", "column", "20"]),
                ("lattice pile 10x10x9", ["generate", "pile", "10", "10", "9"])]
    if not args.skip_pile:
        work = args.keep or tempfile.mkdtemp(prefix="wiregrain-methods-")
        made = [os.path.join(work, f"problem_{step}.hdf5") for step in (7000, 14000)]
        if all(os.path.exists(path) for path in made):  # --keep DIR of an earlier run
            moving, settled = made
        else:
            moving, settled = siconos_pile.pile_problems(os.path.join(args.build, "liggghts"), fclib_nscd, work)
        problems += [("915-grain pile, step 7000 (moving)", ["solve", moving]),
                     ("915-grain pile, step 14000 (settled)", ["solve", settled])]
    print(f"{'problem':<44} {'solver':<42} {'sweeps':>7} {'Siconos error':>13} {'time [s]':>10} "
          f"{'ns/update':>9} {'ratio':>7}")
    for label, arguments in problems:
        contacts, rows = solve(fclib_nscd, arguments, args.repeat)
        for name, sweeps, error, seconds, ratio, capped in rows:
            per_update = 1e9 * seconds / max(sweeps * contacts, 1)
            print(f"{label + f' ({contacts})':<44} {name:<42} {sweeps:7d} {error:13.3e} {seconds:10.4f} "
                  f"{per_update:9.0f} {ratio:7.3f}{'  (cap)' if capped else ''}", flush=True)


if __name__ == "__main__":
    main()
