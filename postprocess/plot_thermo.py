#!/usr/bin/python3
"""Plot thermo columns of a LIGGGHTS log against the step (or time) as a PNG.

    postprocess/plot_thermo.py log.liggghts -o thermo.png [-c KinEng wire[3] ...] [--run N]

Columns: names as in the log's header line (default: all but Step). --run: which run of
the log (1-based, default: the last). Uses Debian's python3-matplotlib and numpy."""

import argparse
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def thermo_tables(text):
    """Every thermo table of a log as (header, rows)."""
    tables, header, rows = [], None, []
    for line in text.splitlines():
        words = line.split()
        if words[:1] == ["Step"]:
            header, rows = words, []
            continue
        if header is None:
            continue
        if len(words) == len(header) and re.match(r"^-?\d+$", words[0]):
            try:
                rows.append([float(w) for w in words])
                continue
            except ValueError:
                pass
        if rows:
            tables.append((header, np.array(rows)))
        header, rows = None, []
    if header is not None and rows:
        tables.append((header, np.array(rows)))
    return tables


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("log")
    parser.add_argument("-o", "--output", default="thermo.png")
    parser.add_argument("-c", "--columns", nargs="*")
    parser.add_argument("--run", type=int, default=0)
    args = parser.parse_args(argv)
    with open(args.log) as f:
        tables = thermo_tables(f.read())
    if not tables:
        sys.exit(f"{args.log}: no thermo table found")
    header, data = tables[args.run - 1 if args.run else -1]
    columns = args.columns or [c for c in header if c != "Step"]
    missing = [c for c in columns if c not in header]
    if missing:
        sys.exit(f"columns {missing} not in the log header {header}")
    fig, axes = plt.subplots(len(columns), 1, sharex=True, figsize=(7, 2.2 * len(columns)), squeeze=False)
    for ax, name in zip(axes[:, 0], columns):
        ax.plot(data[:, 0], data[:, header.index(name)])
        ax.set_ylabel(name)
        ax.grid(alpha=0.3)
    axes[-1, 0].set_xlabel("Step")
    fig.tight_layout()
    fig.savefig(args.output, dpi=100)
    print(f"{args.output}: {len(columns)} columns, {len(data)} rows")


if __name__ == "__main__":
    main()
