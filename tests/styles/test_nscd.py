"""fix nscd/polyhedra: stacks, inclines, sliding and corners against statics and
Coulomb's law; 1 vs 2 ranks; restart with warm-start impulses; error messages."""

import math
import os

import numpy as np

from liggghts_run import DeckTestCase, dump_frames, full_precision, grains_data, main, read_dump, run, warning_lines
from test_wire_grain import deck as wire_deck, scene as wire_scene

G = 1.0


# the head of every deck here: one rank per x slab
HEAD = """
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
processors      * 1 1
"""


def restarted(path):
    """The head of a deck that continues from the restart file `path`."""
    return HEAD + f"read_restart    {path}\n"


def deck(body):
    """A deck on grains.data and grains.shapes (grains_data) with `body` after them."""
    return HEAD + f"""grain_shapes    read grains.shapes
read_data       grains.data
{body}
"""


def cube_stack(case, n):
    """grains.data and grains.shapes (grains_data) of n unit cubes stacked on the floor z = 0,
    made in a folder the caller's deck then runs in (made.workdir)."""
    made = grains_data("cube 1.0", [(0, 0, 0.5 + k, 1, 0, 0, 0) for k in range(n)])
    case.assertRanCleanly(made)
    return made


class Stack(DeckTestCase):
    # N unit cubes (m = 1) stacked on a floor, the fix's default solver (method subspace,
    # tolerance 1e-4): interface k from the top carries k m g, the floor N m g, no grain
    # feels a horizontal force or a torque, and the overlaps stay at round-off, on every
    # sample of the run (10 snapshots, the floor every 10 steps). Measured (2026-12-05): the
    # worst relative interface error 2.2e-16, 8.9e-16 and 1.2e-14 for N = 1, 5 and 20, the
    # floor's 4.4e-16, 1.3e-15 and 1.5e-14, horizontal forces and torques at most 4.8e-16
    # N m g, overlaps 0: the stick solve of the resting contacts is exact. Held to 1e-13
    # and 5e-15 N m g; a solve that stopped at its tolerance would be ~1e-4 off.
    def check(self, n, steps):
        made = cube_stack(self, n)
        r = run(full_precision(deck(f"""
fix             g all gravity {G} vector 0 0 -1
fix             nscd all nscd/polyhedra friction 0.5 wall 0 0 0 0 0 1
timestep        1e-3
thermo_style    custom step f_nscd[1] f_nscd[3] f_nscd[4] f_nscd[9]
thermo_modify   format float %.17g
thermo          10
dump            d all custom {steps // 10} dump.s id z f_nscd[1] f_nscd[2] f_nscd[3] f_nscd[4] f_nscd[5] f_nscd[6]
run             {steps}
"""), "d"), workdir=made.workdir)
        self.assertRanCleanly(r)
        t = r.thermo()
        k = np.arange(1, n + 1)
        worst, sideways = 0.0, 0.0
        for d in [frame for _, frame in dump_frames(r.path("dump.s"))][1:]:          # after the first step
            order = np.argsort(-d["z"])                          # top first
            interface = np.cumsum(d["f_nscd[3]"][order])         # force from below on the top k grains
            worst = max(worst, np.max(np.abs(interface / (k * G) - 1.0)))
            sideways = max(sideways, max(np.max(np.abs(d[f"f_nscd[{c}]"])) for c in (1, 2, 4, 5, 6)) / (n * G))
        floor = np.max(np.abs(-t["nscd[9]"][1:] / (n * G) - 1.0))
        print(f"stack of {n}, {steps} steps: worst interface force error {worst:.2e}, floor {floor:.2e}, "
              f"horizontal forces and torques {sideways:.2e} N m g, largest overlap {np.max(t['nscd[4]']):.2e}, "
              f"sweeps at the end {t['nscd[1]'][-1]:.0f}")
        self.assertLess(worst, 1e-13)
        self.assertLess(floor, 1e-13)
        self.assertLess(sideways, 5e-15)
        self.assertLess(np.max(t["nscd[4]"]), 1e-14)  # measured 0
        self.assertNotIn("starts with an overlap", r.output)

    def test_stacks(self):
        for n, steps in ((1, 10000), (5, 10000), (20, 1000)):
            self.check(n, steps)


class IrregularStack(DeckTestCase):
    # 12 Table 1 grains (create_grains, a in [0.8, 1], sweep 0.1, density 1.5) dropped
    # into a column 2.4 wide between frictional side walls (wall_friction 0.3) on a
    # frictional floor (0.5): they wedge against the walls and against each other, the
    # side walls carrying part of the weight by friction. Settled (8 time units falling,
    # 2 more with damping 10 to stop any rattler, then 2 undamped), every grain is at rest
    # and in equilibrium: its contact force (per-atom f_nscd[1..3], impulses / h) is −m g,
    # its contact torque (f_nscd[4..6]) 0, and the walls' forces (global f_nscd[7..21],
    # 5 walls) add up to the total weight. Measured (seed 5, 2026-12-05): speeds 1.6e-18,
    # force errors at most 2.9e-15 m g, torques at most 1.6e-15 m g a_max, the walls' sum
    # 1e-15 M g off; of the seeds 1–7, 4 came to rest to round-off within these 12 time
    # units (2 more to 1e-9, still converging, and one kept a rattler moving). Held to
    # 3e-14 and 1e-14; the side walls' share (about a third of the weight, pulling down
    # here: the floor carries more than the weight) only needs to be there.
    def test_every_grain_in_equilibrium(self):
        r = run(full_precision(HEAD + f"""
region          box block -2 2 -2 2 -1 40
create_box      1 box
region          column block -0.05 0.05 -0.05 0.05 1.2 30
create_grains   1 12 random column seed 5
fix             g all gravity {G} vector 0 0 -1
fix             nscd all nscd/polyhedra timestep 2e-3 wall 0 0 0 0 0 1 &
                wall -1.2 0 0 1 0 0 wall_friction 0.3 wall 1.2 0 0 -1 0 0 wall_friction 0.3 &
                wall 0 -1.2 0 0 1 0 wall_friction 0.3 wall 0 1.2 0 0 -1 0 wall_friction 0.3
timestep        2e-3
thermo_style    custom step ke f_nscd[1] f_nscd[2] f_nscd[3] f_nscd[6] f_nscd[9]
thermo_modify   format float %.6g norm no
thermo          1000
run             4000
fix_modify      nscd damping 10
run             1000
fix_modify      nscd damping 0
variable        mass equal mass(all)
thermo_style    custom step ke v_mass f_nscd[7] f_nscd[8] f_nscd[9] f_nscd[10] f_nscd[11] f_nscd[12] &
                f_nscd[13] f_nscd[14] f_nscd[15] f_nscd[16] f_nscd[17] f_nscd[18] f_nscd[19] f_nscd[20] f_nscd[21]
thermo_modify   format float %.17g norm no
thermo          1000
dump            d all custom 1000 dump.s id mass x y z vx vy vz f_nscd[1] f_nscd[2] f_nscd[3] f_nscd[4] f_nscd[5] f_nscd[6]
run             1000
""", "d"))
        self.assertRanCleanly(r)
        t = r.thermo()
        d = read_dump(r.path("dump.s"))
        m = d["mass"]
        force = np.column_stack([d[f"f_nscd[{c}]"] for c in (1, 2, 3)])
        torque = np.column_stack([d[f"f_nscd[{c}]"] for c in (4, 5, 6)])
        speed = np.max(np.abs([d[c] for c in ("vx", "vy", "vz")]))
        weight = m.sum() * G
        self.assertAlmostEqual(t["mass"][-1], m.sum(), delta=1e-12 * m.sum())
        walls = np.array([[t[f"nscd[{6 + 3 * w + c}]"][-1] for c in (1, 2, 3)] for w in range(5)])
        force_error = np.max(np.abs(force - np.column_stack([0 * m, 0 * m, m * G])), axis=1) / (m * G)
        torque_error = np.max(np.abs(torque), axis=1) / (m * G)
        print(f"\nirregular stack: 12 grains up to z = {d['z'].max():.2f}, largest speed {speed:.1e}, force errors at most "
              f"{force_error.max():.1e} m g, torques {torque_error.max():.1e} m g a_max; walls carry {-walls[:, 2].sum():.15g} "
              f"(weight {weight:.15g}): floor {-walls[0, 2]:.6g}, side walls {-walls[1:, 2].sum():.6g}")
        self.assertLess(speed, 1e-12)
        self.assertLess(force_error.max(), 3e-14)
        self.assertLess(torque_error.max(), 1e-14)
        np.testing.assert_allclose(walls.sum(axis=0), [0.0, 0.0, -weight], rtol=0, atol=3e-14 * weight)
        self.assertGreater(np.abs(walls[1:, 2].sum()), 1e-3 * weight)  # friction on the side walls holds
        self.assertGreater(np.abs(walls[1:, :2]).max(), 1e-3 * weight)  # the grains press on them


class WireLoadedStack(DeckTestCase):
    # Three cubes of edge 2 (sweep 0.1, density 1) stacked on the floor and a Table 1 wire
    # on top: a double loop of radius 0.6 (2 turns rising 0.25, 37 segments) laid 0.02
    # above the top face, which falls onto it, its upper turn onto its lower one (pair
    # wire/contact). Sub-cycled as in docs/tutorial.md: the wire's step 1e-3, the grains'
    # NSCD step 2e-3 (fix wire/grain passes the wire's forces on, averaged over the NSCD
    # step); fix viscous 0.02 on the beads stops the wire's vibration (no force at rest).
    # At rest (20 time units) the floor carries (3 m_c + m_w) g, the interface below the
    # k-th cube from the top (k m_c + m_w) g, and the grains carry the whole wire: the
    # beads' forces from the grains (per-atom f_wg[3]) add up to m_w g. Measured
    # (2026-12-05): the wire's kinetic energy 7e-28, the interfaces 2.9e-15, 1.3e-15 and
    # 8.9e-16 (relative) off, i.e. the wire's share in each 2.6e-13 of m_w g off, the
    # beads' sum 2.4e-13 of m_w g; held to 3e-14 and 3e-12 (without the damping the wire
    # still moves after 10 time units and the interfaces are 9e-6 off).
    SOLVE, RANKS = "", 1  # (test_distributed.py: the same with solve distributed on 2 ranks)
    PROCESSORS = "* * *"

    def test_the_stack_carries_the_wire(self):
        made = wire_scene([(0, 0, 1.1 + 2.2 * k, 1, 0, 0, 0) for k in range(3)], ["loop 0 0 6.72 0.6 2 0.25"],
                          shape="cube 2", box=(-3, 3, -3, 3, -1, 9))
        r = run(full_precision(wire_deck(f"""
pair_style      wire/contact
pair_coeff      * *
neighbor        0.1 bin
neigh_modify    delay 0
fix             g all gravity {G} vector 0 0 -1
fix             elastic wire wire/elastic
fix             integr wire nve/gear scheme verlet
fix             nscd grains nscd/polyhedra timestep 2e-3 {self.SOLVE} wall 0 0 0 0 0 1
fix             wg wire wire/grain grains
fix             calm wire viscous 0.02
timestep        1e-3
compute         kew wire ke
thermo_style    custom step c_kew f_nscd[1] f_nscd[9] f_wg[1] f_wg[6]
thermo_modify   format float %.17g norm no
thermo          2000
dump            d all custom 20000 dump.s id type mass z f_nscd[3] f_wg[3]
run             20000
""", processors=self.PROCESSORS), "d"), workdir=made.workdir, np_ranks=self.RANKS)
        self.assertRanCleanly(r)
        t = r.thermo()
        d = read_dump(r.path("dump.s"))
        cubes = d["type"] == 1
        m_wire = d["mass"][~cubes].sum()
        order = np.argsort(-d["z"][cubes])                                     # top first
        interface = np.cumsum(d["f_nscd[3]"][cubes][order])                    # from below on the top k cubes
        expected = (m_wire + np.cumsum(d["mass"][cubes][order])) * G
        carried = d["f_wg[3]"][~cubes].sum()
        print(f"\nwire on a stack: kinetic energy of the wire {t['kew'][-1]:.1e}, {t['wg[1]'][-1]:.0f} wire-grain contacts, "
              f"interfaces {interface} (expected {expected}), floor {-t['nscd[9]'][-1]:.15g}, the grains hold "
              f"{carried:.15g} of the wire's weight {m_wire * G:.15g}")
        self.assertEqual(len(expected), 3)
        self.assertLess(t["kew"][-1], 1e-20)
        np.testing.assert_allclose(interface, expected, rtol=3e-14)
        # what each interface carries above the cubes' weight: the wire's, to 2.6e-13 of it
        share = interface - np.cumsum(d["mass"][cubes][order]) * G
        np.testing.assert_allclose(share, m_wire * G, rtol=3e-12)
        self.assertAlmostEqual(-t["nscd[9]"][-1] / expected[-1], 1.0, delta=3e-14)
        self.assertAlmostEqual(carried / (m_wire * G), 1.0, delta=3e-12)
        self.assertAlmostEqual(-t["wg[6]"][-1] / (m_wire * G), 1.0, delta=3e-12)


class Incline(DeckTestCase):
    # A box on a plane tilted by θ (gravity tilted instead of the floor), μ = 0.5:
    # it sticks for θ < atan μ and slides with a = g (sin θ − μ cos θ) above. The θ = 1
    # scheme gains h a per step, starting with the solve at the run's setup, and moves with
    # the end-of-step velocity, so after n steps it has travelled h² a n(n+1)/2, not the
    # continuum a t²/2 (1/n = 5e-4 less at the end). Solver tolerance 1e-10: with
    # overlap_recovery 0 (the default) an overlap the first solve leaves
    # within its tolerance is kept, not pushed out (7.8e-14 at 1e-8, which put the
    # travelled distance 1.0e-12 off; 1.8e-14 at 1e-10).
    def motion(self, theta):
        made = grains_data("box 1.0 0.9 0.8", [(0, 0, 0.4, 1, 0, 0, 0)])
        self.assertRanCleanly(made)
        r = run(deck(f"""
fix             g all gravity {G} vector {math.sin(theta)!r} 0 {-math.cos(theta)!r}
fix             nscd all nscd/polyhedra friction 0.5 tolerance 1e-10 wall 0 0 0 0 0 1
timestep        1e-3
variable        x1 equal x[1]
variable        vx1 equal vx[1]
thermo_style    custom step time v_x1 v_vx1
thermo_modify   format float %.15g
thermo          100
run             2000
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        return r.thermo()

    def test_stick_and_slide(self):
        critical = math.atan(0.5)
        stick = self.motion(critical - math.radians(0.5))
        moved = np.max(np.abs(stick["x1"] - stick["x1"][0]))
        self.assertLess(moved, 2e-12)  # measured 2.1e-15 (2.3e-13 at tolerance 1e-8)
        theta = critical + math.radians(0.5)
        slide = self.motion(theta)
        a = np.polyfit(slide["Time"][2:], slide["vx1"][2:], 1)[0]
        expected = G * (math.sin(theta) - 0.5 * math.cos(theta))
        h, n = 1e-3, slide["Step"][-1]
        travelled = slide["x1"][-1] - slide["x1"][0]
        discrete = h * h * expected * n * (n + 1) / 2
        print(f"incline: sticks at atan(mu) - 0.5 deg (moved {moved:.1e}); at +0.5 deg a = {a:.6f}, "
              f"g(sin - mu cos) = {expected:.6f}, relative error {a / expected - 1:.1e}; travelled {travelled:.15g}, "
              f"the scheme's h^2 a n(n+1)/2 = {discrete:.15g} (relative error {travelled / discrete - 1:.1e}), "
              f"a t^2/2 = {expected * (n * h) ** 2 / 2:.15g}")
        # measured 4.7e-14 and 1.8e-14 (5.5e-14 and 4.0e-14 at tolerance 1e-8 with the
        # overlaps pushed out; the fit starts at step 200)
        self.assertAlmostEqual(a / expected, 1.0, delta=5e-13)
        self.assertAlmostEqual(travelled / discrete, 1.0, delta=4e-13)


def launch_one_grain(case, shape, z, nscd_options, steps, every):
    """One grain of `shape` resting at height z on the floor z = 0, launched at vx = 1 under
    gravity G with fix nscd/polyhedra `nscd_options`; h = 1e-3. Returns the thermo (x1, v1:
    its x and vx every `every` steps)."""
    made = grains_data(shape, [(0, 0, z, 1, 0, 0, 0)])
    case.assertRanCleanly(made)
    r = run(deck(f"""
velocity        all set 1.0 0 0
fix             g all gravity {G} vector 0 0 -1
fix             nscd all nscd/polyhedra {nscd_options} wall 0 0 0 0 0 1
timestep        1e-3
variable        x1 equal x[1]
variable        v1 equal vx[1]
thermo_style    custom step v_x1 v_v1
thermo_modify   format float %.15g
thermo          {every}
run             {steps}
"""), workdir=made.workdir)
    case.assertRanCleanly(r)
    return r.thermo()


class Launch(DeckTestCase):
    # A box launched at v0 on flat ground stops after v0^2 / (2 μ g). The θ = 1 scheme
    # decelerates by μ g h per step and moves with the end-of-step velocity, so with
    # N = v0 / (μ g h) steps (an integer here) it travels h Σ_{k=1..N} (v0 − k μ g h)
    # = v0^2 / (2 μ g) − h v0 / 2: 0.9995 for v0 = 1, μ g = 0.5, h = 1e-3.
    def test_stopping_distance(self):
        thermo = launch_one_grain(self, "box 1.0 0.9 0.8", 0.4, "friction 0.5 tolerance 1e-8", 3000, 100)
        travelled = thermo["x1"][-1]
        h, v0, decel = 1e-3, 1.0, 0.5 * G
        steps = round(v0 / (decel * h))
        discrete = h * sum(v0 - k * decel * h for k in range(1, steps + 1))
        print(f"launch: stopped after {travelled:.12f}, v0^2/(2 mu g) = 1.0, the scheme's {discrete:.12f}")
        self.assertAlmostEqual(travelled, discrete, delta=1e-9)


class RollingFriction(DeckTestCase):
    # fix nscd/polyhedra rolling_friction μ_r: a sphere (radius r = 0.5, its sweep radius)
    # launched at v0 without spin. While it slides, friction slows it (v' = −μ g) and spins
    # it up against the rolling couple μ_r r m g (I ω' = (μ − μ_r) m g r, I = 2/5 m r²), so
    # it rolls from t1 = v0 / (g (μ + 5/2 (μ − μ_r))) at v1 = v0 − μ g t1 (2.2222 and
    # 0.5556 for v0 = 1, μ = 0.2, μ_r = 0.1, g = 1); then the couple slows it at
    # (5/7) μ_r g to rest: v0 t1 − μ g t1² / 2 + v1² / (2 (5/7) μ_r g) = 1.7284 + 2.1605
    # travelled, less O(h v0) for the θ = 1 steps. Without rolling_friction it would roll
    # on at 5 v0 / 7.
    def test_launched_sphere_slides_rolls_and_stops(self):
        thermo = launch_one_grain(self, "sphere 0.5", 0.5, "friction 0.2 rolling_friction 0.1 tolerance 1e-10", 12000, 500)
        v0, mu, mu_r = 1.0, 0.2, 0.1
        t1 = v0 / (G * (mu + 2.5 * (mu - mu_r)))
        v1 = v0 - mu * G * t1
        decel = 5.0 / 7.0 * mu_r * G
        expected = v0 * t1 - mu * G * t1 ** 2 / 2 + v1 ** 2 / (2 * decel)
        travelled = thermo["x1"][-1]
        v_at_7 = v1 - decel * (7.0 - t1)  # rolling, slowed by the couple
        print(f"rolling friction: travelled {travelled:.9f}, continuous {expected:.9f}, "
              f"v at t = 7 {thermo['v1'][14]:.9f} (continuous {v_at_7:.9f})")
        self.assertLess(abs(thermo["v1"][-1]), 1e-12)  # at rest (one step slows it by 7e-5)
        self.assertAlmostEqual(travelled, expected, delta=1e-3)  # measured 5.3e-4
        self.assertAlmostEqual(thermo["v1"][14], v_at_7, delta=2e-4)  # measured 7.1e-5


class WallFriction(DeckTestCase):
    # The same launch (v0 = 1) stops after v0²/(2 μ g) with the floor's μ: a wall takes the
    # grains' 'friction' whatever the keyword order, follows fix_modify friction, and keeps
    # its own 'wall_friction'.
    def stop(self, fix_line, before_run=""):
        made = grains_data("box 1.0 0.9 0.8", [(0, 0, 0.4, 1, 0, 0, 0)])
        self.assertRanCleanly(made)
        r = run(deck(f"""
fix             g all gravity {G} vector 0 0 -1
{fix_line}
timestep        1e-3
variable        x1 equal x[1]
thermo_style    custom step v_x1
thermo_modify   format float %.15g
thermo          100
run             0
{before_run}
velocity        all set 1.0 0 0
run             5000
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        return r.thermo()["x1"][-1]

    def test_order_and_fix_modify(self):
        cases = [("friction after the wall", "fix nscd all nscd/polyhedra tolerance 1e-8 wall 0 0 0 0 0 1 friction 0.25",
                  "", 0.25),
                 ("fix_modify friction", "fix nscd all nscd/polyhedra tolerance 1e-8 wall 0 0 0 0 0 1",
                  "fix_modify nscd friction 0.25", 0.25),
                 ("own wall_friction", "fix nscd all nscd/polyhedra tolerance 1e-8 wall 0 0 0 0 0 1 wall_friction 0.5",
                  "fix_modify nscd friction 0.25", 0.5)]
        for name, fix_line, before_run, mu in cases:
            travelled = self.stop(fix_line, before_run)
            # the θ = 1 scheme's distance (Launch): v0²/(2 μ g) − h v0/2. The velocity is set
            # between runs (after `run 0`): the second run starts from it as the first run
            # would (guards against + h v0/2: the set velocity moved with for one step)
            h, v0, decel = 1e-3, 1.0, mu * G
            steps = round(v0 / (decel * h))
            discrete = h * sum(v0 - k * decel * h for k in range(1, steps + 1))
            print(f"{name}: stopped after {travelled:.12f}, v0^2/(2 mu g) = {1 / (2 * mu * G):.6f}, "
                  f"the scheme's {discrete:.12f}")
            self.assertAlmostEqual(travelled, discrete, delta=1e-9, msg=name)


class TallStack(DeckTestCase):
    # 20 unit cubes (density 1: m = 1) stacked on a frictional floor, at rest, g = 1, 500
    # steps. Statics: the floor carries 20 m g, and every cube stays where it is (top
    # centre at 19.5). With the fix's defaults (method subspace, tolerance 1e-4) the floor
    # force is 20 to 1e-10 on every printed step and the top cube moves less than 1e-9;
    # method gauss_seidel hits the sweep cap on nearly every step (the comparison is printed).
    def stack(self, solver):
        made = cube_stack(self, 20)
        r = run(deck(f"""
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra {solver} wall 0 0 0 0 0 1
timestep        1e-3
variable        ztop equal bound(all,zmax)
thermo_style    custom step f_nscd[9] f_nscd[1] f_nscd[6] v_ztop f_nscd[13] f_nscd[14]
thermo_modify   format float %.15g
thermo          50
run             500
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        return r.thermo()

    def test_floor_carries_the_stack(self):
        t = self.stack("")
        plain = self.stack("method gauss_seidel")
        floor, top = -t["nscd[9]"], t["ztop"]
        print(f"20-cube stack, subspace: floor force {floor[-1]:.12f} (20), top moved {abs(top[-1] - 19.5):.1e}, "
              f"sweeps {t['nscd[1]'][-1]:.0f}, capped steps {t['nscd[6]'][-1]:.0f}; gauss_seidel: floor force "
              f"{-plain['nscd[9]'][-1]:.6f}, top moved {abs(plain['ztop'][-1] - 19.5):.1e}, capped steps "
              f"{plain['nscd[6]'][-1]:.0f}")
        self.assertLess(np.max(np.abs(floor[1:] - 20.0)), 1e-10)
        self.assertLess(np.max(np.abs(top - 19.5)), 1e-9)
        self.assertEqual(t["nscd[6]"][-1], 0)
        self.assertGreater(plain["nscd[6]"][-1], 0)
        # stick solves tried / kept (f_ID[6+3W+4], [6+3W+5]): at least one per step with
        # the default method (the closing one), none with gauss_seidel
        self.assertGreaterEqual(t["nscd[13]"][-1], 500)
        self.assertGreater(t["nscd[14]"][-1], 0)
        self.assertLessEqual(t["nscd[14]"][-1], t["nscd[13]"][-1])
        self.assertEqual(plain["nscd[13]"][-1], 0)


class ColouredOrder(DeckTestCase):
    # The 20-cube stack with `order coloured` (colour by colour of the contact graph): each
    # inner cube has 8 contact points (4 below, 4 above), so no colouring has fewer than 8
    # colours, and the greedy one from the top down has 8 (the first interface 0-3, the next
    # 4-7, the next 0-3 again, ...; the floor's points touch one cube only): 8 colours per
    # solve on every step (f_ID[30+3W+4P], summed over the solves). The stack is carried
    # as with the forward order: the floor force 20 to 1e-10, the top cube still.
    def test_stack_coloured(self):
        made = cube_stack(self, 20)
        r = run(deck("""
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra order coloured wall 0 0 0 0 0 1
timestep        1e-3
variable        ztop equal bound(all,zmax)
thermo_style    custom step f_nscd[9] f_nscd[6] v_ztop f_nscd[28] f_nscd[33]
thermo_modify   format float %.15g
thermo          1
run             50
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        t = r.thermo()
        colours = np.diff(t["nscd[33]"]) / np.diff(t["nscd[28]"])
        print(f"20-cube stack, order coloured: colours per solve {sorted(set(colours))}, floor force "
              f"{-t['nscd[9]'][-1]:.12f} (20), top moved {np.max(np.abs(t['ztop'] - 19.5)):.1e}")
        np.testing.assert_array_equal(colours, 8.0)
        self.assertLess(np.max(np.abs(-t["nscd[9]"][1:] - 20.0)), 1e-10)
        self.assertLess(np.max(np.abs(t["ztop"] - 19.5)), 1e-9)
        self.assertEqual(t["nscd[6]"][-1], 0)


class Corner(DeckTestCase):
    # A cube in the corner of a floor and a frictionless wall, pushed into it by a tilted
    # gravity. Frictionless floor: floor force m g cos α, wall force m g sin α exactly.
    # Frictional floor (μ = 0.5): floor friction may share the horizontal load (statically
    # indeterminate), but the resultants balance gravity; steady, no blow-up.
    def forces(self, floor_friction):
        made = grains_data("cube 1.0", [(0.5, 0, 0.5, 1, 0, 0, 0)])
        self.assertRanCleanly(made)
        r = run(deck(f"""
fix             g all gravity {G} vector {-math.sin(self.ALPHA)!r} 0 {-math.cos(self.ALPHA)!r}
fix             nscd all nscd/polyhedra tolerance 1e-9 wall 0 0 0 0 0 1 wall_friction {floor_friction} wall 0 0 0 1 0 0 wall_friction 0
timestep        1e-3
thermo_style    custom step f_nscd[7] f_nscd[9] f_nscd[10] f_nscd[12] f_nscd[4]
thermo_modify   format float %.15g
thermo          100
run             2000
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        t = r.thermo()
        return -t["nscd[7]"], -t["nscd[9]"], -t["nscd[10]"]

    ALPHA = 0.3

    def test_resultants(self):
        c, s = math.cos(self.ALPHA), math.sin(self.ALPHA)
        floor_x, floor_z, wall_x = self.forces(0.0)
        print(f"corner, frictionless: floor {floor_z[-1]:.12f} (cos {c:.12f}), wall {wall_x[-1]:.12f} (sin {s:.12f})")
        self.assertLess(np.max(np.abs(floor_z - c)), 1e-6)
        self.assertLess(np.max(np.abs(wall_x - s)), 1e-6)
        floor_x, floor_z, wall_x = self.forces(0.5)
        print(f"corner, floor mu 0.5: floor z {floor_z[-1]:.12f}, wall {wall_x[-1]:.6f} + floor friction {floor_x[-1]:.6f}")
        self.assertLess(np.max(np.abs(floor_z - c)), 1e-6)
        self.assertLess(np.max(np.abs(wall_x + floor_x - s)), 1e-6)


class MovingWall(DeckTestCase):
    # A box pressed by a sideways gravity against a frictionless wall moving away at 0.1
    # (and resting on a frictionless floor) follows the wall exactly: x = 0.5 + 0.1 t.
    def test_grain_follows_moving_wall(self):
        made = grains_data("box 1.0 0.9 0.8", [(0.5, 0, 0.4, 1, 0, 0, 0)])
        self.assertRanCleanly(made)
        r = run(deck("""
fix             g all gravity 1.0 vector -0.6 0 -0.8
fix             nscd all nscd/polyhedra friction 0 tolerance 1e-9 wall 0 0 0 0 0 1 wall 0 0 0 1 0 0 wall_velocity 0.1 0 0
timestep        1e-3
variable        x1 equal x[1]
thermo_style    custom step time v_x1 f_nscd[10]
thermo_modify   format float %.15g
thermo          100
run             2000
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        t = r.thermo()
        lag = np.max(np.abs(t["x1"] - (0.5 + 0.1 * t["Time"])))
        print(f"moving nscd wall: largest |x - (0.5 + 0.1 t)| = {lag:.2e}, wall force {-t['nscd[10]'][-1]:.6f} "
              f"(m g sin = {0.72 * 1.0 * 0.6:.6f})")
        self.assertLess(lag, 1e-10)
        self.assertAlmostEqual(-t["nscd[10]"][-1], 0.72 * 0.6, delta=1e-6)


class ThetaMethod(DeckTestCase):
    # Free fall from rest, h = 1e-2, 100 steps: positions x += h((1 − θ) v_n + θ v_{n+1}).
    # θ = 1/2 (trapezoid) is exact for constant g: z = z0 − g t²/2; θ = 1 lags by g h t / 2.
    def fall(self, theta):
        made = grains_data("box 1.0 0.9 0.8", [(0, 0, 10.0, 1, 0, 0, 0)])
        self.assertRanCleanly(made)
        r = run(deck(f"""
fix             g all gravity {G} vector 0 0 -1
fix             nscd all nscd/polyhedra theta {theta} wall 0 0 0 0 0 1
timestep        1e-2
variable        z1 equal z[1]
thermo_style    custom step time v_z1
thermo_modify   format float %.15g
thermo          10
run             100
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        t = r.thermo()
        return t["Time"], t["z1"] - (10.0 - 0.5 * G * t["Time"] ** 2)

    def test_free_fall(self):
        time, half = self.fall(0.5)
        time, one = self.fall(1.0)
        lag = np.max(np.abs(one + 0.5 * G * 1e-2 * time))
        print(f"free fall: theta 1/2 error {np.max(np.abs(half)):.1e}; theta 1 error {one[-1]:.6f} at t = 1 "
              f"(-g h t / 2 = -0.005), deviation from it {lag:.1e}")
        self.assertLess(np.max(np.abs(half)), 1e-12)
        self.assertLess(lag, 1e-12)


class DampingAndOverlap(DeckTestCase):
    # damping γ (implicit): v_{k+1} = (v_k − g h)/(1 + h γ) in free fall, so the speed tends to
    # the terminal g/γ as 1 − (1 + hγ)^−k. overlap_recovery β: a cube started 0.01 into the
    # floor without gravity keeps (1 − β) of it after one step and none after two: the push-out
    # speed β·overlap/h is a real velocity (it stays with the grain).
    def test_terminal_velocity(self):
        made = grains_data("cube 1.0", [(0, 0, 50.0, 1, 0, 0, 0)])
        self.assertRanCleanly(made)
        r = run(deck("""
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra damping 2 wall 0 0 0 0 0 1
timestep        1e-2
variable        vz1 equal vz[1]
thermo_style    custom step v_vz1
thermo_modify   format float %.15g
thermo          100
run             300
fix_modify      nscd damping 0
run             100
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        t, after = r.thermo(0), r.thermo(1)
        expected = -0.5 * (1.0 - (1.0 + 2e-2) ** -(t["Step"] + 1))   # + 1: the setup solve
        error = np.max(np.abs(t["vz1"] - expected))
        free = after["vz1"][-1] - after["vz1"][0]
        print(f"damping 2: vz {t['vz1'][-1]:.12f} at step 300 (terminal -0.5), error {error:.1e}; "
              f"after fix_modify damping 0, 100 steps gain {free:.12f} (-g t = -1)")
        self.assertLess(error, 1e-12)
        self.assertAlmostEqual(free, -1.0, delta=1e-12)

    def test_damping_keeps_the_weight(self):
        # damping acts on motion only: a cube resting on the floor with damping 1000 (h γ = 1)
        # still presses with m g (the impulses see the damped mass (1 + h γ) m)
        made = grains_data("box 1.0 0.9 0.8", [(0, 0, 0.4, 1, 0, 0, 0)])
        self.assertRanCleanly(made)
        r = run(deck("""
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra damping 1000 tolerance 1e-12 wall 0 0 0 0 0 1
timestep        1e-3
thermo_style    custom step f_nscd[9]
thermo_modify   format float %.15g
thermo          10
run             50
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        floor = -r.thermo()["nscd[9]"]
        print(f"damping 1000, resting box (m g = 0.72): floor force {floor[-1]:.15f}")
        self.assertLess(np.max(np.abs(floor - 0.72)), 1e-12)

    def test_overlap_recovery(self):
        made = grains_data("cube 1.0", [(0, 0, 0.49, 1, 0, 0, 0)])
        self.assertRanCleanly(made)
        r = run(deck("""
fix             nscd all nscd/polyhedra overlap_recovery 0.5 overlap_speed 1e9 tolerance 1e-12 project 0 &
                wall 0 0 0 0 0 1
timestep        1e-3
variable        vz1 equal vz[1]
thermo_style    custom step f_nscd[4] v_vz1
thermo_modify   format float %.15g
thermo          1
run             3
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        t = r.thermo()
        print(f"overlap_recovery 0.5: overlaps {t['nscd[4]']} (0.01, 0.005, 0, 0); vz {t['vz1'][-1]:.12f} "
              f"(the recovery speed 0.5 * 0.01 / h = 5 is kept: no gravity)")
        self.assertLess(np.max(np.abs(t["nscd[4]"] - [0.01, 0.005, 0, 0])), 1e-12)
        self.assertLess(np.max(np.abs(t["vz1"] - 5.0)), 1e-9)

    def cube_sunk_into_the_floor(self, options, columns, every, steps):
        # a unit cube created 0.05 into the floor, no gravity: thermo of its overlap and vz
        # (and `columns`) under fix nscd/polyhedra tolerance 1e-12 `options`
        made = grains_data("cube 1.0", [(0, 0, 0.45, 1, 0, 0, 0)])
        self.assertRanCleanly(made)
        r = run(deck(f"""
fix             nscd all nscd/polyhedra tolerance 1e-12 {options} wall 0 0 0 0 0 1
timestep        1e-3
variable        vz1 equal vz[1]
variable        z1 equal z[1]
thermo_style    custom step f_nscd[4] v_vz1 {columns}
thermo_modify   format float %.15g
thermo          {every}
run             {steps}
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        return r.thermo()

    def test_overlap_speed(self):
        # the default push-out speed cap 0.1 with overlap_recovery 1 (off by default): a
        # cube created 0.05 into the floor leaves at 0.1 (not 0.05 / h = 50) and is out
        # after 0.5 time units; then it rests (no gravity: at 0.1) (the
        # projection off: it would remove the overlap at the first solve, next test)
        t = self.cube_sunk_into_the_floor("project 0 overlap_recovery 1", "", every=100, steps=600)
        print(f"overlap_speed 0.1: overlaps {t['nscd[4]']}, vz {t['vz1'][-1]:.12f}")
        self.assertLess(np.max(np.abs(t["nscd[4]"][:6] - (0.05 - 0.1 * 1e-3 * t["Step"][:6]))), 1e-12)
        self.assertLess(t["nscd[4]"][-1], 1e-15)
        self.assertLess(np.max(np.abs(t["vz1"] - 0.1)), 1e-12)

    def test_projection_moves_the_pose_not_the_velocity(self):
        # project (default 5e-5 of the pair's size): the same cube, 0.05 into the floor, is
        # lifted at the end of the first solve to half the tolerance inside (the gap of a
        # flat face is linear in the height: one pass), so the second step starts with an
        # overlap of ½ 5e-5 (√3/2) = 2.17e-5; with overlap_recovery 0 (the default)
        # nothing else moves it: the pose is corrected, the velocity stays 0
        t = self.cube_sunk_into_the_floor("", "v_z1 f_nscd[17] f_nscd[18]", every=1, steps=3)
        size = 3 ** 0.5 / 2
        print(f"project 5e-5: overlaps {t['nscd[4]']}, z {t['z1']}, vz {t['vz1']}, corrections {t['nscd[17]']}")
        self.assertAlmostEqual(t["nscd[4]"][0], 0.05, delta=1e-15)
        self.assertAlmostEqual(t["nscd[18]"][0], 0.05 / size, delta=1e-12)  # found at the first solve
        self.assertAlmostEqual(t["nscd[4]"][1], 0.5 * 5e-5 * size, delta=1e-12)
        self.assertAlmostEqual(t["z1"][1], 0.5 - 0.5 * 5e-5 * size, delta=1e-12)
        self.assertLess(np.max(np.abs(t["vz1"])), 1e-12)  # overlap_recovery 0: no push-out speed at all
        self.assertEqual(t["nscd[17]"][-1], 1)  # one correction in all


class WriteProblems(DeckTestCase):
    # A unit cube (m = 1, I = 1/6) resting on the floor: 4 contact points at its bottom
    # corners; the written problem has q_n = −g h (free velocity, zero gap) and the
    # Delassus diagonal W_nn = 1/m + |r × n|² / I = 1 + 0.5 · 6 = 4 for each corner.
    def test_written_problem(self):
        made = grains_data("cube 1.0", [(0, 0, 0.5, 1, 0, 0, 0)])
        self.assertRanCleanly(made)
        r = run(deck("""
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra tolerance 1e-12 write_problems 2 problem_*.txt wall 0 0 0 0 0 1
timestep        1e-3
run             3
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        for step in (0, 2):
            with open(r.path(f"problem_{step}.txt")) as f:
                lines = f.read().splitlines()
            self.assertEqual(lines[0], "wiregrain_reduced_problem 1")
            self.assertEqual(lines[2], "contacts 4 blocks 16")
            q = np.array([[float(w) for w in line.split()] for line in lines[9:13]])
            diagonal = [float(line.split()[2]) for line in lines[14:30] if line.split()[0] == line.split()[1]]
            print(f"problem of step {step}: q_n {q[:, 0]}, W_nn {diagonal}")
            self.assertLess(np.max(np.abs(q[:, 0] + 1e-3)), 1e-15)
            self.assertLess(np.max(np.abs(q[:, 1:])), 1e-15)
            self.assertLess(np.max(np.abs(np.array(diagonal) - 4.0)), 1e-12)
        self.assertFalse(os.path.exists(r.path("problem_1.txt")))


def heap_of_30():
    """grains.data and grains.shapes of 30 random grains in a 6 x 6 x 7 region of an
    8 x 8 x 12 box (the decks of RanksAndRestart and PairReuse)."""
    return run("""
units lj
atom_style polyhedron
atom_modify map array sort 0 0.0
boundary f f f
region box block -4 4 -4 4 0 12
create_box 1 box
region fill block -3 3 -3 3 1 8
create_grains 1 30 random fill seed 11
write_data grains.data
grain_shapes write grains.shapes
""")


class RanksAndRestart(DeckTestCase):
    # A small heap of random grains, solve replicated: 1 and 2 ranks give the same state (the
    # default on 2 ranks, solve distributed, agrees within the solver's tolerance:
    # test_distributed.py), a restart (with the
    # warm-start impulses and the stick-solve backoff) reproduces the straight run. The
    # restart comes at t = 1.2, when the heap has settled and its stick solves are being
    # skipped: without the backoff in the restart file the runs differed by 2.9e-11. With
    # rolling_friction the restart file carries the warm-start couples too. The pair cache
    # (with warm_geometry yes, its pairs' GJK simplices) is in the restart file: without it
    # the runs with warm_geometry differed by 8.0e-12 (1.8e-10 with rolling_friction).
    BODY = """
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra tolerance 1e-6 solve replicated EXTRA wall 0 0 0 0 0 1 wall -4 0 0 1 0 0 wall_friction 0 wall 4 0 0 -1 0 0 wall_friction 0 wall 0 -4 0 0 1 0 wall_friction 0 wall 0 4 0 0 -1 0 wall_friction 0
timestep        1e-3
dump            d all custom 100 dump.h id x y z vx vy vz omegax omegay omegaz
"""

    def test_same_state(self):
        self.check_same_state("")

    def test_same_state_with_warm_geometry(self):
        self.check_same_state("warm_geometry yes")

    def test_same_state_with_rolling_friction_and_warm_geometry(self):
        self.check_same_state("rolling_friction 0.2 warm_geometry yes")

    def check_same_state(self, extra):
        made = heap_of_30()
        self.assertRanCleanly(made)
        body = self.BODY.replace("EXTRA", extra)
        text = full_precision(deck(body), "d")
        one = run(text + "run 2400\n", workdir=made.workdir)
        a = read_dump(made.path("dump.h"))
        two = run(text.replace("dump.h", "dump2.h") + "run 2400\n", workdir=made.workdir, np_ranks=2)
        # detection shared (the default: each rank a block of the pairs) or replicated
        two_replicated = run(text.replace("dump.h", "dump5.h").replace("tolerance 1e-6", "tolerance 1e-6 detection replicated")
                             + "run 2400\n", workdir=made.workdir, np_ranks=2)
        half = run(text.replace("dump.h", "dump3.h") + "run 1200\nwrite_restart heap.restart\n", workdir=made.workdir)
        for r in (one, two, two_replicated, half):
            self.assertRanCleanly(r)
        rest = run(full_precision(restarted("heap.restart") + body.replace("dump.h", "dump4.h") + "run 1200\n", "d"), workdir=made.workdir)
        self.assertRanCleanly(rest)
        b, c = read_dump(made.path("dump2.h")), read_dump(made.path("dump4.h"))
        cols = ("x", "y", "z", "vx", "vy", "vz", "omegax", "omegay", "omegaz")
        ranks = max(np.max(np.abs(a[k] - b[k])) for k in cols)
        restart = max(np.max(np.abs(a[k] - c[k])) for k in cols)
        e = read_dump(made.path("dump5.h"))
        replicated = max(np.max(np.abs(a[k] - e[k])) for k in cols)
        print(f"heap of 30 ({extra or 'defaults'}): 1 vs 2 ranks {ranks:.2e} (detection replicated {replicated:.2e}), restart vs straight {restart:.2e}")
        self.assertLess(ranks, 1e-12)
        self.assertLess(replicated, 1e-12)
        self.assertLess(restart, 1e-12)


class PairReuse(DeckTestCase):
    # keyword skin: the grain pairs kept between steps while no grain moved more than the
    # skin allows (core/nscd/grain_pairs.h); every pair within the activation distance is
    # among them, visited in the same order, and a kept pair is skipped only while its gap
    # minus how far its grains moved stays beyond the activation distance, so a pour into
    # a box follows the trajectory of a search every step (skin 0) to the last bit, with 1
    # or 2 ranks (solve replicated; warm_geometry no, the default: with yes the cached pairs' GJK starts from
    # their last simplex, the same to GJK's tolerance, not to the bit; RanksAndRestart)
    def test_pour_follows_the_full_search_to_the_bit(self):
        made = heap_of_30()
        self.assertRanCleanly(made)
        body = RanksAndRestart.BODY.replace("EXTRA", "") + """
thermo_style    custom step f_nscd[3] f_nscd[27] f_nscd[28] f_nscd[39]
thermo          1500
run             1500
"""
        states, counts = {}, {}
        for skin, ranks in ((0, 1), (0.1, 1), (0.5, 2)):
            text = full_precision(deck(body.replace("tolerance 1e-6", f"tolerance 1e-6 skin {skin} warm_geometry no")
                                       .replace("dump.h", f"dump_{skin}.h")), "d")
            r = run(text, workdir=made.workdir, np_ranks=ranks)
            self.assertRanCleanly(r)
            states[skin] = read_dump(made.path(f"dump_{skin}.h"))
            t = r.thermo()
            counts[skin] = (t["nscd[27]"][-1], t["nscd[28]"][-1], t["nscd[39]"][-1])
        print(f"\nskin 0.1: {counts[0.1][0]:.0f} searches, {counts[0.1][1]:.0f} reuses, {counts[0.1][2]:.0f} kept "
              f"pairs skipped; skin 0.5 (2 ranks): {counts[0.5][0]:.0f}, {counts[0.5][1]:.0f}, {counts[0.5][2]:.0f}")
        for skin in (0.1, 0.5):
            for column in ("x", "y", "z", "vx", "vy", "vz", "omegax", "omegay", "omegaz"):
                np.testing.assert_array_equal(states[skin][column], states[0][column], err_msg=f"skin {skin} {column}")
            self.assertGreater(counts[skin][1], counts[skin][0])  # mostly reused
            self.assertGreater(counts[skin][2], counts[skin][1])  # more than one kept pair apart per reuse
        self.assertEqual(counts[0], (0, 0, 0))


class Sleeping(DeckTestCase):
    # keyword sleep v_sleep t_sleep (core/nscd/grain_step.h, "Sleeping"): two stacks of
    # three unit cubes (m = 1, one stack per rank with 2 ranks) fall asleep after t_sleep
    # (nothing solved, the 20 contact points frozen) and the floor still carries 6 m g. The
    # top cube of one stack given vz = -1 wakes (a set velocity); a perfectly inelastic
    # impact on a stack standing on the floor moves none of it, so the cubes under it stay
    # asleep and carry it (their equilibrium checks); the top cube comes back to rest and
    # sleeps, and the floor carries 6 m g again (statics, to the solver's tolerance). 1 vs 2 ranks and a restart taken with
    # one stack asleep and the other not yet (per-grain sleep state and frozen contacts in
    # the restart file) to the bit.
    V_SLEEP, T_SLEEP = 2e-3, 0.2
    BODY = f"""
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra tolerance 1e-10 sleep {V_SLEEP} {T_SLEEP} wall 0 0 0 0 0 1
timestep        1e-3
dump            d all custom 100 dump.h id x y z vx vy vz omegax omegay omegaz
variable        floor equal -f_nscd[9]
thermo_style    custom step v_floor f_nscd[3] f_nscd[19] f_nscd[20] f_nscd[21]
thermo_modify   format float %.17g
thermo          10
"""
    KICK = "set atom 3 vz -1.0\nrun 600\n"

    def test_stacks_sleep_wake_and_carry_their_weight(self):
        made = grains_data("cube 1.0", [(x, 0, 0.5 + k, 1, 0, 0, 0) for x in (-0.6, 0.6) for k in range(3)])
        self.assertRanCleanly(made)
        text = full_precision(deck(self.BODY), "d")
        one = run(text + "run 300\n" + self.KICK, workdir=made.workdir)
        two = run(text.replace("dump.h", "dump2.h") + "run 300\n" + self.KICK, workdir=made.workdir, np_ranks=2)
        half = run(text.replace("dump.h", "dump3.h") + "run 300\nset atom 3 vz -1.0\nrun 150\nwrite_restart stacks.restart\n",
                   workdir=made.workdir)
        for r in (one, two, half):
            self.assertRanCleanly(r)
        rest = run(full_precision(restarted("stacks.restart") + self.BODY.replace("dump.h", "dump4.h") + "run 450\n", "d"), workdir=made.workdir)
        self.assertRanCleanly(rest)
        settled, kicked = one.thermo(0), one.thermo(-1)  # the runs before and after the kick
        weight = 6 * G
        woken = kicked["nscd[20]"]
        print(f"\nstacks at step 300: {settled['nscd[19]'][-1]:.0f} asleep, {settled['nscd[3]'][-1]:.0f} points "
              f"solved, {settled['nscd[21]'][-1]:.0f} frozen, floor {settled['floor'][-1]:.15f}; after the kick "
              f"{woken.sum():.0f} wake-ups seen, fewest asleep {kicked['nscd[19]'].min():.0f}, at the end "
              f"{kicked['nscd[19]'][-1]:.0f}, floor {kicked['floor'][-1]:.15f}")
        self.assertEqual(settled["nscd[19]"][-1], 6)
        self.assertEqual(settled["nscd[3]"][-1], 0)
        self.assertEqual(settled["nscd[21]"][-1], 24)  # 4 corners at 3 faces (floor included) per stack
        self.assertLess(abs(settled["floor"][-1] - weight), 1e-8)
        self.assertEqual(kicked["nscd[19]"].min(), 5)  # only the kicked cube woke
        self.assertEqual(kicked["nscd[19]"][-1], 6)
        self.assertLess(abs(kicked["floor"][-1] - weight), 1e-8)
        a, b, c = (read_dump(made.path(f)) for f in ("dump.h", "dump2.h", "dump4.h"))
        for column in ("x", "y", "z", "vx", "vy", "vz", "omegax", "omegay", "omegaz"):
            np.testing.assert_array_equal(b[column], a[column], err_msg=f"2 ranks {column}")
            np.testing.assert_array_equal(c[column], a[column], err_msg=f"restart {column}")


class IterationCap(DeckTestCase):
    # A cap of 1 sweep from zero impulses (no warm start) on a 5-cube stack at tolerance
    # 1e-15: every step hits it; the first 10 are named in warnings, all are counted in
    # f_ID[6].
    def test_cap_warnings(self):
        made = cube_stack(self, 5)
        r = run(deck("""
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra tolerance 1e-15 max_iterations 1 warm_start no wall 0 0 0 0 0 1
timestep        1e-3
thermo_style    custom step f_nscd[6]
thermo          50
run             50
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        named = r.output.count("hit the iteration cap 1, residual")
        counted = r.thermo()["nscd[6]"][-1]
        print(f"iteration cap: {named} warnings, {counted:.0f} steps counted")
        self.assertEqual(named, 10)
        self.assertIn("further steps that hit the iteration cap are only counted (f_nscd[6])", r.output)
        self.assertEqual(counted, 51)                 # the setup solve and 50 steps


class Every(DeckTestCase):
    # every N: one solve with h = N dt every N steps, the grains move once per solve and are
    # held in between. 50 steps of dt with every 5 are 10 steps of 5 dt.
    def fall(self, every, dt, steps, thermo):
        made = grains_data("box 1.0 0.9 0.8", [(0, 0, 10.0, 1, 0, 0, 0)])
        self.assertRanCleanly(made)
        r = run(deck(f"""
fix             g all gravity {G} vector 0 0 -1
fix             nscd all nscd/polyhedra every {every} wall 0 0 0 0 0 1
velocity        all set 0.3 -0.2 0.5
timestep        {dt}
variable        x1 equal x[1]
variable        y1 equal y[1]
variable        z1 equal z[1]
thermo_style    custom step v_x1 v_y1 v_z1
thermo_modify   format float %.17g
thermo          {thermo}
run             {steps}
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        return r.thermo()

    def test_free_fall_every_5(self):
        every = self.fall(5, 1e-3, 50, 1)
        once = self.fall(1, 5e-3, 10, 1)
        end = np.array([every[k][-1] for k in ("x1", "y1", "z1")])
        expected = np.array([once[k][-1] for k in ("x1", "y1", "z1")])
        difference = np.max(np.abs(end - expected))
        # held between solves: the position changes only at the step after a solve (1, 6, 11, ...)
        moved = np.flatnonzero(np.diff(every["z1"]) != 0.0) + 1
        print(f"every 5 at dt vs every 1 at 5 dt: largest position difference {difference:.1e}; "
              f"moved at steps {every['Step'][moved][:4]}")
        self.assertLess(difference, 1e-12)
        np.testing.assert_array_equal(every["Step"][moved], np.arange(1, 50, 5))

    def test_resting_cube_every_5(self):
        made = grains_data("cube 1.0", [(0, 0, 0.5, 1, 0, 0, 0)])
        self.assertRanCleanly(made)
        r = run(deck(f"""
fix             g all gravity {G} vector 0 0 -1
fix             nscd all nscd/polyhedra every 5 tolerance 1e-12 wall 0 0 0 0 0 1
timestep        1e-3
variable        z1 equal z[1]
thermo_style    custom step f_nscd[9] v_z1
thermo_modify   format float %.15g
thermo          5
run             50
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        t = r.thermo()
        print(f"every 5, resting cube (m g = 1): floor force {-t['nscd[9]'][-1]:.15f}, "
              f"z drift {np.max(np.abs(t['z1'] - 0.5)):.1e}")
        self.assertLess(np.max(np.abs(t["nscd[9]"] + 1.0)), 1e-9)
        self.assertLess(np.max(np.abs(t["z1"] - 0.5)), 1e-12)


class AtomsAfterRestart(DeckTestCase):
    # Grains created after read_restart have no restart record of the fix: they start from
    # their own state, as grains created between two runs of one deck do. Two grains created
    # at rest 10 above the floor at t0 do not move in their first step (no solve has given
    # them a velocity yet), then fall freely, θ = 1/2 being exact: z = z0 − g (t − t0 − h)²/2;
    # the restarted run equals the straight one.
    BODY = """
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra theta 0.5 wall 0 0 0 0 0 1
timestep        1e-2
"""
    CREATE_AND_RUN = """
region          high block -3 3 -3 3 9.5 10.5
create_grains   1 2 random high seed 5 shape cube 1.0
variable        z1 equal z[1]
variable        z2 equal z[2]
variable        z3 equal z[3]
thermo_style    custom step time v_z1 v_z2 v_z3
thermo_modify   format float %.15g
thermo          10
run             100
"""

    def test_created_grains_fall_freely(self):
        made = grains_data("cube 1.0", [(0, 0, 0.5, 1, 0, 0, 0)])
        self.assertRanCleanly(made)
        straight = run(deck(self.BODY + "run 20\n" + self.CREATE_AND_RUN), workdir=made.workdir)
        first = run(deck(self.BODY + "run 20\nwrite_restart one.restart\n"), workdir=made.workdir)
        restarted = run(f"""
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
read_restart    one.restart
{self.CREATE_AND_RUN.replace("run ", self.BODY + "run ")}
""", workdir=made.workdir)
        for r in (straight, first, restarted):
            self.assertRanCleanly(r)
        a, b = straight.thermo(), restarted.thermo()
        h = 1e-2
        fall = 0.5 * G * np.maximum(a["Time"] - a["Time"][0] - h, 0.0) ** 2
        errors = [np.max(np.abs(a[z] - (a[z][0] - fall))) for z in ("z2", "z3")]
        difference = max(np.max(np.abs(a[z] - b[z])) for z in ("z1", "z2", "z3"))
        print(f"grains created after a restart: free-fall error {max(errors):.1e}, restarted vs straight "
              f"{difference:.1e}, resting grain moved {np.max(np.abs(a['z1'] - 0.5)):.1e}")
        self.assertLess(max(errors), 1e-12)
        self.assertLess(difference, 1e-12)
        self.assertLess(np.max(np.abs(a["z1"] - 0.5)), 1e-6)

    def test_restart_without_atom_modify_map(self):
        # read_restart does not keep the atom map; atom_style polyhedron turns it on, so a
        # deck without atom_modify map continues the run. Guards against the fix finding
        # none of its grains when it hands back their velocities: a cube dropped 0.3 onto
        # the floor would keep the speed of the restart step (z 0.616 instead of 0.5 at the end).
        made = grains_data("cube 1.0", [(0, 0, 0.8, 1, 0, 0, 0)])
        self.assertRanCleanly(made)
        # the height by a compute (an indexed z[1] in a variable would need the map too)
        body = self.BODY + "compute z1 all reduce max z\nthermo_style custom step time c_z1\n" \
                           "thermo_modify format float %.15g\nthermo 10\n"
        straight = run(deck(body + "run 20\nrun 80\n"), workdir=made.workdir)
        first = run(deck(body + "run 20\nwrite_restart drop.restart\n"), workdir=made.workdir)
        restarted = run("units lj\nread_restart drop.restart\natom_modify sort 0 0.0\n" + body + "run 80\n",
                        workdir=made.workdir)
        for r in (straight, first, restarted):
            self.assertRanCleanly(r)
        a, b = straight.thermo(), restarted.thermo()
        # landed on the floor (half the cube's height, within the bounce θ = 1/2 leaves), not
        # fallen through it (z = 0.3 at the end)
        self.assertLess(abs(a["z1"][-1] - 0.5), 0.01)
        np.testing.assert_allclose(b["z1"], a["z1"][-len(b["z1"]):], rtol=0, atol=1e-12)


class LostGrain(DeckTestCase):
    # LIGGGHTS deletes a grain that leaves a fixed boundary and says nothing by default
    # (thermo_modify lost ignore); the fix names the loss in a warning, once per loss
    # (bench/stress_matrix.py found a grain leaving the open top of a box silently).
    def test_lost_grain_is_named(self):
        made = grains_data("cube 1.0", [(0, 0, 0.5, 1, 0, 0, 0), (3, 0, 0.5, 1, 0, 0, 0)])
        self.assertRanCleanly(made)
        r = run(deck("""
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra wall 0 0 0 0 0 1
set             atom 2 vz 200
timestep        1e-3
thermo_style    custom step atoms
thermo          100
run             400
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        warnings = [line for line in r.output.splitlines() if "grain(s) of the group lost" in line]
        print(f"lost grain: {warnings}")
        self.assertEqual(len(warnings), 1)
        self.assertRegex(warnings[0], r"^WARNING: fix nscd/polyhedra \(id nscd\): 1 grain\(s\) of the group lost "
                                      r"by step \d+, 1 left \(a grain outside a fixed boundary is deleted")
        self.assertEqual(r.thermo()["Atoms"][-1], 1)


class OverlapWarning(DeckTestCase):
    # An overlap at a step start beyond half the sweep radius r_p is named with h and the
    # fastest grain's speed, the first 10 times: a cube of sweep 0.1 created 0.06 into
    # the floor (no gravity) is pushed out at overlap_speed 0.1 (overlap_recovery 1), 1e-4 a
    # step, so it stays beyond 0.05 for 100 steps (the projection off: it would lift it at
    # the first solve).
    def test_overlap_is_named_ten_times(self):
        made = grains_data("cube 1.0", [(0, 0, 0.54, 1, 0, 0, 0)], sweep=0.1)
        self.assertRanCleanly(made)
        r = run(deck("""
fix             nscd all nscd/polyhedra project 0 overlap_recovery 1 wall 0 0 0 0 0 1
timestep        1e-3
thermo_style    custom step f_nscd[4]
thermo          1
run             20
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        found = warning_lines(r.output, "starts with an overlap")
        print("\n".join(found))
        head = "fix nscd/polyhedra (id nscd): step "
        self.assertEqual(found[0], head + "0 starts with an overlap of 0.06 = 0.6 r_p (beyond 0.5 r_p, r_p = 0.1): "
                                          "the step h = 0.001 moves the fastest grain (speed 0) h v = 0 r_p; use a "
                                          "smaller timestep")
        self.assertEqual(found[1], head + "1 starts with an overlap of 0.0599 = 0.599 r_p (beyond 0.5 r_p, "
                                          "r_p = 0.1): the step h = 0.001 moves the fastest grain (speed 0.1) "
                                          "h v = 0.001 r_p; use a smaller timestep")
        self.assertEqual(len(found), 10)
        self.assertTrue(found[9].startswith(head + "9 starts with an overlap of 0.0591 = 0.591 r_p"), found[9])
        self.assertTrue(found[9].endswith("; further large overlaps are not reported"), found[9])

    def test_sharp_grains_take_a_tenth_of_their_bounding_radius(self):
        # a sharp unit cube (bounding radius √3/2): the reference is 0.0866; created 0.05
        # into the floor: 0.577 of it
        made = grains_data("cube 1.0", [(0, 0, 0.45, 1, 0, 0, 0)])
        self.assertRanCleanly(made)
        r = run(deck("fix nscd all nscd/polyhedra wall 0 0 0 0 0 1\ntimestep 1e-3\nrun 0\n"), workdir=made.workdir)
        self.assertRanCleanly(r)
        self.assertEqual(warning_lines(r.output, "starts with an overlap"), [
            "fix nscd/polyhedra (id nscd): step 0 starts with an overlap of 0.05 = 0.577 r_p (beyond 0.5 r_p, "
            "r_p = 0.0866, for sharp grains a tenth of the bounding radius): the step h = 0.001 moves the fastest "
            "grain (speed 0) h v = 0 r_p; use a smaller timestep"])


class BadInput(DeckTestCase):
    def check(self, options, message):
        made = grains_data("cube 1.0", [(0, 0, 0.5, 1, 0, 0, 0)])
        self.assertStopsWith(run(deck(f"fix nscd all nscd/polyhedra {options}\nrun 1"), workdir=made.workdir), message)

    def test_non_finite_state(self):
        # the data reader refuses non-finite numbers (test_malformed_data_file); LIGGGHTS' set
        # does not (atof: 1e400 = inf)
        made = grains_data("cube 1.0", [(0, 0, 0.5, 1, 0, 0, 0), (3, 0, 0.5, 1, 0, 0, 0)])
        self.assertRanCleanly(made)
        self.assertStopsWith(run(deck("set atom 2 vx 1e400\nfix nscd all nscd/polyhedra wall 0 0 0 0 0 1\nrun 1"),
                                 workdir=made.workdir),
                             "fix nscd/polyhedra (id nscd): grain 2 has a non-finite velocity at step 0")

    def test_malformed_data_file(self):
        # non-finite and malformed numbers in the Atoms and Velocities sections of a grain data file
        def stops(section, column, word, message):
            made = grains_data("cube 1.0", [(0, 0, 0.5, 1, 0, 0, 0)])
            with open(made.path("grains.data")) as f:
                lines = f.read().splitlines()
            if section == "Velocities":
                lines += ["", "Velocities", "", "1 0 0 0 0 0 0"]
            k = next(i for i, line in enumerate(lines) if line.startswith(section)) + 2
            words = lines[k].split()
            words[column] = word
            lines[k] = " ".join(words)
            with open(made.path("grains.data"), "w") as f:
                f.write("\n".join(lines) + "\n")
            self.assertStopsWith(run(deck("run 0"), workdir=made.workdir), message)
        atoms = "atom_style polyhedron: Atoms section of data file: "
        stops("Atoms", 3, "inf", atoms + "density must be a finite number > 0, got 'inf'")
        stops("Atoms", 3, "1e400", atoms + "density must be a finite number > 0, got '1e400'")
        stops("Atoms", 4, "1.0x", atoms + "qw must be a finite number, got '1.0x'")
        stops("Atoms", 7, "nan", atoms + "qk must be a finite number, got 'nan'")
        velocities = "atom_style polyhedron: Velocities section of data file: "
        stops("Velocities", 2, "abc", velocities + "vy of atom 1 must be a finite number, got 'abc'")
        stops("Velocities", 6, "inf", velocities + "omegaz of atom 1 must be a finite number, got 'inf'")

    def test_messages(self):
        self.check("friction -0.1", "fix nscd/polyhedra (id nscd): value of 'friction' must be >= 0, got -0.1")
        self.check("tolerance -1e-4", "fix nscd/polyhedra (id nscd): value of 'tolerance' must be > 0, got -1e-4")
        self.check("max_iterations 0", "fix nscd/polyhedra (id nscd): value of 'max_iterations' must be >= 1, got 0")
        self.check("theta 0.4", "fix nscd/polyhedra (id nscd): value of 'theta' must be in [0.5, 1], got 0.4")
        self.check("overlap_recovery 2", "fix nscd/polyhedra (id nscd): value of 'overlap_recovery' must be in [0, 1], got 2")
        self.check("overlap_speed -1", "fix nscd/polyhedra (id nscd): value of 'overlap_speed' must be >= 0, got -1")
        self.check("damping -1", "fix nscd/polyhedra (id nscd): value of 'damping' must be >= 0, got -1")
        self.check("\nfix_modify nscd damping", "fix_modify nscd/polyhedra (id nscd): missing value after 'damping'")
        self.check("write_problems 10 problem.txt",
                   "fix nscd/polyhedra (id nscd): the file name of 'write_problems' must contain a '*' "
                   "(replaced by the step), got 'problem.txt'")
        self.check("write_problems 1 no_such_directory/p_*.txt",
                   "fix nscd/polyhedra (id nscd): cannot open 'no_such_directory/p_0.txt' for writing")
        self.check("write_problems 0 p_*.txt",
                   "fix nscd/polyhedra (id nscd): value of 'write_problems' (every N steps) must be >= 1, got 0")
        self.check("every 0", "fix nscd/polyhedra (id nscd): value of 'every' must be >= 1, got 0")
        self.check("project -1e-4", "fix nscd/polyhedra (id nscd): value of 'project' must be >= 0, got -1e-4")
        self.check("project", "fix nscd/polyhedra (id nscd): missing value after 'project'")
        self.check("project_passes 0", "fix nscd/polyhedra (id nscd): value of 'project_passes' must be >= 1, got 0")
        self.check("sleep -1e-3 0.5", "fix nscd/polyhedra (id nscd): value of 'sleep' must be >= 0, got -1e-3")
        self.check("sleep 1e-3 0", "fix nscd/polyhedra (id nscd): value of 'sleep' must be > 0, got 0")
        self.check("sleep 1e-3", "fix nscd/polyhedra (id nscd): missing value after 'sleep'")
        self.check("\nfix_modify nscd sleep 1e-3", "fix_modify nscd/polyhedra (id nscd): missing value after 'sleep'")
        self.check("restitution 1.5", "fix nscd/polyhedra (id nscd): value of 'restitution' must be in [0, 1], got 1.5")
        self.check("freeze -1", "fix nscd/polyhedra (id nscd): value of 'freeze' must be >= 0, got -1")
        self.check("freeze 5 convergence increment",
                   "fix nscd/polyhedra (id nscd): 'freeze' needs 'convergence natural_map' or 'convergence both'")
        self.check("order chaotic", "fix nscd/polyhedra (id nscd): value of 'order' must be forward, alternating, random or coloured")
        self.check("method newton", "fix nscd/polyhedra (id nscd): value of 'method' must be gauss_seidel or subspace, got 'newton'")
        self.check("subspace_regularization 1", "fix nscd/polyhedra (id nscd): value of 'subspace_regularization' must be in (0, 1), got 1 (")
        self.check("subspace_regularization 0", "fix nscd/polyhedra (id nscd): value of 'subspace_regularization' must be > 0, got 0")
        self.check("rolling_friction -0.1", "fix nscd/polyhedra (id nscd): value of 'rolling_friction' must be >= 0, got -0.1")
        self.check("rolling_friction 0.1 write_problems 1 p_*.txt",
                   "fix nscd/polyhedra (id nscd): 'write_problems' cannot carry 'rolling_friction' (a reduced FCLib problem has no rolling couples)")
        self.check("subspace_closing -0.1", "fix nscd/polyhedra (id nscd): value of 'subspace_closing' must be >= 0, got -0.1")
        self.check("subspace_closing 2", "fix nscd/polyhedra (id nscd): value of 'subspace_closing' must be in [0, 1], got 2")
        self.check("\nfix_modify nscd subspace_closing 2", "fix_modify nscd/polyhedra (id nscd): value of 'subspace_closing' must be in [0, 1], got 2")
        self.check("wall 0 0 0 0 0 0", "fix nscd/polyhedra (id nscd): wall 1: the normal (nx ny nz) must not be zero")
        self.check("\nfix twice all nve/polyhedron", "fix nscd/polyhedra (id nscd): 1 grains are also integrated by fix twice")
        wire = """
units lj
atom_style wire
boundary f f f
region box block -1 1 -1 1 -1 1
create_box 1 box
fix nscd all nscd/polyhedra
"""
        self.assertStopsWith(run(wire), "fix nscd/polyhedra (id nscd): needs atom_style polyhedron")


if __name__ == "__main__":
    main()
