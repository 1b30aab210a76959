"""Bad input across the plugin's styles and commands, table-driven: each case is a tiny
deck (a few atoms, run 0 or run 1) and the exact ERROR text it must stop with, naming the
style, its ID and the argument. Cases that the code handled badly before (a crash, a
silent acceptance, a misleading or generic message) say so in a comment."""

from liggghts_run import DeckTestCase, main, run

WIRE = """
units           lj
atom_style      wire
atom_modify     map array sort 0 0.0
boundary        f f f
region          box block -2 2 -2 2 -2 2
create_box      2 box
"""
WIRE_LINE = WIRE + "create_wire 1 line 0 0 0 1 0 0\n"

POLY = """
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
region          box block -6 6 -6 6 -6 6
create_box      1 box
"""
ONE_CUBE = POLY + "create_grains 1 1 random box seed 5 shape cube 1 sweep 0\n"

# one cube grain (type 1) and a wire (type 2) above it
HYBRID = """
units           lj
atom_style      hybrid polyhedron wire
atom_modify     map array sort 0 0.0
boundary        f f f
region          box block -4 4 -4 4 -1 6
create_box      2 box
create_grains   1 1 random box seed 3 shape cube 1 sweep 0.1
create_wire     2 line -0.5 0.2 3.3 0.5 0.2 3.3 segment 0.5 radius 0.1
group           grains type 1
group           wire type 2
"""

# a tetrahedron: the smallest hull
SHAPES = "wiregrain shapes 1 mass dilated\nshape 0 sweep 0.1 vertices 4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"


def wire_data(rows, velocities=None):
    """A data file of wire beads: Atoms lines 'id type prev next rest radius mass x y z'."""
    lines = ["wire beads", "", f"{len(rows)} atoms", "2 atom types", "-5 5 xlo xhi", "-5 5 ylo yhi",
             "-5 5 zlo zhi", "", "Atoms", ""] + rows
    if velocities:
        lines += ["", "Velocities", ""] + velocities
    return "\n".join(lines) + "\n"


CHAIN = ["1 1 0 2 0.2 0.1 1.0 0 0 0", "2 1 1 3 0.2 0.1 1.0 0.2 0 0", "3 1 2 0 0 0.1 1.0 0.4 0 0"]


def chain_with(k, row):
    """The 3-bead chain with line k replaced."""
    rows = list(CHAIN)
    rows[k] = row
    return {"c.data": wire_data(rows)}


READ_WIRE = """
units           lj
atom_style      wire
atom_modify     map array sort 0 0.0
boundary        f f f
read_data       c.data
"""


def grain_data(row):
    """A one-grain data file (Atoms line 'id type shape density qw qi qj qk x y z') read with
    the tetrahedron library."""
    text = "\n".join(["grains", "", "1 atoms", "1 atom types", "-5 5 xlo xhi", "-5 5 ylo yhi", "-5 5 zlo zhi",
                      "", "Atoms", "", row]) + "\n"
    return {"g.data": text, "s.shapes": SHAPES}


READ_GRAIN = """
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
grain_shapes    read s.shapes
read_data       g.data
"""


class Table(DeckTestCase):
    """CASES: (deck, expected ERROR text[, files]); every deck must stop with it."""
    CASES = ()

    def test_cases(self):
        for case in self.CASES:
            deck, message = case[0], case[1]
            files = case[2] if len(case) > 2 else None
            with self.subTest(message=message):
                self.assertStopsWith(run(deck + "\n", files=files), message)


class WireLinks(Table):
    # A link to a bead ID beyond the largest atom ID used to read past the end of
    # LIGGGHTS' array map: bead 99 was taken as some other atom and the run went on
    # silently; bead 7 gave "the segment from bead 1 to bead 7 has zero length".
    CASES = (
        (READ_WIRE + "fix el all wire/elastic\nrun 0", "fix wire/elastic (id el): bead 3 links to bead 99, "
         "which is neither owned nor a ghost here", chain_with(2, "3 1 2 99 0.2 0.1 1.0 0.4 0 0")),
        (READ_WIRE + "fix el all wire/elastic\nrun 0", "fix wire/elastic (id el): bead 1 links to bead 7, "
         "which is neither owned nor a ghost here", chain_with(0, "1 1 0 7 0.2 0.1 1.0 0 0 0")),
        (READ_WIRE + "pair_style wire/contact\npair_coeff * *\nrun 0", "pair wire/contact (id -): bead 3 links to "
         "bead 99, which is neither owned nor a ghost here", chain_with(2, "3 1 2 99 0.2 0.1 1.0 0.4 0 0")),
    )


class NscdCounts(Table):
    # Counts beyond an int used to wrap: max_iterations 3000000000 stopped at the first
    # solve with "max_iterations must be >= 1, got -1294967296", every 3000000000 with
    # "h must be > 0", write_problems 3000000000 was accepted (and never wrote), and a
    # 'timestep' of more than 2^31 LIGGGHTS steps silently solved every step.
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


class GrainShapesFile(Table):
    # A non-finite vertex coordinate used to be reported as "too few vertex coordinates"; a
    # negative shape count was read as an empty library; reading a library while grains
    # exist replaced the shapes under them (grains 1 and 2 kept indices beyond the new
    # one-shape library: out-of-bounds reads, the run went on).
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


class PairCoeffTypes(Table):
    # Ranges used to pass unchecked: '3*' of 2 types selected nothing and stopped with
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


class DumpCannotWrite(Table):
    # VTK's writer returns success when it cannot open the file: the snapshot went
    # missing and only the series file's failure stopped the run, naming that file.
    CASES = (
        (ONE_CUBE + "shell touch blocker\ndump d all polyhedron/vtk 10 blocker/g_*.vtp\nrun 0",
         "dump polyhedron/vtk (id d): cannot write file 'blocker/g_0.vtp'"),
        (WIRE_LINE + "shell touch blocker\ndump d all wire/vtk 10 blocker/w_*.vtp\nrun 0",
         "dump wire/vtk (id d): cannot write file 'blocker/w_0.vtp'"),
    )


if __name__ == "__main__":
    main()
