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
        # 45° about x at z = 7, whose top is an edge √½ above its centre; on 1 rank and on 3
        # (one x slab each: the tops are never gathered, each rank counts its own)
        turned = (math.cos(math.pi / 8), math.sin(math.pi / 8), 0.0, 0.0)
        poses = [(2.0 * k - 5.0, 0.0, 1.0 + k) + IDENTITY for k in range(5)] + [(5.0, 3.0, 7.0) + turned]
        tops = [1.0 + k + 0.5 + 0.1 for k in range(5)] + [7.0 + math.sqrt(0.5) + 0.1]
        for ranks in (1, 3):
            made = scene(poses, [], shape="cube 1", box=(-6, 6, -6, 6, -1, 9))
            r = run(deck("""
compute         top grains column/height quantile 1
compute         q75 grains column/height quantile 0.75
compute         h grains column/height
compute         low grains column/height quantile 0.1
thermo_style    custom step c_top c_q75 c_h c_low
thermo_modify   format float %.15g
run             0
""", processors="* 1 1"), np_ranks=ranks, workdir=made.workdir)
            self.assertRanCleanly(r)
            t = r.thermo()
            for column, q in (("top", 1.0), ("q75", 0.75), ("h", 0.98), ("low", 0.1)):
                expected = np.quantile(tops, q)  # linear interpolation between order statistics
                self.assertAlmostEqual(t[column][0], expected, delta=1e-12, msg=f"{column} on {ranks} ranks")
            print(f"\ncolumn height on {ranks} rank(s): max {t['top'][0]:.12g}, q = 0.75 {t['q75'][0]:.12g}, "
                  f"default q = 0.98 {t['h'][0]:.12g}, q = 0.1 {t['low'][0]:.12g}")


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


def segment_box_distance(p0, p1, centre, half):
    """Distance from the segment p0–p1 to the axis-aligned box of the given centre and half
    widths: the distance of a point to the box is the norm of its clamped offset, a convex
    function of the point, minimised along the segment by golden-section search."""
    p0, p1, centre = np.asarray(p0), np.asarray(p1), np.asarray(centre)

    def distance(t):
        offset = np.abs(p0 + t * (p1 - p0) - centre) - half
        return float(np.linalg.norm(np.maximum(offset, 0.0)))

    if distance(0.0) > 1.0 + np.linalg.norm(p1 - p0):  # far: the point distance is 1-Lipschitz
        return distance(0.0) - np.linalg.norm(p1 - p0)

    lo, hi = 0.0, 1.0
    ratio = (math.sqrt(5.0) - 1.0) / 2.0
    for _ in range(120):  # the bracket shrinks to 0.618^120 ~ 1e-25
        a, b = hi - ratio * (hi - lo), lo + ratio * (hi - lo)
        if distance(a) <= distance(b):
            hi = b
        else:
            lo = a
    return min(distance(0.0), distance(1.0), distance(0.5 * (lo + hi)))


def height_quantile(tops, q):
    """The q-quantile of the tops by linear interpolation between order statistics."""
    z = sorted(tops)
    p = q * (len(z) - 1)
    k = int(math.floor(p))
    return z[k] if k + 1 == len(z) else z[k] + (p - k) * (z[k + 1] - z[k])


class StaticColumn(DeckTestCase):
    """in.column's four observables (H_n, φ_p, U_s/L, z_wpc), formed as the deck forms them
    at its end, on a column built by hand: three layers of 3 x 3 upright cubes (core edge 1,
    sweep r_p = 0.1, centres 1.5 apart, each layer resting on the one below), two more
    cubes on the middle stack, and a wire loop (turns 0.95, pitch 0, Table 1's r_w = 0.1 and
    rest length l_w = 0.2) about the column's axis at height 3.69, 0.19 above the cores' top
    faces of the third layer: a segment over a top face overlaps the cube by 0.01, a
    segment over a gap touches nothing or a rounded edge. The beads are put on an ellipse
    (half axes 1.04 R and 1.01 R, R = 1.8), so that the segments are stretched and bent by
    different amounts. Every expected value is computed here from the geometry."""

    R, Z_WIRE, TURNS = 1.8, 3.69, 0.95
    SCALE = (1.04, 1.01)
    L_W, R_W, R_P = 0.2, 0.1, 0.1
    E_W, M_ELO, M_ROT = 100.0, 2.0, 0.3

    def layout(self):
        """Grain centres (upright cubes) and bead positions."""
        cubes = [(1.5 * i, 1.5 * j, 0.6 + 1.2 * k) for k in range(3) for j in (-1, 0, 1) for i in (-1, 0, 1)]
        cubes += [(0.0, 0.0, 4.2), (0.0, 0.0, 5.4)]
        # create_wire loop with pitch 0: nodes at azimuth k Δφ, Δφ = 2 asin(l_w / 2R), as many
        # whole segments as fit in the turns (docs/commands/create_wire.md); moved here to
        # the ellipse at the same azimuths
        step = 2.0 * math.asin(self.L_W / (2.0 * self.R))
        segments = int(math.floor(2.0 * math.pi * self.TURNS / step))
        beads = np.array([(self.SCALE[0] * self.R * math.cos(k * step), self.SCALE[1] * self.R * math.sin(k * step),
                           self.Z_WIRE) for k in range(segments + 1)])
        return cubes, beads

    def expected_energy(self, beads):
        """U_s + U_b of the discrete wire (fix wire/elastic's law, docs/design.md section 1.2):
        ½ k_s (|d| − l_w)² per segment, k_s = m_elo E π r_w² / l_w; ½ κ θ² per inner bead,
        κ = m_rot E π r_w⁴ / (4 l_w), θ the angle between its two segments."""
        k_s = self.M_ELO * self.E_W * math.pi * self.R_W ** 2 / self.L_W
        kappa = self.M_ROT * self.E_W * math.pi * self.R_W ** 4 / (4.0 * self.L_W)
        d = np.diff(beads, axis=0)
        lengths = np.linalg.norm(d, axis=1)
        stretching = 0.5 * k_s * np.sum((lengths - self.L_W) ** 2)
        cross = np.linalg.norm(np.cross(d[:-1], d[1:]), axis=1)
        theta = np.arctan2(cross, np.sum(d[:-1] * d[1:], axis=1))
        bending = 0.5 * kappa * np.sum(theta ** 2)
        return stretching, bending, lengths.sum()

    def test_observables_of_a_hand_built_column(self):
        cubes, beads = self.layout()
        made = scene([c + IDENTITY for c in cubes], [f"loop 0 0 {self.Z_WIRE} {self.R} {self.TURNS} 0"],
                     shape="cube 1", sweep=self.R_P, box=(-6, 6, -6, 6, -1, 8))
        with open(made.path("scene.data")) as f:
            text = f.read().splitlines()
        k = next(i for i, line in enumerate(text) if line.startswith("Atoms")) + 2
        end = next(i for i in range(k, len(text)) if not text[i].strip())
        rows = [i for i in range(k, end) if int(text[i].split()[5]) < 0]  # the beads (no shape)
        self.assertEqual(len(rows), len(beads))  # create_wire laid as many nodes as computed here
        for i in rows:
            words = text[i].split()
            words[2:5] = [repr(float(v)) for v in beads[int(words[0]) - len(cubes) - 1]]
            text[i] = " ".join(words)
        with open(made.path("scene.data"), "w") as f:
            f.write("\n".join(text) + "\n")
        # the observables as in.column forms them: H0 = $(c_h) at the start of the wall
        # phase, H_n = c_h / H0 later; here the top cube is then moved to the floor beside
        # the column (outside the loop), a second `run 0` evaluates them again
        r = run(deck(f"""
fix             materialE all property/global youngsModulus peratomtype 1000 {self.E_W}
fix             materialNu all property/global poissonsRatio peratomtype 0.3 0
fix             floor wire wire/wall plane 0 0 0 0 0 1 mu_s 0.5 mu_d 0.5 restitution 0.5
fix             nscd grains nscd/polyhedra friction 0.5 timestep 2e-3 wall_fix floor wall_friction 0.5
fix             elastic wire wire/elastic m_elo {self.M_ELO} m_rot {self.M_ROT}
fix             integr wire nve/gear scheme verlet
fix             wg wire wire/grain grains mu_s 0.5 mu_d 0.5 restitution 0.5 E_p 1000 nu_p 0.3
timestep        1e-3
compute         h grains column/height update_on_run_end yes
compute         phi grains column/retention wire axis 0 0
compute         energy wire wire/energy
variable        Us equal c_energy[5]
variable        Ustr equal c_energy[1]
variable        Ubend equal c_energy[2]
variable        L equal c_energy[4]
compute         zwp wire wire/contacts kind wire_grain
variable        zwpc equal c_zwp[5]
thermo_style    custom step c_h c_phi[1] c_phi[2] c_phi[3] c_phi[4] v_Us v_Ustr v_Ubend v_L v_zwpc c_zwp[1] c_zwp[2]
thermo_modify   format float %.17g norm no
run             0
variable        H0 equal $(c_h)
variable        Hn equal c_h/${{H0}}
set             atom {len(cubes)} x 4.0 z 0.6
thermo_style    custom step c_h v_Hn c_phi[1] c_phi[3] c_phi[4] v_Us v_zwpc
thermo_modify   format float %.17g norm no
run             0
write_dump      all custom dump.c id type x y z f_wg[4] modify format '%d %d %.17g %.17g %.17g %.17g'
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        first, second = r.thermo(0), r.thermo(-1)

        # H: the 0.98 quantile of the tops z + 1/2 + r_p (29 tops: p = 0.98 x 28 = 27.44,
        # between the two highest), before and after the top cube moved to the floor
        tops = [z + 0.5 + self.R_P for _, _, z in cubes]
        h0 = height_quantile(tops, 0.98)
        h1 = height_quantile(tops[:-1] + [0.6 + 0.5 + self.R_P], 0.98)
        self.assertAlmostEqual(h0, 4.8 + 0.44 * 1.2, delta=1e-12)  # the formula on these tops, by hand
        # (measured: H exact in both states, H_n 3e-16 off; every value below is exact but
        # for round-off, measured at most 4e-15 off, and held to a few times that)
        self.assertAlmostEqual(first["h"][0], h0, delta=1e-14)
        self.assertAlmostEqual(second["h"][0], h1, delta=1e-14)
        self.assertAlmostEqual(second["Hn"][0], h1 / h0, delta=2e-15)

        # φ_p: the grains whose centre lies inside the cylinder of the beads' mean distance
        # from the axis (here 1.8 x ~1.01: the middle and the four edge stacks, 5 per layer,
        # and the two cubes on top; not the corner stacks at 2.12)
        radius = np.mean(np.hypot(beads[:, 0], beads[:, 1]))
        inside = [math.hypot(x, y) < radius for x, y, _ in cubes]
        self.assertEqual(sum(inside), 17)
        self.assertAlmostEqual(first["phi[2]"][0], radius, delta=1e-14)
        self.assertEqual((first["phi[3]"][0], first["phi[4]"][0]), (17, 29))
        self.assertEqual(first["phi[1]"][0], 17 / 29)
        self.assertEqual((second["phi[3]"][0], second["phi[4]"][0]), (16, 29))  # the moved cube is out
        self.assertEqual(second["phi[1]"][0], 16 / 29)

        # U_s/L from the bead positions (stretched by 1 to 4 %, bent by about Δφ at each inner bead)
        stretching, bending, length = self.expected_energy(beads)
        print(f"\nhand-built column: H0 {h0:.15g}, H {h1:.15g}, H_n {h1 / h0:.15g}; φ_p 17/29 in radius {radius:.15g}; "
              f"U_s {stretching:.10g} + U_b {bending:.10g} over L {length:.15g}: U_s/L {(stretching + bending) / length:.15g} "
              f"(fix: {first['Us'][0]:.15g})")
        self.assertGreater(stretching, 0.5 * bending)  # both terms matter
        self.assertAlmostEqual(first["Ustr"][0] / stretching, 1.0, delta=1e-14)  # measured 4e-16
        self.assertAlmostEqual(first["Ubend"][0] / bending, 1.0, delta=1e-14)     # 7e-16
        self.assertAlmostEqual(first["L"][0], length, delta=3e-14)                # 3.6e-15
        self.assertAlmostEqual(first["Us"][0] / ((stretching + bending) / length), 1.0, delta=1e-14)
        self.assertEqual(second["Us"][0], first["Us"][0])

        # z_wpc: a segment touches a cube where the distance from its axis to the cube's
        # core is below r_p + r_w = 0.2 (no distance here within 2e-3 of that)
        reach = self.R_P + self.R_W
        counts = np.zeros(len(beads))
        closest = math.inf
        for s in range(len(beads) - 1):
            for c in cubes:
                d = segment_box_distance(beads[s], beads[s + 1], c, 0.5)
                closest = min(closest, abs(d - reach))
                counts[s] += d < reach
        self.assertGreater(closest, 2e-3)
        segments = len(beads) - 1
        print(f"z_wpc: {counts.sum():.0f} contacts on {segments} segments (closest distance {closest:.2e} from "
              f"the reach), fix {first['zwpc'][0]:.15g}")
        self.assertGreater(counts.sum(), 0.5 * segments)
        self.assertLess(counts.sum(), segments)  # some segments over the gaps
        self.assertEqual(first["zwp[1]"][0], counts.sum())
        self.assertAlmostEqual(first["zwp[2]"][0], reach - (self.Z_WIRE - 3.5), delta=1e-14)  # 0.01 deep
        self.assertAlmostEqual(first["zwpc"][0], counts.sum() / segments, delta=1e-15)
        self.assertEqual(second["zwpc"][0], first["zwpc"][0])
        dump = read_dump(r.path("dump.c"))
        on_beads = dump["type"] == 2
        np.testing.assert_array_equal(dump["f_wg[4]"][on_beads], counts)  # segment by segment
        np.testing.assert_array_equal(np.column_stack([dump[c][on_beads] for c in "xyz"]), beads)
        self.assertEqual(dump["x"][len(cubes) - 1], 4.0)  # the moved cube


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
