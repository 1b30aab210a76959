#!/usr/bin/python3
"""The load test's observables and its force–strain curves, from the time series
post/load.txt that input_scripts/in.column_load writes (LIGGGHTS' fix ave/time format:
t d strain F_grains F_wire F F/W F_floor/W H U_s lost v_cm v_p F_drive/W; a series of an
older build without the last two is read too).

    postprocess/load_curve.py RUN [RUN ...] [--plot FILE.png] [--fit-to 0.5] [--onset 0.01]
                              [--json]

RUN is a run's folder (its post/load.txt is read) or the file itself; its label in the
table and the plot is the folder's name. Per run, one line:

- onset: the strain at which the plate load F/W first exceeds --onset (the plate has
  reached the column);
- stiffness: the slope d(F/W)/d(strain) of a least-squares line through the points from
  the onset to the first one where F/W reaches --fit-to times the peak (the initial,
  approximately linear part of the response); nan with fewer than 3 such points;
- peak: the largest F/W and the strain at which it was reached;
- end: the last strain, F/W and grains lost.

With --plot, F/W against the strain of every run in one figure (matplotlib, Agg). Uses
numpy only otherwise."""

import argparse
import json
import os
import sys

import numpy as np

COLUMNS = ["t", "d", "strain", "F_grains", "F_wire", "F", "F_W", "floor_W", "H", "U_s", "lost", "v_cm", "v_p",
           "F_drive_W"]
# the columns of a series written before the plate's mode (in.column_load's `plate`)
FIRST_COLUMNS = COLUMNS[:12]


def read_series(path):
    """The columns of a post/load.txt as a dict of arrays (comment lines skipped)."""
    if os.path.isdir(path):
        path = os.path.join(path, "post", "load.txt")
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            values = line.split()
            # fix ave/time: the step first, then the averaged values
            rows.append([float(v) for v in values[1:]])
    if not rows:
        raise ValueError(f"{path}: no data lines")
    data = np.array(rows)
    if data.shape[1] not in (len(COLUMNS), len(FIRST_COLUMNS)):
        raise ValueError(f"{path}: {data.shape[1]} values per line, expected {len(COLUMNS)} ({' '.join(COLUMNS)}) "
                         f"or the first {len(FIRST_COLUMNS)}")
    return {name: data[:, k] for k, name in enumerate(COLUMNS[:data.shape[1]])}


def observables(series, onset=0.01, fit_to=0.5):
    """Onset strain, initial stiffness, peak F/W and its strain, end state (module doc)."""
    strain, load = series["strain"], series["F_W"]
    peak_index = int(np.argmax(load))
    result = {"peak": float(load[peak_index]), "strain_at_peak": float(strain[peak_index]),
              "end_strain": float(strain[-1]), "end_load": float(load[-1]), "end_lost": float(series["lost"][-1]),
              "onset": float("nan"), "stiffness": float("nan")}
    above = np.nonzero(load > onset)[0]
    if len(above) == 0:
        return result
    first = int(above[0])
    result["onset"] = float(strain[first])
    reached = np.nonzero(load[first:] >= fit_to * result["peak"])[0]
    last = first + (int(reached[0]) if len(reached) else len(load) - first - 1)
    if last - first + 1 >= 3:
        slope, _ = np.polyfit(strain[first:last + 1], load[first:last + 1], 1)
        result["stiffness"] = float(slope)
    return result


def label_of(path):
    path = os.path.abspath(path)
    if os.path.isfile(path):
        path = os.path.dirname(os.path.dirname(path)) if os.path.basename(os.path.dirname(path)) == "post" \
            else os.path.dirname(path)
    return os.path.basename(path)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--plot", help="write F/W against the strain to this PNG")
    parser.add_argument("--fit-to", type=float, default=0.5, help="fraction of the peak up to which the stiffness is fitted")
    parser.add_argument("--onset", type=float, default=0.01, help="F/W at which the plate has reached the column")
    parser.add_argument("--json", action="store_true", help="one JSON object per run instead of the table")
    args = parser.parse_args(argv)
    if not 0 < args.fit_to <= 1:
        parser.error(f"--fit-to must be in (0, 1], got {args.fit_to}")
    curves = []
    if not args.json:
        print(f"{'run':24s} {'onset':>8s} {'stiffness':>10s} {'peak F/W':>9s} {'at strain':>9s} "
              f"{'end strain':>10s} {'end F/W':>8s} {'lost':>5s}")
    for run in args.runs:
        series = read_series(run)
        obs = observables(series, args.onset, args.fit_to)
        curves.append((label_of(run), series))
        if args.json:
            print(json.dumps(dict(run=run, **obs)))
        else:
            print(f"{label_of(run):24s} {obs['onset']:8.4f} {obs['stiffness']:10.3f} {obs['peak']:9.4f} "
                  f"{obs['strain_at_peak']:9.4f} {obs['end_strain']:10.4f} {obs['end_load']:8.4f} {obs['end_lost']:5.0f}")
    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 4))
        for label, series in curves:
            ax.plot(series["strain"], series["F_W"], label=label)
        ax.set_xlabel("strain (z_top0 - z_plate) / z_top0")
        ax.set_ylabel("plate load F / W")
        ax.axhline(0, color="0.7", lw=0.5)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(args.plot, dpi=120)
    return 0


if __name__ == "__main__":
    sys.exit(main())
