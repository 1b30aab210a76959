#!/usr/bin/python3
"""Janssen's law fitted to the floor load of the silo that input_scripts/in.silo fills
(its time series post/silo.txt: layer phase t N H z_cm W F_floor F_walls ke quiet).

    postprocess/janssen.py RUN [RUN ...] [--phase auto|mobilized|rest] [--density measured|fitted]
                           [--height H|zcm] [--D D] [--mu-wall MU] [--plot FILE.png] [--json]

RUN is a run's folder (its post/silo.txt is read, else its silo.txt) or the file itself. Janssen's law for a
square section of side D (area A = D², perimeter 4D), wall friction μ_w fully mobilized
and a horizontal-to-vertical stress ratio K:

    M_floor(H) = ρ_b g A λ (1 − exp(−H/λ)),   λ = A / (perimeter μ_w K) = D / (4 μ_w K)

The bulk weight per height ρ_b g A is taken from the data (--density measured, the
default): each state's own W/H, Janssen's uniform fill (W = ρ_b g A H), so that

    M_floor / W = (λ / H) (1 − exp(−H/λ))

and λ is the only parameter, fitted by least squares on M_floor (scipy curve_fit); its
standard error comes from the fit's covariance scaled by the residuals (absolute_sigma
False), and K = D / (4 μ_w λ) with σ_K = K σ_λ / λ. W is known exactly, so fitting ρ_b g A
as a second parameter (--density fitted: M = w λ (1 − exp(−H/λ)) with w free) only adds a
parameter that correlates with λ when H is not several λ (the 9 a_max silo reaches H ≈ λ);
it is there to compare with the measured W/H. --height zcm uses 2 z_cm (the height of a
uniform fill with the grains' centre of mass) instead of H (the 0.98 quantile of the grains'
tops, compute column/height), which lies above the mean surface by a fraction of a grain.

Which lines (--phase): `mobilized`: the lines of phase 2 (the loads averaged while the floor
descends, in.silo v_floor > 0: the wall friction fully mobilized, as Janssen assumes);
`rest`: the lines of phase 0 (each layer settled) with quiet = 1, the last layer's replaced
by the final line (phase 1, quiet or not); `auto` (default): mobilized for a run that has
phase 2 lines, rest otherwise. D and μ_w are read from the file's header (# D ... mu_wall
...) unless given.

Per run one line: its phase, points, the largest H, M_floor/W there, λ ± σ, K ± σ, and the
saturation: the least-squares slope dM_floor/dW over the last third of its points (at least
3), the fraction of the last layers' weight that still reaches the floor (1 without wall
friction, exp(−H/λ) by Janssen). Then per phase the fit of all its runs' points together and,
with 2 or more runs, K's mean and standard error over the runs. --json adds a last line with
all of it. --plot draws M_floor/W against H, every run's points and each phase's common fit
(matplotlib, Agg)."""

import argparse
import json
import math
import os
import sys

import numpy as np
from scipy.optimize import curve_fit

COLUMNS = ["layer", "phase", "t", "N", "H", "z_cm", "W", "F_floor", "F_walls", "ke", "quiet"]
PHASES = {"rest": (0, 1), "mobilized": (2,)}


def read_silo(path):
    """(header parameters as a dict of strings, columns as a dict of arrays) of a silo.txt."""
    if os.path.isdir(path):
        inside = os.path.join(path, "post", "silo.txt")
        path = inside if os.path.exists(inside) else os.path.join(path, "silo.txt")
    params, rows = {}, []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                words = line[1:].split()
                if words and words[0] == "D":
                    params.update(zip(words[0::2], words[1::2]))
                continue
            if line.strip():
                rows.append([float(v) for v in line.split()])
    if not rows:
        raise ValueError(f"{path}: no data lines")
    data = np.array(rows)
    if data.shape[1] != len(COLUMNS):
        raise ValueError(f"{path}: {data.shape[1]} values per line, expected {len(COLUMNS)} ({' '.join(COLUMNS)})")
    return params, {name: data[:, k] for k, name in enumerate(COLUMNS)}


def select(series, phase):
    """Indices of the lines of `phase` ("mobilized" or "rest"), in the order of the file."""
    kind = series["phase"].astype(int)
    if phase == "mobilized":
        return np.nonzero(kind == 2)[0]
    final = np.nonzero(kind == 1)[0]
    settled = (kind == 0) & (series["quiet"] == 1)
    if len(final):
        settled &= series["layer"] != series["layer"][final[-1]]
    return np.sort(np.concatenate([np.nonzero(settled)[0], final]))


def janssen_ratio(H, lam):
    """M_floor / W of a uniform fill of height H: (λ / H)(1 − exp(−H/λ))."""
    x = H / lam
    return -np.expm1(-x) / x


def fit(H, W, M, D, mu_wall, density="measured"):
    """Janssen's λ and K with their standard errors from the states (H, W, M_floor);
    density "measured": ρ_b g A = W/H per state, λ the only parameter; "fitted": w free."""
    H, W, M = (np.asarray(a, dtype=float) for a in (H, W, M))
    if len(H) < 2 + (density == "fitted"):
        raise ValueError(f"{len(H)} points: too few for a fit")
    scale = float(np.max(H))
    # the start: the saturated load of the last point's state, M/W = λ/H, else a few H
    guess = float(np.clip(M[-1] / W[-1] * H[-1], 0.05 * scale, 20 * scale))
    bounds_lam = (1e-6 * scale, 1e6 * scale)
    if density == "measured":
        model = lambda h, lam: W * janssen_ratio(h, lam)  # noqa: E731 (W of the same states)
        p, cov = curve_fit(model, H, M, p0=[guess], bounds=([bounds_lam[0]], [bounds_lam[1]]), absolute_sigma=False)
        lam, sigma_lam, w = float(p[0]), float(math.sqrt(cov[0, 0])), float(np.sum(W * H) / np.sum(H * H))
        sigma_w = float("nan")
    elif density == "fitted":
        w0 = float(np.sum(W * H) / np.sum(H * H))
        model = lambda h, w, lam: w * h * janssen_ratio(h, lam)  # noqa: E731
        p, cov = curve_fit(model, H, M, p0=[w0, guess], bounds=([0, bounds_lam[0]], [np.inf, bounds_lam[1]]),
                           absolute_sigma=False)
        w, lam = float(p[0]), float(p[1])
        sigma_w, sigma_lam = float(math.sqrt(cov[0, 0])), float(math.sqrt(cov[1, 1]))
    else:
        raise ValueError(f"density must be measured or fitted, got {density}")
    K = D / (4 * mu_wall * lam) if mu_wall > 0 else float("inf")
    predicted = model(H, *p)
    # λ at its upper bound: the floor carries the weight or more (walls pulling down on
    # balance), which no K > 0 describes
    return {"lambda": lam, "at_bound": bool(lam >= 0.5 * bounds_lam[1]), "sigma_lambda": sigma_lam, "K": K,
            "sigma_K": K * sigma_lam / lam,
            "w": w, "sigma_w": sigma_w, "rms": float(np.sqrt(np.mean((M - predicted) ** 2))), "points": int(len(H))}


def saturation(W, M):
    """The least-squares slope dM/dW over the last third of the points (at least 3)."""
    n = max(3, int(math.ceil(len(W) / 3)))
    if len(W) < 3:
        return float("nan")
    return float(np.polyfit(W[-n:], M[-n:], 1)[0])


def label_of(path):
    path = os.path.abspath(path)
    if os.path.isfile(path):
        parent = os.path.dirname(path)
        path = os.path.dirname(parent) if os.path.basename(parent) == "post" else parent
    return os.path.basename(path)


def heights(series, which):
    return series["H"] if which == "H" else 2 * series["z_cm"]


def analyse(paths, phase="auto", density="measured", height="H", D=None, mu_wall=None):
    """Per run and per phase fits (module doc) as a dict."""
    runs, groups = [], {}
    for path in paths:
        params, series = read_silo(path)
        d = float(D if D is not None else params.get("D", "nan"))
        mu = float(mu_wall if mu_wall is not None else params.get("mu_wall", "nan"))
        if not (d > 0) or not (mu >= 0):
            raise ValueError(f"{path}: D and mu_wall neither in the header nor given (--D, --mu-wall)")
        which = phase
        if which == "auto":
            which = "mobilized" if np.any(series["phase"] == 2) else "rest"
        idx = select(series, which)
        H, W, M = heights(series, height)[idx], series["W"][idx], series["F_floor"][idx]
        run = {"run": label_of(path), "phase": which, "D": d, "mu_wall": mu, "H": H.tolist(), "W": W.tolist(),
               "M": M.tolist(), "H_max": float(H.max()) if len(H) else float("nan"),
               "M_over_W_at_H_max": float(M[np.argmax(H)] / W[np.argmax(H)]) if len(H) else float("nan"),
               "saturation": saturation(W, M)}
        try:
            run.update(fit(H, W, M, d, mu, density))
        except (ValueError, RuntimeError) as error:
            run["error"] = str(error)
        runs.append(run)
        groups.setdefault(which, []).append(run)
    phases = {}
    for which, members in groups.items():
        summary = {"runs": len(members)}
        if len({(r["D"], r["mu_wall"]) for r in members}) == 1:
            H = np.concatenate([r["H"] for r in members])
            W = np.concatenate([r["W"] for r in members])
            M = np.concatenate([r["M"] for r in members])
            try:
                summary["pooled"] = fit(H, W, M, members[0]["D"], members[0]["mu_wall"], density)
            except (ValueError, RuntimeError) as error:
                summary["pooled"] = {"error": str(error)}
        Ks = [r["K"] for r in members if "K" in r]
        if len(Ks) >= 2:
            summary["K_mean"] = float(np.mean(Ks))
            summary["K_standard_error"] = float(np.std(Ks, ddof=1) / math.sqrt(len(Ks)))
        phases[which] = summary
    return {"runs": runs, "phases": phases, "density": density, "height": height}


def plot(result, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    markers = {"mobilized": "o", "rest": "s"}
    colours = {"mobilized": "C0", "rest": "C1"}
    H_top = max((r["H_max"] for r in result["runs"] if np.isfinite(r["H_max"])), default=1.0)
    for r in result["runs"]:
        H, W, M = np.array(r["H"]), np.array(r["W"]), np.array(r["M"])
        ax.plot(H, M / W, markers[r["phase"]], color=colours[r["phase"]], alpha=0.6, ms=4,
                mfc="none" if r["phase"] == "rest" else colours[r["phase"]])
    h = np.linspace(1e-3 * H_top, 1.05 * H_top, 200)
    for which, summary in result["phases"].items():
        pooled = summary.get("pooled", {})
        if "lambda" not in pooled:
            continue
        ax.plot(h, janssen_ratio(h, pooled["lambda"]), "-", color=colours[which],
                label=f"{which}: K = {pooled['K']:.3g} ± {pooled['sigma_K']:.2g}, λ = {pooled['lambda']:.3g}")
    ax.axhline(1.0, color="0.6", lw=0.8, ls=":")
    ax.set_xlabel("fill height H (a_max)")
    ax.set_ylabel("floor load / weight of the grains")
    ax.set_ylim(0, 1.1)
    ax.set_xlim(0, 1.05 * H_top)
    ax.legend(loc="lower left", fontsize=8, title="Janssen fit, (λ/H)(1 − exp(−H/λ))", title_fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("runs", nargs="+", help="run folders (post/silo.txt or silo.txt) or silo.txt files")
    parser.add_argument("--phase", choices=["auto", "mobilized", "rest"], default="auto")
    parser.add_argument("--density", choices=["measured", "fitted"], default="measured")
    parser.add_argument("--height", choices=["H", "zcm"], default="H")
    parser.add_argument("--D", type=float, help="the container's side (default: the file's header)")
    parser.add_argument("--mu-wall", type=float, help="the side walls' friction (default: the file's header)")
    parser.add_argument("--plot", help="write the figure to this file")
    parser.add_argument("--json", action="store_true", help="a last line with everything as JSON")
    args = parser.parse_args(argv)
    result = analyse(args.runs, args.phase, args.density, args.height, args.D, args.mu_wall)
    print(f"{'run':24s} {'phase':9s} {'pts':>3s} {'H_max':>7s} {'M/W':>6s} {'lambda':>16s} {'K':>16s} {'dM/dW':>7s}")
    for r in result["runs"]:
        if "error" in r:
            print(f"{r['run']:24s} {r['phase']:9s} {len(r['H']):3d}  {r['error']}")
            continue
        print(f"{r['run']:24s} {r['phase']:9s} {r['points']:3d} {r['H_max']:7.3f} {r['M_over_W_at_H_max']:6.3f} "
              f"{r['lambda']:8.4g} ± {r['sigma_lambda']:<5.2g} {r['K']:8.4g} ± {r['sigma_K']:<5.2g} "
              f"{r['saturation']:7.3f}" + ("  lambda at its bound (M_floor >= W)" if r["at_bound"] else ""))
    for which, s in result["phases"].items():
        p = s.get("pooled", {})
        line = f"{which}: {s['runs']} run(s)"
        if "lambda" in p:
            line += (f", all points: lambda = {p['lambda']:.4g} ± {p['sigma_lambda']:.2g}, "
                     f"K = {p['K']:.4g} ± {p['sigma_K']:.2g} ({p['points']} points, rms {p['rms']:.3g})")
        if "K_mean" in s:
            line += f"; over runs K = {s['K_mean']:.4g} ± {s['K_standard_error']:.2g} (standard error)"
        print(line)
    if args.plot:
        plot(result, args.plot)
    if args.json:
        print(json.dumps(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
