"""The wire pile with contacts (tangential springs in use, contacts across the subdomain
boundary) on 1 and 2 MPI ranks, and restarted midway with its contact history."""

import numpy as np

from liggghts_run import DeckTestCase, deck, full_precision, main, read_dump, run

EXAMPLE = "examples/wire_pile/in.wire_pile"
SETTINGS = {"swirl": 0.5, "dumpevery": 0}

COLUMNS = ("x", "y", "z", "vx", "vy", "vz")


def max_difference(a, b):
    assert np.array_equal(a["id"], b["id"])
    return max(np.max(np.abs(a[c] - b[c])) for c in COLUMNS)


def example(nsteps, tail=""):
    text = full_precision(deck(EXAMPLE), "beads")
    text = text.replace("dump            paraview all wire/vtk ${dumpevery} post/wire_*.vtp energy elastic\n", "")
    # start from the coil already resting on the floor with its turns in contact
    text = text.replace("create_wire     1 loop 0 0 0.3 1.5 42.5 0.3", "create_wire     1 loop 0 0 0.1 1.5 10 0.19")
    return text.replace("run             ${nsteps}", f"run {nsteps}\n{tail}")


class WirePile(DeckTestCase):
    def test_one_and_two_ranks_agree(self):
        runs = {n: run(example(300), np_ranks=n, variables=dict(SETTINGS, dumpevery=300)) for n in (1, 2)}
        for r in runs.values():
            self.assertRanCleanly(r)
        contacts = runs[1].thermo()["contacts"]
        self.assertGreater(np.min(contacts), 100)
        diff = max_difference(*(read_dump(runs[n].path("dump.wire_pile")) for n in (1, 2)))
        print(f"wire pile: {int(contacts[-1])} contacts; 1 vs 2 ranks after 300 steps: max |difference| = {diff:.3e}")
        self.assertLess(diff, 1e-10)

    def test_restart_keeps_tangential_springs(self):
        straight = run(example(300), variables=dict(SETTINGS, dumpevery=300))
        self.assertRanCleanly(straight)
        first = run(example(150, "write_restart restart.half"), variables=dict(SETTINGS, dumpevery=150))
        self.assertRanCleanly(first)
        rest = full_precision(deck(EXAMPLE), "beads")
        rest = rest[rest.index("\npair_style") + 1:].replace("run             ${nsteps}", "run 150")
        rest = rest.replace("dump            paraview all wire/vtk ${dumpevery} post/wire_*.vtp energy elastic\n", "")
        restarted_deck = ("units lj\natom_style wire\nboundary f f f\nnewton off\nprocessors * 1 1\n"
                          "read_restart restart.half\n" + rest)
        second = run(restarted_deck, workdir=first.workdir, variables=dict(SETTINGS, dumpevery=150))
        self.assertRanCleanly(second)
        diff = max_difference(read_dump(straight.path("dump.wire_pile")),
                              read_dump(second.path("dump.wire_pile")))
        print(f"wire pile: restart at step 150 vs straight 300 steps: max |difference| = {diff:.3e}")
        self.assertLess(diff, 1e-12)


if __name__ == "__main__":
    main()
