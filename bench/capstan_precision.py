#!/usr/bin/python3
"""Work-precision benchmark on a case with a known answer: the capstan.

    bench/capstan_precision.py [--liggghts build/liggghts] [--wrap 3.14159] [--mu 0.5] [--out capstan_precision.png]
        [--steps 1e-4 2e-4 5e-4 1e-3 2e-3] [--schemes gear5 verlet]

The scene and the measurement are the regression test's (tests/styles/test_wire_grain.py,
class Capstan): a wire wrapped by θ over a fixed sphere (no gravity, no bending
stiffness), held by T₁ at one end while the pull T₂ at the other end is raised slowly;
the whole arc slides at the discrete capstan ratio, that of the wire's static equilibrium
with every contact on the Coulomb limit (within 1e-3 of e^{μθ}: the polygon of 64
segments per π). The ratio is measured from the tensions of the leg segments next to the
arc when every contact slides. Here the same measurement is made with the wire's step
Δt_SP and its integrator varied (the test: Verlet at 1e-3), the grain solved every step.
Errors: the measured ratio, and the applied T₂/T₁ at that moment, relative to the discrete
ratio. Run time: LIGGGHTS' loop time of the two runs (one rank), the settling (2 time
units) and the ramp (20)."""

import argparse
import os
import re
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--liggghts", default=os.path.join(ROOT, "build", "liggghts"))
    parser.add_argument("--wrap", type=float, default=3.141592653589793, help="θ, the arc's angle (rad)")
    parser.add_argument("--mu", type=float, default=0.5, help="the friction coefficient μ_s = μ_d")
    parser.add_argument("--steps", type=float, nargs="*", default=[1e-4, 2e-4, 5e-4, 1e-3, 2e-3])
    parser.add_argument("--schemes", nargs="*", default=["gear5", "verlet"])
    parser.add_argument("--out", default="capstan_precision.png")
    args = parser.parse_args()
    # the test harness reads its paths from the environment (as ctest sets them)
    os.environ["LIGGGHTS"] = os.path.abspath(args.liggghts)
    os.environ.setdefault("WIREGRAIN_SOURCE", os.path.abspath(ROOT))
    os.environ.setdefault("OMPI_MCA_btl_vader_single_copy_mechanism", "none")
    sys.path[:0] = [os.path.join(ROOT, "tests", "tools"), os.path.join(ROOT, "tests", "styles")]
    from test_wire_grain import Capstan

    case = Capstan("test_half_turn")
    rows = []
    print(f"capstan θ = {args.wrap:.4f}, μ = {args.mu}: T2/T1 from the leg tensions when every contact slides, and "
          f"the applied T2/T1 then, against the discrete capstan ratio")
    print(f"{'dt_SP':>8} {'scheme':>7} {'loop s':>8} {'discrete':>10} {'measured':>10} {'error':>9} {'applied':>10} "
          f"{'error':>9}")
    for scheme in args.schemes:
        for dt in args.steps:
            start = time.time()
            try:
                r = case.sphere(args.wrap, args.mu, timestep=dt, scheme=scheme)
            except AssertionError as failed:  # e.g. no gross slip, a run that stopped
                lines = str(failed).splitlines() or ["(no message)"]
                why = next((line for line in lines if "ERROR" in line), lines[0])
                print(f"{dt:8.0e} {scheme:>7} failed: {why.strip()[:110]}")
                rows.append((dt, scheme, time.time() - start, None, None))
                continue
            loop = sum(float(x) for x in re.findall(r"Loop time of ([\d.eE+-]+)", case.last_output))
            slip, applied = r["measured"] / r["discrete"] - 1, r["applied"] / r["discrete"] - 1
            rows.append((dt, scheme, loop, slip, applied))
            print(f"{dt:8.0e} {scheme:>7} {loop:8.2f} {r['discrete']:10.6f} {r['measured']:10.6f} {slip:+9.1e} "
                  f"{r['applied']:10.6f} {applied:+9.1e}", flush=True)
    ok = [r for r in rows if r[3] is not None]
    if ok:
        base = next((r for r in ok if r[0] == 1e-4 and r[1] == "gear5"), ok[0])
        print(f"\nspeed-up against dt_SP = {base[0]:.0e} {base[1]} ({base[2]:.2f} s):")
        for dt, scheme, loop, slip, applied in ok:
            print(f"  {dt:8.0e} {scheme:>7}: {base[2] / loop:6.2f}x, |slip error| {abs(slip):.1e}")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib missing: no plot")
        return
    fig, ax = plt.subplots(figsize=(6, 4))
    for scheme, marker in zip(args.schemes, "os^"):
        pts = [(r[2], abs(r[3]), r[0]) for r in ok if r[1] == scheme]
        if not pts:
            continue
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker=marker, label=scheme)
        for t, e, dt in pts:
            ax.annotate(f"{dt:.0e}", (t, e), textcoords="offset points", xytext=(4, 4), fontsize=7)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("loop time [s] (one rank)")
    ax.set_ylabel("|T2/T1 at slip / discrete ratio − 1|")
    ax.set_title(f"capstan θ = {args.wrap:.3f}: work against precision (labels: Δt_SP)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)
    print(f"plot: {args.out}")


if __name__ == "__main__":
    main()
