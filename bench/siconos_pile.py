#!/usr/bin/python3
"""Benchmark: our Gauss-Seidel against Siconos numerics' fc3d_nsgs on the contact problems
of a settled pile of 915 grains (the paper's N_p), written by fix nscd/polyhedra
(write_problems), converted to FCLib HDF5 files and solved cold by both (bench/fclib_nscd).

    bench/siconos_pile.py [--liggghts build/liggghts] [--fclib-nscd build/bench/fclib_nscd]
                          [--grains 915] [--settle 10000] [--relax 4000] [--every 7000]
                          [--keep DIR]

The pile: Table 1 grains (a in [0.8, 1], b/a 0.8, c/a 0.6, N_v 20, r_p 0.1, rho_p 1.5) in
layers of up to 221 (create_grains layer, two staggered lattices 2 a_max apart) 4.6 a_max
apart in a 22 x 22 box, frictional floor (mu 0.5), frictionless side walls, g = 1,
h = 1e-3, deposited for --settle steps, then relaxed with `damping 2` for --relax steps.
The problems of every --every steps are written; the last two are compared (by default
steps 7000, the pile still moving, and 14000, settled). For each: Siconos with its defaults
(tolerance 1e-4, 1000 iterations), then our solver until it reaches Siconos' final
error, in several orders and stopping measures; the ratio is our time over Siconos'."""

import argparse
import glob
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
region          box block -12 12 -12 12 0 {top}
create_box      1 box
region          inside block -11 11 -11 11 0 {top}
{layers}
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra write_problems {every} problem_*.txt wall 0 0 0 0 0 1 &
                wall -12 0 0 1 0 0 wall_friction 0 wall 12 0 0 -1 0 0 wall_friction 0 &
                wall 0 -12 0 0 1 0 wall_friction 0 wall 0 12 0 0 -1 0 wall_friction 0
timestep        1e-3
compute         rot all grain/rotation
compute         ket all ke
variable        ke equal c_ket+c_rot[1]
compute         zmax all reduce max z
thermo_style    custom step f_nscd[1] f_nscd[3] f_nscd[4] v_ke c_zmax
thermo          1000
run             {settle}
fix_modify      nscd damping 2
run             {relax}
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--liggghts", default=os.path.join(HERE, "..", "build", "liggghts"))
    parser.add_argument("--fclib-nscd", default=os.path.join(HERE, "..", "build", "bench", "fclib_nscd"))
    parser.add_argument("--grains", type=int, default=915)
    parser.add_argument("--settle", type=int, default=10000)
    parser.add_argument("--relax", type=int, default=4000)
    parser.add_argument("--every", type=int, default=7000)
    parser.add_argument("--keep", help="directory for the deck, problems and FCLib files")
    args = parser.parse_args()
    work = args.keep or tempfile.mkdtemp(prefix="wiregrain-siconos-")
    for hdf5 in pile_problems(args.liggghts, args.fclib_nscd, work, args.grains, args.settle, args.relax,
                              args.every):
        result = subprocess.run([args.fclib_nscd, "solve", hdf5, "--repeat", "1"],
                                stdout=subprocess.PIPE, check=True).stdout.decode()
        print(result)


def pile_problems(liggghts, fclib_nscd, work, grains=915, settle=10000, relax=4000, every=7000):
    """Runs the pile deck in `work` and returns the FCLib files of the last two problems
    written (the pile still moving, and settled); prints the deck's thermo table."""
    os.makedirs(work, exist_ok=True)
    layers, left, z, seed = [], grains, 1.0, 4242
    while left > 0:
        n = min(221, left)
        layers.append(f"create_grains   1 {n} layer inside {z} seed {seed}")
        left, z, seed = left - n, z + 4.6, seed + 2
    with open(os.path.join(work, "in.pile"), "w") as f:
        f.write(DECK.format(top=z + 4, layers="\n".join(layers), every=every, settle=settle, relax=relax))
    out = subprocess.run([liggghts, "-in", "in.pile", "-log", "none"], cwd=work,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT).stdout.decode()
    tables = re.findall(r"^\s*Step .*?(?=^Loop time)", out, re.M | re.S)
    print(f"pile of {grains} grains in {work}:")
    print("".join(tables) if tables else out[-3000:], flush=True)
    problems = sorted(glob.glob(os.path.join(work, "problem_*.txt")),
                      key=lambda p: int(re.search(r"problem_(\d+)", p).group(1)))[-2:]
    files = []
    for text in problems:
        hdf5 = text[:-4] + ".hdf5"
        subprocess.run([fclib_nscd, "convert", text, hdf5], check=True, stdout=subprocess.DEVNULL)
        files.append(hdf5)
    return files


if __name__ == "__main__":
    main()
