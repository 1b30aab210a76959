"""fix nscd/polyhedra's `plate`: a fix wire/wall plane as a body of the grains' contact
problem. Three unit cubes stacked on a floor under a plate pressed by a load F: the statics
of every interface and the Love–Weber stress of every cube; a spring-driven plate on the
same column at rest against a prescribed one; its error messages."""

import numpy as np

from liggghts_run import DeckTestCase, full_precision, main, read_dump, read_local_dump, run

G = 1.0
HEADER = """
units           lj
atom_style      hybrid polyhedron wire
atom_modify     map array sort 0 0.0
boundary        f f f
"""
# three unit cubes (density 1: m = 1, A = 1, sweep 0) stacked on the floor z = 0, the top
# face at z = 3
N_BOXES = 3


def stack():
    """scene.data / scene.shapes: the stack of cubes (atom type 1), no wire beads (type 2)."""
    made = run(HEADER + f"""
region          box block -3 3 -3 3 -1 6
create_box      2 box
create_grains   1 {N_BOXES} random box seed 7 shape cube 1.0 sweep 0 density 1
write_data      scene.data
grain_shapes    write scene.shapes
""")
    if made.returncode != 0:
        raise AssertionError(made.output[-3000:])
    with open(made.path("scene.data")) as f:
        text = f.read().splitlines()
    k = next(i for i, line in enumerate(text) if line.startswith("Atoms")) + 2
    # hybrid Atoms line: id type x y z | shape density qw qi qj qk | prev next rest radius mass
    for n in range(N_BOXES):
        words = text[k + n].split()
        z = 0.5 + (int(words[0]) - 1)
        words[2:5] = ["0.0", "0.0", repr(z)]
        words[7:11] = ["1.0", "0.0", "0.0", "0.0"]
        text[k + n] = " ".join(words)
    with open(made.path("scene.data"), "w") as f:
        f.write("\n".join(text) + "\n")
    return made


def deck(plate_line, z_plate, body):
    """The stack under gravity g = 1 on the floor (wall 1) with a top plane at z_plate
    (wall 2, fix wire/wall `top`); plate_line: fix nscd/polyhedra's words after
    `wall_fix top` (e.g. "plate 2 load 5")."""
    return HEADER + f"""
grain_shapes    read scene.shapes
read_data       scene.data
group           grains type 1
group           wire type 2
fix             g grains gravity {G} vector 0 0 -1
fix             floor wire wire/wall plane 0 0 0 0 0 1
fix             top wire wire/wall plane 0 0 {z_plate} 0 0 -1
fix             nscd grains nscd/polyhedra friction 0.5 tolerance 1e-10 wall_fix floor wall_fix top {plate_line}
timestep        1e-3
compute         contacts all contact/local
compute         stress grains grain/stress
{body}
"""


# compute contact/local's columns 1..13: kind a b x y z nx ny nz f_n fx fy fz (force on b)
CONTACT_COLUMNS = " ".join(f"c_contacts[{k}]" for k in range(1, 14))
# f_nscd's plate values with W = 2 walls: after 6 + 3 W + 18 = 30 values
TRAVEL, VELOCITY, GRAINS_FORCE, DRIVE_FORCE = 31, 32, 33, 34


class LoadedStack(DeckTestCase):
    # A plate of mass 2 starts 0.005 above the stack, pressed by F = 5 (weightless: F is
    # all its load); it falls onto the stack, and at rest (1000 steps) each interface
    # carries the statics: the plate F, the interface below cube k (from the top) F + k m g,
    # the floor F + 3 m g; the Love–Weber σ_zz of cube k, whose top carries T = F + (k−1) m g
    # and bottom B = T + m g, is (1/V) Σ (x_c − x_k)_z f_z = (1/a³)(a/2)(−T − B):
    #     σ_zz = −(T + B) / (2A) = −(2F + (2k − 1) m g) / 2     (a = 1).
    # Measured (tolerance 1e-10; the stick solve is exact at rest): interface sums 1.1e-16 off,
    # σ_zz 5.6e-16 (relative to F + 3 m g), the plate's force 0, its travel 0.005 + 2.9e-15,
    # grain speeds 4e-19; held to 1e-14, 1e-14, 1e-14, 1e-13 and 1e-17. (At the default
    # tolerance 1e-4 the impact step overshoots by ~h 1e-4 v_impact = 1e-8, an overlap kept
    # since, which moves the contact points and σ_zz by ~1e-9.) A plate that is a
    # prescribed wall instead would carry the weight alone: the load would not act.
    F = 5.0

    @classmethod
    def setUpClass(cls):
        cls.made = stack()
        cls.result = run(full_precision(deck(f"plate 2.0 load {cls.F}", 3.005, f"""
thermo_style    custom step f_nscd[12] f_nscd[31] f_nscd[32] f_nscd[33] f_nscd[34]
thermo_modify   format float %.17g
thermo          10
dump            c all local 1000 contacts.dump {CONTACT_COLUMNS}
dump_modify     c format "{' '.join(['%.17g'] * 13)}"
dump            d grains custom 1000 grains.dump id z vx vy vz c_stress[3]
run             1000
"""), "d"), workdir=cls.made.workdir)

    def test_plate_falls_at_load_over_mass(self):
        # before it reaches the stack (0.005 below: after ~63 steps) the plate is free: the
        # solve at the end of step n is the (n + 1)-th (the setup solve first), so
        # v = (n + 1) h F/m_p and, with θ = 1, s = h² (F/m_p) (n + 1)(n + 2)/2. Round-off:
        # measured 1.3e-16 (v) and 0 (s) relative; held to 1e-15.
        self.assertRanCleanly(self.result)
        t = self.result.thermo()
        row = list(t["Step"]).index(20)
        a, h, k = self.F / 2.0, 1e-3, 21
        print(f"\nfree fall at step 20: v {t['nscd[32]'][row]!r} (expected {k * h * a!r}), s {t['nscd[31]'][row]!r} "
              f"(expected {h * h * a * k * (k + 1) / 2!r})")
        self.assertLess(abs(t["nscd[32]"][row] - k * h * a), 1e-15 * k * h * a)
        self.assertLess(abs(t["nscd[31]"][row] - h * h * a * k * (k + 1) / 2), 1e-15 * h * h * a * k * (k + 1) / 2)

    def test_two_ranks_repeat_one_rank_to_the_bit(self):
        # the replicated solve with the plate on 2 ranks, the subdomains cutting the stack
        # (processors 1 1 *): the grains' state, their stresses and the plate's travel,
        # velocity and forces are one rank's to the last bit. Measured: identical.
        self.assertRanCleanly(self.result)
        text = full_precision(deck(f"plate 2.0 load {self.F}", 3.005, """
thermo_style    custom step f_nscd[12] f_nscd[31] f_nscd[32] f_nscd[33] f_nscd[34]
thermo_modify   format float %.17g
thermo          10
dump            d grains custom 1000 grains2.dump id z vx vy vz c_stress[3]
run             1000
""").replace("read_data", "processors      1 1 *\nread_data", 1), "d")
        two = run(text, workdir=self.made.workdir, np_ranks=2)
        self.assertRanCleanly(two)
        one, other = read_dump(self.result.path("grains.dump")), read_dump(two.path("grains2.dump"))
        for k in one:
            np.testing.assert_array_equal(other[k], one[k], err_msg=k)
        t1, t2 = self.result.thermo(), two.thermo()
        for k in ("nscd[12]", "nscd[31]", "nscd[32]", "nscd[33]", "nscd[34]"):
            np.testing.assert_array_equal(t2[k], t1[k], err_msg=k)

    def test_plate_and_interfaces_carry_the_statics(self):
        self.assertRanCleanly(self.result)
        t = self.result.thermo()
        scale = self.F + N_BOXES * G
        # the plate: it came down by its gap (and no further: the stack is rigid) and rests
        self.assertAlmostEqual(t["nscd[31]"][-1], 0.005, delta=1e-13)
        self.assertLess(abs(t["nscd[32]"][-1]), 1e-12)
        self.assertLess(abs(t["nscd[33]"][-1] - self.F) / scale, 1e-14)   # the grains hold it
        self.assertEqual(t["nscd[34]"][-1], self.F)                       # the load itself
        self.assertLess(abs(t["nscd[12]"][-1] - self.F) / scale, 1e-14)   # wall 2's force, z
        c = read_local_dump(self.result.path("contacts.dump"))
        z, fz, kind = c["c_contacts[6]"], c["c_contacts[13]"], c["c_contacts[1]"]
        worst = 0.0
        for level in range(N_BOXES + 1):  # interface at z = level: what the grains above weigh
            rows = np.abs(z - level) < 1e-6
            expected = self.F + (N_BOXES - level) * G
            self.assertTrue(np.all(kind[rows] == (3 if 0 < level < N_BOXES else 4)), level)
            # force on b (the upper grain, or the grain at a wall) along z: its load from below,
            # or from the plate (b below it) downwards
            carried = abs(np.sum(fz[rows]))
            worst = max(worst, abs(carried - expected) / scale)
        g = read_dump(self.result.path("grains.dump"))
        order = np.argsort(-g["z"])  # top first
        k = np.arange(1, N_BOXES + 1)
        sigma = -(2 * self.F + (2 * k - 1) * G) / 2.0
        stress_error = np.max(np.abs(g["c_stress[3]"][order] - sigma)) / scale
        speed = np.max(np.sqrt(g["vx"] ** 2 + g["vy"] ** 2 + g["vz"] ** 2))
        print(f"\nloaded stack: interface sums off by {worst:.1e}, sigma_zz by {stress_error:.1e} (F + 3 m g), "
              f"plate force {t['nscd[33]'][-1]!r}, travel {t['nscd[31]'][-1]!r}, grain speed {speed:.1e}")
        self.assertLess(worst, 1e-14)
        self.assertLess(stress_error, 1e-14)
        self.assertLess(speed, 1e-17)


class SpringOnAStackAtRest(DeckTestCase):
    # The plate (mass 1) touching the top of the stack at rest. Driven through a spring
    # k = 100 whose drive point moves down at 0.5, the plate cannot move (the stack is
    # rigid): the force on the stack is the spring's, k (drive travel − plate travel) ≤
    # k × 0.1005 = 10.05 after 200 steps (the drive travels 201 steps of 1e-3: the setup
    # solve's and the run's), and the grains stay at rest. The same plate prescribed at 0.5
    # (the wall of in.column_load's `prescribed` mode) meets a chain that cannot give: the
    # solve has no solution, its impulses grow with the sweeps and the cubes are thrown.
    # Measured (tolerance 1e-10): the spring's force on the stack 10.05 + 8e-15, the plate's
    # travel −2e-21, the fastest grain 8.8e-19 over the run, the floor's load at most 13.05
    # (3 m g + 10.05); the prescribed plate: 90 of the 200 steps at the iteration cap, the
    # floor's load up to 8.9e12, grains thrown at up to 4. Held: the force ≤ the bound
    # (1 + 1e-12) and within 1e-14 of it, the travel within 1e-19, the grains below 1e-17,
    # the floor within 1e-12 of 3 m g + the bound; the prescribed plate's grains above 0.1
    # and its floor load above 1e6 times the spring's bound.
    K, V_DRIVE, STEPS = 100.0, 0.5, 200

    @classmethod
    def setUpClass(cls):
        cls.made = stack()
        body = f"""
variable        speed atom sqrt(vx*vx+vy*vy+vz*vz)
compute         fastest grains reduce max v_speed
thermo_style    custom step c_fastest f_nscd[6] f_nscd[9] f_nscd[12] f_nscd[31] f_nscd[32] f_nscd[33] f_nscd[34]
thermo_modify   format float %.17g
thermo          1
dump            d grains custom {cls.STEPS} grains.dump id z vx vy vz
run             {cls.STEPS}
"""
        cls.spring = run(full_precision(deck(f"plate 1.0 spring {cls.K} {cls.V_DRIVE}", 3.0, body), "d"),
                         workdir=cls.made.workdir)
        prescribed = deck("", 3.0, body).replace("0 0 3.0 0 0 -1", f"0 0 3.0 0 0 -1 velocity 0 0 -{cls.V_DRIVE}")
        prescribed = prescribed.replace(" f_nscd[31] f_nscd[32] f_nscd[33] f_nscd[34]", "")
        cls.prescribed = run(prescribed.replace("grains.dump", "prescribed.dump"), workdir=cls.made.workdir)

    def test_spring_bounds_the_force_and_nothing_flies(self):
        self.assertRanCleanly(self.spring)
        t = self.spring.thermo()
        # the solve at the end of step n is that of the step to t = (n + 1) dt (the setup solve
        # did the first): the drive has travelled (n + 1) dt v_drive then
        bound = self.K * self.V_DRIVE * 1e-3 * (self.STEPS + 1)
        force = t["nscd[33]"][1:]
        self.assertLessEqual(np.max(force), bound * (1 + 1e-12))
        # the plate does not move, so the spring's force goes to the stack: k × drive travel
        self.assertLess(abs(force[-1] - bound), 1e-14 * bound)
        self.assertLess(abs(t["nscd[31]"][-1]), 1e-19)
        self.assertLess(abs(t["nscd[34]"][-1] - force[-1]), 1e-14 * bound)
        # over the whole run: the fastest grain and the floor's load (3 m g + the spring's)
        speed = np.max(t["fastest"])
        floor = np.max(-t["nscd[9]"])
        self.assertLessEqual(floor, bound + N_BOXES * G + 1e-12 * bound)
        self.assertRanCleanly(self.prescribed)
        p = self.prescribed.thermo()
        thrown, crushed = np.max(p["fastest"]), np.max(-p["nscd[9]"])
        print(f"\nspring: force {force[-1]!r} (bound {bound}), plate travel {t['nscd[31]'][-1]:.1e}, fastest grain "
              f"{speed:.1e}, floor force at most {floor:.4g}; prescribed plate: fastest grain {thrown:.2g}, floor "
              f"force at most {crushed:.2g}, {p['nscd[6]'][-1]:.0f} of {self.STEPS} steps at the iteration cap")
        self.assertLess(speed, 1e-17)
        self.assertGreater(thrown, 0.1)
        self.assertGreater(crushed, 1e6 * bound)


class FreeSpringOscillation(DeckTestCase):
    # A plate (m_p = 1) on a spring k = 100 whose drive point stands still (v_drive 0),
    # started at v0 = 0.5 towards the grains (its fix wire/wall's velocity) 2 above the
    # stack, which it never reaches (amplitude v0/ω = 0.05): a free oscillator of ω = 10.
    # With θ = 1 the plate's step is backward Euler on s and v (nscd_plate.h):
    #     s_{n+1} = s_n + h v_{n+1},   m_p (v_{n+1} − v_n) = −h k s_{n+1},
    # so u = v + iωs obeys u_{n+1} = u_n / (1 − iωh): u_n = v0 (1 − iωh)^(−n), a spiral that
    # keeps the period 2π/ω to O(h²) and loses amplitude by (1 + ω²h²)^(−1/2) per step
    # (backward Euler's damping). The thermo row of step n follows the (n + 1)-th solve.
    # Measured over 3000 steps (4.8 periods): s and v within 2.5e-15 and 2.4e-15 of the
    # closed form relative to the amplitudes, the spring's force k (d − s) exact; held to
    # 1e-13 (the plate's mass 1 % off, m_p + 1.01 h² k, gives 1.2e-5). The amplitude after
    # 3000 steps is 0.8607 of v0/ω (the exact oscillator's would stay 1).
    M, K, V0, STEPS, H = 1.0, 100.0, 0.5, 3000, 1e-3

    def test_plate_follows_the_discrete_oscillator(self):
        made = stack()
        text = deck(f"plate {self.M} spring {self.K} 0", 5.0, f"""
thermo_style    custom step f_nscd[31] f_nscd[32] f_nscd[34]
thermo_modify   format float %.17g
thermo          10
run             {self.STEPS}
""").replace("0 0 5.0 0 0 -1", f"0 0 5.0 0 0 -1 velocity 0 0 -{self.V0}")
        r = run(text, workdir=made.workdir)
        self.assertRanCleanly(r)
        t = r.thermo()
        omega = np.sqrt(self.K / self.M)
        u = self.V0 * (1 - 1j * omega * self.H) ** (-(t["Step"] + 1))
        amplitude = self.V0 / omega
        s_error = np.max(np.abs(t["nscd[31]"] - u.imag / omega)) / amplitude
        v_error = np.max(np.abs(t["nscd[32]"] - u.real)) / self.V0
        drive_error = np.max(np.abs(t["nscd[34]"] + self.K * t["nscd[31]"])) / (self.K * amplitude)
        kept = abs(u[-1]) / self.V0
        print(f"\nfree spring plate over {self.STEPS} steps: s off by {s_error:.1e}, v by {v_error:.1e} (of the "
              f"amplitudes), spring force by {drive_error:.1e}; amplitude kept {kept:.4f}")
        self.assertLess(s_error, 1e-13)
        self.assertLess(v_error, 1e-13)
        self.assertLess(drive_error, 1e-13)
        # it did oscillate: a full swing each way
        self.assertGreater(np.max(t["nscd[31]"]), 0.8 * amplitude)
        self.assertLess(np.min(t["nscd[31]"]), -0.8 * amplitude)


class RestartOfAPlate(DeckTestCase):
    # The plate's state is in the fix's restart data: a spring plate driven down onto the
    # stack (k = 100, v_drive 0.5, from 0.002 above it) for 300 steps, written to a restart
    # file at step 150 and continued from it, repeats the straight run to the bit: the
    # grains, the plate's travel, velocity and forces. Without the plate's state the
    # continued plate starts at rest with an unstretched spring: its travel at step 300 is
    # 1e-15 instead of 0.002, and the stack carries 7.5 instead of 14.85.
    BODY = """
thermo_style    custom step f_nscd[31] f_nscd[32] f_nscd[33] f_nscd[34]
thermo_modify   format float %.17g
thermo          10
dump            d grains custom 300 {dump} id x y z vx vy vz
"""

    def test_continued_run_repeats_the_straight_one(self):
        made = stack()
        plate = "plate 1.0 spring 100 0.5"
        straight = run(full_precision(deck(plate, 3.002, self.BODY.format(dump="straight.dump") + "run 300\n"), "d"),
                       workdir=made.workdir)
        first = run(deck(plate, 3.002, "run 150\nwrite_restart   plate.restart\n"), workdir=made.workdir)
        for r in (straight, first):
            self.assertRanCleanly(r)
        text = deck(plate, 3.002, self.BODY.format(dump="continued.dump") + "run 150\n")
        text = text.replace("grain_shapes    read scene.shapes\nread_data       scene.data\n",
                            "read_restart    plate.restart\n")
        continued = run(full_precision(text, "d"), workdir=made.workdir)
        self.assertRanCleanly(continued)
        a, b = straight.thermo(), continued.thermo()
        rows = np.isin(a["Step"], b["Step"])
        print(f"\nplate restarted at step 150: travel at 300 {b['nscd[31]'][-1]!r} (straight {a['nscd[31]'][-1]!r}), "
              f"grains' force {b['nscd[33]'][-1]!r}")
        self.assertGreater(a["nscd[33]"][-1], 1.0)  # the plate presses on the stack
        for k in ("nscd[31]", "nscd[32]", "nscd[33]", "nscd[34]"):
            np.testing.assert_array_equal(b[k], a[k][rows], err_msg=k)
        one, other = read_dump(straight.path("straight.dump")), read_dump(continued.path("continued.dump"))
        for k in one:
            np.testing.assert_array_equal(other[k], one[k], err_msg=k)


class PlateErrors(DeckTestCase):
    # bad input of the `plate` keyword: the full ERROR text, naming the argument
    P = "fix nscd/polyhedra (id nscd): "
    CASES = (
        ("plate 0 load 1", "value of 'plate m_p' must be > 0, got 0"),
        ("plate -2 load 1", "value of 'plate m_p' must be > 0, got -2"),
        ("plate 1 push 1", "value of 'plate' mode must be load or spring, got 'push'"),
        ("plate 1 load abc", "value of 'plate load' must be a finite number or v_name (an equal-style variable), got 'abc'"),
        ("plate 1 load", "missing value after 'plate load'"),
        ("plate 1 spring 0 0.1", "value of 'plate spring k' must be > 0, got 0"),
        ("plate 1 spring -5 0.1", "value of 'plate spring k' must be > 0, got -5"),
        ("plate 1 spring 10 inf", "value of 'plate spring v_drive' must be a finite number or v_name (an equal-style "
         "variable), got 'inf'"),
        ("plate 1 load 1 plate 2 load 1", "wall_fix top has a 'plate' already"),
        ("wall 0 0 -1 0 0 1 plate 1 load 1", "'plate' must follow a 'wall_fix' (a plate moves the plane of a fix wire/wall)"),
        ("plate 1 load v_nope", "plate load: variable 'nope' does not exist"),
        ("plate 1 spring 10 v_nope", "plate spring v_drive: variable 'nope' does not exist"),
        ("plate 1 load v_peratom", "plate load: variable 'peratom' is not equal-style"),
        ("plate 1 load v_infinite", "plate: variable 'infinite' is inf at step 0"),
        ("plate 1 load 1 solve distributed", "'solve distributed' does not take a 'plate' (the plate would be a body of "
         "every rank): use 'solve replicated'"),
    )

    def test_messages(self):
        made = stack()
        for words, message in self.CASES:
            with self.subTest(words=words):
                text = deck(words, 3.0, "run 1").replace("fix             nscd",
                                                         "variable        peratom atom x\n"
                                                         "variable        infinite equal 1e308*10\n"
                                                         "fix             nscd")
                self.assertStopsWith(run(text, workdir=made.workdir), self.P + message)
        # no plate keyword before a wall, an unknown wall_fix ID, a fix that is not wire/wall
        nowall = deck("", 3.0, "run 1").replace("wall_fix floor wall_fix top ", "plate 1 load 1")
        self.assertStopsWith(run(nowall, workdir=made.workdir), self.P + "'plate' must follow a 'wall' or 'wall_fix'")
        unknown = deck("plate 1 load 1", 3.0, "run 1").replace("wall_fix top", "wall_fix nope")
        self.assertStopsWith(run(unknown, workdir=made.workdir), self.P + "wall_fix nope: no fix with this ID")
        gravity = deck("plate 1 load 1", 3.0, "run 1").replace("wall_fix top", "wall_fix g")
        self.assertStopsWith(run(gravity, workdir=made.workdir),
                             self.P + "wall_fix g: fix style is gravity, not wire/wall")


if __name__ == "__main__":
    main()
