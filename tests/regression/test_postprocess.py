"""postprocess/: the sweep driver runs values × seeds, skips finished runs when called
again, reports a failed run and tries it again; the plot scripts read its output and
write PNGs. On the tiny column without wire (a second per run)."""

import csv
import glob
import json
import math
import os
import re
import shutil
import struct
import subprocess
import tempfile

import numpy as np

from liggghts_run import LIGGGHTS, SOURCE, DeckTestCase, deck, main, run

SOURCE = os.environ["WIREGRAIN_SOURCE"]
POST = os.path.join(SOURCE, "postprocess")
TINY = ["--var", "R", "3", "--var", "nlayers", "1", "--var", "Np", "13", "--var", "t_layer", "0.5",
        "--var", "t_relax", "1", "--var", "t_end", "1.5", "--var", "t_obs", "0.1"]


def script(name, *args, cwd):
    proc = subprocess.run(["/usr/bin/python3", os.path.join(POST, name), *args], cwd=cwd,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=600)
    return proc.returncode, proc.stdout.decode(errors="replace")


class Sweep(DeckTestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.mkdtemp(prefix="wiregrain-sweep-")
        cls.out = os.path.join(cls.work, "v_wall")
        cls.sweep = ["v_wall", "0.2", "0.4", "--seeds", "11", "22", "--out", cls.out, "--jobs", "2",
                     "--liggghts", LIGGGHTS, "--var", "wire", "0"] + TINY
        cls.first = script("sweep.py", *cls.sweep, cwd=cls.work)

    def rows(self):
        with open(os.path.join(self.out, "summary.csv"), newline="") as f:
            return list(csv.DictReader(f))

    def test_runs_every_value_and_seed(self):
        status, text = self.first
        self.assertEqual(status, 0, text[-2000:])
        rows = self.rows()
        self.assertEqual([(r["value"], r["seed"]) for r in rows],
                         [("0.2", "11"), ("0.2", "22"), ("0.4", "11"), ("0.4", "22")])
        for r in rows:
            where = os.path.join(self.out, f"v_wall={r['value']}", f"seed={r['seed']}")
            with open(os.path.join(where, "log.liggghts")) as f:
                final = [l for l in f if l.startswith("in.column final:")][-1]
            # the row holds the deck's own final line
            self.assertEqual(float(r["H_n"]), float(final.split("H_n = ")[1].split()[0]))
            self.assertEqual(float(r["H_c_n"]), float(final.split("H_c_n = ")[1].split()[0]))
            self.assertEqual(float(r["U_s/L"]), 0.0)
        # the seeds differ: the columns differ
        self.assertNotEqual(rows[0]["H0"], rows[1]["H0"])

    def test_finished_runs_are_not_repeated(self):
        logs = [os.path.join(self.out, "v_wall=0.2", f"seed={s}", "log.liggghts") for s in (11, 22)]
        before = [os.stat(p).st_mtime_ns for p in logs]
        status, text = script("sweep.py", *self.sweep, cwd=self.work)
        self.assertEqual(status, 0, text[-2000:])
        self.assertEqual([os.stat(p).st_mtime_ns for p in logs], before)
        self.assertEqual(len(self.rows()), 4)

    def test_a_failed_run_is_reported_and_tried_again(self):
        out = os.path.join(self.work, "bad")
        args = ["v_wall", "-1", "--seeds", "5", "--out", out, "--liggghts", LIGGGHTS, "--var", "wire", "0"] + TINY
        for _ in range(2):
            status, text = script("sweep.py", *args, cwd=self.work)
            self.assertEqual(status, 1)
            self.assertIn("in.column: v_wall must be > 0, got -1", text)
            self.assertFalse(os.path.exists(os.path.join(out, "v_wall=-1", "seed=5", "final.json")))

    def test_an_interrupted_run_continues_from_its_latest_restart(self):
        # a run of two layers with layer restarts, then its folder as an interruption after
        # the first layer would leave it (no final.json, no error.txt; the restart files of
        # layer 1 and column_layer.txt naming it): the second call continues it with
        # resume 4 and ends with the straight run's H_n, φ_p and H_c_n (in.column's resume 4
        # repeats the straight run: tests/regression/test_column.py), its first log kept
        variables = ["--var", "layer_restart", "1", "--var", "R", "3", "--var", "nlayers", "2", "--var", "Np", "24",
                     "--var", "t_layer", "0.5", "--var", "t_relax", "2.5", "--var", "t_end", "3", "--var", "t_obs", "0.1"]
        straight = os.path.join(self.work, "straight")
        args = ["v_wall", "0.2", "--seeds", "11", "--liggghts", LIGGGHTS] + variables
        status, text = script("sweep.py", *args, "--out", straight, cwd=self.work)
        self.assertEqual(status, 0, text[-2000:])
        done = os.path.join(straight, "v_wall=0.2", "seed=11")
        cut = os.path.join(self.work, "cut")
        where = os.path.join(cut, "v_wall=0.2", "seed=11")
        shutil.copytree(done, where)
        for name in os.listdir(where):
            if name.startswith(("column_walls", "column_relaxed", "column_deposited", "column_layer_2", "final")) or \
                    name.startswith("column.") or name == "column_layer.txt":
                os.remove(os.path.join(where, name))
        with open(os.path.join(where, "column_layer.txt"), "w") as f:
            f.write("1\n")
        # a LIGGGHTS killed before it prints anything (a signal, out of memory): no ERROR
        # line, so the run is interrupted, not failed, and keeps its restart files
        killed = os.path.join(self.work, "killed_liggghts")
        with open(killed, "w") as f:
            f.write("#!/bin/sh\nkill -9 $$\n")
        os.chmod(killed, 0o755)
        status, text = script("sweep.py", *[killed if a == LIGGGHTS else a for a in args], "--out", cut,
                              cwd=self.work)
        self.assertEqual(status, 1)
        self.assertIn(f"FAILED v_wall=0.2 seed=11: {where}: exit -9, no ERROR line and no final line: interrupted; "
                      "the next call continues it from its latest restart", text)
        self.assertFalse(os.path.exists(os.path.join(where, "error.txt")))
        status, text = script("sweep.py", *args, "--out", cut, cwd=self.work)
        self.assertEqual(status, 0, text[-2000:])
        self.assertIn("v_wall=0.2 seed=11: continues with resume 4", text)
        self.assertTrue(os.path.exists(os.path.join(where, "log.liggghts.1")))
        with open(os.path.join(where, "log.liggghts")) as f:
            log = f.read()
        self.assertNotIn("in.column layer 1:", log)
        self.assertIn("in.column layer 2: grains", log)
        with open(os.path.join(done, "final.json")) as f:
            a = json.load(f)
        with open(os.path.join(where, "final.json")) as f:
            b = json.load(f)
        for name in ("H_n", "phi_p", "H_c_n"):
            self.assertAlmostEqual(b[name], a[name], delta=1e-12 * abs(a[name]), msg=name)

    def test_plots(self):
        status, text = script("plot_sweep.py", os.path.join(self.out, "summary.csv"), "-o", "sweep.png", "--table",
                              cwd=self.work)
        self.assertEqual(status, 0, text[-2000:])
        # mean ± standard deviation over the two seeds, from the rows
        for value in ("0.2", "0.4"):
            h = np.array([float(r["H_n"]) for r in self.rows() if r["value"] == value])
            self.assertIn(f"v_wall = {float(value):g}\tH_n = {h.mean():.4g} ± {h.std(ddof=1):.2g} (2 seeds)", text)
        run_dir = os.path.join(self.out, "v_wall=0.2", "seed=11")
        for name, args in (("plot_column.py", [run_dir]), ("plot_columns.py", [run_dir, os.path.join(self.out, "v_wall=0.4", "seed=11")])):
            status, text = script(name, *args, "-o", name + ".png", cwd=self.work)
            self.assertEqual(status, 0, text[-2000:])
        for png in ("sweep.png", "plot_column.py.png", "plot_columns.py.png"):
            with open(os.path.join(self.work, png), "rb") as f:
                self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n", png)

    def test_paired_differences(self):
        # hand-made tables: the differences from the baseline of the same seed are
        # (0.125, 0.25, 0) at value 0.6 (mean 0.125, std 0.125, standard error 0.125/√3)
        # and (−0.125, +0.125) at 0.1, whose seed 4 has no baseline run (mean 0, standard
        # error 0.125)
        work = tempfile.mkdtemp(prefix="wiregrain-paired-")
        header = "param,value,seed,H_n,phi_p,U_s/L,z_wpc,H0,H,wall_s\n"
        with open(os.path.join(work, "base.csv"), "w") as f:
            f.write(header + "".join(f"wire,0,{s},{h},0.5,0,0,8,{8 * h},1\n" for s, h in ((1, 0.5), (2, 0.25), (3, 0.75))))
        with open(os.path.join(work, "wire.csv"), "w") as f:
            f.write(header + "".join(f"mu_w,{v},{s},{h},0.5,0.01,0.5,8,{8 * h},1\n" for v, s, h in
                                     ((0.6, 1, 0.625), (0.6, 2, 0.5), (0.6, 3, 0.75), (0.1, 1, 0.375), (0.1, 2, 0.375), (0.1, 4, 0.9))))
        status, text = script("plot_sweep.py", "wire.csv", "-o", "p.png", "--baseline", "base.csv",
                              "--baseline-label", "none", "--legend", "wire", "--paired", cwd=work)
        self.assertEqual(status, 0, text)
        self.assertIn(f"wire − none\t0.6\tH_n: +0.125 ± {0.125 / 3 ** 0.5:.2g} (3 seeds; +{3 ** 0.5:.2f} standard errors)", text)
        self.assertIn("wire − none\t0.1\tH_n: +0 ± 0.12 (2 seeds; +0.00 standard errors)", text)
        # the final height H = 8 H_n here: its differences are 8 times those of H_n
        self.assertIn(f"wire − none\t0.6\tH: +1 ± {1 / 3 ** 0.5:.2g} (3 seeds; +{3 ** 0.5:.2f} standard errors)", text)
        status, text = script("plot_sweep.py", "wire.csv", "-o", "p.png", "--paired", cwd=work)
        self.assertEqual(status, 2)
        self.assertIn("--paired needs --baseline", text)

    def test_work_precision(self):
        # a coarser setting against the baseline, seeds 1–3: H_n differences (0.1, 0.2,
        # 0.3): mean 0.2, standard error 0.1/√3, shift 2√3 = 3.46 standard errors; φ_p
        # differences (−0.02, 0, −0.04): −0.02 ± 0.02/√3, −1.73; U_s/L the same (no
        # standard error: n/a); z_wpc (0.002, 0.001, 0): +1.73; wall time 100 s per baseline
        # run against 25 s: speed-up 4
        work = tempfile.mkdtemp(prefix="wiregrain-wp-")
        header = "param,value,seed,H_n,phi_p,U_s/L,z_wpc,H0,H,wall_s\n"
        base = ((1, 0.5, 0.3), (2, 0.6, 0.32), (3, 0.7, 0.34))
        with open(os.path.join(work, "base.csv"), "w") as f:
            f.write(header + "".join(f"dt,1e-3,{s},{h},{p},0.01,0.5,8,{8 * h},100\n" for s, h, p in base))
        with open(os.path.join(work, "coarse.csv"), "w") as f:
            f.write(header + "".join(f"dt,5e-3,{s},{h + dh},{p + dp},0.01,{0.5 + dz},8,{8 * (h + dh)},25\n"
                                     for (s, h, p), dh, dp, dz in zip(base, (0.1, 0.2, 0.3), (-0.02, 0, -0.04),
                                                                      (0.002, 0.001, 0))))
        status, text = script("plot_sweep.py", "coarse.csv", "-o", "p.png", "--baseline", "base.csv",
                              "--baseline-label", "fine", "--legend", "coarse", "--paired", "--work-precision", "wp.png",
                              cwd=work)
        self.assertEqual(status, 0, text)
        self.assertIn("work–precision: baseline fine, 100 s per run", text)
        self.assertIn(f"coarse\t0.005\t25\t4.00\t+{2 * 3 ** 0.5:.2f}\t-{3 ** 0.5:.2f}\tn/a\t+{3 ** 0.5:.2f}", text)
        with open(os.path.join(work, "wp.png"), "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
        status, text = script("plot_sweep.py", "coarse.csv", "-o", "p.png", "--work-precision", "wp.png", cwd=work)
        self.assertEqual(status, 2)
        self.assertIn("--work-precision needs --paired", text)

    def test_sphere_column(self):
        # a column of stock spheres (-var grains spheres, with rolling friction):
        # plot_columns.py draws its legacy VTK, observables.py reads its dumps without a
        # shape library
        out = os.path.join(self.work, "spheres")
        status, text = script("sweep.py", "grains", "spheres", "--seeds", "11", "--out", out, "--liggghts", LIGGGHTS,
                              "--var", "wire", "0", "--var", "mu_roll", "0.1", *TINY, cwd=self.work)
        self.assertEqual(status, 0, text[-2000:])
        run_dir = os.path.join(out, "grains=spheres", "seed=11")
        status, text = script("plot_columns.py", run_dir, "-o", "spheres.png", cwd=self.work)
        self.assertEqual(status, 0, text[-2000:])
        with open(os.path.join(self.work, "spheres.png"), "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
        dumps = [sorted(glob.glob(os.path.join(run_dir, "post", f"column_{w}_*.dump")))[-1]
                 for w in ("relaxed", "final")]
        status, text = script("observables.py", *dumps, "--radius", "3", "--json", cwd=self.work)
        self.assertEqual(status, 0, text[-2000:])
        with open(os.path.join(run_dir, "final.json")) as f:
            final = json.load(f)
        obs = json.loads(text.splitlines()[-1])
        self.assertAlmostEqual(obs["H_n"], final["H_n"], delta=1e-14)
        self.assertEqual(obs["phi_p"], final["phi_p"])


def write_tops_dump(path, snapshots):
    """A dump custom file of `id x y z c_gs[7]` (in.column's post/tops.dump columns):
    snapshots = [(step, x, y, z, top)]."""
    with open(path, "w") as f:
        for step, x, y, z, top in snapshots:
            f.write(f"ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF ATOMS\n{len(x)}\n"
                    "ITEM: BOX BOUNDS ff ff ff\n-20 20\n-20 20\n0 20\nITEM: ATOMS id x y z c_gs[7]\n")
            for i in range(len(x)):
                f.write(f"{i + 1} {x[i]:.9g} {y[i]:.9g} {z[i]:.9g} {top[i]:.9g}\n")


class ColumnReadings(DeckTestCase):
    """postprocess/column_readings.py on written dumps: a block of grains covering the half
    x <= -0.6 of a disk of R = 6 (the grains on a lattice of spacing 0.25, tops h = 3). With
    cells of 0.5 the grid nodes at x <= -0.5 see a grain within a cell and those at x >= 0
    none, so the surface reading is h times the disk's share left of x = -0.25 (the circular
    segment's area R^2 acos(d/R) - d sqrt(R^2 - d^2) over pi R^2, d = 0.25), within the grid's
    resolution; the rim (nodes within a cell of r = R) is h times the share of that ring left
    of x = -0.25, about (pi - 2 asin(d / R)) / 2 pi; q98 is h; the centre reading, twice the
    mean centre height, is h for centres at h/2. Each reading is normalised by the relaxed
    column's (tops 2h, centres at h): all 0.5."""

    def test_half_disk(self):
        h, R, d = 3.0, 6.0, 0.25
        gx, gy = np.meshgrid(-0.6 - 0.25 * np.arange(30), -7.0 + 0.25 * np.arange(57), indexing="ij")
        x, y = gx.ravel(), gy.ravel()
        with tempfile.TemporaryDirectory() as work:
            os.makedirs(os.path.join(work, "half", "post"))
            write_tops_dump(os.path.join(work, "half", "post", "column_relaxed_1000.dump"),
                            [(1000, x, y, np.full_like(x, h), np.full_like(x, 2 * h))])
            write_tops_dump(os.path.join(work, "half", "post", "tops.dump"),
                            [(1000, x, y, np.full_like(x, 9.0), np.full_like(x, 9.0)),
                             (3000, x, y, np.full_like(x, h / 2), np.full_like(x, h))])
            status, text = script("column_readings.py", "half", "--radius", str(R), "--cell", "0.5", "--dt", "1e-3",
                                  "--csv", "readings.csv", "--plot", "readings.png", cwd=work)
            self.assertEqual(status, 0, text)
            print(text)
            with open(os.path.join(work, "readings.csv")) as f:
                rows = list(csv.DictReader(f))
            self.assertTrue(os.path.getsize(os.path.join(work, "readings.png")) > 0)
            # the CSV read back: the same rows, drawn again without the dumps
            again, text_again = script("column_readings.py", "readings.csv", "--plot", "again.png", cwd=work)
            self.assertEqual(again, 0, text_again)
            self.assertEqual(text_again.splitlines(), text.splitlines())
            self.assertTrue(os.path.getsize(os.path.join(work, "again.png")) > 0)
        # the relaxed column, then the snapshot after it (the one at the relaxed step is not a new one)
        self.assertEqual([float(r["t_since_walls"]) for r in rows], [0.0, 2.0])
        later = {k: float(v) for k, v in rows[1].items() if k != "run"}
        segment = (R * R * math.acos(d / R) - d * math.sqrt(R * R - d * d)) / (math.pi * R * R)
        self.assertAlmostEqual(later["H_q98"], h, delta=1e-12)
        self.assertAlmostEqual(later["H_centre"], h, delta=1e-12)
        self.assertAlmostEqual(later["H_surface"], h * segment, delta=0.01 * h)
        self.assertAlmostEqual(later["H_rim"], h * (math.pi - 2 * math.asin(d / R)) / (2 * math.pi), delta=0.01 * h)
        for k in ("q98", "surface", "rim", "centre"):
            self.assertAlmostEqual(later[f"Hn_{k}"], 0.5, delta=1e-7, msg=k)
            self.assertAlmostEqual(float(rows[0][f"Hn_{k}"]), 1.0, delta=1e-12, msg=k)

    def test_without_the_tops_dump(self):
        with tempfile.TemporaryDirectory() as work:
            os.makedirs(os.path.join(work, "run", "post"))
            status, text = script("column_readings.py", "run", "--radius", "6", cwd=work)
        self.assertNotEqual(status, 0)
        self.assertIn("column_readings.py: run: needs post/column_relaxed_STEP.dump and post/tops.dump "
                      "(in.column -var t_tops T)", text)


def write_column_dump(path, step, atoms):
    """A dump custom file of `id type x y z` (in.column's post/column_*.dump columns):
    atoms = [(id, type, x, y, z)]."""
    with open(path, "w") as f:
        f.write(f"ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF ATOMS\n{len(atoms)}\n"
                "ITEM: BOX BOUNDS ff ff ff\n-20 20\n-20 20\n0 20\nITEM: ATOMS id type x y z\n")
        for atom in atoms:
            f.write("%d %d %.12g %.12g %.12g\n" % atom)


class WireHold(DeckTestCase):
    """postprocess/wire_hold.py on written dumps: two wire chains (consecutive IDs) of 60 beads
    each on circles about the axis, at z = 1 and 2, radius 5 in the relaxed column and 5.5 in
    the final one, with l_w 1/1.1 of the relaxed chord 2 r sin(pi/60): stretch 0.1 relaxed and
    0.1 + 1.1 x 0.1 = 0.21 final on every segment (the pair across the two chains' ends, about
    1.13 apart, beyond 2 l_w, is no segment); four grains at r = 2 (inside) whose centres sink from 1 to 0.9 and
    four at r = 7 (outside) from 1 to 0.5: H_c ratios 0.9, 0.5 and 0.7, 4 of 8 outside. The
    same grains without the wire need --radius."""

    def test_two_rings(self):
        chord = 2 * 5.0 * math.sin(math.pi / 60)
        segment = chord / 1.1

        def atoms(radius, inside_z, outside_z, wire=True):
            out = []
            for k in range(4):
                a = 0.5 * math.pi * k
                out.append((1 + k, 1, 2 * math.cos(a), 2 * math.sin(a), inside_z))
                out.append((5 + k, 1, 7 * math.cos(a + 0.3), 7 * math.sin(a + 0.3), outside_z))
            if wire:
                for chain, z in enumerate((1.0, 2.0)):
                    for j in range(60):
                        a = 2 * math.pi * j / 60
                        out.append((9 + 60 * chain + j, 2, radius * math.cos(a), radius * math.sin(a), z))
            return out

        with tempfile.TemporaryDirectory() as work:
            for name, wire in (("wire", True), ("bare", False)):
                os.makedirs(os.path.join(work, name, "post"))
                write_column_dump(os.path.join(work, name, "post", "column_relaxed_100.dump"), 100,
                                  atoms(5.0, 1.0, 1.0, wire))
                write_column_dump(os.path.join(work, name, "post", "column_final_900.dump"), 900,
                                  atoms(5.5, 0.9, 0.5, wire))
            status, text = script("wire_hold.py", "wire", "--segment", repr(segment), "--csv", "hold.csv", cwd=work)
            self.assertEqual(status, 0, text)
            print(text)
            with open(os.path.join(work, "hold.csv")) as f:
                row = {k: v for k, v in next(csv.DictReader(f)).items()}
            refused, message = script("wire_hold.py", "bare", cwd=work)
            bare, bare_text = script("wire_hold.py", "bare", "--radius", "5", "--csv", "bare.csv", cwd=work)
            self.assertEqual(bare, 0, bare_text)
            with open(os.path.join(work, "bare.csv")) as f:
                bare_row = next(csv.DictReader(f))
        expected = {"loops_radius_relaxed": 5.0, "loops_radius_final": 5.5, "stretch_mean_relaxed": 0.1,
                    "stretch_mean_final": 0.21, "stretch_q99_relaxed": 0.1, "stretch_q99_final": 0.21,
                    "grains": 8, "grains_outside": 4, "Hc_n_inside": 0.9, "Hc_n_outside": 0.5, "Hc_n": 0.7}
        for key, value in expected.items():
            self.assertAlmostEqual(float(row[key]), value, delta=1e-9, msg=key)
        self.assertNotEqual(refused, 0)
        self.assertIn("wire_hold.py: bare: the relaxed column has no wire: give --radius", message)
        for key in ("grains", "grains_outside", "Hc_n_inside", "Hc_n_outside", "Hc_n"):
            self.assertAlmostEqual(float(bare_row[key]), expected[key], delta=1e-9, msg=key)
        self.assertEqual(bare_row["loops_radius_relaxed"], "nan")


class EarlyEnd(DeckTestCase):
    """postprocess/early_end.py reads a run made with ke_stop far below any kinetic energy
    and says when each phase would have ended with a given ke_stop; the deck run with that
    ke_stop is the independent answer (its own loop of chunks): the same end times and,
    for the wall phase continued from the same relaxed column, the same observables."""
    TINY_COLUMN = {"R": 3, "nlayers": 2, "Np": 24, "t_layer": 0.5, "t_relax": 2.5, "t_end": 3.5, "t_obs": 0.1,
                   "t_check": 0.1, "t_quiet": 0.2, "free_dist": 0.01, "root": SOURCE}

    def test_predicts_the_decks_early_end(self):
        column = deck("input_scripts/in.column")
        straight = run(column, variables=dict(self.TINY_COLUMN, ke_stop=1e-30))
        self.assertRanCleanly(straight)
        phases = {}
        for ke_of in ("grains", "all"):
            status, text = script("early_end.py", straight.path("log.liggghts"), "--ke-stop", "1e9", "0.45", "1e-30",
                                  "--ke-of", ke_of, "--t-quiet", "0.2", "--free-dist", "0.01", "--json",
                                  cwd=straight.workdir)
            self.assertEqual(status, 0, text[-2000:])
            print(text)
            phases[ke_of] = json.loads(text.splitlines()[-1])["phases"]
        # 1e-30 never ends a phase; 1e9 ends the relaxation after t_quiet (t_dep + 0.2 = 2.2)
        # and the wall phase after max(t_quiet, free_dist / v_wall) = 0.5 (2.5 + 0.5)
        relax, walls = phases["grains"]["relax"]["candidates"], phases["grains"]["walls"]["candidates"]
        self.assertEqual([c["stops"] for c in relax][::2], [True, False])
        self.assertAlmostEqual(relax[0]["t"], 2.2, delta=1e-12)
        self.assertAlmostEqual(walls[0]["t"], 3.0, delta=1e-12)
        # the grains' kinetic energy is part of everything's
        for phase in ("relax", "walls"):
            for (t, grains), (_, everything) in zip(phases["grains"][phase]["ke_rel"], phases["all"][phase]["ke_rel"]):
                self.assertLessEqual(grains, everything, f"{phase} t = {t}")
        for ke_of, k, ke_stop in (("grains", 0, 1e9), ("grains", 1, 0.45), ("all", 1, 0.45)):
            relax, walls = phases[ke_of]["relax"]["candidates"], phases[ke_of]["walls"]["candidates"]
            early = run(column, variables=dict(self.TINY_COLUMN, ke_stop=ke_stop, ke_of=ke_of))
            self.assertRanCleanly(early)
            t = float(re.search(r"^in\.column relaxed at t = (\S+) ", early.output, re.M).group(1))
            self.assertAlmostEqual(t, relax[k]["t"], delta=1e-12)
            resumed = run(column, variables=dict(self.TINY_COLUMN, ke_stop=ke_stop, ke_of=ke_of, resume=1),
                          workdir=straight.workdir)
            self.assertRanCleanly(resumed)
            line = next(l for l in resumed.output.splitlines() if l.startswith("in.column final:"))
            self.assertAlmostEqual(float(re.search(r" at t = (\S+) ", line).group(1)), walls[k]["t"], delta=1e-12)
            for name, value in walls[k]["at_stop"].items():
                # the thermo row holds 8 significant digits
                got = float(re.search(re.escape(name) + r" = (\S+)", line).group(1))
                self.assertAlmostEqual(got, value, delta=1e-7 * max(abs(got), 1e-12), msg=name)


class RenderColumn(DeckTestCase):
    """postprocess/render_column.py on the VTK files of a tiny deck (six grains falling
    under a double wire loop, 100 steps, both dumps every 50): single pictures from the
    files and from the series, and two states side by side; each a PNG of the size asked
    for whose pixels are not all one colour."""
    DECK = """
units           lj
atom_style      hybrid polyhedron wire
atom_modify     map array sort 0 0.0
boundary        f f f
region          box block -3 3 -3 3 -1 8
create_box      2 box
region          fill block -2 2 -2 2 1.1 3.5
create_grains   1 6 random fill seed 5
group           grains type 1
create_wire     2 loop 0 0 4.5 1.8 2 0.25
group           wire type 2
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd grains nscd/polyhedra timestep 1e-3 wall 0 0 0 0 0 1
timestep        1e-3
pair_style      wire/contact
pair_coeff      * *
neighbor        0.1 bin
neigh_modify    delay 0
fix             elastic wire wire/elastic
fix             integr wire nve/gear
fix             floor wire wire/wall plane 0 0 0 0 0 1
fix             wg wire wire/grain grains
dump            grains grains polyhedron/vtk 50 post/grains_*.vtp
dump            wire wire wire/vtk 50 post/wire_*.vtp energy elastic
run             100
"""

    @classmethod
    def setUpClass(cls):
        cls.result = run(cls.DECK)

    def png_size(self, path):
        """(width, height) from the PNG's IHDR chunk."""
        with open(path, "rb") as f:
            head = f.read(24)
        self.assertEqual(head[:8], b"\x89PNG\r\n\x1a\n", path)
        self.assertEqual(head[12:16], b"IHDR", path)
        return struct.unpack(">II", head[16:24])

    def pixels(self, path):
        from vtkmodules.util.numpy_support import vtk_to_numpy
        from vtkmodules.vtkIOImage import vtkPNGReader
        reader = vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
        image = reader.GetOutput()
        width, height, _ = image.GetDimensions()
        return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, -1)[:, :, :3]

    def render(self, name, *args, size=(320, 240)):
        out = os.path.join(self.result.workdir, name)
        status, text = script("render_column.py", *args, "--out", out, "--size", *map(str, size),
                              cwd=self.result.workdir)
        self.assertEqual(status, 0, text[-2000:])
        self.assertGreater(os.path.getsize(out), 1000, text)
        self.assertEqual(self.png_size(out), size)
        return out

    def assertPainted(self, pixels, what):
        """Not one flat colour: many colours and some spread of the values."""
        colours = np.unique(pixels.reshape(-1, 3), axis=0)
        self.assertGreater(len(colours), 50, what)
        self.assertGreater(pixels.astype(float).std(), 5.0, what)

    def test_deck_wrote_both_series(self):
        self.assertRanCleanly(self.result)
        for name in ("grains", "wire"):
            with open(self.result.path(f"post/{name}.vtp.series")) as f:
                self.assertEqual(len(json.load(f)["files"]), 3, name)

    def test_files(self):
        out = self.render("files.png", "--grains", self.result.path("post/grains_100.vtp"),
                          "--wire", self.result.path("post/wire_100.vtp"), "--view", "side")
        # the scene, left of the colour bar (the right 12 %)
        self.assertPainted(self.pixels(out)[:, :280], "files.png")

    def test_series_frame(self):
        out = self.render("series.png", "--series", self.result.path("post"), "--frame", "t=0.05",
                          size=(300, 200))
        self.assertPainted(self.pixels(out)[:, :260], "series.png")

    def test_before_after(self):
        out = self.render("pair.png", "--before", self.result.path("post"), "0", "--after", self.result.path("post"),
                          "--titles", "start", "end", "--layout", "row", size=(480, 240))
        pixels = self.pixels(out)
        # each panel (the left and right 44 % of the picture; the colour bar beside them)
        self.assertPainted(pixels[:, :210], "left panel")
        self.assertPainted(pixels[:, 215:420], "right panel")

    def test_bad_frame(self):
        status, text = script("render_column.py", "--series", self.result.path("post"), "--frame", "7", "--out", "x.png",
                              cwd=self.result.workdir)
        self.assertNotEqual(status, 0)
        self.assertIn("--frame 7: ", text)
        self.assertIn("has frames 0 to 2", text)

if __name__ == "__main__":
    main()
