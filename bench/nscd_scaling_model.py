#!/usr/bin/python3
"""Benchmark and model: how fix nscd/polyhedra `solve distributed` would run a column on
many ranks, from what one, two and four ranks measure on the paper's Table 1 column.

    bench/nscd_scaling_model.py [--liggghts build/liggghts] [--relaxed DIR] [--time 2]
                                [--latency 2e-6] [--bandwidth 5e9]

Measured: the Table 1 column without wire (in.column -var wire 0, 915 grains; the relaxed
restart made as bench/nscd_distributed.py makes it, or --relaxed DIR), its wall phase for
--time time units with `solve distributed` on 1, 2 and 4 ranks (processors * * 1: the
container cut across x, then x and y; 4 ranks oversubscribed where the machine has fewer
cores, so their clocks are not used): per NSCD solve, the sweeps, the communication rounds
and reductions (rank 0), the values rank 0 sent, its own and ghost grains (LIGGGHTS'
Nlocal, Nghost), and on 1 and 2 ranks rank 0's NSCD time (detection + solve + scatter).

Model (docs/benchmarks.md, "A model for many ranks"): the grains fill a box of n grains per
unit volume; P ranks cut it into px x py x pz blocks a x b x c; a rank owns n a b c grains
and holds as ghosts those within a shell of width w on its cut sides,
n ((a + 2w)(b + 2w)(c + 2w) - a b c) for an inner block (the slowest rank sets the pace;
a dimension cut in two adds w, not 2w).
Per NSCD solve it computes for t_c (owned + lambda ghosts) seconds, and communicates
rounds(P) x (2 d latency) (LIGGGHTS sends each round to the neighbours of the d cut
dimensions one after the other, both ways) + values(P) x 8 bytes / bandwidth +
reductions(P) x 2 latency x log2 P. t_c is the one-rank time per grain; w the shell width
that gives the two-rank run its ghosts; lambda the cost of a ghost against an own grain that
gives the two-rank run its time; values(P) = rounds(P) x (values per round and ghost, from
two ranks) x ghosts; rounds and reductions per solve grow with log2 P as from 1 to 4 ranks.
The latency and bandwidth are assumptions (defaults: 2 us per message, 5 GB/s per rank, an
InfiniBand cluster), not measurements."""

import argparse
import math
import os
import re
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from nscd_distributed import PREP, ROOT, mpirun, relaxed_column  # noqa: E402
from nscd_memory import stat  # noqa: E402

# The Table 1 column as laid by in.column (R = 10, margin 1.5: the container 23 x 23 a_max;
# 915 grains, H0 about 6.4 a_max: docs/results.md)
TABLE1 = {"grains": 915, "width": 23.0, "height": 6.4}


def measure(run_dir, ranks, liggghts, phase):
    elapsed, text, rss = mpirun([], ranks, liggghts, run_dir, dict(phase, solve="distributed"),
                                os.path.join(run_dir, "log.txt"))
    clocks = re.search(r"NSCD clocks: gather \+ detection (\S+) s, solve (\S+) s, scatter \+ overlap projection (\S+) s",
                       text)
    counts = re.search(r"NSCD counts: solves (\S+), sweeps (\S+); solve distributed, rank 0: values sent (\S+), "
                       r"communication rounds (\S+), reductions (\S+)", text)
    if not clocks or not counts:
        raise SystemExit(f"no NSCD clocks or counts in {run_dir}/log.txt")
    solves, sweeps, values, rounds, reductions = (float(v) for v in counts.groups())
    # the wall phase's counts: the fix is made anew by the resumed run, so all of them
    return {"ranks": ranks, "elapsed": elapsed, "nscd": sum(float(c) for c in clocks.groups()), "solves": solves,
            "sweeps": sweeps / solves, "values": values / solves, "rounds": rounds / solves,
            "reductions": reductions / solves, "owned": stat(text, "Nlocal")[0], "ghosts": stat(text, "Nghost")[0],
            "rss": max(rss)}


class Model:
    def __init__(self, runs, column, latency, bandwidth):
        one, two, four = runs[1], runs[2], runs[4]
        self.latency, self.bandwidth = latency, bandwidth
        self.n = column["grains"] / (column["width"] ** 2 * column["height"])  # grains per unit volume
        self.t_c = one["nscd"] / one["solves"] / column["grains"]  # s per own grain and solve
        # two ranks: the container cut once across x, each rank a block width/2 x width x
        # height whose ghosts fill the shell on its cut face, n w b c
        b, c = column["width"], column["height"]
        self.w = two["ghosts"] / (self.n * b * c)
        self.lam = (two["nscd"] / two["solves"] / self.t_c - two["owned"]) / two["ghosts"]
        self.per_round_ghost = two["values"] / (two["rounds"] * two["ghosts"])
        # rounds and reductions per solve against log2 P (1 -> 4 ranks)
        self.rounds = (one["rounds"], (four["rounds"] - one["rounds"]) / 2.0)
        self.reductions = (one["reductions"], (four["reductions"] - one["reductions"]) / 2.0)
        self.sweeps = (one["sweeps"], (four["sweeps"] - one["sweeps"]) / 2.0)

    def grid(self, P, box):
        """the px x py x pz of P that makes the blocks most nearly cubes"""
        best = None
        for px in range(1, P + 1):
            if P % px:
                continue
            for py in range(1, P // px + 1):
                if (P // px) % py:
                    continue
                pz = P // px // py
                dims = (box[0] / px, box[1] / py, box[2] / pz)
                surface = dims[0] * dims[1] + dims[1] * dims[2] + dims[0] * dims[2]
                if best is None or surface < best[0]:
                    best = (surface, (px, py, pz), dims)
        return best[1], best[2]

    def step(self, P, box):
        (px, py, pz), (a, b, c) = self.grid(P, box)
        w = self.w
        owned = self.n * a * b * c
        # the shell on the cut sides only: one side where a dimension is cut in two, two for
        # an inner block where it is cut in more
        grow = [d + w * min(p - 1, 2) for d, p in ((a, px), (b, py), (c, pz))]
        ghosts = self.n * grow[0] * grow[1] * grow[2] - owned
        cut = sum(1 for p in (px, py, pz) if p > 1)
        lg = math.log2(P)
        rounds = self.rounds[0] + self.rounds[1] * lg
        reductions = self.reductions[0] + self.reductions[1] * lg
        compute = self.t_c * (owned + self.lam * ghosts)
        messages = rounds * 2 * cut * self.latency
        volume = rounds * self.per_round_ghost * ghosts * 8.0 / self.bandwidth
        reduce = reductions * 2.0 * self.latency * lg
        return {"grid": (px, py, pz), "owned": owned, "ghosts": ghosts, "compute": compute, "messages": messages,
                "volume": volume, "reduce": reduce, "total": compute + messages + volume + reduce}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--liggghts", default=os.path.join(ROOT, "build", "liggghts"))
    parser.add_argument("--relaxed", help="a folder with column_relaxed.restart and column_deposited.txt (no wire)")
    parser.add_argument("--time", type=float, default=2.0, help="time units of the wall phase measured")
    parser.add_argument("--latency", type=float, default=2e-6, help="s per message (assumed)")
    parser.add_argument("--bandwidth", type=float, default=5e9, help="bytes per s per rank (assumed)")
    args = parser.parse_args()
    liggghts = os.path.abspath(args.liggghts)
    work = relaxed_column(liggghts, args.relaxed, PREP, "nscd-scaling-model-")
    phase = dict(PREP, resume=1, t_end=PREP["t_relax"] + args.time)
    runs = {}
    for ranks in (1, 2, 4):
        run_dir = os.path.join(work, f"distributed-{ranks}")
        os.makedirs(run_dir)
        for name in ("column_relaxed.restart", "column_deposited.txt"):
            shutil.copy(os.path.join(work, name), run_dir)
        r = runs[ranks] = measure(run_dir, ranks, liggghts, phase)
        print(f"{ranks} rank(s): {r['solves']:.0f} solves; per solve {r['sweeps']:.1f} sweeps, {r['rounds']:.1f} rounds, "
              f"{r['reductions']:.1f} reductions, rank 0 sent {r['values']:.0f} values; own {r['owned']:.0f} and ghost "
              f"{r['ghosts']:.0f} grains per rank; rank 0's NSCD {r['nscd']:.2f} s "
              f"({1e3 * r['nscd'] / r['solves']:.2f} ms per solve){' (oversubscribed: not used)' if ranks > 2 else ''}",
              flush=True)
    m = Model(runs, TABLE1, args.latency, args.bandwidth)
    print(f"\nfitted: t_c {1e6 * m.t_c:.1f} us per own grain and solve, ghost shell w {m.w:.2f} a_max, a ghost costs "
          f"{m.lam:.2f} of an own grain, {m.per_round_ghost:.1f} values per ghost and round; per solve "
          f"{m.sweeps[0]:.1f} + {m.sweeps[1]:.1f} log2 P sweeps, {m.rounds[0]:.1f} + {m.rounds[1]:.1f} log2 P rounds, "
          f"{m.reductions[0]:.1f} + {m.reductions[1]:.1f} log2 P reductions; latency {1e6 * args.latency:.1f} us, "
          f"bandwidth {args.bandwidth / 1e9:.1f} GB/s (assumed)")
    two = m.step(2, (TABLE1["width"], TABLE1["width"], TABLE1["height"]))
    print(f"check, the Table 1 column on 2 ranks: model {1e3 * two['total']:.2f} ms per solve (its fit), measured "
          f"{1e3 * runs[2]['nscd'] / runs[2]['solves']:.2f} ms")
    n = TABLE1["grains"] / (TABLE1["width"] ** 2 * TABLE1["height"])
    # columns of the Table 1 grains at its packing, as grains and height (side = their square base)
    columns = [("Table 1", 915, 6.4), ("10x: 70 layers of the Table 1 column's", 9150, 64.0),
               ("100x: 70 layers of 10x the Table 1 column's", 91500, 64.0)]
    for name, grains, height in columns:
        side = math.sqrt(grains / (n * height))
        box = (side, side, height)
        one = m.step(1, box)
        name = f"{name} ({grains} grains, {side:.0f} x {side:.0f} x {height:.1f} a_max)"
        print(f"\n{name}: model per NSCD solve")
        print(f"{'ranks':>6s} {'grid':>10s} {'own':>8s} {'ghosts':>8s} {'compute':>10s} {'latency':>10s} "
              f"{'volume':>10s} {'reduce':>10s} {'total':>10s} {'speed-up':>9s} {'efficiency':>10s}")
        for P in (1, 2, 4, 16, 64, 256):
            s = m.step(P, box)
            if s["owned"] < 1.0:
                continue
            print(f"{P:6d} {'x'.join(str(p) for p in s['grid']):>10s} {s['owned']:8.0f} {s['ghosts']:8.0f} "
                  f"{1e3 * s['compute']:8.2f}ms {1e3 * s['messages']:8.2f}ms {1e3 * s['volume']:8.3f}ms "
                  f"{1e3 * s['reduce']:8.3f}ms {1e3 * s['total']:8.2f}ms {one['total'] / s['total']:9.1f} "
                  f"{one['total'] / s['total'] / P:10.2f}")
    print(f"(runs in {work})")


if __name__ == "__main__":
    main()
