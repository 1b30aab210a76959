"""input_scripts/in.silo and postprocess/janssen.py on narrow silos (D = 4 a_max, 4 grains a
layer, placement random): Janssen's saturation of the floor load when the floor is lowered
after each layer (the wall friction fully mobilized), the vertical force balance of the pile
at rest with frictionless and with frictional side walls, the deck's checks of its
variables, and the fit on synthetic series of known K."""

import json
import os
import subprocess
import sys
import tempfile

import numpy as np

from liggghts_run import SOURCE, DeckTestCase, deck, main, run

sys.path.insert(0, os.path.join(SOURCE, "postprocess"))
import janssen  # noqa: E402

SILO = deck("input_scripts/in.silo")
JANSSEN = os.path.join(SOURCE, "postprocess", "janssen.py")
COLUMNS = ["layer", "phase", "t", "N", "H", "z_cm", "W", "F_floor", "F_walls", "ke", "quiet"]
NARROW = {"D": 4, "placement": "random", "dump_layers": 0, "t_check": 0.25, "root": SOURCE}
# (a) 12 layers of 4 grains, each settled to 1e-4 m g a_max per grain, then the floor lowered
# by 0.05 a_max at 0.05; no relaxation at the end
LOWERED = dict(NARROW, nlayers=12, Np=48, t_layer=10, ke_layer=1e-4, t_quiet_layer=0.5, v_floor=0.05,
               floor_drop=0.05, t_relax=0)
# (b), (c) the floor stays; every layer settles to 1e-6, the last to rest (1e-30)
AT_REST = dict(NARROW, t_layer=20, ke_relax=1e-30, t_quiet=1, t_relax=20)
# a state at rest to round-off: the grains' kinetic energy per grain below this (m g a_max)
STILL = 1e-30


def series(result):
    data = np.loadtxt(result.path("post/silo.txt"), comments="#", ndmin=2)
    return {name: data[:, k] for k, name in enumerate(COLUMNS)}


def imbalance(s):
    """(F_floor + F_walls − W) / W per line: the vertical momentum balance of the grains,
    whose only vertical forces are gravity, the floor's and the side walls' (g = 1)."""
    return (s["F_floor"] + s["F_walls"] - s["W"]) / s["W"]


class Janssen(DeckTestCase):
    """(a) The floor lowered after every layer: the floor load saturates."""

    @classmethod
    def setUpClass(cls):
        cls.result = run(SILO, variables=LOWERED)

    def test_ran_and_wrote_every_line(self):
        self.assertRanCleanly(self.result)
        s = series(self.result)
        self.assertEqual(list(s["phase"]), [0, 2] * 12 + [1])
        np.testing.assert_array_equal(s["N"][s["phase"] != 1], np.repeat(4 * np.arange(1, 13), 2))

    # The descent moves the pile as a block: the loads averaged over its second half balance
    # the weight up to the mean acceleration of that half (measured: at most 1.0e-2 W over the
    # 12 descents of seeds 4242 and 1, 2026-12-06); the kinetic energy per grain is then that
    # of the block, v_floor² / 2 = 1.25e-3, not the settling of a layer (measured 1.3–6.0e-3).
    def test_descents_are_slow_enough_to_balance(self):
        s = series(self.result)
        lowered = s["phase"] == 2
        off = np.abs(imbalance(s)[lowered])
        print(f"descents: |F_floor + F_walls - W| / W at most {off.max():.2e}, kinetic energy per grain "
              f"{s['ke'][lowered].min():.2e} to {s['ke'][lowered].max():.2e}")
        self.assertLess(off.max(), 0.03)
        self.assertLess(s["ke"][lowered].max(), 0.02)

    # Janssen: M_floor = w λ (1 − exp(−H/λ)), so each layer's weight adds exp(−H/λ) of itself
    # to the floor, and M_floor/W = (λ/H)(1 − exp(−H/λ)) falls as 1/H once H >> λ; without
    # wall friction both would be 1. Measured on seed 4242 (2026-12-06): over the last third
    # of the layers dM_floor/dW = 0.058 (over seeds 1–4 of the same silo −0.34 to −0.02: the
    # slope of 4 noisy points), M_floor/W = 0.42 at H = 9.1, K = 0.465 ± 0.016 (seeds 1–4:
    # 0.34–0.59). The bounds: dM/dW < 0.4, well below 1 and above Janssen's exp(−H/λ) ≈ 0.12
    # plus the seeds' scatter; M/W < 0.6; 0.2 < K < 1.5 — K of a granular material at rest
    # or sliding down slowly lies between the active Rankine K_a = (1 − sin φ)/(1 + sin φ)
    # (0.22 for an internal friction angle φ of 40°, more below it) and well below the
    # passive K_p = 1/K_a (≥ 2.5 for φ ≥ 25°).
    def test_floor_load_saturates_and_K_is_sensible(self):
        out = subprocess.run([sys.executable, JANSSEN, self.result.workdir, "--json"], capture_output=True, text=True,
                             check=True).stdout
        result = json.loads(out.splitlines()[-1])
        r = result["runs"][0]
        print(f"lowered floor: dM_floor/dW over the last third {r['saturation']:.3f}, M/W {r['M_over_W_at_H_max']:.3f} "
              f"at H = {r['H_max']:.2f}, K = {r['K']:.3f} ± {r['sigma_K']:.3f}, lambda = {r['lambda']:.3f}")
        self.assertEqual(r["phase"], "mobilized")
        self.assertEqual(r["points"], 12)
        self.assertGreater(r["H_max"], 2 * LOWERED["D"])  # H >> D
        self.assertLess(r["saturation"], 0.4)
        self.assertLess(r["M_over_W_at_H_max"], 0.6)
        self.assertGreater(r["K"], 0.2)
        self.assertLess(r["K"], 1.5)
        self.assertLess(r["sigma_K"], 0.2 * r["K"])


class AtRest(DeckTestCase):
    """(b), (c) The vertical force balance of the pile at rest."""

    @classmethod
    def setUpClass(cls):
        cls.frictionless = run(SILO, variables=dict(AT_REST, nlayers=3, Np=12, mu_wall=0))
        cls.frictional = run(SILO, variables=dict(AT_REST, nlayers=6, Np=24, mu_wall=0.5))

    def test_ran(self):
        self.assertRanCleanly(self.frictionless)
        self.assertRanCleanly(self.frictional)

    # (b) Frictionless side walls push horizontally only: their vertical load is 0 exactly in
    # every line, and at rest the floor carries the weight. At rest to round-off (kinetic
    # energy per grain < 1e-30; the closing stick solve of subspace_closing 0 makes the
    # contact problem exact at rest, below the solver's tolerance 1e-4) measured
    # |F_floor − W| / W ≤ 1.2e-15 over 3 such lines (2026-12-06): tolerance 1e-12. Residual
    # motion spoils it: a line with the deck's quiet flag (kinetic energy per grain < 1e-6
    # for a time unit) but not at rest, measured 7.0e-6 here and up to 5.8e-3 in other seeds
    # (a grain still rocking at 1.3e-7): tolerance 2e-2 for those.
    def test_frictionless_walls_floor_carries_the_weight(self):
        s = series(self.frictionless)
        self.assertTrue(np.all(s["F_walls"] == 0), s["F_walls"])
        still = s["ke"] < STILL
        quiet = (s["quiet"] == 1) & ~still
        print(f"frictionless walls: {int(still.sum())} lines at rest, |F_floor/W - 1| at most "
              f"{np.abs(s['F_floor'][still] / s['W'][still] - 1).max():.1e}; {int(quiet.sum())} quiet lines not at rest, "
              f"at most {np.abs(s['F_floor'][quiet] / s['W'][quiet] - 1).max(initial=0):.1e}")
        self.assertEqual(s["ke"][-1] < STILL, True, "the final state is not at rest")
        self.assertGreaterEqual(int(still.sum()), 2)
        np.testing.assert_allclose(s["F_floor"][still], s["W"][still], rtol=1e-12)
        np.testing.assert_allclose(s["F_floor"][quiet], s["W"][quiet], rtol=2e-2)

    # (c) With wall friction the walls carry part of the weight, a share that the history of
    # the rigid pile sets (here up to 14.6 % of W; −22 % to +17 % in a 15-layer pile), and at
    # rest floor + walls = W, whatever Janssen says. Measured |F_floor + F_walls − W| / W
    # ≤ 4.2e-16 over the 4 lines at rest to round-off (2026-12-06): tolerance 1e-12; the
    # walls' share is 11 orders of magnitude above it, so leaving F_walls out fails. Quiet
    # lines not at rest: measured up to 1.1e-7 here; tolerance 2e-2 as in (b).
    def test_frictional_walls_floor_and_walls_carry_the_weight(self):
        s = series(self.frictional)
        still = s["ke"] < STILL
        quiet = (s["quiet"] == 1) & ~still
        off = np.abs(imbalance(s))
        share = np.abs(s["F_walls"] / s["W"])
        print(f"frictional walls: {int(still.sum())} lines at rest, |F_floor + F_walls - W| / W at most "
              f"{off[still].max():.1e}, the walls' share up to {share[still].max():.3f}; {int(quiet.sum())} quiet lines "
              f"not at rest: at most {off[quiet].max(initial=0):.1e}")
        self.assertEqual(s["ke"][-1] < STILL, True, "the final state is not at rest")
        self.assertGreaterEqual(int(still.sum()), 2)
        self.assertGreater(share[still].max(), 0.01)
        self.assertLess(off[still].max(), 1e-12)
        self.assertLess(off[quiet].max(initial=0), 2e-2)


class BadInput(DeckTestCase):
    """(d) The deck's checks of its variables."""

    def test_bad_variables_stop_with_a_message(self):
        for variables, message in (
                ({"D": 0}, "ERROR: in.silo: D must be > 0, got 0"),
                ({"D": 2}, "ERROR: in.silo: D (2) must be > 2 (a_max + 0.1) = 2.2: the grains must fit between the "
                           "side walls"),
                ({"mu_wall": -0.1}, "ERROR: in.silo: mu_wall must be >= 0, got -0.1"),
                ({"placement": "heap"}, "ERROR: in.silo: placement must be layer or random, got heap"),
                ({"D": 6}, "ERROR: in.silo: a layer of placement layer in D = 6 has 1 lattice site(s), fewer than its "
                           "13 grains (Np / nlayers, the remainder in the last): widen D, add layers or use "
                           "placement random"),
                ({"v_floor": -1}, "ERROR: in.silo: v_floor must be >= 0 (0: the floor stays), got -1"),
                ({"v_floor": 10, "floor_drop": 0.01}, "ERROR: in.silo: floor_drop (0.01) must be at least 2 v_floor "
                                                      "dt_NSCD (v_floor 10, dt_NSCD 2e-3)"),
                ({"t_check": 2}, "ERROR: in.silo: t_check must be > 0 and t_quiet, t_quiet_layer >= t_check, got 2, "
                                 "5 and 1"),
                ({"slab": 0}, "ERROR: in.silo: slab must be > 0, got 0")):
            with self.subTest(**variables):
                self.assertStopsWith(run(SILO, variables=dict(variables, root=SOURCE)), message)


def write_series(folder, H, W, M, D, mu_wall, phase=2):
    """A post/silo.txt of the given states (one line each, all of one phase)."""
    os.makedirs(os.path.join(folder, "post"), exist_ok=True)
    with open(os.path.join(folder, "post", "silo.txt"), "w") as f:
        f.write("# in.silo time series (input_scripts/in.silo)\n")
        f.write(f"# D {D!r} mu_wall {mu_wall!r} mu_floor 0.5 seed 1\n")
        f.write("# " + " ".join(COLUMNS) + "\n")
        for k, (h, w, m) in enumerate(zip(H, W, M), 1):
            f.write(f"{k} {phase} {k} {4 * k} {h!r} {h / 2!r} {w!r} {m!r} {w - m!r} 0 1\n")


def janssen_load(H, w, D, mu_wall, K):
    lam = D / (4 * mu_wall * K)
    return w * lam * (1 - np.exp(-H / lam))


class JanssenFit(DeckTestCase):
    """(e) postprocess/janssen.py on series made from Janssen's law."""

    D, MU, K, w = 4.0, 0.5, 0.45, 11.0
    H = np.linspace(1.0, 12.0, 12)

    def test_recovers_K_of_a_noise_free_series(self):
        folder = tempfile.mkdtemp(prefix="wiregrain-")
        write_series(folder, self.H, self.w * self.H, janssen_load(self.H, self.w, self.D, self.MU, self.K), self.D,
                     self.MU)
        plot = os.path.join(folder, "janssen.png")
        out = subprocess.run([sys.executable, JANSSEN, folder, "--json", "--plot", plot], capture_output=True, text=True,
                             check=True).stdout
        r = json.loads(out.splitlines()[-1])["runs"][0]
        self.assertEqual(r["phase"], "mobilized")
        lam = self.D / (4 * self.MU * self.K)
        self.assertAlmostEqual(r["K"] / self.K, 1.0, delta=1e-6)
        self.assertAlmostEqual(r["lambda"] / lam, 1.0, delta=1e-6)
        self.assertGreater(os.path.getsize(plot), 1000)
        # the bulk weight per height as a second parameter: w and K again
        fitted = janssen.fit(self.H, self.w * self.H, janssen_load(self.H, self.w, self.D, self.MU, self.K), self.D,
                             self.MU, density="fitted")
        self.assertAlmostEqual(fitted["K"] / self.K, 1.0, delta=1e-6)
        self.assertAlmostEqual(fitted["w"] / self.w, 1.0, delta=1e-6)

    # With Gaussian noise of known σ on M_floor, the fit's standard error of K (the covariance
    # scaled by the residuals) covers the truth as a standard error should: with 12 points and
    # one parameter, |K − K_true| / σ_K follows Student's t of 11 degrees of freedom nearly
    # (the model is smooth in λ at this noise), so it is ≤ 1 in 66.1 % and ≤ 2 in 92.9 % of
    # the series (scipy.stats.t). Over 400 series the binomial standard deviations of these
    # fractions are 0.024 and 0.013; bounds 3 of them (measured 0.627 and 0.930, 2026-12-06).
    def test_standard_error_covers_the_truth(self):
        from scipy.stats import t as student
        rng = np.random.default_rng(7)
        sigma = 0.5  # force units: 1 % of the saturated load w λ = 48.9
        exact = janssen_load(self.H, self.w, self.D, self.MU, self.K)
        within1 = within2 = 0
        found = []
        n = 400
        for _ in range(n):
            r = janssen.fit(self.H, self.w * self.H, exact + sigma * rng.standard_normal(len(self.H)), self.D, self.MU)
            within1 += abs(r["K"] - self.K) <= r["sigma_K"]
            within2 += abs(r["K"] - self.K) <= 2 * r["sigma_K"]
            found.append(r["K"])
        for k, within in ((1, within1), (2, within2)):
            p = student.cdf(k, len(self.H) - 1) - student.cdf(-k, len(self.H) - 1)
            spread = np.sqrt(p * (1 - p) / n)
            print(f"noise sigma {sigma}: within {k} sigma_K {within / n:.3f} (expected {p:.3f} ± {spread:.3f})")
            self.assertLess(abs(within / n - p), 3 * spread)
        print(f"K = {np.mean(found):.5f} (true {self.K}), spread {np.std(found):.5f}")
        self.assertLess(abs(np.mean(found) - self.K), 3 * np.std(found) / np.sqrt(n))

    def test_mean_over_runs_and_the_rest_lines(self):
        folders = []
        for K in (0.4, 0.5):
            folders.append(tempfile.mkdtemp(prefix="wiregrain-"))
            write_series(folders[-1], self.H, self.w * self.H, janssen_load(self.H, self.w, self.D, self.MU, K),
                         self.D, self.MU)
        result = janssen.analyse(folders)
        phase = result["phases"]["mobilized"]
        self.assertAlmostEqual(phase["K_mean"], 0.45, delta=1e-6)
        self.assertAlmostEqual(phase["K_standard_error"], 0.05, delta=1e-6)  # std 0.0707 over √2
        # rest: the settled lines of phase 0 (quiet 1), the last layer's replaced by the final line
        s = {"layer": np.array([1, 2, 3, 3]), "phase": np.array([0, 0, 0, 1]), "quiet": np.array([1, 0, 1, 1])}
        self.assertEqual(list(janssen.select(s, "rest")), [0, 3])


if __name__ == "__main__":
    main()
