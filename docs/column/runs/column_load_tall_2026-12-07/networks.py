#!/usr/bin/python3
"""The tall column's contact network standing (the plate not yet on it), in the most loaded
snapshot written (the largest plate load F/W among the snapshots) and in the last one (the
end of the load test, or with an in.column_load older than its end snapshot the last of
every t_net), and the silo's at rest, summarised over the seeds (docs/results.md, "The column under
a plate"). Calls postprocess/force_network.py on each snapshot and gathers its JSON.

    networks.py WORK OUT
    networks.py --plot OUT/networks.csv FIGURE.png

WORK holds the runs of command.sh (tall_load_ARM_sSEED/, tall_silo_sSEED/); OUT gets
networks.csv (one line per run and snapshot), the force_network.py summaries
(ARM_sSEED/network_STEP.json), confinement.png (side pressure and K per slab) and
confinement_stress_r.png (the grains' σ_zz against r). With --plot, the figure again from
networks.csv alone. Run from the repository root."""

import csv
import glob
import json
import os
import re
import subprocess
import sys
import warnings

import numpy as np

SCRIPT = os.path.join("postprocess", "force_network.py")
SLABS = 6
RINGS, R_MAX = 6, 9.0   # rings 1.5 a_max wide about the axis (the wire at R = 3: the first two)


def network(run, step, out, radius, *extra):
    subprocess.run([sys.executable, SCRIPT, run, "--step", str(step), "--R", str(radius), "--z-bins", str(SLABS),
                    "--r-bins", str(RINGS), "--r-max", str(R_MAX), "--no-plots", "--no-picture", "--out", out, *extra],
                   check=True, capture_output=True)
    with open(os.path.join(out, f"network_{step}.json")) as f:
        return json.load(f)


def steps(post, prefix):
    return sorted(int(re.search(r"_(\d+)\.dump$", p).group(1)) for p in glob.glob(f"{post}/{prefix}_contacts_*.dump"))


def row(name, arm, seed, snapshot, step, r, load=None):
    n, c = r["networks"]["strong"], r["confinement"]
    mid = r["transmission"][len(r["transmission"]) // 2]
    k = np.array([np.nan if v is None else v for v in c["K"]], dtype=float)
    p = np.array(c["pressure"], dtype=float)
    return {"run": name, "arm": arm, "seed": seed, "snapshot": snapshot, "step": step,
            "F/W": load if load is not None else "", "beta": r["forces"]["beta"],
            "strong_contacts": n["fraction_of_contacts"], "strong_force": n["fraction_of_force"],
            "strong_angle": n["fabric_weighted"]["angle_from_vertical"] if n["fabric_weighted"] else "",
            "strong_major": n["fabric_weighted"]["eigenvalues"][-1] if n["fabric_weighted"] else "",
            "inner_fraction_mid": mid["inner_fraction"], "z_mid": mid["z"],
            "F_wire_side": c["F_wire"], "F_walls_side": c["F_walls"],
            "p_mean": float(np.nanmean(p[1:-1])), "K_mean": float(np.nanmean(k[1:-1])),
            "K": " ".join(f"{v:.4g}" for v in k), "p": " ".join(f"{v:.4g}" for v in p),
            "sigma_v": " ".join(f"{float(v):.4g}" for v in c["sigma_v"]),
            "q_wire": " ".join(f"{v:.4g}" for v in c["q_wire"]), "q_hoop": " ".join(f"{v:.4g}" for v in c["q_hoop"]),
            "sigma_zz_r": " ".join("nan" if v is None else f"{v:.4g}" for v in r["stress"]["along_r"]["mean"]),
            "grains_r": " ".join(str(v) for v in r["stress"]["along_r"]["grains"])}


def main(work, out):
    rows = []
    for run in sorted(glob.glob(f"{work}/tall_load_*_s*")):
        name = os.path.basename(run)
        arm, seed = re.match(r"tall_load_(.+)_s(\d+)$", name).groups()
        post = os.path.join(run, "post")
        series = np.loadtxt(os.path.join(post, "load.txt"), comments="#")
        # TimeStep t d strain F_grains F_wire F F/W ...: the plate load at each written step
        load_at = {int(s): series[k, 7] for k, s in enumerate(series[:, 0])}
        have = steps(post, "load")
        loaded = max(have[1:], key=lambda s: load_at.get(s, -1.0))
        for snapshot, step in (("standing", have[0]), ("loaded", loaded), ("last", have[-1])):
            r = network(run, step, os.path.join(out, f"{arm}_s{seed}"), 3)
            rows.append(row(name, arm, seed, snapshot, step, r, load_at.get(step)))
    for run in sorted(glob.glob(f"{work}/tall_silo_s*")):
        seed = re.search(r"_s(\d+)$", run).group(1)
        step = steps(os.path.join(run, "post"), "silo")[-1]
        # R: the silo's inscribed circle (r < R/2 is 0.196 of its section, against 1/4 of a disc)
        r = network(run, step, os.path.join(out, f"silo_s{seed}"), 4.5, "--prefix", "silo", "--section", "square", "9")
        rows.append(row(os.path.basename(run), "silo", seed, "at rest", step, r))
    with open(os.path.join(out, "networks.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    groups = grouped(rows)
    for (arm, snapshot), rs in groups.items():
        line = [f"{arm:8s} {snapshot:9s} n={len(rs)}"]
        for key in ("F/W", "beta", "strong_contacts", "strong_force", "strong_angle", "inner_fraction_mid", "p_mean",
                    "K_mean", "F_wire_side", "F_walls_side"):
            v = np.array([float(r[key]) for r in rs if r[key] not in ("", None)], dtype=float)
            v = v[np.isfinite(v)]
            if len(v):
                se = v.std(ddof=1) / np.sqrt(len(v)) if len(v) > 1 else float("nan")
                line.append(f"{key} {v.mean():.3g} +- {se:.2g}")
        print("; ".join(line))
    plot(groups, os.path.join(out, "confinement.png"))


def grouped(rows):
    groups = {}
    for r in rows:
        groups.setdefault((r["arm"], r["snapshot"]), []).append(r)
    return groups


def plot(groups, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(9, 4.8), sharey=True)
    z = (np.arange(SLABS) + 0.5) / SLABS
    style = {("wire", "standing"): ("C0", "-", "wire, standing"), ("wire", "loaded"): ("C0", "--", "wire, most loaded"),
             ("no_wire", "standing"): ("C1", "-", "no wire, standing"),
             ("no_wire", "loaded"): ("C1", "--", "no wire, most loaded"), ("silo", "at rest"): ("C3", "-", "silo at rest")}
    for key, (colour, ls, label) in style.items():
        if key not in groups or key[0] == "no_wire":   # nothing holds the grains in sideways
            continue
        p = np.array([[float(v) for v in r["p"].split()] for r in groups[key]])
        k = np.array([[float(v) for v in r["K"].split()] for r in groups[key]])
        ax.plot(p.mean(0), z, ls, color=colour, marker="o", ms=3, label=f"{label} ({len(p)})")
        bx.plot(np.nanmean(k, 0), z, ls, color=colour, marker="o", ms=3)
    ax.set_xlabel("side pressure p (m g / a_max²)")
    ax.set_ylabel("slab centre / column top")
    ax.legend(fontsize=8)
    bx.set_xlabel("K = p / σ_v")
    bx.axvline(0, color="0.6", lw=0.6)
    fig.suptitle("what holds the grains in: the wire (R = 3) against the silo's walls (D = 9)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    # the grains' vertical stress against their distance from the axis
    fig, ax = plt.subplots(figsize=(6, 4.5))
    rings = (np.arange(RINGS) + 0.5) * R_MAX / RINGS
    for key, (colour, ls, label) in style.items():
        if key not in groups:
            continue
        s = -np.array([[float(v) for v in r["sigma_zz_r"].split()] for r in groups[key]])
        with warnings.catch_warnings():   # rings no grain reaches (the silo's beyond its corners)
            warnings.simplefilter("ignore", RuntimeWarning)
            mean = np.nanmean(s, 0)
        ax.plot(rings, mean, ls, color=colour, marker="o", ms=3, label=f"{label} ({len(s)})")
    ax.axvline(3.0, color="0.6", lw=0.6)
    ax.text(3.05, ax.get_ylim()[1] * 0.95, "wire, R = 3", fontsize=8, va="top")
    ax.set_xlabel("distance of the grain's centre from the axis r (a_max)")
    ax.set_ylabel("−σ_zz, volume-weighted mean over the ring's grains")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path.replace(".png", "_stress_r.png"), dpi=110)


if __name__ == "__main__":
    if sys.argv[1] == "--plot":
        with open(sys.argv[2], newline="") as f:
            plot(grouped(list(csv.DictReader(f))), sys.argv[3])
    else:
        main(sys.argv[1], sys.argv[2])
