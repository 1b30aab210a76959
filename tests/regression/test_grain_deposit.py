"""examples/grain_deposit: 500 random grains poured into a box and quenched (damping
1000) come to rest under NSCD (kinetic energy below 1e-8 of m g a_max per grain, overlaps
below 1e-3 a_max at the end), and the pile gives the same state on 1 and 2 ranks after
100 more steps."""

import numpy as np

from liggghts_run import DeckTestCase, deck, full_precision, main, read_dump, run

EXAMPLE = "examples/grain_deposit/in.grain_deposit"
COLUMNS = ("x", "y", "z", "vx", "vy", "vz", "omegax", "omegay", "omegaz")

CONTINUE = """
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
processors      * 1 1
read_restart    grain_deposit.restart
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra tolerance 1e-6 &
                wall 0 0 0 0 0 1 &
                wall -5 0 0 1 0 0 wall_friction 0 wall 5 0 0 -1 0 0 wall_friction 0 &
                wall 0 -5 0 0 1 0 wall_friction 0 wall 0 5 0 0 -1 0 wall_friction 0
timestep        1e-3
dump            d all custom 100 dump.{ranks} id x y z vx vy vz omegax omegay omegaz
run             100
"""


class GrainDeposit(DeckTestCase):
    def test_comes_to_rest(self):
        r = run(deck(EXAMPLE))
        self.assertRanCleanly(r)
        settle, relax, rest = r.thermo(0), r.thermo(1), r.thermo(2)
        mass = rest["mass"][-1]
        threshold = 1e-8 * mass * 1.0 * 1.0          # 1e-8 m g a_max per grain, summed
        ke = rest["ke"][-1]
        print(f"deposit of 500: kinetic energy {settle['ke'][-1]:.3g} after the settling, "
              f"{relax['ke'][-1]:.3g} after damping, {ke:.3g} at the end (threshold {threshold:.3g}); "
              f"largest overlap at the end {rest['nscd[4]'][-1]:.2e}, of all steps {rest['nscd[24]'][-1]:.6e}; "
              f"floor force {-rest['nscd[9]'][-1]:.6f} (m g = {mass:.6f}); {rest['nscd[3]'][-1]:.0f} contact points")
        self.assertTrue(np.all(rest["Atoms"] == 500))
        self.assertLess(ke, threshold)
        self.assertLess(rest["nscd[4]"][-1], 1e-3)
        # transient overlaps during the impacts of the deposition: the projection (default
        # project 5e-5) leaves at most 5e-5 R per pair, R the smaller bounding radius of the
        # pair, at most 1.1614 a_max among these grains (LIGGGHTS' radius, compute reduce
        # max); without it they reached 1.3e-3 a_max. The resting state's are at round-off
        # of the 1e-6 solve
        self.assertLess(rest["nscd[24]"][-1], 5e-5 * 1.1614)
        # the frictional floor carries the weight (frictionless side walls) but for what the
        # quench's damping carries: the pile still creeps (about 2e-5 a_max per time unit,
        # 1.7 % of the weight); a static pile would give exactly m g
        self.assertAlmostEqual(-rest["nscd[9]"][-1] / mass, 1.0, delta=0.02)

        states = {}
        for ranks in (1, 2):
            c = run(full_precision(CONTINUE.format(ranks=ranks), "d"), np_ranks=ranks, workdir=r.workdir)
            self.assertRanCleanly(c)
            states[ranks] = read_dump(c.path(f"dump.{ranks}"))
        difference = max(np.max(np.abs(states[1][k] - states[2][k])) for k in COLUMNS)
        print(f"settled pile, 100 more steps: 1 vs 2 ranks differ by {difference:.2e}")
        self.assertLess(difference, 1e-12)


if __name__ == "__main__":
    main()
