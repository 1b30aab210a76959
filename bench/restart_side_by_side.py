#!/usr/bin/python3
"""Benchmark: two LIGGGHTS builds (or two settings of one build) on the same phase of a
column, from one of its restart files, run at the same time (one rank each, so both see
the same machine), for a change that must not alter the column (or to price a setting).

    bench/restart_side_by_side.py --restart RUN/column_deposited.restart --resume 2
        --var t_relax 146 --var t_end 146.5 --a OLD/liggghts --b NEW/liggghts
        [--b-var dt_SP 2e-3 ...] [--deck input_scripts/in.column] [--out DIR]

Each run gets its own directory under --out (a copy of the decks of this checkout and a
link to the restart) and runs `liggghts -in DECK -var root . -var resume R [--var ...]`
(run B with --b-var on top: they take precedence over --var). Prints, for A and B and their ratio B / A: the loop time of
each `run`, LIGGGHTS' per-fix times (`modify_timing on`, the deck's default: fix
nscd/polyhedra, fix wire/grain, the wire–wire pair, fix wire/elastic, fix nve/gear), the
NSCD clocks the deck prints, and the final observables, with whether they agree to the
last printed digit (a change meant to give the same bits must). The restart's clock is
t = step × dt_SP (input_scripts/README.md, resume): give t_relax / t_end in it.

`--alternate R [--np N]` runs them one after the other instead, A B A B ... (R rounds),
each on N ranks (`mpirun -np N`; default 2, the Table 1 run's), and prints every round's
figures and the ratio of the sums: the simultaneous runs' second slot was measured 4-9 %
slower in every part, unrelated builds alike (2026-11-27, commit 3156e83), which hides a
change of a few per cent; alternating runs share the machine's drift instead."""

import argparse
import os
import re
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FIXES = [("fix nscd/polyhedra", r"^Fix \S+ nscd/polyhedra time \(%\) = ([\d.e+-]+)"),
         ("fix wire/grain", r"^Fix \S+ wire/grain time \(%\) = ([\d.e+-]+)"),
         ("pair (wire-wire)", r"^Pair  time \(%\) = ([\d.e+-]+)"),
         ("fix wire/elastic", r"^Fix \S+ wire/elastic time \(%\) = ([\d.e+-]+)"),
         ("fix nve/gear", r"^Fix \S+ nve/gear time \(%\) = ([\d.e+-]+)")]
CLOCKS = re.compile(r"^in\.column NSCD clocks: gather \+ detection (\S+) s, solve (\S+) s, "
                    r"scatter \+ overlap projection (\S+) s", re.M)
FINAL = re.compile(r"^in\.column final: (.*) at t = ", re.M)


def prepare(directory, restart):
    os.makedirs(directory, exist_ok=True)
    scripts = os.path.join(directory, "input_scripts")
    if os.path.isdir(scripts):
        shutil.rmtree(scripts)
    shutil.copytree(os.path.join(ROOT, "input_scripts"), scripts)  # a study must not read a deck being edited
    link = os.path.join(directory, os.path.basename(restart))
    if os.path.lexists(link):
        os.remove(link)
    os.symlink(os.path.abspath(restart), link)
    # the deck's records beside the restart: the deposition's end, H0 and the walls' start
    for record in ("column_deposited.txt", "column_walls.txt"):
        path = os.path.join(os.path.dirname(os.path.abspath(restart)), record)
        if os.path.exists(path):
            shutil.copy(path, directory)


def figures(log_text):
    """Sums over the log's runs: loop time, per-fix times, NSCD clocks; the final line."""
    out = {"loop": sum(float(t) for t in re.findall(r"^Loop time of (\S+)", log_text, re.M))}
    for name, pattern in FIXES:
        out[name] = sum(float(t) for t in re.findall(pattern, log_text, re.M))
    clocks = CLOCKS.findall(log_text)
    if clocks:
        for name, value in zip(("NSCD gather + detection", "NSCD solve", "NSCD scatter + projection"), clocks[-1]):
            out[name] = float(value)
    final = FINAL.findall(log_text)
    return out, final[-1] if final else None


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--restart", required=True)
    parser.add_argument("--resume", type=int, required=True, choices=(1, 2, 3))
    parser.add_argument("--a", required=True, help="liggghts binary A (the reference)")
    parser.add_argument("--b", required=True, help="liggghts binary B (may be A, with --b-var)")
    parser.add_argument("--var", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"))
    parser.add_argument("--b-var", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"))
    parser.add_argument("--deck", default="input_scripts/in.column")
    parser.add_argument("--out", default="side_by_side")
    parser.add_argument("--alternate", type=int, default=0, metavar="ROUNDS",
                        help="run A and B one after the other, ROUNDS times each, on --np ranks")
    parser.add_argument("--np", type=int, default=2)
    args = parser.parse_args()

    env = dict(os.environ, OMPI_MCA_btl_vader_single_copy_mechanism="none", OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")

    def start(label, binary, extra, directory, launcher):
        prepare(directory, args.restart)
        command = launcher + [os.path.abspath(binary), "-in", args.deck, "-var", "root", ".", "-var", "resume",
                              str(args.resume), "-log", "log.liggghts"]
        for name, value in extra + args.var:  # LIGGGHTS keeps the first -var of a name: B's win
            command += ["-var", name, value]
        with open(os.path.join(directory, "command.txt"), "w") as f:
            f.write(" ".join(command) + "\n")
        stdout = open(os.path.join(directory, "stdout.txt"), "w")
        return (label, directory, subprocess.Popen(command, cwd=directory, stdout=stdout, stderr=subprocess.STDOUT,
                                                   env=env), stdout)

    def finish(label, directory, process, stdout):
        code = process.wait()
        stdout.close()
        with open(os.path.join(directory, "log.liggghts")) as f:
            text = f.read()
        if code != 0 or "ERROR" in text:
            errors = [line for line in text.splitlines() if line.startswith("ERROR")]
            sys.exit(f"run {label} failed ({code}): {errors[:1]} (see {directory})")
        return figures(text)

    runs = (("A", args.a, []), ("B", args.b, args.b_var))
    results = {}
    if args.alternate > 0:
        launcher = ["mpirun", "-np", str(args.np)]
        sums = {}
        for r in range(args.alternate):
            for label, binary, extra in runs:
                got, final = finish(*start(label, binary, extra, os.path.join(args.out, f"{label}{r}"), launcher))
                print(f"round {r} {label}: loop {got['loop']:.2f} s, "
                      + ", ".join(f"{k} {v:.2f}" for k, v in got.items() if k.startswith("NSCD")), flush=True)
                total = sums.setdefault(label, {})
                for k, v in got.items():
                    total[k] = total.get(k, 0.0) + v
                results[label] = (total, final)
        print(f"sums over {args.alternate} rounds, {args.np} ranks each:")
    else:
        processes = [start(label, binary, extra, os.path.join(args.out, label), []) for label, binary, extra in runs]
        for process in processes:
            results[process[0]] = finish(*process)

    (a, final_a), (b, final_b) = results["A"], results["B"]
    print(f"{'':28s} {'A [s]':>10s} {'B [s]':>10s} {'B / A':>7s}")
    for name in a:
        if name in b and a[name] > 0:
            print(f"{name:28s} {a[name]:10.2f} {b[name]:10.2f} {b[name] / a[name]:7.3f}")
    print(f"final A: {final_a}\nfinal B: {final_b}")
    print("final observables: " + ("identical to the last printed digit" if final_a == final_b else "DIFFER"))


if __name__ == "__main__":
    main()
