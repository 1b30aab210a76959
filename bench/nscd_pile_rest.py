#!/usr/bin/python3
"""Benchmark: does an undamped pile come to rest? 500 Table 1 grains poured into a 10 x 10
box (examples/grain_deposit without its damping), integrated by fix nscd/polyhedra with
each solver setting side by side; prints the kinetic energy per grain (translation +
rotation, in m g a_max with m the mean grain mass) at several times, the mean and largest
sweeps per step, the contact points solved, the largest overlap at a step start (of the
last step and of all steps so far, in a_max), the grains asleep, the frozen points and
the sleepers solved in the last step's equilibrium checks (keyword sleep), the steps that
hit the sweep cap and the wall time.

    bench/nscd_pile_rest.py [--liggghts build/liggghts] [--steps 20000] [--every 2000]
        [--config "method gauss_seidel" "method subspace tolerance 1e-6" ...] [--side-by-side]
        [--grains 500] [--half-width 5] [--create "sweep 0" "sweep 0.03" ...]
        [--seeds 2718 1 2 3] [--jobs 2]

--create gives create_grains keywords (e.g. the sweep radius r_p); each entry is run with
each --config (default: the grains of the Table 1 shape library as they are, r_p = 0.1).

--grains and --half-width change the pile: N grains created in the box of that half
width less 1.1 (the heap of 60 for docs/design.md, "Sleeping grains": --grains 60
--half-width 3 --config "sleep 1e-2 0.2").

--side-by-side runs the settings at the same time (one process each; on a 2-core machine
two settings share the machine equally, so their wall times compare); --jobs N runs at most
N at a time instead.

--seeds: the create_grains seeds (default 2718, examples/grain_deposit's); each setting
is run with each. The deposit is chaotic (a change of rounding gives another pile), so
whether a pile comes to rest is a fraction of seeds: after the tables, one summary line
per setting and seed (from when the kinetic energy stays below the bar, its last value,
the largest grain's share of it) and the count of seeds at rest at the end.

The grains are created at random in the box from z = 1.1 to 38 and fall under g = 1; the
pile is complete by t ~ 12. At rest means: kinetic energy below 1e-8 m g a_max per grain
and staying there."""

import argparse
import os
import re
import subprocess
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))

DECK = """
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
region          box block -{w} {w} -{w} {w} 0 40
create_box      1 box
region          fill block -{f} {f} -{f} {f} 1.1 38
create_grains   1 {grains} random fill seed {seed} {create}
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra {config} &
                wall 0 0 0 0 0 1 &
                wall -{w} 0 0 1 0 0 wall_friction 0 wall {w} 0 0 -1 0 0 wall_friction 0 &
                wall 0 -{w} 0 0 1 0 wall_friction 0 wall 0 {w} 0 0 -1 0 wall_friction 0
timestep        1e-3
compute         rot all grain/rotation
compute         ket all ke
variable        mg equal mass(all)/count(all)
variable        ke equal (c_ket+c_rot[1])/count(all)/v_mg
variable        sweeps equal f_nscd[1]
variable        zcm equal xcm(all,z)
# the fastest grain's share of the translational kinetic energy (1: one rattler)
compute         kea all ke/atom
compute         keamax all reduce max c_kea
variable        share equal c_keamax/(c_ket+1e-300)
thermo_style    custom step v_ke v_sweeps f_nscd[3] f_nscd[4] f_nscd[24] f_nscd[6] f_nscd[25] f_nscd[26] f_nscd[31] f_nscd[33] f_nscd[34] v_zcm v_share
thermo_modify   norm no format float %.9g
thermo          {every}
run             {steps}
"""


def start(liggghts, config, steps, every, grains=500, half_width=5.0, create="", seed=2718):
    work = tempfile.mkdtemp(prefix="wiregrain-pile-")
    with open(os.path.join(work, "in.pile"), "w") as f:
        f.write(DECK.format(config=config, steps=steps, every=every, grains=grains, w=half_width, f=half_width - 1.1,
                            create=create, seed=seed))
    # the run's own end time is written by its shell: side by side, the runs are collected
    # in order, and a run that ended first would otherwise be timed to the end of the others
    command = f"'{liggghts}' -in in.pile -log none; status=$?; date +%s.%N > ended; exit $status"
    return time.time(), work, subprocess.Popen(["sh", "-c", command], cwd=work, stdout=subprocess.PIPE,
                                               stderr=subprocess.STDOUT)


def finish(config, started):
    begin, work, process = started
    out = process.communicate()[0].decode()
    with open(os.path.join(work, "ended")) as f:
        seconds = float(f.read()) - begin
    number = r"\s+([0-9.eE+-]+)"
    rows = re.findall(r"^\s*(\d+)" + 13 * number + r"\s*$", out, re.M)
    if not rows:
        raise SystemExit(f"no thermo output for '{config}':\n{out[-2000:]}")
    return rows, seconds


def report(config, rows, seconds):
    overlap_all, capped, tried, kept = (float(v) for v in rows[-1][5:9])
    print(f"{config}: {seconds:.0f} s, largest overlap {overlap_all:.2e}, steps at the cap {capped:.0f}, "
          f"stick solves {tried:.0f} (kept {kept:.0f})", flush=True)
    print(f"  {'t':>6} {'KE per grain':>13} {'sweeps (last step)':>19} {'contacts':>9} {'overlap':>9} {'of all':>9}"
          f" {'asleep':>7} {'frozen':>7} {'checked':>7} {'mean z':>9}")
    for step, ke, sweeps, contacts, overlap, overlap_all, _, _, _, asleep, frozen, checked, zcm, _ in rows:
        print(f"  {int(step) * 1e-3:6.1f} {float(ke):13.3e} {float(sweeps):19.0f} {float(contacts):9.0f}"
              f" {float(overlap):9.2e} {float(overlap_all):9.2e} {float(asleep):7.0f} {float(frozen):7.0f} {float(checked):7.0f}"
              f" {float(zcm):9.6f}", flush=True)


BAR = 1e-8  # at rest: kinetic energy per grain below this, in m g a_max


def at_rest(rows):
    """(time from which the kinetic energy per grain stays below BAR to the end, or None;
    its last value; the fastest grain's share of the translational part at the end)"""
    since = None
    for step, ke, *_ in rows:
        if float(ke) < BAR:
            since = int(step) * 1e-3 if since is None else since
        else:
            since = None
    return since, float(rows[-1][1]), float(rows[-1][13])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--liggghts", default=os.path.join(HERE, "..", "build", "liggghts"))
    parser.add_argument("--steps", type=int, default=20000)
    parser.add_argument("--every", type=int, default=2000)
    parser.add_argument("--config", nargs="*", default=["method gauss_seidel", "method subspace"])
    parser.add_argument("--side-by-side", action="store_true")
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--grains", type=int, default=500)
    parser.add_argument("--half-width", type=float, default=5.0)
    parser.add_argument("--create", nargs="*", default=[""])
    parser.add_argument("--seeds", type=int, nargs="*", default=[2718])
    args = parser.parse_args()
    runs = [(create, config, seed) for create in args.create for config in args.config for seed in args.seeds]
    jobs = len(runs) if args.side_by_side else max(1, args.jobs)

    def label(create, config, seed):
        name = f"{create} | {config}" if create else config
        return f"{name} | seed {seed}" if len(args.seeds) > 1 else name

    def launch(run):
        create, config, seed = run
        return start(args.liggghts, config, args.steps, args.every, args.grains, args.half_width, create, seed)

    # at most `jobs` at a time, reported in order
    results = []
    running = [launch(run) for run in runs[:jobs]]
    for k, run in enumerate(runs):
        rows, seconds = finish(run[1], running.pop(0))
        if k + jobs < len(runs):
            running.append(launch(runs[k + jobs]))
        report(label(*run), rows, seconds)
        results.append((run, rows))

    print(f"\nat rest: kinetic energy per grain below {BAR:g} m g a_max from the time given to the end")
    settings = []
    for create, config, _ in runs:
        if (create, config) not in settings:
            settings.append((create, config))
    for create, config in settings:
        mine = [(seed, rows) for (c, g, seed), rows in results if (c, g) == (create, config)]
        resting = 0
        for seed, rows in mine:
            since, last, share = at_rest(rows)
            resting += since is not None
            state = f"from t = {since:.1f}" if since is not None else "not at rest"
            print(f"  {label(create, config, seed)}: {state}; at the end {last:.2e}, fastest grain {share:.0%} of it")
        print(f"  {create + ' | ' if create else ''}{config}: {resting} of {len(mine)} seeds at rest at the end")


if __name__ == "__main__":
    main()
