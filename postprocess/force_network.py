#!/usr/bin/python3
"""The contact-force network of a column, from the dumps that input_scripts/in.column_load
writes (or any run that writes the same dumps): the distribution of the normal forces, the
strong and weak networks and their orientation, the vertical stress in the column and the
load's path to the floor, the wire's tension, and a picture of the network.

    postprocess/force_network.py RUN [--step STEP] [--out DIR] [--per-point]
        [--bin-width 0.25] [--density 1.5] [--g 1] [--axis X Y] [--R R] [--r-bins 4] [--r-max RMAX]
        [--z-bins 5] [--section circle | --section square D] [--planes 5 | --plane-z Z [Z ...]]
        [--E-w 100] [--m-elo 1] [--l0 0.2]
        [--prefix load] [--contacts FILE] [--grains FILE] [--wire FILE] [--vtp FILE]
        [--stress c_stress[3]] [--energy c_energy] [--no-plots] [--no-picture]
        [--size 1000 1000] [--view side|elevated|top] [--bar-radius 0.2]

Input. RUN is the folder of the run (its post/ is read) or the post/ folder itself; the
snapshot of step STEP (default: the last step with a contacts file) is read from
  PREFIX_contacts_STEP.dump  dump local of compute contact/local, its 16 columns c_ID[1..16]
                             (kind, a, b, point, normal, f_n, force on b, f_t, overlap, status)
  PREFIX_grains_STEP.dump    dump custom: id mass x y z and the grains' σ_zz (--stress, the
                             column c_ID[3] of compute grain/stress)
  PREFIX_wire_STEP.dump      dump custom: id x y z radius c_energy[1] c_energy[3] (compute
                             wire/energy: per bead stretching energy, length of the segment
                             to the next bead); optional (no wire: no tension)
  PREFIX_grains_STEP.vtp     dump polyhedron/vtk: the grains' shapes, for the picture
(PREFIX "load"), or from the files given by --contacts, --grains, --wire, --vtp. The last
snapshot of a file is read.

A contact. By default a contact is a pair of bodies: the rows of one pair (the points of a
contact manifold of fix nscd/polyhedra) are summed: f_n the sum of their normal forces, the
normal the f_n-weighted mean of their normals (oriented from the lower ID to the higher; a
wall, −w, first), the point the f_n-weighted mean of their points. For rigid grains only
the pair's resultant is determined by statics, not its share among the points. --per-point
takes each row as a contact. A row is open when its status is 0 (it carries no force) or
its f_n is 0; a contact is open when all its rows are. Open contacts are counted and left
out of 1 and 2.

Output (printed, and in DIR/network_STEP.json; DIR defaults to the contacts file's folder):
1. Forces: the grain–grain contacts (kind 3): their number, the open ones, the mean normal
   force ⟨f⟩ of the closed ones and the histogram of x = f_n/⟨f⟩ (bins of --bin-width from
   0; counts and the density P(x) = count/(N width)), drawn on a log scale
   (network_STEP_forces.png) with the exponential tail P ∝ exp(−β x) above x = 1. β is the
   maximum-likelihood rate of x − 1 over the n_t contacts with x > 1, in its unbiased form
   β = (n_t − 1)/Σ(x − 1) with the standard error β/√(n_t − 2) (an exponential above 1 is
   again an exponential of x − 1; no binning enters); the line drawn is
   (n_t/N) β exp(−β (x − 1)).
2. Networks: strong, f_n > ⟨f⟩, and weak, 0 < f_n ≤ ⟨f⟩ (and all): the fraction of the
   closed contacts and of their total normal force; the fabric tensor φ_ij = ⟨n_i n_j⟩ of
   their normals, unweighted and weighted by f_n (Σ f_n n_i n_j / Σ f_n), its eigenvalues
   (ascending; they sum to 1: 1/3 each for an isotropic set, (0, 0, 1) for all normals
   along one line) and the angle of its major axis (the eigenvector of the largest) from
   the vertical, in degrees.
3. Stress: σ_zz of the grains (--stress; tension positive) binned by the horizontal
   distance r of the grain's centre from the axis (--axis, 0 0; --r-bins from 0 to the
   largest r, or to --r-max, beyond which grains count as outside) and its height z
   (--z-bins from 0 to the highest centre): in each bin the volume-weighted mean over its
   grains Σ V σ_zz / Σ V, V = mass/density (--density, 1.5, create_grains' default; the
   mean does not depend on it), and the bin's coarse-grained stress Σ V σ_zz / V_bin with
   V_bin = π (r_1² − r_0²)(z_1 − z_0) and its solid fraction Σ V / V_bin (these do); a 2-D
   map and the two 1-D profiles (network_STEP_stress.png, −σ_zz: compression up). The
   walls' loads from the grain–wall rows (kind 4): per wall index, its force (the opposite
   of the grains'), its load Σ f_n and its side (floor: its normal towards the grains
   points up; plate: down); the wire's on the walls (kind 1, split by the normal's sign).
   Where the load goes: through each horizontal plane z = h (--planes N evenly spaced
   between the lowest and highest grain centres, or --plane-z), the force T transmitted
   by the grain–grain contacts whose two grain centres are on either side (the upward
   force on the grains above, Σ f_z), binned by the contact point's r (--r-bins), and the
   share within r < R/2 (an even spread over the disc of radius R would put 1/4 there).
   R is --R, else the wire beads' mean distance from the axis, else the largest r of a
   grain centre. With it, the balance of the grains above the plane: their weight W_U
   (--g, 1), the walls' and the wire's vertical force on them; at rest
   T = W_U − F_walls − F_wire, and the residual T − W_U + F_walls + F_wire is their total
   m a_z (network_STEP_transmission.png).
4. Wire: per segment (a bead with a next bead, c_energy[3] > 0, its length l) the tension
   T = m_elo E_w π r_w² (l − l0)/l0 (the segment's spring k_s (l − l0) of fix
   wire/elastic, k_s = m_elo E_w π r_w²/l0; --E-w 100, --m-elo 1, --l0 0.2: create_wire's
   segment; r_w the bead's radius), against the bead's z (network_STEP_wire.png). Check:
   the stretching energy ½ k_s (l − l0)² of the segments, half to each bead (consecutive
   IDs along a wire, as create_wire numbers them), against the dump's c_energy[1]; a wrong
   E_w, m_elo or l0 shows as a mismatch.
5. Confinement: in --z-bins slabs from the floor to the highest grain centre or
   wire–grain contact point, what holds the grains in sideways, as Janssen's silo: per
   slab the force normal to the confining surface that the wire (the rows of kind 2: its
   horizontal force on the grain along −e_r, e_r the unit vector from the axis to the
   contact point) and the side walls (kind 4 rows whose normal is within 30° of the
   horizontal: their f_n) put on the grains, per unit height (q = Σ f / Δz) and as a
   pressure p = q / perimeter; the vertical stress of the grains whose centres are in the
   slab and inside the section, σ_v = −Σ V σ_zz / (A Δz); and their ratio K = p / σ_v,
   Janssen's K where the walls confine. The section (--section): a circle of radius R
   (perimeter 2πR, area πR²; the column) or, with --section square D, a square of side D
   (4D, D²; in.silo's container). From the wire's side (item 4), the hoop force of its
   tension: each segment pulls its two beads towards each other with T; q_hoop is the sum
   over the beads in the slab of that pull's component towards the axis, over Δz (a
   circular loop of radius r: T l / r per segment of length l). It is what the wire's
   other forces balance: the grains' push (q_wire), and also the walls' friction on beads
   lying on the floor, the turns of a loop pressing on each other, bending and the beads'
   acceleration; q_hoop = q_wire says that the tension is held by the grains
   (network_STEP_confinement.png).
6. Picture (network_STEP_picture.png, --size W H pixels, --view): each grain–grain and
   grain–wall contact with f_n > 0 as a tube from grain centre to grain centre (to the
   contact point for a wall), its radius --bar-radius × f_n / max f_n (at least a tenth of
   it, to stay visible) and its colour f_n (colour bar), over the grains of the .vtp drawn
   semi-transparent, and the wire as a thin grey tube; rendered offscreen with VTK as
   postprocess/render_column.py does (its own Xvfb when DISPLAY is unset).

Uses numpy, matplotlib (Agg) and, for the picture, python3-vtk9."""

import argparse
import glob
import json
import math
import os
import re
import sys

import numpy as np

# compute contact/local's columns (c_ID[k]) that are read
CONTACT_COLUMNS = {1: "kind", 2: "a", 3: "b", 4: "px", 5: "py", 6: "pz", 7: "nx", 8: "ny", 9: "nz", 10: "fn",
                   11: "fx", 12: "fy", 13: "fz", 16: "status"}
KINDS = {0: "wire_wire", 1: "wire_wall", 2: "wire_grain", 3: "grain_grain", 4: "grain_wall"}
GRAIN_GRAIN, GRAIN_WALL, WIRE_GRAIN, WIRE_WALL = 3, 4, 2, 1


def fail(message):
    sys.exit(f"force_network.py: {message}")


# --- reading ------------------------------------------------------------------------------

def read_snapshot(path):
    """The last snapshot of a LAMMPS text dump (custom or local): (step, column names, rows)."""
    try:
        with open(path) as f:
            lines = f.read().splitlines()
    except OSError as e:
        fail(f"cannot read {path} ({e.strerror})")
    starts = [k for k, line in enumerate(lines) if line.startswith("ITEM: TIMESTEP")]
    if not starts:
        fail(f"{path}: no snapshot (not a LAMMPS text dump)")
    block = lines[starts[-1]:]
    try:
        step, count = int(block[1]), int(block[3])
        head = next(k for k, line in enumerate(block) if line.startswith(("ITEM: ATOMS", "ITEM: ENTRIES")))
    except (IndexError, ValueError, StopIteration):
        fail(f"{path}: the last snapshot has no header of atoms or entries")
    names = block[head].split()[2:]
    rows = block[head + 1:head + 1 + count]
    values = " ".join(rows).split()
    if len(rows) < count or len(values) != count * len(names):
        fail(f"{path}: the last snapshot is cut short ({len(rows)} of {count} rows of {len(names)} values)")
    return step, names, np.array(values, dtype=float).reshape(count, len(names))


def read_contacts(path):
    """The rows of compute contact/local as {name: array} (CONTACT_COLUMNS), found by the
    k of their c_ID[k] headers."""
    step, names, data = read_snapshot(path)
    index = {}
    for j, name in enumerate(names):
        found = re.fullmatch(r"c_\w+\[(\d+)\]", name)
        if found:
            index.setdefault(int(found.group(1)), j)
    missing = [f"c_ID[{k}] ({what})" for k, what in CONTACT_COLUMNS.items() if k not in index]
    if missing:
        fail(f"{path}: no column {', '.join(missing)}; dump the 16 columns of compute contact/local")
    contacts = {what: data[:, index[k]] for k, what in CONTACT_COLUMNS.items()}
    contacts["kind"] = contacts["kind"].astype(int)
    contacts["a"] = contacts["a"].astype(np.int64)
    contacts["b"] = contacts["b"].astype(np.int64)
    contacts["point"] = np.column_stack([contacts.pop(c) for c in ("px", "py", "pz")])
    contacts["normal"] = np.column_stack([contacts.pop(c) for c in ("nx", "ny", "nz")])
    contacts["force"] = np.column_stack([contacts.pop(c) for c in ("fx", "fy", "fz")])
    contacts["step"] = step
    return contacts


def read_custom(path, needed):
    """A dump custom's last snapshot as {column: array}, sorted by id; fails naming a
    missing column of `needed`."""
    step, names, data = read_snapshot(path)
    missing = [n for n in needed if n not in names]
    if missing:
        fail(f"{path}: no column {', '.join(missing)} (its columns: {' '.join(names)})")
    data = data[np.argsort(data[:, names.index("id")], kind="stable")]
    table = {name: data[:, j] for j, name in enumerate(names)}
    table["id"] = table["id"].astype(np.int64)
    table["step"] = step
    return table


class Grains:
    """The grains of a dump: ids, masses, centres, and a map id → row."""

    def __init__(self, table, stress):
        self.id = table["id"]
        self.mass = table["mass"]
        self.x = np.column_stack([table["x"], table["y"], table["z"]])
        self.sigma_zz = table[stress] if stress in table else None
        self.row = {int(i): k for k, i in enumerate(self.id)}

    def rows_of(self, ids):
        """Rows of these ids (−1 where an id is no grain of the dump)."""
        return np.array([self.row.get(int(i), -1) for i in ids], dtype=np.int64)


# --- contacts ------------------------------------------------------------------------------

def contacts_of(rows, kind, per_point=False):
    """The contacts of one kind: the rows of a pair summed (module doc, "A contact"), or each
    row with per_point. Returns {lo, hi, fn, normal, point, force (on hi), rows, open_rows}."""
    sel = rows["kind"] == kind
    a, b = rows["a"][sel], rows["b"][sel]
    closed = (rows["status"][sel] != 0) & (rows["fn"][sel] > 0)
    fn = np.where(closed, rows["fn"][sel], 0.0)
    lo, hi = np.minimum(a, b), np.maximum(a, b)
    sign = np.where(a == lo, 1.0, -1.0)   # a row listed from the higher ID: its normal and force turn
    if per_point:
        group, first = np.arange(len(a)), np.arange(len(a))
    elif len(a):
        _, first, group = np.unique(np.column_stack([lo, hi]), axis=0, return_index=True, return_inverse=True)
        group = group.ravel()
    else:
        group, first = np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
    m = len(first)

    def sums(weights):   # per contact (float also when there is none)
        return np.bincount(group, weights, m).astype(float)

    total = sums(fn)
    normal = np.column_stack([sums(fn * sign * rows["normal"][sel][:, j]) for j in range(3)]).reshape(m, 3)
    point = np.column_stack([sums(fn * rows["point"][sel][:, j]) for j in range(3)]).reshape(m, 3)
    force = np.column_stack([sums(np.where(closed, sign, 0.0) * rows["force"][sel][:, j]) for j in range(3)]).reshape(m, 3)
    on = total > 0
    length = np.linalg.norm(normal, axis=1)
    normal[on] /= np.where(length[on] > 0, length[on], 1.0)[:, None]
    point[on] /= total[on][:, None]
    point[~on] = rows["point"][sel][first[~on]]
    return {"lo": lo[first], "hi": hi[first], "fn": total, "normal": normal, "point": point, "force": force,
            "rows": int(sel.sum()), "open_rows": int((~closed).sum())}


def force_distribution(fn, bin_width):
    """Item 1 of the module doc for the normal forces fn (open ones, f_n = 0, counted apart)."""
    f = fn[fn > 0]
    out = {"contacts": int(len(fn)), "closed": int(len(f)), "open": int((fn <= 0).sum()),
           "mean_f": float(f.mean()) if len(f) else float("nan"), "bin_width": bin_width}
    if not len(f):
        out.update(edges=[], counts=[], density=[], beta=float("nan"), beta_error=float("nan"), tail=0)
        return out
    x = f / f.mean()
    bins = max(1, int(math.floor(x.max() / bin_width)) + 1)
    edges = bin_width * np.arange(bins + 1)
    counts = np.histogram(x, edges)[0]
    tail = x[x > 1.0] - 1.0
    n_t = len(tail)
    beta = (n_t - 1) / tail.sum() if n_t >= 2 and tail.sum() > 0 else float("nan")
    error = beta / math.sqrt(n_t - 2) if n_t > 2 else float("nan")
    out.update(edges=edges.tolist(), counts=counts.tolist(), density=(counts / (len(f) * bin_width)).tolist(),
               beta=float(beta), beta_error=float(error), tail=int(n_t), tail_fraction=n_t / len(f),
               max_x=float(x.max()))
    return out


def fabric(normals, weights=None):
    """φ_ij = Σ w n_i n_j / Σ w, its eigenvalues (ascending), major axis and that axis'
    angle from the vertical (degrees)."""
    if len(normals) == 0:
        return None
    w = np.ones(len(normals)) if weights is None else np.asarray(weights, dtype=float)
    phi = (normals * w[:, None]).T @ normals / w.sum()
    values, vectors = np.linalg.eigh(phi)
    values = np.maximum(values, 0.0)   # φ is positive semi-definite: −1e-17 is round-off
    major = vectors[:, -1] * (1.0 if vectors[2, -1] >= 0 else -1.0)
    angle = math.degrees(math.acos(min(1.0, abs(major[2]))))
    return {"tensor": phi.tolist(), "eigenvalues": values.tolist(), "major_axis": major.tolist(),
            "angle_from_vertical": angle}


def networks(contacts):
    """Item 2: the strong (f_n > ⟨f⟩), weak and whole networks of the closed contacts."""
    on = contacts["fn"] > 0
    f, n = contacts["fn"][on], contacts["normal"][on]
    if not len(f):
        return {}
    mean = f.mean()
    out = {}
    for name, sel in (("strong", f > mean), ("weak", f <= mean), ("all", np.ones(len(f), bool))):
        out[name] = {"contacts": int(sel.sum()), "fraction_of_contacts": float(sel.mean()),
                     "fraction_of_force": float(f[sel].sum() / f.sum()),
                     "fabric": fabric(n[sel]), "fabric_weighted": fabric(n[sel], f[sel])}
    return out


# --- stresses, walls, transmission ------------------------------------------------------------

def bin_index(values, edges):
    """The bin of each value in edges (the last edge included); −1 outside."""
    k = np.searchsorted(edges, values, side="right") - 1
    k[values == edges[-1]] = len(edges) - 2
    k[(values < edges[0]) | (values > edges[-1])] = -1
    return k


def stress_bins(grains, density, axis, r_edges, z_edges):
    """Item 3: the volume-weighted mean σ_zz, the coarse-grained σ_zz and the solid fraction
    per (r, z) bin and along each of the two."""
    volume = grains.mass / density
    r = np.hypot(grains.x[:, 0] - axis[0], grains.x[:, 1] - axis[1])
    ir, iz = bin_index(r, r_edges), bin_index(grains.x[:, 2], z_edges)
    inside = (ir >= 0) & (iz >= 0)
    shape = (len(r_edges) - 1, len(z_edges) - 1)
    vs, v, count = np.zeros(shape), np.zeros(shape), np.zeros(shape, dtype=int)
    np.add.at(vs, (ir[inside], iz[inside]), volume[inside] * grains.sigma_zz[inside])
    np.add.at(v, (ir[inside], iz[inside]), volume[inside])
    np.add.at(count, (ir[inside], iz[inside]), 1)
    bin_volume = np.pi * np.diff(r_edges ** 2)[:, None] * np.diff(z_edges)[None, :]

    def summary(vs, v, count, bin_volume):
        with np.errstate(invalid="ignore", divide="ignore"):
            mean = np.where(v > 0, vs / v, np.nan)
        return {"mean": mean.tolist(), "coarse": (vs / bin_volume).tolist(), "solid_fraction": (v / bin_volume).tolist(),
                "grains": count.tolist()}

    return {"r_edges": r_edges.tolist(), "z_edges": z_edges.tolist(), "map": summary(vs, v, count, bin_volume),
            "along_z": summary(vs.sum(0), v.sum(0), count.sum(0), bin_volume.sum(0)),
            "along_r": summary(vs.sum(1), v.sum(1), count.sum(1), bin_volume.sum(1)),
            "outside": int((~inside).sum())}


def side_of(normal_z):
    return "floor" if normal_z > 0.5 else "plate" if normal_z < -0.5 else "side"


def wall_loads(rows):
    """The walls' forces from the grain–wall rows (per wall index) and the wire–wall rows
    (per side, by the normal: the wire's walls are each the first of their fix)."""
    walls = []
    for kind, body in ((GRAIN_WALL, "grains"), (WIRE_WALL, "wire")):
        sel = rows["kind"] == kind
        wall = -np.minimum(rows["a"][sel], rows["b"][sel])
        closed = (rows["status"][sel] != 0) & (rows["fn"][sel] > 0)
        side = np.array([side_of(nz) for nz in rows["normal"][sel][:, 2]], dtype=object)
        keys = sorted(set(zip(wall.tolist(), side.tolist()))) if kind == WIRE_WALL else \
            sorted(set((w, None) for w in wall.tolist()))
        for w, s in keys:
            mine = (wall == w) & ((side == s) if s is not None else True)
            on = mine & closed
            mean_nz = float(rows["normal"][sel][mine][:, 2].mean())
            walls.append({"by": body, "wall": int(w), "side": s if s is not None else side_of(mean_nz),
                          "rows": int(mine.sum()), "closed": int(on.sum()),
                          "force_on_wall": (-rows["force"][sel][on].sum(0)).tolist(),
                          "load": float(rows["fn"][sel][on].sum())})
    return walls


def transmission(rows, grains, planes, radius, axis, r_edges, g):
    """Item 3, where the load goes: per plane z = h the force T through it and the balance of
    the grains above it."""
    gg = rows["kind"] == GRAIN_GRAIN
    ra, rb = grains.rows_of(rows["a"][gg]), grains.rows_of(rows["b"][gg])
    if (ra < 0).any() or (rb < 0).any():
        missing = sorted(set(rows["a"][gg][ra < 0].tolist()) | set(rows["b"][gg][rb < 0].tolist()))
        fail(f"grain–grain contacts name grains the grains dump does not hold: {missing[:10]}")
    za, zb = grains.x[ra, 2], grains.x[rb, 2]
    fz = rows["force"][gg][:, 2]
    r = np.hypot(rows["point"][gg][:, 0] - axis[0], rows["point"][gg][:, 1] - axis[1])
    others = external_forces(rows, grains)
    out = []
    for h in planes:
        up_b, up_a = (za < h) & (zb >= h), (zb < h) & (za >= h)   # the upper grain is b, or a
        t = np.where(up_b, fz, 0.0) - np.where(up_a, fz, 0.0)
        crossing = up_a | up_b
        per_bin = np.bincount(np.maximum(bin_index(r, r_edges), 0), t * (bin_index(r, r_edges) >= 0),
                              len(r_edges) - 1)
        inner = t[r < radius / 2].sum()
        above = grains.x[:, 2] >= h
        weight = g * grains.mass[above].sum()
        walls, wire = others["walls"][above].sum(), others["wire"][above].sum()
        total = t.sum()
        out.append({"z": float(h), "crossing": int(crossing.sum()),
                    "crossing_closed": int((crossing & (rows["fn"][gg] > 0) & (rows["status"][gg] != 0)).sum()),
                    "T": float(total), "T_inner": float(inner), "T_outer": float(total - inner),
                    "inner_fraction": float(inner / total) if total != 0 else float("nan"),
                    "T_per_r_bin": per_bin.tolist(),
                    "grains_above": int(above.sum()), "weight_above": float(weight),
                    "walls_on_above": float(walls), "wire_on_above": float(wire),
                    "residual": float(total - weight + walls + wire)})
    return out


def external_forces(rows, grains):
    """Per grain the vertical force of the walls (kind 4) and of the wire (kind 2) on it."""
    out = {}
    for name, kind in (("walls", GRAIN_WALL), ("wire", WIRE_GRAIN)):
        sel = rows["kind"] == kind
        a, b, fz = rows["a"][sel], rows["b"][sel], rows["force"][sel][:, 2]
        rb, ra = grains.rows_of(b), grains.rows_of(a)
        on_b = rb >= 0
        grain = np.where(on_b, rb, ra)
        force = np.where(on_b, fz, -fz)   # the force listed is b's; a receives its opposite
        per = np.zeros(len(grains.id))
        np.add.at(per, grain[grain >= 0], force[grain >= 0])
        out[name] = per
    return out


def confinement(rows, grains, wire, tension, axis, radius, square, z_bins, density):
    """Item 5: the sideways confinement of the grains per height slab, by the wire and the
    side walls, against their vertical stress."""
    wg, gw = rows["kind"] == WIRE_GRAIN, rows["kind"] == GRAIN_WALL
    closed = (rows["status"] != 0) & (rows["fn"] > 0)
    # the wire: the force on the grain (listed on b; a grain listed as a receives its opposite)
    on_b = grains.rows_of(rows["b"][wg]) >= 0
    force = np.where(on_b[:, None], rows["force"][wg], -rows["force"][wg]) * closed[wg][:, None]
    point = rows["point"][wg]
    rx, ry = point[:, 0] - axis[0], point[:, 1] - axis[1]
    r = np.hypot(rx, ry)
    with np.errstate(invalid="ignore", divide="ignore"):
        inward = np.where(r > 0, -(force[:, 0] * rx + force[:, 1] * ry) / r, 0.0)
    side = gw & closed & (np.abs(rows["normal"][:, 2]) < 0.5)
    top = max([float(grains.x[:, 2].max())] + point[:, 2].tolist())
    edges = np.linspace(0.0, top * (1 + 1e-12) + 1e-12, z_bins + 1)
    dz = np.diff(edges)

    def per_slab(z, values):
        k = bin_index(np.asarray(z, dtype=float), edges)
        return np.bincount(k[k >= 0], np.asarray(values, dtype=float)[k >= 0], z_bins)

    q_wire = per_slab(point[:, 2], inward) / dz
    q_walls = per_slab(rows["point"][side][:, 2], rows["fn"][side]) / dz
    if square is not None:
        perimeter, area = 4.0 * square, square ** 2
        inside = (np.abs(grains.x[:, 0] - axis[0]) <= square / 2) & (np.abs(grains.x[:, 1] - axis[1]) <= square / 2)
    else:
        perimeter, area = 2.0 * np.pi * radius, np.pi * radius ** 2
        inside = np.hypot(grains.x[:, 0] - axis[0], grains.x[:, 1] - axis[1]) <= radius
    if grains.sigma_zz is not None:
        vs = (grains.mass / density) * grains.sigma_zz
        sigma_v = -per_slab(grains.x[inside, 2], vs[inside]) / (area * dz)
    else:
        sigma_v = np.full(z_bins, np.nan)
    q_hoop = np.zeros(z_bins)
    if wire is not None and tension is not None and tension["segments"]:
        # each segment pulls its two beads towards each other with its tension T
        row = {int(i): k for k, i in enumerate(wire["id"])}
        here = np.array([row[int(i)] for i in tension["id"]], dtype=np.int64)
        nxt = np.array([row.get(int(i) + 1, -1) for i in tension["id"]], dtype=np.int64)
        ok = nxt >= 0
        xyz = np.column_stack([wire["x"], wire["y"], wire["z"]])
        chord = xyz[nxt[ok]] - xyz[here[ok]]
        pull = np.array(tension["tension"])[ok][:, None] * chord / np.linalg.norm(chord, axis=1)[:, None]
        on_bead = np.zeros_like(xyz)
        np.add.at(on_bead, here[ok], pull)
        np.add.at(on_bead, nxt[ok], -pull)
        bx, by = wire["x"] - axis[0], wire["y"] - axis[1]
        rb = np.hypot(bx, by)
        with np.errstate(invalid="ignore", divide="ignore"):
            bead_inward = np.where(rb > 0, -(on_bead[:, 0] * bx + on_bead[:, 1] * by) / rb, 0.0)
        q_hoop = per_slab(wire["z"], bead_inward) / dz
    pressure = (q_wire + q_walls) / perimeter
    with np.errstate(invalid="ignore", divide="ignore"):
        ratio = np.where(sigma_v > 0, pressure / sigma_v, np.nan)
    return {"section": "square" if square is not None else "circle", "perimeter": perimeter, "area": area,
            "z_edges": edges.tolist(), "q_wire": q_wire.tolist(), "q_walls": q_walls.tolist(),
            "q_hoop": q_hoop.tolist(), "pressure": pressure.tolist(), "sigma_v": sigma_v.tolist(),
            "K": ratio.tolist(), "F_wire": float((q_wire * dz).sum()), "F_walls": float((q_walls * dz).sum()),
            "grains_inside": int(inside.sum())}


# --- wire -------------------------------------------------------------------------------------

def wire_tension(wire, energy, young, m_elo, l0):
    """Item 4: the tension of every segment and the stretching-energy check."""
    length = wire[f"{energy}[3]"]
    seg = length > 0
    area = np.pi * wire["radius"] ** 2
    stiffness = m_elo * young * area / l0
    tension = stiffness * (length - l0)
    u_seg = np.where(seg, 0.5 * stiffness * (length - l0) ** 2, 0.0)
    # bead j: half of its own segment and half of the previous bead's (ID j − 1)
    row = {int(i): k for k, i in enumerate(wire["id"])}
    previous = np.array([row.get(int(i) - 1, -1) for i in wire["id"]])
    u_bead = 0.5 * u_seg + 0.5 * np.where(previous >= 0, u_seg[np.maximum(previous, 0)], 0.0)
    # the mean tension in 10 bins of the beads' heights
    z = wire["z"][seg]
    edges = np.linspace(z.min(), z.max() * (1 + 1e-12) + 1e-12, 11) if seg.any() else np.zeros(1)
    k = bin_index(z, edges) if seg.any() else np.zeros(0, dtype=int)
    count = np.bincount(k, minlength=len(edges) - 1)
    with np.errstate(invalid="ignore", divide="ignore"):
        profile = np.bincount(k, tension[seg], len(edges) - 1) / count
    dumped = wire[f"{energy}[1]"]
    scale = max(np.abs(dumped).max(), 1e-300)
    return {"segments": int(seg.sum()), "id": wire["id"][seg].tolist(), "z": wire["z"][seg].tolist(),
            "tension": tension[seg].tolist(), "profile_z": (0.5 * (edges[1:] + edges[:-1]))[count > 0].tolist(),
            "profile_tension": profile[count > 0].tolist(),
            "tension_mean": float(tension[seg].mean()) if seg.any() else float("nan"),
            "tension_max": float(tension[seg].max()) if seg.any() else float("nan"),
            "tension_min": float(tension[seg].min()) if seg.any() else float("nan"),
            "stretching_energy": float(u_seg.sum()), "stretching_energy_dumped": float(dumped.sum()),
            "bead_energy_difference": float(np.abs(u_bead - dumped).max() / scale) if len(dumped) else 0.0}


def wire_radius(wire, axis):
    return float(np.hypot(wire["x"] - axis[0], wire["y"] - axis[1]).mean())


# --- plots ----------------------------------------------------------------------------------------

def plots(result, out_base):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    written = []
    d = result["forces"]
    if d["closed"]:
        fig, ax = plt.subplots(figsize=(6, 4.5))
        edges, density = np.array(d["edges"]), np.array(d["density"])
        shown = density > 0
        ax.bar(edges[:-1][shown], density[shown], width=d["bin_width"], align="edge", color="0.75", edgecolor="0.4",
               label=f"{d['closed']} closed grain–grain contacts")
        if np.isfinite(d["beta"]):
            x = np.linspace(1.0, edges[-1], 50)
            ax.plot(x, d["tail_fraction"] * d["beta"] * np.exp(-d["beta"] * (x - 1.0)), "C3",
                    label=f"exp(−β x), β = {d['beta']:.2f} ± {d['beta_error']:.2f}")
        ax.set_yscale("log")
        ax.set_xlabel("f_n / ⟨f⟩")
        ax.set_ylabel("P(f_n / ⟨f⟩)")
        ax.set_title(f"normal forces, ⟨f⟩ = {d['mean_f']:.3g}")
        ax.legend(fontsize=8)
        written.append(save(fig, out_base + "_forces.png"))
    s = result["stress"]
    if s is not None:
        written.append(stress_plot(plt, s, result["walls"], out_base + "_stress.png"))
    if result["transmission"]:
        written.append(transmission_plot(plt, result, out_base + "_transmission.png"))
    written.append(confinement_plot(plt, result["confinement"], out_base + "_confinement.png"))
    if result["wire"] is not None and result["wire"]["segments"]:
        w = result["wire"]
        fig, ax = plt.subplots(figsize=(6, 4.5))
        ax.plot(w["tension"], w["z"], ".", ms=3, color="C0", label="segments")
        ax.plot(w["profile_tension"], w["profile_z"], "o-", color="C1", label="mean per height bin")
        ax.axvline(0, color="0.6", lw=0.6)
        ax.legend(fontsize=8)
        ax.set_xlabel("segment tension T")
        ax.set_ylabel("bead height z")
        ax.set_title(f"wire: {w['segments']} segments, mean T = {w['tension_mean']:.3g}")
        written.append(save(fig, out_base + "_wire.png"))
    return written


def confinement_plot(plt, c, path):
    z = 0.5 * (np.array(c["z_edges"][1:]) + np.array(c["z_edges"][:-1]))
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(9, 4.5), sharey=True)
    ax.plot(np.array(c["q_wire"]) / c["perimeter"], z, "o-", color="C0", label="wire (its contacts)")
    ax.plot(np.array(c["q_hoop"]) / c["perimeter"], z, "x--", color="C0", label="wire (its tension's hoop force)")
    ax.plot(np.array(c["q_walls"]) / c["perimeter"], z, "s-", color="C3", label="side walls")
    ax.plot(c["sigma_v"], z, "^-", color="0.3", label="σ_v of the grains inside")
    ax.axvline(0, color="0.6", lw=0.6)
    ax.set_xlabel(f"pressure on the {c['section']} section's side, σ_v")
    ax.set_ylabel("z")
    ax.legend(fontsize=8)
    bx.plot(c["K"], z, "o-", color="C2")
    bx.set_xlabel("K = p / σ_v")
    fig.suptitle("confinement per height slab")
    return save(fig, path)


def save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    import matplotlib.pyplot as plt
    plt.close(fig)
    return path


def stress_plot(plt, s, walls, path):
    r_edges, z_edges = np.array(s["r_edges"]), np.array(s["z_edges"])
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.5))
    mean = -np.array(s["map"]["mean"], dtype=float)
    image = axes[0].pcolormesh(r_edges, z_edges, np.ma.masked_invalid(mean).T, cmap="viridis", shading="flat")
    fig.colorbar(image, ax=axes[0], label="−σ_zz (mean over the grains)")
    axes[0].set_xlabel("r")
    axes[0].set_ylabel("z")
    zc, rc = 0.5 * (z_edges[1:] + z_edges[:-1]), 0.5 * (r_edges[1:] + r_edges[:-1])
    axes[1].plot(-np.array(s["along_z"]["mean"], dtype=float), zc, "o-", label="mean over the grains")
    axes[1].plot(-np.array(s["along_z"]["coarse"], dtype=float), zc, "s--", label="Σ V σ_zz / V_bin")
    axes[1].set_xlabel("−σ_zz")
    axes[1].set_ylabel("z")
    axes[2].plot(rc, -np.array(s["along_r"]["mean"], dtype=float), "o-", label="mean over the grains")
    axes[2].plot(rc, -np.array(s["along_r"]["coarse"], dtype=float), "s--", label="Σ V σ_zz / V_bin")
    axes[2].set_xlabel("r")
    axes[2].set_ylabel("−σ_zz")
    axes[0].set_title("by r and z")
    axes[1].set_title("by height")
    axes[2].set_title("by distance from the axis")
    for ax in axes[1:]:
        ax.legend(fontsize=8)
    loads = "; ".join(f"{w['by']} on {w['side']} {w['wall']}: {w['load']:.3g}" for w in walls)
    fig.suptitle(f"vertical stress (compression positive); wall loads: {loads}", fontsize=8)
    return save(fig, path)


def transmission_plot(plt, result, path):
    planes, r_edges = result["transmission"], np.array(result["stress"]["r_edges"])
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    area = np.pi * np.diff(r_edges ** 2)
    rc = 0.5 * (r_edges[1:] + r_edges[:-1])
    for p in planes:
        axes[0].plot(rc, np.array(p["T_per_r_bin"]) / area, "o-", label=f"z = {p['z']:.3g}")
    axes[0].axvline(result["R"] / 2, color="0.6", ls=":", lw=0.8)
    axes[0].set_xlabel("r of the contact point")
    axes[0].set_ylabel("transmitted force per area")
    axes[0].legend(fontsize=7)
    z = [p["z"] for p in planes]
    axes[1].plot([p["T"] for p in planes], z, "o-", label="T through the plane")
    axes[1].plot([p["weight_above"] - p["walls_on_above"] - p["wire_on_above"] for p in planes], z, "x--",
                 label="W above − walls − wire (at rest)")
    axes[1].plot([p["T_inner"] for p in planes], z, "s:", label=f"T within r < R/2 = {result['R'] / 2:.3g}")
    axes[1].set_xlabel("force")
    axes[1].set_ylabel("plane height z")
    axes[1].legend(fontsize=7)
    return save(fig, path)


# --- picture ------------------------------------------------------------------------------------

def bars(contacts_gg, contacts_gw, grains):
    """The bars of the picture: (start points, end points, f_n) of the closed contacts."""
    starts, ends, forces = [], [], []
    on = contacts_gg["fn"] > 0
    lo, hi = grains.rows_of(contacts_gg["lo"][on]), grains.rows_of(contacts_gg["hi"][on])
    keep = (lo >= 0) & (hi >= 0)
    starts.append(grains.x[lo[keep]])
    ends.append(grains.x[hi[keep]])
    forces.append(contacts_gg["fn"][on][keep])
    on = contacts_gw["fn"] > 0
    grain = grains.rows_of(contacts_gw["hi"][on])
    keep = grain >= 0
    starts.append(grains.x[grain[keep]])
    ends.append(contacts_gw["point"][on][keep])
    forces.append(contacts_gw["fn"][on][keep])
    return np.concatenate(starts), np.concatenate(ends), np.concatenate(forces)


def picture(args, vtp, contacts_gg, contacts_gw, grains, wire, path):
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import render_column
    xvfb = render_column.start_xvfb(*(args.size or (1200, 1200)))
    try:
        return draw(args, vtp, contacts_gg, contacts_gw, grains, wire, path, render_column)
    finally:
        if xvfb is not None:
            xvfb.terminate()
            xvfb.wait()


def tube_polydata(starts, ends, arrays):
    """Lines from starts to ends, with point arrays {name: per-line values}."""
    import vtk
    from vtkmodules.util.numpy_support import numpy_to_vtk
    points = vtk.vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(np.column_stack([starts, ends]).reshape(-1, 3)), deep=True))
    lines = vtk.vtkCellArray()
    for k in range(len(starts)):
        lines.InsertNextCell(2)
        lines.InsertCellPoint(2 * k)
        lines.InsertCellPoint(2 * k + 1)
    data = vtk.vtkPolyData()
    data.SetPoints(points)
    data.SetLines(lines)
    for name, values in arrays.items():
        array = numpy_to_vtk(np.ascontiguousarray(np.repeat(values, 2)), deep=True)
        array.SetName(name)
        data.GetPointData().AddArray(array)
    return data


def draw(args, vtp, contacts_gg, contacts_gw, grains, wire, path, rc):
    import vtk
    from vtk_files import read_polydata
    starts, ends, forces = bars(contacts_gg, contacts_gw, grains)
    keep = np.linalg.norm(ends - starts, axis=1) > 1e-9
    starts, ends, forces = starts[keep], ends[keep], forces[keep]
    f_max = float(forces.max()) if len(forces) else 1.0
    renderer = vtk.vtkRenderer()
    renderer.SetBackground(1.0, 1.0, 1.0)
    renderer.SetUseDepthPeeling(1)
    renderer.SetMaximumNumberOfPeels(12)
    vtk.vtkLightKit().AddLightsToRenderer(renderer)
    datasets = []
    if vtp is not None:
        shapes = read_polydata(vtp)
        datasets.append(shapes)
        actor = rc.grain_actor(shapes)
        actor.GetProperty().SetOpacity(args.grain_opacity)
        renderer.AddActor(actor)
    lut = rc.energy_lookup(0.0, f_max)
    if len(forces):
        radius = args.bar_radius * np.maximum(forces / f_max, 0.1)
        data = tube_polydata(starts, ends, {"radius": radius, "f_n": forces})
        data.GetPointData().SetActiveScalars("radius")
        datasets.append(data)
        tube = vtk.vtkTubeFilter()
        tube.SetInputData(data)
        tube.SetVaryRadiusToVaryRadiusByAbsoluteScalar()
        tube.SetNumberOfSides(10)
        tube.CappingOn()
        mapper = vtk.vtkPolyDataMapper()
        mapper.SetInputConnection(tube.GetOutputPort())
        mapper.SetScalarModeToUsePointFieldData()
        mapper.SelectColorArray("f_n")
        mapper.SetLookupTable(lut)
        mapper.UseLookupTableScalarRangeOn()
        actor = vtk.vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetSpecular(0.2)
        renderer.AddActor(actor)
    if wire is not None and not args.no_wire_picture:
        add_wire(renderer, wire, datasets)
    if not datasets:
        fail("nothing to draw")
    bounds = rc.union_bounds(datasets)
    elevation, azimuth = rc.VIEWS[args.view]
    frame = rc.view_frame(bounds, elevation, azimuth)
    bar_width = 0.14
    if args.size is not None:
        width, height = args.size
    else:   # 1200 wide, as tall as the scene asks below the title band (between 400 and 1200)
        width = 1200
        height = int(round(min(1200, max(400, (1 - bar_width) * width * frame[4] / frame[3] / 0.9))))
    renderer.SetViewport(0.0, 0.0, 1.0 - bar_width, 1.0)
    title = f"contact normal forces, step {grains_step(grains)}: {len(forces)} contacts, max f_n {f_max:.3g}"
    renderer.AddActor2D(rc.text_actor(title, max(12, height // 30), 0.5, 0.98))
    rc.place_camera(renderer, frame, (1.0 - bar_width) * width / height, True)
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(width, height)
    window.SetMultiSamples(0)
    window.SetAlphaBitPlanes(1)
    window.AddRenderer(renderer)
    font = max(12, height // 30)
    window.AddRenderer(rc.colour_bar_renderer(lut, bar_width, font, "f_n", font, 0.9))
    if not rc.write_png(window, path):
        fail(f"cannot write {path}")
    return path


def grains_step(grains):
    return getattr(grains, "step", "?")


def add_wire(renderer, wire, datasets):
    """The wire as a thin grey tube through consecutive beads (a segment: c_energy[3] > 0)."""
    import vtk
    x = np.column_stack([wire["x"], wire["y"], wire["z"]])
    row = {int(i): k for k, i in enumerate(wire["id"])}
    nxt = np.array([row.get(int(i) + 1, -1) for i in wire["id"]])
    seg = (nxt >= 0) & (wire["length"] > 0)
    if not seg.any():
        return
    data = tube_polydata(x[seg], x[nxt[seg]], {})
    datasets.append(data)
    tube = vtk.vtkTubeFilter()
    tube.SetInputData(data)
    tube.SetRadius(float(np.median(wire["radius"])) * 0.4)
    tube.SetNumberOfSides(8)
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(tube.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.6, 0.65, 0.72)
    actor.GetProperty().SetOpacity(0.35)
    renderer.AddActor(actor)


# --- the run ----------------------------------------------------------------------------------

def find_files(args):
    """The contacts, grains, wire and .vtp files (module doc, "Input")."""
    files = {"contacts": args.contacts, "grains": args.grains, "wire": args.wire, "vtp": args.vtp}
    if args.run is None:
        if not (args.contacts and args.grains):
            fail("give a RUN folder, or --contacts and --grains")
        return files
    post = args.run
    if not os.path.isdir(post):
        fail(f"{args.run} is not a folder")
    if os.path.isdir(os.path.join(post, "post")):
        post = os.path.join(post, "post")
    pattern = os.path.join(post, f"{args.prefix}_contacts_*.dump")
    steps = sorted(int(m.group(1)) for m in (re.search(r"_contacts_(\d+)\.dump$", p) for p in glob.glob(pattern)) if m)
    step = args.step
    if step is None:
        if not steps and not args.contacts:
            fail(f"no {args.prefix}_contacts_STEP.dump in {post}")
        step = steps[-1] if steps else None
    elif steps and step not in steps:
        fail(f"--step {step}: {post} has {args.prefix}_contacts_STEP.dump for steps {' '.join(map(str, steps))}")
    for name, kind in (("contacts", "contacts_{}.dump"), ("grains", "grains_{}.dump"), ("wire", "wire_{}.dump"),
                       ("vtp", "grains_{}.vtp")):
        if files[name] is None and step is not None:
            candidate = os.path.join(post, f"{args.prefix}_" + kind.format(step))
            if name in ("contacts", "grains") or os.path.exists(candidate):
                files[name] = candidate
    return files


def analyse(args, files):
    rows = read_contacts(files["contacts"])
    table = read_custom(files["grains"], ["id", "mass", "x", "y", "z", args.stress])
    grains = Grains(table, args.stress)
    grains.step = table["step"]
    wire = None
    if files["wire"]:
        needed = ["id", "x", "y", "z", f"{args.energy}[1]", f"{args.energy}[3]"]
        wire = read_custom(files["wire"], needed)
        if "radius" not in wire:
            wire["radius"] = np.full(len(wire["id"]), args.r_w)
        wire["length"] = wire[f"{args.energy}[3]"]
    axis = args.axis
    gg = contacts_of(rows, GRAIN_GRAIN, args.per_point)
    gw = contacts_of(rows, GRAIN_WALL, args.per_point)
    if args.R is not None:
        radius, radius_from = args.R, "--R"
    elif wire is not None and len(wire["id"]):
        radius, radius_from = wire_radius(wire, axis), "the wire's mean radius"
    else:
        radius = float(np.hypot(grains.x[:, 0] - axis[0], grains.x[:, 1] - axis[1]).max())
        radius_from = "the farthest grain centre"
    r_grains = np.hypot(grains.x[:, 0] - axis[0], grains.x[:, 1] - axis[1])
    r_outer = args.r_max if args.r_max is not None else max(float(r_grains.max()), radius) * (1 + 1e-12)
    r_edges = np.linspace(0.0, r_outer, args.r_bins + 1)
    z_edges = np.linspace(0.0, float(grains.x[:, 2].max()) * (1 + 1e-12), args.z_bins + 1)
    if args.plane_z:
        planes = list(args.plane_z)
    else:
        lo, hi = float(grains.x[:, 2].min()), float(grains.x[:, 2].max())
        planes = [lo + (hi - lo) * k / (args.planes + 1) for k in range(1, args.planes + 1)]
    counts = {KINDS[k]: int((rows["kind"] == k).sum()) for k in KINDS}
    result = {"step": rows["step"], "files": files, "rows": counts, "per_point": args.per_point,
              "forces": force_distribution(gg["fn"], args.bin_width), "networks": networks(gg),
              "grain_grain_rows": {"rows": gg["rows"], "open_rows": gg["open_rows"]},
              "grain_wall": {"contacts": len(gw["fn"]), "closed": int((gw["fn"] > 0).sum())},
              "stress": stress_bins(grains, args.density, axis, r_edges, z_edges) if grains.sigma_zz is not None else None,
              "walls": wall_loads(rows), "R": radius, "R_from": radius_from, "axis": list(axis),
              "transmission": transmission(rows, grains, planes, radius, axis, r_edges, args.g),
              "wire": wire_tension(wire, args.energy, args.E_w, args.m_elo, args.l0) if wire is not None else None}
    result["confinement"] = confinement(rows, grains, wire, result["wire"], axis, radius, args.section_square,
                                        args.z_bins, args.density)
    return result, (gg, gw, grains, wire)


def report(result):
    """The printed summary."""
    d, lines = result["forces"], []
    lines.append(f"step {result['step']}: rows {', '.join(f'{k} {v}' for k, v in result['rows'].items())}")
    what = "rows" if result["per_point"] else "pairs"
    lines.append(f"grain-grain contacts ({what}): {d['contacts']}, open {d['open']}, closed {d['closed']}; "
                 f"<f> = {d['mean_f']:.6g}")
    if d["closed"]:
        lines.append(f"tail f/<f> > 1: {d['tail']} contacts, beta = {d['beta']:.4g} +- {d['beta_error']:.2g}")
    for name, n in result["networks"].items():
        fw, f = n["fabric_weighted"], n["fabric"]
        if f is None:
            lines.append(f"{name:6s} network: no contacts")
            continue
        lines.append(f"{name:6s} network: {n['contacts']} contacts ({n['fraction_of_contacts']:.3f}), "
                     f"force fraction {n['fraction_of_force']:.3f}; fabric eigenvalues "
                     f"{' '.join(f'{v:.3f}' for v in f['eigenvalues'])} (major axis {f['angle_from_vertical']:.1f} deg "
                     f"from vertical), f_n-weighted {' '.join(f'{v:.3f}' for v in fw['eigenvalues'])} "
                     f"({fw['angle_from_vertical']:.1f} deg)")
    for w in result["walls"]:
        lines.append(f"wall {w['wall']} ({w['side']}) from the {w['by']}: {w['closed']} of {w['rows']} rows closed, "
                     f"load {w['load']:.6g}, force on the wall {' '.join(f'{v:.6g}' for v in w['force_on_wall'])}")
    s = result["stress"]
    if s is not None:
        zc = 0.5 * (np.array(s["z_edges"][1:]) + np.array(s["z_edges"][:-1]))
        lines.append("sigma_zz by height (mean over the grains, coarse-grained): " + "; ".join(
            f"z {z:.3g}: {m:.4g}, {c:.4g}" for z, m, c in zip(zc, s["along_z"]["mean"], s["along_z"]["coarse"])))
    lines.append(f"R = {result['R']:.4g} ({result['R_from']})")
    for p in result["transmission"]:
        lines.append(f"plane z = {p['z']:.4g}: T = {p['T']:.6g} through {p['crossing_closed']} contacts, within "
                     f"r < R/2 {p['inner_fraction']:.3f}; above: {p['grains_above']} grains, weight "
                     f"{p['weight_above']:.6g}, walls {p['walls_on_above']:.6g}, wire {p['wire_on_above']:.6g}; "
                     f"residual {p['residual']:.3g}")
    c = result["confinement"]
    zc = 0.5 * (np.array(c["z_edges"][1:]) + np.array(c["z_edges"][:-1]))
    lines.append(f"confinement ({c['section']} section, perimeter {c['perimeter']:.4g}, area {c['area']:.4g}; "
                 f"wire {c['F_wire']:.6g}, side walls {c['F_walls']:.6g} in all), per slab z: q_wire, q_hoop, "
                 "q_walls, p, sigma_v, K: " + "; ".join(
                     f"z {z:.3g}: {a:.4g}, {h:.4g}, {b:.4g}, {p:.4g}, {v:.4g}, {k:.3g}" for z, a, h, b, p, v, k in
                     zip(zc, c["q_wire"], c["q_hoop"], c["q_walls"], c["pressure"], c["sigma_v"], c["K"])))
    w = result["wire"]
    if w is not None and w["segments"]:
        lines.append(f"wire: {w['segments']} segments, tension mean {w['tension_mean']:.4g}, min {w['tension_min']:.4g}, "
                     f"max {w['tension_max']:.4g}; stretching energy {w['stretching_energy']:.6g} against the dump's "
                     f"{w['stretching_energy_dumped']:.6g} (per bead differ by up to {w['bead_energy_difference']:.2g} "
                     f"of the largest)")
    return "\n".join(lines)


def finite(value):
    """value with NaN as None (JSON has no NaN)."""
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {k: finite(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [finite(v) for v in value]
    if isinstance(value, np.integer):
        return int(value)
    if isinstance(value, np.floating):
        return finite(float(value))
    return value


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run", nargs="?", help="the run's folder or its post/ folder")
    parser.add_argument("--step", type=int, help="the snapshot's step (default: the last)")
    parser.add_argument("--prefix", default="load", help="the dumps' name prefix (default load)")
    parser.add_argument("--contacts", help="the contacts dump (dump local of compute contact/local)")
    parser.add_argument("--grains", help="the grains dump (id mass x y z and σ_zz)")
    parser.add_argument("--wire", help="the wire dump (id x y z radius c_energy[1..3])")
    parser.add_argument("--vtp", help="the grains' shapes (dump polyhedron/vtk)")
    parser.add_argument("--out", help="the folder of the outputs (default: the contacts file's)")
    parser.add_argument("--per-point", action="store_true", help="each row a contact (default: each pair)")
    parser.add_argument("--bin-width", type=float, default=0.25, help="histogram bin in f/<f> (0.25)")
    parser.add_argument("--density", type=float, default=1.5, help="the grains' density (1.5)")
    parser.add_argument("--g", type=float, default=1.0, help="gravity (1)")
    parser.add_argument("--axis", type=float, nargs=2, default=[0.0, 0.0], metavar=("X", "Y"),
                        help="the column's vertical axis (0 0)")
    parser.add_argument("--R", type=float, help="the column's radius (default: the wire's mean radius)")
    parser.add_argument("--r-bins", type=int, default=4, help="bins of the distance from the axis (4)")
    parser.add_argument("--r-max", type=float,
                        help="the outer edge of the r bins (default: the farthest grain centre, or R if farther)")
    parser.add_argument("--z-bins", type=int, default=5, help="bins of the height (5)")
    parser.add_argument("--section", nargs="+", default=["circle"], metavar="SHAPE",
                        help="the confining section: circle (radius R) or square D (side D)")
    parser.add_argument("--planes", type=int, default=5, help="planes between the lowest and highest centres (5)")
    parser.add_argument("--plane-z", type=float, nargs="+", help="the planes' heights")
    parser.add_argument("--E-w", dest="E_w", type=float, default=100.0, help="the wire's Young's modulus (100)")
    parser.add_argument("--m-elo", dest="m_elo", type=float, default=1.0, help="fix wire/elastic's m_elo (1)")
    parser.add_argument("--l0", type=float, default=0.2, help="the segments' rest length (0.2)")
    parser.add_argument("--r-w", dest="r_w", type=float, default=0.1, help="the wire's radius when the dump has none")
    parser.add_argument("--stress", default="c_stress[3]", help="the grains dump's σ_zz column (c_stress[3])")
    parser.add_argument("--energy", default="c_energy", help="the wire dump's compute wire/energy (c_energy)")
    parser.add_argument("--no-plots", action="store_true", help="no matplotlib figures")
    parser.add_argument("--no-picture", action="store_true", help="no VTK picture")
    parser.add_argument("--no-wire-picture", action="store_true", help="leave the wire out of the picture")
    parser.add_argument("--size", type=int, nargs=2, metavar=("W", "H"),
                        help="the picture's pixels (default 1200 wide, as tall as the scene)")
    parser.add_argument("--view", choices=("side", "elevated", "top"), default="side")
    parser.add_argument("--bar-radius", type=float, default=0.2, help="the tube radius of the largest force (0.2)")
    parser.add_argument("--grain-opacity", type=float, default=0.25, help="the grains' opacity in the picture (0.25)")
    args = parser.parse_args(argv)
    if args.r_max is not None and not args.r_max > 0:
        parser.error(f"--r-max must be > 0, got {args.r_max}")
    for name in ("bin_width", "density", "l0", "E_w", "r_w", "bar_radius"):
        if getattr(args, name) <= 0:
            parser.error(f"--{name.replace('_', '-')} must be > 0, got {getattr(args, name)}")
    for name in ("r_bins", "z_bins", "planes"):
        if getattr(args, name) < 1:
            parser.error(f"--{name.replace('_', '-')} must be >= 1, got {getattr(args, name)}")
    args.section_square = None
    if args.section[0] == "square" and len(args.section) == 2:
        try:
            args.section_square = float(args.section[1])
        except ValueError:
            parser.error(f"--section square D: D must be a number, got {args.section[1]}")
        if not args.section_square > 0:
            parser.error(f"--section square D: D must be > 0, got {args.section[1]}")
    elif args.section != ["circle"]:
        parser.error(f"--section must be circle or square D, got {' '.join(args.section)}")
    if args.size is not None and (args.size[0] < 16 or args.size[1] < 16):
        parser.error("--size: at least 16 x 16 pixels")
    files = find_files(args)
    result, (gg, gw, grains, wire) = analyse(args, files)
    out = args.out or os.path.dirname(os.path.abspath(files["contacts"]))
    os.makedirs(out, exist_ok=True)
    base = os.path.join(out, f"network_{result['step']}")
    written = [] if args.no_plots else plots(result, base)
    if not args.no_picture:
        written.append(picture(args, files["vtp"], gg, gw, grains, wire, base + "_picture.png"))
    with open(base + ".json", "w") as f:
        json.dump(finite(result), f, indent=1)
    written.append(base + ".json")
    print(report(result))
    print("written: " + " ".join(written))
    return 0


if __name__ == "__main__":
    sys.exit(main())
