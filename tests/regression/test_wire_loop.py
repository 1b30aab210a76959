"""The wire example on 1 and 2 MPI ranks (the loop crosses the subdomain boundary),
restarted midway, and written to / read from a data file: all give the same state."""

import numpy as np

from liggghts_run import DeckTestCase, deck, full_precision, main, read_dump, run

EXAMPLE = "examples/wire_loop/in.wire_loop"

CONTINUE = """
units           lj
atom_style      wire
boundary        f f f
processors      * 1 1
{load}
fix             elastic all wire/elastic
fix             integr all nve/gear scheme {scheme}
fix             gravity all gravity 1.0 vector 0 0 -1
timestep        1e-4
compute         wire all wire/energy
thermo_style    custom step atoms ke c_wire[1] c_wire[2] c_wire[4]
thermo_modify   format float %.17g norm no
thermo          100
dump            beads all custom {n} dump.wire_loop id x y z vx vy vz
dump_modify     beads format "%d %.17g %.17g %.17g %.17g %.17g %.17g"
run             {n}
"""

COLUMNS = ("x", "y", "z", "vx", "vy", "vz")


def max_difference(a, b):
    assert np.array_equal(a["id"], b["id"])
    return max(np.max(np.abs(a[c] - b[c])) for c in COLUMNS)


class WireLoop(DeckTestCase):
    def straight(self, np_ranks, nsteps, scheme="gear5"):
        r = run(full_precision(deck(EXAMPLE), "beads"), np_ranks=np_ranks,
                variables={"nsteps": nsteps, "dumpevery": nsteps, "scheme": scheme})
        self.assertRanCleanly(r)
        return r

    def test_one_and_two_ranks_agree(self):
        one = read_dump(self.straight(1, 200).path("dump.wire_loop"))
        two_run = self.straight(2, 200)
        self.assertIn("2 by 1 by 1 MPI processor grid", two_run.output)
        two = read_dump(two_run.path("dump.wire_loop"))
        diff = max_difference(one, two)
        print(f"wire: 1 vs 2 ranks after 200 steps: max |difference| = {diff:.3e}")
        self.assertLess(diff, 1e-10)
        # the loop does span both subdomains
        self.assertLess(np.min(one["x"]), -1.0)
        self.assertGreater(np.max(one["x"]), 1.0)

    def test_restart_reproduces_straight_run(self):
        for scheme in ("gear5", "verlet"):
            straight = read_dump(self.straight(1, 200, scheme).path("dump.wire_loop"))
            for ranks in (1, 2):
                first = run(full_precision(deck(EXAMPLE), "beads") + "\nwrite_restart restart.half\n", np_ranks=ranks,
                            variables={"nsteps": 100, "dumpevery": 100, "scheme": scheme})
                self.assertRanCleanly(first)
                second = run(CONTINUE.format(load="read_restart restart.half", scheme=scheme, n=100),
                             workdir=first.workdir, np_ranks=ranks)
                self.assertRanCleanly(second)
                diff = max_difference(straight, read_dump(second.path("dump.wire_loop")))
                print(f"wire {scheme}, {ranks} rank(s): restart at step 100 vs straight 200 steps: "
                      f"max |difference| = {diff:.3e}")
                self.assertLess(diff, 1e-12 if ranks == 1 else 1e-10)

    def test_data_file_round_trip(self):
        # write_data keeps the links and rest lengths: the same elastic energies and the
        # same data file after a read_data / write_data cycle.
        first = run(full_precision(deck(EXAMPLE), "beads") + "\nwrite_data wire.data\n",
                    variables={"nsteps": 100, "dumpevery": 100, "scheme": "verlet"})
        self.assertRanCleanly(first)
        energies_before = first.thermo()
        second = run(CONTINUE.format(load="read_data wire.data", scheme="verlet", n=0)
                     .replace("dump            beads all custom 0 dump.wire_loop id x y z vx vy vz\n", "")
                     .replace('dump_modify     beads format "%d %.17g %.17g %.17g %.17g %.17g %.17g"\n', "")
                     + "write_data wire2.data\n", workdir=first.workdir)
        self.assertRanCleanly(second)
        energies_after = second.thermo()
        for column in ("wire[1]", "wire[2]", "wire[4]"):
            self.assertAlmostEqual(energies_after[column][0] / energies_before[column][-1], 1.0,
                                   delta=1e-14, msg=column)

        def atoms_section(name):
            with open(first.path(name)) as f:
                text = f.read()
            body = text[text.index("Atoms"):]
            return sorted(line for line in body.splitlines()[2:] if line.strip() and
                          not line.startswith("Velocities"))
        self.assertEqual(atoms_section("wire.data"), atoms_section("wire2.data"))


if __name__ == "__main__":
    main()
