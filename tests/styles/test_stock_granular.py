"""Stock LIGGGHTS keeps working in our build: frictional spheres (pair gran
hooke/history, fix nve/sphere, fix wall/gran) settle, and dump custom/vtk writes VTK."""

import glob
import re

import numpy as np

from liggghts_run import DeckTestCase, main, run

DECK = """
atom_style      granular
atom_modify     map array
boundary        p p f
newton          off
communicate     single vel yes
units           si
region          box block -0.03 0.03 -0.03 0.03 0.0 0.1 units box
create_box      1 box
neighbor        0.002 bin
neigh_modify    delay 0
fix  m1 all property/global youngsModulus peratomtype 5.0e6
fix  m2 all property/global poissonsRatio peratomtype 0.3
fix  m3 all property/global coefficientRestitution peratomtypepair 1 0.3
fix  m4 all property/global coefficientFriction peratomtypepair 1 0.5
fix  m5 all property/global characteristicVelocity scalar 1.0
pair_style      gran model hooke tangential history
pair_coeff      * *
timestep        1.0e-5
fix  gravi all gravity 9.81 vector 0.0 0.0 -1.0
fix  floor all wall/gran model hooke tangential history primitive type 1 zplane 0.0
lattice         sc 0.0105
region          fill block -0.03 0.03 -0.03 0.03 0.006 0.08 units box
create_atoms    1 region fill
set             group all diameter 0.01 density 2500
displace_atoms  all random 0.0002 0.0002 0.0002 32452843 units box
fix             integr all nve/sphere
compute         zmin all reduce min z
thermo_style    custom step atoms ke c_zmin
thermo_modify   format float %.10g norm no
thermo          2000
dump            vtk all custom/vtk 50000 particles_*.vtk id type x y z vx vy vz radius
run             50000
"""


class StockGranular(DeckTestCase):
    def test_spheres_settle_and_vtk_dump(self):
        r = run(DECK)
        self.assertRanCleanly(r)
        t = r.thermo()
        natoms = int(t["Atoms"][0])
        self.assertGreater(natoms, 100)
        self.assertTrue(np.all(t["Atoms"] == natoms))
        # at rest after 0.2 s: kinetic energy far below its value during the fall
        self.assertLess(t["KinEng"][-1], 1e-3 * np.max(t["KinEng"]))
        # no sphere sinks into the floor by more than 2 % of its radius
        self.assertGreater(t["zmin"][-1], 0.005 * 0.98)

        files = sorted(glob.glob(r.path("particles_[0-9]*.vtk")))
        self.assertEqual(len(files), 2, files)
        with open(files[-1], "rb") as f:
            head = f.read(4096).decode("latin-1")
        self.assertIn("vtk DataFile", head)
        m = re.search(r"POINTS (\d+)", head)
        self.assertIsNotNone(m, head[:500])
        self.assertEqual(int(m.group(1)), natoms)


if __name__ == "__main__":
    main()
