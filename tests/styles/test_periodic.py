"""Periodic boundaries: grains, wire and their contacts across periodic faces (minimum
image) do what they do in the middle of the box; a grain wrapped across a corner carries
its weight; a periodic pile is the same on 1 and 2 ranks and across a restart; a box too
short for the minimum image, or a wall across a periodic dimension, stops with an ERROR."""

import os

import numpy as np

from liggghts_run import DeckTestCase, full_precision, grains_data, main, read_dump, run

import test_wire_grain as wire_grain

G = 1.0
HEAD = """
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        {boundary}
processors      * 1 1
"""


def deck(body, boundary):
    """A deck on grains.data and grains.shapes (grains_data) with `body` after them."""
    return HEAD.format(boundary=boundary) + f"""grain_shapes    read grains.shapes
read_data       grains.data
{body}
"""


def periodic_difference(a, b, length):
    """a − b in the minimum image of a period `length`."""
    d = a - b
    return d - length * np.round(d / length)


class Collision(DeckTestCase):
    # Two unit cubes (m = 1) collide with restitution 0.5 and friction 0.5 across the
    # periodic face x = 5 of a 10-long box: cube 1 at x = 4.75 moving at vx = 2 meets cube 2,
    # which sits at x = -4.15 (its image at 5.85, 0.1 apart), offset in y and z so that
    # friction turns them; they touch with their centres on both sides of the face, so the
    # contact exists in the minimum image only, and cube 1 crosses the face (wraps) after
    # the collision. The same scene shifted by -5 along x collides in the middle of the box,
    # where no minimum image is involved: the velocities after the collision must be equal
    # to round-off and the positions a period apart. Measured: velocities 2.3e-15 (tolerance
    # 1e-14), positions 1.4e-13: the position updates x += h v round at the scale of |x|,
    # ~5 on one side and ~0.3 on the other, 400 steps × ulp(5) = 3.6e-13 at most (tolerance
    # 1e-12).
    BODY = """
set             atom 1 vx 2.0 vy 0.3
set             atom 2 vx -0.2 vz 0.1
fix             nscd all nscd/polyhedra restitution 0.5 friction 0.5 tolerance 1e-13 max_iterations 100000
timestep        1e-3
thermo_style    custom step f_nscd[3]
thermo          1
dump            d all custom 400 dump.c id x y z ix vx vy vz omegax omegay omegaz
run             400
"""

    def collide(self, shift):
        made = grains_data("cube 1.0", [(4.75 + shift, 0.3, 0.0, 1, 0, 0, 0),
                                        (-4.15 + shift + (10 if shift else 0), 0.0, 0.2, 1, 0, 0, 0)],
                           box=(-5, 5, -3, 3, -3, 3))
        self.assertRanCleanly(made)
        r = run(full_precision(deck(self.BODY, "p f f"), "d"), workdir=made.workdir)
        self.assertRanCleanly(r)
        return r.thermo(), read_dump(r.path("dump.c"))

    def test_collision_across_a_face_is_the_collision_in_the_middle(self):
        (t_face, face), (t_mid, middle) = self.collide(0.0), self.collide(-5.0)
        self.assertGreater(t_face["nscd[3]"].max(), 0)   # contact points found
        self.assertEqual(face["ix"][0], 1.0)             # cube 1 wrapped, with its image flag
        self.assertEqual(middle["ix"][0], 0.0)
        velocities = max(np.max(np.abs(face[c] - middle[c])) for c in ("vx", "vy", "vz", "omegax", "omegay", "omegaz"))
        positions = max(np.max(np.abs(periodic_difference(face["x"] + 5.0, middle["x"], 10.0))),
                        np.max(np.abs(face["y"] - middle["y"])), np.max(np.abs(face["z"] - middle["z"])))
        print(f"\ncollision across x = 5: velocities differ from the middle's by {velocities:.1e}, "
              f"positions by {positions:.1e}; cube 1 vx {face['vx'][0]:.6f} (before 2), |omega| "
              f"{np.hypot(face['omegax'][0], face['omegaz'][0]):.4f}")
        self.assertLess(abs(face["vx"][0] - 2.0), 1.9)   # it collided
        self.assertGreater(abs(face["vx"][0] - 2.0), 0.5)
        self.assertLess(velocities, 1e-14)
        self.assertLess(positions, 1e-12)


class CornerStack(DeckTestCase):
    # Two unit cubes (m = 1) stacked on a floor across the corner of the periodic faces
    # x = y = 2.5 of a 5 x 5 box: the lower one straddles both faces (centre 2.45, 2.45), the
    # upper one sits 0.1 and 0.07 off its axis as the image of a cube at (-2.45, -2.48):
    # their contact exists only in the minimum image. Statics: the floor carries 2 m g, the
    # upper cube gets m g from the lower, the lower m g net (2 m g up, m g down); nothing
    # moves. Measured (solver tolerance 1e-12, reached to round-off): floor and contact forces
    # 2.2e-16 relative (one ulp), displacements 0; tolerances 1e-15 (about 5 ulp).
    def test_stack_across_a_corner_carries_its_weight(self):
        made = grains_data("cube 1.0", [(2.45, 2.45, 0.5, 1, 0, 0, 0), (-2.45, -2.48, 1.5, 1, 0, 0, 0)],
                           box=(-2.5, 2.5, -2.5, 2.5, -1, 5))
        self.assertRanCleanly(made)
        r = run(full_precision(deck(f"""
fix             g all gravity {G} vector 0 0 -1
fix             nscd all nscd/polyhedra friction 0.5 tolerance 1e-12 max_iterations 100000 wall 0 0 0 0 0 1
timestep        1e-3
thermo_style    custom step f_nscd[9]
thermo_modify   format float %.17g
thermo          100
dump            d all custom 2000 dump.s id mass x y z f_nscd[1] f_nscd[2] f_nscd[3]
run             2000
""", "p p f"), "d"), workdir=made.workdir)
        self.assertRanCleanly(r)
        floor = -r.thermo()["nscd[9]"]
        d = read_dump(r.path("dump.s"))
        m = d["mass"]
        moved = max(abs(d["x"][0] - 2.45), abs(d["y"][0] - 2.45), abs(d["z"][0] - 0.5),
                    abs(d["x"][1] + 2.45), abs(d["y"][1] + 2.48), abs(d["z"][1] - 1.5))
        floor_error = np.max(np.abs(floor / (2 * G) - 1.0))
        force_error = max(np.max(np.abs(d["f_nscd[3]"] / (m * G) - 1.0)), np.max(np.abs(d["f_nscd[1]"])),
                          np.max(np.abs(d["f_nscd[2]"])))
        print(f"\ncorner stack: floor {floor[-1]:.17g} (2 m g = {2 * m[0] * G}), relative error over the run "
              f"{floor_error:.1e}; contact forces z {d['f_nscd[3]']} (m g each), error {force_error:.1e}; largest "
              f"displacement {moved:.1e}")
        np.testing.assert_allclose(m, 1.0, rtol=1e-15)
        self.assertLess(floor_error, 1e-15)
        self.assertLess(force_error, 1e-15)
        self.assertLess(moved, 1e-15)


class WireAcrossAFace(DeckTestCase):
    # The three cubes of test_wire_grain (edge 1, sweep 0.1, turned about z) under a wire of
    # ten 0.4 segments dropped onto them, and a second wire across the first: in a box
    # periodic along x (length 6), once in the middle and once shifted by +2.9, so that the
    # first wire and the middle cube's top lie across the face x = 3 and the second wire
    # crosses the first on the face (pair wire/contact through periodic ghosts). After 400
    # steps (80 NSCD steps of 5 sub-steps) the forces of fix wire/grain on every bead and
    # grain, the velocities and the positions (a period apart) are those of the middle
    # scene. Measured: forces 2.6e-14 (of 0.017), velocities 1.2e-13, positions 5.1e-15;
    # tolerances 1e-13, 5e-13 and 2e-14.
    def build(self, shift):
        cubes = []
        for x, turn in ((-1.6, 0.3), (0.0, -0.2), (1.6, 0.5)):
            cubes.append((x + shift, 0.05 * x, 0.62, np.cos(turn / 2), 0.0, 0.0, np.sin(turn / 2)))
        wires = [f"line {-2.0 + shift} 0.1 1.35 {2.0 + shift} 0.1 1.35 segment 0.4 radius 0.1",
                 f"line {0.1 + shift} -1.5 1.54 {0.1 + shift} 1.5 1.54 segment 0.4 radius 0.1"]
        made = wire_grain.scene(cubes, wires, shape="cube 1", box=(-3, 3, -3, 3, -0.5, 3), boundary="p f f")
        r = run(full_precision(wire_grain.deck(wire_grain.COUPLED.format(g=G, every=5, contact="") + """
pair_style      wire/contact
pair_coeff      * *
neighbor        0.1 bin
neigh_modify    delay 0
compute         wc wire wire/contacts
thermo_style    custom step f_wg[1] c_wc[1]
thermo          50
dump            d all custom 400 dump.w id x y z vx vy vz f_wg[1] f_wg[2] f_wg[3]
run             400
""", boundary="p f f"), "d"), workdir=made.workdir)
        self.assertRanCleanly(r)
        return r.thermo(), read_dump(r.path("dump.w"))

    def test_same_forces_as_in_the_middle(self):
        (t_mid, middle), (t_face, face) = self.build(0.0), self.build(2.9)
        self.assertGreater(t_face["wg[1]"][-1], 0)   # wire-grain contacts
        self.assertGreater(t_face["wc[1]"].max(), 0)  # the two wires touched
        np.testing.assert_array_equal(t_face["wg[1]"], t_mid["wg[1]"])
        np.testing.assert_array_equal(t_face["wc[1]"], t_mid["wc[1]"])
        forces = max(np.max(np.abs(face[c] - middle[c])) for c in ("f_wg[1]", "f_wg[2]", "f_wg[3]"))
        velocities = max(np.max(np.abs(face[c] - middle[c])) for c in ("vx", "vy", "vz"))
        positions = max(np.max(np.abs(periodic_difference(face["x"] - 2.9, middle["x"], 6.0))),
                        np.max(np.abs(face["y"] - middle["y"])), np.max(np.abs(face["z"] - middle["z"])))
        largest = np.max(np.abs(middle["f_wg[3]"]))
        print(f"\nwire across x = 3: fix wire/grain forces differ from the middle's by {forces:.1e} (largest "
              f"{largest:.3g}), velocities by {velocities:.1e}, positions by {positions:.1e}; contacts "
              f"{t_face['wg[1]'][-1]:.0f} wire-grain, {t_face['wc[1]'].max():.0f} wire-wire at most")
        self.assertGreater(largest, 1e-3)
        self.assertLess(forces, 1e-13)
        self.assertLess(velocities, 5e-13)
        self.assertLess(positions, 2e-14)


def periodic_pile():
    """grains.data and grains.shapes of 30 random grains filling the whole x and y extent of
    an 8 x 8 x 10 box up to z = 5 periodic along x and y (create_grains keeps them apart across the
    faces)."""
    return run("""
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        p p f
region          box block -4 4 -4 4 0 10
create_box      1 box
region          fill block -4 4 -4 4 1 5
create_grains   1 30 random fill seed 11
write_data      grains.data
grain_shapes    write grains.shapes
""")


class PeriodicPile(DeckTestCase):
    # 30 grains fall onto a frictional floor in a box periodic along x and y, launched
    # sideways (vx = 0.8, vy = 0.5) so that grains cross the faces and wrap: 1 and 2 ranks
    # (the subdomains split x; solve replicated, the distributed solve on this pile:
    # test_distributed.py) give the same state to the bit, and a run continued from a
    # restart file written in the middle (step 1500) that of the straight run to the bit.
    # (Every position fix nscd/polyhedra writes is wrapped at once, so the grains wrap at
    # the same steps whatever the ranks and restarts; measured differences: 0.)
    BODY = """
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra tolerance 1e-6 solve replicated wall 0 0 0 0 0 1
timestep        1e-3
thermo_style    custom step f_nscd[3] f_nscd[9]
thermo          100
dump            d all custom 100 dump.h id x y z ix iy vx vy vz omegax omegay omegaz
"""

    def test_one_and_two_ranks_and_restart(self):
        made = periodic_pile()
        self.assertRanCleanly(made)
        launch = "velocity        all set 0.8 0.5 0.0\n"
        text = full_precision(deck(launch + self.BODY, "p p f"), "d")
        one = run(text + "run 3000\n", workdir=made.workdir)
        self.assertRanCleanly(one)
        a = read_dump(made.path("dump.h"))
        two = run(text.replace("dump.h", "dump2.h") + "run 3000\n", workdir=made.workdir, np_ranks=2)
        self.assertRanCleanly(two)
        half = run(text.replace("dump.h", "dump3.h") + "run 1500\nwrite_restart pile.restart\n", workdir=made.workdir)
        self.assertRanCleanly(half)
        rest = run(full_precision(HEAD.format(boundary="p p f") + "read_restart    pile.restart\n" +
                                  self.BODY.replace("dump.h", "dump4.h") + "run 1500\n", "d"), workdir=made.workdir)
        self.assertRanCleanly(rest)
        b, c = read_dump(made.path("dump2.h")), read_dump(made.path("dump4.h"))
        wrapped = int(np.sum((a["ix"] != 0) | (a["iy"] != 0)))
        cols = ("x", "y", "z", "ix", "iy", "vx", "vy", "vz", "omegax", "omegay", "omegaz")
        ranks = max(np.max(np.abs(a[k] - b[k])) for k in cols)
        restart = max(np.max(np.abs(a[k] - c[k])) for k in cols)
        print(f"\nperiodic pile of 30: {wrapped} grains wrapped; 1 vs 2 ranks {ranks:.1e}, restart vs straight "
              f"{restart:.1e}; heights {a['z'].min():.3f} to {a['z'].max():.3f}")
        points = one.thermo()["nscd[3]"][-1]
        print(f"contact points at the end {points:.0f}, floor force {-one.thermo()['nscd[9]'][-1]:.4f}")
        self.assertGreater(wrapped, 5)
        self.assertGreater(points, 40)  # a pile: grain-grain and floor contacts (61 at the end)
        for k in cols:
            np.testing.assert_array_equal(b[k], a[k], err_msg=f"2 ranks {k}")
            np.testing.assert_array_equal(c[k], a[k], err_msg=f"restart {k}")


class Errors(DeckTestCase):
    def test_box_shorter_than_twice_the_pair_reach(self):
        # A unit cube (bounding radius √3/2): each periodic length must be at least
        # 2 (2 R + skin + margin) = 3.864 with the default skin 0.1; 3 is refused, naming the
        # dimension and the numbers.
        made = grains_data("cube 1.0", [(0.0, 0.0, 0.5, 1, 0, 0, 0)], box=(-1.5, 1.5, -5, 5, 0, 5))
        self.assertRanCleanly(made)
        radius = 3 ** 0.5 / 2
        r = run(deck("fix             nscd all nscd/polyhedra wall 0 0 0 0 0 1\nrun 1", "p f f"), workdir=made.workdir)
        self.assertStopsWith(r, f"ERROR: fix nscd/polyhedra (id nscd): the periodic box is 3 long along x, below 2 x "
                                f"the pair reach (2 x the largest bounding radius {radius:.12g} + skin 0.1 + margin 0) "
                                f"= {2 * (2 * radius + 0.1):.12g}: a grain could touch two images of another; enlarge "
                                f"the box along x")
        # with skin 0 and margin 0.2 the reach is 2 R + 0.2
        r = run(deck("fix             nscd all nscd/polyhedra skin 0 margin 0.2 wall 0 0 0 0 0 1\nrun 1", "p f f"),
                workdir=made.workdir)
        self.assertStopsWith(r, f"the pair reach (2 x the largest bounding radius {radius:.12g} + skin 0 + margin 0.2) "
                                f"= {2 * (2 * radius + 0.2):.12g}")

    def test_wall_across_a_periodic_dimension(self):
        made = grains_data("cube 1.0", [(0.0, 0.0, 0.5, 1, 0, 0, 0)], box=(-5, 5, -5, 5, 0, 5))
        self.assertRanCleanly(made)
        r = run(deck("fix             nscd all nscd/polyhedra wall 0 0 0 0 0 1 wall 0 4 0 0 -1 1\nrun 1", "f p f"),
                workdir=made.workdir)
        self.assertStopsWith(r, "ERROR: fix nscd/polyhedra (id nscd): wall 2 is not parallel to the periodic dimension y "
                                "(its normal has a component along y): a wall must not cut a periodic dimension")

    def test_box_shorter_than_twice_the_wire_grain_reach(self):
        # one segment of rest length 1 with max_stretch 2 (reach (1 + 2) 1/2 + r_w = 1.6, +
        # skin 0.1) over cubes of edge 0.2 (bounding radius 0.1 √3 + 0.05): the NSCD reach is
        # small, the wire-grain reach 1.923 needs a period of 3.85; the box is 3.6 long along x
        cubes = [(x, 0.0, 0.15, 1.0, 0.0, 0.0, 0.0) for x in (-1.0, 1.0)]
        made = wire_grain.scene(cubes, ["line -0.5 0.02 0.45 0.5 0.02 0.45 segment 1.0 radius 0.1"], shape="cube 0.2",
                                sweep=0.05, box=(-1.8, 1.8, -2, 2, -0.5, 2))
        body = wire_grain.COUPLED.format(g=G, every=5, contact="max_stretch 2.0")
        r = run(wire_grain.deck(body + "run 1\n", boundary="p f f"), workdir=made.workdir)
        reach = 0.1 * 3 ** 0.5 + 0.05 + 1.6 + 0.1
        self.assertStopsWith(r, f"ERROR: fix wire/grain (id wg): cannot hold the grains at step 0: the periodic box is "
                                f"3.6 long along x, below twice the wire-grain reach {reach:.12g} (the largest bounding "
                                f"radius + half the longest segment + the wire radius + the skin)")

if __name__ == "__main__":
    main()
