#!/usr/bin/python3
"""Benchmark: a 4242-segment wire (Table 1 material) piled in a box, its time per step
with wire-wire contacts (pair_style wire/contact, with its pair cache and with `cache
no`) against without, and the exact segment-pair evaluations per second. The runs start
from the same piled state, one after the other in this invocation.

    bench/wire_contacts.py [--liggghts build/liggghts] [--steps 2000] [--np 1]"""

import argparse
import os
import re
import subprocess
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))

# the wire, its walls and integrator, shared by the piling and the timed runs
FIXES = """
fix             elastic all wire/elastic
fix             integr all nve/gear forces velocity
fix             gravity all gravity 1.0 vector 0 0 -1
fix             floor all wire/wall plane 0 0 0 0 0 1
fix             wxlo all wire/wall plane -2 0 0 1 0 0 mu_s 0 mu_d 0
fix             wxhi all wire/wall plane 2 0 0 -1 0 0 mu_s 0 mu_d 0
fix             wylo all wire/wall plane 0 -2 0 0 1 0 mu_s 0 mu_d 0
fix             wyhi all wire/wall plane 0 2 0 0 -1 0 mu_s 0 mu_d 0
timestep        1e-4
"""

PILE = """
units           lj
atom_style      wire
boundary        f f f
newton          off
region          box block -3 3 -3 3 -1 30
create_box      1 box
create_wire     1 loop 0 0 0.1 1.5 90.3 0.21
pair_style      wire/contact
pair_coeff      * *
neighbor        0.1 bin
{fixes}run             5000
write_restart   pile.restart
"""

MEASURE = """
units           lj
atom_style      wire
boundary        f f f
newton          off
read_restart    pile.restart
{pair}
neighbor        0.1 bin
{fixes}{stats}
thermo          {steps}
run             {steps}
"""


def liggghts(args, work, text):
    with open(os.path.join(work, "in.bench"), "w") as f:
        f.write(text)
    cmd = [args.liggghts, "-in", "in.bench", "-log", "none"]
    if args.np > 1:
        cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(args.np)] + cmd
    return subprocess.run(cmd, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          check=True).stdout.decode()


def loop_time(out):
    seconds, steps, atoms = re.findall(
        r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms", out)[-1]
    return float(seconds), int(steps), int(atoms)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--liggghts", default=os.path.join(HERE, "..", "build", "liggghts"))
    parser.add_argument("--steps", type=int, default=2000)
    parser.add_argument("--np", type=int, default=1)
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="wiregrain-bench-")
    liggghts(args, work, PILE.format(fixes=FIXES))

    stats = ("compute c all wire/contacts\nthermo_style custom step atoms c_c[1] c_c[4]\n"
             "thermo_modify norm no")
    with_contacts = liggghts(args, work, MEASURE.format(
        pair="pair_style wire/contact\npair_coeff * *", stats=stats, steps=args.steps, fixes=FIXES))
    no_cache = liggghts(args, work, MEASURE.format(
        pair="pair_style wire/contact cache no\npair_coeff * *", stats=stats, steps=args.steps, fixes=FIXES))
    without = liggghts(args, work, MEASURE.format(pair="pair_style none", stats="", steps=args.steps, fixes=FIXES))
    t_with, steps, atoms = loop_time(with_contacts)
    t_no_cache, _, _ = loop_time(no_cache)
    t_without, _, _ = loop_time(without)
    rows = re.findall(r"^\s*\d+\s+\d+\s+([0-9.eE+-]+)\s+([0-9.eE+-]+)\s*$", with_contacts, re.M)
    contacts, evaluations = (float(v) for v in rows[-1])
    print(f"ranks: {args.np}, {atoms} beads ({atoms - 1} segments), {steps} steps, "
          f"{contacts:.0f} wire-wire contacts, {evaluations:.0f} segment-pair evaluations per step")
    print(f"with contacts   : {t_with / steps * 1e3:8.3f} ms per step  "
          f"{t_with / (steps * atoms) * 1e9:8.1f} ns per bead-step")
    print(f"  cache no      : {t_no_cache / steps * 1e3:8.3f} ms per step  "
          f"{t_no_cache / (steps * atoms) * 1e9:8.1f} ns per bead-step")
    print(f"without contacts: {t_without / steps * 1e3:8.3f} ms per step  "
          f"{t_without / (steps * atoms) * 1e9:8.1f} ns per bead-step")
    print(f"ratio with / without: {t_with / t_without:.2f} (cache no: {t_no_cache / t_without:.2f}); "
          f"cache yes / no: {t_with / t_no_cache:.2f}")
    print(f"segment-pair evaluations per second (whole step time): {evaluations * steps / t_with:.4g}")


if __name__ == "__main__":
    main()
