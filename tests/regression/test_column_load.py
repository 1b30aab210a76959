"""input_scripts/in.column_load on tiny columns built by input_scripts/in.column (3 particle
layers of 5 grains, R = 2, with and without the wire): the momentum balance of its time
series, the plate force against the contacts it lists, the strain at which it stops, and
its checks of its variables."""

import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

import numpy as np

from liggghts_run import SOURCE, DeckTestCase, deck, deck_box, main, read_local_dump, run

COLUMN = deck("input_scripts/in.column")
LOAD = deck("input_scripts/in.column_load")
TINY = {"R": 2, "nlayers": 3, "Np": 15, "t_layer": 1.5, "t_wire": 0.5, "t_relax": 8, "t_end": 10, "v_wall": 1,
        "ke_walls": 0, "ke_relax": 0, "root": SOURCE}
# every step one line of the series (t_out = dt_SP), the drop stop out of reach
# (contacts and grain stresses every 10 steps)
EVERY_STEP = {"R": 2, "v_plate": 0.2, "load_min": 1e9, "load_max": 1e12, "t_out": 1e-3,
              "t_net": 0.01}
STRAIN_MAX = {1: 0.05, 0: 0.15}
DT_NSCD = 2e-3
COLUMNS = ["step", "t", "d", "strain", "F_grains", "F_wire", "F", "F_W", "floor_W", "H", "U_s", "lost", "v_cm"]


def series(result):
    data = np.loadtxt(result.path("post/load.txt"), comments="#", ndmin=2)
    return {name: data[:, k] for k, name in enumerate(COLUMNS)}


def final_line(result):
    found = re.search(r"^in\.column_load: stopped by (\S+) at strain (\S+) .*peak F/W (\S+) at strain (\S+); "
                      r"W = (\S+), z_top0 = (\S+)$", result.output, re.M)
    if found is None:
        raise AssertionError("no final line:\n" + result.output[-3000:])
    return found


class Load(DeckTestCase):
    @classmethod
    def setUpClass(cls):
        cls.columns = {}
        for wire in (1, 0):
            built = run(COLUMN, variables=dict(TINY, wire=wire))
            cls.columns[wire] = built
        # the column without wire to strain 0.15: the plate reaches its grains after 0.1
        cls.loaded = {wire: run(LOAD, variables=dict(EVERY_STEP, strain_max=STRAIN_MAX[wire]),
                                workdir=cls.columns[wire].workdir) for wire in (1, 0)}

    def test_columns_were_built_and_loaded(self):
        for wire in (1, 0):
            self.assertRanCleanly(self.columns[wire])
            self.assertRanCleanly(self.loaded[wire])

    # Without wire every force on the grains and the plate comes from the NSCD solve, which
    # runs on even steps (dt_NSCD = 2 dt_SP) and whose forces the series prints on the step
    # of the solve and the next: over each NSCD step the centre of mass's velocity changes by
    # (F_floor − W − F) h / M, M = W / g (g = 1). The series has 6 digits (%g). With the wire
    # the same sum is off by the velocity-Verlet half kick still pending at the sample,
    # (dt_SP / 2) × the wire's force on the grains (measured on the tiny column: the running
    # difference follows 4.99e-4 × F_wire→grains, dt_SP / 2 = 5e-4, to 7e-5), so the exact
    # per-step check is made on the column without wire.
    def test_momentum_balance_of_each_step(self):
        s = series(self.loaded[0])
        even = np.nonzero(s["step"].astype(int) % 2 == 0)[0]
        change = np.diff(s["v_cm"][even])
        impulse = (s["floor_W"] - 1 - s["F_W"])[even[1:]] * DT_NSCD
        error = np.abs(change - impulse)
        plate = s["F_W"].sum() * 1e-3
        print(f"{len(change)} NSCD steps, |dv_cm| up to {np.abs(change).max():.2e}, the plate's impulse "
              f"{plate:.3f} W, balance off by up to {error.max():.1e}")
        self.assertGreater(np.abs(change).max(), 1e-2)  # the column moves
        self.assertGreater(plate, 0.1)  # and the plate pushes it
        self.assertLess(error.max(), 3e-6)  # measured 1.2e-6

    def test_series_columns_agree(self):
        for wire in (1, 0):
            s, line = series(self.loaded[wire]), final_line(self.loaded[wire])
            W, z_top0 = float(line.group(5)), float(line.group(6))
            np.testing.assert_allclose(s["t"], s["step"] * 1e-3, rtol=1e-5, atol=1e-12)
            np.testing.assert_allclose(s["d"], EVERY_STEP["v_plate"] * s["t"], rtol=1e-5, atol=1e-12)
            # the plate starts gap a_max = 0.02 above the top
            np.testing.assert_allclose(s["strain"], (s["d"] - 0.02) / z_top0, rtol=1e-4, atol=1e-6)
            np.testing.assert_allclose(s["F"], s["F_grains"] + s["F_wire"], rtol=1e-5, atol=1e-5)
            np.testing.assert_allclose(s["F_W"], s["F"] / W, rtol=1e-5, atol=1e-9)

    def test_stops_in_the_chunk_that_passes_strain_max(self):
        for wire in (1, 0):
            s, line = series(self.loaded[wire]), final_line(self.loaded[wire])
            self.assertEqual(line.group(1), "strain_max")
            self.assertGreaterEqual(s["strain"][-1], STRAIN_MAX[wire])
            self.assertLess(s["strain"][-2], STRAIN_MAX[wire])
            # the end's snapshot is written whether or not a t_net dump falls on it
            end = int(s["step"][-1])
            names = ["contacts", "grains"] + (["wire"] if wire else [])
            print(f"wire {wire}: ends at step {end} (t_net every 10 steps)")
            for name in names:
                self.assertTrue(os.path.exists(self.loaded[wire].path(f"post/load_{name}_{end}.dump")), name)

    # The plate force of the grains is the sum over the contact rows of wall 2 (the plate),
    # a = −2, the force listed being the one the grain receives.
    def test_plate_force_is_the_sum_of_its_contact_rows(self):
        r = self.loaded[1]
        s = series(r)
        steps = s["step"].astype(int)
        # the dumped step (every 10) where the grains press hardest on the plate
        dumped = steps % 10 == 0
        k = np.nonzero(dumped)[0][np.argmax(s["F_grains"][dumped])]
        path = r.path(f"post/load_contacts_{steps[k]}.dump")
        local = read_local_dump(path)
        rows = np.column_stack([local[f"c_contacts[{k}]"] for k in range(1, 17)])
        plate = (rows[:, 0] == 4) & (rows[:, 1] == -2)
        pushed = -rows[plate, 12].sum()
        print(f"step {steps[k]}: {int(plate.sum())} plate rows, their force {pushed:.6g}, "
              f"the series' F_grains {s['F_grains'][k]:.6g}")
        self.assertGreater(pushed, 0.1 * float(final_line(r).group(5)))  # a tenth of the weight at least
        np.testing.assert_allclose(pushed, s["F_grains"][k], rtol=1e-5)
        self.assertTrue(os.path.exists(r.path(f"post/load_grains_{steps[k]}.dump")))

    def test_load_curve_reads_the_series(self):
        folder = self.loaded[1].workdir
        out = subprocess.run([sys.executable, os.path.join(SOURCE, "postprocess", "load_curve.py"), folder,
                              "--plot", os.path.join(folder, "load.png")],
                             capture_output=True, text=True, check=True).stdout
        self.assertIn(os.path.basename(folder), out)
        self.assertGreater(os.path.getsize(os.path.join(folder, "load.png")), 1000)

    # ke_settle: the column without wire held under the still plate until its grains rest,
    # then the plate brought to gap above the settled top: the load starts from rest
    def test_settles_before_loading(self):
        folder = tempfile.mkdtemp(prefix="wiregrain-")
        shutil.copy(self.columns[0].path("column.restart"), folder)
        r = run(LOAD, variables={"R": 2, "root": SOURCE, "v_plate": 0.2, "strain_max": 0.02, "t_out": 0.01, "ke_settle": 1e-8,
                                 "t_settle": 20, "t_quiet": 1, "t_check": 0.5},
                workdir=folder)
        self.assertRanCleanly(r)
        settled = re.search(r"^in\.column_load: settled for (\S+) \(ended early: (\d)\), KE per grain (\S+) m g a_max",
                            r.output, re.M)
        placed = re.search(r"^in\.column_load: the plate at (\S+), the settled top at (\S+)$", r.output, re.M)
        self.assertIsNotNone(settled, r.output[-3000:])
        self.assertLess(float(settled.group(3)), 1e-8)
        z0, top = float(placed.group(1)), float(placed.group(2))
        print(f"settled for {settled.group(1)}; the plate {z0 - top:.6f} above the settled top")
        # gap 0.02 a_max, the approach's last step at most v_approach dt = 1e-3 short of it
        self.assertGreaterEqual(z0 - top, 0.02 - 1e-12)
        self.assertLess(z0 - top, 0.02 + 1e-3)
        s = series(r)
        self.assertLess(abs(s["v_cm"][0]), 1e-3)  # at rest when the plate starts
        self.assertEqual(final_line(r).group(6), placed.group(2))  # the strain counts from the settled top

    # The plate as a body (plate load, plate spring) on the column with wire, every step in
    # the series. load (gap 0: the plate starts on the column's highest point): the drive column is F/W = load_rate t at the NSCD steps (even steps;
    # the odd ones repeat the last solve's), to the series' 6 digits. spring: the spring's
    # force k_plate (drive travel − plate travel) W stays below k_plate × the drive's travel
    # v_plate (t + dt_NSCD) (the setup solve moved the drive one NSCD step ahead).
    def test_plate_modes(self):
        for plate, extra in (("load", {"load_rate": 20, "load_min": 0.1, "load_max": 3, "drop": 0.99, "strain_max": 0.5,
                                       "gap": 0}),
                             ("spring", {"strain_max": 0.03})):
            folder = tempfile.mkdtemp(prefix="wiregrain-")
            shutil.copy(self.columns[1].path("column.restart"), folder)
            variables = dict(EVERY_STEP, root=SOURCE, plate=plate, t_net=0, **extra)
            r = run(LOAD, variables=variables, workdir=folder)
            self.assertRanCleanly(r)
            s = series(r)
            data = np.loadtxt(r.path("post/load.txt"), comments="#", ndmin=2)
            v_p, drive = data[:, 13], data[:, 14]
            even = s["step"].astype(int) % 2 == 0
            stopped = final_line(r).group(1)
            print(f"plate {plate}: stopped by {stopped} at t = {s['t'][-1]:.3f}, d = {s['d'][-1]:.4f}, "
                  f"F/W up to {s['F_W'].max():.3f}, drive up to {drive.max():.3f} W, plate speed {v_p[-1]:.4f}")
            if plate == "load":
                np.testing.assert_allclose(drive[even], 20 * s["t"][even], rtol=1e-5, atol=1e-9)
                self.assertEqual(stopped, "load_max")
            else:
                self.assertTrue(np.all(drive <= 100 * EVERY_STEP["v_plate"] * (s["t"] + DT_NSCD) * (1 + 1e-5)))
                self.assertEqual(stopped, "strain_max")

    def test_bad_variables_stop_with_a_message(self):
        workdir = self.columns[1].workdir
        z_top0 = final_line(self.loaded[1]).group(6)
        for variables, message in (
                ({"v_plate": -1}, "in.column_load: v_plate must be > 0 (the plate moves down), got -1"),
                ({"strain_max": 1}, "in.column_load: strain_max must be in (0, 1), got 1"),
                ({"drop": 0}, "in.column_load: drop must be in (0, 1), got 0"),
                ({"load_max": 0.05}, "in.column_load: load_max (0.05) must be > load_min (0.1)"),
                ({"t_out": "1e-4"}, "in.column_load: t_out (1e-4) must be at least dt_SP (1e-3)"),
                ({"ke_settle": -1}, "in.column_load: ke_settle must be >= 0 (0: no settling), got -1"),
                ({"ke_settle": 1e-6, "t_quiet": 0.1},
                 "in.column_load: with ke_settle, t_check must be > 0 and t_check <= t_quiet <= t_settle, "
                 "got 0.5, 0.1 and 50"),
                ({"v_approach": 0}, "in.column_load: v_approach must be > 0, got 0"),
                ({"plate": "push"}, "in.column_load: plate must be prescribed, load or spring, got push"),
                ({"m_plate": 0}, "in.column_load: m_plate must be > 0, got 0"),
                ({"load_rate": -1}, "in.column_load: load_rate must be > 0, got -1"),
                ({"k_plate": 0}, "in.column_load: k_plate must be > 0, got 0"),
                ({"z_plate": 1}, f"in.column_load: z_plate (1) is below the top of the column ({z_top0}): "
                                 "the plate must start above it")):
            self.assertStopsWith(run(LOAD, variables=dict(R=2, **variables), workdir=workdir), message)

    def test_a_restart_without_grains_stops_with_a_message(self):
        made = run(deck_box("hybrid polyhedron wire", 3, (-1, 5), 2) + """create_wire     2 line 0 0 1 1 0 1
write_restart   wire_only.restart
""")
        self.assertRanCleanly(made)
        self.assertStopsWith(run(LOAD, variables={"restart": "wire_only.restart"}, workdir=made.workdir),
                             "in.column_load: wire_only.restart holds no grains (type 1): not a column of in.column")


# postprocess/load_curve.py on a series of known shape: F/W = 0 up to strain 0.01, then
# 5 (strain − 0.01) up to the peak 0.5 at strain 0.11, then falling
class LoadCurve(DeckTestCase):
    def test_observables_of_a_known_curve(self):
        folder = tempfile.mkdtemp(prefix="wiregrain-")
        os.makedirs(os.path.join(folder, "post"))
        strain = np.round(np.arange(-0.02, 0.2001, 0.005), 10)
        load = np.where(strain <= 0.01, 0.0, 5 * (strain - 0.01))
        load = np.where(strain > 0.11, 0.5 - 3 * (strain - 0.11), load)
        with open(os.path.join(folder, "post", "load.txt"), "w") as f:
            f.write("# Time-averaged data for fix series\n# TimeStep v_t ...\n")
            for k, (e, l) in enumerate(zip(strain, load)):
                # step t d strain F_grains F_wire F F/W floor/W H U_s lost v_cm
                f.write(f"{k} {k} {k} {e!r} 0 0 0 {l!r} {1 + l!r} 1 0 {k % 3} 0\n")
        out = subprocess.run([sys.executable, os.path.join(SOURCE, "postprocess", "load_curve.py"), folder, "--json",
                              "--onset", "0.01"], capture_output=True, text=True, check=True).stdout
        obs = json.loads(out.splitlines()[-1])
        self.assertAlmostEqual(obs["onset"], 0.015, delta=1e-12)  # the first point above F/W 0.01
        self.assertAlmostEqual(obs["stiffness"], 5.0, delta=1e-9)
        self.assertAlmostEqual(obs["peak"], 0.5, delta=1e-12)
        self.assertAlmostEqual(obs["strain_at_peak"], 0.11, delta=1e-12)
        self.assertAlmostEqual(obs["end_strain"], strain[-1], delta=1e-12)
        self.assertEqual(obs["end_lost"], (len(strain) - 1) % 3)


if __name__ == "__main__":
    main()
