#!/usr/bin/python3
"""Work-precision benchmark: run time against error of the time-stepping
settings of the wire-grain coupling, all cases side by side in one invocation, a table
printed and a PNG drawn.

    bench/work_precision.py [--liggghts build/liggghts] [--t-drop 6] [--mu-w 0.5] [--out work_precision.png]

Scene: a pile of 16 Table 1 grains (a paper-style particle layer, settled on the floor with
damping), made 1000 times denser than Table 1 so that the wire cannot move them, and a
double wire loop of R = 2 (126 beads, Table 1 wire) released 0.1 above the pile's top,
falling onto it under gravity with a viscous damping of the beads (fix viscous 0.005: a
rate of 1.6 per time unit on Table 1's beads, so that it lands within about 1 and then
comes to rest), for --t-drop time units. Everything Table 1 (E_w = 100, mu_w = 0.5 or --mu-w, m_elo = 1,
pair wire/contact, fix wire/wall floor, fix wire/grain with the default skin).

Settings (columns: Δt_NSCD, Δt_SP, N = Δt_NSCD/Δt_SP, the wire's integrator):
  the paper's Δt_NSCD = 1e-3 with N = 10 (Δt_SP = 1e-4), 5, 2 and 1 (Δt_SP = 1e-3), Gear-5
  and velocity Verlet; Δt_NSCD = 2e-3 and 5e-4 at N = 1 and N = 10.
References: Δt_NSCD = 1e-3 with Δt_SP = 1e-5 (N = 100: the sub-steps converged at the
paper's grain step), and Δt_NSCD = 1e-4, Δt_SP = 1e-5 (both steps fine), Gear-5; each
setting's errors against both.

Errors against the reference at t = t_drop:
  force  the wire's force on each grain (fix wire/grain's per-atom f_wg[1..3], averaged
         over the last time unit), |F − F_ref|₂ / |F_ref|₂ over the grains (F_ref sums to the wire's weight less
         what the floor carries);
  beads  the RMS distance of the beads from the reference, in r_w.
The wire comes to rest on frictional contacts: its resting state depends on the path, so
these errors measure how far a setting's trajectory strays, not a truncation order.
Run time: LIGGGHTS' loop time of the drop (one rank), per simulated time unit.
About 8 minutes (the two references are 2/3 of it)."""

import argparse
import os
import re
import subprocess
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))

HEADER = """
units           lj
atom_style      hybrid polyhedron wire
atom_modify     map array sort 0 0.0
boundary        f f f
"""

PILE = HEADER + """
region          box block -4 4 -4 4 -1 10
create_box      2 box
region          inside block -2.9 2.9 -2.9 2.9 0 10
create_grains   1 16 layer inside 1.15 seed 5 density 1500 spacing 1.45
group           grains type 1
fix             g grains gravity 1.0 vector 0 0 -1
fix             nscd grains nscd/polyhedra damping 20 wall 0 0 0 0 0 1 &
                wall -3 0 0 1 0 0 wall_friction 0 wall 3 0 0 -1 0 0 wall_friction 0 &
                wall 0 -3 0 0 1 0 wall_friction 0 wall 0 3 0 0 -1 0 wall_friction 0
timestep        1e-3
compute         top grains column/height update_on_run_end yes quantile 1
thermo_style    custom step f_nscd[3] c_top
run             6000
fix_modify      nscd damping 0
run             1000
print           "PILE TOP $(c_top)"
reset_timestep  0
write_restart   pile.restart
"""

DROP = HEADER + """
read_restart    pile.restart
group           grains type 1
create_wire     2 loop 0 0 {z} 2 2 0.25
group           wire type 2
fix             g all gravity 1.0 vector 0 0 -1
fix             floor wire wire/wall plane 0 0 0 0 0 1 mu_s {mu} mu_d {mu}
fix             nscd grains nscd/polyhedra timestep {dt_nscd} wall_fix floor &
                wall -3 0 0 1 0 0 wall_friction 0 wall 3 0 0 -1 0 0 wall_friction 0 &
                wall 0 -3 0 0 1 0 wall_friction 0 wall 0 3 0 0 -1 0 wall_friction 0
pair_style      wire/contact mu_s {mu} mu_d {mu}
pair_coeff      * *
neighbor        0.1 bin
neigh_modify    delay 0
fix             elastic wire wire/elastic
fix             integr wire nve/gear scheme {scheme}
fix             wg wire wire/grain grains mu_s {mu} mu_d {mu}
fix             calm wire viscous 0.005
timestep        {dt_sp}
fix             mean grains ave/atom 1 {unit} {steps} f_wg[1] f_wg[2] f_wg[3]
thermo_style    custom step f_wg[1] f_nscd[1]
thermo          {thermo}
dump            dg grains custom {steps} grains.txt id f_mean[1] f_mean[2] f_mean[3]
dump_modify     dg format "%d %.17g %.17g %.17g" sort id
dump            dw wire custom {steps} beads.txt id x y z
dump_modify     dw format "%d %.17g %.17g %.17g" sort id
run             {steps}
"""

# two references: the sub-steps at the paper's Δt_NSCD (N = 100), and both steps fine
REFERENCES = [("1e-3", "1e-5", "gear5"), ("1e-4", "1e-5", "gear5")]
SETTINGS = [  # Δt_NSCD, Δt_SP, scheme
    ("1e-3", "1e-4", "gear5"), ("1e-3", "2e-4", "gear5"), ("1e-3", "5e-4", "gear5"), ("1e-3", "1e-3", "gear5"),
    ("1e-3", "1e-4", "verlet"), ("1e-3", "2e-4", "verlet"), ("1e-3", "5e-4", "verlet"), ("1e-3", "1e-3", "verlet"),
    ("5e-4", "5e-5", "gear5"), ("5e-4", "5e-4", "gear5"), ("2e-3", "2e-4", "gear5"), ("2e-3", "2e-3", "gear5"),
]


def liggghts(args, work, name, text):
    with open(os.path.join(work, name), "w") as f:
        f.write(text)
    out = subprocess.run([args.liggghts, "-in", name, "-log", "none"], cwd=work, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT).stdout.decode(errors="replace")
    if re.search(r"^ERROR", out, re.M) or "Loop time" not in out:
        raise SystemExit(f"{name} failed in {work}:\n" + out[-3000:])
    return out


def read_columns(path):
    with open(path) as f:
        lines = f.read().splitlines()
    k = max(i for i, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))  # the last snapshot
    return np.array([[float(w) for w in line.split()] for line in lines[k + 1:] if line.strip()])


def drop(args, work, dt_nscd, dt_sp, scheme, top):
    name = f"in.drop_{dt_nscd}_{dt_sp}_{scheme}"
    sub = os.path.join(work, name[3:])
    os.makedirs(sub, exist_ok=True)
    os.symlink(os.path.join(work, "pile.restart"), os.path.join(sub, "pile.restart"))
    steps = int(round(args.t_drop / float(dt_sp)))
    out = liggghts(args, sub, "in.drop", DROP.format(z=top + 0.2, mu=args.mu_w, dt_nscd=dt_nscd, dt_sp=dt_sp, scheme=scheme,
                                                     steps=steps, thermo=max(1, steps // 10),
                                                     unit=int(round(1.0 / float(dt_sp)))))
    seconds = float(re.search(r"Loop time of (\S+) on \d+ procs for " + str(steps) + " steps", out).group(1))
    warnings = sorted({line[:100] for line in out.splitlines() if line.startswith("WARNING") and "thermo_style" not in line})
    return dict(seconds=seconds, forces=read_columns(os.path.join(sub, "grains.txt"))[:, 1:4],
                beads=read_columns(os.path.join(sub, "beads.txt"))[:, 1:4], warnings=warnings)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--liggghts", default=os.path.join(HERE, "..", "build", "liggghts"))
    parser.add_argument("--t-drop", type=float, default=6.0)
    parser.add_argument("--out", default="work_precision.png")
    parser.add_argument("--mu-w", type=float, default=0.5,
                        help="the wire's friction (wire-wire, wire-floor, wire-grain); 0: a frictionless drape")
    args = parser.parse_args()
    args.liggghts = os.path.abspath(args.liggghts)
    work = tempfile.mkdtemp(prefix="wiregrain-work-precision-")
    pile = liggghts(args, work, "in.pile", PILE)
    top = float(re.search(r"^PILE TOP (\S+)", pile, re.M).group(1))
    print(f"pile of 16 grains, top at {top:.3f}; wire released at {top + 0.2:.3f}; t_drop = {args.t_drop:g}; "
          f"work dir {work}", flush=True)

    refs = []
    for ref in REFERENCES:
        r = drop(args, work, *ref, top)
        refs.append(r)
        print(f"reference Δt_NSCD {ref[0]}, Δt_SP {ref[1]}: {r['seconds']:.1f} s; wire force on the grains "
              f"|F_ref| = {np.linalg.norm(r['forces']):.4g} (sum z {r['forces'][:, 2].sum():.4g})", flush=True)
    ref_gap = np.sqrt(np.mean(np.sum((refs[0]["beads"] - refs[1]["beads"]) ** 2, axis=1))) / 0.1
    print(f"the two references differ by {ref_gap:.3g} r_w (beads) and "
          f"{np.linalg.norm(refs[0]['forces'] - refs[1]['forces']) / np.linalg.norm(refs[1]['forces']):.3g} (forces)")

    def errors(r, ref):
        return (np.linalg.norm(r["forces"] - ref["forces"]) / np.linalg.norm(ref["forces"]),
                np.sqrt(np.mean(np.sum((r["beads"] - ref["beads"]) ** 2, axis=1))) / 0.1)

    rows = []
    for dt_nscd, dt_sp, scheme in SETTINGS:
        r = drop(args, work, dt_nscd, dt_sp, scheme, top)
        n = int(round(float(dt_nscd) / float(dt_sp)))
        rows.append((dt_nscd, dt_sp, n, scheme, r["seconds"] / args.t_drop) + errors(r, refs[0]) + errors(r, refs[1])
                    + (r["warnings"],))
        print(f"  Δt_NSCD {dt_nscd:>5} Δt_SP {dt_sp:>5} N {n:>3} {scheme:<7} {rows[-1][4]:8.2f} s per time unit"
              + (f"; {r['warnings'][0]}" if r["warnings"] else ""), flush=True)

    print()
    print(f"{'':34}{'against Δt_NSCD 1e-3, Δt_SP 1e-5':^26}{'against 1e-4, 1e-5':^26}")
    print(f"{'Δt_NSCD':>8}{'Δt_SP':>8}{'N':>4}  {'wire':<7}{'s per t':>9}{'speed-up':>9}"
          f"{'force':>13}{'beads/r_w':>13}{'force':>13}{'beads/r_w':>13}")
    base = rows[0][4]
    for dt_nscd, dt_sp, n, scheme, seconds, fa, ba, fb, bb, warnings in rows:
        print(f"{dt_nscd:>8}{dt_sp:>8}{n:>4}  {scheme:<7}{seconds:9.2f}{base / seconds:9.2f}"
              f"{fa:13.3g}{ba:13.3g}{fb:13.3g}{bb:13.3g}" + ("  (warned)" if warnings else ""))

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not available: no PNG")
        return
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
    panels = ((axes[0], 6, "Δt_NSCD 1e-3, Δt_SP 1e-5"), (axes[1], 8, "Δt_NSCD 1e-4, Δt_SP 1e-5"))
    for ax, k, reference in panels:
        for scheme, marker in (("gear5", "o"), ("verlet", "s")):
            for dt_nscd, color in (("1e-3", "C0"), ("5e-4", "C1"), ("2e-3", "C2")):
                if k == 6 and dt_nscd != "1e-3":
                    continue
                pts = [(r[4], r[k], r[2]) for r in rows if r[3] == scheme and r[0] == dt_nscd]
                if not pts:
                    continue
                ax.plot([p[0] for p in pts], [max(p[1], 1e-16) for p in pts], marker=marker, color=color,
                        linestyle="-" if scheme == "gear5" else "--", label=f"Δt_NSCD {dt_nscd}, {scheme}")
                for p in pts:
                    ax.annotate(f"N={p[2]}", (p[0], max(p[1], 1e-16)), fontsize=7, xytext=(3, 3),
                                textcoords="offset points")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("run time per simulated time unit [s] (one rank)")
        ax.set_ylabel(f"bead positions, RMS error / r_w, against {reference}")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle(f"wire dropped on a pile of 16 grains, t = {args.t_drop:g}: error against fine references")
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
