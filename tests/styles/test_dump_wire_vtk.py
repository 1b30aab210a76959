"""dump wire/vtk: wires as VTK XML polylines on 1 and 2 MPI ranks (chain order, segment
lengths, per-bead energies against fix wire/elastic), the binary format, the ParaView
series file, cut and closed chains, and its error messages. Files are read with
xml.etree (no VTK Python module needed)."""

import json
import math
import os
import re
import struct
import xml.etree.ElementTree as ET
import zlib

import numpy as np

from liggghts_run import DeckTestCase, main, run

SEGMENT = 0.2
DT = 1e-4

DECK = """
units           lj
atom_style      wire
boundary        f f f
region          box block -5 5 -5 5 -5 5
create_box      1 box
create_wire     1 line -3 -3 -3 3 -3 -3 segment {segment}
create_wire     1 loop 0 0 0 2 2 0.3 segment {segment}
{groups}
fix             el all wire/elastic
fix             int all nve/gear
velocity        all set 0.0 0.0 0.5
timestep        {dt}
dump            d {group} wire/vtk 10 post/wire_*.vtp {options}
thermo_style    custom step f_el[1] f_el[2] f_el[3]
thermo_modify   format float %.15g
thermo          10
run             20
{after}
"""


def wire_deck(options="energy el format ascii", group="all", groups="", after=""):
    return DECK.format(segment=SEGMENT, dt=DT, options=options, group=group, groups=groups,
                       after=after)


def created_beads(output):
    counts = [int(n) for n in re.findall(r"^create_wire: (\d+) beads", output, re.M)]
    assert counts, "no create_wire line in the output"
    return sum(counts)


def thermo_column(table, name):
    for key in (name, name[2:]):  # LIGGGHTS prints f_el[2] as el[2]
        if key in table:
            return table[key]
    raise KeyError(f"{name} not in thermo columns {sorted(table)}")


class Snapshot:
    """One .vtp file: points (N x 3), point arrays by name, polylines as index lists."""

    def __init__(self, points, arrays, cell_arrays, verts, lines):
        self.points = points
        self.arrays = arrays
        self.cell_arrays = cell_arrays
        self.verts = verts
        self.lines = lines


def split_cells(connectivity, offsets):
    starts = np.concatenate([[0], offsets[:-1]]).astype(int)
    return [connectivity[s:e].astype(int).tolist() for s, e in zip(starts, offsets.astype(int))]


def read_ascii_vtp(path):
    piece = ET.parse(path).getroot().find("PolyData/Piece")

    def values(element):
        return np.array(element.text.split() if element.text else [], dtype=float)

    def table(parent):
        out = {}
        for a in parent.findall("DataArray") if parent is not None else []:
            v = values(a)
            n = int(a.get("NumberOfComponents", "1"))
            out[a.get("Name")] = v.reshape(-1, n) if n > 1 else v
        return out

    cells = {}
    for kind in ("Verts", "Lines"):
        arrays = table(piece.find(kind))
        cells[kind] = split_cells(arrays["connectivity"], arrays["offsets"])
    points = values(piece.find("Points/DataArray")).reshape(-1, 3)
    assert len(points) == int(piece.get("NumberOfPoints"))
    assert len(cells["Lines"]) == int(piece.get("NumberOfLines"))
    return Snapshot(points, table(piece.find("PointData")), table(piece.find("CellData")),
                    cells["Verts"], cells["Lines"])


def read_binary_vtp(path):
    """A VTK XML file with raw appended data (header UInt32 or UInt64, zlib or none)."""
    with open(path, "rb") as f:
        raw = f.read()
    marker = raw.index(b"<AppendedData")
    start = raw.index(b"_", marker) + 1
    head = raw[:marker].decode()
    root = re.search(r"<VTKFile[^>]*>", head).group(0)
    header_type = re.search(r'header_type="(\w+)"', root).group(1)
    compressed = "compressor=" in root
    word, code = (4, "I") if header_type == "UInt32" else (8, "Q")
    dtypes = {"Int32": "<i4", "Int64": "<i8", "Float64": "<f8", "Float32": "<f4",
              "UInt8": "<u1"}

    def block(offset, dtype):
        p = start + offset
        if not compressed:
            (n,) = struct.unpack("<" + code, raw[p:p + word])
            return np.frombuffer(raw[p + word:p + word + n], dtype=dtype)
        nblocks, _, _ = struct.unpack("<" + code * 3, raw[p:p + 3 * word])
        sizes = struct.unpack("<" + code * nblocks, raw[p + 3 * word:p + (3 + nblocks) * word])
        q, data = p + (3 + nblocks) * word, b""
        for s in sizes:
            data += zlib.decompress(raw[q:q + s])
            q += s
        return np.frombuffer(data, dtype=dtype)

    # a DataArray tag with its enclosing section
    sections = {}
    for m in re.finditer(r"<(PointData|CellData|Points|Verts|Lines|Strips|Polys)\b|"
                         r"<DataArray([^>]*)>", head):
        if m.group(1):
            section = m.group(1)
            continue
        attrs = dict(re.findall(r'(\w+)="([^"]*)"', m.group(2)))
        assert attrs["format"] == "appended", attrs
        v = block(int(attrs["offset"]), dtypes[attrs["type"]])
        n = int(attrs.get("NumberOfComponents", "1"))
        sections.setdefault(section, {})[attrs["Name"]] = v.reshape(-1, n) if n > 1 else v
    lines = sections["Lines"]
    verts = sections.get("Verts", {"connectivity": np.zeros(0), "offsets": np.zeros(0)})
    return Snapshot(sections["Points"]["Points"], sections["PointData"],
                    sections.get("CellData", {}),
                    split_cells(verts["connectivity"], verts["offsets"]),
                    split_cells(lines["connectivity"], lines["offsets"]))


def read_series(path):
    with open(path) as f:
        series = json.load(f)
    assert series["file-series-version"] == "1.0"
    return [(e["name"], e["time"]) for e in series["files"]]


class WireVTK(DeckTestCase):
    def run_ok(self, deck, np_ranks=1, files=None):
        r = run(deck, np_ranks=np_ranks, files=files)
        self.assertRanCleanly(r)
        return r

    def check_run(self, r, np_ranks):
        n_beads = created_beads(r.output)
        if np_ranks > 1:  # the beads really are spread over the ranks
            nmax = float(re.search(r"^Nlocal:\s+\S+ ave (\S+) max", r.output, re.M).group(1))
            self.assertLess(nmax, n_beads)
        thermo = r.thermo()
        steps = thermo["Step"].astype(int).tolist()
        self.assertEqual(steps, [0, 10, 20])
        snaps = {}
        for k, step in enumerate(steps):
            s = read_ascii_vtp(r.path(f"post/wire_{step}.vtp"))
            snaps[step] = s
            self.assertEqual(len(s.lines), 2)
            self.assertEqual(len(s.verts), 0)
            self.assertEqual(len(s.points), n_beads)
            self.assertEqual(sorted(sum(s.lines, [])), list(range(n_beads)))
            ids = s.arrays["id"]
            self.assertEqual(sorted(ids.astype(int).tolist()), list(range(1, n_beads + 1)))
            self.assertTrue(np.all(s.arrays["type"] == 1))
            self.assertEqual(s.arrays["velocity"].shape, (n_beads, 3))
            self.assertTrue(np.allclose(s.arrays["velocity"][:, 2], 0.5, atol=1e-3))
            self.assertEqual(s.cell_arrays["wire"].tolist(), [0, 1])
            for line in s.lines:  # chain order: create_wire numbers the beads along the wire
                self.assertTrue(np.all(np.diff(ids[line]) == 1), ids[line])
            # per-bead energies against the fix's totals
            bend = thermo_column(thermo, "f_el[2]")[k]
            stretch = thermo_column(thermo, "f_el[1]")[k]
            total = thermo_column(thermo, "f_el[3]")[k]
            self.assertGreater(bend, 0.0)
            self.assertAlmostEqual(s.arrays["bending_energy"].sum() / bend, 1.0, delta=1e-9)
            self.assertAlmostEqual(s.arrays["stretching_energy"].sum(), stretch,
                                   delta=1e-9 * total)
            self.assertAlmostEqual(s.arrays["elastic_energy"].sum() / total, 1.0, delta=1e-9)
            np.testing.assert_allclose(s.arrays["elastic_energy"],
                                       s.arrays["stretching_energy"] + s.arrays["bending_energy"],
                                       rtol=1e-15, atol=0)
        # at step 0 consecutive points of a polyline are one segment apart
        s0 = snaps[0]
        for line in s0.lines:
            d = np.linalg.norm(np.diff(s0.points[line], axis=0), axis=1)
            self.assertLess(np.max(np.abs(d - SEGMENT)), 1e-9)
        # the line wire starts at its first end point
        first = s0.lines[0]
        np.testing.assert_allclose(s0.points[first[0]], [-3, -3, -3], atol=1e-12)
        series = read_series(r.path("post/wire.vtp.series"))
        self.assertEqual([n for n, _ in series], ["wire_0.vtp", "wire_10.vtp", "wire_20.vtp"])
        np.testing.assert_allclose([t for _, t in series], [0.0, 10 * DT, 20 * DT],
                                   rtol=1e-12, atol=1e-18)
        return snaps

    def test_one_and_two_ranks(self):
        runs = {np_ranks: self.run_ok(wire_deck(), np_ranks) for np_ranks in (1, 2)}
        snaps = {np_ranks: self.check_run(r, np_ranks) for np_ranks, r in runs.items()}
        for step in (0, 10, 20):
            a, b = snaps[1][step], snaps[2][step]
            self.assertEqual(a.lines, b.lines)
            np.testing.assert_array_equal(a.points, b.points)
            for name in a.arrays:
                np.testing.assert_array_equal(a.arrays[name], b.arrays[name], name)
        print(f"dump wire/vtk: {len(snaps[1][0].points)} beads in 2 polylines, "
              "1 and 2 ranks write the same snapshots")

    def test_binary_is_the_default(self):
        ascii_run = self.run_ok(wire_deck())
        for np_ranks in (1, 2):
            r = self.run_ok(wire_deck("energy el"), np_ranks)
            for step in (0, 10, 20):
                path = r.path(f"post/wire_{step}.vtp")
                with open(path, "rb") as f:
                    self.assertIn(b'<AppendedData encoding="raw">', f.read())
                b = read_binary_vtp(path)
                a = read_ascii_vtp(ascii_run.path(f"post/wire_{step}.vtp"))
                self.assertEqual(a.lines, b.lines)
                np.testing.assert_array_equal(a.points, b.points)
                for name in ("id", "type", "velocity", "stretching_energy", "bending_energy",
                             "elastic_energy"):
                    np.testing.assert_array_equal(a.arrays[name], b.arrays[name], name)
                self.assertEqual(b.cell_arrays["wire"].tolist(), [0, 1])

    def test_without_energy(self):
        r = self.run_ok(wire_deck("format ascii"))
        s = read_ascii_vtp(r.path("post/wire_20.vtp"))
        self.assertEqual(sorted(s.arrays), ["id", "type", "velocity"])

    def test_group_cuts_chains(self):
        # leaving out beads 10..12 of the line wire cuts it in two; bead 14 alone is a vertex
        groups = "group gap id 10 11 12 13 15\ngroup kept subtract all gap"
        r = self.run_ok(wire_deck(group="kept", groups=groups))
        n_beads = created_beads(r.output)
        s = read_ascii_vtp(r.path("post/wire_0.vtp"))
        self.assertEqual(len(s.points), n_beads - 5)
        ids = s.arrays["id"].astype(int)
        self.assertEqual([ids[line].tolist() for line in s.verts], [[14]])
        self.assertEqual(len(s.lines), 3)
        self.assertEqual(ids[s.lines[0]].tolist(), list(range(1, 10)))
        self.assertEqual(ids[s.lines[1]][0], 16)
        self.assertEqual(s.cell_arrays["wire"].tolist(), [1, 0, 2, 3])  # vertices first

    def test_grains_of_the_group_are_left_out(self):
        # 'all' of atom_style hybrid polyhedron wire (two cubes, ids 1-2, and a line of 11
        # beads, ids 3-13): the file holds the one polyline of the beads, no grain (unfiltered,
        # each grain is written as a lone vertex)
        deck = """
units           lj
atom_style      hybrid polyhedron wire
atom_modify     map array sort 0 0.0
boundary        f f f
region          box block -4 4 -4 4 -1 6
create_box      2 box
create_grains   1 2 layer box 1.0 seed 3 shape cube 1.0
create_wire     2 line -1 0 3 1 0 3
dump            d all wire/vtk 10 post/wire_*.vtp format ascii
run             0
"""
        r = self.run_ok(deck)
        s = read_ascii_vtp(r.path("post/wire_0.vtp"))
        ids = s.arrays["id"].astype(int)
        self.assertEqual(s.verts, [])
        self.assertEqual([ids[line].tolist() for line in s.lines], [list(range(3, 14))])

    def test_closed_ring(self):
        n, radius = 12, 1.0
        chord = 2 * radius * math.sin(math.pi / n)
        lines = ["ring", "", f"{n} atoms", "1 atom types", "-5 5 xlo xhi", "-5 5 ylo yhi",
                 "-5 5 zlo zhi", "", "Atoms", ""]
        for k in range(n):
            a = 2 * math.pi * k / n
            prev = k if k > 0 else n
            nxt = k + 2 if k + 1 < n else 1
            lines.append(f"{k + 1} 1 {prev} {nxt} {chord!r} 0.05 1.0 "
                         f"{radius * math.cos(a)!r} {radius * math.sin(a)!r} 0.0")
        deck = """
units lj
atom_style wire
boundary f f f
read_data ring.data
fix el all wire/elastic
dump d all wire/vtk 1 ring_*.vtp format ascii energy el
run 0
"""
        r = self.run_ok(deck, files={"ring.data": "\n".join(lines) + "\n"})
        s = read_ascii_vtp(r.path("ring_0.vtp"))
        self.assertEqual(len(s.lines), 1)
        line = s.lines[0]
        self.assertEqual(len(line), n + 1)
        self.assertEqual(line[0], line[-1])
        self.assertEqual(s.arrays["id"][line[:-1]].astype(int).tolist(), list(range(1, n + 1)))
        d = np.linalg.norm(np.diff(s.points[line], axis=0), axis=1)
        self.assertLess(np.max(np.abs(d - chord)), 1e-12)
        bend = s.arrays["bending_energy"]  # every node of the ring is bent alike
        self.assertGreater(bend.min(), 0.0)
        np.testing.assert_allclose(bend, bend.mean(), rtol=1e-9)
        self.assertEqual(read_series(r.path("ring.vtp.series")), [("ring_0.vtp", 0.0)])

    def test_series_continues_with_append(self):
        redo = "undump d\ndump d all wire/vtk 10 post/wire_*.vtp format ascii\n{modify}\nrun 10"
        for modify, names in (("dump_modify d append yes", [0, 10, 20, 30]), ("", [20, 30])):
            r = self.run_ok(wire_deck(after=redo.format(modify=modify)))
            series = read_series(r.path("post/wire.vtp.series"))
            self.assertEqual([n for n, _ in series], [f"wire_{k}.vtp" for k in names], modify)
            np.testing.assert_allclose([t for _, t in series], [k * DT for k in names],
                                       rtol=1e-12, atol=1e-18)


class Errors(DeckTestCase):
    def check(self, dump_line, message, deck=None):
        text = deck or wire_deck()
        text = re.sub(r"^dump .*$", dump_line, text, flags=re.M)
        self.assertStopsWith(run(text), message)

    def test_file_without_star(self):
        self.check("dump d all wire/vtk 10 post/wire.vtp",
                   "dump wire/vtk (id d): file 'post/wire.vtp' must contain a '*' in its name")

    def test_file_not_vtp(self):
        self.check("dump d all wire/vtk 10 wire_*.vtu",
                   "dump wire/vtk (id d): file 'wire_*.vtu' must end in '.vtp'")

    def test_energy_fix_not_wire_elastic(self):
        self.check("dump d all wire/vtk 10 wire_*.vtp energy int",
                   "dump wire/vtk (id d): energy fix 'int' is a fix nve/gear, "
                   "not a fix wire/elastic")

    def test_energy_fix_missing(self):
        self.check("dump d all wire/vtk 10 wire_*.vtp energy nope",
                   "dump wire/vtk (id d): energy fix 'nope' does not exist")

    def test_grains_fix_not_wire_grain(self):
        self.check("dump d all wire/vtk 10 wire_*.vtp grains el",
                   "dump wire/vtk (id d): grains fix 'el' is a fix wire/elastic, not a fix wire/grain")

    def test_grains_fix_missing(self):
        self.check("dump d all wire/vtk 10 wire_*.vtp grains nope",
                   "dump wire/vtk (id d): grains fix 'nope' does not exist (define it before the dump)")

    def test_grains_missing_value(self):
        self.check("dump d all wire/vtk 10 wire_*.vtp energy el grains",
                   "dump wire/vtk (id d): missing value after 'grains'")

    def test_missing_value(self):
        self.check("dump d all wire/vtk 10 wire_*.vtp energy",
                   "dump wire/vtk (id d): missing value after 'energy'")

    def test_unknown_keyword(self):
        self.check("dump d all wire/vtk 10 wire_*.vtp colour red",
                   "dump wire/vtk (id d): unknown keyword 'colour'; accepted: energy, grains, format")

    def test_bad_format(self):
        self.check("dump d all wire/vtk 10 wire_*.vtp format hex",
                   "dump wire/vtk (id d): value of 'format' must be 'ascii' or 'binary', "
                   "got 'hex'")

    def test_atom_style_without_wire(self):
        deck = """
units lj
atom_style atomic
boundary f f f
region box block -5 5 -5 5 -5 5
create_box 1 box
dump d all wire/vtk 10 wire_*.vtp
"""
        self.check("dump d all wire/vtk 10 wire_*.vtp",
                   "dump wire/vtk (id d): needs atom_style wire (or hybrid with wire), "
                   "not 'atomic'", deck)


if __name__ == "__main__":
    main()
