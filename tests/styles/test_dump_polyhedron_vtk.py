"""dump polyhedron/vtk: grains as VTK XML polygons. Files are read by VTK's own reader
(build/tests/styles/read_vtp, path in $READ_VTP) for the counts and array names, and
parsed from the ascii format here for the geometry: cube vertices at √3/2 edge from the
grain centre (√0.86 with the faces swept out by 0.1), faces outward and counter-clockwise,
Euler's formula on random ellipsoid hulls; 1 and 2 MPI ranks write identical files; the
ParaView series file; grains without a shape; the ERROR texts."""

import json
import os
import re
import subprocess
import unittest
import xml.etree.ElementTree as ET

import numpy as np

from liggghts_run import DeckTestCase, full_precision, main, read_dump, run

READ_VTP = os.environ.get("READ_VTP")
DT = 1e-3
VELOCITY = (0.1, -0.2, 0.3)
OMEGA = (1.5, -0.5, 2.0)
SWEEP = 0.1

DECK = """
units           lj
atom_style      polyhedron
atom_modify     sort 0 0.0
boundary        f f f
processors      * 1 1
region          box block -6 6 -6 6 -3 9
create_box      1 box
create_grains   1 {n} layer box 1.0 seed 1234 sweep {sweep} {shape}
velocity        all set {v[0]} {v[1]} {v[2]}
set             group all omegax {w[0]} omegay {w[1]} omegaz {w[2]}
timestep        {dt}
dump            d all polyhedron/vtk 10 post/grains_*.vtp {options}
dump            c all custom 10 post/grains.dump id type x y z
thermo_style    custom step atoms
thermo          10
run             20
"""


def grain_deck(options="format ascii", shape="shape cube 1.0", n=5):
    text = DECK.format(n=n, sweep=SWEEP, shape=shape, v=VELOCITY, w=OMEGA, dt=DT,
                       options=options)
    return full_precision(text, "c")


def read_vtp(path):
    """What VTK's vtkXMLPolyDataReader finds in a file: counts and {array: (kind, comps, n)}."""
    proc = subprocess.run([READ_VTP, path], stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    text = proc.stdout.decode(errors="replace")
    assert proc.returncode == 0, f"read_vtp failed on {path}:\n{text}"
    counts, arrays = {}, {}
    for line in text.splitlines():
        words = line.split()
        if words[0] in ("point_array", "cell_array"):
            arrays[words[1]] = (words[0], int(words[2]), int(words[3]))
        else:
            counts[words[0]] = int(words[1])
    return counts, arrays


class Mesh:
    """An ascii .vtp of polygons: points (N x 3), polys (index lists), point and cell arrays."""

    def __init__(self, path):
        piece = ET.parse(path).getroot().find("PolyData/Piece")

        def values(element):
            return np.array(element.text.split() if element.text else [], dtype=float)

        def table(parent):
            out = {}
            for a in parent.findall("DataArray") if parent is not None else []:
                v = values(a)
                n = int(a.get("NumberOfComponents", "1"))
                assert a.get("format") == "ascii", a.attrib
                out[a.get("Name")] = v.reshape(-1, n) if n > 1 else v
            return out

        self.points = values(piece.find("Points/DataArray")).reshape(-1, 3)
        polys = table(piece.find("Polys"))
        offsets = polys.get("offsets", np.zeros(0)).astype(int)
        starts = np.concatenate([[0], offsets[:-1]]).astype(int)
        conn = polys.get("connectivity", np.zeros(0)).astype(int)
        self.polys = [conn[s:e].tolist() for s, e in zip(starts, offsets)]
        self.point_arrays = table(piece.find("PointData"))
        self.cell_arrays = table(piece.find("CellData"))
        assert len(self.points) == int(piece.get("NumberOfPoints"))
        assert len(self.polys) == int(piece.get("NumberOfPolys"))


def read_series(path):
    with open(path) as f:
        series = json.load(f)
    assert series["file-series-version"] == "1.0"
    return [(e["name"], e["time"]) for e in series["files"]]


def read_shapes(path):
    """create_grains' write_shapes file: {tag: shape, sweep, x, q, vertices, faces}."""
    with open(path) as f:
        lines = [line.split() for line in f if line.strip() and not line.startswith("#")]
    grains, k = {}, 0
    while k < len(lines):
        w = lines[k]
        assert w[0] == "grain", w
        nv, nf = int(w[13]), int(w[14])
        vertices = np.array([[float(c) for c in line] for line in lines[k + 1:k + 1 + nv]])
        faces = [[int(c) for c in line[1:]] for line in lines[k + 1 + nv:k + 1 + nv + nf]]
        grains[int(w[1])] = {"shape": int(w[2]), "sweep": float(w[3]),
                             "x": np.array([float(c) for c in w[6:9]]),
                             "q": [float(c) for c in w[9:13]], "vertices": vertices,
                             "faces": faces}
        k += 1 + nv + nf
    return grains


def rotation_matrix(q):
    """Body → space rotation of the unit quaternion (w, i, j, k)."""
    w, x, y, z = np.array(q) / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def newell_normal(p):
    n = np.zeros(3)
    for k in range(len(p)):
        n += np.cross(p[k], p[(k + 1) % len(p)])
    return n / np.linalg.norm(n)


@unittest.skipUnless(READ_VTP, "built without VTK (no READ_VTP)")
class PolyhedronVTK(DeckTestCase):
    def run_ok(self, deck, np_ranks=1):
        r = run(deck, np_ranks=np_ranks)
        self.assertRanCleanly(r)
        return r

    def centres(self, r):
        d = read_dump(r.path("post/grains.dump"))
        return {int(i): np.array([x, y, z]) for i, x, y, z in zip(d["id"], d["x"], d["y"], d["z"])}

    def check_cubes(self, r, step, sweep):
        """Every face of every cube grain, in the ascii file of `step`."""
        centres = self.centres(r)
        n = len(centres)
        self.assertGreater(n, 1)
        path = r.path(f"post/grains_{step}.vtp")
        counts, arrays = read_vtp(path)
        # points: one per face vertex (faces do not share points)
        self.assertEqual(counts["cells"], 6 * n)
        self.assertEqual(counts["polys"], 6 * n)
        self.assertEqual(counts["points"], 24 * n)
        self.assertEqual(arrays, {"velocity": ("point_array", 3, 24 * n),
                                  "angular_velocity": ("point_array", 3, 24 * n),
                                  "id": ("cell_array", 1, 6 * n),
                                  "type": ("cell_array", 1, 6 * n),
                                  "shape": ("cell_array", 1, 6 * n),
                                  "center": ("cell_array", 3, 6 * n),
                                  "top": ("cell_array", 1, 6 * n)})
        m = Mesh(path)
        ids = m.cell_arrays["id"].astype(int)
        self.assertEqual(ids.tolist(), sorted(ids.tolist()))  # grains in id order
        self.assertEqual(sorted(set(ids.tolist())), sorted(centres))
        self.assertTrue(np.all(m.cell_arrays["type"] == 1))
        self.assertTrue(np.all(m.cell_arrays["shape"] >= 0))
        np.testing.assert_allclose(m.point_arrays["velocity"], np.tile(VELOCITY, (24 * n, 1)),
                                   rtol=0, atol=1e-15)
        np.testing.assert_allclose(m.point_arrays["angular_velocity"],
                                   np.tile(OMEGA, (24 * n, 1)), rtol=0, atol=1e-15)
        half = 0.5 + (SWEEP if sweep else 0.0)  # distance of a face plane from the centre
        corner = np.sqrt(0.5 + half ** 2)  # √3/2 for the bare cube
        self.assertEqual(sorted(sum(m.polys, [])), list(range(24 * n)))
        for face, grain in zip(m.polys, ids):
            p = m.points[face] - centres[grain]
            self.assertEqual(len(face), 4)
            np.testing.assert_allclose(np.linalg.norm(p, axis=1), corner, rtol=0, atol=1e-12)
            edges = np.linalg.norm(p - np.roll(p, -1, axis=0), axis=1)
            np.testing.assert_allclose(edges, 1.0, rtol=0, atol=1e-12)
            normal = newell_normal(p)  # counter-clockwise seen from outside: outward
            np.testing.assert_allclose(p @ normal, half, rtol=0, atol=1e-12)
        # cell arrays: the grain's centre, and its top = the highest cube corner + the
        # sweep radius (corners: the points moved back along their face's normal with
        # `sweep yes`), whatever `sweep` says
        np.testing.assert_allclose(m.cell_arrays["center"], [centres[g] for g in ids], rtol=0, atol=1e-14)
        highest = {}
        for face, grain in zip(m.polys, ids):
            corners = m.points[face] - (SWEEP if sweep else 0.0) * newell_normal(m.points[face] - centres[grain])
            highest[grain] = max(highest.get(grain, -np.inf), corners[:, 2].max())
        np.testing.assert_allclose(m.cell_arrays["top"], [highest[g] + SWEEP for g in ids], rtol=0, atol=1e-12)
        return m

    def test_cube_grains_one_and_two_ranks(self):
        runs = {k: self.run_ok(grain_deck(), k) for k in (1, 2)}
        n = int(runs[1].thermo()["Atoms"][0])
        nmax = float(re.search(r"^Nlocal:\s+\S+ ave (\S+) max", runs[2].output, re.M).group(1))
        self.assertLess(nmax, n)  # the grains really are spread over the ranks
        for k, r in runs.items():
            self.assertEqual(r.thermo()["Step"].astype(int).tolist(), [0, 10, 20])
            for step in (0, 10, 20):
                self.check_cubes(r, step, sweep=False)
            series = read_series(r.path("post/grains.vtp.series"))
            self.assertEqual([name for name, _ in series],
                             ["grains_0.vtp", "grains_10.vtp", "grains_20.vtp"])
            np.testing.assert_allclose([t for _, t in series], [0.0, 10 * DT, 20 * DT],
                                       rtol=1e-12, atol=1e-18)
        for step in (0, 10, 20):
            with open(runs[1].path(f"post/grains_{step}.vtp"), "rb") as f1, \
                    open(runs[2].path(f"post/grains_{step}.vtp"), "rb") as f2:
                self.assertEqual(f1.read(), f2.read(), f"grains_{step}.vtp differs")
        print(f"dump polyhedron/vtk: {n} cube grains, {6 * n} faces; 1 and 2 ranks write "
              "identical files")

    def test_sweep_moves_faces_out(self):
        r = self.run_ok(grain_deck("format ascii sweep yes"))
        self.check_cubes(r, 20, sweep=True)

    def test_binary_is_the_default(self):
        ascii_run = self.run_ok(grain_deck())
        for np_ranks in (1, 2):
            r = self.run_ok(grain_deck(""), np_ranks)
            for step in (0, 20):
                path = r.path(f"post/grains_{step}.vtp")
                with open(path, "rb") as f:
                    self.assertIn(b'<AppendedData encoding="raw">', f.read())
                self.assertEqual(read_vtp(path),
                                 read_vtp(ascii_run.path(f"post/grains_{step}.vtp")))

    def test_ellipsoid_hulls(self):
        """Random hulls (create_grains' default shapes) against the geometry create_grains
        reports with write_shapes: every face point is x + R(q)·v (+ r·n with sweep)."""
        for sweep in (False, True):
            r = self.run_ok(grain_deck("format ascii" + (" sweep yes" if sweep else ""),
                                       shape="write_shapes shapes.txt", n=6))
            grains = read_shapes(r.path("shapes.txt"))
            path = r.path("post/grains_0.vtp")
            counts, arrays = read_vtp(path)
            m = Mesh(path)
            n_faces = sum(len(g["faces"]) for g in grains.values())
            self.assertEqual(counts["cells"], n_faces)
            self.assertEqual(counts["points"], sum(len(f) for g in grains.values()
                                                   for f in g["faces"]))
            self.assertEqual(len(m.polys), n_faces)
            self.assertEqual(sorted(arrays),
                             ["angular_velocity", "center", "id", "shape", "top", "type", "velocity"])
            ids = m.cell_arrays["id"].astype(int)
            expected_ids, expected_shapes, expected_points = [], [], []
            for tag in sorted(grains):
                g = grains[tag]
                rotation = rotation_matrix(g["q"])
                for face in g["faces"]:
                    body = g["vertices"][face]
                    offset = g["sweep"] * newell_normal(body) if sweep else 0.0
                    expected_points.append((body + offset) @ rotation.T + g["x"])
                    expected_ids.append(tag)
                    expected_shapes.append(g["shape"])
            self.assertEqual(ids.tolist(), expected_ids)
            self.assertEqual(m.cell_arrays["shape"].astype(int).tolist(), expected_shapes)
            got = np.concatenate([m.points[f] for f in m.polys])
            np.testing.assert_allclose(got, np.concatenate(expected_points), rtol=0, atol=1e-12)
            # top: the highest vertex of the posed hull + the sweep radius
            top = {tag: (g["vertices"] @ rotation_matrix(g["q"]).T)[:, 2].max() + g["x"][2] + g["sweep"]
                   for tag, g in grains.items()}
            np.testing.assert_allclose(m.cell_arrays["top"], [top[i] for i in ids], rtol=0, atol=1e-12)
            np.testing.assert_allclose(m.cell_arrays["center"], [grains[i]["x"] for i in ids], rtol=0, atol=1e-12)
            if sweep:
                continue
            for tag, g in grains.items():  # Euler's formula per grain, faces outward
                faces = [f for f, i in zip(m.polys, ids) if i == tag]
                corners = {tuple(m.points[k]) for f in faces for k in f}  # bit-equal
                n_edges = sum(len(f) for f in faces) / 2
                self.assertEqual(len(corners) - n_edges + len(faces), 2, f"grain {tag}")
                q = np.array(sorted(corners)) - g["x"]
                for f in faces:
                    normal = newell_normal(m.points[f] - g["x"])
                    offset = (m.points[f] - g["x"]) @ normal
                    np.testing.assert_allclose(offset, offset.mean(), rtol=0, atol=1e-9)
                    self.assertLessEqual(np.max(q @ normal), offset.mean() + 1e-9)

    def test_sphere_grains(self):
        """Sphere grains (one-vertex shapes) are drawn as their ball, with or without
        `sweep yes`: 8 bands x 16 sectors = 128 polygons (32 triangles, 96 quadrilaterals,
        480 points) per grain, every point at the radius from the grain's centre, every
        polygon planar and counter-clockwise seen from outside."""
        radius = 0.5
        deck = DECK.replace(" sweep {sweep}", "")
        files = {}
        for options in ("format ascii", "format ascii sweep yes"):
            text = full_precision(deck.format(n=4, shape=f"shape sphere {radius}", v=VELOCITY, w=OMEGA,
                                              dt=DT, options=options), "c")
            r = self.run_ok(text)
            centres = self.centres(r)
            n = len(centres)
            self.assertEqual(n, 4)
            path = r.path("post/grains_20.vtp")
            counts, _ = read_vtp(path)
            self.assertEqual((counts["cells"], counts["points"]), (128 * n, 480 * n))
            m = Mesh(path)
            self.assertEqual(sorted(len(f) for f in m.polys), [3] * (32 * n) + [4] * (96 * n))
            for face, grain in zip(m.polys, m.cell_arrays["id"].astype(int)):
                p = m.points[face] - centres[grain]
                np.testing.assert_allclose(np.linalg.norm(p, axis=1), radius, rtol=0, atol=1e-12)
                normal = newell_normal(p)
                self.assertGreater(normal @ p.mean(axis=0), 0.0)
                np.testing.assert_allclose(p @ normal, (p @ normal).mean(), rtol=0, atol=1e-12)
            with open(path, "rb") as f:
                files[options] = f.read()
        self.assertEqual(files["format ascii"], files["format ascii sweep yes"])

    def test_series_matches_wire_dump(self):
        """Grains and a wire in one system (atom_style hybrid): both series files list the
        same times, also across a change of time step, so ParaView plays them together."""
        deck = """
units           lj
atom_style      hybrid polyhedron wire
atom_modify     sort 0 0.0
boundary        f f f
region          box block -6 6 -6 6 -3 9
create_box      2 box
create_grains   1 3 layer box 1.0 seed 1234 shape cube 1.0
create_wire     2 line -3 3 5 3 3 5
group           grains type 1
group           wire type 2
timestep        0.001
dump            g grains polyhedron/vtk 10 post/grains_*.vtp
dump            w wire wire/vtk 10 post/wire_*.vtp
run             20
timestep        0.0025
run             20
"""
        r = self.run_ok(deck)
        grains = read_series(r.path("post/grains.vtp.series"))
        wire = read_series(r.path("post/wire.vtp.series"))
        steps = [0, 10, 20, 30, 40]
        self.assertEqual([n for n, _ in grains], [f"grains_{k}.vtp" for k in steps])
        self.assertEqual([n for n, _ in wire], [f"wire_{k}.vtp" for k in steps])
        self.assertEqual([t for _, t in grains], [t for _, t in wire])
        np.testing.assert_allclose([t for _, t in grains], [0, 0.01, 0.02, 0.045, 0.07],
                                   rtol=1e-12, atol=1e-18)
        counts, _ = read_vtp(r.path("post/grains_40.vtp"))
        self.assertEqual((counts["cells"], counts["points"]), (18, 72))

    def test_beads_of_the_group_are_left_out(self):
        # 'all' of atom_style hybrid polyhedron wire: the 3 cubes (6 faces of 4 points each)
        # and nothing of the 31 beads, without a warning (unfiltered, each bead is counted as a
        # grain without a shape)
        deck = """
units           lj
atom_style      hybrid polyhedron wire
atom_modify     sort 0 0.0
boundary        f f f
region          box block -6 6 -6 6 -3 9
create_box      2 box
create_grains   1 3 layer box 1.0 seed 1234 shape cube 1.0
create_wire     2 line -3 3 5 3 3 5
dump            g all polyhedron/vtk 10 post/grains_*.vtp format ascii
run             0
"""
        r = self.run_ok(deck)
        self.assertNotIn("without a shape", r.output)
        mesh = Mesh(r.path("post/grains_0.vtp"))
        self.assertEqual((len(mesh.polys), len(mesh.points)), (18, 72))
        self.assertEqual(mesh.cell_arrays["id"].astype(int).tolist(), [1] * 6 + [2] * 6 + [3] * 6)

    def test_grains_without_shape(self):
        deck = """
units lj
atom_style polyhedron
atom_modify sort 0 0.0
boundary f f f
region box block -5 5 -5 5 -5 5
create_box 1 box
create_atoms 1 single 0 0 0
dump d all polyhedron/vtk 1 g_*.vtp format ascii
run 0
"""
        r = self.run_ok(deck)
        self.assertIn("dump polyhedron/vtk (id d): 1 grains without a shape (shape -1) "
                      "are not written", r.output)
        counts, arrays = read_vtp(r.path("g_0.vtp"))
        self.assertEqual((counts["points"], counts["cells"]), (0, 0))
        self.assertEqual(read_series(r.path("g.vtp.series")), [("g_0.vtp", 0.0)])


class Errors(DeckTestCase):
    BOX = """
units lj
atom_style {style}
boundary f f f
region box block -5 5 -5 5 -5 5
create_box 1 box
{dump}
"""

    def check(self, dump_line, message, style="polyhedron"):
        self.assertStopsWith(run(self.BOX.format(style=style, dump=dump_line)),
                             "dump polyhedron/vtk (id d): " + message)

    def test_atom_style_without_polyhedron(self):
        self.check("dump d all polyhedron/vtk 10 g_*.vtp",
                   "needs atom_style polyhedron (or hybrid with polyhedron), not 'atomic'",
                   style="atomic")

    def test_file_without_star(self):
        self.check("dump d all polyhedron/vtk 10 post/grains.vtp",
                   "file 'post/grains.vtp' must contain a '*' in its name")

    def test_file_not_vtp(self):
        self.check("dump d all polyhedron/vtk 10 grains_*.vtu",
                   "file 'grains_*.vtu' must end in '.vtp'")

    def test_unknown_keyword(self):
        self.check("dump d all polyhedron/vtk 10 g_*.vtp colour red",
                   "unknown keyword 'colour'; accepted: format, sweep")

    def test_missing_value(self):
        self.check("dump d all polyhedron/vtk 10 g_*.vtp sweep", "missing value after 'sweep'")
        self.check("dump d all polyhedron/vtk 10 g_*.vtp format", "missing value after 'format'")

    def test_bad_values(self):
        self.check("dump d all polyhedron/vtk 10 g_*.vtp sweep maybe",
                   "value of 'sweep' must be 'yes' or 'no', got 'maybe'")
        self.check("dump d all polyhedron/vtk 10 g_*.vtp format hex",
                   "value of 'format' must be 'ascii' or 'binary', got 'hex'")


if __name__ == "__main__":
    main()
