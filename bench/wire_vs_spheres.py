#!/usr/bin/python3
"""Benchmark: cost of one wire bead-step (fix wire/elastic + fix nve/gear) against one
stock LIGGGHTS sphere-step (pair gran hooke/history + fix nve/sphere) at the same count.

    bench/wire_vs_spheres.py [--liggghts build/liggghts] [--steps 2000] [--np 1]

The wire is one helix of 4242 segments (the paper's N_w, Table 1 material); the spheres
sit on a simple cubic lattice, each touching its six neighbours, so every step evaluates
about 3 contacts per sphere. Both run in this invocation, one after the other, and the
script prints time per particle-step for each and their ratio (target: <= 1)."""

import argparse
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))

WIRE = """
units           lj
atom_style      wire
boundary        f f f
region          box block -12 12 -12 12 -2 12
create_box      1 box
create_wire     1 loop 0 0 0 10 {turns} 0.5 segment 0.2
fix             elastic all wire/elastic
fix             integr all nve/gear
timestep        1e-4
thermo          {steps}
run             {warmup}
run             {steps}
"""

SPHERES = """
units           si
atom_style      granular
atom_modify     map array
boundary        p p p
newton          off
communicate     single vel yes
region          box block 0 {side_x} 0 {side_y} 0 {side_z} units box
create_box      1 box
neighbor        0.0002 bin
neigh_modify    delay 0
fix  m1 all property/global youngsModulus peratomtype 1.0e7
fix  m2 all property/global poissonsRatio peratomtype 0.3
fix  m3 all property/global coefficientRestitution peratomtypepair 1 0.5
fix  m4 all property/global coefficientFriction peratomtypepair 1 0.5
fix  m5 all property/global characteristicVelocity scalar 1.0
pair_style      gran model hooke tangential history
pair_coeff      * *
timestep        1.0e-6
lattice         sc 0.000999
create_atoms    1 box
set             group all diameter 0.001 density 2500
fix             integr all nve/sphere
thermo          {steps}
run             {warmup}
run             {steps}
"""


def loop_time(liggghts, text, np_ranks):
    work = tempfile.mkdtemp(prefix="wiregrain-bench-")
    with open(os.path.join(work, "in.bench"), "w") as f:
        f.write(text)
    cmd = [liggghts, "-in", "in.bench", "-log", "none"]
    if np_ranks > 1:
        cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(np_ranks)] + cmd
    out = subprocess.run(cmd, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         check=True).stdout.decode()
    times = re.findall(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms", out)
    seconds, steps, atoms = times[-1]
    return float(seconds), int(steps), int(atoms)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--liggghts", default=os.path.join(HERE, "..", "build", "liggghts"))
    parser.add_argument("--steps", type=int, default=2000)
    parser.add_argument("--np", type=int, default=1)
    args = parser.parse_args()

    segments = 4242
    turns = segments * 0.2 / (2 * 3.141592653589793 * 10) + 0.01
    wire = loop_time(args.liggghts, WIRE.format(turns=turns, steps=args.steps, warmup=100), args.np)
    # a 17 x 17 x 15 lattice: 4335 spheres, the count closest to 4243 beads on a cube-ish grid
    d = 0.000999
    spheres = loop_time(args.liggghts, SPHERES.format(side_x=17 * d, side_y=17 * d, side_z=15 * d,
                                                      steps=args.steps, warmup=100), args.np)
    per_bead = wire[0] / (wire[1] * wire[2])
    per_sphere = spheres[0] / (spheres[1] * spheres[2])
    print(f"ranks: {args.np}, steps: {args.steps}")
    print(f"wire    : {wire[2]:6d} beads   {wire[0]:8.3f} s  {per_bead * 1e9:8.1f} ns per bead-step   "
          f"{1.0 / per_bead:12.4g} bead-steps/s")
    print(f"spheres : {spheres[2]:6d} spheres {spheres[0]:8.3f} s  {per_sphere * 1e9:8.1f} ns per sphere-step "
          f"{1.0 / per_sphere:12.4g} sphere-steps/s")
    print(f"ratio bead-step / sphere-step: {per_bead / per_sphere:.3f}  (target <= 1)")


if __name__ == "__main__":
    sys.exit(main())
