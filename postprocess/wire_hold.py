#!/usr/bin/python3
"""What the wire holds of an in.column run: the loops' radius and stretch, and the height of
the grains inside the loops against those outside, between the relaxed column (the walls'
start) and the end of the run.

    postprocess/wire_hold.py RUN [RUN ...] [--segment 0.2] [--radius R] [--csv OUT.csv] [--label NAME ...]

RUN is an in.column run folder: its post/column_relaxed_STEP.dump and
post/column_final_STEP.dump (dump custom: id type x y z, grains type 1, wire beads type 2;
the last of each when there are several). The axis is x = y = 0 (in.column's). For each run:

- the loops' radius: the beads' mean distance from the axis, relaxed and final;
- the wire's stretch: |x_j+1 − x_j| / l_w − 1 over the segments between beads of consecutive
  IDs (create_wire numbers a chain's beads in order; l_w = --segment, Table 1's 0.2); a pair
  farther apart than 2 l_w is taken as the gap between two loops' free ends, not a segment.
  Mean and 0.99 quantile, relaxed and final;
- the grains inside the loops: those whose centre lay within the relaxed loops' radius (or
  --radius, which a run without wire needs) of the axis in the relaxed column (by ID,
  wherever they went), and those outside (the corners and margin of the square container
  around circular loops, which no loop holds);
- the centre height H_c = 2 × the mean centre height, of the grains inside, of those outside
  and of all (in.column's H_c), final over relaxed: a held core keeps its H_c inside near 1.

Prints one line per run; --csv writes the same numbers, one row per run."""

import argparse
import csv
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from observables import read_dump  # noqa: E402

COLUMNS = ("run", "loops_radius_relaxed", "loops_radius_final", "stretch_mean_relaxed", "stretch_mean_final",
           "stretch_q99_relaxed", "stretch_q99_final", "grains", "grains_outside", "Hc_n_inside", "Hc_n_outside",
           "Hc_n")


def last_dump(run, when):
    found = sorted(glob.glob(os.path.join(run, "post", f"column_{when}_*.dump")),
                   key=lambda p: int(p.rsplit("_", 1)[1].split(".")[0]))
    if not found:
        raise SystemExit(f"wire_hold.py: {run}: needs post/column_relaxed_STEP.dump and post/column_final_STEP.dump "
                         "(in.column writes them)")
    return found[-1]


def snapshot(path):
    """Grains (id, x, y, z) and beads (x, y, z in ID order) of one dump."""
    _, columns = read_dump(path)[-1]
    kind = columns["type"].astype(int)
    grains = {k: columns[k][kind == 1] for k in ("id", "x", "y", "z")}
    order = np.argsort(columns["id"][kind == 2])
    beads = {k: columns[k][kind == 2][order] for k in ("id", "x", "y", "z")}
    return grains, beads


def stretch(beads, segment):
    """The stretch of the segments between beads of consecutive IDs (see the module's text)."""
    d = np.sqrt(np.diff(beads["x"]) ** 2 + np.diff(beads["y"]) ** 2 + np.diff(beads["z"]) ** 2)
    linked = (np.diff(beads["id"]) == 1) & (d < 2.0 * segment)
    return d[linked] / segment - 1.0


def hold(run, segment, split_radius=None):
    """The numbers of one run (COLUMNS after "run"); the wire's are nan without a wire."""
    relaxed_grains, relaxed_beads = snapshot(last_dump(run, "relaxed"))
    final_grains, final_beads = snapshot(last_dump(run, "final"))
    wired = relaxed_beads["x"].size >= 2
    if not wired and split_radius is None:
        raise SystemExit(f"wire_hold.py: {run}: the relaxed column has no wire: give --radius")
    nan = float("nan")
    radius = {name: float(np.mean(np.hypot(b["x"], b["y"]))) if wired else nan
              for name, b in (("relaxed", relaxed_beads), ("final", final_beads))}
    strains = {name: stretch(b, segment) if wired else np.array([nan])
               for name, b in (("relaxed", relaxed_beads), ("final", final_beads))}
    split = radius["relaxed"] if split_radius is None else split_radius
    inside_ids = relaxed_grains["id"][np.hypot(relaxed_grains["x"], relaxed_grains["y"]) < split]

    def centre_ratio(which):
        """H_c final over relaxed of the grains inside (True), outside (False) or all (None)."""
        start, end = (np.ones(g["id"].size, bool) if which is None else np.isin(g["id"], inside_ids) == which
                      for g in (relaxed_grains, final_grains))
        if not start.any() or not end.any():
            return float("nan")
        return float(np.mean(final_grains["z"][end]) / np.mean(relaxed_grains["z"][start]))

    return (radius["relaxed"], radius["final"], float(strains["relaxed"].mean()), float(strains["final"].mean()),
            float(np.quantile(strains["relaxed"], 0.99)), float(np.quantile(strains["final"], 0.99)),
            int(relaxed_grains["id"].size), int(relaxed_grains["id"].size - inside_ids.size),
            centre_ratio(True), centre_ratio(False), centre_ratio(None))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--segment", type=float, default=0.2, help="the wire's rest segment length l_w (0.2)")
    parser.add_argument("--radius", type=float, help="the radius that parts the grains inside from those outside "
                        "(default: the relaxed loops' mean radius)")
    parser.add_argument("--csv")
    parser.add_argument("--label", nargs="+", help="a name per run (default: its folder)")
    args = parser.parse_args()
    labels = args.label or args.runs
    if len(labels) != len(args.runs):
        raise SystemExit("wire_hold.py: give one --label per run")
    rows = []
    for run, label in zip(args.runs, labels):
        numbers = hold(run, args.segment, args.radius)
        rows.append((label,) + numbers)
        r0, r1, s0, s1, q0, q1, n, out, h_in, h_out, h_all = numbers
        print(f"{label}: loops' radius {r0:.3f} -> {r1:.3f} ({100 * (r1 / r0 - 1):+.1f} %); stretch mean "
              f"{s0:.4f} -> {s1:.4f}, 0.99 quantile {q0:.4f} -> {q1:.4f}; grains outside the loops {out} of {n}; "
              f"H_c final/relaxed: inside {h_in:.4f}, outside {h_out:.4f}, all {h_all:.4f}")
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            writer = csv.writer(f)
            writer.writerow(COLUMNS)
            writer.writerows(rows)


if __name__ == "__main__":
    main()
