#!/usr/bin/python3
"""Benchmark: the same column deck with each grain model, one after the other on the same
ranks: wall time, its ratio, and the final observables.

    bench/grain_models.py [--liggghts build/liggghts] [--np 1] [--deck examples/column/in.column_small]
        [--seed 4242] [--var NAME VALUE ...]

Runs DECK with -var grains nscd (rigid spheropolyhedra, fix nscd/polyhedra: the paper),
-var grains spheres (stock Hertz spheres of the same volumes, fix nve/sphere) and, with
--models, -var grains superquadrics (LIGGGHTS' superquadrics standing in for the grains),
each in a fresh directory, and prints per model the wall time of the liggghts process, the
time LIGGGHTS reports for its runs (the sum of its "Loop time" lines), the final H_n, φ_p,
U_s/L and z_wpc, and the ratio of each model's times to nscd's. Run it on an otherwise
idle machine."""

import os

from column_runs import ROOT, column_arguments, run_column


def run(args, model):
    wall, loop, obs, _ = run_column(args.liggghts, args.np, args.deck,
                                    [("grains", model), ("seed", args.seed)] + args.var, model)
    return wall, loop, obs


def main():
    parser = column_arguments(__doc__.splitlines()[0], 1)
    parser.add_argument("--models", nargs="+", default=["nscd", "spheres", "superquadrics"],
                        choices=["nscd", "spheres", "superquadrics"], help="nscd is always run (the reference)")
    args = parser.parse_args()
    models = ["nscd"] + [m for m in args.models if m != "nscd"]
    results = {model: run(args, model) for model in models}
    print(f"# {os.path.relpath(args.deck, ROOT)}, seed {args.seed}, {args.np} rank(s)")
    print(f"{'model':13s} {'wall [s]':>9s} {'loops [s]':>9s} {'H_n':>8s} {'phi_p':>7s} {'U_s/L':>10s} {'z_wpc':>7s}")
    for model, (wall, loop, obs) in results.items():
        print(f"{model:13s} {wall:9.1f} {loop:9.1f} {obs[0]:8.4f} {obs[1]:7.4f} {obs[2]:10.3e} {obs[3]:7.4f}")
    for model in models[1:]:
        ratio_wall = results[model][0] / results["nscd"][0]
        ratio_loop = results[model][1] / results["nscd"][1]
        print(f"{model} / nscd: wall {ratio_wall:.2f}, loops {ratio_loop:.2f}")


if __name__ == "__main__":
    main()
