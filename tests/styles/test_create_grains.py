"""create_grains (atom_style polyhedron): the particle layer on two staggered lattices and
random non-overlapping insertion. Checked independently of the C++ geometry: no overlaps by
an exact polytope distance written here (separating-axis test for disjointness, then the
minimum over vertex-face and edge-edge feature pairs), masses by Steiner's formula, the
same grains on 1 and 2 MPI ranks, and the ERROR texts."""

import math
import os
import re
import unittest

import numpy as np

from liggghts_run import DeckTestCase, main, read_dump, run

HEADER = """
units           lj
atom_style      polyhedron
atom_modify     sort 0 0.0
boundary        f f f
region          box block -8 8 -5 5 -2 12
create_box      1 box
"""

FOOTER = """
dump            d all custom 1 dump.g id x y z vx vy vz mass
dump_modify     d format "%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g"
write_data      data.g
run             0
"""


# ---------------------------------------------------------------------------------------
# reading what create_grains and write_data wrote

class Grain:
    def __init__(self, words):
        self.tag, self.shape = int(words[1]), int(words[2])
        self.sweep, self.volume, self.density = (float(w) for w in words[3:6])
        self.x = np.array([float(w) for w in words[6:9]])
        self.q = np.array([float(w) for w in words[9:13]])
        self.n_vertices, self.n_faces = int(words[13]), int(words[14])
        self.body = None
        self.faces = []

    def rotation(self):
        w, x, y, z = self.q / np.linalg.norm(self.q)
        return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                         [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                         [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])

    def world(self):
        return self.body @ self.rotation().T + self.x

    def bounding_radius(self):
        return np.max(np.linalg.norm(self.body, axis=1)) + self.sweep

    def edges(self):
        pairs = set()
        for f in self.faces:
            for a, b in zip(f, f[1:] + f[:1]):
                pairs.add((min(a, b), max(a, b)))
        return sorted(pairs)


def read_shapes(path):
    grains = []
    with open(path) as f:
        lines = [line for line in f.read().splitlines() if line and not line.startswith("#")]
    k = 0
    while k < len(lines):
        g = Grain(lines[k].split())
        k += 1
        g.body = np.array([[float(w) for w in lines[k + v].split()] for v in range(g.n_vertices)])
        k += g.n_vertices
        for _ in range(g.n_faces):
            words = [int(w) for w in lines[k].split()]
            assert words[0] == len(words) - 1
            g.faces.append(words[1:])
            k += 1
        grains.append(g)
    return grains


def read_data_atoms(path):
    """write_data Atoms: id type shape density qw qi qj qk x y z ix iy iz, sorted by id."""
    with open(path) as f:
        lines = f.read().splitlines()
    k = lines.index("Atoms") + 2
    rows = []
    while k < len(lines) and lines[k].strip():
        rows.append([float(w) for w in lines[k].split()])
        k += 1
    data = np.array(rows)
    return data[np.argsort(data[:, 0])]


def reported(output):
    """create_grains' 'minimum gap G over P close pairs' of the last command (None if none)."""
    found = re.findall(r"^create_grains: minimum gap (\S+) over (\d+) close pairs", output, re.M)
    return (float(found[-1][0]), int(found[-1][1])) if found else None


# ---------------------------------------------------------------------------------------
# exact geometry of convex polytopes, independent of the plugin's GJK / SAT

def face_planes(vertices, faces):
    normals, offsets = [], []
    for f in faces:
        p = vertices[f]
        n = np.cross(p, np.roll(p, -1, axis=0)).sum(axis=0)  # Newell
        n /= np.linalg.norm(n)
        normals.append(n)
        offsets.append(n @ p.mean(axis=0))
    return np.array(normals), np.array(offsets)


def separated_by_axes(va, vb, axes):
    """Largest separation of the two vertex sets along the given axes (> 0: disjoint)."""
    pa, pb = va @ axes.T, vb @ axes.T
    sep = np.maximum(pb.min(axis=0) - pa.max(axis=0), pa.min(axis=0) - pb.max(axis=0))
    return sep.max()


def point_segment(p, a, b):
    """Distances of points p (n x 3) to segments a-b (m x 3): n x m."""
    d = b - a
    t = np.einsum("nmk,mk->nm", p[:, None, :] - a[None, :, :], d) / np.einsum("mk,mk->m", d, d)
    t = np.clip(t, 0.0, 1.0)
    closest = a[None, :, :] + t[:, :, None] * d[None, :, :]
    return np.linalg.norm(p[:, None, :] - closest, axis=2)


def segment_segment(p1, q1, p2, q2):
    """Distances between segments p1-q1 (n) and p2-q2 (m), Ericson's closest points: n x m."""
    d1, d2 = (q1 - p1)[:, None, :], (q2 - p2)[None, :, :]
    r = p1[:, None, :] - p2[None, :, :]
    a, e = (d1 * d1).sum(axis=2), (d2 * d2).sum(axis=2)
    b, c, f = (d1 * d2).sum(axis=2), (d1 * r).sum(axis=2), (d2 * r).sum(axis=2)
    denom = a * e - b * b
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(denom > 1e-14 * a * e, np.clip((b * f - c * e) / denom, 0.0, 1.0), 0.0)
        t = (b * s + f) / e
        s = np.where(t < 0.0, np.clip(-c / a, 0.0, 1.0), np.where(t > 1.0, np.clip((b - c) / a, 0.0, 1.0), s))
    t = np.clip(t, 0.0, 1.0)
    diff = r + s[:, :, None] * d1 - t[:, :, None] * d2
    return np.linalg.norm(diff, axis=2)


def vertex_face(points, vertices, faces, normals, offsets):
    """Smallest distance of points to the faces whose interior they project into."""
    best = math.inf
    for f, n, off in zip(faces, normals, offsets):
        h = points @ n - off
        proj = points - h[:, None] * n
        p = vertices[f]
        inside = np.ones(len(points), dtype=bool)
        for a, b in zip(p, np.roll(p, -1, axis=0)):
            inside &= np.cross(b - a, proj - a) @ n >= 0.0
        mask = inside & (h > 0.0)
        if mask.any():
            best = min(best, h[mask].min())
    return best


def point_core_distance(point, g):
    """Exact distance of a point (a sphere's core) and a polytope core; -1 if the point is
    inside (no separating axis among the polytope's face normals: the faces of point − P
    are P's faces). Outside: the nearest of its edges (ends included) and faces."""
    v = g.world()
    normals, offsets = face_planes(v, g.faces)
    p = np.array([point])
    if separated_by_axes(p, v, normals) <= 0.0:
        return -1.0
    e = np.array(g.edges())
    return min(point_segment(p, v[e[:, 0]], v[e[:, 1]]).min(), vertex_face(p, v, g.faces, normals, offsets))


def core_distance(ga, gb):
    """Exact distance of the two sharp cores; -1 if they intersect (no separating axis
    among the face normals and edge-edge cross products). A sphere's core is its centre
    (one vertex, no faces)."""
    if not ga.faces and not gb.faces:
        return float(np.linalg.norm(ga.world()[0] - gb.world()[0]))
    if not ga.faces or not gb.faces:
        point, poly = (ga, gb) if not ga.faces else (gb, ga)
        return point_core_distance(point.world()[0], poly)
    va, vb = ga.world(), gb.world()
    na, oa = face_planes(va, ga.faces)
    nb, ob = face_planes(vb, gb.faces)
    ea, eb = np.array(ga.edges()), np.array(gb.edges())
    da, db = va[ea[:, 1]] - va[ea[:, 0]], vb[eb[:, 1]] - vb[eb[:, 0]]
    cross = np.cross(da[:, None, :], db[None, :, :]).reshape(-1, 3)
    norm = np.linalg.norm(cross, axis=1)
    cross = cross[norm > 1e-12] / norm[norm > 1e-12, None]
    if separated_by_axes(va, vb, np.vstack([na, nb, cross])) <= 0.0:
        return -1.0
    d = segment_segment(va[ea[:, 0]], va[ea[:, 1]], vb[eb[:, 0]], vb[eb[:, 1]]).min()
    d = min(d, point_segment(va, vb[eb[:, 0]], vb[eb[:, 1]]).min(),
            point_segment(vb, va[ea[:, 0]], va[ea[:, 1]]).min())
    d = min(d, vertex_face(va, vb, gb.faces, nb, ob), vertex_face(vb, va, ga.faces, na, oa))
    return d


def segment_core_distance(g, a, b):
    """Exact distance of the grain's core and the segment a-b; -1 if they intersect."""
    v = g.world()
    normals, offsets = face_planes(v, g.faces)
    e = np.array(g.edges())
    d = v[e[:, 1]] - v[e[:, 0]]
    cross = np.cross(d, b - a)
    norm = np.linalg.norm(cross, axis=1)
    cross = cross[norm > 1e-12] / norm[norm > 1e-12, None]
    if separated_by_axes(v, np.array([a, b]), np.vstack([normals, cross])) <= 0.0:
        return -1.0
    dist = segment_segment(v[e[:, 0]], v[e[:, 1]], a[None, :], b[None, :]).min()
    dist = min(dist, point_segment(v, a[None, :], b[None, :]).min())
    return min(dist, vertex_face(np.array([a, b]), v, g.faces, normals, offsets))


def gap_of(a, b):
    return core_distance(a, b) - a.sweep - b.sweep


def gaps(grains):
    """Gap (core distance − r_A − r_B) of every pair whose bounding spheres meet."""
    out = []
    for i in range(len(grains)):
        for j in range(i + 1, len(grains)):
            a, b = grains[i], grains[j]
            if np.linalg.norm(a.x - b.x) > a.bounding_radius() + b.bounding_radius():
                continue
            out.append(core_distance(a, b) - a.sweep - b.sweep)
    return np.array(out)


def dilated_volume(g):
    """Steiner: V + S r + (r^2/2) sum_e L_e alpha_e + 4/3 pi r^3 of the grain's core."""
    v, faces, r = g.body, g.faces, g.sweep
    normals, _ = face_planes(v, faces)
    volume = sum(np.linalg.det(np.array([v[f[0]], v[f[k]], v[f[k + 1]]])) / 6.0
                 for f in faces for k in range(1, len(f) - 1))
    area = sum(0.5 * np.linalg.norm(np.cross(v[f[k]] - v[f[0]], v[f[k + 1]] - v[f[0]]))
               for f in faces for k in range(1, len(f) - 1))
    edge_faces = {}
    for fi, f in enumerate(faces):
        for a, b in zip(f, f[1:] + f[:1]):
            edge_faces.setdefault((min(a, b), max(a, b)), []).append(fi)
    wedge = 0.0
    for (a, b), fs in edge_faces.items():
        assert len(fs) == 2
        n1, n2 = normals[fs[0]], normals[fs[1]]
        wedge += np.linalg.norm(v[a] - v[b]) * math.atan2(np.linalg.norm(np.cross(n1, n2)), n1 @ n2)
    return volume + area * r + 0.5 * r * r * wedge + 4.0 / 3.0 * math.pi * r ** 3


def lattice_sites(lo, hi, spacing, z0, a_max, inside):
    """The layer's sites in create_grains' order (same floating-point operations)."""
    cells = [math.floor((hi[d] - lo[d]) / spacing + 1e-9) for d in range(2)]
    margin = [0.5 * ((hi[d] - lo[d]) - cells[d] * spacing) for d in range(2)]
    sites = []
    for lattice in (0, 1):
        z = z0 if lattice == 0 else z0 + 2.0 * a_max
        shift = 0.5 * spacing if lattice == 0 else spacing
        for j in range(cells[1] - lattice):
            y = lo[1] + (margin[1] + shift) + j * spacing
            for i in range(cells[0] - lattice):
                x = lo[0] + (margin[0] + shift) + i * spacing
                if inside(x, y, z):
                    sites.append((x, y, z))
    return sites


def cube_grain(center, q=(1.0, 0.0, 0.0, 0.0), edge=1.0, sweep=0.0):
    """A Grain of a cube (6 quadrilaterals, counter-clockwise seen from outside)."""
    h = 0.5 * edge
    g = Grain(["grain", "0", "0", repr(sweep), "0", "1", *map(repr, center), *map(repr, q), "8", "6"])
    g.body = np.array([[(i & 1) * 2 * h - h, ((i >> 1) & 1) * 2 * h - h, (i >> 2) * 2 * h - h]
                       for i in range(8)])
    g.faces = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    return g


class Checker(DeckTestCase):
    """The Python distance used above, on configurations with known answers."""

    def test_known_distances(self):
        s = math.sqrt(0.5)  # half the face diagonal of the unit cube
        z45 = (math.cos(math.pi / 8), 0.0, 0.0, math.sin(math.pi / 8))  # 45 degrees about z
        x45 = (math.cos(math.pi / 8), math.sin(math.pi / 8), 0.0, 0.0)  # 45 degrees about x
        y45 = (math.cos(math.pi / 8), 0.0, math.sin(math.pi / 8), 0.0)  # 45 degrees about y
        a = cube_grain((0.0, 0.0, 0.0))
        az = cube_grain((0.0, 0.0, 0.0), z45)  # leading edge along z at x = s
        cases = [
            (a, cube_grain((1.7, 0.0, 0.0)), 0.7),                               # face-face
            (a, cube_grain((1.5, 1.5, 1.5)), math.sqrt(3) * 0.5),                # vertex-vertex
            (a, cube_grain((1.5, 1.5, 0.3)), math.sqrt(0.5)),                    # parallel edges
            (a, cube_grain((0.5 + s + 0.25, 0.0, 0.2), z45), 0.25),              # edge on face
            (az, cube_grain((0.5 + s + 0.3, 0.0, 0.0), x45), 0.3),               # face under edge
            (az, cube_grain((2 * s + 0.1, 0.0, 0.0), y45), 0.1),                 # crossed edges
            (az, cube_grain((2 * s + 0.1, 0.3, 0.35), y45), 0.1),                # crossed, offset
            (az, cube_grain((2 * s + 0.1, 0.8, 0.0), y45), 0.4 * s),             # vertex-face
        ]
        for ga, gb, expected in cases:
            self.assertAlmostEqual(core_distance(ga, gb), expected, delta=1e-14)
        # overlap and sweep
        self.assertEqual(core_distance(a, cube_grain((0.9, 0.1, 0.0), z45)), -1.0)
        g = gaps([cube_grain((0, 0, 0), sweep=0.1), cube_grain((1.25, 0, 0), sweep=0.1)])
        self.assertAlmostEqual(g[0], 0.05, delta=1e-14)
        g = gaps([cube_grain((0, 0, 0), sweep=0.1), cube_grain((1.15, 0, 0), sweep=0.1)])
        self.assertLess(g[0], 0.0)

    def test_steiner_volume(self):
        e, r = 1.3, 0.2
        g = cube_grain((0, 0, 0), edge=e, sweep=r)
        self.assertAlmostEqual(dilated_volume(g), e ** 3 + 6 * e * e * r + 3 * math.pi * r * r * e
                               + 4 / 3 * math.pi * r ** 3, delta=1e-13)


# ---------------------------------------------------------------------------------------

class GrainChecks(DeckTestCase):
    def insert(self, body, np_ranks=1):
        result = run(HEADER + body + FOOTER, np_ranks=np_ranks)
        self.assertRanCleanly(result)
        return result

    def check_grains(self, result, n, inside, density=1.5, shapes_file="shapes.txt"):
        """n grains, centres inside, no overlaps, masses; returns (grains, gaps)."""
        grains = read_shapes(result.path(shapes_file))
        dump = read_dump(result.path("dump.g"))
        data = read_data_atoms(result.path("data.g"))
        self.assertEqual(len(grains), n)
        tags = [g.tag for g in grains]
        self.assertTrue(set(tags) <= set(dump["id"].astype(int).tolist()))
        for g in grains:
            self.assertTrue(inside(*g.x), f"grain {g.tag} at {g.x} is outside the region")
            self.assertAlmostEqual(np.linalg.norm(g.q), 1.0, delta=1e-15)
            k = int(np.searchsorted(dump["id"], g.tag))
            np.testing.assert_array_equal([dump["x"][k], dump["y"][k], dump["z"][k]], g.x)
            np.testing.assert_array_equal(data[k, 4:8], g.q)  # qw qi qj qk
            self.assertEqual(int(data[k, 2]), g.shape)
            self.assertEqual([dump["vx"][k], dump["vy"][k], dump["vz"][k]], [0.0, 0.0, 0.0])
            # mass = density x library volume; that volume = Steiner's formula here
            self.assertEqual(g.density, density)
            self.assertAlmostEqual(dump["mass"][k] / (density * g.volume), 1.0, delta=1e-14)
            self.assertAlmostEqual(g.volume / dilated_volume(g), 1.0, delta=1e-12)
        g = gaps(grains)
        self.assertTrue(np.all(g > 0.0), f"overlapping pairs: gaps {np.sort(g)[:5]}")
        return grains, g


class RandomInsertion(GrainChecks):
    BODY = """
region          cont block -7 7 -4 4 0 4
create_grains   1 60 random cont seed {seed} write_shapes shapes.txt
"""

    @staticmethod
    def inside(x, y, z):
        return -7 <= x <= 7 and -4 <= y <= 4 and 0 <= z <= 4

    def test_random_block_one_and_two_ranks(self):
        one = self.insert(self.BODY.format(seed=11))
        grains, g = self.check_grains(one, 60, self.inside)
        # the gap create_grains reports is the smallest one found here, over the same pairs
        gap, pairs = reported(one.output)
        self.assertEqual(pairs, len(g))
        self.assertAlmostEqual(gap / g.min(), 1.0, delta=1e-9)
        print(f"\nrandom 60 grains: {len(g)} close pairs, minimum gap {g.min():.6g} "
              f"(create_grains: {gap:.6g})")
        self.assertEqual(sorted(g.tag for g in grains), list(range(1, 61)))
        self.assertGreater(len({g.shape for g in grains}), 59)  # a shape per grain

        two = self.insert(self.BODY.format(seed=11), np_ranks=2)
        a, b = read_data_atoms(one.path("data.g")), read_data_atoms(two.path("data.g"))
        np.testing.assert_array_equal(a, b)  # tags, shapes, quaternions, positions: identical
        with open(one.path("shapes.txt")) as f1, open(two.path("shapes.txt")) as f2:
            self.assertEqual(f1.read(), f2.read())
        # both ranks own grains: the box is split at x = 0
        self.assertIn("2 by 1 by 1 MPI processor grid", two.output)
        self.assertTrue(np.any(a[:, 8] < 0) and np.any(a[:, 8] >= 0))

        other = self.insert(self.BODY.format(seed=12))
        c = read_data_atoms(other.path("data.g"))
        self.assertGreater(np.min(np.abs(a[:, 8:11] - c[:, 8:11]).max(axis=1)), 1e-6)

    def test_dense_random_in_cylinder(self):
        # a crowded cylinder: many close pairs, small gaps
        body = """
region          cyl cylinder z 0 0 3 0 3
create_grains   1 30 random cyl seed 5 attempts 20000 write_shapes shapes.txt
"""
        res = self.insert(body)
        inside = lambda x, y, z: math.hypot(x, y) <= 3 and 0 <= z <= 3
        grains, g = self.check_grains(res, 30, inside)
        gap, pairs = reported(res.output)
        self.assertEqual(pairs, len(g))
        self.assertAlmostEqual(gap / g.min(), 1.0, delta=1e-9)
        print(f"\ndense cylinder, 30 grains: {len(g)} close pairs, minimum gap {g.min():.6g}")

    def test_fixed_shapes(self):
        # one library shape for all grains; mass of a dilated box by Steiner in closed form
        lx, ly, lz, r, rho = 1.2, 0.8, 0.6, 0.05, 2.0
        res = self.insert(f"""
region          cont block -7 7 -4 4 0 4
create_grains   1 30 random cont seed 3 shape box {lx} {ly} {lz} sweep {r} density {rho} write_shapes shapes.txt
""")
        grains, _ = self.check_grains(res, 30, self.inside, density=rho)
        self.assertEqual({g.shape for g in grains}, {0})
        volume = (lx * ly * lz + 2 * (lx * ly + ly * lz + lx * lz) * r + math.pi * r * r * (lx + ly + lz)
                  + 4 / 3 * math.pi * r ** 3)
        dump = read_dump(res.path("dump.g"))
        np.testing.assert_allclose(dump["mass"], rho * volume, rtol=1e-14)
        for shape in ("cube 0.9", "tetrahedron 1.5", "octahedron 1.1", "file pts.txt"):
            files = {"pts.txt": "# a cube\n" + "".join(f"{(i & 1) - 0.5} {((i >> 1) & 1) - 0.5} {(i >> 2) - 0.5}\n"
                                                       for i in range(8))}
            text = HEADER + f"""
region          cont block -7 7 -4 4 0 4
create_grains   1 20 random cont seed 4 shape {shape} write_shapes shapes.txt
""" + FOOTER
            res = run(text, files=files)
            self.assertRanCleanly(res)
            self.check_grains(res, 20, self.inside)

    def test_spheres(self):
        """shape sphere R: one-vertex grains of radius R, mass ρ 4/3 π R³, no overlaps
        (centres more than 2R apart); then spheres among cubes, the sphere-cube gaps by
        the point-polytope distance above, the smallest one the gap create_grains reports
        (over the sphere-cube pairs: spheres whose bounding spheres meet overlap)."""
        r, rho = 0.6, 2.0
        res = self.insert(f"""
region          cont block -7 7 -4 4 0 4
create_grains   1 150 random cont seed 9 shape sphere {r} density {rho} write_shapes shapes.txt
""")
        grains, g = self.check_grains(res, 150, self.inside, density=rho)
        volume = 4.0 / 3.0 * math.pi * r ** 3
        for grain in grains:
            self.assertEqual((grain.shape, grain.n_vertices, grain.n_faces, grain.sweep), (0, 1, 0, r))
            self.assertEqual(grain.body.tolist(), [[0.0, 0.0, 0.0]])
            self.assertAlmostEqual(grain.volume / volume, 1.0, delta=1e-15)
        np.testing.assert_allclose(read_dump(res.path("dump.g"))["mass"], rho * volume, rtol=1e-15)
        centres = np.array([grain.x for grain in grains])
        apart = np.linalg.norm(centres[:, None, :] - centres[None, :, :], axis=2)[np.triu_indices(150, 1)]
        self.assertGreater(apart.min(), 2 * r)
        # a sphere's bounding sphere is the sphere: bounding spheres that meet overlap, so
        # no placed pair is a close pair
        self.assertEqual(len(g), 0)
        self.assertIsNone(reported(res.output))
        self.assertIn("create_grains: no close pairs (bounding spheres apart)", res.output)
        print(f"\n150 spheres: smallest gap {apart.min() - 2 * r:.6g} (centre distance - 2R)")

        res = self.insert("""
region          cont block -7 7 -4 4 0 4
create_grains   1 30 random cont seed 3 shape cube 1.0 sweep 0.1 write_shapes first.txt
create_grains   1 40 random cont seed 4 shape sphere 0.5 write_shapes shapes.txt
""")
        spheres, _ = self.check_grains(res, 40, self.inside)
        cubes = read_shapes(res.path("first.txt"))
        self.assertEqual({grain.shape for grain in spheres}, {1})
        mixed = [gap_of(c, s) for c in cubes for s in spheres
                 if np.linalg.norm(c.x - s.x) <= c.bounding_radius() + s.bounding_radius()]
        both = gaps(spheres).tolist() + mixed
        self.assertGreater(len(mixed), 10)
        self.assertTrue(np.all(np.array(both) > 0.0))
        gap, pairs = reported(res.output)
        self.assertEqual(pairs, len(both))
        self.assertAlmostEqual(gap / min(both), 1.0, delta=1e-9)
        print(f"40 spheres among 30 cubes: {len(mixed)} close sphere-cube pairs, minimum gap {min(both):.6g}")

    def test_avoids_existing_grains(self):
        res = self.insert("""
region          cont block -7 7 -4 4 0 6
create_grains   1 40 layer cont 1 seed 21 write_shapes first.txt
create_grains   1 40 random cont seed 22 write_shapes shapes.txt
""")
        inside = lambda x, y, z: -7 <= x <= 7 and -4 <= y <= 4 and 0 <= z <= 6
        second, _ = self.check_grains(res, 40, inside)
        first = read_shapes(res.path("first.txt"))
        self.assertEqual([g.tag for g in second], list(range(41, 81)))
        self.assertEqual(min(g.shape for g in second), 40)  # appended to the library
        g_all, g_first = gaps(first + second), gaps(first)
        self.assertTrue(np.all(g_all > 0.0))
        # the second command reports the pairs it checked: new-new and new-old
        gap, pairs = reported(res.output)
        self.assertEqual(pairs, len(g_all) - len(g_first))
        new = np.sort(g_all)
        for x in g_first:  # drop the old-old pairs
            new = np.delete(new, np.argmin(np.abs(new - x)))
        self.assertAlmostEqual(gap / new.min(), 1.0, delta=1e-9)


    def test_avoids_existing_grains_beside_the_region(self):
        # existing grains whose centres lie outside the new region but within reach of it
        # (the layer at z = 1.5 below a region from z = 2) are obstacles: every new grain
        # keeps apart from them and the command counts every new-old pair whose bounding
        # spheres meet; a layer far above (z = 10) is out of reach and changes nothing.
        res = self.insert("""
region          low block -7 7 -4 4 0 2
region          high block -7 7 -4 4 2 6
region          top block -7 7 -4 4 9 11
create_grains   1 25 layer top 10 seed 20 write_shapes far.txt
create_grains   1 25 layer low 1.5 seed 21 write_shapes first.txt
create_grains   1 60 random high seed 22 write_shapes shapes.txt
""")
        inside = lambda x, y, z: -7 <= x <= 7 and -4 <= y <= 4 and 2 <= z <= 6
        second, _ = self.check_grains(res, 60, inside)
        first, far = read_shapes(res.path("first.txt")), read_shapes(res.path("far.txt"))
        g_all, g_old = gaps(far + first + second), gaps(far + first)
        self.assertTrue(np.all(g_all > 0.0))
        gap, pairs = reported(res.output)
        self.assertEqual(pairs, len(g_all) - len(g_old))
        self.assertGreater(len(gaps(first + second)) - len(gaps(first)) - len(gaps(second)), 0)  # in reach
        # only the atoms within reach are gathered from the ranks: a centre within its
        # bounding radius plus the largest new one of the box of the new centres, counted
        # here from the written grains with the region's box (the second command, a layer,
        # takes the box of its sites, inside the region's: the far layer is out of reach of
        # both, none; the third: the layer below, not the far one)
        counts = [(int(a), int(b)) for a, b in re.findall(
            r"^create_grains: (\d+) of the (\d+) atoms already in the box within reach of the region", res.output, re.M)]

        def within_reach(old, new, lo, hi):
            reach = max(g.bounding_radius() for g in new)
            return sum(all(lo[d] - g.bounding_radius() - reach <= g.x[d] <= hi[d] + g.bounding_radius() + reach
                           for d in range(3)) for g in old)

        self.assertEqual(counts, [(within_reach(far, first, (-7, -4, 0), (7, 4, 2)), 25),
                                  (within_reach(far + first, second, (-7, -4, 2), (7, 4, 6)), 50)])
        self.assertEqual([n for n, _ in counts], [0, 25])

    def test_avoids_wire(self):
        # atom_style hybrid: grains keep clear of the wire's segments (spherocylinders of
        # the bead radius between consecutive beads), not only of its beads
        text = HEADER.replace("atom_style      polyhedron", "atom_style      hybrid polyhedron wire") + """
region          cont block -3 3 -3 3 0 3
create_wire     1 line -3 -2 0.2 3 2 2.8 segment 1.0 radius 0.1
create_wire     1 line -3 2 2.8 3 -2 0.2 segment 1.2 radius 0.15
create_wire     1 loop 0 0 1.5 2 2 0.5
create_grains   1 25 random cont seed 31 write_shapes shapes.txt
""" + FOOTER
        res = run(text)
        self.assertRanCleanly(res)
        grains = read_shapes(res.path("shapes.txt"))
        self.assertEqual(len(grains), 25)
        # hybrid Atoms line: id type x y z | shape density qw qi qj qk | prev next rest radius mass
        data = read_data_atoms(res.path("data.g"))
        beads = data[data[:, 5] < 0]
        ids = beads[:, 0].astype(int)
        pos = {i: beads[k, 2:5] for k, i in enumerate(ids)}
        radius = {i: beads[k, 14] for k, i in enumerate(ids)}
        segments = [(pos[i], pos[int(nxt)], radius[i]) for i, nxt in zip(ids, beads[:, 12]) if nxt > 0]
        self.assertGreater(len(segments), 20)
        closest = math.inf
        for g in grains:
            for a, b, r in segments:
                mid, half = 0.5 * (a + b), 0.5 * np.linalg.norm(b - a)
                if np.linalg.norm(mid - g.x) > g.bounding_radius() + half + r:
                    continue
                closest = min(closest, segment_core_distance(g, a, b) - g.sweep - r)
        self.assertGreater(closest, 0.0)
        self.assertLess(closest, 0.5)  # the wire runs through the region: some grains are close
        print(f"\ngrains around a wire: smallest grain-segment gap {closest:.6g}")


class Layer(GrainChecks):
    def test_block_layer_sites(self):
        # region -7..7 x -4..4: 7 x 4 sites at z0 and 6 x 3 sites 2 a_max higher
        body = """
region          cont block -7 7 -4 4 0 10
create_grains   1 40 layer cont 1.5 seed 5 a_max 1.0 write_shapes shapes.txt
"""
        one = self.insert(body)
        inside = lambda x, y, z: -7 <= x <= 7 and -4 <= y <= 4 and 0 <= z <= 10
        grains, g = self.check_grains(one, 40, inside)
        sites = lattice_sites((-7, -4), (7, 4), 2.0, 1.5, 1.0, inside)
        self.assertEqual(len(sites), 28 + 18)
        self.assertIn("layer of 46 lattice sites", one.output)
        for grain, site in zip(grains, sites):  # centres of mass exactly on the sites, in order
            np.testing.assert_array_equal(grain.x, site)
        self.assertEqual(sorted({g.x[2] for g in grains}), [1.5, 3.5])
        self.assertEqual(sum(g.x[2] == 1.5 for g in grains), 28)
        gap, pairs = reported(one.output)
        self.assertEqual(pairs, len(g))
        self.assertAlmostEqual(gap / g.min(), 1.0, delta=1e-9)
        print(f"\nlayer of 40 grains: {len(g)} close pairs, minimum gap {g.min():.6g}")

        two = self.insert(body, np_ranks=2)
        np.testing.assert_array_equal(read_data_atoms(one.path("data.g")), read_data_atoms(two.path("data.g")))

    def test_cylinder_layer_and_spacing(self):
        body = """
region          cyl cylinder z 0 0 5 0 10
create_grains   1 {n} layer cyl 2 seed 8 spacing 2.5 a_max 0.9 a_min 0.7 write_shapes shapes.txt
"""
        inside = lambda x, y, z: math.hypot(x, y) <= 5 and 0 <= z <= 10
        sites = lattice_sites((-5, -5), (5, 5), 2.5, 2.0, 0.9, inside)
        res = self.insert(body.format(n=len(sites)))
        grains, _ = self.check_grains(res, len(sites), inside)
        for grain, site in zip(grains, sites):
            np.testing.assert_array_equal(grain.x, site)
        self.assertEqual(sorted({g.x[2] for g in grains}), [2.0, 3.8])
        # too many grains for the sites
        res = run(HEADER + body.format(n=len(sites) + 1) + FOOTER)
        self.assertStopsWith(res, f"command create_grains (id -): region too small for the layer: "
                                  f"{len(sites) + 1} grains asked, {len(sites)} sites")


class StockSpheres(DeckTestCase):
    """Without atom_style polyhedron, create_grains makes stock granular spheres, each of
    the (swept) volume the grain of the same command would have: the same sites, the same
    volumes in the same order, as the polyhedra's write_shapes file gives them."""

    SPHERE_HEADER = HEADER.replace("atom_style      polyhedron", "atom_style      sphere")
    SPHERE_FOOTER = """
dump            d all custom 1 dump.s id x y z radius mass
dump_modify     d format "%d %.17g %.17g %.17g %.17g %.17g"
run             0
"""

    def test_spheres_of_the_grains_volumes(self):
        for mode in ("layer cont 1.5", "random cont"):
            command = f"""
region          cont block -7 7 -4 4 0 10
create_grains   1 40 {mode} seed 5 a_max 1.0 density 2.0"""
            polyhedra = run(HEADER + command + " write_shapes shapes.txt\n" + FOOTER)
            self.assertRanCleanly(polyhedra)
            spheres = run(self.SPHERE_HEADER + command + "\n" + self.SPHERE_FOOTER)
            self.assertRanCleanly(spheres)
            self.assertIn("create_grains: 40 spheres of the grains' volumes", spheres.output)
            grains = read_shapes(polyhedra.path("shapes.txt"))
            d = read_dump(spheres.path("dump.s"))
            volume = np.array([g.volume for g in grains])
            np.testing.assert_allclose(4.0 / 3.0 * np.pi * d["radius"] ** 3, volume, rtol=1e-13, atol=0)
            np.testing.assert_allclose(d["mass"], 2.0 * volume, rtol=1e-13, atol=0)
            centres = np.array([d["x"], d["y"], d["z"]]).T
            if mode.startswith("layer"):  # on the lattice sites of the polyhedra
                np.testing.assert_array_equal(centres, np.array([g.x for g in grains]))
            apart = [np.linalg.norm(centres[i] - centres[j]) - d["radius"][i] - d["radius"][j]
                     for i in range(len(centres)) for j in range(i)]
            self.assertGreater(min(apart), 0.0)
            print(f"\n{mode}: 40 spheres of the grains' volumes, radii {d['radius'].min():.4f}.."
                  f"{d['radius'].max():.4f}, smallest gap {min(apart):.4g}")

    def test_errors(self):
        text = self.SPHERE_HEADER + "region cont block -7 7 -4 4 0 4\n"
        self.assertStopsWith(run(text + "create_grains 1 4 random cont seed 1 write_shapes s.txt\n"),
                             "command create_grains (id -): keyword 'write_shapes' applies to polyhedra "
                             "(atom_style polyhedron), not to spheres")
        atomic = HEADER.replace("atom_style      polyhedron", "atom_style      atomic")
        self.assertStopsWith(run(atomic + "region cont block -7 7 -4 4 0 4\n"
                                 "create_grains 1 4 random cont seed 1\n"),
                             "command create_grains (id -): needs atom_style polyhedron, sphere (granular) or "
                             "superquadric, plain or in a hybrid, not 'atomic'")


@unittest.skipUnless(os.environ.get("WIREGRAIN_SUPERQUADRIC") == "ON", "LIGGGHTS built without superquadrics")
class StockSuperquadrics(DeckTestCase):
    """With atom_style superquadric (no polyhedra), create_grains makes LIGGGHTS'
    superquadrics standing in for the grains: the grain's volume (LIGGGHTS' own volume
    formula gives it back), its site and orientation, the longest half-axis along the
    grain's longest extent, the blockiness given."""

    SQ_HEADER = HEADER.replace("atom_style      polyhedron", "atom_style      superquadric")
    SQ_FOOTER = """
dump            d all custom 1 dump.s id x y z shapex shapey shapez blockiness1 blockiness2 quat1 quat2 quat3 quat4 mass
dump_modify     d format "%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g"
run             0
"""

    def test_superquadrics_standing_in_for_the_grains(self):
        command = """
region          cont block -7 7 -4 4 0 10
create_grains   1 40 layer cont 1.5 seed 5 a_max 1.0 density 2.0"""
        polyhedra = run(HEADER + command + " write_shapes shapes.txt\n" + FOOTER)
        self.assertRanCleanly(polyhedra)
        sq = run(self.SQ_HEADER + command + " blockiness 3 4\n" + self.SQ_FOOTER)
        self.assertRanCleanly(sq)
        self.assertIn("create_grains: 40 superquadrics standing in for the grains", sq.output)
        grains = read_shapes(polyhedra.path("shapes.txt"))
        d = read_dump(sq.path("dump.s"))
        volume = np.array([g.volume for g in grains])
        np.testing.assert_allclose(d["mass"], 2.0 * volume, rtol=1e-13, atol=0)
        np.testing.assert_array_equal(np.array([d["x"], d["y"], d["z"]]).T, np.array([g.x for g in grains]))
        np.testing.assert_array_equal(d["blockiness1"], 3.0)
        np.testing.assert_array_equal(d["blockiness2"], 4.0)
        q = np.array([d["quat1"], d["quat2"], d["quat3"], d["quat4"]]).T
        q_grains = np.array([g.q / np.linalg.norm(g.q) for g in grains])
        np.testing.assert_allclose(np.abs(np.sum(q * q_grains, axis=1)), 1.0, rtol=0, atol=1e-14)
        half_axes = np.array([d["shapex"], d["shapey"], d["shapez"]]).T
        extents = np.array([np.abs(g.body).max(axis=0) for g in grains])
        # the longest half-axis along the grain's longest extent (b/a = 0.8 sets them apart;
        # the two shorter ones can swap: the inertia ellipsoid's proportions are not the extents')
        np.testing.assert_array_equal(np.argmax(half_axes, axis=1), np.argmax(extents, axis=1))
        print(f"\n40 superquadrics (n = 3, 4): half-axes {half_axes.min():.4f}..{half_axes.max():.4f}")

    def test_errors(self):
        text = self.SQ_HEADER + "region cont block -7 7 -4 4 0 4\n"
        self.assertStopsWith(run(text + "create_grains 1 4 random cont seed 1 blockiness 1.5 3\n"),
                             "command create_grains (id -): value of 'blockiness' must be a finite number >= 2, "
                             "got 1.5")
        self.assertStopsWith(run(text + "create_grains 1 4 random cont seed 1 write_shapes s.txt\n"),
                             "command create_grains (id -): keyword 'write_shapes' applies to polyhedra "
                             "(atom_style polyhedron), not to superquadrics")
        self.assertStopsWith(run(HEADER + "region cont block -7 7 -4 4 0 4\n"
                                 "create_grains 1 4 random cont seed 1 blockiness 3 3\n"),
                             "command create_grains (id -): keyword 'blockiness' applies to superquadrics "
                             "(atom_style superquadric) only")


class Errors(DeckTestCase):
    def check(self, command, message, header=HEADER, files=None, pattern=None):
        text = header + "region cont block -7 7 -4 4 0 4\n" + command + "\nrun 0\n"
        res = run(text, files=files)
        self.assertStopsWith(res, "command create_grains (id -): " + message)
        if pattern:
            self.assertRegex("\n".join(res.errors()), pattern)

    def test_errors(self):
        base = "create_grains 1 10 random cont seed 1 "
        self.check(base + "vertices 3", "value of 'vertices' must be >= 4, got 3")
        self.check(base + "b_over_a 1.2", "value of 'b_over_a' must be in (0, 1], got 1.2")
        self.check(base + "c_over_a 0.9", "value of 'c_over_a' must be in (0, b_over_a] = (0, 0.8], got 0.9")
        self.check(base + "a_min 1.2", "a_min (1.2) must not exceed a_max (1)")
        self.check(base + "density 0", "value of 'density' must be > 0, got 0")
        self.check(base + "density -1.5", "value of 'density' must be > 0, got -1.5")
        self.check(base + "sweep -0.1", "value of 'sweep' must be >= 0, got -0.1")
        self.check("create_grains 1 10 random nowhere seed 1", "region 'nowhere' does not exist")
        self.check(base + "shape file missing.txt",
                   "'shape file': cannot open vertex file 'missing.txt'")
        self.check(base + "shape file flat.txt", "'shape file': vertex file 'flat.txt'",
                   files={"flat.txt": "0 0 0\n1 0 0\n0 1 0\n1 1 0\n"})
        self.check(base + "shape cylinder 1", "unknown shape 'cylinder' (ellipsoid, cube, box, tetrahedron, "
                                              "octahedron, sphere or file)")
        self.check(base + "shape sphere 0", "value of 'shape sphere' must be > 0, got 0")
        self.check(base + "shape sphere -0.5", "value of 'shape sphere' must be > 0, got -0.5")
        self.check(base + "shape sphere 0.5 sweep 0.1",
                   "keyword 'sweep' does not apply to 'shape sphere' (its radius is the sweep radius)")
        self.check(base + "shape sphere 0.5", "'shape sphere': a sphere has no sharp mass properties: its core "
                   "is one point, of zero volume (use the dilated mass model)",
                   header=HEADER.replace("atom_style      polyhedron", "atom_style      polyhedron mass sharp"))
        self.check(base + "shape file point.txt sweep 0", "'shape file': one point is a sphere and needs "
                   "sweep_radius > 0 (its radius), got 0", files={"point.txt": "0.5 0.5 0.5\n"})
        self.check("create_grains 1 10 random cont", "missing keyword 'seed'")
        self.check("create_grains 1 10 random cont seed 0", "value of 'seed' must be a positive integer, got 0")
        self.check(base + "spacing 2", "keyword 'spacing' applies to 'layer' only")
        self.check("create_grains 1 0 random cont seed 1", "value of 'N' must be >= 1, got 0")
        self.check("create_grains 2 10 random cont seed 1", "atom type 2 is outside 1..1")
        self.check("create_grains 1 10 pile cont seed 1", "unknown mode 'pile' (layer or random)")
        self.check(base + "colour red", "unknown keyword 'colour'; accepted: "
                   "seed, a_min, a_max, b_over_a, c_over_a, vertices, sweep, density, spacing, attempts, blockiness, write_shapes, shape")
        self.check("create_grains 1 500 random cont seed 1 attempts 5", "could only place ",
                   pattern=r"could only place \d+ of 500 grains in region 'cont' \(5 attempts for grain \d+\)")
        self.check("create_grains 1 10 layer cont 20 seed 1", "region too small for the layer: 10 grains asked, 0 sites")
        self.check("create_grains 1 10 layer cont 2 seed 1 spacing 1.2", "grain ",
                   pattern=r"grain \d+ of 10 at the lattice site \(\S+, \S+, 2\) overlaps other grains in all "
                           r"1000 orientations tried \(increase 'spacing' or 'attempts'\)")

    def test_could_only_place(self):
        text = HEADER + "region cont block -2 2 -2 2 0 2\ncreate_grains 1 40 random cont seed 1 attempts 50\nrun 0\n"
        res = run(text)
        self.assertStopsWith(res, "command create_grains (id -): could only place ")
        k = int(re.search(r"could only place (\d+) of 40 grains in region 'cont' \(50 attempts for grain (\d+)\)",
                          "\n".join(res.errors())).group(1))
        self.assertGreater(k, 0)


if __name__ == "__main__":
    main()
