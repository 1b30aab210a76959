#!/usr/bin/python3
"""Benchmark: fix nscd/polyhedra `solve replicated` against `solve distributed` on the
paper's Table 1 column (input_scripts/in.column: 915 grains; without its wire unless
--wire), its wall phase continued from column_relaxed.restart for --time time units, on 1
and 2 ranks, the runs alternated (--repeat rounds): the wall time of the run, the NSCD
clocks of rank 0 (gather + detection, solve, scatter + overlap projection), the stick
solves (tried, kept, and the factorisations, or with `solve distributed` the
conjugate-gradient iterations, they made), the peak resident memory of each rank, the
column's height at the end, and the speed-ups side by side.

    bench/nscd_distributed.py [--liggghts build/liggghts] [--wire] [--relaxed DIR] [--time 5] [--repeat 2]
        [--var NAME VALUE ...] [--ranks 1 2]

Without --relaxed the restart is made first (in.column with each layer, and with --wire
each wire layer, deposited for 1.5 time units and relaxed for 1 more: a few minutes on 2
ranks) in a temporary folder; --relaxed DIR reuses the column_relaxed.restart and
column_deposited.txt of a folder made with the same --wire. When DIR is the folder of a
whole in.column run (it holds column_walls.txt: H0 and the time the walls started), the
window starts at that time and the run's own deck variables are to be given again with
--var (e.g. -var R 7 -var nlayers 10 ... for a column not at the defaults); --var is passed
to every run."""

import argparse
import os
import re
import shutil
import subprocess
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
PREP = {"wire": 0, "t_layer": 1.5, "t_wire": 0, "t_relax": 14, "t_end": 14.01}
PREP_WIRE = {"wire": 1, "t_layer": 1.5, "t_wire": 1.5, "t_relax": 22, "t_end": 22.01}


def mpirun(args, ranks, liggghts, workdir, variables, log):
    # each rank's peak resident memory into rss.<rank> (Open MPI names the rank in the environment)
    line = ["/usr/bin/time", "-f", "%M", "-o", "rss.$OMPI_COMM_WORLD_RANK", liggghts, "-in",
            os.path.join(ROOT, "input_scripts", "in.column"), "-var", "root", ROOT]
    for key, value in variables.items():
        line += ["-var", key, str(value)]
    cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks), "sh", "-c",
           " ".join(f"'{w}'" if not w.startswith("rss.") else w for w in line)]
    start = time.time()
    with open(log, "w") as out:
        proc = subprocess.run(cmd + args, cwd=workdir, stdout=out, stderr=subprocess.STDOUT)
    elapsed = time.time() - start
    text = open(log).read()
    if proc.returncode != 0:
        raise SystemExit(f"run failed ({log}):\n{text[-3000:]}")
    rss = [int(open(os.path.join(workdir, f"rss.{r}")).read().split()[-1]) / 1024.0 for r in range(ranks)]
    return elapsed, text, rss


def relaxed_column(liggghts, relaxed, prep, prefix):
    """A temporary folder holding column_relaxed.restart and column_deposited.txt: copied
    from the folder `relaxed`, or made there by in.column with the variables `prep` on 2 ranks."""
    work = tempfile.mkdtemp(prefix=prefix)
    if relaxed:
        for name in ("column_relaxed.restart", "column_deposited.txt"):
            shutil.copy(os.path.join(relaxed, name), work)
    else:
        print(f"making the relaxed column in {work} ...", flush=True)
        mpirun([], 2, liggghts, work, prep, os.path.join(work, "prep.log"))
    return work


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--liggghts", default=os.path.join(ROOT, "build", "liggghts"))
    parser.add_argument("--wire", action="store_true", help="the column with its wire (default: without)")
    parser.add_argument("--relaxed", help="a folder with column_relaxed.restart and column_deposited.txt")
    parser.add_argument("--time", type=float, default=5.0, help="time units of the wall phase timed")
    parser.add_argument("--repeat", type=int, default=2)
    parser.add_argument("--var", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"),
                        help="a deck variable for every run (repeatable)")
    parser.add_argument("--ranks", type=int, nargs="+", default=[1, 2], help="the rank counts timed (1 and 2)")
    args = parser.parse_args()
    liggghts = os.path.abspath(args.liggghts)
    prep = PREP_WIRE if args.wire else PREP
    work = relaxed_column(liggghts, args.relaxed, prep, "nscd-distributed-")
    walls_record = os.path.join(args.relaxed, "column_walls.txt") if args.relaxed else ""
    if walls_record and os.path.exists(walls_record):
        # a whole run's relaxed column: its walls started at the record's second number
        t_start = float(open(walls_record).read().split()[1])
        phase = dict(wire=1 if args.wire else 0, resume=1, t_relax=t_start, t_end=t_start + args.time)
    else:
        phase = dict(prep, resume=1, t_end=prep["t_relax"] + args.time)
    phase.update(dict(args.var))
    results = {}
    for round_ in range(args.repeat):
        for solve in ("replicated", "distributed"):
            for ranks in args.ranks:
                run_dir = os.path.join(work, f"{solve}-{ranks}-{round_}")
                os.makedirs(run_dir)
                for name in ("column_relaxed.restart", "column_deposited.txt"):
                    shutil.copy(os.path.join(work, name), run_dir)
                elapsed, text, rss = mpirun([], ranks, liggghts, run_dir, dict(phase, solve=solve),
                                            os.path.join(run_dir, "log.txt"))
                clocks = re.search(r"NSCD clocks: gather \+ detection (\S+) s, solve (\S+) s, scatter \+ overlap "
                                   r"projection (\S+) s", text)
                final = re.search(r"in.column final: H_n = (\S+)", text)
                stick = re.search(r"in.column NSCD stick solves: tried (\S+), kept (\S+), factorisations "
                                  r"\(solve distributed: CG iterations\) (\S+)", text)
                entry = results.setdefault((solve, ranks), [])
                entry.append((elapsed, *[float(c) for c in clocks.groups()], max(rss), float(final.group(1))))
                print(f"{solve:11s} {ranks} rank(s): {elapsed:6.1f} s wall, detection {entry[-1][1]:6.2f} s, solve "
                      f"{entry[-1][2]:6.2f} s, scatter {entry[-1][3]:5.2f} s, peak RSS per rank {max(rss):6.1f} MiB, "
                      f"H_n {entry[-1][5]:.6f}, stick solves tried {stick.group(1)}, kept {stick.group(2)}, "
                      f"{'CG iterations' if solve == 'distributed' else 'factorisations'} {stick.group(3)}", flush=True)
    best = {key: min(values) for key, values in results.items()}
    given = "".join(f" -var {name} {value}" for name, value in args.var)
    print(f"\nin.column{given} {'with' if args.wire else 'without'} wire, wall phase {args.time} time units from the "
          f"relaxed restart, best of {args.repeat}:")
    print(f"{'':24s} {'wall s':>8s} {'detect s':>9s} {'solve s':>8s} {'NSCD s':>8s} {'RSS MiB':>8s}")
    for (solve, ranks), b in sorted(best.items()):
        print(f"{solve + ' ' + str(ranks) + ' rank(s)':24s} {b[0]:8.1f} {b[1]:9.2f} {b[2]:8.2f} {b[1] + b[2]:8.2f} "
              f"{b[4]:8.1f}")
    for solve in ("replicated", "distributed"):
        if (solve, 1) not in best or (solve, 2) not in best:
            continue
        one, two = best[(solve, 1)], best[(solve, 2)]
        print(f"{solve}: 2 ranks against 1: wall {one[0] / two[0]:.2f}x, NSCD (detection + solve) "
              f"{(one[1] + one[2]) / (two[1] + two[2]):.2f}x")
    for ranks in args.ranks:
        rep, dist = best[("replicated", ranks)], best[("distributed", ranks)]
        print(f"{ranks} rank(s), distributed against replicated: wall {rep[0] / dist[0]:.2f}x, NSCD "
              f"{(rep[1] + rep[2]) / (dist[1] + dist[2]):.2f}x")
    print(f"(runs in {work})")


if __name__ == "__main__":
    main()
