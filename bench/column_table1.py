#!/usr/bin/python3
"""Benchmark: the paper's Table 1 column (input_scripts/in.column at its defaults: 915
grains in 7 particle layers, 7 double loops of R = 10, Δt_SP = Δt_NSCD = 1e-3) with
`mpirun -np 2`: wall time per step of each phase, its breakdown by part, and the wall time
of the paper's full procedure (t_layer = 10, t = 300 and 600) extrapolated from them.

    bench/column_table1.py [--liggghts build/liggghts] [--np 2] [--t-layer 0.5] [--t-after 0.3]
        [--sample 2000] [--relaxed RESTART] [--var NAME VALUE ...]
    bench/column_table1.py --log LOG [--var nlayers 7]

The deck is in.column with shorter times only: each layer deposited for --t-layer (the
paper: 10), relaxation and wall removal for --t-after time units each, then --sample steps of the
complete column with the walls moving (the phase that is 4.6 of the paper's 6 million
steps). LIGGGHTS' timers (modify_timing on) of every run give the parts:
  wire elastic + integration  fix wire/elastic + fix nve/gear
  wire–wire contacts           Pair + Neigh (pair wire/contact and the lists only it needs)
  wire–wall contacts           the five fix wire/wall
  wire–grain contacts          fix wire/grain (broad phase, exact evaluations, springs,
                               holding its rank's grains once per NSCD step)
  grain detection, NSCD solve  fix nscd/polyhedra, split by its own clocks f_nscd[22]
                               (gather + detection) and f_nscd[23] (solve)
  communication, output        Comm, Outpt
  other                        the rest (gravity, computes, the loop itself)
The extrapolation counts the steps of the run's own Δt_SP (the deck prints it: by
default Δt_NSCD, N = 1; --var dt_SP 1e-4 is the paper's N = 10; in.column's dt_SP,
dt_NSCD and skin set the wire's sub-step, the grains' step and fix wire/grain's pair
cache). Extrapolation: each layer's deposition at the measured cost per step of that layer's run
× the paper's 10^5 steps per layer, plus (600 − 140)/Δt_SP steps at the complete column's
cost per step. The layers deposited faster than in the paper land on each other while
still moving; the cost per step of a layer's run is what the extrapolation uses, so this
matters only through the contacts in flight. --var passes other in.column variables (e.g.
`--var R 3 --var Np 91` for a quick check of the script). About 15 minutes with the defaults.

--log LOG: no run; the wall time and breakdown of a real run of in.column from its screen
output or log.liggghts (e.g. `mpirun -np 2 build/liggghts -in input_scripts/in.column >
log.out`): every run's time summed per phase (deposition, relaxation, walls moving; the
deck's "in.column relaxed" line separates the last two) and per part as below (the
deck's `timing 1`, its default, turns on the per-fix timers; its "in.column NSCD clocks"
line splits fix nscd/polyhedra's time into gather + detection, solve, and scatter +
overlap projection; without them the parts are LIGGGHTS' Pair, Neigh, Comm, Outpt and
Other only). Measured, not extrapolated.

--relaxed RESTART: the complete column's cost per step measured instead on a relaxed
column from a real run (its column_relaxed.restart, continued with in.column's resume 1
for --sample steps with the walls moving). The quick deposit packs looser than the
paper's (1775 contact points per step against 3375 in the Table 1 column deposited for
t_layer = 10, 9.9 against 19-20 ms per step on 2 ranks; 2026-11-25, commit bc5ab83), so
without it the relaxation and wall removal, most of the run, are underestimated about
twofold. The
deposition is still extrapolated from the quick deposit's layers, and the NSCD split
from its sample."""

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPOSITORY = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from wire_grain_contacts import timers  # noqa: E402  (LIGGGHTS' timer lines of one run)

PAPER_T_LAYER, PAPER_T_RELAX, PAPER_T_END = 10.0, 300.0, 600.0
NLAYERS = 7  # in.column's default


def runs(out):
    """Every run of the screen output: (steps, seconds, atoms, timers)."""
    found = []
    for m in re.finditer(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms", out):
        block = out[m.start():]
        nxt = block.find("Loop time of", 10)
        found.append((int(m.group(2)), float(m.group(1)), int(m.group(3)), timers(block if nxt < 0 else block[:nxt])))
    return found


def parts(t, nscd_split):
    """Seconds per part from one run's timers; nscd_split = (gather+detection, solve) or
    (gather+detection, solve, scatter+projection) fractions of fix nscd's time."""
    fix = {k[4:]: v for k, v in t.items() if k.startswith("fix ")}
    if nscd_split is None:  # no split known: fix nscd/polyhedra as one part
        named, total = parts(t, (1.0, 0.0, 0.0))
        named["NSCD step (detection, solve, projection)"] = named.pop("grain detection (NSCD)")
        del named["NSCD solve"], named["NSCD overlap projection"]
        return named, total
    walls = sum(fix.get(w, 0.0) for w in ("floor", "wxlo", "wxhi", "wylo", "wyhi"))
    nscd = fix.get("nscd", 0.0)
    # the loop's time: LIGGGHTS' sections (Modfy, the fixes' sum, with modify_timing on)
    total = sum(t.get(k, 0.0) for k in ("Pair", "Neigh", "Comm", "Outpt", "Modfy", "Other"))
    named = {
        "wire elastic + integration": fix.get("elastic", 0.0) + fix.get("integr", 0.0),
        "wire–wire contacts": t.get("Pair", 0.0) + t.get("Neigh", 0.0),
        "wire–wall contacts": walls,
        "wire–grain contacts": fix.get("wg", 0.0),
        "grain detection (NSCD)": nscd * nscd_split[0],
        "NSCD solve": nscd * nscd_split[1],
        "NSCD overlap projection": nscd * (nscd_split[2] if len(nscd_split) > 2 else 0.0),
        "communication": t.get("Comm", 0.0),
        "output": t.get("Outpt", 0.0),
    }
    named["other"] = max(0.0, total - sum(named.values()))
    return named, total


def relaxed_sample(args, dt):
    """The complete column's last run continued from args.relaxed (in.column resume 1, the
    walls moving for args.sample steps): (steps, seconds, atoms, timers)."""
    work = tempfile.mkdtemp(prefix="wiregrain-column-bench-relaxed-")
    shutil.copy(args.relaxed, os.path.join(work, "column_relaxed.restart"))
    # the deposition's end, which in.column's resume checks the restart's step against: the
    # run's own record, or (a restart whose folder holds no such record) 0, which leaves only
    # the check against t_end
    record = os.path.join(os.path.dirname(os.path.abspath(args.relaxed)), "column_deposited.txt")
    if os.path.exists(record):
        shutil.copy(record, work)
    else:
        with open(os.path.join(work, "column_deposited.txt"), "w") as f:
            f.write("0\n")
    with open(os.path.join(work, "in.bench"), "w") as f:
        f.write(f"modify_timing on\nvariable root index {REPOSITORY}\ninclude {REPOSITORY}/input_scripts/in.column\n")
    t_relax = PAPER_T_RELAX
    cmd = [args.liggghts, "-in", "in.bench", "-log", "log.liggghts", "-var", "resume", "1", "-var", "t_relax",
           str(t_relax), "-var", "t_end", repr(t_relax + args.sample * dt), "-var", "t_obs", "0.1"]
    for name, value in args.var:
        cmd += ["-var", name, value]
    if args.np > 1:
        cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(args.np)] + cmd
    print(f"running in {work}: {' '.join(cmd)}", flush=True)
    out = subprocess.run(cmd, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT).stdout.decode(errors="replace")
    found = runs(out)
    if "ERROR" in out or not found or found[-1][0] != args.sample:
        sys.exit(f"the relaxed column failed in {work}:\n" + out[-3000:])
    steps, seconds, atoms, _ = found[-1]
    print(f"complete column from {args.relaxed}: {atoms} atoms, {steps} steps, {1e3 * seconds / steps:.2f} ms/step")
    return found[-1]


def from_log(path, nlayers):
    """The wall time of a real run and its breakdown, per phase, from its screen output."""
    with open(path, errors="replace") as f:
        out = f.read()
    found = runs(out)
    if len(found) < 2 * nlayers:
        sys.exit(f"{path}: {len(found)} runs, fewer than the {2 * nlayers} of the deposition: not a run of in.column?")
    dt = float(re.search(r"^in\.column: dt_SP (\S+),", out, re.M).group(1))
    starts = [m.start() for m in re.finditer(r"Loop time of", out)]
    relaxed = out.find("in.column relaxed at t")
    # the deposition's runs: those before the deck's "in.column deposited at" line (a layer
    # ended early by ke_layer runs in chunks); logs without that line: the first 2 nlayers
    deposited = re.search(r"^in\.column deposited at t", out, re.M)
    phase_of = []
    for k, pos in enumerate(starts):
        in_deposition = pos < deposited.start() if deposited else k < 2 * nlayers
        phase_of.append("deposition" if in_deposition else "relaxation" if relaxed < 0 or pos < relaxed else "walls moving")
    number = r"([0-9.eE+-]+)"  # (the echoed print command has the $(...) instead)
    clocks = re.search(rf"in\.column NSCD clocks: gather \+ detection {number} s, solve {number} s, "
                       rf"scatter \+ overlap projection {number} s", out)
    if clocks:
        c = [float(v) for v in clocks.groups()]
        split = tuple(v / sum(c) for v in c) if sum(c) > 0 else (1.0, 0.0, 0.0)
    else:
        split = None  # fix nscd's time as one part
    timed = any(any(k.startswith("fix ") for k in r[3]) for r in found)
    total_wall = re.search(r"Total wall time: (\d+):(\d+):(\d+)", out)
    finals = re.findall(r"^in\.column (relaxed at t = \S+|final: .*)$", out, re.M)
    print(f"{path}: {len(found)} runs, {sum(r[0] for r in found)} steps of dt_SP = {dt:g}"
          + (f", total wall time {int(total_wall.group(1))}:{total_wall.group(2)}:{total_wall.group(3)}"
             if total_wall else "")
          + ("" if "in.column final:" in out else " (no 'in.column final' line: the run has not ended)"))
    for line in finals:
        print(f"  in.column {line}")
    phases = ["deposition", "relaxation", "walls moving"]
    seconds = sum(r[1] for r in found)
    unit, scale = ("hours", 3600.0) if seconds > 600 else ("seconds", 1.0)
    print(f"\n{'phase':<16}{'runs':>6}{'time units':>12}{unit:>9}{'ms/step':>9}{'atoms':>7}")
    for ph in phases:
        rs = [r for r, p in zip(found, phase_of) if p == ph]
        if not rs:
            continue
        steps = sum(r[0] for r in rs)
        spent = sum(r[1] for r in rs)
        print(f"{ph:<16}{len(rs):>6}{steps * dt:>12.1f}{spent / scale:>9.2f}{1e3 * spent / max(steps, 1):>9.2f}{rs[-1][2]:>7}")
    print(f"{'all':<16}{len(found):>6}{sum(r[0] for r in found) * dt:>12.1f}{seconds / scale:>9.2f}")
    if not timed:
        print("\n(no per-fix timers in this log: run the deck with timing 1, its default, for the breakdown)")
    label = ("NSCD split from the deck's clocks line: " + ", ".join(f"{100 * v:.0f} %" for v in split)
             if clocks else "no NSCD clocks line: fix nscd/polyhedra's time as one part")
    print(f"\nbreakdown, {unit} ({label})")
    per_phase = {ph: {} for ph in phases}
    for r, ph in zip(found, phase_of):
        named, _ = parts(r[3], split)
        for k, v in named.items():
            per_phase[ph][k] = per_phase[ph].get(k, 0.0) + v
    names = sorted({k for d in per_phase.values() for k in d}, key=lambda k: -sum(d.get(k, 0.0) for d in per_phase.values()))
    print(f"{'part':<42}" + "".join(f"{ph:>14}" for ph in phases) + f"{'all':>10}{'share':>8}")
    for k in names:
        row = [per_phase[ph].get(k, 0.0) for ph in phases]
        print(f"{k:<42}" + "".join(f"{v / scale:>14.3f}" for v in row) + f"{sum(row) / scale:>10.3f}{100 * sum(row) / seconds:>7.1f}%")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--liggghts", default=os.path.join(REPOSITORY, "build", "liggghts"))
    parser.add_argument("--np", type=int, default=2)
    parser.add_argument("--t-layer", type=float, default=0.5)
    parser.add_argument("--t-after", type=float, default=0.3)
    parser.add_argument("--sample", type=int, default=2000)
    parser.add_argument("--relaxed", help="column_relaxed.restart of a real run: the complete column measured on it")
    parser.add_argument("--var", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"))
    parser.add_argument("--log", help="a real run's screen output: its wall time and breakdown, no run")
    args = parser.parse_args()
    given = dict(args.var)
    nlayers = int(given.get("nlayers", NLAYERS))
    if args.log:
        from_log(args.log, nlayers)
        return

    work = tempfile.mkdtemp(prefix="wiregrain-column-bench-")
    t_relax = 2 * nlayers * args.t_layer + args.t_after
    deck = f"""modify_timing on
variable root index {REPOSITORY}
include {REPOSITORY}/input_scripts/in.column
# the complete column, walls moving: the NSCD split of the sample run
thermo_style custom step atoms f_nscd[1] f_nscd[3] f_nscd[22] f_nscd[23]
thermo {args.sample}
run {args.sample}
"""
    with open(os.path.join(work, "in.bench"), "w") as f:
        f.write(deck)
    cmd = [args.liggghts, "-in", "in.bench", "-log", "log.liggghts", "-var", "t_layer", str(args.t_layer),
           "-var", "t_relax", str(t_relax), "-var", "t_end", str(t_relax + args.t_after), "-var", "t_obs", "0.1"]
    for name, value in args.var:
        cmd += ["-var", name, value]
    if args.np > 1:
        cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(args.np)] + cmd
    print(f"running in {work}: {' '.join(cmd)}", flush=True)
    start = time.time()
    out = subprocess.run(cmd, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT).stdout.decode(errors="replace")
    wall = time.time() - start
    found = runs(out)
    if "ERROR" in out or len(found) < 2 * nlayers + 3:
        sys.exit(f"the column failed in {work} after {len(found)} runs:\n" + out[-3000:])
    dt = float(re.search(r"^in\.column: dt_SP (\S+),", out, re.M).group(1))  # the run's LIGGGHTS step

    # the NSCD split from the sample run's thermo: f_nscd[22], f_nscd[23] in seconds
    last_rows = re.findall(r"^\s*\d+\s+\d+\s+\S+\s+\S+\s+([0-9.eE+-]+)\s+([0-9.eE+-]+)\s*$",
                           out[out.rfind("f_nscd[22]") if "f_nscd[22]" in out else 0:], re.M)
    detect, solve = (float(v) for v in last_rows[-1]) if last_rows else (0.5, 0.5)
    split = (detect / (detect + solve), solve / (detect + solve)) if detect + solve > 0 else (0.5, 0.5)

    deposition = found[:2 * nlayers]
    sample = found[-1]
    if args.relaxed:
        sample = relaxed_sample(args, dt)
    print(f"\nmeasured: {len(found)} runs, {sum(r[0] for r in found)} steps, {wall:.0f} s wall "
          f"(mpirun -np {args.np}, t_layer {args.t_layer:g})")
    print(f"{'run':<22}{'atoms':>7}{'steps':>8}{'ms/step':>9}")
    for k, (steps, seconds, atoms, _) in enumerate(deposition):
        name = f"layer {k // 2 + 1} {'grains' if k % 2 == 0 else 'wire'}"
        print(f"{name:<22}{atoms:>7}{steps:>8}{1e3 * seconds / steps:>9.2f}")
    label = "complete (--relaxed)" if args.relaxed else "complete, walls moving"
    print(f"{label:<22}{sample[2]:>7}{sample[0]:>8}{1e3 * sample[1] / sample[0]:>9.2f}")

    paper_layer_steps = PAPER_T_LAYER / dt
    paper_rest_steps = (PAPER_T_END - 2 * nlayers * PAPER_T_LAYER) / dt
    dep_seconds = sum(seconds / steps * paper_layer_steps for steps, seconds, _, _ in deposition)
    rest_seconds = sample[1] / sample[0] * paper_rest_steps
    print(f"\nthe paper's procedure extrapolated: deposition {dep_seconds / 3600:.2f} h "
          f"({2 * nlayers} x {paper_layer_steps:.0f} steps), relaxation + wall removal {rest_seconds / 3600:.2f} h "
          f"({paper_rest_steps:.0f} steps), total {(dep_seconds + rest_seconds) / 3600:.2f} h "
          f"(the paper: about a week on one core; the target: 1 h)")

    # breakdown: deposition runs weighted by the paper's steps, the sample by the rest
    total_parts = {}
    weighted = [(run, paper_layer_steps) for run in deposition] + [(sample, paper_rest_steps)]
    for (steps, _, _, t), paper_steps in weighted:
        named, _ = parts(t, split)
        weight = paper_steps / steps
        for k, v in named.items():
            total_parts[k] = total_parts.get(k, 0.0) + v * weight
    whole = sum(total_parts.values())
    print(f"\nbreakdown of the extrapolated run (NSCD split from f_nscd[22], f_nscd[23]: "
          f"{100 * split[0]:.0f} % gather + detection, {100 * split[1]:.0f} % solve)")
    print(f"{'part':<30}{'hours':>8}{'share':>8}   complete column, ms/step")
    named_sample, _ = parts(sample[3], split)
    for k, v in sorted(total_parts.items(), key=lambda kv: -kv[1]):
        print(f"{k:<30}{v / 3600:>8.2f}{100 * v / whole:>7.1f}%   {1e3 * named_sample[k] / sample[0]:.3f}")


if __name__ == "__main__":
    main()
