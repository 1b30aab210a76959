#!/usr/bin/python3
"""Two LIGGGHTS builds on the same column deck from its start, for a change that must give
the same bits (a refactor): both run at the same time, one rank each (or `--np N` each,
one after the other), in their own folders with this checkout's decks; prints the final
observables of `in.column` side by side and compares every file both runs wrote under
post/ (the dump custom files hold %.17g numbers) byte for byte.

    bench/same_physics.py --a OLD/liggghts --b NEW/liggghts
        [--deck input_scripts/in.column_reduced] [--var NAME VALUE ...] [--np 1] [--out DIR]

Exit status 0 when every compared file is identical and both runs printed the same final
line, 1 otherwise."""

import argparse
import filecmp
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
FINAL = re.compile(r"^in\.column final: (.*)$", re.M)


def prepare(folder, deck):
    os.makedirs(folder, exist_ok=True)
    root = os.path.join(folder, "root")
    shutil.copytree(os.path.join(ROOT, "input_scripts"), os.path.join(root, "input_scripts"))
    return os.path.join(root, os.path.relpath(os.path.abspath(deck), ROOT))


def command(binary, deck, root, variables, np):
    cmd = [binary, "-in", deck, "-var", "root", root]
    for name, value in variables:
        cmd += ["-var", name, value]
    if np > 1:
        cmd = ["mpirun", "--oversubscribe", "-np", str(np)] + cmd
    return cmd


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--a", required=True, help="LIGGGHTS binary A (before)")
    ap.add_argument("--b", required=True, help="LIGGGHTS binary B (after)")
    ap.add_argument("--deck", default=os.path.join(ROOT, "input_scripts", "in.column_reduced"))
    ap.add_argument("--var", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"))
    ap.add_argument("--np", type=int, default=1, help="ranks per run (1: A and B at once)")
    ap.add_argument("--out", default=None, help="folder for the runs (default: a new temporary one)")
    args = ap.parse_args()

    out = os.path.abspath(args.out or tempfile.mkdtemp(prefix="same_physics_"))
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    runs = {}
    for label, binary in (("A", args.a), ("B", args.b)):
        folder = os.path.join(out, label)
        deck = prepare(folder, args.deck)
        runs[label] = (folder, command(os.path.abspath(binary), deck, os.path.join(folder, "root"),
                                       args.var, args.np))
    procs = {}
    for label, (folder, cmd) in runs.items():
        log = open(os.path.join(folder, "log.txt"), "w")
        procs[label] = subprocess.Popen(cmd, cwd=folder, stdout=log, stderr=subprocess.STDOUT, env=env)
        if args.np > 1:
            procs[label].wait()
    status = {label: p.wait() for label, p in procs.items()}

    finals = {}
    for label, (folder, _) in runs.items():
        text = open(os.path.join(folder, "log.txt"), errors="replace").read()
        match = FINAL.findall(text)
        finals[label] = match[-1] if match else f"(no final line; exit {status[label]})"
    print(f"runs in {out}")
    for label in ("A", "B"):
        print(f"{label}: {finals[label]}")
    same = finals["A"] == finals["B"] and all(s == 0 for s in status.values())
    print("final line: " + ("identical" if same else "DIFFERENT"))

    post_a, post_b = (os.path.join(runs[l][0], "post") for l in ("A", "B"))
    names = sorted(set(os.listdir(post_a)) | set(os.listdir(post_b))) if os.path.isdir(post_a) and os.path.isdir(post_b) else []
    differ = [n for n in names
              if not (os.path.exists(os.path.join(post_a, n)) and os.path.exists(os.path.join(post_b, n))
                      and filecmp.cmp(os.path.join(post_a, n), os.path.join(post_b, n), shallow=False))]
    print(f"post/: {len(names)} files, {len(names) - len(differ)} byte-identical"
          + (f"; differ: {', '.join(differ)}" if differ else ""))
    return 0 if same and names and not differ else 1


if __name__ == "__main__":
    sys.exit(main())
