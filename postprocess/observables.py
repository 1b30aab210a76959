#!/usr/bin/python3
"""The column observables (H, H_n, φ_p, U_s/L, z_wpc; docs/results.md, "Observables") from a
LIGGGHTS/LAMMPS `dump custom` text file, so that they can be had from any run that wrote
one: ours (in.column writes post/column_relaxed_STEP.dump and post/column_final_STEP.dump),
a stock LIGGGHTS sphere run, or another code's dump in the same format; or from the VTK
files of the deck (post/grains_{relaxed,final}_STEP.vtp with the wire_..._STEP.vtp beside
it; .vtk for stock spheres).

    postprocess/observables.py FILE [FILE ...] [--h0 H0] [--shapes FILE] [--grain-type 1]
        [--wire-type 2] [--axis X Y] [--radius R] [--quantile 0.98] [--json]

Every snapshot of every file is one line: step, H, H_n, φ_p, U_s/L, z_wpc.

A FILE ending in .vtp is a `dump polyhedron/vtk` snapshot of the grains: a grain's centre
and top are its cell arrays `center` and `top`, its type the cell array `type`. One ending
in .vtk is a legacy VTK of stock grains (LIGGGHTS' `dump custom/vtk ... x y z radius
[c_gs[7]]`): top = the array c_gs[7] (in.column writes it: compute grain/shape's top, for
superquadrics too), else z + radius. The wire is the `dump wire/vtk` file beside it (the name with "grains"
replaced by "wire", .vtp), if there is one: beads are its points, their energies its point
arrays `stretching_energy` and `bending_energy` (`energy` keyword), a bead's segment the
line from it to the next point of its polyline (none for a chain's last bead), the grains
touching it the point array `grain_contacts` (`grains` keyword). The step is the last
number in the grains file's name. Reading VTK needs python3-vtk9.

- Grains are the atoms of --grain-type, wire beads those of --wire-type.
- H: the --quantile (numpy's linear interpolation) of the grains' tops. A grain's top is
  taken, in this order, from the library of --shapes (`grain_shapes write` of the run) with
  the columns c_gs[1] (shape index) and c_gs[2..5] (quaternion qw qi qj qk, body → space)
  of `compute gs all grain/shape`: max over the body-frame vertices v of (R(q) v)_z + z +
  the sweep radius; else from the column c_gs[7] (the top the run computed); else z +
  radius (spheres of any code).
- H_n = H / H0: --h0, else H of the first snapshot read (the in.column file of t_relax).
- φ_p: the fraction of grain centres whose horizontal distance from the axis (--axis,
  default 0 0) is below the mean horizontal distance of the wire beads from it; --radius R
  instead for a run without wire.
- U_s/L = Σ (c_energy[1] + c_energy[2]) / Σ c_energy[3] over the beads (`compute energy
  wire wire/energy`: per bead stretching and bending energy and its segment's length).
- z_wpc = Σ f_wg[4] over the beads (`fix wg ... wire/grain`: grains touching the bead's
  segment) / the number of segments (beads whose c_energy[3] > 0).
Columns that are missing give nan for what needs them. Uses numpy only."""

import argparse
import json
import math
import sys

import numpy as np


def read_dump(path):
    """The snapshots of a LAMMPS text dump, `dump custom` (ITEM: ATOMS) or `dump local`
    (ITEM: ENTRIES): [(step, {column: array})]."""
    snapshots = []
    with open(path) as f:
        lines = f.read().splitlines()
    k = 0
    while k < len(lines):
        if not lines[k].startswith("ITEM: TIMESTEP"):
            k += 1
            continue
        step = int(lines[k + 1])
        n = int(lines[k + 3])
        header = lines[k + 8].split()
        if header[:2] not in (["ITEM:", "ATOMS"], ["ITEM:", "ENTRIES"]):
            sys.exit(f"observables.py: {path}: expected 'ITEM: ATOMS' or 'ITEM: ENTRIES' at line {k + 9}")
        names = header[2:]
        rows = np.array([[float(w) for w in line.split()] for line in lines[k + 9:k + 9 + n]]).reshape(n, len(names))
        snapshots.append((step, {name: rows[:, j] for j, name in enumerate(names)}))
        k += 9 + n
    return snapshots


def read_vtk(path):
    """A VTK snapshot of the grains (and the wire file beside it) as the columns of a dump
    custom snapshot: [(step, {column: array})]."""
    import vtk_files as vf
    columns = {name: [] for name in ("type", "x", "y", "z", "radius", "c_gs[7]", "c_energy[1]", "c_energy[2]",
                                     "c_energy[3]", "f_wg[4]")}
    if path.endswith(".vtk"):
        centres, arrays = vf.read_legacy_spheres(path)
        grain_type = arrays["type"] if "type" in arrays else np.ones(len(centres))
        # the top the run computed (in.column writes c_gs[7]; a superquadric's radius is its
        # bounding sphere's), else a sphere's
        tops = arrays["c_gs[7]"] if "c_gs[7]" in arrays else centres[:, 2] + arrays["radius"]
        radii = arrays["radius"]
    else:
        grains = vf.read_polydata(path)
        ids, centers, tops_per_face = (vf.cell_array(grains, name) for name in ("id", "center", "top"))
        if ids is None or centers is None or tops_per_face is None:
            sys.exit(f"observables.py: {path} has no cell arrays id, center and top (dump polyhedron/vtk "
                     "writes them; for a file without them read the run's dump custom files instead)")
        first = np.unique(ids, return_index=True)[1]  # one face per grain
        centres, tops = centers[first], tops_per_face[first]
        grain_type = vf.cell_array(grains, "type")[first]
        radii = np.full(len(first), math.nan)
    n = len(centres)
    columns["type"].append(grain_type)
    for d, name in enumerate("xyz"):
        columns[name].append(centres[:, d])
    columns["radius"].append(radii)
    columns["c_gs[7]"].append(tops)
    for name in ("c_energy[1]", "c_energy[2]", "c_energy[3]", "f_wg[4]"):
        columns[name].append(np.full(n, math.nan))
    wire_path = vf.wire_beside(path)
    if wire_path:
        wire = vf.read_polydata(wire_path)
        beads = vf.vtk_to_numpy(wire.GetPoints().GetData())
        length = np.zeros(len(beads))
        for line in vf.cells(wire.GetLines()):
            # consecutive points of a polyline: the segment from a bead to the next
            # (a closed ring repeats its first point at the end)
            length[line[:-1]] = np.linalg.norm(beads[line[1:]] - beads[line[:-1]], axis=1)
        nan = np.full(len(beads), math.nan)
        stretching, bending, contacts = (vf.point_array(wire, name) for name in
                                         ("stretching_energy", "bending_energy", "grain_contacts"))
        columns["type"].append(vf.point_array(wire, "type"))
        for d, name in enumerate("xyz"):
            columns[name].append(beads[:, d])
        columns["radius"].append(nan)
        columns["c_gs[7]"].append(nan)
        columns["c_energy[1]"].append(nan if stretching is None else stretching)
        columns["c_energy[2]"].append(nan if bending is None else bending)
        columns["c_energy[3]"].append(length)
        columns["f_wg[4]"].append(nan if contacts is None else contacts)
    atoms = {name: np.concatenate(parts).astype(float) for name, parts in columns.items()
             if wire_path or not name.startswith(("c_energy", "f_wg"))}
    return [(vf.step_of(path), atoms)]


def read_shapes(path):
    """The library of `grain_shapes write`: [(sweep, vertices (V × 3))] in index order."""
    with open(path) as f:
        words = f.read().split()
    if words[:2] != ["wiregrain", "shapes"]:
        sys.exit(f"observables.py: {path} is no `grain_shapes write` file")
    count, k, shapes = int(words[2]), 5, []
    for _ in range(count):
        # shape K sweep R vertices V, then V × 3 numbers
        sweep, n_vertices = float(words[k + 3]), int(words[k + 5])
        vertices = np.array(words[k + 6:k + 6 + 3 * n_vertices], dtype=float).reshape(n_vertices, 3)
        shapes.append((sweep, vertices))
        k += 6 + 3 * n_vertices
    return shapes


def rotation(q):
    """The rotation matrix of the unit quaternion (w, i, j, k)."""
    w, x, y, z = np.asarray(q, dtype=float) / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def grain_tops(atoms, grains, shapes):
    if shapes is not None and "c_gs[1]" in atoms:
        tops = []
        for i in np.nonzero(grains)[0]:
            if atoms["c_gs[1]"][i] < 0:  # no library shape: a stock sphere (-1) or superquadric (-3)
                tops.append(atoms["c_gs[7]"][i] if "c_gs[7]" in atoms else atoms["z"][i] + atoms["radius"][i])
                continue
            sweep, vertices = shapes[int(atoms["c_gs[1]"][i])]
            q = [atoms[f"c_gs[{c}]"][i] for c in range(2, 6)]
            tops.append((vertices @ rotation(q).T)[:, 2].max() + atoms["z"][i] + sweep)
        return np.array(tops)
    if "c_gs[7]" in atoms:
        return atoms["c_gs[7]"][grains]
    return atoms["z"][grains] + atoms["radius"][grains]


def observables(atoms, args, shapes):
    grains = atoms["type"] == args.grain_type
    beads = atoms["type"] == args.wire_type
    out = {"H": float(np.quantile(grain_tops(atoms, grains, shapes), args.quantile))}
    distance = np.hypot(atoms["x"] - args.axis[0], atoms["y"] - args.axis[1])
    radius = args.radius if args.radius else (distance[beads].mean() if beads.any() else math.nan)
    out["phi_p"] = float(np.mean(distance[grains] < radius))
    if all(f"c_energy[{c}]" in atoms for c in (1, 2, 3)):
        length = atoms["c_energy[3]"][beads]
        out["U_s/L"] = float((atoms["c_energy[1]"][beads] + atoms["c_energy[2]"][beads]).sum() / length.sum())
        segments = np.count_nonzero(length > 0.0)
        out["z_wpc"] = float(atoms["f_wg[4]"][beads].sum() / segments) if "f_wg[4]" in atoms and segments else math.nan
    else:
        out["U_s/L"] = out["z_wpc"] = math.nan
    return out


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dumps", nargs="+")
    parser.add_argument("--h0", type=float, default=None)
    parser.add_argument("--shapes", default=None)
    parser.add_argument("--grain-type", type=int, default=1)
    parser.add_argument("--wire-type", type=int, default=2)
    parser.add_argument("--axis", type=float, nargs=2, default=(0.0, 0.0))
    parser.add_argument("--radius", type=float, default=None)
    parser.add_argument("--quantile", type=float, default=0.98)
    parser.add_argument("--json", action="store_true", help="one JSON object per snapshot")
    args = parser.parse_args(argv)
    shapes = read_shapes(args.shapes) if args.shapes else None
    h0 = args.h0
    if not args.json:
        print("# step H H_n phi_p U_s/L z_wpc")
    for path in args.dumps:
        snapshots = read_vtk(path) if path.endswith((".vtp", ".vtk")) else read_dump(path)
        for step, atoms in snapshots:
            obs = observables(atoms, args, shapes)
            h0 = h0 if h0 is not None else obs["H"]
            obs["H_n"] = obs["H"] / h0
            obs["step"] = step
            if args.json:
                print(json.dumps(obs))
            else:
                print(f"{step} {obs['H']:.10g} {obs['H_n']:.10g} {obs['phi_p']:.10g} {obs['U_s/L']:.10g} "
                      f"{obs['z_wpc']:.10g}")


if __name__ == "__main__":
    main()
