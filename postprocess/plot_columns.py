#!/usr/bin/python3
"""The final columns side by side (the paper's Fig. 12): grains as their polyhedra, the wire
as a line coloured by its elastic strain energy per bead.

    postprocess/plot_columns.py RUN [RUN ...] -o columns.png [--legend "R = 3" ...]
        [--elevation 15] [--azimuth 30]

RUN: a run directory of input_scripts/in.column (or of postprocess/sweep.py), whose post/
holds the grains_final_STEP.vtp and wire_final_STEP.vtp the deck writes at its end (a run
without wire has no wire file; a run of stock spheres, `-var grains spheres`, has
grains_final_STEP.vtk, LIGGGHTS' legacy VTK with a radius per point, drawn as spheres;
one of superquadrics, `-var grains superquadrics`, the same with their half-axes,
blockiness and rotation, drawn as superquadrics),
or a grains VTP file itself (the wire file is then looked
for beside it, with "grains" replaced by "wire"). All panels share one length scale, in
a_max, so that columns of different R compare. Reads VTK's XML with Debian's
python3-vtk9; draws with python3-matplotlib."""

import argparse
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib import cm, colors  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection  # noqa: E402
from vtk_files import cells, read_legacy_spheres, read_polydata, wire_beside  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402


def final_files(run):
    """(grains VTP or sphere VTK, wire VTP or None) of a run directory or a grains file."""
    if os.path.isfile(run):
        grains = run
    else:
        found = sorted(glob.glob(os.path.join(run, "post", "grains_final_*.vtp")))
        found = found or sorted(f for f in glob.glob(os.path.join(run, "post", "grains_final_*.vtk"))
                                if "boundingBox" not in f)
        if not found:
            sys.exit(f"plot_columns.py: no post/grains_final_*.vtp (or .vtk) in {run}")
        grains = found[-1]
    return grains, wire_beside(grains)


def sphere_faces(centres, radii, subdivisions=8):
    """Each sphere as a latitude–longitude mesh of quadrilaterals (for Poly3DCollection)."""
    theta = np.linspace(0.0, np.pi, subdivisions + 1)
    phi = np.linspace(0.0, 2.0 * np.pi, 2 * subdivisions + 1)
    unit = np.stack([np.outer(np.sin(theta), np.cos(phi)), np.outer(np.sin(theta), np.sin(phi)),
                     np.outer(np.cos(theta), np.ones_like(phi))], axis=-1)
    faces = []
    for c, r in zip(centres, radii):
        p = c + r * unit
        for i in range(subdivisions):
            for j in range(2 * subdivisions):
                faces.append(np.array([p[i, j], p[i + 1, j], p[i + 1, j + 1], p[i, j + 1]]))
    return faces


def superquadric_faces(centres, half_axes, blockiness, rotations, subdivisions=8):
    """Each superquadric (LIGGGHTS': (|x/a|^n2 + |y/b|^n2)^(n1/n2) + |z/c|^n1 = 1) as a mesh
    of quadrilaterals on Barr's parametrisation (latitude η, longitude ω, exponents 2/n),
    turned by its rotation matrix (body → world) and moved to its centre."""
    eta = np.linspace(-0.5 * np.pi, 0.5 * np.pi, subdivisions + 1)
    omega = np.linspace(0.0, 2.0 * np.pi, 2 * subdivisions + 1)
    eta, omega = np.meshgrid(eta, omega, indexing="ij")

    def signed_power(v, e):
        return np.sign(v) * np.abs(v) ** e

    faces = []
    for c, (a, b, h), (n1, n2), R in zip(centres, half_axes, blockiness, rotations):
        ce = signed_power(np.cos(eta), 2.0 / n1)
        body = np.stack([a * ce * signed_power(np.cos(omega), 2.0 / n2), b * ce * signed_power(np.sin(omega), 2.0 / n2),
                         h * signed_power(np.sin(eta), 2.0 / n1)], axis=-1)
        p = c + body @ np.asarray(R).reshape(3, 3).T
        for i in range(subdivisions):
            for j in range(2 * subdivisions):
                faces.append(np.array([p[i, j], p[i + 1, j], p[i + 1, j + 1], p[i, j + 1]]))
    return faces


def grain_faces(path):
    """The faces of the grains of a polyhedron VTP, or of a stock-grain VTK: superquadrics
    (with shapex.. and LIGGGHTS' rotation TENSOR, as in.column writes them) or spheres
    (points with radius)."""
    if path.endswith(".vtp"):
        grains = read_polydata(path)
        points = vtk_to_numpy(grains.GetPoints().GetData())
        return [points[f] for f in cells(grains.GetPolys())]
    centres, arrays = read_legacy_spheres(path)
    if all(k in arrays for k in ("shapex", "shapey", "shapez", "blockiness1", "blockiness2", "TENSOR")):
        return superquadric_faces(centres, np.stack([arrays["shapex"], arrays["shapey"], arrays["shapez"]], axis=1),
                                  np.stack([arrays["blockiness1"], arrays["blockiness2"]], axis=1), arrays["TENSOR"])
    return sphere_faces(centres, arrays["radius"])


def draw(ax, grains_path, wire_path, energy_norm):
    faces = grain_faces(grains_path)
    points = np.concatenate(faces)
    # a fixed light from above-front: shade each face by its normal
    normals = [np.cross(f[1] - f[0], f[2] - f[0]) for f in faces]
    light = np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8])
    shade = [0.55 + 0.45 * max(0.0, float(n @ light) / (np.linalg.norm(n) or 1.0)) for n in normals]
    ax.add_collection3d(Poly3DCollection(faces, facecolors=[(s * 0.85, s * 0.8, s * 0.72) for s in shade],
                                         edgecolors="none"))
    extent = [points.min(axis=0), points.max(axis=0)]
    if wire_path:
        wire = read_polydata(wire_path)
        beads = vtk_to_numpy(wire.GetPoints().GetData())
        energy = vtk_to_numpy(wire.GetPointData().GetArray("elastic_energy"))
        segments, values = [], []
        for line in cells(wire.GetLines()):
            for a, b in zip(line[:-1], line[1:]):
                segments.append([beads[a], beads[b]])
                values.append(0.5 * (energy[a] + energy[b]))
        collection = Line3DCollection(segments, cmap="plasma", norm=energy_norm, linewidths=1.5)
        collection.set_array(np.array(values))
        ax.add_collection3d(collection)
        extent = [np.minimum(extent[0], beads.min(axis=0)), np.maximum(extent[1], beads.max(axis=0))]
    return extent


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--legend", nargs="+", default=None)
    parser.add_argument("--elevation", type=float, default=15.0)
    parser.add_argument("--azimuth", type=float, default=30.0)
    args = parser.parse_args()
    if args.legend and len(args.legend) != len(args.runs):
        parser.error(f"--legend needs one label per run ({len(args.runs)})")

    files = [final_files(run) for run in args.runs]
    energies = [vtk_to_numpy(read_polydata(w).GetPointData().GetArray("elastic_energy")) for _, w in files if w]
    top = max((e.max() for e in energies), default=1.0)
    energy_norm = colors.Normalize(vmin=0.0, vmax=top if top > 0.0 else 1.0)

    fig = plt.figure(figsize=(4.5 * len(files), 4.8), constrained_layout=True)
    axes, extents = [], []
    for k, (grains, wire) in enumerate(files):
        ax = fig.add_subplot(1, len(files), k + 1, projection="3d")
        extents.append(draw(ax, grains, wire, energy_norm))
        ax.set_title(args.legend[k] if args.legend else args.runs[k], fontsize=9)
        ax.view_init(elev=args.elevation, azim=args.azimuth)
        axes.append(ax)
    # one scale for all panels: the largest horizontal span and height
    span = max(max(e[1][0] - e[0][0], e[1][1] - e[0][1]) for e in extents)
    height = max(e[1][2] for e in extents)
    for ax, e in zip(axes, extents):
        cx, cy = 0.5 * (e[0][0] + e[1][0]), 0.5 * (e[0][1] + e[1][1])
        ax.set_xlim(cx - span / 2, cx + span / 2)
        ax.set_ylim(cy - span / 2, cy + span / 2)
        ax.set_zlim(0.0, height)
        ax.set_box_aspect((span, span, height))
        ax.set_xlabel("x [a_max]", fontsize=8)
        ax.set_ylabel("y [a_max]", fontsize=8)
        ax.set_zlabel("z [a_max]", fontsize=8)
        ax.tick_params(labelsize=7)
        ax.zaxis.set_major_locator(MaxNLocator(3))  # squat columns: few z ticks, no overlap
    if energies:
        bar = fig.colorbar(cm.ScalarMappable(norm=energy_norm, cmap="plasma"), ax=axes, shrink=0.6)
        bar.set_label("wire elastic energy per bead  [ρ₁ g a_max⁴]")
    fig.savefig(args.output, dpi=120)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
