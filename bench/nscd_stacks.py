#!/usr/bin/python3
"""Benchmark: stacks of boxes at rest (bench/nscd_stack, box_stack.h), method gauss_seidel
against the fix's default method subspace (both at the default tolerance 1e-4, the other
settings the fix's defaults), side by side in one run; prints one line per
stack and method (worst relative interface-load error over all steps, steps over 1e-4,
steps at the sweep cap, sweeps, wall time).

    bench/nscd_stacks.py [--build build] [--steps 1000] [--sizes 20 100 200 500]
        [--gs-steps 200]

Plain Gauss-Seidel hits its cap of 1000 sweeps on nearly every step of a tall stack, so it
runs --gs-steps steps (and only up to 100 boxes)."""

import argparse
import os
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(HERE, "..", "build"))
    parser.add_argument("--steps", type=int, default=1000)
    parser.add_argument("--gs-steps", type=int, default=200)
    parser.add_argument("--sizes", type=int, nargs="*", default=[20, 100, 200, 500])
    args = parser.parse_args()
    binary = os.path.join(args.build, "bench", "nscd_stack")
    for n in args.sizes:
        for alternate in ([], ["--alternate"]):
            runs = [["--method", "subspace", "--steps", str(args.steps)]]
            if n <= 100:
                runs.insert(0, ["--method", "gauss_seidel", "--steps", str(args.gs_steps)])
            for extra in runs:
                out = subprocess.run([binary, "--n", str(n)] + alternate + extra, stdout=subprocess.PIPE,
                                     check=True).stdout.decode().strip()
                print(f"{extra[1]:>12}: {out}", flush=True)


if __name__ == "__main__":
    main()
