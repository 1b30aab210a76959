"""postprocess/force_network.py: each of its quantities against values worked out by hand on
small dump files written here (forces and normals chosen, an exactly exponential sample,
grains of known stress, a stack of known forces, a stretched chain), and end to end on tiny
columns built by input_scripts/in.column and loaded by input_scripts/in.column_load: the
force balance of the grains above a plane just below the plate, the grains' stresses
against their contacts, the wire's tension against its stretching energy, and the
picture."""

import json
import math
import os
import struct
import subprocess
import sys
import tempfile

import numpy as np

from liggghts_run import SOURCE, DeckTestCase, deck, main, read_dump, read_local_dump, run

SCRIPT = os.path.join(SOURCE, "postprocess", "force_network.py")
COLUMN = deck("input_scripts/in.column")
LOAD = deck("input_scripts/in.column_load")
# the tiny column of test_column_load.py (3 layers of 5 grains, R = 2)
TINY = {"R": 2, "nlayers": 3, "Np": 15, "t_layer": 1.5, "t_wire": 0.5, "t_relax": 8, "t_end": 10, "v_wall": 1,
        "ke_walls": 0, "ke_relax": 0, "root": SOURCE}
STEP = 100
AREA = math.pi * 0.1 ** 2   # the wire's cross-section, r_w = 0.1 (create_wire's default)


def script(*args):
    proc = subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True, timeout=300)
    return proc.returncode, proc.stdout + proc.stderr


# --- dump files ---------------------------------------------------------------------------

def header(kind, count, names):
    return (f"ITEM: TIMESTEP\n{STEP}\nITEM: NUMBER OF {kind}\n{count}\nITEM: BOX BOUNDS ff ff ff\n"
            f"-10 10\n-10 10\n-1 10\nITEM: {'ENTRIES' if kind == 'ENTRIES' else 'ATOMS'} {' '.join(names)}\n")


def contact(kind, a, b, point, normal, fn, force=None, status=1):
    """One row of compute contact/local: the force on b is fn·normal unless given."""
    force = [fn * c for c in normal] if force is None else force
    return [kind, a, b, *point, *normal, fn, *force, 0.0, 0.0, status]


def write_contacts(folder, rows):
    names = [f"c_contacts[{k}]" for k in range(1, 17)]
    with open(os.path.join(folder, f"load_contacts_{STEP}.dump"), "w") as f:
        f.write(header("ENTRIES", len(rows), names))
        for r in rows:
            f.write(" ".join(repr(float(v)) if isinstance(v, float) else str(v) for v in r) + "\n")


def write_grains(folder, grains):
    """grains: [(id, mass, x, y, z, σ_zz)]; the other stress columns 0."""
    names = ["id", "mass", "x", "y", "z"] + [f"c_stress[{k}]" for k in range(1, 11)]
    with open(os.path.join(folder, f"load_grains_{STEP}.dump"), "w") as f:
        f.write(header("ATOMS", len(grains), names))
        for i, m, x, y, z, s in grains:
            f.write(f"{i} {m!r} {x!r} {y!r} {z!r} 0 0 {s!r} 0 0 0 0 0 0 0\n")


def write_wire(folder, beads):
    """beads: [(id, x, y, z, stretching energy, length)]."""
    names = ["id", "x", "y", "z", "radius", "c_energy[1]", "c_energy[2]", "c_energy[3]"]
    with open(os.path.join(folder, f"load_wire_{STEP}.dump"), "w") as f:
        f.write(header("ATOMS", len(beads), names))
        for i, x, y, z, e, l in beads:
            f.write(f"{i} {x!r} {y!r} {z!r} 0.1 {e!r} 0 {l!r}\n")


def analysed(folder, *args):
    status, text = script(folder, "--no-plots", "--no-picture", *args)
    if status != 0:
        raise AssertionError(text)
    with open(os.path.join(folder, f"network_{STEP}.json")) as f:
        return json.load(f)


def lone_grains(n):
    """Grains 1..n on a row, for contacts whose positions do not matter."""
    return [(i, 1.0, float(i), 0.0, 0.5, 0.0) for i in range(1, n + 1)]


# --- by hand ------------------------------------------------------------------------------------

X, Y, Z = (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)


class Synthetic(DeckTestCase):
    def folder(self):
        return tempfile.mkdtemp(prefix="wiregrain-network-")

    # Six closed grain–grain contacts of f_n 1, 1, 2, 3, 5, 6 (the last one two rows of one
    # pair, 2.5 and 3.5, one listed from each side) and three open ones (status 0 with
    # f_n 0, status 0 with f_n 3, status 1 with f_n 0): ⟨f⟩ = 18/6 = 3, x = f/⟨f⟩ = 1/3,
    # 1/3, 2/3, 1, 5/3, 2. Normals: the strong contacts (5, 6) vertical; the weak ones
    # x (f 1), y (f 1), z (f 2), x (f 3).
    def distribution_rows(self):
        p = (0.0, 0.0, 1.0)
        return [contact(3, 1, 2, p, X, 1.0), contact(3, 1, 3, p, Y, 1.0), contact(3, 2, 3, p, Z, 2.0),
                contact(3, 3, 4, p, X, 3.0), contact(3, 4, 5, p, Z, 5.0),
                contact(3, 5, 6, p, Z, 2.5), contact(3, 6, 5, p, (0.0, 0.0, -1.0), 3.5),
                contact(3, 1, 4, p, Z, 0.0, status=0), contact(3, 1, 5, p, Z, 3.0, status=0),
                contact(3, 1, 6, p, Z, 0.0, status=1)]

    def test_distribution_and_networks(self):
        folder = self.folder()
        write_contacts(folder, self.distribution_rows())
        write_grains(folder, lone_grains(6))
        r = analysed(folder)
        d = r["forces"]
        self.assertEqual((d["contacts"], d["closed"], d["open"]), (9, 6, 3))
        self.assertAlmostEqual(d["mean_f"], 3.0, delta=1e-14)
        # bins of 0.25 from 0, each [lower, upper): 1/3 → 1, 2/3 → 2, 1 → 4, 5/3 → 6, 2 → 8
        self.assertEqual(d["counts"], [0, 2, 1, 0, 1, 0, 1, 0, 1])
        np.testing.assert_allclose(d["density"], np.array([0, 2, 1, 0, 1, 0, 1, 0, 1]) / (6 * 0.25), rtol=1e-14)
        # the tail above 1: x − 1 = 2/3, 1; rate (n − 1)/Σ = 1/(5/3)
        self.assertEqual(d["tail"], 2)
        self.assertAlmostEqual(d["beta"], 0.6, delta=1e-14)
        n = r["networks"]
        self.assertEqual(n["strong"]["contacts"], 2)
        self.assertAlmostEqual(n["strong"]["fraction_of_contacts"], 1 / 3, delta=1e-14)
        self.assertAlmostEqual(n["strong"]["fraction_of_force"], 11 / 18, delta=1e-14)
        self.assertAlmostEqual(n["weak"]["fraction_of_contacts"], 2 / 3, delta=1e-14)
        self.assertAlmostEqual(n["weak"]["fraction_of_force"], 7 / 18, delta=1e-14)
        # the fabric tensors, diagonal here: φ = Σ w n n / Σ w
        expected = {("strong", "fabric"): (0, 0, 1), ("strong", "fabric_weighted"): (0, 0, 1),
                    ("weak", "fabric"): (2 / 4, 1 / 4, 1 / 4), ("weak", "fabric_weighted"): (4 / 7, 1 / 7, 2 / 7),
                    ("all", "fabric"): (2 / 6, 1 / 6, 3 / 6), ("all", "fabric_weighted"): (4 / 18, 1 / 18, 13 / 18)}
        for (network, which), diagonal in expected.items():
            f = n[network][which]
            np.testing.assert_allclose(f["tensor"], np.diag(diagonal), atol=1e-14, err_msg=f"{network} {which}")
            np.testing.assert_allclose(f["eigenvalues"], sorted(diagonal), atol=1e-14)
            # the major axis: z (0 degrees) or x (90)
            self.assertAlmostEqual(f["angle_from_vertical"], 0.0 if np.argmax(diagonal) == 2 else 90.0, delta=1e-6)
        # each row a contact: 7 closed rows, ⟨f⟩ = 18/7
        d = analysed(folder, "--per-point")["forces"]
        self.assertEqual((d["contacts"], d["closed"], d["open"]), (10, 7, 3))
        self.assertAlmostEqual(d["mean_f"], 18 / 7, delta=1e-14)

    def test_fabric_of_known_sets(self):
        # an isotropic set (the four diagonals of a cube): φ = I/3; all tilted by 30° from
        # the vertical in the xz plane: φ = n n, eigenvalues (0, 0, 1), axis at 30°
        s = 1 / math.sqrt(3)
        t = math.radians(30)
        # (equal forces for the isotropic set, so that the weighted tensor is I/3 as well)
        for normals, forces, eigen, angle in (([(s, s, s), (s, -s, s), (-s, s, s), (-s, -s, s)], [1.0] * 4, (1 / 3,) * 3,
                                               None),
                                              ([(math.sin(t), 0.0, math.cos(t))] * 3, [1.0, 2.0, 3.0], (0, 0, 1), 30.0)):
            folder = self.folder()
            write_contacts(folder, [contact(3, 1, k + 2, (0.0, 0.0, 1.0), n, f)
                                    for k, (n, f) in enumerate(zip(normals, forces))])
            write_grains(folder, lone_grains(len(normals) + 1))
            for which in ("fabric", "fabric_weighted"):
                f = analysed(folder)["networks"]["all"][which]
                np.testing.assert_allclose(f["eigenvalues"], eigen, atol=1e-14)
                if angle is not None:
                    self.assertAlmostEqual(f["angle_from_vertical"], angle, delta=1e-9)

    # An exactly exponential tail: ⟨f⟩ = 1 by construction (measured 1 − 1.6e-4 and
    # 1 − 5.3e-4: the quantiles' finite mean; checked to 2e-3), the body uniform on
    # [0, 0.8) (n_b mid-quantiles), the tail 1 + q/β (n_t mid-quantiles q of the unit
    # exponential); n_b/n_t set so that the mean is 1 (0.4 n_b + (1 + 1/β) n_t = n_b + n_t).
    # Measured: β = 1.99688 for β = 2 (−0.16 %) and 0.49851 for 0.5 (−0.30 %): the finite
    # quantile set (its mean is 1 − 0.7e-3 for n = 500) and the (n − 1) of the unbiased rate;
    # tolerance 1 %, three times the larger. The standard error is β/√n_t asymptotically.
    def test_exponential_tail(self):
        for beta, n_b, n_t in ((2.0, 500, 600), (0.5, 1000, 300)):
            mid = lambda n: (np.arange(n) + 0.5) / n
            forces = np.concatenate([0.8 * mid(n_b), 1.0 - np.log(1.0 - mid(n_t)) / beta])
            folder = self.folder()
            write_contacts(folder, [contact(3, 1, k + 2, (0.0, 0.0, 1.0), Z, float(f)) for k, f in enumerate(forces)])
            write_grains(folder, lone_grains(len(forces) + 1))
            d = analysed(folder)["forces"]
            print(f"beta {beta}: fitted {d['beta']:.6g} +- {d['beta_error']:.3g} from {d['tail']} contacts")
            self.assertEqual(d["tail"], n_t)
            self.assertAlmostEqual(d["mean_f"], 1.0, delta=2e-3)
            self.assertLess(abs(d["beta"] / beta - 1), 0.01)
            self.assertLess(abs(d["beta_error"] / (beta / math.sqrt(n_t)) - 1), 0.01)

    # Five grains of known mass and σ_zz, --R 2, two r bins [0, 1), [1, 2] and two z bins
    # [0, 1), [1, 2] (z to the highest centre, 2): V = m/1.5 (create_grains' density).
    # Bin (0, 0): grains A (V 2, σ −2) and B (V 1, σ −6): mean −10/3, Σ V σ = −10 over the
    # bin's volume π; (1, 0): C (V 1, σ −1); (1, 1): D (V 2, σ −4); (0, 1): E (V 1, σ 0).
    # The outer edges are 1 + 1e-12 times the largest r and z (the highest centre falls
    # inside), so the bins' volumes, and the stresses per volume, are checked to 1e-11.
    def test_stress_bins(self):
        folder = self.folder()
        write_contacts(folder, [])
        write_grains(folder, [(1, 3.0, 0.5, 0.0, 0.5, -2.0), (2, 1.5, 0.0, -0.3, 0.8, -6.0),
                              (3, 1.5, 1.5, 0.0, 0.5, -1.0), (4, 3.0, 0.0, 1.2, 1.5, -4.0),
                              (5, 1.5, 0.1, 0.0, 2.0, 0.0)])
        for density, extra in ((1.5, []), (3.0, ["--density", "3"])):
            s = analysed(folder, "--R", "2", "--r-bins", "2", "--z-bins", "2", *extra)["stress"]
            v = 1.5 / density   # the volumes scale as 1/density
            np.testing.assert_allclose(s["r_edges"], [0, 1, 2], rtol=1e-11)
            np.testing.assert_allclose(s["z_edges"], [0, 1, 2], rtol=1e-11)
            np.testing.assert_allclose(s["map"]["mean"], [[-10 / 3, 0.0], [-1.0, -4.0]], rtol=1e-14)
            self.assertEqual(s["map"]["grains"], [[2, 1], [1, 1]])
            slab = [[math.pi, math.pi], [3 * math.pi, 3 * math.pi]]   # π (r1² − r0²) (z1 − z0)
            np.testing.assert_allclose(s["map"]["coarse"], v * np.array([[-10, 0], [-1, -8]]) / slab, rtol=1e-11)
            np.testing.assert_allclose(s["map"]["solid_fraction"], v * np.array([[3, 1], [1, 2]]) / slab, rtol=1e-11)
            # along z: z < 1 A, B, C (Σ V σ −11 v, Σ V 4 v), z ≥ 1 D, E (−8 v, 3 v), slabs 4π
            np.testing.assert_allclose(s["along_z"]["mean"], [-11 / 4, -8 / 3], rtol=1e-14)
            np.testing.assert_allclose(s["along_z"]["coarse"], [-11 * v / (4 * math.pi), -8 * v / (4 * math.pi)],
                                       rtol=1e-11)
            # along r: r < 1 A, B, E (−10 v, 4 v), r ≥ 1 C, D (−9 v, 3 v); rings π·2 and 3π·2
            np.testing.assert_allclose(s["along_r"]["mean"], [-10 / 4, -9 / 3], rtol=1e-14)
            np.testing.assert_allclose(s["along_r"]["coarse"], [-10 * v / (2 * math.pi), -9 * v / (6 * math.pi)],
                                       rtol=1e-11)
        # --r-max 1.4: rings [0, 0.7] (A 0.5, B 0.3, E 0.1) and [0.7, 1.4] (D 1.2); C (1.5) outside
        s = analysed(folder, "--R", "2", "--r-bins", "2", "--z-bins", "2", "--r-max", "1.4")["stress"]
        np.testing.assert_allclose(s["r_edges"], [0, 0.7, 1.4], rtol=1e-14)
        np.testing.assert_allclose(s["along_r"]["mean"], [-10 / 4, -4.0], rtol=1e-14)
        self.assertEqual(s["outside"], 1)

    # A stack at rest (g = 1): grain 1 (mass 1) on the floor, grain 2 (mass 1) on it, grains
    # 3 (mass 1, on the axis) and 4 (mass 2, r = 1.5) on grain 2 under the plate, which
    # pushes 3 down by 2 and 4 by 1; a wire segment lifts grain 2 by 0.5. Grain 3 gets 3
    # from grain 2 (contact at r = 0), grain 4 gets 3 (contact at r = 1.2, listed from 4 to
    # 2: the force on 2 is −3), grain 2 gets 1 + 3 + 3 − 0.5 = 6.5 from grain 1, and grain 1
    # 1 + 6.5 = 7.5 from the floor.
    def test_transmission_through_planes_of_a_stack(self):
        folder = self.folder()
        write_grains(folder, [(1, 1.0, 0.0, 0.0, 0.5, 0.0), (2, 1.0, 0.0, 0.0, 1.5, 0.0), (3, 1.0, 0.0, 0.0, 2.5, 0.0),
                              (4, 2.0, 1.5, 0.0, 2.5, 0.0)])
        down = (0.0, 0.0, -1.0)
        write_contacts(folder, [
            contact(4, -1, 1, (0.0, 0.0, 0.0), Z, 7.5), contact(3, 1, 2, (0.0, 0.0, 1.0), Z, 6.5),
            contact(3, 2, 3, (0.0, 0.0, 2.0), Z, 3.0), contact(3, 4, 2, (1.2, 0.0, 2.0), down, 3.0),
            contact(4, -2, 3, (0.0, 0.0, 3.0), down, 2.0), contact(4, -2, 4, (1.5, 0.0, 3.0), down, 1.0),
            contact(2, 50, 2, (0.4, 0.0, 1.5), Z, 0.5), contact(1, -1, 50, (0.4, 0.0, 0.0), Z, 0.25),
            contact(1, -1, 51, (0.4, 0.0, 3.0), down, 0.1)])
        r = analysed(folder, "--R", "2", "--r-bins", "2", "--plane-z", "0.25", "1", "1.5", "2", "3")
        planes = {p["z"]: p for p in r["transmission"]}
        # T through each plane; the grains above it, their weight, the walls' and the wire's
        # force on them; at rest T = W − walls − wire. A centre on the plane (grain 2 at 1.5)
        # counts as above it.
        for h, T, above, weight, walls, wire in ((0.25, 0.0, 4, 5.0, 7.5 - 3.0, 0.5), (1.0, 6.5, 3, 4.0, -3.0, 0.5),
                                                 (1.5, 6.5, 3, 4.0, -3.0, 0.5),
                                                 (2.0, 6.0, 2, 3.0, -3.0, 0.0), (3.0, 0.0, 0, 0.0, 0.0, 0.0)):
            p = planes[h]
            self.assertAlmostEqual(p["T"], T, delta=1e-14, msg=h)
            self.assertEqual(p["grains_above"], above)
            self.assertAlmostEqual(p["weight_above"], weight, delta=1e-14)
            self.assertAlmostEqual(p["walls_on_above"], walls, delta=1e-14)
            self.assertAlmostEqual(p["wire_on_above"], wire, delta=1e-14)
            self.assertAlmostEqual(p["residual"], 0.0, delta=1e-14)
        # at z = 2 half of T within r < R/2 = 1 (r = 0) and half outside (r = 1.2)
        self.assertAlmostEqual(planes[2.0]["inner_fraction"], 0.5, delta=1e-14)
        self.assertEqual(planes[2.0]["T_per_r_bin"], [3.0, 3.0])
        self.assertAlmostEqual(planes[1.0]["inner_fraction"], 1.0, delta=1e-14)
        # the walls: the floor carries 7.5 from the grains and 0.25 from the wire, the plate 3
        # and 0.1 (the wire's walls are told apart by their normals: each is wall 1 of its fix)
        walls = {(w["by"], w["wall"], w["side"]): w for w in r["walls"]}
        self.assertEqual(sorted(walls), [("grains", 1, "floor"), ("grains", 2, "plate"), ("wire", 1, "floor"),
                                         ("wire", 1, "plate")])
        for key, load in ((("grains", 1, "floor"), 7.5), (("grains", 2, "plate"), 3.0), (("wire", 1, "floor"), 0.25),
                          (("wire", 1, "plate"), 0.1)):
            self.assertAlmostEqual(walls[key]["load"], load, delta=1e-14)
            sign = -1.0 if key[2] == "floor" else 1.0   # the floor is pushed down, the plate up
            np.testing.assert_allclose(walls[key]["force_on_wall"], [0.0, 0.0, sign * load], atol=1e-14)

    # Two straight wires along x (Table 1: E_w 100, r_w 0.1, rest length 0.2): beads 1–6
    # 0.21 apart (strain 0.05: T = E_w π r_w² 0.05 = 0.05 π) and beads 7–9 0.22 apart at z 1
    # (T = 0.1 π); each bead's stretching energy half of each of its segments' ½ (E A/l0)
    # (l − l0)² (fix wire/elastic), the last bead of a wire has length 0.
    def test_wire_tension_of_stretched_chains(self):
        folder = self.folder()
        beads = []
        for ids, spacing, z in ((range(1, 7), 0.21, 0.5), (range(7, 10), 0.22, 1.0)):
            u = 0.5 * (100 * AREA / 0.2) * (spacing - 0.2) ** 2
            for k, i in enumerate(ids):
                inner = 0 < k < len(ids) - 1
                beads.append((i, k * spacing, 0.0, z, u if inner else 0.5 * u, spacing if k < len(ids) - 1 else 0.0))
        write_wire(folder, beads)
        write_contacts(folder, [])
        write_grains(folder, lone_grains(1))
        w = analysed(folder)["wire"]
        self.assertEqual(w["id"], [1, 2, 3, 4, 5, 7, 8])
        np.testing.assert_allclose(w["tension"], [0.05 * math.pi] * 5 + [0.1 * math.pi] * 2, rtol=1e-12)
        np.testing.assert_allclose(w["z"], [0.5] * 5 + [1.0] * 2, rtol=1e-15)
        self.assertLess(w["bead_energy_difference"], 1e-12)
        # a wrong modulus doubles T and the energies it implies: the check shows it
        w = analysed(folder, "--E-w", "200")["wire"]
        np.testing.assert_allclose(w["tension"], [0.1 * math.pi] * 5 + [0.2 * math.pi] * 2, rtol=1e-12)
        self.assertAlmostEqual(w["bead_energy_difference"], 1.0, delta=1e-9)

    # The confinement per slab (z_bins 2: the slabs [0, 0.75] and [0.75, 1.5], the top the
    # highest grain centre or wire contact, 1.5). Grain 1 (V = 1, σ_zz −2) at z 0.5, grain 2
    # (V 2, σ_zz −4) at z 1.5, grain 3 outside both sections (σ_zz −100: left out of σ_v).
    # The wire pushes grain 1 with (−3, 1, 0.2) at (2, 0, 0.5): 3 towards the axis; grain 2
    # (listed as a: the force on it is minus the one listed) with (0, 2, 0) at (0, −2, 1.5):
    # 2; an open row (status 0) counts nothing. A side wall pushes grain 1 with f_n 5; the
    # floor's vertical row is no side wall. Three beads (0, −2), (2, 0), (0, 2) at z 0.5,
    # two segments of length 2√2 at rest length 2: T = E_w π r_w² (√2 − 1); the middle bead
    # is pulled by √2 T towards the axis, each end by T/√2: 2√2 T in the lower slab.
    def test_confinement_per_slab(self):
        folder = self.folder()
        write_grains(folder, [(1, 1.5, 0.5, 0.0, 0.5, -2.0), (2, 3.0, 0.0, -1.0, 1.5, -4.0),
                              (3, 1.5, 5.0, 0.0, 0.5, -100.0)])
        write_contacts(folder, [
            contact(2, 50, 1, (2.0, 0.0, 0.5), X, 3.0, force=[-3.0, 1.0, 0.2]),
            contact(2, 2, 51, (0.0, -2.0, 1.5), Y, 2.0, force=[0.0, -2.0, 0.0]),
            contact(2, 52, 1, (2.0, 0.0, 0.5), X, 9.0, force=[-9.0, 0.0, 0.0], status=0),
            contact(4, -2, 1, (-2.0, 0.0, 0.5), X, 5.0), contact(4, -1, 3, (5.0, 0.0, 0.0), Z, 7.0)])
        d = 2 * math.sqrt(2)
        write_wire(folder, [(60, 0.0, -2.0, 0.5, 0.0, d), (61, 2.0, 0.0, 0.5, 0.0, d), (62, 0.0, 2.0, 0.5, 0.0, 0.0)])
        tension = 100 * AREA * (math.sqrt(2) - 1)
        for args, perimeter, area in ((["--R", "2"], 4 * math.pi, 4 * math.pi),
                                      (["--R", "2", "--section", "square", "4"], 16.0, 16.0)):
            c = analysed(folder, "--z-bins", "2", "--l0", "2", *args)["confinement"]
            np.testing.assert_allclose(c["z_edges"], [0, 0.75, 1.5], rtol=1e-11)
            np.testing.assert_allclose(c["q_wire"], [3 / 0.75, 2 / 0.75], rtol=1e-11)
            np.testing.assert_allclose(c["q_walls"], [5 / 0.75, 0.0], rtol=1e-11, atol=1e-15)
            np.testing.assert_allclose(c["q_hoop"], [d * tension / 0.75, 0.0], rtol=1e-11, atol=1e-15)
            np.testing.assert_allclose(c["pressure"], [8 / 0.75 / perimeter, 2 / 0.75 / perimeter], rtol=1e-11)
            np.testing.assert_allclose(c["sigma_v"], [2 / (area * 0.75), 8 / (area * 0.75)], rtol=1e-11)
            np.testing.assert_allclose(c["K"], [8 / perimeter * area / 2, 2 / perimeter * area / 8], rtol=1e-11)
            self.assertAlmostEqual(c["F_wire"], 5.0, delta=1e-13)
            self.assertAlmostEqual(c["F_walls"], 5.0, delta=1e-13)
            self.assertEqual(c["grains_inside"], 2)
        status, text = script(folder, "--no-plots", "--no-picture", "--section", "square", "0")
        self.assertEqual(status, 2)
        self.assertIn("force_network.py: error: --section square D: D must be > 0, got 0", text)
        status, text = script(folder, "--no-plots", "--no-picture", "--section", "disc")
        self.assertEqual(status, 2)
        self.assertIn("force_network.py: error: --section must be circle or square D, got disc", text)

    def test_bad_input(self):
        folder = self.folder()
        write_grains(folder, lone_grains(2))
        with open(os.path.join(folder, f"load_contacts_{STEP}.dump"), "w") as f:
            f.write(header("ENTRIES", 1, [f"c_c[{k}]" for k in range(1, 11)]) + " ".join(["1"] * 10) + "\n")
        status, text = script(folder, "--no-plots", "--no-picture")
        self.assertEqual(status, 1)
        self.assertIn(f"force_network.py: {folder}/load_contacts_{STEP}.dump: no column c_ID[11] (fx), c_ID[12] (fy), "
                      "c_ID[13] (fz), c_ID[16] (status); dump the 16 columns of compute contact/local", text)
        status, text = script(folder, "--step", "7")
        self.assertEqual(status, 1)
        self.assertIn(f"force_network.py: --step 7: {folder} has load_contacts_STEP.dump for steps {STEP}", text)


# --- end to end -------------------------------------------------------------------------------

def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n" and head[12:16] == b"IHDR", path
    return struct.unpack(">II", head[16:24])


def png_pixels(path):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    # (VTK's rows run from the bottom up: turned, so that row 0 is the top)
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, -1)[::-1, :, :3]


class EndToEnd(DeckTestCase):
    """The tiny column without wire, at rest after t = 16 (its height is constant from
    t = 15), loaded by the plate at 0.05 (contacts every 0.1, to strain 0.028, before the
    chain that jams it forms); the tiny column with wire (t_end 10) loaded as in
    test_column_load.py, its snapshot of the standing column at step 100."""

    @classmethod
    def setUpClass(cls):
        cls.bare = run(COLUMN, variables=dict(TINY, wire=0, t_end=16))
        cls.bare_load = run(LOAD, variables={"R": 2, "v_plate": 0.05, "t_out": 0.1, "t_net": 0.1, "strain_max": 0.028,
                                             "load_min": 1e9, "load_max": 1e12}, workdir=cls.bare.workdir)
        cls.wired = run(COLUMN, variables=dict(TINY, wire=1))
        cls.wired_load = run(LOAD, variables={"R": 2, "v_plate": 0.2, "t_out": 0.1, "strain_max": 0.05,
                                              "load_min": 1e9, "load_max": 1e12}, workdir=cls.wired.workdir)

    def test_runs_were_clean(self):
        for r in (self.bare, self.bare_load, self.wired, self.wired_load):
            self.assertRanCleanly(r)

    def post(self, r, name):
        return os.path.join(r.workdir, "post", name)

    def analyse(self, r, step, *args):
        out = tempfile.mkdtemp(prefix="wiregrain-network-")
        status, text = script(r.workdir, "--step", str(step), "--out", out, *args)
        self.assertEqual(status, 0, text[-3000:])
        with open(os.path.join(out, f"network_{step}.json")) as f:
            return json.load(f), out, text

    # The grains above a horizontal plane z = h just below the plate (h the lowest centre of
    # the grains the plate touches) are held by the plate's push P, their weight W_U and the
    # force T the contacts crossing the plane transmit: at rest T = P + W_U, so T is not the
    # plate load alone (here W_U, one grain's weight 2.42, is 3.5 to 12.6 % of P). The plate
    # moves at 0.05: the grains are not quite at rest, T − P − W_U is their m a_z. Measured
    # on the ten dumps whose plate load and the previous dump's exceed W/2 (steps 800 to
    # 1700): |T − P − W_U| up to 0.21 (0.30 % of P, step 1700), 0.83 % of P at most (step
    # 1200), 0.2 % in the median; tolerance 3 % of P. (The dump where the plate first
    # strikes an unloaded column is off by 15 %: an impact.)
    def test_force_through_a_plane_below_the_plate(self):
        weight = None
        checked = []
        previous = 0.0
        for step in range(STEP, 10 ** 6, STEP):
            path = self.post(self.bare_load, f"load_contacts_{step}.dump")
            if not os.path.exists(path):
                break
            c = read_local_dump(path)
            g = read_dump(self.post(self.bare_load, f"load_grains_{step}.dump"))
            weight = g["mass"].sum()
            plate = (c["c_contacts[1]"] == 4) & (c["c_contacts[2]"] == -2) & (c["c_contacts[10]"] > 0)
            load = -c["c_contacts[13]"][plate].sum()
            if load > 0.5 * weight and previous > 0.5 * weight:
                z = dict(zip(g["id"].astype(int), g["z"]))
                h = min(z[int(b)] for b in c["c_contacts[3]"][plate]) - 1e-6
                r, _, _ = self.analyse(self.bare_load, step, "--no-plots", "--no-picture", "--plane-z", repr(h))
                p = r["transmission"][0]
                w_u = g["mass"][g["z"] >= h].sum()
                self.assertAlmostEqual(p["walls_on_above"], -load, delta=1e-9 * load)   # the plate's rows, all
                off = p["T"] - load - w_u
                print(f"step {step}: plate {load:.5g}, T {p['T']:.5g}, weight above {w_u:.4g}: T - P - W_U = {off:.3g} "
                      f"({off / load:.2%} of P)")
                checked.append(step)
                self.assertLess(abs(off), 0.03 * load)
                self.assertGreater(abs(p["T"] - load), 5 * abs(off))   # the weight above counts
            previous = load
        self.assertGreaterEqual(len(checked), 5, checked)

    # Σ V σ_zz of a bin is Σ over its grains of Σ_c (z_c − z_i) f_z,c (Love–Weber, compute
    # grain/stress) with V = mass/1.5 (create_grains' density): computed here from the
    # contact rows of the dump. Measured: equal to 5.6e-6 of the largest bin (the dumps'
    # 6 digits); tolerance 2e-5.
    def test_binned_stress_from_the_contacts(self):
        step = 1600
        r, _, _ = self.analyse(self.bare_load, step, "--no-plots", "--no-picture")
        s = r["stress"]
        c = read_local_dump(self.post(self.bare_load, f"load_contacts_{step}.dump"))
        g = read_dump(self.post(self.bare_load, f"load_grains_{step}.dump"))
        row = {int(i): k for k, i in enumerate(g["id"])}
        moment = np.zeros(len(g["id"]))
        for kind, a, b, pz, fz in zip(c["c_contacts[1]"], c["c_contacts[2]"], c["c_contacts[3]"], c["c_contacts[6]"],
                                      c["c_contacts[13]"]):
            for body, force in ((int(b), fz), (int(a), -fz)):
                if body in row and kind in (2, 3, 4):
                    moment[row[body]] += (pz - g["z"][row[body]]) * force
        r_edges, z_edges = np.array(s["r_edges"]), np.array(s["z_edges"])
        ir = np.clip(np.searchsorted(r_edges, np.hypot(g["x"], g["y"]), side="right") - 1, 0, len(r_edges) - 2)
        iz = np.clip(np.searchsorted(z_edges, g["z"], side="right") - 1, 0, len(z_edges) - 2)
        expected = np.zeros((len(r_edges) - 1, len(z_edges) - 1))
        np.add.at(expected, (ir, iz), moment)
        volume = np.pi * np.diff(r_edges ** 2)[:, None] * np.diff(z_edges)[None, :]
        got = np.array(s["map"]["coarse"]) * volume
        error = np.abs(got - expected).max() / np.abs(expected).max()
        print(f"sum V sigma_zz per bin against the contacts: {error:.2g} of the largest bin {np.abs(expected).max():.4g}")
        self.assertGreater(np.abs(expected).max(), 1.0)
        self.assertLess(error, 2e-5)

    # The tension per segment against the stretching energy that fix wire/elastic computed
    # from the full-precision positions: ½ (E A/l0)(l − l0)² = T² l0 / (2 E A) per segment,
    # half to each bead. Measured: per bead within 2.7e-5 of the largest bead energy (the
    # dump's 6 digits of l); tolerance 1e-4. The loops hold the grains in: their mean
    # tension is positive (measured 0.071).
    def test_wire_tension_against_its_energy(self):
        r, out, text = self.analyse(self.wired_load, 100, "--no-picture")
        w = r["wire"]
        beads = read_dump(self.post(self.wired_load, "load_wire_100.dump"))
        u_seg = {i: t * t * 0.2 / (2 * 100 * AREA) for i, t in zip(w["id"], w["tension"])}
        u_bead = np.array([0.5 * u_seg.get(int(i), 0.0) + 0.5 * u_seg.get(int(i) - 1, 0.0) for i in beads["id"]])
        dumped = beads["c_energy[1]"]
        error = np.abs(u_bead - dumped).max() / dumped.max()
        print(f"{w['segments']} segments, mean tension {w['tension_mean']:.3g}; bead energies within {error:.2g} "
              f"of the largest")
        self.assertEqual(w["segments"], int((beads["c_energy[3]"] > 0).sum()))
        self.assertLess(error, 1e-4)
        self.assertGreater(w["tension_mean"], 0.0)
        for name in ("forces", "stress", "transmission", "wire"):
            self.assertGreater(os.path.getsize(os.path.join(out, f"network_100_{name}.png")), 5000, name)

    def assertPicture(self, path, size):
        self.assertEqual(png_size(path), size)
        # the scene: below the title (the top tenth), left of the colour bar (the right 14 %)
        pixels = png_pixels(path)[int(0.1 * size[1]):, : int(0.8 * size[0])]
        self.assertGreater(len(np.unique(pixels.reshape(-1, 3), axis=0)), 50)
        self.assertGreater(pixels.astype(float).std(), 5.0)

    def test_pictures(self):
        for r, step, size in ((self.bare_load, 1600, (400, 300)), (self.wired_load, 100, (360, 360))):
            _, out, text = self.analyse(r, step, "--no-plots", "--size", *map(str, size), "--view", "elevated")
            self.assertPicture(os.path.join(out, f"network_{step}_picture.png"), size)


if __name__ == "__main__":
    main()
