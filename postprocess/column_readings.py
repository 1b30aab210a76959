#!/usr/bin/python3
"""Readings of a column's height other than the 0.98 quantile of the grains' tops, through
the wall phase of an in.column run, each normalised by its own value when the walls start.

    postprocess/column_readings.py RUN [RUN ...] [--radius R] [--cell 1.0] [--dt 1e-3]
        [--csv OUT.csv] [--plot OUT.png] [--label NAME ...]

RUN is an in.column run folder run with `-var t_tops T`, or a CSV this script wrote (--csv;
its rows are read back, so that a kept table can be drawn again without the dumps): its post/tops.dump (the grains'
id x y z and top every T in the wall phase) and post/column_relaxed_STEP.dump (the column
when the walls start, the reference of every reading). The readings, for one snapshot:

- q98: the 0.98 quantile of the tops (numpy's linear interpolation), the deck's H; it sees
  the column's highest part, its centre while the flanks slump.
- surface: the mean height of the column's upper surface inside the loop radius R: on a
  square grid of spacing --cell (a_max) centred on the axis, each node's height the highest
  top of the grains centred within --cell of it horizontally (0, the floor, where none is),
  averaged over the nodes within R of the axis. A slumping flank lowers it.
- rim: the same mean over the nodes between R − cell and R from the axis: the height of the
  column at the wire's radius, where a wall of grains should stand.
- centre: the grains' mean centre height times 2 (the height of a uniform block with the same
  mean centre height; it falls as the column spreads, whether its top is flat or not): the
  deck's H_c, whose ratio H_c_n column.obs and the deck's final line give.

Prints one line per snapshot and run (t, then each reading H and H/H(t_walls)); --csv writes
them, --plot draws the normalised readings against the time since the walls started, one
panel per reading, one line per run. The axis is x = y = 0 (in.column's)."""

import argparse
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from observables import read_dump  # noqa: E402

READINGS = ("q98", "surface", "rim", "centre")


def readings(x, y, z, top, radius, cell):
    """The four heights of one snapshot (see the module's text)."""
    q98 = float(np.quantile(top, 0.98))
    # the surface on a square grid of spacing `cell` centred on the axis: at each node the
    # highest top of the grains centred within `cell` of it horizontally (0: none)
    n = int(np.ceil(radius / cell))
    g = cell * np.arange(-n, n + 1)
    gx, gy = np.meshgrid(g, g, indexing="ij")
    gx, gy = gx.ravel(), gy.ravel()
    r = np.hypot(gx, gy)
    keep = r <= radius + 1e-12
    gx, gy, r = gx[keep], gy[keep], r[keep]
    near = (gx[:, None] - x[None, :]) ** 2 + (gy[:, None] - y[None, :]) ** 2 <= cell * cell
    height = np.where(near, top[None, :], 0.0).max(axis=1)
    rim = r > radius - cell
    return {"q98": q98, "surface": float(height.mean()), "rim": float(height[rim].mean()),
            "centre": 2.0 * float(np.mean(z))}


def grains_of(atoms, grain_type=1):
    """x, y, z, top of the grains of a snapshot (a tops.dump snapshot has grains only)."""
    keep = atoms["type"] == grain_type if "type" in atoms else np.ones(len(atoms["x"]), bool)
    top = atoms["c_gs[7]"][keep]
    return atoms["x"][keep], atoms["y"][keep], atoms["z"][keep], top


def series_of(run, radius, cell, dt):
    """[(t − t_walls, {reading: H})] of one run folder, the first entry the relaxed column."""
    relaxed = sorted(glob.glob(os.path.join(run, "post", "column_relaxed_*.dump")))
    tops = os.path.join(run, "post", "tops.dump")
    if not relaxed or not os.path.exists(tops):
        sys.exit(f"column_readings.py: {run}: needs post/column_relaxed_STEP.dump and post/tops.dump "
                 "(in.column -var t_tops T)")
    step0, atoms0 = read_dump(relaxed[0])[0]
    out = [(0.0, readings(*grains_of(atoms0), radius, cell))]
    for step, atoms in read_dump(tops):
        if step > step0:
            out.append(((step - step0) * dt, readings(*grains_of(atoms), radius, cell)))
    return out


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--radius", type=float, help="the loop radius R (needed for run folders)")
    parser.add_argument("--cell", type=float, default=1.0, help="the surface cells' side (a_max)")
    parser.add_argument("--dt", type=float, default=1e-3, help="the LIGGGHTS time step of the runs")
    parser.add_argument("--label", nargs="*", help="one name per run (default: the folder's name)")
    parser.add_argument("--csv")
    parser.add_argument("--plot")
    args = parser.parse_args(argv)
    labels = args.label or [os.path.basename(os.path.normpath(r)) for r in args.runs]
    if len(labels) != len(args.runs):
        sys.exit("column_readings.py: --label needs one name per run")
    if any(r.endswith(".csv") for r in args.runs) and args.label:
        sys.exit("column_readings.py: a CSV's rows keep their run names (no --label with a CSV)")
    rows = []
    for run, label in zip(args.runs, labels):
        if run.endswith(".csv"):
            with open(run) as f:
                table = [line.rstrip("\n").split(",") for line in f][1:]
            rows += [[r[0]] + [float(v) for v in r[1:]] for r in table]
            continue
        if args.radius is None:
            sys.exit("column_readings.py: --radius R is needed to read a run folder")
        series = series_of(run, args.radius, args.cell, args.dt)
        ref = series[0][1]
        for t, h in series:
            rows.append([label, t] + [v for k in READINGS for v in (h[k], h[k] / ref[k])])
    head = ["run", "t_since_walls"] + [v for k in READINGS for v in (f"H_{k}", f"Hn_{k}")]
    print(" ".join(head))
    for r in rows:
        print(r[0], " ".join(f"{v:.6g}" for v in r[1:]))
    if args.csv:
        with open(args.csv, "w") as f:
            f.write(",".join(head) + "\n")
            for r in rows:
                f.write(r[0] + "," + ",".join(f"{v:.8g}" for v in r[1:]) + "\n")
    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(1, len(READINGS), figsize=(4 * len(READINGS), 3.4), sharey=True)
        for ax, k in zip(axes, READINGS):
            col = head.index(f"Hn_{k}")
            for label in dict.fromkeys(r[0] for r in rows):
                mine = [r for r in rows if r[0] == label]
                ax.plot([r[1] for r in mine], [r[col] for r in mine], label=label)
            ax.set_title(k)
            ax.set_xlabel("t since the walls started")
            ax.grid(alpha=0.3)
        axes[0].set_ylabel("H / H(walls start)")
        axes[0].legend()
        fig.tight_layout()
        fig.savefig(args.plot, dpi=120)


if __name__ == "__main__":
    main()
