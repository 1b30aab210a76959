"""fix wire/grain against stock LIGGGHTS superquadrics (atom_style hybrid wire
superquadric, fix nve/superquadric; a LIGGGHTS built with WIREGRAIN_SUPERQUADRIC, the
default): an ellipsoid on two wires lying on the floor against the ellipse geometry worked
out here, a wire lying on a fixed rounded box at rest and carried whole, momentum, 1 vs 2 ranks,
restart in contact, the top of a superquadric in compute column/height."""

import math

import numpy as np

import test_wire_sphere as spheres
from liggghts_run import DeckTestCase, full_precision, main, read_dump, run

G = 1.0
HEADER = """
units           lj
atom_style      hybrid wire superquadric
atom_modify     map array sort 0 0.0
newton          off
"""


def superquadric_scene(grains, wires, box=(-4, 4, -4, 4, -1, 5)):
    """The deck lines that make the superquadrics [(x, y, z, (a, b, c), (n1, n2), density,
    quat w i j k)] (atom type 1, IDs 1...) and the wires of the `create_wire 2 ...`
    argument strings (atom type 2). (In place of a data file: LIGGGHTS 3.8 reads and writes
    no data file of a hybrid with superquadrics.)"""
    made_grains = "\n".join(
        f"create_atoms    1 single {x!r} {y!r} {z!r}\n"
        f"set             atom {k + 1} shape {a!r} {b!r} {c!r} blockiness {n1!r} {n2!r} density {rho!r} "
        f"quat_direct {q[0]!r} {q[1]!r} {q[2]!r} {q[3]!r}"  # (LIGGGHTS' quat[0..3] = w i j k)
        for k, (x, y, z, (a, b, c), (n1, n2), rho, q) in enumerate(grains))
    lines = "\n".join(f"create_wire     2 {w}" for w in wires)
    return f"""
region          box block {' '.join(map(str, box))}
create_box      2 box
{made_grains}
{lines}
"""


def deck(scene, body, processors="* * *"):
    return HEADER + f"""
boundary        f f f
processors      {processors}
{scene}
group           grains type 1
group           wire type 2
{body}
"""


def ellipse_closest_point(b, c, py, pz):
    """The point of the ellipse (y/b)² + (z/c)² = 1 nearest (py, pz) outside it: the root
    of the normal-line condition in the angle θ of (b cos θ, c sin θ), by bisection on
    the derivative of the squared distance (an independent way to the contact normal)."""
    def slope(theta):  # d/dθ of ½|p − e(θ)|²
        y, z = b * math.cos(theta), c * math.sin(theta)
        return -(py - y) * (-b * math.sin(theta)) - (pz - z) * (c * math.cos(theta))
    lo, hi = 0.0, math.pi / 2  # (py, pz) in the first quadrant
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if slope(lo) * slope(mid) <= 0.0:
            hi = mid
        else:
            lo = mid
    theta = 0.5 * (lo + hi)
    return np.array([b * math.cos(theta), c * math.sin(theta)])


class Statics(DeckTestCase):
    def test_ellipsoid_on_two_rails_lying_on_the_floor(self):
        # a frictionless axis-aligned ellipsoid (half-axes 1.2, 0.8, 0.6) resting on two
        # straight wires 0.8 apart along x lying on a frictional floor: at rest the wires
        # carry m g; by symmetry the contacts lie in the plane x = x_c of the centre, where
        # the ellipsoid's section is the ellipse of half-axes 0.8, 0.6: the normal is that
        # ellipse's normal at its point nearest the rail's axis, N n_z = m g/2 each, shared
        # by the segment's beads as (1 − t, t), t of x_c on the segment; the ellipse point
        # from the dumped positions (fix viscous takes out the bouncing; no force at rest)
        half = (1.2, 0.8, 0.6)
        made = superquadric_scene([(0.0, 0.0, 0.75, half, (2.0, 2.0), 0.1, (1, 0, 0, 0))],
                                  ["line -2.25 -0.4 0.1 2.25 -0.4 0.1 segment 0.5 radius 0.1",
                                   "line -2.25 0.4 0.1 2.25 0.4 0.1 segment 0.5 radius 0.1"])
        r = run(full_precision(deck(made, f"""
fix             g all gravity {G} vector 0 0 -1
fix             floor wire wire/wall plane 0 0 0 0 0 1 mu_s 1 mu_d 1
fix             elastic wire wire/elastic
fix             integr wire nve/gear
fix             nve grains nve/superquadric
fix             calm all viscous 0.05
fix             wg wire wire/grain grains mu_s 0 mu_d 0
timestep        1e-3
thermo_style    custom step ke f_wg[1] f_wg[6]
thermo_modify   format float %.15g
thermo          1000
dump            d all custom 50000 dump.w id mass x y z f_wg[1] f_wg[2] f_wg[3]
run             50000
"""), "d"))
        self.assertRanCleanly(r)
        t = r.thermo()
        d = read_dump(r.path("dump.w"))
        self.assertEqual(t["wg[1]"][-1], 2.0)
        grain = d["id"] == 1
        weight = d["mass"][grain][0] * G
        # LIGGGHTS' mass of the ellipsoid: 4/3 π a b c ρ
        self.assertAlmostEqual(d["mass"][grain][0] / (4 / 3 * math.pi * 1.2 * 0.8 * 0.6 * 0.1), 1.0, delta=1e-12)
        centre = np.array([d["x"][grain][0], d["y"][grain][0], d["z"][grain][0]])
        force = np.array([d["f_wg[1]"], d["f_wg[2]"], d["f_wg[3]"]]).T
        print(f"\nellipsoid on rails: force of the wires {force[grain][0]}, m g = {weight:.15g}")
        np.testing.assert_allclose(force[grain][0], [0.0, 0.0, weight], rtol=0, atol=1e-8 * weight)
        for rail in (-0.4, 0.4):
            beads = np.nonzero((d["id"] > 1) & (np.abs(d["y"] - rail) < 0.2))[0]
            beads = beads[np.argsort(d["x"][beads])]
            a = np.searchsorted(d["x"][beads], centre[0]) - 1  # the segment under the centre
            i, j = beads[a], beads[a + 1]
            x0 = np.array([d["x"][i], d["y"][i], d["z"][i]])
            x1 = np.array([d["x"][j], d["y"][j], d["z"][j]])
            t_foot = (centre[0] - x0[0]) / (x1[0] - x0[0])
            axis = x0 + t_foot * (x1 - x0)  # the rail's axis in the plane x = x_c
            # (in the ellipse's frame: |y|, z below the centre as +z by symmetry)
            py, pz = abs(axis[1] - centre[1]), centre[2] - axis[2]
            ey, ez = ellipse_closest_point(half[1], half[2], py, pz)
            normal = np.array([0.0, ey / half[1] ** 2, ez / half[2] ** 2])
            normal /= np.linalg.norm(normal)
            n = np.array([0.0, math.copysign(normal[1], axis[1] - centre[1]), -normal[2]])
            on_wire = 0.5 * weight / abs(n[2]) * n
            print(f"rail y = {rail}: t = {t_foot:.6f}, n = {n}, bead forces {force[i]}, {force[j]} "
                  f"(expected {(1 - t_foot) * on_wire}, {t_foot * on_wire})")
            np.testing.assert_allclose(force[i], (1 - t_foot) * on_wire, rtol=0, atol=1e-8 * weight)
            np.testing.assert_allclose(force[j], t_foot * on_wire, rtol=0, atol=1e-8 * weight)

    def test_wire_lying_on_a_fixed_rounded_box_comes_to_rest_carried_whole(self):
        # a straight wire laid just above the top (z = 2.5) of a rounded box (n1 = n2 = 3,
        # turned about z) that nothing integrates (fixed), shorter than the top: it settles
        # on it; at rest the box carries the wire's whole weight and the wire stays at rest
        # (blockier tops need a smaller time step for that: docs/commands/fix_wire_grain.md,
        # Restrictions)
        made = superquadric_scene([(0.0, 0.0, 2.0, (0.6, 0.9, 0.5), (3.0, 3.0), 1.0, (0.96, 0.0, 0.0, 0.28))],
                                  ["line -0.4 0.1 2.56 0.4 0.1 2.56 segment 0.2 radius 0.05"])
        r = run(full_precision(deck(made, f"""
fix             g all gravity {G} vector 0 0 -1
fix             elastic wire wire/elastic
fix             integr wire nve/gear
fix             calm wire viscous 0.01
fix             wg wire wire/grain grains
timestep        1e-3
thermo_style    custom step ke f_wg[1]
thermo_modify   format float %.15g
thermo          1000
dump            d all custom 20000 dump.w id mass z f_wg[1] f_wg[2] f_wg[3]
run             20000
"""), "d"))
        self.assertRanCleanly(r)
        t = r.thermo()
        d = read_dump(r.path("dump.w"))
        wire_weight = d["mass"][d["id"] > 1].sum() * G
        grain = d["id"] == 1
        print(f"\nlying on a rounded box: {t['wg[1]'][-1]:.0f} contacts, kinetic energy {t['KinEng'][-1]:.3g}, "
              f"force on it ({d['f_wg[1]'][grain][0]:.3g}, {d['f_wg[2]'][grain][0]:.3g}, "
              f"{d['f_wg[3]'][grain][0]:.15g}), wire weight {wire_weight:.15g}")
        self.assertGreaterEqual(t["wg[1]"][-1], 3)  # lying along the top
        self.assertLess(t["KinEng"][-1], 1e-20)
        self.assertAlmostEqual(d["f_wg[3]"][grain][0] / -wire_weight, 1.0, delta=1e-8)
        self.assertLess(np.hypot(d["f_wg[1]"][grain][0], d["f_wg[2]"][grain][0]), 1e-8 * wire_weight)


def flying_scene():
    """Zero gravity: a tilted superquadric thrown at a free straight wire."""
    return superquadric_scene([(0.0, 0.05, 0.0, (0.5, 0.4, 0.6), (3.0, 4.0), 1.0, (0.9, 0.3, 0.2, 0.1))],
                              ["line -1.25 0.1 -0.9 1.25 0.1 -0.9 segment 0.5 radius 0.1"],
                              box=(-6, 6, -6, 6, -6, 6))


FLIGHT_FIXES = spheres.FLIGHT_FIXES.replace("nve/sphere", "nve/superquadric")


class Momentum(spheres.FlightThroughAWire, DeckTestCase):
    """test_wire_sphere.py's flight of a grain through a free wire, with a tilted
    superquadric: momentum, 1 vs 2 ranks, restart in contact."""

    HEADER = HEADER
    FLIGHT_FIXES = FLIGHT_FIXES

    def flight_deck(self, body, processors="* * *", workdir=None):
        # the scene is made by the deck itself
        return deck(flying_scene(), spheres.VELOCITIES + FLIGHT_FIXES + body, processors=processors), workdir


class ColumnHeight(DeckTestCase):
    def test_top_of_a_tilted_superquadric(self):
        # compute column/height quantile 1 of one grain: its highest point, here from the
        # test's own sampling of the surface (Barr's parametrisation, rotated), which
        # comes within its spacing of the support point from below
        a, b, c, n1, n2 = 0.5, 0.4, 0.6, 3.0, 4.0
        q = np.array([0.9, 0.3, 0.2, 0.1])
        made = superquadric_scene([(0.3, -0.2, 1.5, (a, b, c), (n1, n2), 1.0, tuple(q))], [])
        r = run(full_precision(deck(made, """
compute         h grains column/height quantile 1
compute         gs grains grain/shape
thermo_style    custom step c_h
thermo_modify   format float %.17g
dump            d all custom 1 dump.g id c_gs[1] c_gs[2] c_gs[3] c_gs[4] c_gs[5] c_gs[7]
run             0
"""), "d"))
        self.assertRanCleanly(r)
        top = r.thermo()["h"][-1]
        # compute grain/shape: shape index -3, the quaternion set, the same top
        g = read_dump(r.path("dump.g"))
        self.assertEqual(g["c_gs[1]"][0], -3.0)
        np.testing.assert_allclose([g[f"c_gs[{k}]"][0] for k in (2, 3, 4, 5)], q / np.linalg.norm(q), rtol=0,
                                   atol=1e-15)
        self.assertEqual(g["c_gs[7]"][0], top)
        w, x, y, z = q / np.linalg.norm(q)
        rz = np.array([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)])  # row z of R
        eta, omega = np.meshgrid(np.linspace(-np.pi / 2, np.pi / 2, 801), np.linspace(0, 2 * np.pi, 1601))
        sp = lambda v, e: np.sign(v) * np.abs(v) ** e  # noqa: E731
        ce = sp(np.cos(eta), 2 / n1)
        points = np.stack([a * ce * sp(np.cos(omega), 2 / n2), b * ce * sp(np.sin(omega), 2 / n2),
                           c * sp(np.sin(eta), 2 / n1)])
        sampled = 1.5 + np.tensordot(rz, points, axes=1).max()
        print(f"\ntop of the superquadric: compute {top:.15g}, sampled {sampled:.15g}")
        self.assertGreaterEqual(top, sampled - 1e-12)
        self.assertLess(top - sampled, 1e-4)


if __name__ == "__main__":
    main()
