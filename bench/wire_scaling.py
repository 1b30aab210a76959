#!/usr/bin/python3
"""Benchmark: time per step of a Table 1 wire against its number of segments (1e3, 1e4, 1e5
by default), one size after the other in one invocation, with the exponent b of time ∝ n^b
between consecutive sizes (1: linear), in total and by part (fix wire/elastic + fix
nve/gear, pair wire/contact + its neighbour lists, the floor).

    bench/wire_scaling.py [--liggghts build/liggghts] [--segments 1000 10000 100000] [--steps 200] [--np 1]

The wire of each size is a coil of radius 5 (157 segments of l_w = 0.2 per turn) whose
turns touch (pitch 0.21 = 2 r_w + 0.01: every segment has neighbours in the turns above
and below), standing on a frictional floor under gravity: the same contacts per segment
at every size. Each size is first run for 500 steps (the coil settles onto its contacts),
then timed for --steps steps (LIGGGHTS' timers, modify_timing on)."""

import argparse
import math
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from wire_grain_contacts import timers  # noqa: E402  (LIGGGHTS' timer lines of one run)

RADIUS, SEGMENT, PITCH = 5.0, 0.2, 0.21

DECK = """
units           lj
atom_style      wire
boundary        f f f
newton          off
region          box block -7 7 -7 7 -1 {height}
create_box      1 box
create_wire     1 loop 0 0 0.11 {radius} {turns} {pitch}
pair_style      wire/contact
pair_coeff      * *
neighbor        0.1 bin
neigh_modify    delay 0
fix             elastic all wire/elastic
fix             integr all nve/gear
fix             gravity all gravity 1.0 vector 0 0 -1
fix             floor all wire/wall plane 0 0 0 0 0 1
timestep        1e-4
thermo          500
run             500
modify_timing   on
run             {steps}
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--liggghts", default=os.path.join(HERE, "..", "build", "liggghts"))
    parser.add_argument("--segments", type=int, nargs="+", default=[1000, 10000, 100000])
    parser.add_argument("--steps", type=int, default=200)
    parser.add_argument("--np", type=int, default=1)
    args = parser.parse_args()
    per_turn = 2 * math.pi * RADIUS / SEGMENT
    print(f"{'segments':>9} {'ms/step':>9} {'elastic':>8} {'contacts':>9} {'floor':>7} {'us/segment':>11}")
    measured = []
    for n in args.segments:
        turns = n / per_turn
        work = tempfile.mkdtemp(prefix="wiregrain-wire-scaling-")
        with open(os.path.join(work, "in.bench"), "w") as f:
            f.write(DECK.format(radius=RADIUS, turns=f"{turns:.4f}", pitch=PITCH,
                                height=f"{turns * PITCH + 5:.2f}", steps=args.steps))
        cmd = [args.liggghts, "-in", "in.bench", "-log", "none"]
        if args.np > 1:
            cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(args.np)] + cmd
        out = subprocess.run(cmd, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT).stdout.decode()
        runs = list(re.finditer(r"Loop time of (\S+) on \d+ procs for (\d+) steps with (\d+) atoms", out))
        if "ERROR" in out or len(runs) < 2:
            sys.exit(f"the {n}-segment coil failed in {work}:\n" + out[-3000:])
        seconds, steps, beads = float(runs[-1].group(1)), int(runs[-1].group(2)), int(runs[-1].group(3))
        t = timers(out[runs[-1].start():])
        fix = {k[4:]: v for k, v in t.items() if k.startswith("fix ")}
        parts = (fix.get("elastic", 0.0) + fix.get("integr", 0.0), t.get("Pair", 0.0) + t.get("Neigh", 0.0),
                 fix.get("floor", 0.0))
        segments = beads - 1
        step = seconds / steps
        print(f"{segments:9d} {1e3 * step:9.3f} {1e3 * parts[0] / steps:8.3f} {1e3 * parts[1] / steps:9.3f} "
              f"{1e3 * parts[2] / steps:7.3f} {1e6 * step / segments:11.3f}", flush=True)
        measured.append((segments, step, parts))
    print("\nexponent b of time per step ∝ n^b between consecutive sizes (1: linear)")
    for (n1, t1, p1), (n2, t2, p2) in zip(measured, measured[1:]):
        b = lambda x, y: math.log(y / x) / math.log(n2 / n1) if x > 0 and y > 0 else float("nan")
        print(f"  {n1} -> {n2} segments: step {b(t1, t2):.2f}, elastic + Gear {b(p1[0], p2[0]):.2f}, "
              f"wire-wire contacts {b(p1[1], p2[1]):.2f}, floor {b(p1[2], p2[2]):.2f}")


if __name__ == "__main__":
    main()
