"""input_scripts/in.run_until_quiet, the early end of a phase (in.column's ke_stop), on one
box sliding on a floor: it ends the phase only once the kinetic energy has stayed below the
threshold for the quiet time, and never while the box slides fast enough, however slowly
that is. The expected end comes from the box's velocity in closed form."""

import math
import re

from liggghts_run import SOURCE, DeckTestCase, grains_data, main, run

H = 1e-3          # time step
V0 = 1.0          # launch speed
BOX = "box 1.0 0.9 0.8"


def deck(friction, v0, ke_stop, t_quiet, chunk, steps, min_steps):
    # g = 1, a_max = 1: ke_rel is the kinetic energy per grain in m g a_max, as in in.column
    return f"""
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
grain_shapes    read grains.shapes
read_data       grains.data
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra tolerance 1e-10 wall 0 0 0 0 0 1 friction {friction}
timestep        {H}
compute         ke all ke update_on_run_end yes
variable        ke_rel equal c_ke/mass(all)
thermo_style    custom step c_ke
thermo          {chunk}
run             0
velocity        all set {v0} 0 0
variable        quiet_steps equal {steps}
variable        quiet_chunk equal {chunk}
variable        quiet_stop equal {ke_stop}
variable        quiet_time equal {t_quiet}
variable        quiet_min equal {min_steps}
variable        quiet_restart_steps equal 0
variable        quiet_restart_file string none
include         {SOURCE}/input_scripts/in.run_until_quiet
print           "phase over: step $(step) done ${{quiet_done}} ended ${{quiet_ended}}"
"""


def expected_end(mu, v0, ke_stop, t_quiet, chunk, steps, min_steps):
    """The step the phase ends at: the box's speed after n steps of the θ = 1 scheme is
    max(v0 − n μ g h, 0) (exact Coulomb friction, test_nscd.py WallFriction), its kinetic
    energy per m g a_max half its square; the rule of in.run_until_quiet on chunk ends."""
    done, quiet = 0, 0.0
    while done < steps:
        n = min(chunk, steps - done)
        done += n
        speed = max(v0 - done * mu * H, 0.0)
        quiet = quiet + n * H if 0.5 * speed * speed < ke_stop else 0.0
        if quiet >= t_quiet - 1e-9 and done >= min_steps:
            return done, 1
    return done, 0


class SlidingBox(DeckTestCase):
    @classmethod
    def setUpClass(cls):
        cls.made = grains_data(BOX, [(0, 0, 0.4, 1, 0, 0, 0)])

    def phase(self, friction, v0, ke_stop, t_quiet=2.0, chunk=500, steps=15200, min_steps=0):
        r = run(deck(friction, v0, ke_stop, t_quiet, chunk, steps, min_steps), workdir=self.made.workdir)
        self.assertRanCleanly(r)
        m = re.search(r"^phase over: step (\d+) done (\d+) ended (\d+)", r.output, re.M)
        got = tuple(int(g) for g in m.groups())
        want = expected_end(friction, v0, ke_stop, t_quiet, chunk, steps, min_steps)
        print(f"mu {friction}, v0 {v0}, ke_stop {ke_stop}, quiet {t_quiet}, min {min_steps}: ended at step {got[0]} "
              f"(early {got[2]}), expected {want[0]} (early {want[1]})")
        self.assertEqual(got[0], got[1])
        return got[0], got[2], want

    def test_decelerating_box_ends_after_its_quiet_time(self):
        # ½ v² < 0.004 from v < 0.0894, t > 9.11: the chunk ends at t = 9.5, 10, 10.5, 11
        # make 2 quiet time units: the phase ends at step 11000 of 15200
        step, early, want = self.phase(0.1, V0, 0.004)
        self.assertEqual((step, early), want)
        self.assertEqual(step, 11000)

    def test_not_before_the_minimum(self):
        step, early, want = self.phase(0.1, V0, 0.004, min_steps=12400)
        self.assertEqual((step, early), want)
        self.assertEqual(step, 12500)

    def test_slowly_sliding_box_keeps_the_phase_going(self):
        # frictionless: the box slides on at v0 = 0.1, ½ v0² = 0.005 = 1.25 ke_stop, to the
        # phase's last (partial) chunk
        step, early, want = self.phase(0.0, 0.1, 0.004)
        self.assertEqual((step, early), want)
        self.assertEqual((step, early), (15200, 0))

    def test_stopped_box_ends_at_the_first_quiet_time(self):
        # a box at rest from the start: quiet after the first t_quiet = 2 (4 chunks)
        step, early, want = self.phase(0.1, 0.0, 0.004)
        self.assertEqual((step, early), want)
        self.assertEqual((step, early), (2000, 1))


if __name__ == "__main__":
    main()
