#!/usr/bin/python3
"""The wire along its length through the wall phase of an in.column run: the tension of its
segments and where it slides on the grains, against the distance from its layer's ends (the
free ends of the paper's loops, the joins of one continuous wire).

    postprocess/wire_along.py RUN [RUN ...] [--bins 10] [--csv OUT.csv] [--plot OUT.png]
        [--label NAME ...]

RUN is an in.column run folder run with `-var t_wire_state T` (post/wire_state.dump: the
beads' id x y z, the length and tension of the segment to the next bead, the grains touching
it, every T in the wall phase; post/wire_grain_contacts.dump: the wire-grain contacts at
the same steps, segment, grain, f_n, f_t, status), or a CSV this script wrote (--csv), read
back so that a kept table can be drawn again without the dumps.

Layers. in.column lays each wire layer by one create_wire call after that layer's grains,
and create_wire numbers the beads along the chain: a run of consecutive bead IDs is one
layer's call. The first layer has no join; its bead count n is the laid path's, the same on
every layer (loops, continuous: the double loop). A later call of more than n beads begins
with its join: its first beads up to the last n. A bead whose segment length is 0 has no next
bead (a chain's end): with loops both ends of every layer are free, with the continuous wire
only the first bead and the last.

Position along a layer. The laid segment from bead j to j + 1 (j = 0 .. n - 2 from the
layer's start) lies d = min(j + 1/2, n - 3/2 - j) segments from the layer's nearer end,
u = d / ((n - 1)/2) in [0, 1]: 0 at an end, 1 at the middle. A segment that starts at a join
bead, or at a layer's last laid bead and goes on (into the next layer's join), is a join
segment.

For each run it prints the layers found and, in --bins equal bins of u:
- tension: the mean tension of the laid segments, over the snapshots and the segments of
  the bin (T = m_elo E A (l - l_0)/l_0, fix wire/elastic's per-atom f_ID[4]), and at the last
  snapshot alone;
- slide: the fraction of the wire-grain contacts of the bin's segments that slide (status 2,
  on the Coulomb limit) among those that carry a force (status 1 stick or 2 slide), over
  the snapshots, their number, and that number per segment and snapshot;
and the same for the join segments (u empty). --csv writes these rows (run, label, part,
u_lo, u_hi, tension, tension_last, slide, contacts, per_segment); --plot draws tension and slide against
u, one line per label (the mean over its runs, ± their standard error with two or more),
the joins as points at u = -0.05. A run's label: --label (one per RUN) or its folder's
parent's name (postprocess/sweep.py's PARAM=VALUE)."""

import argparse
import csv
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from observables import read_dump  # noqa: E402

LENGTH, TENSION = "f_elastic[3]", "f_elastic[4]"   # post/wire_state.dump
SEGMENT, STATUS = "c_wgc[2]", "c_wgc[16]"           # post/wire_grain_contacts.dump
STICK, SLIDE = 1, 2
FIELDS = ("run", "label", "part", "u_lo", "u_hi", "tension", "tension_last", "slide", "contacts", "per_segment")


class Layers:
    """Each bead's place on the wire from the IDs and segment lengths of one snapshot
    (module text): for the laid segments their u, for the others whether they are joins."""

    def __init__(self, ids, lengths):
        order = np.argsort(ids)
        ids, lengths = ids[order].astype(int), lengths[order]
        starts = np.flatnonzero(np.diff(ids) != 1) + 1
        blocks = np.split(np.arange(len(ids)), starts)
        self.calls = len(blocks)
        self.beads = len(blocks[0])
        self.ends = int(np.sum(lengths == 0.0))  # beads without a next bead: one per chain
        self.join_beads = 0
        self.u = {}          # laid segment (its first bead's ID) -> u
        self.join = set()    # join segments (first bead's ID)
        n = self.beads
        if n < 2:
            raise ValueError(f"the first layer has {n} bead(s): not a wire laid by in.column")
        for block in blocks:
            if len(block) < n:
                raise ValueError(f"a layer of {len(block)} beads after a first layer of {n}: "
                                 "not in.column's layers (every layer lays the same path)")
            joined = len(block) - n
            self.join_beads += joined
            for k in block[:joined]:
                if lengths[k] > 0.0:
                    self.join.add(ids[k])
            laid = block[joined:]
            for j, k in enumerate(laid):
                if lengths[k] == 0.0:
                    continue
                if j == n - 1:       # the layer's last bead going on: into the next join
                    self.join.add(ids[k])
                    continue
                d = min(j + 0.5, n - 1.5 - j)
                self.u[ids[k]] = d / (0.5 * (n - 1))


def profile(run, bins):
    """The rows of one run folder (module text)."""
    states = read_dump(os.path.join(run, "post", "wire_state.dump"))
    contacts = dict(read_dump(os.path.join(run, "post", "wire_grain_contacts.dump")))
    if not states:
        raise ValueError(f"{run}: post/wire_state.dump holds no snapshot")
    layers = Layers(states[0][1]["id"], states[0][1][LENGTH])
    edges = np.linspace(0.0, 1.0, bins + 1)

    def bin_of(segment_ids):
        """Bin of each segment (-1: a join, -2: neither, e.g. a chain's last bead)."""
        return np.array([min(int(layers.u[s] * bins), bins - 1) if s in layers.u else (-1 if s in layers.join else -2)
                         for s in segment_ids.astype(int)])

    tension_sum = np.zeros(bins + 1)  # the last entry: joins
    tension_count = np.zeros(bins + 1)
    slide = np.zeros(bins + 1)
    carrying = np.zeros(bins + 1)
    last = np.zeros(bins + 1)
    last_count = np.zeros(bins + 1)
    for index, (step, beads) in enumerate(states):
        b = bin_of(beads["id"])
        for k in range(bins + 1):
            pick = b == (k if k < bins else -1)
            tension_sum[k] += beads[TENSION][pick].sum()
            tension_count[k] += pick.sum()
            if index == len(states) - 1:
                last[k] = beads[TENSION][pick].sum()
                last_count[k] = pick.sum()
        if step not in contacts or len(contacts[step].get(STATUS, [])) == 0:
            continue
        rows = contacts[step]
        b = bin_of(rows[SEGMENT])
        status = rows[STATUS].astype(int)
        for k in range(bins + 1):
            pick = b == (k if k < bins else -1)
            carrying[k] += np.sum(pick & ((status == STICK) | (status == SLIDE)))
            slide[k] += np.sum(pick & (status == SLIDE))
    info = (f"{run}: {layers.calls} layers of {layers.beads} laid beads, {layers.join_beads} join beads, "
            f"{layers.ends} chain(s), {len(states)} snapshots")
    rows = []
    with np.errstate(invalid="ignore", divide="ignore"):
        for k in range(bins + 1):
            rows.append({"part": "layer" if k < bins else "join",
                         "u_lo": edges[k] if k < bins else math.nan, "u_hi": edges[k + 1] if k < bins else math.nan,
                         "tension": tension_sum[k] / tension_count[k], "tension_last": last[k] / last_count[k],
                         "slide": slide[k] / carrying[k], "contacts": int(carrying[k]),
                         "per_segment": carrying[k] / tension_count[k]})
    return info, rows


def read_csv(path):
    """Rows written by --csv, grouped by run: {run: (label, rows)}."""
    runs = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            out = {"part": row["part"], "contacts": int(row["contacts"])}
            for name in ("u_lo", "u_hi", "tension", "tension_last", "slide", "per_segment"):
                out[name] = float(row[name])
            runs.setdefault(row["run"], (row["label"], []))[1].append(out)
    return runs


def plot(runs, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    labels = sorted({label for label, _ in runs.values()})
    for label in labels:
        group = [rows for lab, rows in runs.values() if lab == label]
        layer = [[r for r in rows if r["part"] == "layer"] for rows in group]
        join = [[r for r in rows if r["part"] == "join"] for rows in group]
        u = np.array([0.5 * (r["u_lo"] + r["u_hi"]) for r in layer[0]])
        for ax, name in zip(axes, ("tension", "slide")):
            values = np.array([[r[name] for r in rows] for rows in layer])
            mean = np.nanmean(values, axis=0)
            se = np.nanstd(values, axis=0, ddof=1) / np.sqrt(len(values)) if len(values) > 1 else None
            line = ax.errorbar(u, mean, yerr=se, marker="o", ms=3, capsize=2, label=f"{label} ({len(values)})")
            joins = np.array([[r[name] for r in rows] for rows in join]).ravel()
            if np.any(np.isfinite(joins)):
                ax.plot([-0.05], [np.nanmean(joins)], marker="s", color=line[0].get_color(), ls="none")
    axes[0].set_ylabel("mean tension of the laid segments")
    axes[1].set_ylabel("fraction of wire-grain contacts sliding")
    for ax in axes:
        ax.set_xlabel("u: 0 at the layer's ends, 1 at its middle (squares: joins)")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--bins", type=int, default=10)
    parser.add_argument("--csv")
    parser.add_argument("--plot")
    parser.add_argument("--label", nargs="+")
    a = parser.parse_args()
    if a.bins < 1:
        sys.exit(f"wire_along.py: --bins must be at least 1, got {a.bins}")
    if a.label and len(a.label) != len(a.runs):
        sys.exit(f"wire_along.py: --label gives {len(a.label)} labels for {len(a.runs)} runs")
    runs = {}
    for k, run in enumerate(a.runs):
        if run.endswith(".csv"):
            runs.update(read_csv(run))
            continue
        label = a.label[k] if a.label else os.path.basename(os.path.dirname(os.path.abspath(run)))
        try:
            info, rows = profile(run, a.bins)
        except (OSError, ValueError) as e:
            sys.exit(f"wire_along.py: {e}")
        print(info)
        runs[run] = (label, rows)
    for run, (label, rows) in runs.items():
        for r in rows:
            where = "joins" if r["part"] == "join" else f"u {r['u_lo']:.2f}-{r['u_hi']:.2f}"
            print(f"{label} {run} {where}: tension {r['tension']:.5g} (last {r['tension_last']:.5g}), "
                  f"sliding {r['slide']:.4f} of {r['contacts']} contacts ({r['per_segment']:.3f} per segment and snapshot)")
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=FIELDS)
            w.writeheader()
            for run, (label, rows) in runs.items():
                for r in rows:
                    w.writerow(dict(r, run=run, label=label))
    if a.plot:
        plot(runs, a.plot)


if __name__ == "__main__":
    main()
