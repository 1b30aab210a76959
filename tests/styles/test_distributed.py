"""fix nscd/polyhedra solve distributed: each rank steps the grain pairs it owns with its
own and ghost grains. On one rank it is the replicated solve to the bit (Gauss-Seidel); a
tall stack carries its weight exactly on 1 to 4 ranks (the stick solve by conjugate
gradients over the ranks); one step of a 500-grain pile from the same state finds the same contact
points and velocities within the solver's tolerance on 1 to 4 ranks, as does one step of a
short column with its wire; a run continued from
a restart file repeats the straight run on 2 ranks to the bit; a stack of two cubes
sliding across the ranks' boundary stops where the discrete equations of motion say, to
round-off, on 1 and 2 ranks; a wire loop cut by two subdomains hands its loads on a ghost
grain to the grain's owner; the solves, sweeps and traffic the fix counts add up; the
default, solve auto, takes it on more than one rank and not on one or with sleeping grains;
what it does not carry stops with an ERROR."""

import numpy as np

from liggghts_run import (SOURCE, DeckTestCase, full_precision, grains_data, main, read_dump, read_local_dump, run)
from liggghts_run import deck as deck_file
from test_periodic import periodic_pile
import test_nscd

HEAD = """
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        {boundary}
processors      {processors}
"""


def deck(body, boundary="f f f", processors="* * *"):
    """A deck on grains.data and grains.shapes (grains_data) with `body` after them."""
    return HEAD.format(boundary=boundary, processors=processors) + f"""grain_shapes    read grains.shapes
read_data       grains.data
{body}
"""


def random_pile(count, box, seed, margin=0.0):
    """grains.data and grains.shapes of `count` random grains (create_grains) in the lower
    half of `box` (xlo xhi ylo yhi zlo zhi), kept apart, `margin` from its sides (room to
    spread on the floor without leaving the box)."""
    xlo, xhi, ylo, yhi, zlo, zhi = box
    return run(f"""
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
region          box block {xlo} {xhi} {ylo} {yhi} {zlo} {zhi}
create_box      1 box
region          fill block {xlo + margin} {xhi - margin} {ylo + margin} {yhi - margin} {zlo + 0.5} {0.5 * (zlo + zhi)}
create_grains   1 {count} random fill seed {seed}
write_data      grains.data
grain_shapes    write grains.shapes
""")


class OneRank(DeckTestCase):
    # 30 random grains fall onto a frictional floor for 2000 steps with method
    # gauss_seidel: solve distributed on one rank (its own grains, no ghosts, the same
    # pairs in the same order, the sums over one worker) is the replicated solve to the
    # last bit. Measured: identical.
    def test_one_rank_is_the_replicated_solve(self):
        made = random_pile(30, (-4, 4, -4, 4, 0, 10), 11)
        self.assertRanCleanly(made)
        states = {}
        for mode in ("replicated", "distributed"):
            text = full_precision(deck(f"""
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra tolerance 1e-6 method gauss_seidel solve {mode} wall 0 0 0 0 0 1
timestep        1e-3
dump            d all custom 2000 dump.{mode} id x y z vx vy vz omegax omegay omegaz f_nscd[3]
run             2000
"""), "d")
            r = run(text, workdir=made.workdir)
            self.assertRanCleanly(r)
            states[mode] = read_dump(made.path(f"dump.{mode}"))
        a, b = states["replicated"], states["distributed"]
        self.assertGreater(np.max(np.abs(a["f_nscd[3]"])), 0.0)  # in contact
        for k in a:
            np.testing.assert_array_equal(b[k], a[k], err_msg=k)


class TallStack(DeckTestCase):
    # 50 unit cubes (m = 1) stacked on a frictional floor, g = 1, the default solver
    # (method subspace, tolerance 1e-4), the subdomains cutting the stack across (processors
    # 1 1 *): on 1, 2, 3 and 4 ranks the floor carries 50 m g, interface k from the top k m
    # g, and the top cube does not move, on every sample of 100 steps, with one sweep per
    # step (the stick solve, conjugate gradients over the ranks, makes the step exact).
    # Gauss-Seidel alone hits the sweep cap (1000) every step and leaves the floor 1e-3 off.
    # Measured (2026-12-06): floor 2.0e-15, interfaces 7.8e-16 relative, the top moved
    # 2.5e-12 at most (the stick solve's CG stops at 1e-12 of its right-hand side), at most
    # 2 sweeps; held to 1e-12, 1e-12 and 1e-10.
    N = 50

    def test_stack_on_one_to_four_ranks(self):
        n = self.N
        made = grains_data("cube 1.0", [(0, 0, 0.5 + k, 1, 0, 0, 0) for k in range(n)], box=(-3, 3, -3, 3, -1, n + 2))
        self.assertRanCleanly(made)
        k = np.arange(1, n + 1)
        for ranks in (1, 2, 3, 4):
            r = run(full_precision(deck(f"""
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra friction 0.5 solve distributed wall 0 0 0 0 0 1
timestep        1e-3
variable        ztop equal bound(all,zmax)
thermo_style    custom step f_nscd[9] f_nscd[1] f_nscd[6] v_ztop
thermo_modify   format float %.17g
thermo          10
dump            d all custom 20 dump.{ranks} id z f_nscd[3]
run             100
""", processors="1 1 *"), "d"), workdir=made.workdir, np_ranks=ranks)
            self.assertRanCleanly(r)
            t = r.thermo()
            floor = np.max(np.abs(-t["nscd[9]"][1:] / n - 1.0))
            top = np.max(np.abs(t["ztop"] - (n - 0.5)))
            d = read_dump(r.path(f"dump.{ranks}"))
            order = np.argsort(-d["z"])
            interface = np.max(np.abs(np.cumsum(d["f_nscd[3]"][order]) / k - 1.0))
            print(f"\n{n}-cube stack on {ranks} rank(s): floor {floor:.1e}, interfaces {interface:.1e}, top moved "
                  f"{top:.1e}, sweeps {t['nscd[1]'].max():.0f}, capped steps {t['nscd[6]'][-1]:.0f}")
            self.assertLess(floor, 1e-12)
            self.assertLess(interface, 1e-12)
            self.assertLess(top, 1e-10)
            self.assertEqual(t["nscd[6]"][-1], 0)


class Counts(DeckTestCase):
    # The counts the fix reports for sizing runs (docs/commands/fix_nscd_polyhedra.md,
    # f_ID[25+3W+4P..29+3W+4P]) on the 50-cube stack, 20 steps, every step's sweeps
    # printed: the solves are the steps run (one NSCD step per timestep here, the setup's
    # solve included when it is made), the sweeps their sum over the steps; one rank sends
    # no values (no neighbour), two ranks cut across the stack send some, with at least
    # one communication round and one reduction per sweep (the sweeps exchange the
    # boundary grains' velocities and test convergence on a global residual).
    def test_solves_sweeps_and_traffic(self):
        n = 50
        made = grains_data("cube 1.0", [(0, 0, 0.5 + k, 1, 0, 0, 0) for k in range(n)], box=(-3, 3, -3, 3, -1, n + 2))
        self.assertRanCleanly(made)
        counts = {}
        for ranks in (1, 2):
            r = run(deck(f"""
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra friction 0.5 method gauss_seidel solve distributed wall 0 0 0 0 0 1
timestep        1e-3
thermo_style    custom step f_nscd[1] f_nscd[28] f_nscd[29] f_nscd[30] f_nscd[31] f_nscd[32]
thermo_modify   format float %.17g
thermo          1
run             20
""", processors="1 1 *"), workdir=made.workdir, np_ranks=ranks)
            self.assertRanCleanly(r)
            t = r.thermo()
            solves, sweeps = t["nscd[28]"], t["nscd[29]"]
            # step 0 prints the setup's solve (if any); each later step adds one solve and its sweeps
            np.testing.assert_array_equal(np.diff(solves), np.ones(20))
            np.testing.assert_array_equal(np.diff(sweeps), t["nscd[1]"][1:])
            self.assertGreater(sweeps[-1] - sweeps[0], 20)
            counts[ranks] = (sweeps[-1], t["nscd[30]"][-1], t["nscd[31]"][-1], t["nscd[32]"][-1])
            print(f"\n{ranks} rank(s): solves {solves[-1]:.0f}, sweeps {sweeps[-1]:.0f}, values sent "
                  f"{counts[ranks][1]:.0f}, rounds {counts[ranks][2]:.0f}, reductions {counts[ranks][3]:.0f}")
        sweeps, values, rounds, reductions = counts[1]
        self.assertEqual(values, 0.0)
        sweeps, values, rounds, reductions = counts[2]
        self.assertGreater(values, 0.0)
        self.assertGreaterEqual(rounds, sweeps)
        self.assertGreaterEqual(reductions, sweeps)


class PileStep(DeckTestCase):
    # 500 random grains dropped onto a frictional floor for 4000 steps (replicated; the
    # highest still falling), the state written to a restart file; from it, one NSCD step
    # (tolerance 1e-10) distributed on 1, 2, 3 and 4 ranks and replicated on 1: the
    # detection finds the same contact points (pairs and points to round-off: the same
    # pairs' manifolds computed from the same poses), and the solve the same velocities
    # within its tolerance. Measured: the same 1581 points on every run; velocities within
    # 1.2e-9 (2 ranks), 2.4e-8 (3) and 7.1e-8 (4) of the largest speed 4.0 (2026-12-07).
    # Held: the points' coordinates to 1e-12, the velocities to 5e-8 of that speed.
    def test_one_step_on_one_to_four_ranks(self):
        made = random_pile(500, (-12, 12, -12, 12, 0, 24), 23, margin=2)
        self.assertRanCleanly(made)
        r = run(deck("""
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra wall 0 0 0 0 0 1
timestep        1e-3
run             4000
write_restart   pile.restart
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        step = """
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra tolerance 1e-10 max_iterations 100000 solve {mode} wall 0 0 0 0 0 1
compute         cl all contact/local
timestep        1e-3
dump            d all custom 1 dump.{tag} id vx vy vz omegax omegay omegaz
dump            dl all local 1 local.{tag} c_cl[1] c_cl[2] c_cl[3] c_cl[4] c_cl[5] c_cl[6]
dump_modify     dl format "%g %g %g %.17g %.17g %.17g"
run             1
"""
        runs = {}
        for mode, ranks in (("replicated", 1), ("distributed", 1), ("distributed", 2), ("distributed", 3),
                            ("distributed", 4)):
            tag = f"{mode}{ranks}"
            # (the subdomains split x and y: the pile lies across them)
            text = full_precision(HEAD.format(boundary="f f f", processors="* * 1") + "read_restart pile.restart\n" +
                                  step.format(mode=mode, tag=tag), "d")
            r = run(text, workdir=made.workdir, np_ranks=ranks)
            self.assertRanCleanly(r)
            points = read_local_dump(made.path(f"local.{tag}"))
            rows = np.column_stack([points[f"c_cl[{c}]"] for c in range(1, 7)])
            rows = rows[np.lexsort(rows.T[::-1])]
            runs[tag] = (read_dump(made.path(f"dump.{tag}")), rows)
        reference, reference_rows = runs["replicated1"]
        speed = max(np.max(np.abs(reference[c])) for c in ("vx", "vy", "vz"))
        self.assertEqual(len(reference["id"]), 500)
        self.assertGreater(len(reference_rows), 1000)  # a pile: grain-grain and floor points
        for tag, (state, rows) in runs.items():
            velocities = max(np.max(np.abs(state[c] - reference[c])) for c in
                             ("vx", "vy", "vz", "omegax", "omegay", "omegaz"))
            print(f"\n{tag}: {len(rows)} contact points (replicated {len(reference_rows)}), velocities within "
                  f"{velocities:.1e} of the largest speed {speed:.2e}")
            self.assertEqual(rows.shape, reference_rows.shape, tag)
            np.testing.assert_array_equal(rows[:, :3], reference_rows[:, :3], err_msg=tag)
            self.assertLess(np.max(np.abs(rows[:, 3:] - reference_rows[:, 3:])), 1e-12, tag)
            self.assertLess(velocities, 5e-8 * speed, tag)


class ShortColumnStep(DeckTestCase):
    # The paper's procedure on a short column (input_scripts/in.column: 24 grains in 2
    # layers, a double loop of R = 3), replicated, to the end of its relaxation (t = 2.5,
    # column_relaxed.restart: the column standing in its container); from it, one NSCD step (its
    # N = 2 wire sub-steps), its contacts with the
    # grains, and the grains' NSCD step at tolerance 1e-10, distributed on 1 to 4 ranks (the
    # subdomains cut the column along x and y) and replicated on 1: the grains' velocities
    # agree within the solver's tolerance and the beads' to the round-off of their forces'
    # order of summation. Measured: grains within 0 (2 and 3 ranks) and 5.5e-11 (4 ranks,
    # whose subdomains cut grain pairs) of the largest grain speed, beads within 1.1e-19 of
    # the largest bead speed; held to 5e-8 and 1e-12 (without the mass splitting the 4
    # ranks' grains are 3.1e-4 off).
    TINY = {"R": 3, "nlayers": 2, "Np": 24, "t_layer": 0.5, "t_relax": 2.5, "t_end": 3.5, "t_obs": 0.1}

    def test_one_step_on_one_to_four_ranks(self):
        column = deck_file("input_scripts/in.column")
        variables = dict(self.TINY, root=SOURCE)
        straight = run(column, variables=variables)
        self.assertRanCleanly(straight)
        states = {}
        for mode, ranks in (("replicated", 1), ("distributed", 1), ("distributed", 2), ("distributed", 3),
                            ("distributed", 4)):
            r = run(column, workdir=straight.workdir, np_ranks=ranks,
                    variables=dict(variables, resume=1, t_end=2.502, solve=mode, nscd_tolerance=1e-10))
            self.assertRanCleanly(r)
            self.assertRegex(r.output, r"Loop time of \S+ on \d+ procs for 2 steps")
            states[f"{mode}{ranks}"] = read_dump(r.path("post/column_final_2502.dump"))
        reference = states["replicated1"]
        grains, beads = reference["type"] == 1, reference["type"] == 2
        self.assertGreater(np.count_nonzero(beads), 0)
        speed = {kind: max(np.max(np.abs(reference[c][rows])) for c in ("vx", "vy", "vz"))
                 for kind, rows in (("grains", grains), ("beads", beads))}
        for tag, state in states.items():
            np.testing.assert_array_equal(state["id"], reference["id"], err_msg=tag)
            worst = {kind: max(np.max(np.abs(state[c][rows] - reference[c][rows])) for c in ("vx", "vy", "vz"))
                     / speed[kind] for kind, rows in (("grains", grains), ("beads", beads))}
            print(f"\n{tag}: grains' velocities within {worst['grains']:.1e} of the largest grain speed "
                  f"{speed['grains']:.2e}, beads' within {worst['beads']:.1e} of {speed['beads']:.2e}")
            self.assertLess(worst["grains"], 5e-8, tag)
            self.assertLess(worst["beads"], 1e-12, tag)


class PeriodicRestart(DeckTestCase):
    # 30 grains fall onto a frictional floor in a box periodic along x and y, launched
    # sideways so that they cross the faces and the subdomain boundaries (2 ranks split x)
    # while in contact: a run continued from a restart file written in the middle repeats
    # the straight run to the bit on 2 ranks (the warm starts of both ranks are in the file,
    # the ghosts are taken in tag order whatever LIGGGHTS' storage order). Measured: 0.
    def test_restart_on_two_ranks(self):
        made = periodic_pile()
        self.assertRanCleanly(made)
        body = """
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra tolerance 1e-6 solve distributed wall 0 0 0 0 0 1
timestep        1e-3
thermo_style    custom step f_nscd[3]
thermo          100
dump            d all custom 3000 {dump} id x y z ix iy vx vy vz omegax omegay omegaz
"""
        straight = full_precision(deck("velocity        all set 0.8 0.5 0.0\n" + body.format(dump="dump.a"), "p p f"),
                                  "d") + "run 3000\n"
        r = run(straight, workdir=made.workdir, np_ranks=2)
        self.assertRanCleanly(r)
        half = full_precision(deck("velocity        all set 0.8 0.5 0.0\n" + body.format(dump="dump.h"), "p p f"),
                              "d") + "run 1500\nwrite_restart pile.restart\n"
        self.assertRanCleanly(run(half, workdir=made.workdir, np_ranks=2))
        rest = full_precision(HEAD.format(boundary="p p f", processors="* * *") + "read_restart pile.restart\n" +
                              body.format(dump="dump.b"), "d") + "run 1500\n"
        r = run(rest, workdir=made.workdir, np_ranks=2)
        self.assertRanCleanly(r)
        a, b = read_dump(made.path("dump.a")), read_dump(made.path("dump.b"))
        wrapped = int(np.sum((a["ix"] != 0) | (a["iy"] != 0)))
        print(f"\nperiodic pile on 2 ranks, distributed: {wrapped} grains wrapped, {r.thermo()['nscd[3]'][-1]:.0f} "
              f"contact points at the end; restart against straight "
              f"{max(np.max(np.abs(a[k] - b[k])) for k in a):.1e}")
        self.assertGreater(wrapped, 5)
        for k in a:
            np.testing.assert_array_equal(b[k], a[k], err_msg=k)


class SlidingStackAcrossRanks(DeckTestCase):
    # Two unit cubes (m = 1), one on the other and offset by 0.1 along x, slide along x on a
    # floor of friction 0.3 (the cubes' friction 0.6: the upper cube sticks), both launched
    # at v0 = 1.5: the pair decelerates as one body at mu g = 0.3 and stops after 5 time
    # units (neither cube tips: the normal forces move by mu h/2 = 0.15 towards the front,
    # within the faces they press on). The step's implicit Euler (v_{n+1} = v_n - mu g dt,
    # x_{n+1} = x_n + dt v_{n+1}) moves each cube by dt sum_{k=1}^{5000} (v0 - k mu g dt)
    # = 3.74925 exactly, from x = -1.9 and -1.8: the cubes cross x = 0, the boundary of the
    # 2 ranks' subdomains, in different steps while they touch, so for a while each rank
    # owns one cube of the contact.
    # Measured (2026-12-07): on 1 and 2 ranks the final x and the speeds on the exact values
    # to round-off; held to 1e-12.
    def test_sliding_stack_across_the_ranks(self):
        made = grains_data("cube 1.0", [(-1.9, 0, 0.5, 1, 0, 0, 0), (-1.8, 0, 1.5, 1, 0, 0, 0)],
                           box=(-4, 4, -2, 2, -1, 4))
        self.assertRanCleanly(made)
        distance = 1e-3 * sum(1.5 - k * 0.3e-3 for k in range(1, 5001))
        for ranks in (1, 2):
            r = run(full_precision(deck(f"""
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra friction 0.6 tolerance 1e-10 solve distributed &
                wall 0 0 0 0 0 1 wall_friction 0.3
velocity        all set 1.5 0 0
timestep        1e-3
dump            d all custom 5500 dump.{ranks} id x z vx vz
run             5500
""", processors="2 1 1" if ranks == 2 else "1 1 1"), "d"), workdir=made.workdir, np_ranks=ranks)
            self.assertRanCleanly(r)
            d = read_dump(made.path(f"dump.{ranks}"))
            print(f"\nsliding stack on {ranks} rank(s): x {d['x'][0]:.15g} {d['x'][1]:.15g} (exact "
                  f"{-1.9 + distance:.15g} {-1.8 + distance:.15g}), vx {d['vx'][0]:.1e} {d['vx'][1]:.1e}")
            np.testing.assert_allclose(d["x"], [-1.9 + distance, -1.8 + distance], rtol=0, atol=1e-12)
            np.testing.assert_allclose(d["z"], [0.5, 1.5], rtol=0, atol=1e-12)
            np.testing.assert_allclose(d["vx"], [0.0, 0.0], rtol=0, atol=1e-12)


class GrainWiderThanASubdomain(DeckTestCase):
    # Two cubes of edge 3 (m = 27, bounding radius 2.6) stacked off-axis on the floor, on 4
    # ranks splitting x into subdomains 2 wide, narrower than a grain (LIGGGHTS' ghosts then
    # reach across several subdomains): at rest the floor carries 2 m g and each cube's
    # contact force is m g upwards. Measured: floor and forces exact (54, 27).
    def test_grain_wider_than_a_subdomain(self):
        made = grains_data("cube 3.0", [(0.0, 0.0, 1.5, 1, 0, 0, 0), (0.7, 0.3, 4.5, 1, 0, 0, 0)],
                           box=(-4, 4, -4, 4, -1, 10))
        self.assertRanCleanly(made)
        r = run(full_precision(deck("""
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra solve distributed wall 0 0 0 0 0 1
timestep        1e-3
thermo_style    custom step f_nscd[9]
thermo_modify   format float %.17g
thermo          20
dump            d all custom 100 dump.big id f_nscd[1] f_nscd[2] f_nscd[3]
run             100
""", processors="4 1 1"), "d"), workdir=made.workdir, np_ranks=4)
        self.assertRanCleanly(r)
        floor = -r.thermo()["nscd[9]"][1:]
        d = read_dump(r.path("dump.big"))
        print(f"\ncubes of edge 3 on 4 subdomains 2 wide: floor {floor[-1]:.17g} (54), contact forces z {d['f_nscd[3]']}")
        np.testing.assert_allclose(floor, 54.0, rtol=1e-14)
        np.testing.assert_allclose(d["f_nscd[3]"], 27.0, rtol=1e-14)
        self.assertLess(max(np.max(np.abs(d["f_nscd[1]"])), np.max(np.abs(d["f_nscd[2]"]))), 1e-12)


class WireLoadedStack(test_nscd.WireLoadedStack):
    # test_nscd's wire on three stacked cubes (fix wire/grain, the wire sub-cycled) with
    # solve distributed on 2 ranks, the subdomains cutting the stack (LIGGGHTS splits the
    # box's longest side, z): at rest the interfaces carry the cubes and the wire above them,
    # the grains the whole wire, to the same tolerances as one rank's replicated solve.
    SOLVE, RANKS = "solve distributed", 2


class WireLoadedStackCutAcross(test_nscd.WireLoadedStack):
    # The same with the subdomains cutting the stack and the loop through their axis
    # (processors 2 1 1: the cubes, centred on x = 0, belong to the rank of x >= 0): the
    # segments of x < 0 load the top cube as a ghost grain of their rank, and fix
    # wire/grain's reverse communication brings those loads to its owner (without it the
    # interfaces carry about half the wire: checked).
    SOLVE, RANKS, PROCESSORS = "solve distributed", 2, "2 1 1"


class SolveAuto(DeckTestCase):
    # The default, solve auto: distributed on more than one rank, replicated on one and where
    # the keywords need it (sleep), as f_ID[31+3W+4P] reports (1: distributed; one wall:
    # f_nscd[34]); replicated and distributed taken as given.
    def test_the_mode_taken(self):
        made = grains_data("cube 1.0", [(0.0, 0.0, 0.5, 1, 0, 0, 0), (0.0, 0.0, 1.5, 1, 0, 0, 0)],
                           box=(-3, 3, -3, 3, -1, 10))
        self.assertRanCleanly(made)
        for keywords, ranks, distributed in (("", 1, 0), ("", 2, 1), ("sleep 0.01 0.5", 2, 0),
                                             ("solve auto", 3, 1), ("solve replicated", 2, 0),
                                             ("solve distributed", 1, 1)):
            r = run(deck(f"""
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra friction 0.5 {keywords} wall 0 0 0 0 0 1
timestep        1e-3
thermo_style    custom step f_nscd[34]
run             2
"""), workdir=made.workdir, np_ranks=ranks)
            self.assertRanCleanly(r)
            self.assertEqual(r.thermo()["nscd[34]"][-1], distributed, f"'{keywords}' on {ranks} rank(s)")


class Errors(DeckTestCase):
    def setUp(self):
        self.made = grains_data("cube 1.0", [(0.0, 0.0, 0.5, 1, 0, 0, 0), (0.0, 0.0, 1.5, 1, 0, 0, 0)],
                                box=(-3, 3, -3, 3, -1, 10))
        self.assertRanCleanly(self.made)

    def stops(self, fix, message, extra=""):
        r = run(deck(f"fix             nscd all nscd/polyhedra {fix} wall 0 0 0 0 0 1\n{extra}timestep 1e-3\nrun 1\n"),
                workdir=self.made.workdir, np_ranks=2)
        self.assertStopsWith(r, "ERROR: fix nscd/polyhedra (id nscd): " + message)

    def test_what_it_does_not_carry(self):
        self.stops("solve distributed sleep 0.01 0.5",
                   "'solve distributed' does not take sleeping grains (keyword 'sleep'): use 'solve replicated'")
        self.stops("solve distributed rolling_friction 0.1",
                   "'solve distributed' does not take 'rolling_friction': use 'solve replicated'")
        self.stops("solve distributed warm_geometry yes",
                   "'solve distributed' does not take 'warm_geometry yes' (its GJK simplices are not in the restart "
                   "file): use 'solve replicated'")
        self.stops("solve distributed write_problems 1 p*.txt",
                   "'solve distributed' does not write the whole problem ('write_problems'): use 'solve replicated'")
        self.stops("solve distributed", "'solve distributed' does not take sleeping grains (keyword 'sleep'): use "
                   "'solve replicated'", extra="fix_modify      nscd sleep 0.01 0.5\n")
        self.stops("solve parallel", "value of 'solve' must be auto, replicated or distributed, got 'parallel'")
        # solve auto (the default) chose distributed on 2 ranks; sleeping turned on after
        self.stops("friction 0.5", "'solve auto' (distributed on 2 ranks) does not take sleeping grains (keyword "
                   "'sleep'): use 'solve replicated'", extra="fix_modify      nscd sleep 0.01 0.5\n")

    def test_ghosts_too_short_for_the_activation_distance(self):
        # a cube launched at 500 against the other: the activation distance 4 h v = 2 asks
        # for a ghost cutoff of 2 (sqrt(3)/2 + 2) + skin 0.3 (LIGGGHTS' default skin in lj
        # units; atom_style polyhedron has a radius: LIGGGHTS' granular ghost shells, half
        # the cutoff plus the atom's radius); the run start gave 2 (sqrt(3)/2 + 0.25 sqrt(3)/2)
        # + 0.3
        r = run(deck("fix             nscd all nscd/polyhedra solve distributed wall 0 0 0 0 0 1\n"
                     "velocity        all set 0 0 -500\ntimestep 1e-3\nrun 1\n"), workdir=self.made.workdir, np_ranks=2)
        radius = 3 ** 0.5 / 2
        needed, held = 2 * (radius + 2.0) + 0.3, 2 * 1.25 * radius + 0.3
        self.assertStopsWith(r, "ERROR: fix nscd/polyhedra (id nscd): solve distributed: step 0 has an activation "
                                f"distance of 2 (4 h v_max + margin), so the ghost cutoff must be {needed:.12g} (2 x (the "
                                f"largest bounding radius {radius:.12g} + the activation distance) + the neighbor skin "
                                f"0.3), but it is {held:.12g}: set 'communicate single cutoff 7.55' or a smaller "
                                "timestep")


if __name__ == "__main__":
    main()
