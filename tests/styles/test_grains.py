"""Grains without contacts (atom_style polyhedron, fix nve/polyhedron, compute
grain/rotation, grain_shapes): the torque-free top, free fall, data files, MPI and
restarts, and the error messages."""

import math
import re

import numpy as np

from liggghts_run import DeckTestCase, full_precision, main, read_dump, run

HEADER = """
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
processors      * 1 1
region          box block -6 6 -6 6 -6 6
create_box      1 box
"""


def quaternion_matrix(w, x, y, z):
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def set_body_angular_velocity(data_text, omega_body):
    """Data file text with every grain's angular velocity set to omega_body (body frame),
    converted to the space frame with the grain's quaternion from the Atoms section."""
    lines = data_text.splitlines()
    atoms = lines.index("Atoms") if "Atoms" in lines else next(k for k, l in enumerate(lines) if l.startswith("Atoms"))
    quats = {}
    k = atoms + 2
    while k < len(lines) and lines[k].strip():
        w = lines[k].split()
        quats[w[0]] = [float(v) for v in w[4:8]]
        k += 1
    vel = next(k for k, l in enumerate(lines) if l.startswith("Velocities"))
    k = vel + 2
    while k < len(lines) and lines[k].strip():
        w = lines[k].split()
        omega = quaternion_matrix(*quats[w[0]]) @ np.array(omega_body)
        lines[k] = " ".join(w[:4] + [repr(float(c)) for c in omega])
        k += 1
    return "\n".join(lines) + "\n"


def make_box_grain():
    """One box grain 1 x 2 x 3 (principal moments ascending along body x, y, z), written
    to a data file and a shape file."""
    r = run(HEADER + """
create_grains   1 1 random box seed 4711 shape box 1 2 3 sweep 0
write_data      grain.data
grain_shapes    write grain.shapes
""")
    return r


class TorqueFreeTop(DeckTestCase):
    # Box 1 x 2 x 3, density 1.5: I = m (2.5, 5, 6.5)/6 · ... ascending; spun about one
    # principal axis with a 1 % perturbation. Energy and |L| are conserved; the rotation
    # about the intermediate axis flips (Dzhanibekov), about the others it does not.
    def spin(self, axis):
        made = make_box_grain()
        self.assertRanCleanly(made)
        omega = [0.01, 0.01, 0.01]
        omega[axis] = 1.0
        with open(made.path("grain.data")) as f:
            data = set_body_angular_velocity(f.read(), omega)
        with open(made.path("grain.data"), "w") as f:
            f.write(data)
        r = run("""
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
grain_shapes    read grain.shapes
read_data       grain.data
fix             int all nve/polyhedron rotation splitting4
compute         rot all grain/rotation
variable        w2 equal c_rot[1]
variable        lnorm equal sqrt(c_rot[2]^2+c_rot[3]^2+c_rot[4]^2)
compute         wb all reduce sum c_rot[5] c_rot[6] c_rot[7]
timestep        2e-3
thermo_style    custom step time c_rot[1] v_lnorm c_wb[1] c_wb[2] c_wb[3]
thermo_modify   format float %.16g
thermo          20
run             10000
""", workdir=made.workdir)
        self.assertRanCleanly(r)
        return r.thermo()

    def test_conservation_and_intermediate_axis_flip(self):
        names = ("smallest", "intermediate", "largest")
        for axis in range(3):
            t = self.spin(axis)
            energy, lnorm = t["rot[1]"], t["lnorm"]
            w = t[f"wb[{axis + 1}]"]
            e_err = np.max(np.abs(energy - energy[0])) / energy[0]
            l_err = np.max(np.abs(lnorm - lnorm[0])) / lnorm[0]
            flips = int(np.sum(np.diff(np.sign(w)) != 0))
            print(f"spin about the {names[axis]} axis: energy error {e_err:.2e}, |L| error {l_err:.2e}, "
                  f"sign changes of that body component over t=20: {flips}")
            self.assertLess(e_err, 1e-8)
            self.assertLess(l_err, 1e-12)
            if axis == 1:
                self.assertGreaterEqual(flips, 1)
            else:
                self.assertEqual(flips, 0)
                self.assertGreater(np.min(np.abs(w)), 0.9)


class GrainRotationOfAMixedGroup(DeckTestCase):
    def test_beads_get_zero_rows(self):
        # compute grain/rotation on 'all' of atom_style hybrid polyhedron wire: the 11 beads
        # get zero rows (unfiltered, the quaternion of a shapeless atom), the cube its unit
        # quaternion, and the vector is that of the grain group
        r = run("""
units           lj
atom_style      hybrid polyhedron wire
atom_modify     map array sort 0 0.0
boundary        f f f
region          box block -4 4 -4 4 -1 6
create_box      2 box
create_grains   1 1 random box seed 3 shape cube 1
create_wire     2 line -1 0 5 1 0 5
group           grains type 1
group           wire type 2
compute         r all grain/rotation
compute         rg grains grain/rotation
compute         qw wire reduce sum c_r[1] c_r[2] c_r[3] c_r[4]
compute         qg grains reduce sum c_r[1] c_r[2] c_r[3] c_r[4]
thermo_style    custom step c_qw[1] c_qw[2] c_qw[3] c_qw[4] c_qg[1] c_qg[2] c_qg[3] c_qg[4] c_r[1] c_rg[1]
thermo_modify   format float %.17g norm no
run             0
""")
        self.assertRanCleanly(r)
        t = r.thermo()
        for k in range(1, 5):
            self.assertEqual(t[f"qw[{k}]"][0], 0.0)
        self.assertAlmostEqual(sum(t[f"qg[{k}]"][0] ** 2 for k in range(1, 5)), 1.0, delta=1e-15)
        self.assertEqual(t["r[1]"][0], t["rg[1]"][0])


class FreeFall(DeckTestCase):
    def test_free_fall_exact(self):
        r = run(HEADER + """
region          top block -4 4 -4 4 1 5
create_grains   1 3 random top seed 99 density 1.5
fix             int all nve/polyhedron
fix             g all gravity 1.0 vector 0 0 -1
variable        z1 equal z[1]
timestep        1e-2
thermo_style    custom step time v_z1
thermo_modify   format float %.16g
thermo          10
run             200
""")
        self.assertRanCleanly(r)
        t = r.thermo()
        z = t["z1"][0] - 0.5 * t["Time"] ** 2
        self.assertLess(np.max(np.abs(t["z1"] - z)), 1e-12)


SPIN = """
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
processors      * 1 1
grain_shapes    read g.shapes
read_data       g.data
fix             g all gravity 1.0 vector 0 0 -1
fix             int all nve/polyhedron
timestep        1e-3
dump            d all custom 100 dump.g id x y z vx vy vz omegax omegay omegaz angmomx angmomy angmomz
"""


def spinning_grains():
    """12 grains in a layer, written to g.data with body angular velocity (0.3, 1.0, -0.5)
    and a sideways velocity, and to g.shapes."""
    made = run(HEADER + """
create_grains   1 12 layer box -3 seed 2024
velocity        all set 0.3 0.0 0.1
write_data      g.data
grain_shapes    write g.shapes
""")
    with open(made.path("g.data")) as f:
        data = set_body_angular_velocity(f.read(), [0.3, 1.0, -0.5])
    with open(made.path("g.data"), "w") as f:
        f.write(data)
    return made


class DataFilesAndRestarts(DeckTestCase):
    def test_data_file_round_trip(self):
        first = run(HEADER + """
create_grains   1 10 random box seed 31337
write_data      g.data
grain_shapes    write g.shapes
""")
        self.assertRanCleanly(first)
        second = run("""
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
grain_shapes    read g.shapes
read_data       g.data
write_data      g2.data
grain_shapes    write g2.shapes
""", workdir=first.workdir)
        self.assertRanCleanly(second)

        def numbers(name, start):
            with open(first.path(name)) as f:
                text = f.read()
            return np.array([float(w) for w in re.findall(r"-?\d[\d.eE+-]*", text[text.index(start):])])
        # the same grains: orientations are renormalised on reading (last-digit changes)
        for name, start in (("g.data", "Atoms"), ("g.shapes", "wiregrain")):
            a, b = numbers(name, start), numbers(name.replace("g.", "g2."), start)
            self.assertEqual(len(a), len(b))
            self.assertLess(np.max(np.abs(a - b) / np.maximum(1.0, np.abs(a))), 1e-14, name)
        # without the shapes the data file cannot be read
        third = run("""
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
read_data       g.data
""", workdir=first.workdir)
        self.assertStopsWith(third, "atom_style polyhedron: Atoms section of data file: shape '")

    def test_sphere_shapes_round_trip(self):
        """Sphere grains (one vertex, the radius as sweep) through grain_shapes write/read
        and write_data/read_data: the same file, the same grains, mass ρ 4/3 π R³."""
        first = run(HEADER + """
create_grains   1 8 random box seed 77 shape sphere 0.45 density 2.0
write_data      g.data
grain_shapes    write g.shapes
""")
        self.assertRanCleanly(first)
        with open(first.path("g.shapes")) as f:
            text = f.read()
        self.assertEqual(text, "wiregrain shapes 1 mass dilated\nshape 0 sweep 0.45000000000000001 vertices 1\n0 0 0\n")
        second = run("""
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
grain_shapes    read g.shapes
read_data       g.data
write_data      g2.data
grain_shapes    write g2.shapes
dump            d all custom 1 dump.g id mass
dump_modify     d format "%d %.17g"
run             0
""", workdir=first.workdir)
        self.assertRanCleanly(second)
        with open(first.path("g2.shapes")) as f:
            self.assertEqual(f.read(), text)

        def atoms(name):
            with open(first.path(name)) as f:
                lines = f.read().splitlines()
            k = lines.index("Atoms # polyhedron") if "Atoms # polyhedron" in lines else next(
                i for i, l in enumerate(lines) if l.startswith("Atoms"))
            rows = []
            for line in lines[k + 2:]:
                if not line.strip():
                    break
                rows.append([float(w) for w in line.split()])
            return np.array(sorted(rows))
        a, b = atoms("g.data"), atoms("g2.data")
        self.assertEqual(len(a), 8)
        self.assertLess(np.max(np.abs(a - b)), 1e-14)
        np.testing.assert_allclose(read_dump(first.path("dump.g"))["mass"], 2.0 * 4 / 3 * math.pi * 0.45 ** 3,
                                   rtol=1e-15)

    def test_one_and_two_ranks_and_restart(self):
        made = spinning_grains()
        self.assertRanCleanly(made)
        deck = full_precision(SPIN, "d")
        one = run(deck + "run 300\n", workdir=made.workdir)
        two = run(deck.replace("dump.g", "dump2.g") + "run 300\n", workdir=made.workdir, np_ranks=2)
        half = run(deck.replace("dump.g", "dump3.g") + "run 150\nwrite_restart g.restart\n", workdir=made.workdir)
        for r in (one, two, half):
            self.assertRanCleanly(r)
        self.assertIn("2 by 1 by 1 MPI processor grid", two.output)
        restarted = run("""
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
processors      * 1 1
read_restart    g.restart
fix             g all gravity 1.0 vector 0 0 -1
fix             int all nve/polyhedron
timestep        1e-3
dump            d all custom 150 dump4.g id x y z vx vy vz omegax omegay omegaz angmomx angmomy angmomz
dump_modify     d format "%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g"
run             150
""", workdir=half.workdir)
        self.assertRanCleanly(restarted)
        a, b, c = (read_dump(made.path(name)) for name in ("dump.g", "dump2.g", "dump4.g"))
        cols = ("x", "y", "z", "vx", "vy", "vz", "omegax", "omegay", "omegaz", "angmomx", "angmomy", "angmomz")
        ranks = max(np.max(np.abs(a[k] - b[k])) for k in cols)
        restart = max(np.max(np.abs(a[k] - c[k])) for k in cols)
        self.assertGreater(np.max(np.abs(a["omegax"])), 0.0)
        print(f"grains: 1 vs 2 ranks after 300 steps {ranks:.2e}, restart at 150 vs straight {restart:.2e}")
        self.assertLess(ranks, 1e-12)
        self.assertLess(restart, 1e-12)


class BadInput(DeckTestCase):
    def test_messages(self):
        self.assertStopsWith(run(HEADER.replace("atom_style      polyhedron", "atom_style      polyhedron mass heavy")),
                             "atom_style polyhedron: value of 'mass' must be dilated or sharp, got 'heavy'")
        self.assertStopsWith(run(HEADER + "create_grains 1 2 random box seed 5\nfix int all nve/polyhedron rotation exact\nrun 1\n"),
                             "fix nve/polyhedron (id int): value of 'rotation' must be splitting2 or splitting4, got 'exact'")
        self.assertStopsWith(run(HEADER + "create_grains 1 2 random box seed 5\nfix a all nve/polyhedron\nfix b all nve/polyhedron\nrun 1\n"),
                             "fix nve/polyhedron (id a): 2 grains are also integrated by fix b (nve/polyhedron)")
        self.assertStopsWith(run(HEADER + "create_atoms 1 single 0 0 0\nfix a all nve/polyhedron\nrun 1\n"),
                             "fix nve/polyhedron (id a): 1 grains have no shape")
        self.assertStopsWith(run(HEADER + "grain_shapes read nowhere.shapes\n"),
                             "command grain_shapes (id -): cannot open 'nowhere.shapes'")
        # a one-vertex shape is a sphere and needs a radius; two vertices are no shape
        point = "wiregrain shapes 1 mass dilated\nshape 0 sweep 0 vertices 1\n0 0 0\n"
        self.assertStopsWith(run(HEADER + "grain_shapes read p.shapes\n", files={"p.shapes": point}),
                             "command grain_shapes (id -): 'p.shapes': one point is a sphere and needs "
                             "sweep_radius > 0 (its radius), got 0")
        two = "wiregrain shapes 1 mass dilated\nshape 0 sweep 0.5 vertices 2\n0 0 0\n1 0 0\n"
        self.assertStopsWith(run(HEADER + "grain_shapes read t.shapes\n", files={"t.shapes": two}),
                             "command grain_shapes (id -): 't.shapes': shape 0 is malformed")
        wire = HEADER.replace("atom_style      polyhedron", "atom_style      wire")
        self.assertStopsWith(run(wire + "fix a all nve/polyhedron\n"),
                             "fix nve/polyhedron (id a): needs atom_style polyhedron")
        self.assertStopsWith(run(wire + "compute r all grain/rotation\n"),
                             "compute grain/rotation (id r): needs atom_style polyhedron")


if __name__ == "__main__":
    main()
