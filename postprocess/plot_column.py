#!/usr/bin/python3
"""The column during wall removal (the paper's Fig. 7): H_n and the wire's elastic energy,
normalised by its maximum, against the time since the walls started to move.

    postprocess/plot_column.py RUN [RUN ...] -o column.png [--legend A B ...] [--colors C ...] [--no-energy] [--centre]

RUN: a column.obs written by input_scripts/in.column, or a directory holding one (a run
directory of postprocess/sweep.py). column.obs starts when the walls start to
move; its columns are t, H, H_n, φ_p, U_s/L, z_wpc and H_c_n (a file without H_c_n is read too);
`--centre` draws H_c_n as well, dotted. The energy curve is U_s/L divided by
its largest value over the run (U_s/L is proportional to the total energy U_s, the wire's
length being fixed), as in the paper. Left axis H_n, right axis the energy; time in
units of √(a_max/g). Uses Debian's python3-matplotlib and numpy."""

import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_obs(path):
    """The column.obs table as a dict of arrays (step, t, H, H_n, phi_p, U_s/L, z_wpc, and H_c_n
    when the file has it)."""
    if os.path.isdir(path):
        path = os.path.join(path, "column.obs")
    if not os.path.exists(path):
        sys.exit(f"plot_column.py: {path} does not exist")
    rows = np.atleast_2d(np.loadtxt(path, comments="#"))
    if rows.shape[1] not in (7, 8):
        sys.exit(f"plot_column.py: {path}: expected 7 or 8 columns (step t H H_n phi_p U_s/L z_wpc [H_c_n]), "
                 f"got {rows.shape[1]}")
    return dict(zip(["step", "t", "H", "H_n", "phi_p", "U_s/L", "z_wpc", "H_c_n"], rows.T))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--legend", nargs="+", default=None)
    parser.add_argument("--colors", nargs="+", default=None, help="a matplotlib colour per run (e.g. one per model)")
    parser.add_argument("--no-energy", action="store_true", help="H_n only")
    parser.add_argument("--centre", action="store_true", help="H_c_n as well (dotted), where column.obs has it")
    args = parser.parse_args()
    for name in ("legend", "colors"):
        if getattr(args, name) and len(getattr(args, name)) != len(args.runs):
            parser.error(f"--{name} needs one value per run ({len(args.runs)})")

    fig, height_axis = plt.subplots(figsize=(7, 4.5), constrained_layout=True)
    energy_axis = height_axis.twinx()
    for k, run in enumerate(args.runs):
        obs = read_obs(run)
        since = obs["t"] - obs["t"][0]
        label = args.legend[k] if args.legend else run
        line, = height_axis.plot(since, obs["H_n"], label=f"H_n {label}",
                                 color=args.colors[k] if args.colors else None)
        if args.centre and "H_c_n" in obs:
            height_axis.plot(since, obs["H_c_n"], ls=":", color=line.get_color(), label=f"H_c_n {label}")
        peak = obs["U_s/L"].max()
        if peak > 0.0 and not args.no_energy:
            energy_axis.plot(since, obs["U_s/L"] / peak, ls="--", color=line.get_color(),
                             label=f"U_s / max U_s {label}")
    # (the walls start at t_relax, or earlier when in.column's ke_stop ends the relaxation)
    height_axis.set_xlabel("time since the walls started  [√(a_max / g)]")
    height_axis.set_ylabel("H_n = H / H0, H0 as the walls start  (solid)")
    energy_axis.set_ylabel("U_s / max U_s  (dashed)")
    if args.no_energy:
        energy_axis.set_axis_off()
    energy_axis.set_ylim(0.0, 1.05)
    height_axis.grid(alpha=0.3)
    handles = height_axis.get_legend_handles_labels()[0] + energy_axis.get_legend_handles_labels()[0]
    height_axis.legend(handles=handles, fontsize=7, loc="lower left")
    fig.savefig(args.output, dpi=120)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
