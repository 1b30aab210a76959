"""Bad input across the plugin's styles and commands, table-driven: each case is a tiny
deck (a few atoms, run 0 or run 1) and the exact ERROR text it must stop with, naming the
style, its ID and the argument. Cases that the code handled badly before (a crash, a
silent acceptance, a misleading or generic message) say so in a comment."""

import math

from liggghts_run import DeckTestCase, deck_box, deck_head, main, run


# the keywords fix nscd/polyhedra accepts, as its unknown-keyword message lists them
NSCD_KEYWORDS = ", ".join([
    "friction", "rolling_friction", "damping", "restitution", "theta", "every", "timestep", "tolerance",
    "max_iterations", "convergence", "method", "order", "seed", "freeze", "subspace_regularization",
    "subspace_closing", "warm_start", "warm_geometry", "overlap_recovery", "overlap_speed", "project",
    "project_passes", "margin", "skin", "detection", "solve", "manifold", "sleep", "wall", "wall_fix", "wall_friction",
    "wall_velocity", "plate", "write_problems"])


WIRE = deck_box("wire", 2, (-2, 2), 2)
WIRE_LINE = WIRE + "create_wire 1 line 0 0 0 1 0 0\n"

POLY = deck_box("polyhedron", 6, (-6, 6), 1)
ONE_CUBE = POLY + "create_grains 1 1 random box seed 5 shape cube 1 sweep 0\n"

# one cube grain (type 1) and a wire (type 2) above it
HYBRID = deck_box("hybrid polyhedron wire", 4, (-1, 6), 2) + """create_grains   1 1 random box seed 3 shape cube 1 sweep 0.1
create_wire     2 line -0.5 0.2 3.3 0.5 0.2 3.3 segment 0.5 radius 0.1
group           grains type 1
group           wire type 2
"""

# a tetrahedron: the smallest hull
SHAPES = "wiregrain shapes 1 mass dilated\nshape 0 sweep 0.1 vertices 4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"


def data_file(title, types, rows, velocities=None):
    """A data file in the box [-5, 5]^3 with these Atoms (and Velocities) lines."""
    lines = [title, "", f"{len(rows)} atoms", f"{types} atom types", "-5 5 xlo xhi", "-5 5 ylo yhi",
             "-5 5 zlo zhi", "", "Atoms", ""] + rows
    if velocities:
        lines += ["", "Velocities", ""] + velocities
    return "\n".join(lines) + "\n"


def wire_data(rows, velocities=None):
    """A data file of wire beads: Atoms lines 'id type prev next rest radius mass x y z'."""
    return data_file("wire beads", 2, rows, velocities)


CHAIN = ["1 1 0 2 0.2 0.1 1.0 0 0 0", "2 1 1 3 0.2 0.1 1.0 0.2 0 0", "3 1 2 0 0 0.1 1.0 0.4 0 0"]


def chain_with(k, row):
    """The 3-bead chain with line k replaced."""
    rows = list(CHAIN)
    rows[k] = row
    return {"c.data": wire_data(rows)}


READ_WIRE = deck_head("wire") + "read_data       c.data\n"


def grain_data(row):
    """A one-grain data file (Atoms line 'id type shape density qw qi qj qk x y z') read with
    the tetrahedron library."""
    return {"g.data": data_file("grains", 1, [row]), "s.shapes": SHAPES}


READ_GRAIN = deck_head("polyhedron") + "grain_shapes    read s.shapes\nread_data       g.data\n"


class Table:
    """CASES: (deck, expected ERROR text[, files]); every deck must stop with it. A mixin, not
    a test case itself (an empty table would pass): a table is `class T(Table, DeckTestCase)`."""
    CASES = ()

    def test_cases(self):
        self.assertTrue(self.CASES, "an empty table")
        for case in self.CASES:
            deck, message = case[0], case[1]
            files = case[2] if len(case) > 2 else None
            with self.subTest(message=message):
                self.assertStopsWith(run(deck + "\n", files=files), message)


class WireLinks(Table, DeckTestCase):
    # A link to a bead ID beyond the largest atom ID must be refused: unchecked, it reads past
    # the end of LIGGGHTS' array map (bead 99 taken as some other atom, the run going on
    # silently; bead 7 giving "the segment from bead 1 to bead 7 has zero length").
    CASES = (
        (READ_WIRE + "fix el all wire/elastic\nrun 0", "fix wire/elastic (id el): bead 3 links to bead 99, "
         "which is neither owned nor a ghost here", chain_with(2, "3 1 2 99 0.2 0.1 1.0 0.4 0 0")),
        (READ_WIRE + "fix el all wire/elastic\nrun 0", "fix wire/elastic (id el): bead 1 links to bead 7, "
         "which is neither owned nor a ghost here", chain_with(0, "1 1 0 7 0.2 0.1 1.0 0 0 0")),
        (READ_WIRE + "pair_style wire/contact\npair_coeff * *\nrun 0", "pair wire/contact (id -): bead 3 links to "
         "bead 99, which is neither owned nor a ghost here", chain_with(2, "3 1 2 99 0.2 0.1 1.0 0.4 0 0")),
    )


class NscdCounts(Table, DeckTestCase):
    # Counts beyond an int must be refused, not wrapped: wrapped, max_iterations 3000000000
    # stops at the first solve with "max_iterations must be >= 1, got -1294967296", every
    # 3000000000 with "h must be > 0", write_problems 3000000000 is accepted (and never
    # writes), and a 'timestep' of more than 2^31 LIGGGHTS steps silently solves every step.
    NSCD = ONE_CUBE + "fix nscd all nscd/polyhedra "
    CASES = (
        (NSCD + "max_iterations 3000000000\nrun 1",
         "fix nscd/polyhedra (id nscd): value of 'max_iterations' must be <= 2147483647, got 3000000000"),
        (NSCD + "every 3000000000\nrun 1",
         "fix nscd/polyhedra (id nscd): value of 'every' must be <= 2147483647, got 3000000000"),
        (NSCD + "write_problems 3000000000 p_*.txt\nrun 1",
         "fix nscd/polyhedra (id nscd): value of 'write_problems' (every N steps) must be <= 2147483647, "
         "got 3000000000"),
        (NSCD + "seed 0\nrun 1", "fix nscd/polyhedra (id nscd): value of 'seed' must be >= 1, got 0"),
        (NSCD + "timestep 1e300\nrun 1", "fix nscd/polyhedra (id nscd): value of 'timestep' (1e+300) must be at "
         "most 2147483647 LIGGGHTS timesteps (0.005)"),
    )


class GrainShapesFile(Table, DeckTestCase):
    # Guards against: a non-finite vertex coordinate reported as "too few vertex
    # coordinates"; a negative shape count read as an empty library; a library read while
    # grains exist replacing the shapes under them (grains 1 and 2 keeping indices beyond
    # the new one-shape library: out-of-bounds reads, the run going on).
    READ = POLY + "grain_shapes read s.shapes\n"
    CASES = (
        (READ, "command grain_shapes (id -): 's.shapes': shape 0: vertex coordinate 'nan' must be a finite number",
         {"s.shapes": SHAPES.replace("0 0 1\n", "0 0 nan\n")}),
        (READ, "command grain_shapes (id -): 's.shapes': shape 0: vertex coordinate '1e400' must be a finite number",
         {"s.shapes": SHAPES.replace("0 0 1\n", "0 0 1e400\n")}),
        (READ, "command grain_shapes (id -): 's.shapes': the number of shapes N must be >= 0, got -1",
         {"s.shapes": SHAPES.replace("shapes 1", "shapes -1")}),
        (POLY + "create_grains 1 3 random box seed 1\ngrain_shapes read s.shapes\nfix n all nve/polyhedron\nrun 1",
         "command grain_shapes (id -): read must come before any grain exists (3 grains use the current shape "
         "library): read the shapes before read_data", {"s.shapes": SHAPES}),
    )


class PairCoeffTypes(Table, DeckTestCase):
    # Ranges are checked: unchecked, '3*' of 2 types selects nothing and stops with
    # LIGGGHTS' "All pair coeffs are not set", '*5' with "Numeric index is out of bounds".
    PAIR = WIRE_LINE + "pair_style wire/contact\n"
    CASES = (
        (PAIR + "pair_coeff 3* *\nrun 0",
         "pair_coeff wire/contact (id -): atom type '3*' is not one of 1..2 (nor a range of them)"),
        (PAIR + "pair_coeff * *5\nrun 0",
         "pair_coeff wire/contact (id -): atom type '*5' is not one of 1..2 (nor a range of them)"),
        (PAIR + "pair_coeff 2*1 *\nrun 0",
         "pair_coeff wire/contact (id -): atom type '2*1' is not one of 1..2 (nor a range of them)"),
    )


class DumpCannotWrite(Table, DeckTestCase):
    # VTK's writer returns success when it cannot open the file: the snapshot went
    # missing and only the series file's failure stopped the run, naming that file.
    CASES = (
        (ONE_CUBE + "shell touch blocker\ndump d all polyhedron/vtk 10 blocker/g_*.vtp\nrun 0",
         "dump polyhedron/vtk (id d): cannot write file 'blocker/g_0.vtp'"),
        (WIRE_LINE + "shell touch blocker\ndump d all wire/vtk 10 blocker/w_*.vtp\nrun 0",
         "dump wire/vtk (id d): cannot write file 'blocker/w_0.vtp'"),
    )


class WireDataFile(Table, DeckTestCase):
    CASES = (
        (READ_WIRE + "run 0", "atom_style wire: Atoms section of data file: wire-prev must be a bead ID >= 0 "
         "(0: free end), got '-1'", chain_with(0, "1 1 -1 2 0.2 0.1 1.0 0 0 0")),
        (READ_WIRE + "run 0", "atom_style wire: Atoms section of data file: wire-next must be a bead ID >= 0 "
         "(0: free end), got '2.5'", chain_with(0, "1 1 0 2.5 0.2 0.1 1.0 0 0 0")),
        (READ_WIRE + "run 0", "atom_style wire: Atoms section of data file: rest-length must be > 0 for a bead "
         "with a next bead, got '0'", chain_with(0, "1 1 0 2 0 0.1 1.0 0 0 0")),
        (READ_WIRE + "run 0", "atom_style wire: Atoms section of data file: radius must be a finite number > 0, "
         "got '-0.1'", chain_with(0, "1 1 0 2 0.2 -0.1 1.0 0 0 0")),
        (READ_WIRE + "run 0", "atom_style wire: Atoms section of data file: invalid atom type '5'",
         chain_with(0, "1 5 0 2 0.2 0.1 1.0 0 0 0")),
        (READ_WIRE + "run 0", "atom_style wire: Velocities section of data file: vz of atom 2 must be a finite "
         "number, got 'inf'", {"c.data": wire_data(CHAIN, ["1 0 0 0", "2 0 0 inf", "3 0 0 0"])}),
    )


class DataFileCoordinates(Table, DeckTestCase):
    # An Atoms line that no processor takes, named with its atom and the cause. Unchecked,
    # LIGGGHTS stops after the section with "Did not assign all atoms correctly" (a NaN, a
    # point outside a non-periodic box, 'x = 5' of the box [-5, 5): the high end is outside);
    # in a periodic box it puts a NaN at the box's low edge without a word, and an inf makes
    # remap loop for ever.
    W = "atom_style wire: Atoms section of data file: "
    P = "atom_style polyhedron: Atoms section of data file: "
    PERIODIC_WIRE = READ_WIRE.replace("boundary        f f f", "boundary        p p p")
    CASES = (
        (READ_WIRE + "run 0", W + "z of atom 2 must be a finite number, got 'nan'",
         chain_with(1, "2 1 1 3 0.2 0.1 1.0 0.2 0 nan")),
        (READ_WIRE + "run 0", W + "x of atom 3 must be a finite number, got '1e400'",
         chain_with(2, "3 1 2 0 0 0.1 1.0 1e400 0 0")),
        (READ_WIRE + "run 0", W + "atom 3 lies outside the simulation box: y = -7.5, the box spans [-5, 5) in y "
         "(a non-periodic boundary)", chain_with(2, "3 1 2 0 0 0.1 1.0 0.4 -7.5 0")),
        (PERIODIC_WIRE + "run 0", W + "z of atom 2 must be a finite number, got 'nan'",
         chain_with(1, "2 1 1 3 0.2 0.1 1.0 0.2 0 nan")),
        (PERIODIC_WIRE + "run 0", W + "y of atom 2 must be a finite number, got 'inf'",
         chain_with(1, "2 1 1 3 0.2 0.1 1.0 0.2 inf 0")),
        (READ_GRAIN + "run 0", P + "atom 1 lies outside the simulation box: z = 7, the box spans [-5, 5) in z "
         "(a non-periodic boundary)", grain_data("1 1 0 1.5 1 0 0 0 0 0 7")),
        # the box's high end belongs to no sub-domain
        (READ_GRAIN + "run 0", P + "atom 1 lies outside the simulation box: x = 5, the box spans [-5, 5) in x "
         "(a non-periodic boundary)", grain_data("1 1 0 1.5 1 0 0 0 5 0 0")),
        (READ_GRAIN + "run 0", P + "y of atom 1 must be a finite number, got 'nan'",
         grain_data("1 1 0 1.5 1 0 0 0 0 nan 0")),
    )


class CreateWire(Table, DeckTestCase):
    CW = "command create_wire (id -): "
    CASES = (
        (WIRE + "create_wire 1", CW + "expected: create_wire type line|loop|helix|circle|spiral|polyline ..."),
        (WIRE + "create_wire abc line 0 0 0 1 0 0", CW + "value of 'type' must be an integer, got 'abc'"),
        (WIRE + "create_wire 3 line 0 0 0 1 0 0", CW + "atom type 3 is outside 1..2"),
        (WIRE + "create_wire 1 zigzag 0 0 0 1 0 0",
         CW + "unknown layout 'zigzag' (line, loop, helix, circle, spiral or polyline)"),
        (WIRE + "create_wire 1 line 0 0 0 1 0 nan", CW + "value of 'z1' must be a finite number, got 'nan'"),
        (WIRE + "create_wire 1 loop 0 0 0 -1 2 0.3", CW + "value of 'R' must be > 0, got -1"),
        (WIRE + "create_wire 1 loop 0 0 0 1 0 0.3", CW + "value of 'turns' must be > 0, got 0"),
        (WIRE + "create_wire 1 line 0 0 0 1 0 0 colour red", 
         CW + "unknown keyword 'colour'; accepted: segment, radius, density, shift, start_angle, append, join, join_max, join_min"),
        (WIRE + "create_wire 1 line 0 0 0 1 0 0 segment 1e400",
         CW + "value of 'segment' must be a finite number, got '1e400'"),
        (WIRE + "create_wire 1 line 0 0 0 0.1 0 0",
         CW + "'length': length must be at least one segment_length (0.2), got 0.1"),
        (WIRE + "create_wire 1 polyline missing.txt", CW + "'file': cannot open polyline file 'missing.txt'"),
        (WIRE + "create_wire 1 line 0 0 0 1 0 0 start_angle 30",
         CW + "start_angle needs a layout with a vertical axis (loop, helix, circle or spiral), not 'line'"),
        (WIRE + "create_wire 1 circle 0 0 0 1 shift 0 0", CW + "missing value after 'dz'"),
        (WIRE + "create_wire 1 polyline p.txt",
         CW + "'file': line 2 of 'p.txt': expected three finite numbers x y z, got '1 abc 0'",
         {"p.txt": "0 0 0\n1 abc 0\n"}),
        (WIRE + "create_wire 1 polyline p.txt", CW + "'points': a polyline needs at least 2 points, got 1",
         {"p.txt": "0 0 0\n"}),
        ("units lj\natom_style wire\ncreate_wire 1 line 0 0 0 1 0 0", CW + "create a simulation box first"),
    )


def loop_beads(radius, turns, segment):
    """The beads of a flat loop: chords of length l subtend Δφ = 2 asin(l / 2R), so the turns
    hold floor(2π turns / Δφ) whole chords, one bead more than chords."""
    return math.floor(2 * math.pi * turns / (2 * math.asin(segment / (2 * radius)))) + 1


class CreateWireCount(Table, DeckTestCase):
    # More beads than a wire may have (1e8, create_grains' cap on N) are refused by their
    # count, before a node is stored: unchecked, a loop of R = 1e12 aborts with
    # std::bad_alloc and no ERROR, and a count beyond a long has no defined conversion.
    CW = "command create_wire (id -): 'segment_length': segment_length "
    TAIL = " (take a longer segment_length or a shorter layout)"
    CASES = (
        (WIRE + "create_wire 1 loop 0 0 0 1e12 1 0",
         CW + f"0.2 gives {loop_beads(1e12, 1, 0.2)} beads, more than the 100000000 one wire may have" + TAIL),
        (WIRE + "create_wire 1 loop 0 0 0 1e7 1 0",
         CW + f"0.2 gives {loop_beads(1e7, 1, 0.2)} beads, more than the 100000000 one wire may have" + TAIL),
        # a line of 1 in chords of 1e-8: 1e8 segments, one bead over the limit
        (WIRE + "create_wire 1 line 0 0 0 1 0 0 segment 1e-8",
         CW + "1e-08 gives 100000001 beads, more than the 100000000 one wire may have" + TAIL),
        # a polyline is counted by walking it: 1 / 0.99e-8 = 101010101 chords
        (WIRE + "create_wire 1 polyline p.txt segment 0.99e-8",
         CW + "9.9e-09 gives more than 100000000 beads, the most one wire may have" + TAIL,
         {"p.txt": "0 0 0\n1 0 0\n"}),
    )


# HYBRID with a stock sphere instead of the cube: atom_style hybrid wire sphere, a sphere
# (type 1) and the same wire (type 2)
SPHERE_HYBRID = deck_box("hybrid wire sphere", 4, (-1, 6), 2) + """create_atoms    1 single 0 0 1
set             atom 1 diameter 1 density 1
create_wire     2 line -0.5 0.2 3.3 0.5 0.2 3.3 segment 0.5 radius 0.1
group           grains type 1
group           wire type 2
"""


class CreateWireAppend(Table, DeckTestCase):
    # create_wire ... append: the chain end must exist, be a wire bead and have no next bead;
    # the join must be neither longer than join_max (default 10 segments) nor shorter than
    # join_min segments; its keywords need append, a helix join a layout with an axis.
    # WIRE_LINE's beads 1..6 run from (0,0,0) to (1,0,0).
    CW = "command create_wire (id -): "
    NEW = "create_wire 1 line 0 1 0 1 1 0"
    CASES = (
        (WIRE_LINE + NEW + " append 99", CW + "append 99: no atom has the ID 99"),
        (WIRE_LINE + NEW + " append 3", CW + "append 3: bead 3 already has a next bead (4): append to a chain end"),
        (HYBRID + "create_wire 2 line -0.5 0.2 4.3 0.5 0.2 4.3 segment 0.5 append 1",
         CW + "append 1: atom 1 is a grain, not a wire bead"),
        (SPHERE_HYBRID + "create_wire 2 line -0.5 0.2 4.3 0.5 0.2 4.3 segment 0.5 append 1",
         CW + "append 1: atom 1 is a grain, not a wire bead"),
        (WIRE + "create_wire 1 line 0 0 0 1 0 0 append last",
         CW + "append last: no chain end to append to (no wire bead has a previous bead and no next bead)"),
        # from (1,0,0) to (-1,-1,1): sqrt(6) = 2.449 in 12 segments, beyond the default 10 x 0.2
        (WIRE_LINE + "create_wire 1 line -1 -1 1 0 -1 1 append 6",
         CW + "'join_max': the join from the end bead to the layout's first node is 2.44948974278 long "
         "(12 segments), longer than join_max 2 (raise join_max, or append to another chain end)"),
        (WIRE_LINE + "create_wire 1 line -1 -1 1 0 -1 1 append last join_max 2.4",
         CW + "'join_max': the join from the end bead to the layout's first node is 2.44948974278 long "
         "(12 segments), longer than join_max 2.4 (raise join_max, or append to another chain end)"),
        (WIRE_LINE + "create_wire 1 line 1.05 0 0 1.85 0 0 append 6",
         CW + "'join_min': the layout's first node is 0.05 from the end bead, closer than join_min x "
         "segment_length = 0.2 (lay the layout further away, or lower join_min)"),
        (WIRE_LINE + NEW + " append 6 join_min 2", CW + "value of 'join_min' must be in [0, 1], got 2"),
        (WIRE_LINE + NEW + " append first", CW + "value of 'append' must be an atom ID >= 1 or 'last', got 'first'"),
        (WIRE_LINE + NEW + " append 6 join curved", CW + "value of 'join' must be straight or helix, got 'curved'"),
        (WIRE_LINE + NEW + " join straight", CW + "'join' needs 'append' (a join leads from a chain end to the layout)"),
        (WIRE_LINE + NEW + " join_max 3", CW + "'join_max' needs 'append' (a join leads from a chain end to the layout)"),
        (WIRE_LINE + NEW + " append 6 join helix",
         CW + "join helix needs a layout with a vertical axis (loop, helix, circle or spiral), not 'line'"),
        (WIRE + "create_wire 1 spiral 0 0 0 1 1 2", CW + "'r1': r1 must differ from r0 (1): a spiral of constant radius is a loop"),
        (WIRE + "create_wire 1 circle 0 0 0 0.05", CW + "'radius': radius 0.05 is too small for segment_length 0.2: one "
         "segment must fit in half a turn (4 radius^2 + pitch^2/4 >= segment_length^2)"),
    )


class MixedGroups(Table, DeckTestCase):
    # A group holding grains and wire beads (here 'all': the cube or sphere and 3 beads) is
    # refused by every style that acts on one kind. Unchecked, fix wire/wall pushes the cube
    # as a bead of its bounding radius, fix wire/elastic takes its radius and mass into its
    # time-step check, fix nve/gear integrates it as a point mass (its rotation dropped),
    # fix nscd/polyhedra says "3 grains have no shape (made by create_atoms?...)" of the
    # beads, and fix wire/grain ignores beads in a grain group of polyhedra.
    CASES = (
        (HYBRID + "fix w all wire/wall plane 0 0 -1 0 0 1\nrun 0",
         "fix wire/wall (id w): group 'all' holds 1 grains (give the wire beads only)"),
        (SPHERE_HYBRID + "fix w all wire/wall plane 0 0 -1 0 0 1\nrun 0",
         "fix wire/wall (id w): group 'all' holds 1 grains (give the wire beads only)"),
        (HYBRID + "fix el all wire/elastic\nrun 0",
         "fix wire/elastic (id el): group 'all' holds 1 grains (give the wire beads only)"),
        (HYBRID + "fix i all nve/gear\nrun 0",
         "fix nve/gear (id i): group 'all' holds 1 grains of atom_style polyhedron (rigid bodies: integrate "
         "them by fix nscd/polyhedra or fix nve/polyhedron)"),
        (HYBRID + "fix i grains nve/gear\nrun 0",
         "fix nve/gear (id i): group 'grains' holds 1 grains of atom_style polyhedron (rigid bodies: integrate "
         "them by fix nscd/polyhedra or fix nve/polyhedron)"),
        (SPHERE_HYBRID + "fix i all nve/gear\nrun 0",
         "fix nve/gear (id i): group 'all' holds 3 wire beads and 1 grains (give the wire beads only, or the "
         "grains only)"),
        (HYBRID + "fix nscd all nscd/polyhedra\nrun 0",
         "fix nscd/polyhedra (id nscd): group 'all' holds 3 wire beads (give the grains only)"),
        (HYBRID + "fix nscd wire nscd/polyhedra\nrun 0",
         "fix nscd/polyhedra (id nscd): group 'wire' holds 3 wire beads (give the grains only)"),
        (HYBRID + "fix n all nve/polyhedron\nrun 0",
         "fix nve/polyhedron (id n): group 'all' holds 3 wire beads (give the grains only)"),
        (HYBRID + "fix nscd grains nscd/polyhedra\nfix wg wire wire/grain all\nrun 0",
         "fix wire/grain (id wg): grain group 'all' holds 3 wire beads (give the grains only)"),
    )


class WireElasticAndWall(Table, DeckTestCase):
    CASES = (
        (WIRE_LINE + "fix el all wire/elastic E abc\nrun 0",
         "fix wire/elastic (id el): value of 'E' must be a finite number, got 'abc'"),
        (WIRE_LINE + "fix el all wire/elastic E 1e400\nrun 0",
         "fix wire/elastic (id el): value of 'E' must be a finite number, got '1e400'"),
        (WIRE_LINE + "fix el all wire/elastic m_elo -1\nrun 0", "fix wire/elastic (id el): value of 'm_elo' must be >= 0, got -1"),
        (WIRE_LINE + "fix w all wire/wall\nrun 0", "fix wire/wall (id w): expected 'plane px py pz nx ny nz'"),
        (WIRE_LINE + "fix w all wire/wall plane 0 0 0 0 0\nrun 0", "fix wire/wall (id w): missing value after 'plane'"),
        (WIRE_LINE + "fix w all wire/wall plane 0 0 abc 0 0 1\nrun 0",
         "fix wire/wall (id w): value of 'plane' must be a finite number, got 'abc'"),
        (WIRE_LINE + "fix w all wire/wall plane 0 0 -1 0 0 1 nu 0.5\nrun 0", "fix wire/wall (id w): value of 'nu' must be < 0.5"),
        (WIRE_LINE + "fix w all wire/wall plane 0 0 -1 0 0 1 limit_force maybe\nrun 0",
         "fix wire/wall (id w): value of 'limit_force' must be yes or no"),
        (WIRE_LINE + "fix w all wire/wall plane 0 0 -1 0 0 1 velocity 0 0 inf\nrun 0",
         "fix wire/wall (id w): value of 'velocity' must be a finite number, got 'inf'"),
        (WIRE_LINE + "fix w all wire/wall plane 0 0 -1 0 0 1\nfix_modify w velocity a b c\nrun 0",
         "fix_modify wire/wall (id w): value of 'velocity' must be a finite number, got 'a'"),
        (POLY + "fix w all wire/wall plane 0 0 -1 0 0 1\nrun 0",
         "fix wire/wall (id w): needs atom_style wire (or hybrid with wire), not 'polyhedron'"),
    )


class PairWireContact(Table, DeckTestCase):
    CASES = (
        (WIRE_LINE + "pair_style wire/contact E abc\npair_coeff * *\nrun 0",
         "pair_style wire/contact (id -): value of 'E' must be a finite number, got 'abc'"),
        (WIRE_LINE + "pair_style wire/contact limit_force 1\npair_coeff * *\nrun 0",
         "pair_style wire/contact (id -): value of 'limit_force' must be yes or no"),
        (WIRE_LINE + "pair_style wire/contact\npair_coeff 1 2 mu_s 0.2\nrun 0",
         "pair_coeff wire/contact (id -): mu_d (0.500000) must not exceed mu_s (0.200000)"),
        (WIRE_LINE + "pair_style wire/contact\npair_coeff a 1\nrun 0",
         "pair_coeff wire/contact (id -): atom type 'a' is not one of 1..2"),
        (WIRE_LINE + "pair_style wire/contact\npair_coeff * * restitution\nrun 0",
         "pair_coeff wire/contact (id -): missing value after 'restitution'"),
        (POLY + "pair_style wire/contact\npair_coeff * *\nrun 0",
         "pair wire/contact (id -): needs atom_style wire (or hybrid with wire), not 'polyhedron'"),
    )


class ThickWire(Table, DeckTestCase):
    # Segments that share no bead touch (docs/design.md, 1.2): the segments on either side of
    # a segment of rest length l overlap in the straight wire at rest when their radii sum
    # to more than l. Unchecked, such a wire runs, with overlap warnings that advise a
    # smaller time step. The paper's wire (r_w = 0.1, l_w = 0.2) is at the limit and runs.
    PAIR = "pair_style wire/contact\npair_coeff * *\nrun 0"
    WHY = (": these segments, which share no bead, overlap in the straight wire at rest; a wire's segments "
           "must be at least twice its radius long (create_wire: segment >= 2 radius)")
    # 4 beads, rest 0.2: the middle segment 2-3 between the segments of beads 1 and 3
    FOUR = ["1 1 0 2 0.2 0.1 1.0 0 0 0", "2 1 1 3 0.2 0.1 1.0 0.2 0 0", "3 1 2 4 0.2 {} 1.0 0.4 0 0",
            "4 1 3 0 0 0.1 1.0 0.6 0 0"]
    CASES = (
        (WIRE + "create_wire 1 line 0 0 0 1 0 0 segment 0.1\n" + PAIR,
         "pair wire/contact (id -): the segment from bead 2 to bead 3 (rest length 0.1) is shorter than the radii "
         "of the segments on either side, 0.1 + 0.1" + WHY),
        # one thick bead: its segment and bead 1's sum 0.25 > 0.2 (bead 3's own radius, not bead 2's)
        (READ_WIRE + PAIR, "pair wire/contact (id -): the segment from bead 2 to bead 3 (rest length 0.2) is "
         "shorter than the radii of the segments on either side, 0.1 + 0.15" + WHY,
         {"c.data": wire_data([row.format(0.15) for row in FOUR])}),
    )

    def test_the_papers_wire_at_the_limit_runs(self):
        # radii 0.1 + 0.1 = rest length 0.2: the straight wire's segments 1 and 3 just touch
        data = wire_data([row.format(0.1) for row in self.FOUR])
        self.assertRanCleanly(run(READ_WIRE + self.PAIR + "\n", files={"c.data": data}))


class WireComputes(Table, DeckTestCase):
    THERMO = "\nthermo_style custom step c_e[1]\nrun 0"
    CASES = (
        (WIRE_LINE + "compute e all wire/energy colour red\nrun 0", "compute wire/energy (id e): unknown keyword 'colour'; accepted: fix"),
        (WIRE_LINE + "compute e all wire/energy fix\nrun 0", "compute wire/energy (id e): missing value after 'fix'"),
        (WIRE_LINE + "compute e all wire/energy fix nope" + THERMO,
         "compute wire/energy (id e): fix ID 'nope' is not a fix wire/elastic"),
        (WIRE_LINE + "fix n all nve/gear\ncompute e all wire/energy fix n" + THERMO,
         "compute wire/energy (id e): fix ID 'n' is not a fix wire/elastic"),
        (WIRE_LINE + "compute e all wire/energy" + THERMO, "compute wire/energy (id e): needs a fix wire/elastic"),
        (WIRE_LINE + "fix a all wire/elastic\nfix b all wire/elastic\ncompute e all wire/energy" + THERMO,
         "compute wire/energy (id e): several fix wire/elastic are defined: name one with 'fix ID'"),
        (WIRE_LINE + "compute e all wire/contacts kind\nrun 0", "compute wire/contacts (id e): missing value after 'kind'"),
        (WIRE_LINE + "compute e all wire/contacts colour red\nrun 0", "compute wire/contacts (id e): unknown keyword 'colour'; accepted: kind"),
        (WIRE_LINE + "compute e all wire/contacts kind wire_wall" + THERMO,
         "compute wire/contacts (id e): kind wire_wall needs a fix wire/wall"),
        (WIRE_LINE + "compute e all wire/contacts" + THERMO, "compute wire/contacts (id e): needs pair_style wire/contact"),
        (WIRE_LINE + "fix i all nve/gear forces\nrun 0", "fix nve/gear (id i): missing value after 'forces'"),
    )


class NscdKeywords(Table, DeckTestCase):
    NSCD = ONE_CUBE + "fix nscd all nscd/polyhedra "
    P = "fix nscd/polyhedra (id nscd): "
    CASES = (
        (NSCD + "warm_start maybe\nrun 1", P + "value of 'warm_start' must be yes or no, got 'maybe'"),
        (NSCD + "warm_geometry 1\nrun 1", P + "value of 'warm_geometry' must be yes or no, got '1'"),
        (NSCD + "convergence fast\nrun 1", P + "value of 'convergence' must be natural_map, increment or both, got 'fast'"),
        (NSCD + "manifold all\nrun 1", P + "value of 'manifold' must be near_vertices or closest, got 'all'"),
        (NSCD + "manifold\nrun 1", P + "missing value after 'manifold'"),
        (NSCD + "detection split\nrun 1", P + "value of 'detection' must be shared or replicated, got 'split'"),
        (NSCD + "wall_friction 0.3\nrun 1", P + "'wall_friction' must follow a 'wall' or 'wall_fix'"),
        (NSCD + "wall 0 0 0 0 0\nrun 1", P + "missing value after 'wall'"),
        (NSCD + "max_iterations 1.5\nrun 1", P + "value of 'max_iterations' must be an integer, got '1.5'"),
        (NSCD + "tolerance nan\nrun 1", P + "value of 'tolerance' must be a finite number, got 'nan'"),
        (NSCD + "theta inf\nrun 1", P + "value of 'theta' must be a finite number, got 'inf'"),
        (NSCD + "wall 0 0 -2 0 0 1 wall_velocity 1 0 abc\nrun 1", P + "value of 'wall_velocity' must be a finite number, got 'abc'"),
        (NSCD + "margin -1\nrun 1", P + "value of 'margin' must be >= 0, got -1"),
        (NSCD + "skin -0.1\nrun 1", P + "value of 'skin' must be >= 0, got -0.1"),
        (NSCD + "colour red\nrun 1", P + "unknown keyword 'colour'; accepted: " + NSCD_KEYWORDS),
        (NSCD + "write_problems 10\nrun 1", P + "missing value after 'write_problems'"),
        (NSCD + "wall_fix\nrun 1", P + "missing value after 'wall_fix'"),
        (NSCD + "\nfix_modify nscd tolerance 0\nrun 1", "fix_modify nscd/polyhedra (id nscd): value of 'tolerance' must be > 0, got 0"),
        (NSCD + "\nfix_modify nscd friction abc\nrun 1",
         "fix_modify nscd/polyhedra (id nscd): value of 'friction' must be a finite number, got 'abc'"),
    )


class Grains(Table, DeckTestCase):
    CASES = (
        (ONE_CUBE + "fix int all nve/polyhedron colour red\nrun 1", "fix nve/polyhedron (id int): unknown keyword 'colour'; accepted: rotation"),
        (ONE_CUBE + "fix int all nve/polyhedron rotation\nrun 1", "fix nve/polyhedron (id int): missing value after 'rotation'"),
        (ONE_CUBE + "fix a all nve/polyhedron\nfix b all nscd/polyhedra\nrun 1",
         "fix nve/polyhedron (id a): 1 grains are also integrated by fix b (nscd/polyhedra)"),
        (ONE_CUBE + "compute r all grain/rotation extra\nrun 1", "compute grain/rotation (id r): unknown keyword 'extra'; this style takes no keywords"),
        (ONE_CUBE + "compute h all column/height quantile abc\nrun 0",
         "compute column/height (id h): value of 'quantile' must be a finite number, got 'abc'"),
        (ONE_CUBE + "compute h all column/height quantile -0.1\nrun 0",
         "compute column/height (id h): value of 'quantile' must be in [0, 1], got -0.1"),
        (WIRE + "compute h all column/height\nrun 0",
         "compute column/height (id h): needs atom_style polyhedron, sphere (granular) or superquadric, plain or "
         "in a hybrid, not 'wire'"),
        (ONE_CUBE + "compute p all column/retention radius 1 axis 1 abc\nrun 0",
         "compute column/retention (id p): value of 'axis' must be a finite number, got 'abc'"),
        (ONE_CUBE + "compute p all column/retention radius nan\nrun 0",
         "compute column/retention (id p): value of 'radius' must be a finite number, got 'nan'"),
        (ONE_CUBE + "compute p all column/retention radius 1 colour red\nrun 0",
         "compute column/retention (id p): unknown keyword 'colour'; accepted: axis"),
        (WIRE + "compute p all column/retention radius 1\nrun 0",
         "compute column/retention (id p): needs atom_style polyhedron, sphere (granular) or superquadric, plain or "
         "in a hybrid, not 'wire'"),
        (POLY.replace("atom_style      polyhedron", "atom_style      polyhedron mass"),
         "atom_style polyhedron: missing value after 'mass'"),
        (POLY.replace("atom_style      polyhedron", "atom_style      polyhedron colour red"),
         "atom_style polyhedron: unknown keyword 'colour'; accepted: mass"),
        (READ_GRAIN, "atom_style polyhedron: Atoms section of data file: shape '5' is not in the shape library (1 shapes",
         grain_data("1 1 5 1.5 1 0 0 0 0 0 0")),
        (READ_GRAIN, "atom_style polyhedron: Atoms section of data file: the quaternion qw qi qj qk must not be zero",
         grain_data("1 1 0 1.5 0 0 0 0 0 0 0")),
        (READ_GRAIN, "atom_style polyhedron: Atoms section of data file: invalid atom type '2'",
         grain_data("1 2 0 1.5 1 0 0 0 0 0 0")),
    )


class CreateGrainsAndShapes(Table, DeckTestCase):
    CG = "command create_grains (id -): "
    GS = "command grain_shapes (id -): "
    RANDOM = POLY + "create_grains 1 5 random box seed 1 "
    CASES = (
        (POLY + "create_grains 1 5 random box seed abc", CG + "value of 'seed' must be an integer, got 'abc'"),
        (POLY + "create_grains 1 abc random box seed 1", CG + "value of 'N' must be an integer, got 'abc'"),
        (RANDOM + "a_max nan", CG + "value of 'a_max' must be a finite number, got 'nan'"),
        (RANDOM + "shape box 1 2", CG + "missing value after 'shape box'"),
        (RANDOM + "shape cube -1", CG + "value of 'shape cube' must be > 0, got -1"),
        (RANDOM + "attempts 0", CG + "value of 'attempts' must be >= 1, got 0"),
        (RANDOM + "vertices 2000000", CG + "value of 'vertices' must be <= 1000000, got 2000000"),
        (RANDOM + "write_shapes nodir/s.txt", CG + "cannot write the 'write_shapes' file 'nodir/s.txt'"),
        (POLY + "create_grains 1 10", CG + "expected: create_grains type N layer|random region-ID ..."),
        ("units lj\natom_style polyhedron\ncreate_grains 1 5 random box seed 1", CG + "create a simulation box first"),
        (POLY + "region far block 100 101 100 101 100 101 units box\ncreate_grains 1 5 random far seed 1",
         CG + "region 'far' does not overlap the simulation box"),
        (POLY + "grain_shapes read", GS + "expected: grain_shapes write|read FILE"),
        (POLY + "grain_shapes load s.shapes", GS + "first argument must be write or read, got 'load'"),
        (POLY + "grain_shapes read s.shapes", GS + "'s.shapes' is not a grain shape file (header 'wiregrain shapes N "
         "mass dilated|sharp')", {"s.shapes": SHAPES.replace("dilated", "heavy")}),
        (POLY + "grain_shapes read s.shapes", GS + "'s.shapes': shape 0 has too few vertex coordinates",
         {"s.shapes": SHAPES.replace("0 0 1\n", "")}),
        (POLY + "grain_shapes read s.shapes", GS + "'s.shapes': all points lie in one plane",
         {"s.shapes": SHAPES.replace("0 0 1\n", "1 1 0\n")}),
        (POLY + "grain_shapes read s.shapes", GS + "'s.shapes': sweep_radius must be a finite number >= 0, got -0.1",
         {"s.shapes": SHAPES.replace("sweep 0.1", "sweep -0.1")}),
        (POLY + "grain_shapes write nodir/s.shapes", GS + "cannot write 'nodir/s.shapes'"),
        (WIRE + "grain_shapes write s.shapes", GS + "needs atom_style polyhedron (or hybrid with polyhedron)"),
    )


class WireGrainAndMaterials(Table, DeckTestCase):
    NSCD = HYBRID + "fix nscd grains nscd/polyhedra\n"
    WG = "fix wire/grain (id wg): "
    MATERIALS = ("fix m1 all property/global youngsModulus peratomtype {} {}\n"
                 "fix m2 all property/global poissonsRatio peratomtype {} {}\n")
    CASES = (
        (NSCD + "fix wg wire wire/grain grains nu_w 0.7\nrun 0", WG + "value of 'nu_w' must be < 0.5"),
        (NSCD + "fix wg wire wire/grain grains restitution 2\nrun 0", WG + "value of 'restitution' must be in [0, 1]"),
        (NSCD + "fix wg wire wire/grain grains damping_ratio abc\nrun 0",
         WG + "value of 'damping_ratio' must be a finite number, got 'abc'"),
        (NSCD + "fix wg wire wire/grain grains limit_force 2\nrun 0", WG + "value of 'limit_force' must be yes or no"),
        (NSCD + "fix wg wire wire/grain grains max_stretch inf\nrun 0",
         WG + "value of 'max_stretch' must be a finite number, got 'inf'"),
        (NSCD + MATERIALS.format(100, -3, 0, 0.3) + "fix wg wire wire/grain grains\nrun 0",
         WG + "youngsModulus of atom type 2 must be a finite number > 0, got -3"),
        (NSCD + MATERIALS.format(100, 1000, 0, 0.6) + "fix wg wire wire/grain grains\nrun 0",
         WG + "poissonsRatio of atom type 2 must be in [0, 0.5), got 0.6"),
        (WIRE + MATERIALS.format(0, 100, 0, 0) + "create_wire 1 line 0 0 0 1 0 0\npair_style wire/contact\n"
         "pair_coeff * *\nrun 0", "pair wire/contact (id -): youngsModulus of atom type 1 must be a finite number > 0, got 0"),
        (WIRE + "fix m1 all property/global youngsModulus peratomtype 1e400 100\ncreate_wire 1 line 0 0 0 1 0 0\n"
         "fix el all wire/elastic\nrun 0", "fix wire/elastic (id el): youngsModulus of atom type 1 must be a finite "
         "number > 0, got inf"),
    )


class DumpsAndDeckError(Table, DeckTestCase):
    CASES = (
        (WIRE_LINE + "dump d all wire/vtk 10 a*/w_*.vtp\nrun 0",
         "dump wire/vtk (id d): file 'a*/w_*.vtp' must contain exactly one '*', in its name"),
        (WIRE_LINE + "dump d all wire/vtk 10 w_%_*.vtp\nrun 0",
         "dump wire/vtk (id d): file 'w_%_*.vtp' must not contain '%' (rank 0 writes every snapshot)"),
        (WIRE_LINE + "dump d all wire/vtk 10 w_*.vtp format\nrun 0", "dump wire/vtk (id d): missing value after 'format'"),
        (WIRE_LINE + "fix el all wire/elastic\ndump d all wire/vtk 10 w_*.vtp energy el\nunfix el\nrun 0",
         "dump wire/vtk (id d): energy fix 'el' does not exist (was it unfixed?)"),
        (POLY + "dump d all polyhedron/vtk 10 g_**.vtp",
         "dump polyhedron/vtk (id d): file 'g_**.vtp' must contain exactly one '*', in its name"),
        ("deck_error in.deck: R must be > 0, got -1", "ERROR: in.deck: R must be > 0, got -1"),
        ("deck_error", "ERROR: deck_error: the deck stopped (no message given)"),
    )


if __name__ == "__main__":
    main()
