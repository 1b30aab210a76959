#!/usr/bin/python3
"""Benchmark and model: how fix nscd/polyhedra `solve distributed` would run a column on
many ranks, from what one, two and four ranks measure on the paper's Table 1 column.

    bench/nscd_scaling_model.py [--liggghts build/liggghts] [--relaxed DIR] [--time 2]
                                [--latency 2e-6] [--bandwidth 5e9] [--save FILE | --counts FILE]

Measured: the Table 1 column without wire (in.column -var wire 0, 915 grains; the relaxed
restart made as bench/nscd_distributed.py makes it, or --relaxed DIR), its wall phase for
--time time units with `solve distributed` on 1, 2 and 4 ranks (processors * * 1: the
container cut across x, then x and y; 4 ranks oversubscribed where the machine has fewer
cores, so their clocks are not used): per NSCD solve, the sweeps, the communication rounds
and reductions (rank 0), the values rank 0 sent, its own and ghost grains (LIGGGHTS'
Nlocal, Nghost), and on 1 and 2 ranks rank 0's NSCD time (detection + solve + scatter);
and one rank with `order coloured` (the sweep colour by colour of the contact graph): its
sweeps per solve against the forward order's and its colours per solve. --save FILE keeps
these counts as JSON; --counts FILE models from such a file without running anything
(bench/nscd_scaling_counts.json: the counts of docs/benchmarks.md).

Model (docs/benchmarks.md, "A model for many ranks"): the grains fill a box of n grains per
unit volume; P ranks cut it into px x py x pz blocks a x b x c; a rank owns n a b c grains
and holds as ghosts those within a shell of width w on its cut sides,
n ((a + 2w)(b + 2w)(c + 2w) - a b c) for an inner block (the slowest rank sets the pace;
a dimension cut in two adds w, not 2w).
Per NSCD solve of s(P) sweeps it computes for t_c s(P) (owned + lambda ghosts) seconds,
and communicates rounds(P) x (2 d latency) (LIGGGHTS sends each round to the neighbours of
the d cut dimensions one after the other, both ways) + values(P) x 8 bytes / bandwidth +
reductions(P) x 2 latency x log2 P. t_c is the one-rank time per own grain and sweep; w the
shell width that gives the two-rank run its ghosts; lambda the cost of a ghost against an
own grain that gives the two-rank run its time at its sweeps (held at 0 where the fit falls
below); rounds(P) and reductions(P) are one rank's per sweep times s(P), values(P) =
rounds(P) x (values per round and ghost, from two ranks) x ghosts. The sweeps per solve grow
with the ghosts per own grain, s(P) = s_1 (1 + kappa ghosts / own), kappa fitted to the 2
and 4 ranks' sweeps (Gauss-Seidel within a rank, Jacobi across: the more of a rank's grains
touch ghosts, the more Jacobi-like the sweep).

Two sweeps are modelled: (a) the one `solve distributed` makes, Gauss-Seidel within a rank
and Jacobi across (mass splitting: one exchange per sweep, the sweeps growing with P as
measured); (b) the colour-by-colour sweep a decomposition-independent solve would make: the
sweeps of one rank's `order coloured` run on any P, one exchange (two rounds) per colour
instead of one per sweep, the other rounds and the reductions per sweep as one rank's, and
a colouring of the step's contacts first (two rounds and a reduction per colour, as a
distributed greedy colouring in a fixed order needs). (b) leaves out the waits of ranks
whose share of a colour is larger than their neighbours' (one per colour), so its figures
are a floor.
The latency and bandwidth are assumptions (defaults: 2 us per message, 5 GB/s per rank, an
InfiniBand cluster), not measurements."""

import argparse
import json
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
    counts = re.search(r"NSCD counts: solves ([^,]+), sweeps ([^;]+); solve distributed, rank 0: values sent ([^,]+), "
                       r"communication rounds ([^,]+), reductions ([^;\s]+); order coloured: colours (\S+)", text)
    if not clocks or not counts:
        raise SystemExit(f"no NSCD clocks or counts in {run_dir}/log.txt")
    solves, sweeps, values, rounds, reductions, colours = (float(v) for v in counts.groups())
    # the wall phase's counts: the fix is made anew by the resumed run, so all of them
    return {"ranks": ranks, "elapsed": elapsed, "nscd": sum(float(c) for c in clocks.groups()), "solves": solves,
            "sweeps": sweeps / solves, "values": values / solves, "rounds": rounds / solves, "colours": colours / solves,
            "reductions": reductions / solves, "owned": stat(text, "Nlocal")[0], "ghosts": stat(text, "Nghost")[0],
            "rss": max(rss)}


class Model:
    def __init__(self, runs, column, latency, bandwidth):
        one, two, four = runs["1"], runs["2"], runs["4"]
        self.latency, self.bandwidth = latency, bandwidth
        self.n = column["grains"] / (column["width"] ** 2 * column["height"])  # grains per unit volume
        # s per own grain and sweep (one rank)
        self.t_c = one["nscd"] / one["solves"] / column["grains"] / one["sweeps"]
        # two ranks: the container cut once across x, each rank a block width/2 x width x
        # height whose ghosts fill the shell on its cut face, n w b c
        b, c = column["width"], column["height"]
        self.w = two["ghosts"] / (self.n * b * c)
        # the sweeps grow with the share of a rank's neighbours that are ghosts (Jacobi
        # across ranks): s(P) = s_1 (1 + kappa ghosts / own), kappa fitted to 2 and 4 ranks
        # (least squares through the origin)
        self.sweeps_one = one["sweeps"]
        xs = [r["ghosts"] / r["owned"] for r in (two, four)]
        ys = [r["sweeps"] / one["sweeps"] - 1.0 for r in (two, four)]
        self.kappa = sum(x * y for x, y in zip(xs, ys)) / sum(x * x for x in xs)
        # a ghost's cost against an own grain's at the same sweeps (the pairs are shared
        # out by ownership, so near 0; held at 0 where the fit falls below)
        self.lam = max(0.0, (two["nscd"] / two["solves"] / (self.t_c * two["sweeps"]) - two["owned"]) / two["ghosts"])
        self.per_round_ghost = two["values"] / (two["rounds"] * two["ghosts"])
        # rounds and reductions per sweep (one rank; 2 and 4 ranks make as many per sweep)
        self.rounds_per_sweep = one["rounds"] / one["sweeps"]
        self.reductions_per_sweep = one["reductions"] / one["sweeps"]
        # (b): one rank's coloured sweep
        coloured = runs["coloured"]
        self.coloured_sweeps = one["sweeps"] * coloured["sweeps_ratio"]
        self.colours = coloured["colours"]

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

    def step(self, P, box, sweep="a"):
        """one NSCD solve on P ranks with sweep (a) or (b) (module help)"""
        (px, py, pz), (a, b, c) = self.grid(P, box)
        w = self.w
        owned = self.n * a * b * c
        # the shell on the cut sides only: one side where a dimension is cut in two, two for
        # an inner block where it is cut in more
        grow = [d + w * min(p - 1, 2) for d, p in ((a, px), (b, py), (c, pz))]
        ghosts = self.n * grow[0] * grow[1] * grow[2] - owned
        cut = sum(1 for p in (px, py, pz) if p > 1)
        lg = math.log2(P)
        if sweep == "a":
            sweeps = self.sweeps_one * (1.0 + self.kappa * ghosts / owned)
            rounds = self.rounds_per_sweep * sweeps
            reductions = self.reductions_per_sweep * sweeps
            values = rounds * self.per_round_ghost * ghosts
        else:
            sweeps = self.coloured_sweeps
            # the sweep's exchange (2 rounds) once per colour; the colouring: 2 rounds and a
            # reduction per colour; the values of one exchange per sweep
            rounds = sweeps * (self.rounds_per_sweep - 2.0 + 2.0 * self.colours) + 2.0 * self.colours
            reductions = sweeps * self.reductions_per_sweep + self.colours
            values = sweeps * self.rounds_per_sweep * self.per_round_ghost * ghosts
        compute = self.t_c * sweeps * (owned + self.lam * ghosts)
        messages = rounds * 2 * cut * self.latency
        volume = values * 8.0 / self.bandwidth
        reduce = reductions * 2.0 * self.latency * lg
        return {"grid": (px, py, pz), "owned": owned, "ghosts": ghosts, "sweeps": sweeps, "rounds": rounds,
                "compute": compute, "messages": messages, "volume": volume, "reduce": reduce,
                "total": compute + messages + volume + reduce}


def measure_all(args):
    """the runs of the module help: {"1", "2", "4": per-rank counts, "coloured": ...}"""
    liggghts = os.path.abspath(args.liggghts)
    work = relaxed_column(liggghts, args.relaxed, PREP, "nscd-scaling-model-")
    phase = dict(PREP, resume=1, t_end=PREP["t_relax"] + args.time)
    runs = {}
    for name, ranks, extra in (("1", 1, {}), ("2", 2, {}), ("4", 4, {}), ("coloured", 1, {"nscd_order": "coloured"})):
        run_dir = os.path.join(work, f"distributed-{name}")
        os.makedirs(run_dir)
        for file in ("column_relaxed.restart", "column_deposited.txt"):
            shutil.copy(os.path.join(work, file), run_dir)
        r = runs[name] = measure(run_dir, ranks, liggghts, dict(phase, **extra))
        print(f"{name}{' rank(s)' if name != 'coloured' else ' (1 rank, order coloured)'}: {r['solves']:.0f} solves; "
              f"per solve {r['sweeps']:.2f} sweeps, {r['rounds']:.1f} rounds, {r['reductions']:.1f} reductions, "
              f"{r['colours']:.1f} colours, rank 0 sent {r['values']:.0f} values; own {r['owned']:.0f} and ghost "
              f"{r['ghosts']:.0f} grains per rank; rank 0's NSCD {r['nscd']:.2f} s "
              f"({1e3 * r['nscd'] / r['solves']:.2f} ms per solve){' (oversubscribed: not used)' if ranks > 2 else ''}",
              flush=True)
    runs["coloured"] = {"sweeps_ratio": runs["coloured"]["sweeps"] / runs["1"]["sweeps"],
                        "colours": runs["coloured"]["colours"], "measured on": "the same column and window"}
    print(f"(runs in {work})")
    return runs


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--liggghts", default=os.path.join(ROOT, "build", "liggghts"))
    parser.add_argument("--relaxed", help="a folder with column_relaxed.restart and column_deposited.txt (no wire)")
    parser.add_argument("--time", type=float, default=2.0, help="time units of the wall phase measured")
    parser.add_argument("--latency", type=float, default=2e-6, help="s per message (assumed)")
    parser.add_argument("--bandwidth", type=float, default=5e9, help="bytes per s per rank (assumed)")
    parser.add_argument("--save", help="write the measured counts to this JSON file")
    parser.add_argument("--counts", help="model from this JSON file of counts instead of measuring")
    args = parser.parse_args()
    if args.counts:
        with open(args.counts) as f:
            runs = json.load(f)
        print(f"counts from {args.counts}: {runs.get('source', '')}")
    else:
        runs = measure_all(args)
        if args.save:
            with open(args.save, "w") as f:
                json.dump(runs, f, indent=1)
    m = Model(runs, TABLE1, args.latency, args.bandwidth)
    print(f"\nfitted: t_c {1e6 * m.t_c:.2f} us per own grain and sweep, ghost shell w {m.w:.2f} a_max, a ghost costs "
          f"{m.lam:.2f} of an own grain, {m.per_round_ghost:.1f} values per ghost and round; per solve "
          f"{m.sweeps_one:.2f} (1 + {m.kappa:.3f} ghosts / own) sweeps, {m.rounds_per_sweep:.2f} rounds and "
          f"{m.reductions_per_sweep:.2f} reductions per sweep; (b): {m.coloured_sweeps:.2f} sweeps and "
          f"{m.colours:.1f} colours per solve; latency {1e6 * args.latency:.1f} us, "
          f"bandwidth {args.bandwidth / 1e9:.1f} GB/s (assumed)")
    two = m.step(2, (TABLE1["width"], TABLE1["width"], TABLE1["height"]))
    print(f"check, the Table 1 column on 2 ranks: model {1e3 * two['total']:.2f} ms per solve (its fit), measured "
          f"{1e3 * runs['2']['nscd'] / runs['2']['solves']:.2f} ms")
    n = TABLE1["grains"] / (TABLE1["width"] ** 2 * TABLE1["height"])
    # columns of the Table 1 grains at its packing, as grains and height (side = their square base)
    columns = [("Table 1", 915, 6.4), ("10x: 70 layers of the Table 1 column's", 9150, 64.0),
               ("10x wide: the Table 1 column's 7 layers at R = 31.6", 9137, 6.4),
               ("100x: 70 layers of 10x the Table 1 column's", 91500, 64.0)]
    for name, grains, height in columns:
        side = math.sqrt(grains / (n * height))
        box = (side, side, height)
        one = m.step(1, box)
        name = f"{name} ({grains} grains, {side:.0f} x {side:.0f} x {height:.1f} a_max)"
        print(f"\n{name}: model per NSCD solve, sweep (a) | (b)")
        print(f"{'ranks':>6s} {'grid':>10s} {'own':>8s} {'ghosts':>8s} {'sweeps':>7s} {'rounds':>7s} {'compute':>10s} "
              f"{'latency':>10s} {'volume':>10s} {'reduce':>10s} {'total':>10s} {'speed-up':>9s} {'efficiency':>10s} | "
              f"{'sweeps':>7s} {'rounds':>7s} {'total':>10s} {'b / a':>6s}")
        for P in (1, 2, 4, 16, 64, 256):
            s = m.step(P, box)
            b = m.step(P, box, "b")
            if s["owned"] < 1.0:
                continue
            print(f"{P:6d} {'x'.join(str(p) for p in s['grid']):>10s} {s['owned']:8.0f} {s['ghosts']:8.0f} "
                  f"{s['sweeps']:7.2f} {s['rounds']:7.1f} "
                  f"{1e3 * s['compute']:8.2f}ms {1e3 * s['messages']:8.2f}ms {1e3 * s['volume']:8.3f}ms "
                  f"{1e3 * s['reduce']:8.3f}ms {1e3 * s['total']:8.2f}ms {one['total'] / s['total']:9.1f} "
                  f"{one['total'] / s['total'] / P:10.2f} | {b['sweeps']:7.2f} {b['rounds']:7.1f} "
                  f"{1e3 * b['total']:8.2f}ms {b['total'] / s['total']:6.2f}")


if __name__ == "__main__":
    main()
