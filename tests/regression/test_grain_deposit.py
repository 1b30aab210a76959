"""examples/grain_deposit: 500 random grains poured into a box, undamped, settle under
NSCD (the kinetic energy falls from ~6 to below 1e-4 m g a_max per grain), overlaps stay
below the projection's tolerance, and the pile gives the same state on 1 and 2 ranks
after 100 more steps with the replicated solve (to the bit; the distributed solve, the
default on 2 ranks, agrees within its tolerance: tests/styles/test_distributed.py).

Whether this one deposit comes fully to rest (kinetic energy below 1e-8 m g a_max per grain)
is not asserted: the deposit is chaotic (a change of rounding in the solver gives another
pile) and some piles keep a grain rolling in a well of its neighbours' rounded edges,
which an undamped rigid model does not stop (docs/design.md, "Rolling resistance"; 4 of 6 seeds
were at rest at t = 40, 2026-11-27, commit 74bbd3f). Coming to rest is asserted
where nothing else can move a grain: four Table 1 grains dropped apart onto the floor
(test_lone_grains_come_to_rest), and the absence of the numerical push-out creep on the
cube sunk into the floor (tests/styles/test_nscd.py: no push-out speed at all)."""

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
fix             nscd all nscd/polyhedra tolerance 1e-6 solve replicated &
                wall 0 0 0 0 0 1 &
                wall -5 0 0 1 0 0 wall_friction 0 wall 5 0 0 -1 0 0 wall_friction 0 &
                wall 0 -5 0 0 1 0 wall_friction 0 wall 0 5 0 0 -1 0 wall_friction 0
timestep        1e-3
dump            d all custom 100 dump.{ranks} id x y z vx vy vz omegax omegay omegaz
run             100
"""


LONE_GRAINS = """
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
region          box block -4 4 -4 4 0 10
create_box      1 box
create_grains   1 4 layer box 1.6 seed 7 spacing 4
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra tolerance 1e-4 wall 0 0 0 0 0 1
timestep        1e-3
compute         rot all grain/rotation
compute         ket all ke
variable        ke equal c_ket+c_rot[1]
variable        mass equal mass(all)
thermo_style    custom step atoms f_nscd[3] v_ke f_nscd[9] v_mass
thermo_modify   norm no format float %.15g
thermo          1000
run             40000
"""


class LoneGrains(DeckTestCase):
    def test_lone_grains_come_to_rest(self):
        # four Table 1 grains on a 4 a_max lattice, dropped from 1.6 a_max onto the
        # frictional floor, undamped: each tumbles onto a face alone (no neighbour, no
        # well to roll in), so each must come to rest: below 1e-8 m g a_max per grain at
        # the last 10 samples (t = 31–40); measured at rest from t = 12–24 over seeds 7–12
        # (2026-11-27, commit 4638ea4), at ~1e-38 in all; the floor then carries m g exactly.
        r = run(LONE_GRAINS)
        self.assertRanCleanly(r)
        t = r.thermo(0)
        mass = t["mass"][-1]
        per_grain = t["ke"] / mass
        print(f"4 lone grains: kinetic energy per grain over t = 31–40 at most {per_grain[-10:].max():.2e}; "
              f"floor force / m g {-t['nscd[9]'][-1] / mass:.15f}")
        self.assertTrue(np.all(t["Atoms"] == 4))
        self.assertTrue(np.all(per_grain[-10:] < 1e-8), per_grain[-10:])
        self.assertAlmostEqual(-t["nscd[9]"][-1] / mass, 1.0, delta=1e-9)


class GrainDeposit(DeckTestCase):
    def test_settles(self):
        r = run(deck(EXAMPLE))
        self.assertRanCleanly(r)
        t = r.thermo(0)
        mass = t["mass"][-1]
        per_grain = t["ke"] / mass                   # in m g a_max per grain (g = a_max = 1)
        print(f"undamped deposit of 500: kinetic energy per grain, largest {per_grain.max():.3g}, "
              f"{per_grain[-5:]} over the last 5 samples; largest overlap at the end {t['nscd[4]'][-1]:.2e}, "
              f"of all steps {t['nscd[24]'][-1]:.6e}; floor force / m g {-t['nscd[9]'][-1] / mass:.10f}; "
              f"{t['nscd[3]'][-1]:.0f} contact points")
        self.assertTrue(np.all(t["Atoms"] == 500))
        # poured from up to 38 a_max: 6.1–7.3 m g a_max per grain at the peak (the 8
        # deposits of bench/nscd_pile_rest.py --seeds; 2026-11-27, commit 74bbd3f) ...
        self.assertGreater(per_grain.max(), 3.0)
        # ... settled by t = 21: over t = 21–25 at most 3.2e-5 in those 8 (seed 3, a rattler
        # rolling in a well), 2.1e-5 (seed 1, before its rattler stopped), 2.8e-6, and
        # 1.7e-7 and below in the other five
        self.assertTrue(np.all(per_grain[-5:] < 1e-4), per_grain[-5:])
        # transient overlaps during the impacts of the deposition: the projection (default
        # project 5e-5) leaves at most 5e-5 R per pair, R the smaller bounding radius of the
        # pair, at most 1.1614 a_max among these grains (LIGGGHTS' radius, compute reduce
        # max); without it they reached 1.3e-3 a_max. With overlap_recovery 0 the ones below
        # the tolerance stay
        self.assertLess(t["nscd[24]"][-1], 5e-5 * 1.1614)

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
