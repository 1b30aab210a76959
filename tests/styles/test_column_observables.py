"""The column observables: compute column/height, compute column/retention and the
wire–grain coordination of compute wire/contacts, on hand-built configurations whose
answers are computed here independently; error messages."""

import math

import numpy as np

from liggghts_run import DeckTestCase, full_precision, main, read_dump, run
from test_wire_grain import deck, scene

IDENTITY = (1.0, 0.0, 0.0, 0.0)


class Height(DeckTestCase):
    def test_quantiles_of_the_grain_tops(self):
        # five upright cubes (edge 1, sweep 0.1) with centres at z = 1..5 and one turned by
        # 45° about x at z = 7, whose top is an edge √½ above its centre
        turned = (math.cos(math.pi / 8), math.sin(math.pi / 8), 0.0, 0.0)
        poses = [(2.0 * k - 5.0, 0.0, 1.0 + k) + IDENTITY for k in range(5)] + [(5.0, 3.0, 7.0) + turned]
        made = scene(poses, [], shape="cube 1", box=(-6, 6, -6, 6, -1, 9))
        tops = [1.0 + k + 0.5 + 0.1 for k in range(5)] + [7.0 + math.sqrt(0.5) + 0.1]
        r = run(deck("""
compute         top grains column/height quantile 1
compute         q75 grains column/height quantile 0.75
compute         h grains column/height
thermo_style    custom step c_top c_q75 c_h
thermo_modify   format float %.15g
run             0
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        t = r.thermo()
        for column, q in (("top", 1.0), ("q75", 0.75), ("h", 0.98)):
            expected = np.quantile(tops, q)  # linear interpolation between order statistics
            self.assertAlmostEqual(t[column][0], expected, delta=1e-12, msg=column)
        print(f"\ncolumn height: max {t['top'][0]:.12g}, q = 0.75 {t['q75'][0]:.12g}, default q = 0.98 {t['h'][0]:.12g}")


class StockSpheres(DeckTestCase):
    def test_height_and_retention_of_spheres_beside_a_wire(self):
        # atom_style hybrid wire sphere: six spheres of radii 0.5..1 at known places and a
        # one-turn loop of radius 2 (its beads are not grains): tops z + r, the cylinder
        # of the beads' mean distance 2
        spheres = [(0.0, 0.0, 1.0, 0.5), (1.5, 0.0, 3.0, 0.6), (0.0, -2.5, 1.0, 0.7), (-4.0, 0.0, 4.0, 0.8),
                   (3.0, 3.0, 6.0, 0.9), (-1.0, 1.0, 2.0, 1.0)]
        made = "\n".join(f"create_atoms    1 single {x} {y} {z}\nset             atom {k + 1} diameter {2 * r} density 1"
                         for k, (x, y, z, r) in enumerate(spheres))
        r = run(f"""
units           lj
atom_style      hybrid wire sphere
atom_modify     map array sort 0 0.0
boundary        f f f
region          box block -6 6 -6 6 -1 9
create_box      2 box
{made}
create_wire     2 loop 0 0 6.5 2.0 1 0.3
group           grains type 1
group           wire type 2
compute         top all column/height quantile 1
compute         h all column/height quantile 0.5
compute         phi all column/retention wire axis 0 0
thermo_style    custom step c_top c_h c_phi[1] c_phi[2] c_phi[3] c_phi[4]
thermo_modify   format float %.15g
run             0
""")
        self.assertRanCleanly(r)
        t = r.thermo()
        tops = [z + radius for _, _, z, radius in spheres]
        self.assertAlmostEqual(t["top"][0], max(tops), delta=1e-12)
        self.assertAlmostEqual(t["h"][0], np.quantile(tops, 0.5), delta=1e-12)
        self.assertAlmostEqual(t["phi[2]"][0], 2.0, delta=1e-12)
        inside = sum(math.hypot(x, y) < 2.0 for x, y, _, _ in spheres)
        self.assertEqual((t["phi[3]"][0], t["phi[4]"][0]), (inside, len(spheres)))


class Retention(DeckTestCase):
    def test_grains_inside_the_wire_cylinder(self):
        # a one-turn loop of radius 2 about the box axis (0, 0); grains at horizontal
        # distances 0, 1.5, 2.5 and 4 from it
        poses = [(0.0, 0.0, 1.0) + IDENTITY, (1.5, 0.0, 3.0) + IDENTITY, (0.0, -2.5, 1.0) + IDENTITY,
                 (-4.0, 0.0, 4.0) + IDENTITY]
        made = scene(poses, ["loop 0 0 6.5 2.0 1 0.3"], shape="cube 0.5", box=(-6, 6, -6, 6, -1, 8))
        r = run(full_precision(deck("""
compute         phi grains column/retention wire
compute         sh grains column/retention wire axis 1.5 0.5
compute         fixed grains column/retention radius 2.6 axis 0 0
thermo_style    custom step c_phi[1] c_phi[2] c_phi[3] c_phi[4] c_sh[1] c_sh[2] c_fixed[1] c_fixed[2]
thermo_modify   format float %.15g
dump            d wire custom 1 dump.w id x y z
run             0
"""), "d"), workdir=made.workdir)
        self.assertRanCleanly(r)
        t = r.thermo()
        self.assertAlmostEqual(t["phi[2]"][0], 2.0, delta=1e-12)  # beads on the circle of radius 2
        self.assertEqual((t["phi[3]"][0], t["phi[4]"][0]), (2, 4))
        self.assertEqual(t["phi[1]"][0], 0.5)
        # about (1.5, 0.5): the mean bead distance from the dump, the grains by hand
        beads = read_dump(r.path("dump.w"))
        radius = np.mean(np.hypot(beads["x"] - 1.5, beads["y"] - 0.5))
        inside = sum(math.hypot(x - 1.5, y - 0.5) < radius for x, y, *_ in poses)
        self.assertAlmostEqual(t["sh[2]"][0], radius, delta=1e-12)
        self.assertEqual(t["sh[1]"][0], inside / 4)
        # a fixed cylinder of radius 2.6 (a column without wire): the grains at 0, 1.5, 2.5
        self.assertEqual((t["fixed[1]"][0], t["fixed[2]"][0]), (0.75, 2.6))
        print(f"\nretention: R = {t['phi[2]'][0]:.12g}, φ_p = {t['phi[1]'][0]}; about (1.5, 0.5): R = {radius:.6f}, "
              f"φ_p = {t['sh[1]'][0]}")


class Coordination(DeckTestCase):
    def test_wire_grain_contacts_per_segment(self):
        # four segments lying 0.001 deep on the top face of a cube (top at z = 2.2, wire
        # radius 0.1), two more far above: 4 contacts, 6 segments, z_wpc = 4/6
        made = scene([(0.0, 0.0, 1.1) + IDENTITY],
                     ["line -1.0 0.3 2.299 1.0 0.3 2.299 segment 0.5 radius 0.1",
                      "line -1.0 0.3 6.0 0.0 0.3 6.0 segment 0.5 radius 0.1"])
        r = run(deck("""
fix             nscd grains nscd/polyhedra
fix             wg wire wire/grain grains
compute         zwp wire wire/contacts kind wire_grain
thermo_style    custom step c_zwp[1] c_zwp[2] c_zwp[3] c_zwp[5] f_wg[1]
thermo_modify   format float %.15g
run             0
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        t = r.thermo()
        self.assertEqual(t["zwp[1]"][0], 4)
        self.assertAlmostEqual(t["zwp[2]"][0], 0.001, delta=1e-12)
        self.assertAlmostEqual(t["zwp[3]"][0], 0.01, delta=1e-10)
        self.assertAlmostEqual(t["zwp[5]"][0], 4 / 6, delta=1e-15)
        print(f"\ncoordination: {t['zwp[1]'][0]:.0f} wire-grain contacts on 6 segments, z_wpc = {t['zwp[5]'][0]:.15g}")


class Errors(DeckTestCase):
    @classmethod
    def setUpClass(cls):
        cls.made = scene([(0.0, 0.0, 1.1) + IDENTITY], ["line -0.5 0.2 2.3 0.5 0.2 2.3 segment 0.5 radius 0.1"])

    def check(self, body, message):
        self.assertStopsWith(run(deck(body + "\nrun 0\n"), workdir=Errors.made.workdir), message)

    def test_messages(self):
        self.check("compute h grains column/height quantile 1.5",
                   "compute column/height (id h): value of 'quantile' must be in [0, 1], got 1.5")
        self.check("compute h grains column/height level 2",
                   "compute column/height (id h): unknown keyword 'level'; accepted: quantile")
        self.check("compute h wire column/height\nthermo_style custom step c_h",
                   "compute column/height (id h): group 'wire' has no grains")
        self.check("compute phi grains column/retention",
                   "compute column/retention (id phi): expected the wire group or 'radius r' after 'column/retention'")
        self.check("compute phi grains column/retention radius -1",
                   "compute column/retention (id phi): value of 'radius' must be > 0, got -1")
        self.check("compute phi grains column/retention rope",
                   "compute column/retention (id phi): wire group 'rope' does not exist")
        self.check("compute phi grains column/retention grains\nthermo_style custom step c_phi[1]",
                   "compute column/retention (id phi): wire group 'grains' has no wire beads")
        self.check("compute phi grains column/retention wire axis 1",
                   "compute column/retention (id phi): missing value after 'axis'")
        self.check("compute c wire wire/contacts kind grains",
                   "compute wire/contacts (id c): value of 'kind' must be wire_wire, wire_grain or wire_wall, "
                   "got 'grains'")
        self.check("compute c wire wire/contacts kind wire_grain\nthermo_style custom step c_c[1]",
                   "compute wire/contacts (id c): kind wire_grain needs a fix wire/grain")


if __name__ == "__main__":
    main()
