"""Wire contacts (pair_style wire/contact, fix wire/wall, compute wire/contacts):
restitution, static and dynamic friction, a pile that must not pass through itself, and
the error messages."""

import math
import re

import numpy as np

from liggghts_run import (DeckTestCase, contact_overlap_warning, contact_time_step_warning, full_precision,
                          loaded_contact_measurement, main, read_dump, run, static_contact_measurement, warning_lines)

HEADER = """
units           lj
atom_style      wire
boundary        f f f
newton          off
region          box block -5 5 -5 5 -5 5
create_box      2 box
"""


# A wire coiled above a floor (loop of radius 1.5, pitch 0.3, segments 0.2), falling into a
# 4 x 4 box of frictionless side walls: the piles of Pile and PairCache. {top}: the box
# height, {turns}: the coil's turns, {pair}: pair_style options, {skin}: neighbour skin.
COIL = """
units           lj
atom_style      wire
boundary        f f f
newton          off
region          box block -3 3 -3 3 -1 {top}
create_box      1 box
create_wire     1 loop 0 0 {z0} 1.5 {turns} 0.3 segment 0.2
pair_style      wire/contact {pair}
pair_coeff      * *
neighbor        {skin} bin
fix             el all wire/elastic
fix             int all nve/gear forces velocity
fix             g all gravity 1.0 vector 0 0 -1
fix             floor all wire/wall plane 0 0 0 0 0 1
fix             w1 all wire/wall plane -2 0 0 1 0 0 mu_s 0 mu_d 0
fix             w2 all wire/wall plane 2 0 0 -1 0 0 mu_s 0 mu_d 0
fix             w3 all wire/wall plane 0 -2 0 0 1 0 mu_s 0 mu_d 0
fix             w4 all wire/wall plane 0 2 0 0 -1 0 mu_s 0 mu_d 0
timestep        1e-4
compute         c all wire/contacts
"""

def bead_mass(rho=0.5, r=0.1, l=0.2):
    return rho * math.pi * r * r * l


class Restitution(DeckTestCase):
    # Two one-segment wires crossing at right angles approach head-on; at the crossing the
    # force goes half to each bead, so each wire moves as a rigid body of mass 2m and the
    # pair is a linear spring-dashpot of effective mass m: e(ζ) = exp(−πζ/√(1−ζ²)).
    def measured(self, e_target):
        deck = HEADER + f"""
create_wire     1 line -0.1 0 0.101 0.1 0 0.101
create_wire     1 line 0 -0.1 -0.101 0 0.1 -0.101
group           upper id 1 2
group           lower id 3 4
velocity        upper set 0 0 -0.1
velocity        lower set 0 0 0.1
pair_style      wire/contact restitution {e_target} mu_s 0 mu_d 0
pair_coeff      * *
neighbor        0.1 bin
fix             el all wire/elastic
fix             int all nve/gear forces velocity
timestep        2e-5
compute         vu upper reduce ave vz
compute         vl lower reduce ave vz
compute         c all wire/contacts
thermo_style    custom step c_vu c_vl c_c[1]
thermo_modify   format float %.15g
thermo          100
run             10000
"""
        r = run(deck)
        self.assertRanCleanly(r)
        t = r.thermo()
        self.assertGreater(np.max(t["c[1]"]), 0)
        self.assertEqual(t["c[1]"][-1], 0)
        return (t["vu"][-1] - t["vl"][-1]) / 0.2

    def test_restitution_matches_damping_ratio(self):
        for e in (0.3, 0.5, 0.9):
            measured = self.measured(e)
            print(f"restitution: target {e}, measured {measured:.6f}")
            self.assertAlmostEqual(measured, e, delta=1e-3)


class Stiffness(DeckTestCase):
    # The contact stiffnesses of the paper (section 2.2), measured statically: two one-segment
    # wires crossed at right angles at a known overlap ξ (no velocity: no damping) push each
    # other with k_n ξ, k_n = E* l_w π/4, 1/E* = (1−ν_a²)/E_a + (1−ν_b²)/E_b (E_ww = E/2 for
    # one material); the upper wire then moved by δ along x at a constant speed and stopped
    # carries the tangential spring force k_t δ, k_t = E* r_w, below the slip limit μ_s k_n ξ.
    # A bead on a rigid wall: k_n = E/(1−ν²) l π/4, k_t = E/(1−ν²) r per bead.
    CROSSED = HEADER + """
fix             mE all property/global youngsModulus peratomtype {E1} {E2}
fix             mNu all property/global poissonsRatio peratomtype {nu1} {nu2}
create_wire     1 line -0.1 0 {z} 0.1 0 {z}
create_wire     2 line 0 -0.1 -{z} 0 0.1 -{z}
group           upper type 1
pair_style      wire/contact mu_s 0.5 mu_d 0.5
pair_coeff      * *
neighbor        0.1 bin
"""

    def test_wire_wire(self):
        r_w, l_w, xi, delta, steps = 0.1, 0.2, 1e-3, 4e-4, 100
        for E1, E2, nu1, nu2 in ((100.0, 100.0, 0.0, 0.0), (100.0, 300.0, 0.3, 0.2)):
            r = run(self.CROSSED.format(E1=E1, E2=E2, nu1=nu1, nu2=nu2, z=r_w - xi / 2) +
                    static_contact_measurement("upper", delta, steps))
            self.assertRanCleanly(r)
            t = r.thermo()
            E_star = 1.0 / ((1 - nu1 ** 2) / E1 + (1 - nu2 ** 2) / E2)
            k_n, k_t = E_star * l_w * math.pi / 4, E_star * r_w
            normal, tangential = t["f[3]"][0], -t["f[1]"][-1]
            print(f"crossed wires E {E1:g}/{E2:g} nu {nu1:g}/{nu2:g}: normal {normal:.12g} vs k_n xi "
                  f"{k_n * xi:.12g}; tangential {tangential:.12g} vs k_t delta {k_t * delta:.12g}")
            # measured 1.1e-15 / 1.8e-15 (one material), 8.9e-16 / 2.0e-15 (two)
            self.assertAlmostEqual(normal / (k_n * xi), 1.0, delta=2e-14)
            self.assertLess(k_t * delta, 0.5 * k_n * xi)  # below the slip limit
            self.assertAlmostEqual(tangential / (k_t * delta), 1.0, delta=2e-14)

    def test_wire_wire_beside_a_grain(self):
        # The same crossed wires (two wire types) in atom_style hybrid polyhedron wire with a
        # grain 2 a_max above them: the same k_n ξ, and the neighbour list holds the 6 pairs
        # of the 4 beads only. A type without wire segments gets the cutoff 0: before, every
        # type pair had twice the largest radius of any atom (the grain's) and the list held
        # the grain's 4 pairs with the beads as well.
        r_w, l_w, xi = 0.1, 0.2, 1e-3
        deck = f"""
units           lj
atom_style      hybrid polyhedron wire
atom_modify     map array sort 0 0.0
boundary        f f f
newton          off
region          box block -5 5 -5 5 -5 5
create_box      3 box
fix             mE all property/global youngsModulus peratomtype 1000 100 100
fix             mNu all property/global poissonsRatio peratomtype 0.3 0 0
region          spot block -0.01 0.01 -0.01 0.01 1.99 2.01
create_grains   1 1 random spot seed 5
create_wire     2 line -0.1 0 {r_w - xi / 2} 0.1 0 {r_w - xi / 2}
create_wire     3 line 0 -0.1 -{r_w - xi / 2} 0 0.1 -{r_w - xi / 2}
group           upper type 2
pair_style      wire/contact mu_s 0.5 mu_d 0.5
pair_coeff      * *
neighbor        0.1 bin
""" + static_contact_measurement("upper", 4e-4, 10)
        r = run(deck)
        self.assertRanCleanly(r)
        k_n = 50.0 * l_w * math.pi / 4  # E* = E_w / 2 for one material
        self.assertAlmostEqual(r.thermo()["f[3]"][0] / (k_n * xi), 1.0, delta=2e-14)
        self.assertEqual(re.findall(r"Total # of neighbors = (\d+)", r.output)[-1], "6")

    def test_wall(self):
        r_w, l_w, xi, delta, steps, E, nu = 0.1, 0.2, 1e-3, 4e-4, 100, 100.0, 0.3
        r = run(HEADER + f"""
create_wire     1 line -0.1 0 {r_w - xi!r} 0.1 0 {r_w - xi!r}
fix             wall all wire/wall plane 0 0 0 0 0 1 E {E} nu {nu} mu_s 0.5 mu_d 0.5
atom_modify     sort 0 0.0
""" + static_contact_measurement("all", delta, steps))
        self.assertRanCleanly(r)
        t = r.thermo()
        E_star = E / (1 - nu ** 2)
        k_n, k_t = E_star * l_w * math.pi / 4, E_star * r_w
        normal, tangential = t["f[3]"][0], -t["f[1]"][-1]
        print(f"wire on a wall: normal {normal:.12g} vs 2 k_n xi {2 * k_n * xi:.12g}; tangential {tangential:.12g} "
              f"vs 2 k_t delta {2 * k_t * delta:.12g}")
        self.assertAlmostEqual(normal / (2 * k_n * xi), 1.0, delta=2e-14)           # measured 8.9e-16
        self.assertAlmostEqual(tangential / (2 * k_t * delta), 1.0, delta=2e-14)    # measured 1.9e-15


class ContactsComputeOfAMixedGroup(DeckTestCase):
    def test_overlap_over_the_beads_radius(self):
        # compute wire/contacts on 'all' of atom_style hybrid wire sphere: two one-segment
        # wires (r_w = 0.1) crossed at the overlap ξ = 2e-3 and a sphere of radius 0.02 far
        # off. c_ID[3] is ξ / r_w = 0.02: the sphere's radius is no bead's (unfiltered: ξ / 0.02)
        xi = 2e-3
        r = run(f"""
units           lj
atom_style      hybrid wire sphere
atom_modify     map array sort 0 0.0
boundary        f f f
newton          off
region          box block -5 5 -5 5 -5 5
create_box      2 box
create_atoms    1 single 3 3 3
set             atom 1 diameter 0.04 density 1
create_wire     2 line -0.1 0 {0.1 - xi / 2} 0.1 0 {0.1 - xi / 2}
create_wire     2 line 0 -0.1 -{0.1 - xi / 2} 0 0.1 -{0.1 - xi / 2}
pair_style      wire/contact
pair_coeff      * *
neighbor        0.1 bin
compute         c all wire/contacts
thermo_style    custom step c_c[1] c_c[2] c_c[3]
thermo_modify   format float %.17g
run             0
""")
        self.assertRanCleanly(r)
        t = r.thermo()
        self.assertEqual(t["c[1]"][0], 1)
        # measured 1.7e-18 from ξ and 1.7e-17 from ξ / r_w (rounding of the coordinates)
        self.assertAlmostEqual(t["c[2]"][0], xi, delta=1e-17)
        self.assertAlmostEqual(t["c[3]"][0], xi / 0.1, delta=1e-16)


class StiffnessUnderLoad(DeckTestCase):
    # The same stiffnesses the other way round: beads pushed by a known constant force
    # (fix addforce) settle, damped by the contact's own dashpot only, at the overlap
    # ξ = F/k_n; a tangential force F_t below μ_s F added on top moves them by F_t/k_t.
    # The expected k_n, k_t are the formulas of docs/design.md, "The wire: bead chain with
    # soft contacts", of the input parameters.

    def settled(self, t0, t1, ids):
        """Positions (N x 3) at the start of thermo table t0 and the end of t0 and t1, and
        the largest speed at the end of t1."""
        first = np.array([[t0[f"{c}{k}"][0] for c in "xyz"] for k in ids])
        normal = np.array([[t0[f"{c}{k}"][-1] for c in "xyz"] for k in ids])
        both = np.array([[t1[f"{c}{k}"][-1] for c in "xyz"] for k in ids])
        speed = max(max(t0[f"s{k}"][-1], t1[f"s{k}"][-1]) for k in ids)
        return first, normal, both, speed

    def test_wall(self):
        # beads on a wall z = 0 of their own, read from a data file: a three-bead wire with
        # rest lengths 0.3 and 0.5 (its beads stand for l = 0.3, 0.5 and, the last one, its
        # previous segment's 0.5) and a lone bead (l = 2 r); no fix wire/elastic, so each
        # bead is a sphere of its own on the wall. k_n = E/(1−ν²) l π/4, k_t = E/(1−ν²) r.
        E, nu, dt, steps = 250.0, 0.3, 5e-4, 2000
        beads = [  # id prev next rest radius mass x y
            (1, 0, 2, 0.3, 0.08, 0.004, -1.0, 0.0),
            (2, 1, 3, 0.5, 0.08, 0.006, -0.7, 0.0),
            (3, 2, 0, 0.0, 0.08, 0.005, -0.2, 0.0),
            (4, 0, 0, 0.0, 0.05, 0.003, 1.0, 1.0)]
        rows = [f"{i} 1 {p} {n} {rest!r} {r!r} {m!r} {x!r} {y!r} {r!r}" for i, p, n, rest, r, m, x, y in beads]
        data = "\n".join(["beads on a wall", "", f"{len(rows)} atoms", "1 atom types", "-5 5 xlo xhi",
                          "-5 5 ylo yhi", "-5 5 zlo zhi", "", "Atoms", ""] + rows) + "\n"
        F, Ft = 0.02, 0.002                      # per bead; F_t = 0.1 F, well below μ_s F
        direction = np.array([0.6, 0.8, 0.0])
        ids = [b[0] for b in beads]
        r = run(f"""
units           lj
atom_style      wire
boundary        f f f
read_data       beads.data
atom_modify     sort 0 0.0
fix             wall all wire/wall plane 0 0 0 0 0 1 E {E} nu {nu} mu_s 0.5 mu_d 0.5 damping_ratio 1
fix             int all nve/gear forces velocity
""" + loaded_contact_measurement("all", ids, (0, 0, -F), tuple(Ft * direction), steps, dt),
                files={"beads.data": data})
        self.assertRanCleanly(r)
        first, normal, both, speed = self.settled(r.thermo(0), r.thermo(), ids)
        E_star = E / (1 - nu ** 2)
        radius = np.array([b[4] for b in beads])
        length = np.array([0.3, 0.5, 0.5, 2 * 0.05])
        k_n, k_t = E_star * length * math.pi / 4, E_star * radius
        xi = radius - normal[:, 2]                        # the wall is z = 0
        shift = both - normal
        err_n = xi / (F / k_n) - 1
        err_t = shift[:, :2] / (Ft * direction[:2] / k_t[:, None]) - 1
        print(f"\nwall under load: overlap / (F/k_n) - 1 = {err_n}, tangential shift / (F_t/k_t) - 1 = "
              f"{err_t.ravel()}, normal shift in stage 2 {np.max(np.abs(shift[:, 2])):.1e}, "
              f"largest speed at rest {speed:.1e}")
        np.testing.assert_allclose(first[:, 2], radius, rtol=0, atol=1e-15)   # started touching
        # measured: normal 5e-13, tangential 7e-11 (the round-off of x ~ 1 over the 2000
        # steps, against shifts of ~5e-5)
        self.assertLess(np.max(np.abs(err_n)), 1e-9)
        self.assertLess(np.max(np.abs(err_t)), 1e-9)

    def test_wire_wire(self):
        # a one-segment wire (l 0.3, r 0.08, type 1) lying across a held one (l 0.5, r 0.06,
        # type 2, not integrated) at their middles, both beads pushed down by F: the
        # contact carries 2F = k_n ξ, k_n = E* l̄ π/4 with l̄ = 0.4 the mean rest length,
        # E* = E/(2(1−ν²)) for one material, 1/E* = (1−ν_1²)/E_1 + (1−ν_2²)/E_2 for two;
        # then 2F_t along the held wire (so the load point stays in the middle of the upper
        # one) moves it by 2F_t/k_t, k_t = E* r̄, r̄ = 0.07 the mean radius. The dashpot
        # uses the reduced mass of the two segments, so the upper wire's motion is damped
        # at ζ √(m_B/(m_A + m_B)) ≈ 0.7 of the ζ = 1 given.
        dt, steps, F, Ft = 1e-3, 3000, 0.01, 0.001
        for E1, E2, nu1, nu2 in ((80.0, 80.0, 0.25, 0.25), (100.0, 300.0, 0.3, 0.2)):
            r = run(HEADER + f"""
fix             mE all property/global youngsModulus peratomtype {E1} {E2}
fix             mNu all property/global poissonsRatio peratomtype {nu1} {nu2}
create_wire     1 line -0.15 0 0.14 0.15 0 0.14 segment 0.3 radius 0.08
create_wire     2 line 0 -0.25 0 0 0.25 0 segment 0.5 radius 0.06
group           upper type 1
pair_style      wire/contact mu_s 0.5 mu_d 0.5 damping_ratio 1
pair_coeff      * *
neighbor        0.1 bin
fix             el all wire/elastic
fix             int upper nve/gear forces velocity
""" + loaded_contact_measurement("upper", [1, 2, 3, 4], (0, 0, -F), (0, Ft, 0), steps, dt))
            self.assertRanCleanly(r)
            first, normal, both, speed = self.settled(r.thermo(0), r.thermo(), [1, 2, 3, 4])
            if E1 == E2 and nu1 == nu2:
                E_star = E1 / (2 * (1 - nu1 ** 2))
            else:
                E_star = 1.0 / ((1 - nu1 ** 2) / E1 + (1 - nu2 ** 2) / E2)
            k_n, k_t = E_star * 0.4 * math.pi / 4, E_star * 0.07
            xi = 0.08 + 0.06 - (normal[:2, 2] - normal[2:, 2])
            shift = both[:2, 1] - normal[:2, 1]
            err_n = xi / (2 * F / k_n) - 1
            err_t = shift / (2 * Ft / k_t) - 1
            print(f"\nwires E {E1:g}/{E2:g} nu {nu1:g}/{nu2:g} under load: overlap / (2F/k_n) - 1 = {err_n}, "
                  f"shift / (2F_t/k_t) - 1 = {err_t}, held wire moved {np.max(np.abs(both[2:] - first[2:])):.1e}, "
                  f"largest speed at rest {speed:.1e}")
            self.assertEqual(np.max(np.abs(both[2:] - first[2:])), 0.0)
            self.assertLess(np.max(np.abs(err_n)), 1e-12)    # measured 1e-14, 5e-14
            self.assertLess(np.max(np.abs(err_t)), 1e-12)    # measured 5e-15, 7e-16


class Friction(DeckTestCase):
    # A straight 10-segment wire lying on a floor (μ_s = 0.6, μ_d = 0.4) under gravity g = 1.
    def floor_deck(self, extra, steps):
        return HEADER + f"""
create_wire     1 line -1 0 0.1 1 0 0.1
fix             el all wire/elastic
fix             int all nve/gear forces velocity
fix             g all gravity 1.0 vector 0 0 -1
fix             floor all wire/wall plane 0 0 0 0 0 1 mu_s 0.6 mu_d 0.4 restitution 0.1
timestep        1e-4
run             20000
{extra}
compute         vx all reduce ave vx
compute         x all reduce ave x
thermo_style    custom step time c_vx c_x f_floor[3] f_floor[5]
thermo_modify   format float %.15g
thermo          100
run             {steps}
"""

    def test_sliding_deceleration_is_mu_d_g(self):
        r = run(self.floor_deck("velocity all set 0.5 0 0 sum yes", 5000))
        self.assertRanCleanly(r)
        t = r.thermo()
        moving = t["vx"] > 0.05                     # while clearly sliding
        slope = np.polyfit(t["Time"][moving], t["vx"][moving], 1)[0]
        print(f"sliding wire: deceleration {-slope:.6f}, mu_d g = 0.4")
        self.assertAlmostEqual(-slope / 0.4, 1.0, delta=0.005)
        # the floor carries the weight
        weight = 11 * bead_mass()
        self.assertAlmostEqual(-t["floor[5]"][-1] / weight, 1.0, delta=1e-3)

    def test_sticks_below_mu_s(self):
        weight = 11 * bead_mass()
        for factor, sticks in ((0.9, True), (1.1, False)):
            push = factor * 0.6 * weight / 11      # per bead, ramped up over 0.5 time units
            extra = (f"variable ramp equal ramp(0.0,{push!r})\n"
                     "fix push all addforce v_ramp 0.0 0.0\n"
                     "run 5000\n"
                     "unfix push\n"
                     f"fix push all addforce {push!r} 0.0 0.0")
            r = run(self.floor_deck(extra, 10000))
            self.assertRanCleanly(r)
            t = r.thermo()
            travelled = t["x"][-1]                  # the wire's centre started at x = 0
            print(f"push {factor} mu_s m g: travelled {travelled:.3e}, final vx {t['vx'][-1]:.3e}")
            if sticks:
                self.assertLess(abs(travelled), 1e-3)
                self.assertLess(abs(t["vx"][-1]), 1e-6)
            else:
                self.assertGreater(travelled, 0.01)


class SegmentOnFixedWire(DeckTestCase):
    # A one-segment wire lying across a fixed one-segment rail, launched along it: it
    # decelerates at μ_d g while it slides (the contact normal is vertical). The rail is one
    # long segment: crossing a bead of a many-segment rail makes a fresh contact that
    # sticks until μ_s, which adds friction (about 1 % here with μ_s/μ_d = 0.5/0.3).
    def test_slides_at_mu_d(self):
        deck = HEADER + """
create_wire     1 line -2 0 0 2 0 0 segment 4.0
create_wire     2 line -1.5 -0.1 0.2 -1.5 0.1 0.2
group           rail type 1
group           rider type 2
pair_style      wire/contact mu_s 0.5 mu_d 0.3 restitution 0.1
pair_coeff      * *
neighbor        0.1 bin
fix             el all wire/elastic
fix             int rider nve/gear forces velocity
fix             g rider gravity 1.0 vector 0 0 -1
timestep        1e-4
run             20000
velocity        rider set 0.4 0 0
compute         vx rider reduce ave vx
thermo_style    custom step time c_vx
thermo_modify   format float %.15g
thermo          100
run             10000
"""
        r = run(deck)
        self.assertRanCleanly(r)
        t = r.thermo()
        moving = t["vx"] > 0.05
        slope = np.polyfit(t["Time"][moving], t["vx"][moving], 1)[0]
        print(f"segment on a fixed wire: deceleration {-slope:.6f}, mu_d g = 0.3")
        self.assertAlmostEqual(-slope / 0.3, 1.0, delta=0.005)


class MovingWall(DeckTestCase):
    # A short wire pushed by a sideways gravity against a wall that moves away at 0.1
    # follows it: once the approach has died out (ζ = 0.59 from e = 0.1, ω = 71: e^-80 by
    # t = 2) every bead moves with the wall at the overlap m g/k_n, k_n = E l π/4 (rigid
    # wall, ν = 0), and the wall carries the wire's weight.
    def test_wire_follows_moving_wall(self):
        r = run(HEADER + """
create_wire     1 line 0.1 -0.5 0 0.1 0.5 0
fix             el all wire/elastic
fix             int all nve/gear forces velocity
fix             g all gravity 1.0 vector -1 0 0
fix             wall all wire/wall plane 0 0 0 1 0 0 mu_s 0 mu_d 0 restitution 0.1 velocity 0.1 0 0
timestep        1e-4
compute         xmean all reduce ave x
thermo_style    custom step time c_xmean f_wall[1] f_wall[3]
thermo_modify   format float %.17g norm no
thermo          1000
run             20000
""")
        self.assertRanCleanly(r)
        t = r.thermo()
        k_n = 100.0 / (1.0 - 0.0) * 0.2 * math.pi / 4.0        # rigid wall: E* l_w π/4
        overlap = 0.1 * t["Time"][-1] + 0.1 - t["xmean"][-1]    # wall position + r_w − x
        err = overlap / (bead_mass() / k_n) - 1
        weight = 6 * bead_mass()
        print(f"moving wall: overlap {overlap:.15g}, m g/k_n {bead_mass() / k_n:.15g} (relative error {err:.1e}); "
              f"force on the wall {t['wall[3]'][-1]:.15g} (weight {weight:.15g})")
        self.assertLess(abs(err), 1e-10)                               # measured 1.5e-11
        self.assertAlmostEqual(-t["wall[3]"][-1] / weight, 1.0, delta=1e-12)  # measured 1.4e-13
        self.assertEqual(int(t["wall[1]"][-1]), 6)
        self.assertNotIn("WARNING", r.output)  # neither time step nor overlap


class Pile(DeckTestCase):
    # A 1000-segment wire coiled above a floor falls into a box and piles up; the segments
    # never pass through each other: the largest overlap stays below half the wire radius.
    def test_pile_does_not_pass_through_itself(self):
        deck = COIL.format(top=8, turns=21.25, z0=0.4, pair="", skin=0.1) + """compute         zmax all reduce max z
thermo_style    custom step atoms ke c_c[1] c_c[3] c_zmax f_floor[2]
thermo          1000
run             40000
"""
        r = run(deck)
        self.assertRanCleanly(r)
        t = r.thermo()
        self.assertGreaterEqual(int(t["Atoms"][0]), 1001)
        worst = np.max(t["c[3]"])
        print(f"pile of 1000 segments: largest overlap {worst:.4f} r_w, {int(np.max(t['c[1]']))} contacts at most "
              f"({int(t['c[1]'][0])} at the start), top of the pile {t['zmax'][-1]:.3f}")
        self.assertGreater(np.max(t["c[1]"]), 2 * t["c[1]"][0])  # it did pile up (measured 3283 against 999)
        self.assertLess(t["zmax"][-1], 5.0)                       # fallen from 6.75
        self.assertLess(worst, 0.5)                               # measured 0.29
        # no time-step warning, no wire–wire or floor overlap warning
        self.assertEqual(warning_lines(r.output), [])


def assert_same_with_and_without_cache(test, deck_template, label, **fields):
    """Runs the deck with cache yes and no (its dump d written to {dump}); asserts the dumped
    positions and velocities equal to the bit; returns the contact counts (c_c[1]) with the cache."""
    runs = {}
    for cache in ("yes", "no"):
        r = run(full_precision(deck_template.format(cache=cache, dump=f"cache_{cache}.dump", **fields), "d"))
        test.assertRanCleanly(r)
        runs[cache] = r
    with_cache, without = (read_dump(runs[c].path(f"cache_{c}.dump")) for c in ("yes", "no"))
    for column in ("x", "y", "z", "vx", "vy", "vz"):
        np.testing.assert_array_equal(with_cache[column], without[column], err_msg=f"{label} {column}")
    return runs["yes"].thermo()["c[1]"]


class PairCache(DeckTestCase):
    # pair_style wire/contact cache yes (the default) looks only at the neighbour-list
    # pairs that can touch before the list is built again: a 600-segment coil falling into
    # a box and landing on its floor (neighbour rebuilds every few hundred steps, skin 0.1
    # and 0.4) follows the same trajectory to the bit as with cache no (every pair of the
    # list each step).
    DECK = COIL.format(top=6, turns=12.5, z0=0.4, pair="cache {cache}", skin="{skin}") + """thermo_style    custom step c_c[1]
thermo          1000
dump            d all custom 14000 {dump} id x y z vx vy vz
run             14000
"""

    def test_same_trajectory_with_and_without_the_cache(self):
        for skin in (0.1, 0.4):
            contacts = assert_same_with_and_without_cache(self, self.DECK, f"skin {skin}", skin=skin)
            print(f"skin {skin}: wire–wire contacts at the end {contacts[-1]:.0f}, most {np.max(contacts):.0f}")
            self.assertGreater(np.max(contacts), contacts[0] + 100)  # it lands and piles up


class PairCacheAcrossRuns(DeckTestCase):
    # The cache is rebuilt at every run's setup: LIGGGHTS' Verlet::setup sorts the atoms
    # (atom_modify sort, on by default), builds the list and resets neighbor->ncalls to 0,
    # so a run that builds no list (here `run 0`) leaves the count where the next setup
    # finds it while the atoms' local indices change. The coil falls for 3000 steps, a
    # `run 0`, the whole wire lifted by 0.5 (most beads change sort bins), 2000 steps more:
    # the same trajectory to the bit with cache yes and no. Guards against a cache that keeps
    # the pairs of the old indices (a 10 000-bead coil crashes on them).
    DECK = COIL.format(top=8, turns=12.5, z0=1, pair="cache {cache}", skin=0.1) + """thermo_style    custom step c_c[1]
thermo          1000
run             3000
run             0
displace_atoms  all move 0 0 0.5
dump            d all custom 2000 {dump} id x y z vx vy vz
run             2000
"""

    def test_same_trajectory_with_and_without_the_cache(self):
        contacts = assert_same_with_and_without_cache(self, self.DECK, "lifted")
        print(f"wire–wire contacts after the lift: {contacts[-1]:.0f}")
        self.assertGreater(np.max(contacts), 20)


class Warnings(DeckTestCase):
    # A run stays within the contact model or says why not (bench/stress_matrix.py):
    # the time step against each contact style's stability limit, and overlaps beyond
    # 0.5 r_w (common/contact_checks.h).
    TWO_WIRES = HEADER + """
create_wire     1 line -0.5 0 1 0.5 0 1
create_wire     1 line 0 -0.5 2 0 0.5 2
pair_style      wire/contact restitution 1
pair_coeff      * *
neighbor        0.1 bin
fix             el all wire/elastic m_elo 0.01 m_rot 0.01
fix             int all nve/gear scheme {scheme}
fix             floor all wire/wall plane 0 0 0 0 0 1 {wall}
thermo          5
"""

    def test_time_step_beyond_the_contact_limit(self):
        # Table 1 wire, soft springs (m_elo = m_rot = 0.01: fix wire/elastic's own gear5
        # limit is 0.0198), undamped contacts: wire–wire k = E/2 l π/4 on half a bead,
        # wall k = E l π/4 on a bead: both gear5 limits 0.313/√(5000) = 0.00443. A second
        # run at the same step is not warned again; a new timestep is.
        r = run(self.TWO_WIRES.format(scheme="gear5 check_every 1", wall="restitution 1") + """
timestep        0.006
run             10
run             10
timestep        0.01
run             10
""")
        self.assertRanCleanly(r)
        m = bead_mass()
        pair = lambda dt: contact_time_step_warning("pair wire/contact (id -)", dt, 50 * 0.2 * math.pi / 4, m / 2,
                                            "the reduced mass of two of the lightest beads", 0.0, True)
        wall = lambda dt: contact_time_step_warning("fix wire/wall (id floor)", dt, 100 * 0.2 * math.pi / 4, m,
                                            "the lightest bead", 0.0, True)
        found = warning_lines(r.output, "")
        print("\n".join(found))
        # the run-start checks; fix nve/gear's per-bead check, made at every
        # step here (check_every 1), warns too, and for a bead on the floor alone gives the
        # wall's own limit
        per_bead = [w for w in found if w.startswith("fix nve/gear")]
        self.assertEqual([w for w in found if w not in per_bead], [pair(0.006), wall(0.006), pair(0.01), wall(0.01)])
        self.assertIn("stable limit 0.00442649 of the gear5", found[0])
        self.assertEqual(len(per_bead), 10)
        self.assertIn("carries 1 contact whose summed springs and dashpots on its mass 0.00314159 give a gear5 "
                      "limit of 0.00442649, below the timestep 0.006", per_bead[0])

    def test_time_step_with_verlet_and_damping(self):
        # Verlet: 2/ω (√(1+ζ²) − ζ); the wall with restitution 0.5 (ζ = 0.2155, the factor
        # 0.8075): 0.02284, the wire–wire contact with restitution 1: 0.0283
        r = run(self.TWO_WIRES.format(scheme="verlet", wall="restitution 0.5") + """
timestep        0.025
run             10
""")
        self.assertRanCleanly(r)
        zeta = -math.log(0.5) / math.sqrt(math.pi ** 2 + math.log(0.5) ** 2)
        expected = contact_time_step_warning("fix wire/wall (id floor)", 0.025, 100 * 0.2 * math.pi / 4, bead_mass(),
                                     "the lightest bead", zeta, False)
        found = warning_lines(r.output, "")
        print("\n".join(found))
        self.assertEqual(found, [expected])
        self.assertIn("stable limit 0.0228394 of the verlet", expected)
        # below both limits: no warning
        quiet = run(self.TWO_WIRES.format(scheme="verlet", wall="restitution 0.5") + "timestep 0.02\nrun 10\n")
        self.assertRanCleanly(quiet)
        self.assertNotIn("WARNING", quiet.output)

    def test_overlaps_at_setup(self):
        # two wires crossing 0.08 apart (overlap 0.12 = 1.2 r_w at beads 3-4 and 9-10) and
        # a floor 0.02 below the lower one's axis (overlap 0.08 = 0.8 r_w for each of its
        # beads: the first, 7, is named)
        r = run(HEADER + """
create_wire     1 line -0.5 0 0.04 0.5 0 0.04
create_wire     1 line 0 -0.5 -0.04 0 0.5 -0.04
pair_style      wire/contact
pair_coeff      * *
neighbor        0.1 bin
fix             el all wire/elastic
fix             int all nve/gear
fix             floor all wire/wall plane 0 0 -0.06 0 0 1
timestep        1e-4
run             0
""")
        self.assertRanCleanly(r)
        found = warning_lines(r.output, "overlap by")
        print("\n".join(found))
        self.assertEqual(found, [
            contact_overlap_warning("pair wire/contact (id -)", 0, "the segments of beads 3 and 9", 0.12, 0.1,
                            "a stiffer material (E)"),
            contact_overlap_warning("fix wire/wall (id floor)", 0, "bead 7 and the wall", 0.08, 0.1,
                            "a stiffer material (E)")])

    def test_overlap_of_a_fast_impact_on_a_soft_wall(self):
        # a straight wire falls at 2.5 on a wall of E = 1 (k = 0.157, ω = 7.07): it sinks
        # to 2.5/ω = 0.35 = 3.5 r_w and bounces back (restitution 1). Named: the first step
        # beyond 0.5 r_w, then each time the overlap doubles the largest one named (about
        # 0.5, 1, 2 r_w; the overlap grows by at most v dt = 0.025 r_w a step); not on the
        # way out, nor at a second impact at the same speed (the same depth: nothing
        # doubles).
        r = run(HEADER + """
create_wire     1 line -0.5 0 0.2 0.5 0 0.2
velocity        all set 0 0 -2.5
fix             el all wire/elastic m_elo 0.01 m_rot 0.01
fix             int all nve/gear
fix             floor all wire/wall plane 0 0 0 0 0 1 E 1 restitution 1
timestep        1e-3
thermo_style    custom step f_floor[2]
thermo_modify   format float %.15g
thermo          1
run             600
velocity        all set 0 0 -2.5
run             600
""")
        self.assertRanCleanly(r)
        found = warning_lines(r.output, "overlap by")
        print("\n".join(found))
        deepest = np.max(r.thermo()["floor[2]"]) / 0.1
        self.assertAlmostEqual(deepest, 2.5 / math.sqrt(0.05 * math.pi / bead_mass()) / 0.1, delta=0.05)
        self.assertEqual(len(found), 3)
        ratios = []
        for line in found:
            m = re.fullmatch(r"fix wire/wall \(id floor\): at step (\d+) bead 1 and the wall overlap by (\S+) "
                             r"\((\S+) r_w, beyond 0\.5 r_w: the soft contact assumes small overlaps\); "
                             r"use a smaller timestep or a stiffer material \(E\)", line)
            self.assertIsNotNone(m, line)
            ratios.append(float(m.group(3)))
        self.assertGreater(ratios[0], 0.5)
        self.assertLess(ratios[0], 0.5 + 0.026)
        for a, b in zip(ratios, ratios[1:]):
            self.assertGreater(b, 2 * a)
            self.assertLess(b, 2 * a + 0.026)
        self.assertLess(ratios[-1], deepest)


class BadInput(DeckTestCase):
    def check(self, body, message):
        text = HEADER + "create_wire 1 line 0 0 0 1 0 0\n" + body + "\nrun 1\n"
        self.assertStopsWith(run(text), message)

    def test_negative_parameters(self):
        self.check("pair_style wire/contact E -1\npair_coeff * *",
                   "pair_style wire/contact (id -): value of 'E' must be > 0, got -1")
        self.check("pair_style wire/contact mu_s -0.1\npair_coeff * *",
                   "pair_style wire/contact (id -): value of 'mu_s' must be >= 0, got -0.1")
        self.check("pair_style wire/contact damping_ratio -0.2\npair_coeff * *",
                   "pair_style wire/contact (id -): value of 'damping_ratio' must be >= 0, got -0.2")
        self.check("pair_style wire/contact restitution 1.5\npair_coeff * *",
                   "pair_style wire/contact (id -): value of 'restitution' must be in [0, 1]")

    def test_mu_d_above_mu_s(self):
        self.check("pair_style wire/contact mu_s 0.3 mu_d 0.5\npair_coeff * *",
                   "pair_style wire/contact (id -): mu_d (0.500000) must not exceed mu_s (0.300000)")
        self.check("fix w all wire/wall plane 0 0 -1 0 0 1 mu_s 0.2 mu_d 0.4",
                   "fix wire/wall (id w): mu_d (0.400000) must not exceed mu_s (0.200000)")

    def test_unknown_type(self):
        self.check("pair_style wire/contact\npair_coeff 3 3",
                   "pair_coeff wire/contact (id -): atom type '3' is not one of 1..2")

    def test_pair_coeff_keyword(self):
        self.check("pair_style wire/contact\npair_coeff 1 2 stiffness 4",
                   "pair_coeff wire/contact (id -): unknown keyword 'stiffness'; accepted: E, nu, "
                   "mu_s, mu_d, restitution, damping_ratio, limit_force")

    def test_wall_zero_normal(self):
        self.check("fix w all wire/wall plane 0 0 0 0 0 0",
                   "fix wire/wall (id w): the plane normal (nx ny nz) must not be zero")

    def test_wall_missing_value(self):
        self.check("fix w all wire/wall plane 0 0 0 0 0 1 velocity 1 0",
                   "fix wire/wall (id w): missing value after 'velocity'")


if __name__ == "__main__":
    main()
