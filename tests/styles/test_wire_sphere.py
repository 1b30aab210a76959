"""fix wire/grain against stock LIGGGHTS granular spheres (atom_style hybrid wire sphere,
fix nve/sphere, pair_style gran): static forces against the analytic sphere geometry, the
capstan ratio, momentum, 1 vs 2 ranks, restart, error messages."""

import os

import numpy as np

import test_wire_grain as polyhedra
from liggghts_run import DeckTestCase, full_precision, main, read_dump, run

G = 1.0
HEADER = """
units           lj
atom_style      hybrid wire sphere
atom_modify     map array sort 0 0.0
newton          off
"""


def sphere_scene(spheres, wires, box=(-4, 4, -4, 4, -1, 5), files=None):
    """A data file scene.data with the spheres [(x, y, z, radius, density)] (atom type 1,
    IDs 1...) and the wires of the `create_wire 2 ...` argument strings (atom type 2)."""
    made_spheres = "\n".join(f"create_atoms    1 single {x!r} {y!r} {z!r}\n"
                             f"set             atom {k + 1} diameter {2 * radius!r} density {density!r}"
                             for k, (x, y, z, radius, density) in enumerate(spheres))
    lines = "\n".join(f"create_wire     2 {w}" for w in wires)
    made = run(HEADER + f"""
boundary        f f f
region          box block {' '.join(map(str, box))}
create_box      2 box
{made_spheres}
{lines}
write_data      scene.data
""", files=files)
    if made.returncode != 0:
        raise AssertionError(made.output[-3000:])
    return made


def deck(body, boundary="f f f", processors="* * *"):
    return HEADER + f"""
boundary        {boundary}
processors      {processors}
read_data       scene.data
group           grains type 1
group           wire type 2
{body}
"""


class Statics(DeckTestCase):
    def test_sphere_on_two_rails_lying_on_the_floor(self):
        # a frictionless sphere (R = 1) resting on two straight wires 0.8 apart lying on a
        # frictional floor, over the middle of one segment of each: at rest the wires
        # carry m g, each contact N along n, the unit vector from the sphere's centre to
        # the foot on the wire's axis, with N n_z = m g/2, shared by the segment's beads
        # as (1 − t, t), t of the foot; n and t from the dumped positions (fix viscous
        # takes out the bouncing of the sphere on the soft wires; it has no force at rest)
        made = sphere_scene([(0.0, 0.0, 1.13, 1.0, 0.1)],
                            ["line -2.25 -0.4 0.1 2.25 -0.4 0.1 segment 0.5 radius 0.1",
                             "line -2.25 0.4 0.1 2.25 0.4 0.1 segment 0.5 radius 0.1"])
        r = run(full_precision(deck(f"""
fix             g all gravity {G} vector 0 0 -1
fix             floor wire wire/wall plane 0 0 0 0 0 1 mu_s 1 mu_d 1
fix             elastic wire wire/elastic
fix             integr wire nve/gear
fix             nve grains nve/sphere
fix             calm all viscous 0.05
fix             wg wire wire/grain grains mu_s 0 mu_d 0
timestep        1e-3
thermo_style    custom step ke f_wg[1] f_wg[6]
thermo_modify   format float %.15g
thermo          1000
dump            d all custom 50000 dump.w id mass x y z f_wg[1] f_wg[2] f_wg[3]
run             50000
"""), "d"), workdir=made.workdir)
        self.assertRanCleanly(r)
        t = r.thermo()
        d = read_dump(r.path("dump.w"))
        self.assertEqual(t["wg[1]"][-1], 2.0)
        sphere = d["id"] == 1
        weight = d["mass"][sphere][0] * G
        centre = np.array([d["x"][sphere][0], d["y"][sphere][0], d["z"][sphere][0]])
        force = np.array([d["f_wg[1]"], d["f_wg[2]"], d["f_wg[3]"]]).T
        print(f"\nsphere on rails: force of the wires {force[sphere][0]}, m g = {weight:.15g}")
        np.testing.assert_allclose(force[sphere][0], [0.0, 0.0, weight], rtol=0, atol=1e-8 * weight)
        for rail in (-0.4, 0.4):
            beads = np.nonzero((d["id"] > 1) & (np.abs(d["y"] - rail) < 0.2))[0]
            beads = beads[np.argsort(d["x"][beads])]
            a = np.searchsorted(d["x"][beads], centre[0]) - 1  # the segment under the centre
            i, j = beads[a], beads[a + 1]
            x0 = np.array([d["x"][i], d["y"][i], d["z"][i]])
            x1 = np.array([d["x"][j], d["y"][j], d["z"][j]])
            t_foot = np.dot(centre - x0, x1 - x0) / np.dot(x1 - x0, x1 - x0)
            n = x0 + t_foot * (x1 - x0) - centre
            n /= np.linalg.norm(n)
            on_wire = 0.5 * weight / abs(n[2]) * n  # the contact force on the wire, N n
            print(f"\nrail y = {rail}: t = {t_foot:.6f}, n = {n}, bead forces {force[i]}, {force[j]} "
                  f"(expected {(1 - t_foot) * on_wire}, {t_foot * on_wire})")
            np.testing.assert_allclose(force[i], (1 - t_foot) * on_wire, rtol=0, atol=1e-8 * weight)
            np.testing.assert_allclose(force[j], t_foot * on_wire, rtol=0, atol=1e-8 * weight)
            others = np.setdiff1d(np.nonzero(d["id"] > 1)[0], [i, j])
            untouched = others[np.abs(d["y"][others] - rail) < 0.2]
            self.assertEqual(np.abs(force[untouched]).max(), 0.0)

    def test_wire_draped_over_a_fixed_sphere_is_carried_whole(self):
        # a straight wire dropped across the top of a sphere that nothing integrates
        # (fixed): at rest the sphere carries the wire's whole weight
        made = sphere_scene([(0.0, 0.0, 2.0, 1.0, 1.0)], ["line -1.5 0.0 3.15 1.5 0.0 3.15 segment 0.25 radius 0.05"])
        r = run(full_precision(deck(f"""
fix             g all gravity {G} vector 0 0 -1
fix             elastic wire wire/elastic
fix             integr wire nve/gear
fix             calm wire viscous 0.02
fix             wg wire wire/grain grains
compute         zmin wire reduce min z
timestep        1e-3
thermo_style    custom step ke f_wg[1] f_wg[4] f_wg[5] f_wg[6] c_zmin
thermo_modify   format float %.15g
thermo          1000
dump            d all custom 40000 dump.w id mass z f_wg[1] f_wg[2] f_wg[3]
run             40000
"""), "d"), workdir=made.workdir)
        self.assertRanCleanly(r)
        t = r.thermo()
        d = read_dump(r.path("dump.w"))
        wire_weight = d["mass"][d["id"] > 1].sum() * G
        sphere = d["id"] == 1
        print(f"\ndraped: {t['wg[1]'][-1]:.0f} contacts, force on the sphere "
              f"({d['f_wg[1]'][sphere][0]:.3g}, {d['f_wg[2]'][sphere][0]:.3g}, {d['f_wg[3]'][sphere][0]:.15g}), "
              f"wire weight {wire_weight:.15g}; lowest bead z = {t['zmin'][-1]:.4f}")
        self.assertGreater(t["wg[1]"][-1], 8)       # it lies over an arc
        self.assertGreater(t["zmin"][-1], 1.0)      # and does not hang down to the floor
        self.assertAlmostEqual(d["f_wg[3]"][sphere][0] / -wire_weight, 1.0, delta=1e-8)
        self.assertLess(np.hypot(d["f_wg[1]"][sphere][0], d["f_wg[2]"][sphere][0]), 1e-8 * wire_weight)


class CapstanOverStockSphere(polyhedra.Capstan):
    """The capstan test of fix wire/grain (test_wire_grain.py) over a stock sphere that
    nothing integrates (fixed), radius 1, touched by the closed-form sphere contact."""

    test_quarter_turn = None  # the half turn is enough here
    test_over_a_cube_edge = None

    def make_scene(self, grain, shape, sweep, polyline, chord):
        return sphere_scene([(0.0, 0.0, 0.0, 1.0, 1.0)],
                            [f"polyline wire.txt segment {chord!r} radius {self.WIRE_RADIUS}"],
                            box=(-3, 3, -3, 3, -3, 3), files={"wire.txt": polyline})

    def make_deck(self, body):
        return deck(body)


def flying_sphere_scene():
    """Zero gravity: a sphere (R = 0.5) thrown at a free straight wire."""
    return sphere_scene([(0.0, 0.05, 0.0, 0.5, 1.0)], ["line -1.25 0.1 -0.9 1.25 0.1 -0.9 segment 0.5 radius 0.1"],
                        box=(-6, 6, -6, 6, -6, 6))


VELOCITIES = """
set             group grains vz -1.0
set             group grains vx 0.2
"""
FLIGHT_FIXES = """
fix             elastic wire wire/elastic
fix             integr wire nve/gear scheme verlet
fix             nve grains nve/sphere
fix             wg wire wire/grain grains
timestep        1e-3
"""


class FlightThroughAWire:
    """Zero gravity: a stock grain thrown at a free straight wire (mixed into a
    DeckTestCase; also used by test_wire_superquadric.py). Hooks: HEADER (atom style),
    FLIGHT_FIXES (the wire's fixes and the grain's integrator) and flight_deck(body,
    processors, workdir) -> (deck text, workdir) that makes the scene, sets the grain's
    velocity and appends the fixes and body.

    Velocity Verlet on both sides (the grain's stock integrator, nve/gear scheme verlet),
    forces equal and opposite every step: the total momentum after the collision equals
    the one before to round-off (angular momentum is not conserved: the wire takes the
    force at its axis, the grain at the contact point, the paper's model puts no torque
    on the wire); the friction (and, for a grain that is no sphere, the off-centre hit)
    sets the grain turning."""

    STATE = ("x", "y", "z", "vx", "vy", "vz", "omegax", "omegay", "omegaz")

    def test_grain_hitting_a_free_wire_conserves_momentum(self):
        text, workdir = self.flight_deck("""
variable        px atom mass*vx
variable        pz atom mass*vz
compute         omega grains property/atom omegay
compute         spin grains reduce max c_omega
compute         px all reduce sum v_px
compute         pz all reduce sum v_pz
compute         vg grains reduce max vz
thermo_style    custom step c_px c_pz c_spin c_vg f_wg[1]
thermo_modify   format float %.17g
thermo          5
run             1500
""")
        r = run(text, workdir=workdir)
        self.assertRanCleanly(r)
        t = r.thermo()
        self.assertGreater(t["wg[1]"].max(), 0)   # they touched
        self.assertEqual(t["wg[1]"][-1], 0)       # and parted
        self.assertGreater(t["vg"][-1] - t["vg"][0], 0.02)   # the grain was slowed down
        self.assertGreater(abs(t["spin"][-1] - t["spin"][0]), 1e-4)  # and set turning
        p0 = np.hypot(t["px"][0], t["pz"][0])
        drift = np.hypot(t["px"][-1] - t["px"][0], t["pz"][-1] - t["pz"][0])
        print(f"\nmomentum: |p| = {p0:.15g}, after the collision |Δp| = {drift:.3g} ({drift / p0:.2e} relative); "
              f"spin {t['spin'][-1]:.4g}")
        self.assertLess(drift, 1e-13 * p0)

    def test_two_ranks_give_the_state_of_one(self):
        # the subdomain boundary x = 0 cuts the grain and the wire
        states = []
        for ranks, grid in ((1, "1 1 1"), (2, "2 1 1")):
            text, workdir = self.flight_deck("""
thermo          100
dump            d all custom 900 dump.s id x y z vx vy vz omegax omegay omegaz
run             900
""", processors=grid)
            r = run(full_precision(text, "d"), np_ranks=ranks, workdir=workdir)
            self.assertRanCleanly(r)
            states.append(read_dump(r.path("dump.s")))
        for column in self.STATE:
            np.testing.assert_allclose(states[1][column], states[0][column], rtol=0, atol=1e-13, err_msg=column)

    def test_restart_in_contact_continues_the_straight_run(self):
        # the restart is written at step 700, the grain on the wire (its tangential
        # spring in the restart file); the straight run also stops and goes on at 700
        text, workdir = self.flight_deck("""
thermo_style    custom step f_wg[1]
thermo          700
run             700
dump            d all custom 500 dump.s id x y z vx vy vz omegax omegay omegaz
run             500
""")
        straight = run(full_precision(text, "d"), workdir=workdir)
        self.assertRanCleanly(straight)
        self.assertGreater(straight.thermo(0)["wg[1]"][-1], 0, "no contact at the restart")
        os.rename(straight.path("dump.s"), straight.path("dump.straight"))
        text, _ = self.flight_deck("""
run             700
write_restart   mid.restart
""", workdir=straight.workdir)
        first = run(text, workdir=straight.workdir)
        self.assertRanCleanly(first)
        second = run(full_precision(self.HEADER + """
read_restart    mid.restart
group           grains type 1
group           wire type 2
""" + self.FLIGHT_FIXES + """
dump            d all custom 500 dump.s id x y z vx vy vz omegax omegay omegaz
run             500
""", "d"), workdir=straight.workdir)
        self.assertRanCleanly(second)
        a, b = read_dump(straight.path("dump.straight")), read_dump(straight.path("dump.s"))
        for column in self.STATE:
            np.testing.assert_allclose(b[column], a[column], rtol=0, atol=1e-13, err_msg=column)


class Momentum(FlightThroughAWire, DeckTestCase):
    HEADER = HEADER
    FLIGHT_FIXES = FLIGHT_FIXES

    def flight_deck(self, body, processors="* * *", workdir=None):
        # the scene is a data file in the run's directory: made once per directory
        if workdir is None:
            workdir = flying_sphere_scene().workdir
        return deck(VELOCITIES + FLIGHT_FIXES + body, processors=processors), workdir


class Errors(DeckTestCase):
    def test_groups(self):
        made = flying_sphere_scene()
        for body, message in (
                ("fix wg wire wire/grain all",
                 "fix wire/grain (id wg): grain group 'all' holds 6 wire beads (give the grains only)"),
                ("fix wg wire wire/grain wire",
                 "fix wire/grain (id wg): grain group 'wire' holds 6 wire beads (give the grains only)"),
                ("fix wg all wire/grain grains",
                 "fix wire/grain (id wg): wire group 'all' holds 1 grains (give the wire beads only)")):
            self.assertStopsWith(run(deck(body + "\nrun 1\n"), workdir=made.workdir), message)


if __name__ == "__main__":
    main()
