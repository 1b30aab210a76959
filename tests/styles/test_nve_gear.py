"""fix nve/gear against analytic motions, against stock fix nve, and its error messages."""

import math

import numpy as np

from liggghts_run import DeckTestCase, deck, main, read_dump, run

POINT_MASS = """
units           lj
atom_style      atomic
atom_modify     map array sort 0 0.0
boundary        f f f
region          box block -50 50 -50 50 -50 50
create_box      1 box
create_atoms    1 single 0.0 0.0 0.0
mass            1 2.0
velocity        all set {vx} 0.0 {vz}
timestep        {dt}
{forces}
fix             integr all nve/gear {options}
variable        x equal x[1]
variable        z equal z[1]
variable        vz equal vz[1]
thermo_style    custom step time v_x v_z v_vz
thermo_modify   format float %.17g
thermo          {every}
run             {steps}
"""


def point_mass(forces, options="", dt=0.01, steps=1000, every=100, vx=0.0, vz=0.0):
    text = POINT_MASS.format(forces=forces, options=options, dt=dt, steps=steps, every=every,
                             vx=vx, vz=vz)
    return run(text)


class FreeFall(DeckTestCase):
    # Under constant gravity both schemes reproduce z = v0 t - g t²/2 to round-off.
    def test_free_fall_exact(self):
        for scheme in ("gear5", "verlet"):
            r = point_mass("fix grav all gravity 1.5 vector 0 0 -1", f"scheme {scheme}", vz=3.0)
            self.assertRanCleanly(r)
            t = r.thermo()
            z_exact = 3.0 * t["Time"] - 0.5 * 1.5 * t["Time"] ** 2
            self.assertLess(np.max(np.abs(t["z"] - z_exact)), 1e-11, scheme)
            self.assertLess(np.max(np.abs(t["vz"] - (3.0 - 1.5 * t["Time"]))), 1e-11, scheme)


class Oscillator(DeckTestCase):
    """A mass on fix spring/self (k = 2, m = 2, so omega = 1)."""

    def error(self, scheme, dt, start):
        # start "rest": released at rest from x0 = 1, x(t) = cos t (initial jerk 0);
        # start "moving": from x0 = 0 with v0 = 1, x(t) = sin t (initial jerk -1).
        if start == "rest":
            forces, vx, exact = "fix spring all spring/self 2.0\nset atom 1 x 1.0", 0.0, np.cos
        else:
            forces, vx, exact = "fix spring all spring/self 2.0", 1.0, np.sin
        r = point_mass(forces, f"scheme {scheme}", dt=dt, steps=int(round(20.0 / dt)),
                       every=int(round(1.0 / dt)), vx=vx)
        self.assertRanCleanly(r)
        t = r.thermo()
        return np.max(np.abs(t["x"] - exact(t["Time"])))

    def errors(self, start):
        e = {(s, dt): self.error(s, dt, start) for s in ("gear5", "verlet") for dt in (0.02, 0.01)}
        print(f"oscillator from {start}, max error over 20 time units (dt 0.02 / 0.01): "
              f"gear5 {e['gear5', 0.02]:.3e} / {e['gear5', 0.01]:.3e}, "
              f"verlet {e['verlet', 0.02]:.3e} / {e['verlet', 0.01]:.3e}")
        return e

    def test_gear_from_rest_is_high_order(self):
        e = self.errors("rest")
        self.assertAlmostEqual(math.log2(e["verlet", 0.02] / e["verlet", 0.01]), 2.0, delta=0.1)
        self.assertGreater(math.log2(e["gear5", 0.02] / e["gear5", 0.01]), 3.8)
        self.assertLess(e["gear5", 0.01], 1e-2 * e["verlet", 0.01])

    def test_gear_started_with_unknown_jerk(self):
        # The history starts with jerk 0 although the true jerk is -1: a start-up error
        # of order dt^2 remains, still well below Verlet's.
        e = self.errors("moving")
        self.assertAlmostEqual(math.log2(e["gear5", 0.02] / e["gear5", 0.01]), 2.0, delta=0.1)
        self.assertLess(e["gear5", 0.01], 0.2 * e["verlet", 0.01])


class SameAsStockNve(DeckTestCase):
    # scheme verlet is velocity Verlet, as stock fix nve: the settling example must give the
    # same trajectory up to round-off.
    def test_verlet_matches_fix_nve(self):
        text = deck("examples/settle_gear/in.settle_gear")
        stock = text.replace("nve/gear scheme ${scheme}", "nve")
        self.assertNotEqual(stock, text)
        settings = {"scheme": "verlet", "nsteps": 400, "dumpevery": 400}
        runs = {"verlet": run(text, variables=settings), "nve": run(stock, variables=settings)}
        for r in runs.values():
            self.assertRanCleanly(r)
        a = read_dump(runs["verlet"].path("dump.settle_gear"))
        b = read_dump(runs["nve"].path("dump.settle_gear"))
        self.assertEqual(len(a["id"]), len(b["id"]))
        self.assertGreater(len(a["id"]), 400)
        for c in ("x", "y", "z", "vx", "vy", "vz"):
            self.assertLess(np.max(np.abs(a[c] - b[c])), 1e-12, c)


class VerletAcrossRuns(DeckTestCase):
    # A damped mass on a spring (fix viscous: a velocity-dependent force): velocity Verlet
    # starts each step with the acceleration of the last step's end, which it keeps, so
    # two runs of 1000 steps are the run of 2000 to the bit; stock fix nve starts the
    # second run with the forces LIGGGHTS' setup recomputes at the full-step velocity.
    def test_two_runs_are_one(self):
        body = POINT_MASS.replace("run             {steps}\n", "{runs}")
        forces = "fix spring all spring/self 2.0\nfix drag all viscous 0.3\nset atom 1 x 1.0"
        finals = {}
        for integrator in ("nve/gear scheme verlet", "nve"):
            for runs in ("run 2000\n", "run 1000\nrun 1000\n"):
                text = body.format(forces=forces, options="scheme verlet", dt=0.01, every=2000, vx=0.0, vz=0.0,
                                   runs=runs).replace("nve/gear scheme verlet", integrator)
                r = run(text)
                self.assertRanCleanly(r)
                t = r.thermo()
                finals[integrator, runs] = (t["x"][-1], t["vz"][-1], t["Time"][-1])
            one, two = finals[integrator, "run 2000\n"], finals[integrator, "run 1000\nrun 1000\n"]
            self.assertEqual(one[2], two[2])
            if integrator == "nve":
                self.assertNotEqual(one[0], two[0])  # the stock integrator's restart of the kick
            else:
                self.assertEqual(one[0], two[0])


class AtomsAfterRestart(DeckTestCase):
    # Beads created by create_wire after read_restart (stock create_atoms refuses to run
    # there) have no Gear history in the restart file: they start as new (as beads created
    # between two runs of one deck) and fall freely (no wire/elastic: free beads),
    # z = z0 − g t²/2 from their creation; the restarted run equals the straight one (the
    # first bead's history, restored, keeps it on its parabola too).
    SETUP = """
units           lj
atom_style      wire
atom_modify     map array sort 0 0.0
boundary        f f f
region          box block -50 50 -50 50 -50 50
create_box      1 box
create_atoms    1 single 0.0 0.0 0.0
"""
    BODY = """
fix             grav all gravity 1.5 vector 0 0 -1
fix             integr all nve/gear
timestep        0.01
"""
    CREATE_AND_RUN = """
create_wire     1 line 5.0 0.0 0.0 5.4 0.0 0.0
variable        z1 equal z[1]
variable        z2 equal z[2]
thermo_style    custom step time v_z1 v_z2
thermo_modify   format float %.17g
thermo          10
run             100
"""

    def test_created_beads_fall_freely(self):
        straight = run(self.SETUP + self.BODY + "run 20\n" + self.CREATE_AND_RUN)
        self.assertRanCleanly(straight)
        first = run(self.SETUP + self.BODY + "run 20\nwrite_restart one.restart\n", workdir=straight.workdir)
        restarted = run("units lj\natom_style wire\natom_modify map array sort 0 0.0\nboundary f f f\n"
                        "read_restart one.restart\n" + self.CREATE_AND_RUN.replace("run ", self.BODY + "run "),
                        workdir=straight.workdir)
        for r in (first, restarted):
            self.assertRanCleanly(r)
        a, b = straight.thermo(), restarted.thermo()
        t = a["Time"]
        z1 = -0.5 * 1.5 * t ** 2
        z2 = -0.5 * 1.5 * (t - t[0]) ** 2
        errors = np.max(np.abs(a["z1"] - z1)), np.max(np.abs(a["z2"] - z2))
        difference = max(np.max(np.abs(a[z] - b[z])) for z in ("z1", "z2"))
        print(f"beads created after a restart: free-fall errors {errors[0]:.1e} {errors[1]:.1e}, "
              f"restarted vs straight {difference:.1e}")
        self.assertLess(max(errors), 1e-11)
        self.assertLess(difference, 1e-12)


# A straight wire resting in a V-groove of two fix wire/wall planes at ±45° (strongly
# damped contacts, restitution 0.1): every bead carries two wall contacts at once.
GROOVE = """
units           lj
atom_style      wire
boundary        f f f
newton          off
region          box block -2 2 -2 2 -2 2
create_box      1 box
create_wire     1 line -0.5 0 0.16 0.5 0 0.16
fix             elastic all wire/elastic
fix             integr all nve/gear {options}
fix             gravity all gravity 1.0 vector 0 0 -1
fix             left all wire/wall plane 0 0 0 0 0.70710678118654752 0.70710678118654752 restitution 0.1
fix             right all wire/wall plane 0 0 0 0 -0.70710678118654752 0.70710678118654752 restitution 0.1
timestep        {dt}
compute         ke all ke
thermo_style    custom step c_ke f_integr[1] f_integr[2]
thermo_modify   format float %.15g
thermo          2000
run             20000
"""


def groove_bead_limit():
    """The gear5 limit of one bead of GROOVE, by hand (docs/commands/fix_nve_gear.md, "Each
    bead's time step"): the walls' springs k_n = E l π/4, k_t = E r (E* = E for ν = 0) and
    dashpots γ = 2ζ√(k m) on the bead mass m = ρ π r² l; the two normals (0, ±1, 1)/√2 give
    K = diag(2 k_t, k_n + k_t, k_n + k_t) and Γ likewise; limit = min(0.313 (√(1+ζ²) − ζ)/ω,
    0.075/(ζ ω)) with ω² = (k_n + k_t)/m, ζ ω = (γ_n + γ_t)/(2 m)."""
    E, r, l, rho, e = 100.0, 0.1, 0.2, 0.5, 0.1
    m = rho * math.pi * r * r * l
    k_n, k_t = E * l * math.pi / 4, E * r
    zeta = -math.log(e) / math.sqrt(math.pi ** 2 + math.log(e) ** 2)
    g_n, g_t = 2 * zeta * math.sqrt(k_n * m), 2 * zeta * math.sqrt(k_t * m)
    omega = math.sqrt((k_n + k_t) / m)
    zeta_bead = (g_n + g_t) / (2 * math.sqrt((k_n + k_t) * m))
    single = 0.075 / (zeta * math.sqrt(k_n / m))  # one wall contact alone (its damping decides)
    bead = min(0.313 * (math.sqrt(1 + zeta_bead ** 2) - zeta_bead) / omega, 0.075 / (zeta_bead * omega))
    return bead, single


class BeadContactLoads(DeckTestCase):
    """The per-bead time-step check: a bead loaded by several contacts at once
    is unstable at a step that each contact alone allows (it rattles at the contact
    frequency instead of coming to rest)."""

    def test_groove_beyond_the_bead_limit_rattles_and_warns(self):
        bead, single = groove_bead_limit()
        self.assertLess(1.3 * bead, single)  # a step each wall's own check lets through
        above = run(GROOVE.format(dt=1.3 * bead, options=""))
        self.assertRanCleanly(above)
        self.assertIn("WARNING: fix nve/gear (id integr): at step", above.output)
        self.assertRegex(above.output, r"bead \d+ carries 2 contacts whose summed springs and dashpots on its mass "
                                       r"0\.00314159 give a gear5 limit of 0\.000997")
        self.assertNotIn("WARNING: fix wire/wall", above.output)
        t = above.thermo()
        self.assertAlmostEqual(t["integr[2"][-1], 1.3, delta=1e-9)
        # checked every 10th step by default: nearly every one of the 2000 checks
        self.assertGreater(t["integr[1"][-1], 1900)
        self.assertLessEqual(t["integr[1"][-1], 2000)
        self.assertGreater(np.min(t["ke"][-5:]), 1e-11)  # still rattling after 20000 steps
        every = run(GROOVE.format(dt=1.3 * bead, options="check_every 1"))
        self.assertRanCleanly(every)
        self.assertGreater(every.thermo()["integr[1"][-1], 19000)
        np.testing.assert_array_equal(every.thermo()["ke"], t["ke"])  # the check does not touch the motion
        never = run(GROOVE.format(dt=1.3 * bead, options="check_every 0"))
        self.assertRanCleanly(never)
        self.assertNotIn("WARNING: fix nve/gear", never.output)
        self.assertEqual(never.thermo()["integr[1"][-1], 0)
        self.assertEqual(never.thermo()["integr[2"][-1], 0)
        below = run(GROOVE.format(dt=0.8 * bead, options=""))
        self.assertRanCleanly(below)
        self.assertNotIn("WARNING: fix nve/gear", below.output)
        t = below.thermo()
        self.assertEqual(t["integr[1"][-1], 0)
        self.assertAlmostEqual(t["integr[2"][-1], 0.8, delta=1e-9)
        self.assertLess(t["ke"][-1], 1e-25)  # at rest

    def test_loads_summed_across_ranks(self):
        # two crossing wires on a floor, the crossing on the boundary of two ranks: the
        # loads a rank adds to its ghost beads reach their owners (the same largest ratio
        # at every sample on 1 and 2 ranks, to the round-off the trajectories differ by)
        deck_text = """
units           lj
atom_style      wire
atom_modify     map array
boundary        f f f
newton          off
processors      * 1 1
region          box block -2 2 -2 2 -1 2
create_box      1 box
create_wire     1 line -1.03 0 0.1 1.03 0 0.1
create_wire     1 line 0.05 -1.03 0.29 0.05 1.03 0.29
pair_style      wire/contact restitution 0.1
pair_coeff      * *
neighbor        0.1 bin
fix             elastic all wire/elastic
fix             integr all nve/gear
fix             gravity all gravity 1.0 vector 0 0 -1
fix             floor all wire/wall plane 0 0 0 0 0 1 restitution 0.1
timestep        1e-3
thermo_style    custom step f_integr[1] f_integr[2]
thermo_modify   format float %.15g
thermo          100
run             3000
"""
        one, two = run(deck_text), run(deck_text, np_ranks=2)
        self.assertRanCleanly(one)
        self.assertRanCleanly(two)
        a, b = one.thermo(), two.thermo()
        self.assertGreater(np.max(a["integr[2"]), 1.2)
        np.testing.assert_allclose(b["integr[2"], a["integr[2"], rtol=1e-9)
        np.testing.assert_array_equal(b["integr[1"], a["integr[1"])


class BadInput(DeckTestCase):
    def check(self, options, message):
        r = point_mass("", options, steps=10)
        self.assertStopsWith(r, message)

    def test_unknown_keyword(self):
        self.check("schme gear5", "fix nve/gear (id integr): unknown keyword 'schme'; accepted: scheme, forces, check_every")

    def test_missing_value(self):
        self.check("scheme", "fix nve/gear (id integr): missing value after 'scheme'")

    def test_negative_check_every(self):
        self.check("check_every -1", "fix nve/gear (id integr): value of 'check_every' must be >= 0, got -1")

    def test_bad_scheme(self):
        self.check("scheme rk4",
                   "fix nve/gear (id integr): value of 'scheme' must be gear5 or verlet, got 'rk4'")

    def test_bad_forces(self):
        self.check("forces both",
                   "fix nve/gear (id integr): value of 'forces' must be position or velocity")

    def test_bad_mass(self):
        # a sphere of diameter 0 has rmass 0 (LIGGGHTS' set accepts it); set mass 1e400 gives inf
        spheres = """
units           lj
atom_style      sphere
boundary        f f f
region          box block -5 5 -5 5 -5 5
create_box      1 box
create_atoms    1 single 0 0 0
create_atoms    1 single 1 0 0
set             atom 2 {what}
fix             integr all nve/gear
run             1
"""
        self.assertStopsWith(run(spheres.format(what="diameter 0")),
                             "fix nve/gear (id integr): atom 2 has mass 0 (must be a finite number > 0)")
        self.assertStopsWith(run(spheres.format(what="mass 1e400")),
                             "fix nve/gear (id integr): atom 2 has mass inf (must be a finite number > 0)")

    def test_non_finite_force(self):
        # an infinite force from another style (here fix addforce) stops at the step it appears
        r = point_mass("variable big equal 1e300*(step>=3)*1e300\nfix push all addforce v_big 0 0", steps=10)
        self.assertStopsWith(r, "fix nve/gear (id integr): atom 1 has a non-finite force at step 3 "
                                "(from a force style or fix acting on it)")


if __name__ == "__main__":
    main()
