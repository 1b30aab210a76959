"""create_wire ... append: a chain continued by a second create_wire is the chain one call
lays (links, rest lengths, masses, and the forces and motion that follow, on 1 and 2 ranks and
across a restart); a join carries the tension of a stretched chain unchanged (statics); a
join is laid without stretching. The bad input is in test_bad_input.py (CreateWireAppend)."""

import math

import numpy as np

from liggghts_run import DeckTestCase, main, read_dump, run

BOX = """
units           lj
atom_style      wire
atom_modify     sort 0 0.0
boundary        f f f
{processors}
region          box block -5 5 -5 5 -5 5
create_box      1 box
"""

# The chain from x = -2 to 2 along the x axis (21 beads, l_w = 0.2): in one call, or in two,
# the second starting at x = 0, l_w beyond the first's end bead at x = -0.2 (a join of no
# bead: the end bead's segment to the first new bead is a whole one). On 2 ranks
# (processors 2 1 1, the sub-domains meet at x = 0) the end bead belongs to rank 0 and every
# new bead to rank 1.
ONE_CALL = "create_wire 1 line -2 0 0 2 0 0\n"
TWO_CALLS = "create_wire 1 line -2 0 0 -0.2 0 0\ncreate_wire 1 line 0 0 0 2 0 0 append last\n"

# bead 1 held, the rest falling under gravity: the chain swings down about bead 1, bending
# and stretching all along, across the join too
MOTION = """
group           free id > 1
fix             el all wire/elastic E 100 m_elo 1 m_rot 0.1
fix             g free gravity 1.0 vector 0 0 -1
fix             int free nve/gear scheme verlet
timestep        1e-3
dump            d all custom {steps} state.dump id x y z vx vy vz fx fy fz
dump_modify     d sort id format "%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g"
run             {steps}
"""
STEPS = 2000
# the two-call chain against the one-call chain after STEPS (SameChain.test_motion_on_one_and_two_ranks)
TOL = {"x": 5e-14, "y": 5e-14, "z": 5e-14, "vx": 3e-12, "vy": 3e-12, "vz": 3e-12, "fx": 1e-12, "fy": 1e-12, "fz": 1e-12}


def atoms_section(path):
    """{id: (prev, next, rest, radius, mass, x, y, z)} of a data file written by write_data."""
    with open(path) as f:
        lines = f.read().splitlines()
    start = lines.index("Atoms") + 2
    atoms = {}
    for line in lines[start:]:
        words = line.split()
        if not words:
            break
        atoms[int(words[0])] = tuple(int(w) for w in words[2:4]) + tuple(float(w) for w in words[4:10])
    return atoms


class SameChain(DeckTestCase):
    """Two calls lay the chain one call lays."""

    def laid(self, body, ranks=1):
        deck = BOX.format(processors="processors 2 1 1" if ranks == 2 else "") + body + "write_data chain.data\n"
        res = run(deck, np_ranks=ranks)
        self.assertRanCleanly(res)
        return atoms_section(res.path("chain.data"))

    def moved(self, body, ranks=1):
        deck = BOX.format(processors="processors 2 1 1" if ranks == 2 else "") + body + MOTION.format(steps=STEPS)
        res = run(deck, np_ranks=ranks)
        self.assertRanCleanly(res)
        return read_dump(res.path("state.dump"))

    def test_links_rest_lengths_and_masses(self):
        one = self.laid(ONE_CALL)
        for ranks in (1, 2):
            two = self.laid(TWO_CALLS, ranks)
            self.assertEqual(sorted(two), sorted(one))
            for tag in one:
                # prev, next, rest, radius, mass exactly; positions to round-off (the second
                # line's nodes are 0 + k l_w, the single line's -2 + k l_w: 1 ulp of 2 apart)
                self.assertEqual(two[tag][:5], one[tag][:5], f"bead {tag} on {ranks} rank(s)")
                np.testing.assert_allclose(two[tag][5:], one[tag][5:], rtol=0, atol=1e-15)
        self.assertEqual(one[10][:3], (9, 11, 0.2))   # the end bead of the first call
        self.assertEqual(one[11][:2], (10, 12))

    def test_motion_on_one_and_two_ranks(self):
        # after 2000 steps (t = 2, the chain swung down ~2) the positions, velocities and
        # forces of the two-call chain (1 and 2 ranks) are those of the one-call chain to
        # round-off, grown from the 1 ulp differences of the laid positions through the
        # springs (k_s = 15.7): measured 4.7e-15 (positions, of size 2), 6.5e-13 (velocities,
        # of size 2), 1.8e-13 (forces, of size 0.07; each the sum of spring forces of ~0.3);
        # tolerances TOL, 3-10 times that
        one = self.moved(ONE_CALL)
        self.assertGreater(np.ptp(one["z"]), 1.0)   # it did swing
        for ranks in (1, 2):
            two = self.moved(TWO_CALLS, ranks)
            np.testing.assert_array_equal(two["id"], one["id"])
            for c in ("x", "y", "z", "vx", "vy", "vz", "fx", "fy", "fz"):
                np.testing.assert_allclose(two[c], one[c], rtol=0, atol=TOL[c], err_msg=f"{c} on {ranks} rank(s)")

    def test_restart_after_the_append(self):
        # laid in two calls, written to a restart file, read back and run: the links and rest
        # lengths come back from the file, and the run is the one-call chain's (the same
        # differences were measured as without the restart; TOL)
        one = self.moved(ONE_CALL)
        for ranks in (1, 2):
            proc = "processors 2 1 1" if ranks == 2 else ""
            written = run(BOX.format(processors=proc) + TWO_CALLS + "write_restart laid.restart\n", np_ranks=ranks)
            self.assertRanCleanly(written)
            read = ("\nunits lj\natom_style wire\natom_modify sort 0 0.0\nboundary f f f\n" + proc +
                    "\nread_restart laid.restart\n" + MOTION.format(steps=STEPS))
            again = run(read, np_ranks=ranks, workdir=written.workdir)
            self.assertRanCleanly(again)
            two = read_dump(again.path("state.dump"))
            for c in ("x", "y", "z", "vx", "vy", "vz", "fx", "fy", "fz"):
                np.testing.assert_allclose(two[c], one[c], rtol=0, atol=TOL[c], err_msg=f"{c} on {ranks} rank(s)")


class TensionThroughTheJoin(DeckTestCase):
    """A chain pinned at both ends and stretched, laid in two layers joined by a straight
    join with beads: the tension is the same on both sides of every bead, join beads and
    the end bead included."""

    # along u = (0.6, 0, 0.8): the first layer's line from 0 to u (5 segments), a lone bead
    # made in between (the appended beads' IDs then skip one, as grains between two wire
    # layers make them), the second layer's line from 1.65 u to 2.65 u appended to bead 6:
    # the join from u to 1.65 u has nodes at 1.2 u and 1.4 u (1.6 u dropped: the remainder
    # 0.05 is below join_min l_w = 0.2, join_min's default 2 r_w / l_w here) and a last segment
    # of rest length 0.25
    LAID = """
create_wire     1 line 0 0 0 0.6 0 0.8
create_atoms    1 single 4 4 4
create_wire     1 line 0.99 0 1.32 1.59 0 2.12 append 6
"""

    def test_rest_lengths_of_the_join(self):
        res = run(BOX.format(processors="") + self.LAID + "write_data chain.data\n")
        self.assertRanCleanly(res)
        atoms = atoms_section(res.path("chain.data"))
        # beads 1..6 the first line, 7 the lone bead, 8 and 9 the join, 10..15 the second line
        self.assertEqual(atoms[6][:2], (5, 8))
        self.assertEqual(atoms[8][:2], (6, 9))
        self.assertEqual(atoms[9][:2], (8, 10))
        self.assertEqual(atoms[10][:2], (9, 11))
        self.assertEqual(atoms[7][:3], (0, 0, 0.0))
        self.assertEqual(atoms[15][1], 0)
        self.assertEqual(atoms[6][2], 0.2)
        self.assertEqual(atoms[8][2], 0.2)
        self.assertAlmostEqual(atoms[9][2], 0.25, delta=1e-15)
        u = np.array([0.6, 0.0, 0.8])
        for tag, s in ((8, 1.2), (9, 1.4), (10, 1.65)):
            np.testing.assert_allclose(atoms[tag][5:], s * u, rtol=0, atol=1e-15)

    def test_tension_is_uniform(self):
        # every bead moved to (1 + eps) times its position (about bead 1 at the origin):
        # each segment stretched by the strain eps of its own rest length, so the tension is
        # T = m_elo E pi r_w^2 eps in every segment, the join's short last one too; the end
        # beads feel ±T u, every other bead T - T = 0. Measured (eps = 1e-2): the end forces
        # T u to 1.0e-13 T, the inner beads 1.2e-13 T (round-off of the positions times
        # k_s = 15.7, T = 0.031); tolerance 1e-12 T. A rest length of the join's last segment
        # laid as l_w instead of 0.25 leaves its beads a force of order E A (0.05 / 0.2) ~ 25 T.
        eps, E, r = 1e-2, 100.0, 0.1
        deck = BOX.format(processors="") + self.LAID + f"""
displace_atoms  all ramp x 0 {1.59 * eps!r} x 0 1.59
displace_atoms  all ramp z 0 {2.12 * eps!r} z 0 2.12
group           lone id 7
group           chain subtract all lone
fix             el chain wire/elastic E {E} m_elo 1 m_rot 0.1
dump            d chain custom 1 forces.dump id x y z fx fy fz
dump_modify     d sort id format "%d %.17g %.17g %.17g %.17g %.17g %.17g"
run             0
"""
        res = run(deck)
        self.assertRanCleanly(res)
        d = read_dump(res.path("forces.dump"))
        T = E * math.pi * r * r * eps
        u = np.array([0.6, 0.0, 0.8])
        f = np.stack([d["fx"], d["fy"], d["fz"]], 1)
        ids = list(d["id"])
        self.assertEqual(len(ids), 14)
        np.testing.assert_allclose(f[ids.index(1)], T * u, rtol=0, atol=1e-12 * T)
        np.testing.assert_allclose(f[ids.index(15)], -T * u, rtol=0, atol=1e-12 * T)
        inner = [k for k, tag in enumerate(ids) if tag not in (1, 15)]
        self.assertLess(np.max(np.abs(f[inner])), 1e-12 * T, f"forces on the inner beads: {f[inner]}")


class LaidStressFree(DeckTestCase):
    """The paper's double loops laid as one wire, each appended to the last by a straight or a
    helix join: one chain through every bead, every segment at its rest length."""

    def test_double_loops_joined(self):
        for join in ("straight", "helix"):
            deck = BOX.format(processors="") + f"""
create_wire     1 loop 0 0 -2 3 2 0.25
create_wire     1 loop 0 0 -1 3 2 0.25 append last join {join}
create_wire     1 loop 0 0 0.5 3 2 0.25 append last join {join}
fix             el all wire/elastic E 100
thermo_style    custom step atoms f_el[1] f_el[2] f_el[4]
run             0
write_data      chain.data
"""
            res = run(deck)
            self.assertRanCleanly(res)
            atoms = atoms_section(res.path("chain.data"))
            # one chain: from the bead without a previous bead, the next links visit every
            # bead once, each bead's next names it as its previous
            starts = [t for t, a in atoms.items() if a[0] == 0]
            self.assertEqual(len(starts), 1)
            seen, tag = [], starts[0]
            while tag:
                seen.append(tag)
                nxt = atoms[tag][1]
                if nxt:
                    self.assertEqual(atoms[nxt][0], tag)
                tag = nxt
            self.assertEqual(sorted(seen), sorted(atoms))
            # each rest length is the segment's length (l_w within round-off but for the
            # joins' last segments): stretching energy 0, measured 1.2e-26 with either join
            # (round-off: the 1e-16 chord errors squared), tolerance 1e-25; the bends of the
            # loops and the joins do have energy
            th = res.thermo()
            self.assertLess(abs(th["el[1]"][-1]), 1e-25, join)
            self.assertGreater(th["el[2]"][-1], 0.0)
            for t in seen[:-1]:
                x = np.array(atoms[t][5:])
                y = np.array(atoms[atoms[t][1]][5:])
                self.assertAlmostEqual(np.linalg.norm(y - x), atoms[t][2], delta=1e-12, msg=f"{join}: bead {t}")
                # join_min's default here 2 r_w / l_w = 1: a join's last segment below 2 l_w
                self.assertLessEqual(atoms[t][2], 0.2 * 2 + 1e-12)
                # and none below 2 r_w = 0.2, which pair wire/contact refuses
                self.assertGreaterEqual(atoms[t][2], 0.2 - 1e-12)


class Layouts(DeckTestCase):
    """circle and spiral laid by create_wire (their nodes: tests/core/test_wire_layout.cpp)."""

    def test_circle_and_spiral(self):
        # circle of R = l_w = 0.2: Δφ = 2 asin(1/2) = π/3, a hexagon of 6 beads (the seventh,
        # on the first, left out); spiral r = b φ, b = l_w / (π/2), 3 turns (r1 = 2.4): the
        # second bead at φ = π/2, (0, l_w, z); every segment l_w, one chain each
        res = run(BOX.format(processors="") + """
create_wire     1 circle 1 1 -1 0.2
create_wire     1 spiral 0 0 1 0 2.4 3
write_data      chain.data
""")
        self.assertRanCleanly(res)
        atoms = atoms_section(res.path("chain.data"))
        for k in range(6):
            np.testing.assert_allclose(atoms[k + 1][5:], (1 + 0.2 * math.cos(k * math.pi / 3),
                                                          1 + 0.2 * math.sin(k * math.pi / 3), -1), rtol=0, atol=1e-15)
        self.assertEqual(atoms[6][1], 0)
        self.assertEqual(atoms[7][0], 0)
        np.testing.assert_allclose(atoms[7][5:], (0, 0, 1), rtol=0, atol=1e-15)
        np.testing.assert_allclose(atoms[8][5:], (0, 0.2, 1), rtol=0, atol=1e-14)
        for t, a in atoms.items():
            if a[1]:
                self.assertEqual(atoms[a[1]][0], t)
                self.assertEqual(a[2], 0.2)
                self.assertAlmostEqual(np.linalg.norm(np.array(atoms[a[1]][5:]) - a[5:]), 0.2, delta=1e-13)
        # the spiral's last bead within 2.4 of the axis, beyond 2.4 - l_w
        last = max(atoms)
        self.assertLessEqual(np.hypot(*atoms[last][5:7]), 2.4 + 1e-12)
        self.assertGreater(np.hypot(*atoms[last][5:7]), 2.4 - 0.2)

    def test_shift_and_start_angle(self):
        # shift dx dy dz translates the layout: the polyline (0,0,0) → (1.1,0,0) → (1.1,1.1,0)
        # resampled at chord l_w = 0.2 has beads at x = 0, 0.2, …, 1.0 on the first leg, then
        # (1.1, √(0.2² − 0.1²) + 0.2 j) for j = 0..4 on the second; shifted by (-1, 0.5, 2)
        # start_angle θ turns an axis layout about its axis before the shift: a circle of
        # R = 1 about (0, 0) at z = 1 turned by 90° and shifted by (0.5, 0, 0) has its first
        # bead at (0.5, 1, 1) and every bead at distance 1 from (0.5, 0)
        res = run(BOX.format(processors="") + """
create_wire     1 polyline path.txt shift -1 0.5 2
create_wire     1 circle 0 0 1 1 start_angle 90 shift 0.5 0 0
write_data      chain.data
""", files={"path.txt": "0 0 0\n1.1 0 0\n1.1 1.1 0\n"})
        self.assertRanCleanly(res)
        atoms = atoms_section(res.path("chain.data"))
        for k in range(11):
            expected = (0.2 * k, 0, 0) if k <= 5 else (1.1, math.sqrt(0.03) + 0.2 * (k - 6), 0)
            np.testing.assert_allclose(atoms[k + 1][5:], np.add(expected, (-1, 0.5, 2)), rtol=0, atol=1e-12)
        self.assertEqual(atoms[11][1], 0)  # the polyline's end: 11 beads
        self.assertEqual(atoms[12][0], 0)  # the circle's first bead
        np.testing.assert_allclose(atoms[12][5:], (0.5, 1, 1), rtol=0, atol=1e-15)
        for t in range(12, max(atoms) + 1):
            self.assertAlmostEqual(np.hypot(atoms[t][5] - 0.5, atoms[t][6]), 1.0, delta=1e-14)

if __name__ == "__main__":
    main()
