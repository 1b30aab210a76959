#!/usr/bin/python3
"""Benchmark: the peak resident memory per rank of fix nscd/polyhedra on a large pile,
`solve replicated` (every rank holds every grain) against `solve distributed` (each rank
its own grains and their ghosts), on 1, 2 and 4 ranks (oversubscribed where the machine has
fewer cores: memory, not time, is measured).

    bench/nscd_memory.py [--liggghts build/liggghts] [--grains 10000] [--steps 50] [--ranks 1 2 4]

The pile: --grains random Table 1 grains (create_grains, one shape each) placed apart in a
slab 20 a_max high whose width gives their bounding boxes (2.2 x 1.8 x 1.4 a_max) a packing
fraction of 0.1, above a frictional floor; each run reads the same data file and takes
--steps NSCD steps of 1e-3 (the grains falling, those placed closest already in contact).
Per run: the peak resident memory of every rank (/usr/bin/time %M), the grains each rank
owns and its ghosts (LIGGGHTS' Nlocal and Nghost), the contact points, and the memory of
the largest rank against the one-rank run (ideal: 1/P plus the ghosts' share). Two more
runs on one rank split the memory: LIGGGHTS with an empty box (its own share), and the
grains read without the fix (the shape library and the per-atom arrays)."""

import argparse
import math
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

MAKE = """
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
region          box block -{half} {half} -{half} {half} 0 {height}
create_box      1 box
region          fill block -{inner} {inner} -{inner} {inner} 0.5 {fill_top}
create_grains   1 {grains} random fill seed 4242
write_data      grains.data
grain_shapes    write grains.shapes
"""

EMPTY = """
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
region          box block -1 1 -1 1 -1 1
create_box      1 box
run             0
"""

# the grains read (the shape library and the per-atom arrays)
GRAINS = """
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
processors      * * 1
grain_shapes    read grains.shapes
read_data       grains.data
"""

READ = GRAINS + "run             0\n"

STEP = GRAINS + """fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra solve {solve} wall 0 0 0 0 0 1
timestep        1e-3
thermo_style    custom step f_nscd[3]
thermo          {steps}
run             {steps}
"""


def launch(liggghts, ranks, workdir, deck, log):
    line = ["/usr/bin/time", "-f", "%M", "-o", "rss.$OMPI_COMM_WORLD_RANK", liggghts, "-in", deck, "-log", "none"]
    cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks), "sh", "-c", " ".join(line)]
    with open(log, "w") as out:
        proc = subprocess.run(cmd, cwd=workdir, stdout=out, stderr=subprocess.STDOUT)
    text = open(log).read()
    if proc.returncode != 0:
        sys.exit(f"run failed ({log}):\n{text[-3000:]}")
    rss = [int(open(os.path.join(workdir, f"rss.{r}")).read().split()[-1]) / 1024.0 for r in range(ranks)]
    for r in range(ranks):
        os.remove(os.path.join(workdir, f"rss.{r}"))
    return text, rss


def stat(text, name):
    m = re.search(rf"^{name}:\s+([\d.e+]+) ave ([\d.e+]+) max", text, re.M)
    return (float(m.group(1)), float(m.group(2))) if m else (float("nan"), float("nan"))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--liggghts", default=os.path.join(ROOT, "build", "liggghts"))
    parser.add_argument("--grains", type=int, default=10000)
    parser.add_argument("--steps", type=int, default=50)
    parser.add_argument("--ranks", type=int, nargs="+", default=[1, 2, 4])
    args = parser.parse_args()
    liggghts = os.path.abspath(args.liggghts)
    work = tempfile.mkdtemp(prefix="nscd-memory-")
    # bounding boxes of the Table 1 grains (2.2 x 1.8 x 1.4 a_max at most) at about 0.1 of the fill
    fill_height = 20.0
    inner = math.sqrt(args.grains * 2.2 * 1.8 * 1.4 / 0.1 / fill_height) / 2
    variables = dict(half=inner + 3, inner=inner, height=2 * fill_height + 5, fill_top=fill_height, grains=args.grains)
    with open(os.path.join(work, "make.in"), "w") as f:
        f.write(MAKE.format(**variables))
    made = subprocess.run([liggghts, "-in", "make.in", "-log", "none"], cwd=work, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True)
    if made.returncode != 0:
        sys.exit(made.stdout[-3000:])
    print(f"{args.grains} grains in a slab {2 * inner:.1f} a_max wide and {fill_height:.0f} high ({work})")
    for name, deck in (("an empty box", EMPTY), ("the grains read, no fix", READ)):
        path = os.path.join(work, "split.in")
        with open(path, "w") as f:
            f.write(deck)
        _, rss = launch(liggghts, 1, work, path, os.path.join(work, "split.log"))
        print(f"one rank, {name}: peak RSS {rss[0]:.1f} MiB", flush=True)
    rows = []
    for solve in ("replicated", "distributed"):
        for ranks in args.ranks:
            deck = os.path.join(work, f"step_{solve}.in")
            with open(deck, "w") as f:
                f.write(STEP.format(solve=solve, steps=args.steps))
            text, rss = launch(liggghts, ranks, work, deck, os.path.join(work, f"{solve}_{ranks}.log"))
            nlocal, nghost = stat(text, "Nlocal"), stat(text, "Nghost")
            points = re.findall(rf"^\s*{args.steps}\s+([\d.e+]+)\s*$", text, re.M)
            rows.append((solve, ranks, max(rss), sum(rss), nlocal, nghost, points[-1] if points else "?"))
            print(f"{solve:11s} {ranks} rank(s): peak RSS per rank {' '.join(f'{v:.1f}' for v in rss)} MiB, "
                  f"grains per rank {nlocal[0]:.0f} (max {nlocal[1]:.0f}), ghosts {nghost[0]:.0f} (max {nghost[1]:.0f}), "
                  f"contact points {rows[-1][6]}", flush=True)
    print(f"\n{'':24s} {'max RSS MiB':>11s} {'sum MiB':>8s} {'vs 1 rank':>9s} {'owned':>7s} {'ghosts':>7s}")
    for solve, ranks, top, total, nlocal, nghost, _ in rows:
        one = next(r[2] for r in rows if r[0] == solve and r[1] == min(args.ranks))
        print(f"{solve + ', ' + str(ranks) + ' rank(s)':24s} {top:11.1f} {total:8.1f} {top / one:9.2f} "
              f"{nlocal[1]:7.0f} {nghost[1]:7.0f}")


if __name__ == "__main__":
    main()
