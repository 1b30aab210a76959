#!/usr/bin/python3
"""Benchmark: time per NSCD step (fix nscd/polyhedra) for N grains resting on the floor
of a box, split into gathering + contact detection and the Gauss-Seidel solve, for
several N in one invocation; prints the time per grain and the exponent b of time ∝ N^b
between consecutive N (1: linear), for the detection, the solve and both; then the same
against the work (contact points, contact points × sweeps), which separates the code's
scaling from the scene's (a small layer is mostly edge; Gauss-Seidel takes more sweeps on
a larger pile).

    bench/nscd_scaling.py [--liggghts build/liggghts] [--grains 100 1000 10000] [--steps 50]

Each system is a single layer of Table 1 grains (create_grains layer) dropped from a
grain's height onto a frictional floor and settled for 3000 steps (3 time units) before the timing."""

import argparse
import math
import os
import re
import subprocess
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))

DECK = """
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
region          box block {lo} {hi} {lo} {hi} 0 10
create_box      1 box
create_grains   1 {n} layer box 1.1 seed 4242
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra wall 0 0 0 0 0 1
timestep        1e-3
run             3000
variable        detect equal f_nscd[10]
variable        solve equal f_nscd[11]
thermo_style    custom step f_nscd[1] f_nscd[3] v_detect v_solve
thermo_modify   format float %.6g
thermo          1
run             {steps}
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--liggghts", default=os.path.join(HERE, "..", "build", "liggghts"))
    parser.add_argument("--grains", type=int, nargs="*", default=[100, 1000, 10000])
    parser.add_argument("--steps", type=int, default=50)
    args = parser.parse_args()
    print(f"{'grains':>8} {'contacts':>9} {'sweeps':>7} {'detect ms':>10} {'solve ms':>9} "
          f"{'detect us/grain':>16} {'solve us/grain':>15}")
    measured = []
    for n in args.grains:
        # a square layer: two staggered lattices of spacing 2 give n sites in a side of 2*sqrt(n/2)
        half = math.ceil(math.sqrt(n / 2.0)) + 1
        work = tempfile.mkdtemp(prefix="wiregrain-bench-")
        with open(os.path.join(work, "in.bench"), "w") as f:
            f.write(DECK.format(n=n, lo=-half, hi=half, steps=args.steps))
        out = subprocess.run([args.liggghts, "-in", "in.bench", "-log", "none"], cwd=work,
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, check=True).stdout.decode()
        rows = re.findall(r"^\s*\d+\s+([0-9.eE+-]+)\s+([0-9.eE+-]+)\s+([0-9.eE+-]+)\s+([0-9.eE+-]+)\s*$", out, re.M)
        rows = [[float(v) for v in r] for r in rows[-args.steps:]]
        sweeps = sum(r[0] for r in rows) / len(rows)
        contacts = sum(r[1] for r in rows) / len(rows)
        detect = sum(r[2] for r in rows) / len(rows)
        solve = sum(r[3] for r in rows) / len(rows)
        print(f"{n:8d} {contacts:9.0f} {sweeps:7.1f} {detect * 1e3:10.3f} {solve * 1e3:9.3f} "
              f"{detect / n * 1e6:16.2f} {solve / n * 1e6:15.2f}", flush=True)
        measured.append((n, detect, solve, contacts, sweeps))
    print("\nexponent b of time per step ∝ N^b between consecutive sizes (1: linear)")
    for (n1, d1, s1, *_), (n2, d2, s2, *_) in zip(measured, measured[1:]):
        b = [math.log(y / x) / math.log(n2 / n1) for x, y in ((d1, d2), (s1, s2), (d1 + s1, d2 + s2))]
        print(f"  {n1} -> {n2} grains: detection {b[0]:.2f}, solve {b[1]:.2f}, step {b[2]:.2f}")
    # The work itself: a small layer is mostly edge (fewer grain-grain points per grain,
    # the floor's cheap points a larger share), and Gauss-Seidel needs more sweeps on a
    # larger connected pile; per contact point and per contact update the cost is the code's.
    print("\nper unit of work: contact points per grain, detection per point, solve per point and sweep")
    for n, d, s_, c, sw in measured:
        print(f"  {n:6d} grains: {c / n:5.2f} points per grain, detection {d / c * 1e6:6.2f} us per point, "
              f"solve {s_ / (c * sw) * 1e9:6.1f} ns per point and sweep")
    for (n1, d1, s1, c1, w1), (n2, d2, s2, c2, w2) in zip(measured, measured[1:]):
        bd = math.log(d2 / d1) / math.log(c2 / c1)
        bs = math.log(s2 / s1) / math.log(c2 * w2 / (c1 * w1))
        print(f"  {n1} -> {n2} grains: detection ∝ points^{bd:.2f}, solve ∝ (points × sweeps)^{bs:.2f}")


if __name__ == "__main__":
    main()
