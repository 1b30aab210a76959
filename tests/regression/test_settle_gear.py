"""The settling example (fix nve/gear) on 1 and 2 MPI ranks, and restarted midway:
all give the same state."""

import numpy as np

from liggghts_run import DeckTestCase, align_by_position, deck, full_precision, main, read_dump, run

RESTARTED = """
atom_modify     map array
newton          off
communicate     single vel yes
processors      * 1 1
read_restart    restart.half
neighbor        0.002 bin
neigh_modify    delay 0
fix  m1 all property/global youngsModulus peratomtype 1.0e7
fix  m2 all property/global poissonsRatio peratomtype 0.3
fix  m3 all property/global coefficientRestitution peratomtypepair 1 0.5
fix  m4 all property/global coefficientFriction peratomtypepair 1 0.0
fix  m5 all property/global characteristicVelocity scalar 1.0
pair_style      gran model hooke tangential no_history
pair_coeff      * *
timestep        1.0e-5
fix  gravi all gravity 9.81 vector 0.0 0.0 -1.0
fix  floor all wall/gran model hooke tangential no_history primitive type 1 zplane 0.0
fix  integr all nve/gear scheme {scheme}
thermo_style    custom step atoms ke
thermo          100
dump            d1 all custom {n} dump.settle_gear id x y z vx vy vz
dump_modify     d1 format "%d %.17g %.17g %.17g %.17g %.17g %.17g"
run             {n}
"""

COLUMNS = ("x", "y", "z", "vx", "vy", "vz")


def max_difference(a, b):
    return max(np.max(np.abs(a[c] - b[c])) for c in COLUMNS)


class SettleGear(DeckTestCase):
    def straight(self, np_ranks, nsteps, scheme="gear5"):
        r = run(full_precision(deck("examples/settle_gear/in.settle_gear"), "d1"), np_ranks=np_ranks,
                variables={"nsteps": nsteps, "dumpevery": nsteps, "scheme": scheme})
        self.assertRanCleanly(r)
        return r

    def test_one_and_two_ranks_agree(self):
        one = read_dump(self.straight(1, 300).path("dump.settle_gear"))
        two_run = self.straight(2, 300)
        self.assertIn("2 by 1 by 1 MPI processor grid", two_run.output)
        two = align_by_position(one, read_dump(two_run.path("dump.settle_gear")))
        diff = max_difference(one, two)
        print(f"1 vs 2 ranks after 300 steps: max |difference| = {diff:.3e}")
        self.assertLess(diff, 1e-10)

    def test_restart_reproduces_straight_run(self):
        for scheme in ("gear5", "verlet"):
            straight = read_dump(self.straight(1, 300, scheme).path("dump.settle_gear"))
            first = run(full_precision(deck("examples/settle_gear/in.settle_gear"), "d1") + "\nwrite_restart restart.half\n",
                        variables={"nsteps": 150, "dumpevery": 150, "scheme": scheme})
            self.assertRanCleanly(first)
            second = run(RESTARTED.format(scheme=scheme, n=150), workdir=first.workdir)
            self.assertRanCleanly(second)
            restarted = read_dump(second.path("dump.settle_gear"))
            self.assertTrue(np.array_equal(straight["id"], restarted["id"]))
            diff = max_difference(straight, restarted)
            print(f"{scheme}: restart at step 150 vs straight 300 steps: max |difference| = {diff:.3e}")
            self.assertLess(diff, 1e-12, scheme)


if __name__ == "__main__":
    main()
