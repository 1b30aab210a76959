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

--create gives create_grains keywords (e.g. the sweep radius r_p); each entry is run with
each --config (default: the grains of the Table 1 shape library as they are, r_p = 0.1).

--grains and --half-width change the pile: N grains created in the box of that half
width less 1.1 (the heap of 60 of docs/core_nscd.md, "Sleeping grains": --grains 60
--half-width 3 --config "sleep 1e-2 0.2").

--side-by-side runs the settings at the same time (one process each; on a 2-core machine
two settings share the machine equally, so their wall times compare).

The grains are created at random in the box from z = 1.1 to 38 and fall under g = 1; the
pile is complete by t ~ 12. Issue 13's bar: kinetic energy below 1e-8 m g a_max per grain
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
create_grains   1 {grains} random fill seed 2718 {create}
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
thermo_style    custom step v_ke v_sweeps f_nscd[3] f_nscd[4] f_nscd[24] f_nscd[6] f_nscd[25] f_nscd[26] f_nscd[31] f_nscd[33] f_nscd[34] v_zcm
thermo_modify   norm no format float %.9g
thermo          {every}
run             {steps}
"""


def start(liggghts, config, steps, every, grains=500, half_width=5.0, create=""):
    work = tempfile.mkdtemp(prefix="wiregrain-pile-")
    with open(os.path.join(work, "in.pile"), "w") as f:
        f.write(DECK.format(config=config, steps=steps, every=every, grains=grains, w=half_width, f=half_width - 1.1,
                            create=create))
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
    rows = re.findall(r"^\s*(\d+)" + 12 * number + r"\s*$", out, re.M)
    if not rows:
        raise SystemExit(f"no thermo output for '{config}':\n{out[-2000:]}")
    return rows, seconds


def report(config, rows, seconds):
    overlap_all, capped, tried, kept = (float(v) for v in rows[-1][5:9])
    print(f"{config}: {seconds:.0f} s, largest overlap {overlap_all:.2e}, steps at the cap {capped:.0f}, "
          f"stick solves {tried:.0f} (kept {kept:.0f})", flush=True)
    print(f"  {'t':>6} {'KE per grain':>13} {'sweeps (last step)':>19} {'contacts':>9} {'overlap':>9} {'of all':>9}"
          f" {'asleep':>7} {'frozen':>7} {'checked':>7} {'mean z':>9}")
    for step, ke, sweeps, contacts, overlap, overlap_all, _, _, _, asleep, frozen, checked, zcm in rows:
        print(f"  {int(step) * 1e-3:6.1f} {float(ke):13.3e} {float(sweeps):19.0f} {float(contacts):9.0f}"
              f" {float(overlap):9.2e} {float(overlap_all):9.2e} {float(asleep):7.0f} {float(frozen):7.0f} {float(checked):7.0f}"
              f" {float(zcm):9.6f}", flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--liggghts", default=os.path.join(HERE, "..", "build", "liggghts"))
    parser.add_argument("--steps", type=int, default=20000)
    parser.add_argument("--every", type=int, default=2000)
    parser.add_argument("--config", nargs="*", default=["method gauss_seidel", "method subspace"])
    parser.add_argument("--side-by-side", action="store_true")
    parser.add_argument("--grains", type=int, default=500)
    parser.add_argument("--half-width", type=float, default=5.0)
    parser.add_argument("--create", nargs="*", default=[""])
    args = parser.parse_args()
    runs = [(create, config) for create in args.create for config in args.config]

    def label(create, config):
        return f"{create} | {config}" if create else config

    if args.side_by_side:
        started = [start(args.liggghts, c, args.steps, args.every, args.grains, args.half_width, g) for g, c in runs]
        for (create, config), s in zip(runs, started):
            report(label(create, config), *finish(config, s))
    else:
        for create, config in runs:
            report(label(create, config), *finish(config, start(args.liggghts, config, args.steps, args.every,
                                                               args.grains, args.half_width, create)))


if __name__ == "__main__":
    main()
