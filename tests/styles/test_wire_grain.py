"""fix wire/grain with fix nscd/polyhedra sub-cycling: weights carried by grains, momentum
across sub-cycles, N = 1/5/10 consistency, 1 vs 2 ranks, restart in the middle of a
sub-cycle, error messages."""

import os

import math

import numpy as np

from liggghts_run import (DeckTestCase, contact_overlap_warning, contact_time_step_warning, full_precision,
                          loaded_contact_measurement, main, read_dump, run, static_contact_measurement, warning_lines)

G = 1.0
HEADER = """
units           lj
atom_style      hybrid polyhedron wire
atom_modify     map array sort 0 0.0
"""


def scene(grains, wires, shape="cube 2", sweep=0.1, density=1.0, box=(-6, 6, -6, 6, -1, 8), boundary="f f f",
          files=None):
    """A data file (scene.data + scene.shapes) with len(grains) grains of one shape at the
    given poses [(x, y, z, qw, qi, qj, qk)] (atom type 1) and the wires of the
    `create_wire 2 ...` argument strings `wires` (atom type 2); `files` {name: text} are
    written next to the deck first (polylines)."""
    lines = "\n".join(f"create_wire     2 {w}" for w in wires)
    made = run(HEADER + f"""
boundary        {boundary}
region          box block {' '.join(map(str, box))}
create_box      2 box
create_grains   1 {len(grains)} random box seed 7 shape {shape} {"" if sweep is None else f"sweep {sweep}"} density {density}
{lines}
write_data      scene.data
grain_shapes    write scene.shapes
""", files=files)
    if made.returncode != 0:
        raise AssertionError(made.output[-3000:])
    with open(made.path("scene.data")) as f:
        text = f.read().splitlines()
    k = next(i for i, line in enumerate(text) if line.startswith("Atoms")) + 2
    n = 0
    # hybrid Atoms line: id type x y z | shape density qw qi qj qk | prev next rest radius mass
    while k < len(text) and text[k].strip():
        words = text[k].split()
        if int(words[5]) >= 0:
            x, y, z, qw, qi, qj, qk = grains[int(words[0]) - 1]
            words[2:5] = [repr(x), repr(y), repr(z)]
            words[7:11] = [repr(qw), repr(qi), repr(qj), repr(qk)]
            text[k] = " ".join(words)
            n += 1
        k += 1
    assert n == len(grains), (n, len(grains))
    with open(made.path("scene.data"), "w") as f:
        f.write("\n".join(text) + "\n")
    return made


def deck(body, boundary="f f f", processors="* * *"):
    return HEADER + f"""
boundary        {boundary}
processors      {processors}
grain_shapes    read scene.shapes
read_data       scene.data
group           grains type 1
group           wire type 2
{body}
"""


def resting_cube(x, y, edge=2.0, sweep=0.1):
    return (x, y, 0.5 * edge + sweep, 1.0, 0.0, 0.0, 0.0)


class Weights(DeckTestCase):
    def test_segment_on_a_face_carries_its_weight(self):
        # one segment (two beads) lying on the top face of a cube resting on the floor:
        # at rest, each bead is held up by m_b g, the grain is pressed down by the wire's
        # weight and the floor carries grain + wire
        made = scene([resting_cube(0, 0)], ["line -0.5 0.2 2.3 0.5 0.2 2.3 segment 1.0 radius 0.1"])
        r = run(full_precision(deck(f"""
fix             g all gravity {G} vector 0 0 -1
fix             elastic wire wire/elastic
fix             integr wire nve/gear
fix             nscd grains nscd/polyhedra every 5 tolerance 1e-10 wall 0 0 0 0 0 1
fix             wg wire wire/grain grains
timestep        1e-3
thermo_style    custom step f_wg[1] f_wg[2] f_wg[4] f_wg[5] f_wg[6] f_nscd[9]
thermo_modify   format float %.15g
thermo          500
dump            d all custom 6000 dump.w id mass z f_wg[1] f_wg[2] f_wg[3]
run             6000
"""), "d"), workdir=made.workdir)
        self.assertRanCleanly(r)
        t = r.thermo()
        d = read_dump(r.path("dump.w"))
        beads = d["id"] > 1
        m_beads = d["mass"][beads]
        m_grain = d["mass"][~beads][0]
        wire_weight = m_beads.sum() * G
        print(f"\nsegment on a face: bead forces {d['f_wg[3]'][beads]} (m_b g = {m_beads * G}), "
              f"force on the grain {t['wg[6]'][-1]:.15g} (−m_w g = {-wire_weight:.15g}), "
              f"floor {-t['nscd[9]'][-1]:.15g} (= {(m_grain + m_beads.sum()) * G:.15g})")
        self.assertEqual(t["wg[1]"][-1], 1.0)  # one segment–grain contact
        np.testing.assert_allclose(d["f_wg[3]"][beads], m_beads * G, rtol=1e-8)
        np.testing.assert_allclose(d["f_wg[1]"][beads], 0.0, atol=1e-10 * wire_weight)
        self.assertAlmostEqual(t["wg[6]"][-1] / -wire_weight, 1.0, delta=1e-8)
        self.assertAlmostEqual(d["f_wg[3]"][~beads][0] / -wire_weight, 1.0, delta=1e-8)
        self.assertAlmostEqual(-t["nscd[9]"][-1] / ((m_grain + m_beads.sum()) * G), 1.0, delta=1e-8)
        self.assertNotIn("WARNING", r.output)  # a Table 1 wire at rest: neither time step nor overlap

    def test_straight_wire_across_two_grains_each_carries_half(self):
        # a wire lying across two cubes, symmetric about x = 0 but not about y = 0: by
        # symmetry each grain carries half the wire's weight (fix viscous takes out the
        # vibration of the span between the cubes; it has no force at rest)
        made = scene([resting_cube(-1.5, 0), resting_cube(1.5, 0)],
                     ["line -2.0 0.3 2.3 2.0 0.3 2.3 segment 0.5 radius 0.1"])
        r = run(full_precision(deck(f"""
fix             g all gravity {G} vector 0 0 -1
fix             elastic wire wire/elastic
fix             integr wire nve/gear
fix             nscd grains nscd/polyhedra every 5 tolerance 1e-10 wall 0 0 0 0 0 1
fix             wg wire wire/grain grains
fix             calm wire viscous 0.02
timestep        1e-3
thermo_style    custom step f_wg[1] f_wg[6]
thermo_modify   format float %.15g
thermo          1000
dump            d all custom 16000 dump.w id mass x f_wg[3]
run             16000
"""), "d"), workdir=made.workdir)
        self.assertRanCleanly(r)
        d = read_dump(r.path("dump.w"))
        grains = d["id"] <= 2
        wire_weight = d["mass"][~grains].sum() * G
        carried = -d["f_wg[3]"][grains] / wire_weight
        print(f"\nwire across two grains: shares {carried} of the wire's weight")
        np.testing.assert_allclose(carried, [0.5, 0.5], rtol=1e-6)


    def test_a_segment_stretched_beyond_max_stretch_widens_the_search(self):
        # a sagging wire of Table 1 segments (l 0.2, r_w 0.1) with max_stretch 1e-6: its
        # segments stretch beyond that under their weight, the fix warns once and searches
        # wider; with the default 0.5 it does not warn (it did, at 0 % strain, when the
        # growth allowance of 1.25 also multiplied r_w); nothing physical depends on the
        # search, so the shares are those of the default run to round-off
        made = scene([resting_cube(-1.5, 0), resting_cube(1.5, 0)],
                     ["line -2.0 0.3 2.3 2.0 0.3 2.3 segment 0.2 radius 0.1"])
        shares = {}
        for stretch in ("0.5", "1e-6"):
            r = run(full_precision(deck(f"""
fix             g all gravity {G} vector 0 0 -1
fix             elastic wire wire/elastic
fix             integr wire nve/gear
fix             nscd grains nscd/polyhedra every 5 tolerance 1e-10 wall 0 0 0 0 0 1
fix             wg wire wire/grain grains max_stretch {stretch}
fix             calm wire viscous 0.02
timestep        1e-3
dump            d all custom 4000 dump.w id mass x f_wg[3]
run             4000
"""), "d"), workdir=made.workdir)
            self.assertRanCleanly(r)
            warned = "WARNING: fix wire/grain (id wg): at step" in r.output
            self.assertEqual(warned, stretch == "1e-6", "warning given" if warned else "no warning")
            if warned:
                self.assertEqual(r.output.count("(max_stretch = 1e-06): the contact search widens to follow it"), 1)
            d = read_dump(r.path("dump.w"))
            shares[stretch] = -d["f_wg[3]"][d["id"] <= 2]
        print(f"\nsagging wire: grain loads {shares['0.5']} (max_stretch 0.5) and {shares['1e-6']} (1e-6)")
        self.assertGreater(shares["0.5"].min(), 0.0)
        np.testing.assert_allclose(shares["1e-6"], shares["0.5"], rtol=1e-12)


class Stiffness(DeckTestCase):
    def test_segment_on_a_face_at_a_known_overlap(self):
        # the paper's wire–grain stiffnesses, measured statically (no gravity, no velocity: no
        # damping): a segment (l = 1) lying across the top face of a cube at overlap ξ pushes
        # with k_n ξ, k_n = E_wp l π/4, 1/E_wp = (1−ν_w²)/E_w + (1−ν_p²)/E_p; then moved by δ
        # along its length (the cube held by the floor's friction) and stopped, it carries
        # k_t δ, k_t = E_wp r_w, below the slip limit μ_s k_n ξ.
        E_w, nu_w, E_p, nu_p, r_w, l_w, xi, delta, steps = 100.0, 0.0, 1000.0, 0.3, 0.1, 1.0, 1e-3, 4e-4, 100
        z = 2.1 + 0.1 + r_w - xi  # the sharp top face at 2.1 (the cube rests on its sweep 0.1), sweep 0.1
        made = scene([resting_cube(0, 0)], [f"line -0.5 0.2 {z!r} 0.5 0.2 {z!r} segment {l_w} radius {r_w}"])
        r = run(deck(f"""
fix             nscd grains nscd/polyhedra tolerance 1e-12 wall 0 0 0 0 0 1
fix             wg wire wire/grain grains E_w {E_w} nu_w {nu_w} E_p {E_p} nu_p {nu_p} mu_s 0.5 mu_d 0.5
""" + static_contact_measurement("wire", delta, steps)), workdir=made.workdir)
        self.assertRanCleanly(r)
        first, last = r.thermo(0), r.thermo()
        E_wp = 1.0 / ((1 - nu_w ** 2) / E_w + (1 - nu_p ** 2) / E_p)
        k_n, k_t = E_wp * l_w * math.pi / 4, E_wp * r_w
        normal, tangential = first["f[3]"][0], -last["f[1]"][-1]
        print(f"segment on a face: normal {normal:.12g} vs k_n xi {k_n * xi:.12g}; tangential {tangential:.12g} "
              f"vs k_t delta {k_t * delta:.12g}")
        self.assertLess(k_t * delta, 0.5 * k_n * xi)
        # measured 2.8e-13 (ξ = 1e-3 from heights ~2.3) and 8.0e-15
        self.assertAlmostEqual(normal / (k_n * xi), 1.0, delta=2e-12)
        self.assertAlmostEqual(tangential / (k_t * delta), 1.0, delta=1e-13)

    def test_segment_on_a_face_under_load(self):
        # the same stiffnesses the other way round: a segment (l 0.6, r_w 0.08) lying on the
        # top face of a cube that its weight (g on the grain only) holds on the floor, both
        # beads pushed down by F (fix addforce), settles, damped by the contact's dashpot
        # alone, at the overlap ξ = 2F/k_n, k_n = E_wp l π/4, 1/E_wp = (1−ν_w²)/E_w +
        # (1−ν_p²)/E_p; a tangential force F_t per bead (below μ_s F) added on top moves it
        # across the face by 2F_t/k_t, k_t = E_wp r_w. Overlap and shift are taken relative
        # to the grain (its sharp top face is at its centre + 1, the sweep r_p = 0.1).
        E_w, nu_w, E_p, nu_p, r_w, l_w, r_p = 150.0, 0.2, 800.0, 0.35, 0.08, 0.6, 0.1
        dt, steps, F, Ft = 1e-3, 3000, 0.03, 0.003
        direction = np.array([0.6, 0.8, 0.0])
        z = 2.1 + r_p + r_w                      # touching
        made = scene([resting_cube(0, 0)], [f"line -0.3 0.2 {z!r} 0.3 0.2 {z!r} segment {l_w} radius {r_w}"])
        r = run(deck(f"""
fix             g grains gravity {G} vector 0 0 -1
fix             nscd grains nscd/polyhedra tolerance 1e-12 wall 0 0 0 0 0 1
fix             wg wire wire/grain grains E_w {E_w} nu_w {nu_w} E_p {E_p} nu_p {nu_p} mu_s 0.5 mu_d 0.5 damping_ratio 1
fix             elastic wire wire/elastic
fix             integr wire nve/gear forces velocity
""" + loaded_contact_measurement("wire", [1, 2, 3], (0, 0, -F), tuple(Ft * direction), steps, dt)),
                workdir=made.workdir)
        self.assertRanCleanly(r)
        t0, t1 = r.thermo(0), r.thermo()

        def at(table, k, row):
            return np.array([table[f"{c}{k}"][row] for c in "xyz"])

        grain0, grain1, grain2 = at(t0, 1, 0), at(t0, 1, -1), at(t1, 1, -1)
        wire1 = 0.5 * (at(t0, 2, -1) + at(t0, 3, -1))
        wire2 = 0.5 * (at(t1, 2, -1) + at(t1, 3, -1))
        E_wp = 1.0 / ((1 - nu_w ** 2) / E_w + (1 - nu_p ** 2) / E_p)
        k_n, k_t = E_wp * l_w * math.pi / 4, E_wp * r_w
        xi = r_w + r_p - (wire1[2] - (grain1[2] + 1.0))
        shift = (wire2 - grain2) - (wire1 - grain1)
        err_n = xi / (2 * F / k_n) - 1
        err_t = shift[:2] / (2 * Ft * direction[:2] / k_t) - 1
        speed = max(t1[f"s{k}"][-1] for k in (1, 2, 3))
        print(f"\nsegment on a face under load: overlap / (2F/k_n) - 1 = {err_n:.1e}, shift / (2F_t/k_t) - 1 = "
              f"{err_t}, bead heights differ by {abs(t1['z2'][-1] - t1['z3'][-1]):.1e}, grain moved "
              f"{np.max(np.abs(grain2 - grain0)):.1e}, largest speed at rest {speed:.1e}")
        self.assertLess(abs(err_n), 1e-11)                # measured 6e-14
        self.assertLess(np.max(np.abs(err_t)), 1e-11)     # measured 1.3e-12


class Momentum(DeckTestCase):
    def test_free_grain_hitting_a_free_wire_conserves_momentum(self):
        # zero gravity, no walls: a cube flies into a straight wire; with the forces on
        # the grain averaged over the N = 5 sub-steps and velocity Verlet for the wire
        # (whose velocity changes by exactly dt ΣF/m once the contact is over), the total
        # momentum after the collision equals the one before to round-off
        made = scene([(0.0, 0.0, 0.0, 0.9238795325112867, 0.0, 0.3826834323650898, 0.0)],
                     ["line -1.25 0.1 -1.2 1.25 0.1 -1.2 segment 0.5 radius 0.1"], shape="cube 1",
                     box=(-6, 6, -6, 6, -6, 6))
        r = run(deck("""
set             group grains vz -1.0
set             group grains vx 0.2
fix             elastic wire wire/elastic
fix             integr wire nve/gear scheme verlet
fix             nscd grains nscd/polyhedra every 5
fix             wg wire wire/grain grains
timestep        1e-3
variable        px atom mass*vx
variable        pz atom mass*vz
compute         px all reduce sum v_px
compute         pz all reduce sum v_pz
compute         vg grains reduce max vz
thermo_style    custom step c_px c_pz c_vg f_wg[1]
thermo_modify   format float %.17g
thermo          5
run             1500
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        t = r.thermo()
        self.assertGreater(t["wg[1]"].max(), 0)   # they touched
        self.assertEqual(t["wg[1]"][-1], 0)       # and parted
        self.assertGreater(t["vg"][-1] - t["vg"][0], 0.02)  # the grain was slowed down
        p0 = np.hypot(t["px"][0], t["pz"][0])
        drift = np.hypot(t["px"][-1] - t["px"][0], t["pz"][-1] - t["pz"][0])
        print(f"\nmomentum: |p| = {p0:.15g}, after the collision |Δp| = {drift:.3g} "
              f"({drift / p0:.2e} relative); grain vz {t['vg'][0]:.6f} -> {t['vg'][-1]:.6f}")
        self.assertLess(drift, 1e-13 * p0)


def three_cube_scene(height=0.62):
    """Three cubes (edge 1, sweep 0.1), turned about z, 0.14 and 0.08 apart, their centres
    at `height` (0.6: resting on the floor), and a wire of ten 0.4-long segments at
    z = 1.35, 0.05 above resting cubes, off their centre line."""
    cubes = []
    for x, turn in ((-1.6, 0.3), (0.0, -0.2), (1.6, 0.5)):
        cubes.append((x, 0.05 * x, height, np.cos(turn / 2), 0.0, 0.0, np.sin(turn / 2)))
    return scene(cubes, ["line -2.0 0.1 1.35 2.0 0.1 1.35 segment 0.4 radius 0.1"], shape="cube 1",
                 box=(-3, 3, -3, 3, -0.5, 3))


# solve replicated: the 2-rank runs below give one rank's state to the bit (the wire's
# ghost grains are the same in either solve; the distributed solve with the wire on 2
# ranks: test_distributed.py)
COUPLED = """
fix             g all gravity {g} vector 0 0 -1
fix             elastic wire wire/elastic
fix             integr wire nve/gear
fix             nscd grains nscd/polyhedra every {every} tolerance 1e-8 solve replicated wall 0 0 0 0 0 1
fix             wg wire wire/grain grains {contact}
timestep        1e-3
"""


def cube_mass(edge, sweep, density=1.0):
    """The mass of a cube of the given edge dilated by the sweep radius (atom_style
    polyhedron's default mass model), by Steiner's formula: the cube, a slab `sweep` thick
    on each of its 6 faces, a quarter cylinder along each of its 12 edges, an eighth of a
    ball at each of its 8 corners."""
    return density * (edge ** 3 + 6 * edge ** 2 * sweep + 3 * math.pi * edge * sweep ** 2
                      + 4 / 3 * math.pi * sweep ** 3)


def wire_mass(length, segment, radius, density=0.5):
    """The mass of a straight wire of create_wire (default density 0.5): a bead of mass
    density π r² l at each end of each of its length/l segments."""
    segments = round(length / segment)
    return (segments + 1) * density * math.pi * radius ** 2 * segment


class SubCycling(DeckTestCase):
    def test_one_five_and_ten_sub_steps_reach_the_same_rest_without_energy_gain(self):
        # the wire drops onto three resting cubes and comes to rest on them. At rest its only
        # supports are the grains: the wire's forces on the grains sum to (0, 0, −m_w g) and
        # the floor carries (M + m_w) g, with m_w and M from create_wire's and
        # create_grains' densities and geometry (wire_mass, cube_mass); every component of the
        # wire's force and torque on each grain and of the floor force agrees for N = 1, 5, 10
        # wire sub-steps per NSCD step.
        # Energy E = kinetic + potential + wire elastic (contact springs left out, which
        # only lowers E), taken at the end of each NSCD step, where the grains have their
        # new velocities v' and will move to x + h v' (θ = 1): their potential energy is
        # that of x + h v', so E is the state a Moreau–Jean step can only dissipate; it
        # must never exceed its start value
        made = three_cube_scene(height=0.6)
        m_wire, m_grains = wire_mass(4.0, 0.4, 0.1), 3 * cube_mass(1.0, 0.1)
        rest = {}
        for every in (1, 5, 10):
            r = run(deck(COUPLED.format(g=G, every=every, contact="") + f"""
fix             calm wire viscous 0.02
compute         elastic wire wire/energy
variable        pe_wire atom mass*z
variable        pe_grains atom mass*(z+{every * 1e-3}*vz)
compute         pe_wire wire reduce sum v_pe_wire
compute         pe_grains grains reduce sum v_pe_grains
compute         ke all ke
variable        energy equal c_ke+c_pe_wire+c_pe_grains+c_elastic[3]
thermo_style    custom step f_wg[1] f_nscd[7] f_nscd[8] f_nscd[9] v_energy
thermo_modify   format float %.17g norm no
thermo          1
dump            d grains custom 12000 dump.w id f_wg[1] f_wg[2] f_wg[3] f_wg[4] f_wg[5] f_wg[6]
dump_modify     d sort id format "%d %.17g %.17g %.17g %.17g %.17g %.17g"
run             12000
"""), workdir=made.workdir)
            self.assertRanCleanly(r)
            t = r.thermo()
            d = read_dump(r.path("dump.w"))
            energy = t["energy"][t["Step"] % every == 0]
            gain = np.max(energy - energy[0])
            on_grains = np.array([d[f"f_wg[{k}]"] for k in (1, 2, 3)]).T        # per grain, x y z
            torques = np.array([d[f"f_wg[{k}]"] for k in (4, 5, 6)]).T
            floor = np.array([t[f"nscd[{k}]"][-1] for k in (7, 8, 9)])
            rest[every] = (on_grains, torques, floor, gain)
            print(f"\nN = {every}: wire force on the grains {on_grains[:, 2]}, sum {on_grains.sum(axis=0)} "
                  f"(-m_w g = {-m_wire * G:.12g}), floor {floor} (-(M + m_w) g = {-(m_grains + m_wire) * G:.12g}), "
                  f"contacts {t['wg[1]'][-1]:.0f}, largest energy gain {gain:.3g} "
                  f"(drop {energy[0] - energy[-1]:.4g})")
        weight = (m_grains + m_wire) * G
        for every in (1, 5, 10):
            on_grains, floor = rest[every][0].sum(axis=0), rest[every][2]
            against = [np.abs(rest[every][k] - rest[1][k]).max() / (m_wire * G) for k in range(3)]
            print(f"N = {every}: |sum + m_w g| = {np.abs(on_grains - [0, 0, -m_wire * G]).max() / (m_wire * G):.3g} "
                  f"m_w g, |floor + (M + m_w) g| = {np.abs(floor - [0, 0, -weight]).max() / (m_wire * G):.3g} m_w g; "
                  f"against N = 1, forces, torques, floor: " + ", ".join(f"{a:.3g}" for a in against) + " m_w g")
        # measured: the sum of the wire forces within 1.3e-10 m_w g of −m_w g and the floor force
        # within 8.9e-12 (1.7e-12 of (M + m_w) g) of −(M + m_w) g, the same residual in both,
        # the wire still settling under fix viscous; tolerance 5e-10 m_w g, 4× above
        for every in (1, 5, 10):
            on_grains, torques, floor, gain = rest[every]
            np.testing.assert_allclose(on_grains.sum(axis=0), [0.0, 0.0, -m_wire * G], rtol=0, atol=5e-10 * m_wire * G,
                                       err_msg=f"wire force on the grains, N = {every}")
            np.testing.assert_allclose(floor, [0.0, 0.0, -weight], rtol=0, atol=5e-10 * m_wire * G,
                                       err_msg=f"floor force, N = {every}")
            self.assertLessEqual(gain, 1e-12)
        # measured against N = 1: per-grain forces within 3.3e-11 m_w g, torques (arms ≈ 0.5)
        # 2.2e-11 m_w g, floor 5.5e-12 m_w g; tolerance 1e-10 m_w g, 3× above
        for every in (5, 10):
            for k, name in enumerate(("wire force on each grain", "wire torque on each grain", "floor force")):
                np.testing.assert_allclose(rest[every][k], rest[1][k], rtol=0, atol=1e-10 * m_wire * G,
                                           err_msg=f"{name}, N = {every} against N = 1")

    def test_wire_and_grains_exchange_opposite_impulses_every_nscd_step(self):
        # two cubes (edge 1, sweep 0.1) side by side on the floor, a third turned one on top
        # of both, a wire thrown sideways onto the top one: N = 5 wire sub-steps per NSCD step,
        # with NSCD steps in which the top grain touches the wire and both other grains.
        # Per NSCD step k (sub-steps s = 5k − 4 .. 5k, h = 5 dt), two measures of one impulse:
        # - the wire receives from the grains J_w = dt Σ_s (sum over the beads of the force
        #   from the grains, fix wire/grain's per-bead output, the force added to the beads);
        # - the grains receive from the wire J_g = ΔP − h M g − h F_c: their momentum change
        #   over the step less gravity's impulse (M from the deck: cube_mass) and the contact
        #   impulses of the NSCD solve (fix nscd/polyhedra's per-grain contact force, the
        #   impulses / h; grain–grain impulses cancel in the sum, the floor's remain);
        # and J_w + J_g = 0, all three components (friction gives x and y).
        made = scene([(-0.6, 0.0, 0.6, 1.0, 0.0, 0.0, 0.0), (0.6, 0.0, 0.6, 1.0, 0.0, 0.0, 0.0),
                      (0.1, 0.05, 1.8, math.cos(0.1), 0.0, 0.0, math.sin(0.1))],
                     ["line -1.0 0.2 2.55 1.0 0.2 2.55 segment 0.25 radius 0.1"], shape="cube 1",
                     box=(-3, 3, -3, 3, -0.5, 4))
        every, dt, steps = 5, 1e-3, 1000
        r = run(deck(COUPLED.format(g=G, every=every, contact="") + f"""
velocity        wire set 0.3 0.1 0
group           top id 3
variable        px atom mass*vx
variable        py atom mass*vy
variable        pz atom mass*vz
compute         p grains reduce sum v_px v_py v_pz
compute         fw wire reduce sum f_wg[1] f_wg[2] f_wg[3]
compute         fc grains reduce sum f_nscd[1] f_nscd[2] f_nscd[3]
compute         ontop top reduce sum f_nscd[3] f_wg[3]
thermo_style    custom step f_wg[1] c_p[1] c_p[2] c_p[3] c_fw[1] c_fw[2] c_fw[3] c_fc[1] c_fc[2] c_fc[3] &
                c_ontop[1] c_ontop[2]
thermo_modify   format float %.17g norm no
thermo          1
run             {steps}
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        t = r.thermo()
        np.testing.assert_array_equal(t["Step"], np.arange(steps + 1))
        momentum = np.array([t[f"p[{k}]"] for k in (1, 2, 3)]).T
        on_wire = np.array([t[f"fw[{k}]"] for k in (1, 2, 3)]).T
        contact = np.array([t[f"fc[{k}]"] for k in (1, 2, 3)]).T
        h, m_grains = every * dt, 3 * cube_mass(1.0, 0.1)
        gravity = np.array([0.0, 0.0, -m_grains * G])
        wire_impulse, grain_impulse, both = [], [], 0
        for k in range(1, steps // every + 1):
            end = k * every
            wire_impulse.append(dt * on_wire[end - every + 1:end + 1].sum(axis=0))
            grain_impulse.append(momentum[end] - momentum[end - every] - h * gravity - h * contact[end])
            # the top grain pushed by the wire (its mean wire force) and held by the grains below
            both += t["ontop[2]"][end] != 0.0 and t["ontop[1]"][end] > 0.0
        wire_impulse, grain_impulse = np.array(wire_impulse), np.array(grain_impulse)
        scale = np.abs(wire_impulse).max(axis=0)
        mismatch = np.abs(wire_impulse + grain_impulse).max(axis=0)
        print(f"\nimpulses per NSCD step: largest |J_w| (x, y, z) {scale}, largest |J_w + J_g| {mismatch} "
              f"({mismatch / scale.max()} of the largest); NSCD steps with the top grain touching the wire "
              f"and the grains {both} of {len(wire_impulse)}")
        self.assertGreater(both, 50)
        self.assertGreater(scale.min(), 1e-2 * scale.max())      # friction: x and y impulses too
        # measured: |J_w + J_g| ≤ 5.6e-15 of the largest |J_w| (round-off); tolerance 3e-14, 5× above
        np.testing.assert_allclose(wire_impulse, -grain_impulse, rtol=0, atol=3e-14 * scale.max())

    def test_a_segment_stretched_within_a_long_nscd_step_is_followed(self):
        # N = 50 wire sub-steps per NSCD step, one free Table 1 segment (l 0.2, r_w 0.1)
        # whose far bead is thrown outwards at 20: it stretches to twice its length (0.40
        # measured) within the first NSCD step, beyond the room the grains were held with
        # (a quarter of its half length, + r_w + the skin: 0.35): the fix holds
        # them again, wider, with its warning once, instead of stopping the run with "a
        # segment reaches ... beyond the allowed ..." (the case this guards against)
        made = scene([resting_cube(0.0, 0.0)], ["line 1.5 0 1.1 1.7 0 1.1 segment 0.2 radius 0.1"])
        r = run(deck("""
fix             elastic wire wire/elastic
fix             integr wire nve/gear
fix             nscd grains nscd/polyhedra every 50 tolerance 1e-8 wall 0 0 0 0 0 1
fix             wg wire wire/grain grains
timestep        1e-3
group           tip id 3
velocity        tip set 20 0 0
variable        length equal x[3]-x[2]
thermo_style    custom step v_length
thermo          1
run             100
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        longest = r.thermo()["length"].max()
        print(f"\nlongest segment within the first NSCD steps: {longest:.4f}")
        self.assertGreater(0.5 * longest + 0.1 + 0.1, 1.25 * 0.1 + 0.1 + 0.1)  # beyond the first reach (skin 0.1)
        self.assertEqual(r.output.count("the contact search widens to follow it"), 1)

    def test_two_ranks_give_the_state_of_one(self):
        # the subdomain boundary x = 0 cuts the middle cube and the wire
        made = three_cube_scene()
        states = []
        for ranks, grid in ((1, "1 1 1"), (2, "2 1 1")):
            r = run(full_precision(deck(COUPLED.format(g=G, every=5, contact="") + """
thermo          100
dump            d all custom 400 dump.s id x y z vx vy vz
run             400
""", processors=grid), "d"), np_ranks=ranks, workdir=made.workdir)
            self.assertRanCleanly(r)
            states.append(read_dump(r.path("dump.s")))
        for column in ("x", "y", "z", "vx", "vy", "vz"):
            np.testing.assert_allclose(states[1][column], states[0][column], rtol=0, atol=1e-12, err_msg=column)

    def test_long_segments_across_the_subdomain_boundary(self):
        # segments of length 2 (beads at x = ±1, ±3) over three small cubes (edge 0.2),
        # no pair style and no fix wire/elastic (a chain of free beads): only fix
        # wire/grain's ghost reach, (1 + max_stretch) × the longest rest length + the
        # neighbour skin, makes the far bead of the segment across x = 0 a ghost (the
        # grains' neighbour cutoff, 0.8, does not); 2 ranks give the state of 1
        cubes = [(x, 0.0, 0.15, 1.0, 0.0, 0.0, 0.0) for x in (-2.0, 0.3, 2.0)]
        made = scene(cubes, ["line -3 0.02 0.45 3 0.02 0.45 segment 2.0 radius 0.1"], shape="cube 0.2",
                     sweep=0.05, box=(-4, 4, -2, 2, -0.5, 2))
        states = []
        for ranks, grid in ((1, "1 1 1"), (2, "2 1 1")):
            body = COUPLED.format(g=G, every=5, contact="").replace("fix             elastic wire wire/elastic\n", "")
            r = run(full_precision(deck(body + """
thermo_style    custom step f_wg[1]
thermo          50
dump            d all custom 400 dump.s id x y z vx vy vz
run             400
""", processors=grid), "d"), np_ranks=ranks, workdir=made.workdir)
            self.assertRanCleanly(r)
            self.assertGreater(r.thermo()["wg[1]"].max(), 0)
            states.append(read_dump(r.path("dump.s")))
        for column in ("x", "y", "z", "vx", "vy", "vz"):
            np.testing.assert_allclose(states[1][column], states[0][column], rtol=0, atol=1e-12, err_msg=column)

    def test_segment_finds_a_ghost_grain(self):
        # a rod (box 2.4 × 0.4 × 0.4, sweep 0.05) on the floor of rank 1 (x > 2), its centre
        # 2.9 from the subdomain boundary x = 2, under the far end of a segment (length 2,
        # max_stretch 0.2) whose first bead lies on rank 0 at x = 1.95: rank 0 evaluates the
        # segment against its ghost grains, the rod among them; 2 ranks give the contacts and
        # the state of 1 (holding only its own grains, rank 0 misses the contact: 0 contacts)
        made = scene([(4.9, 0.0, 0.25, 1.0, 0.0, 0.0, 0.0)], ["line 1.95 0 0.59 3.95 0 0.59 segment 2.0 radius 0.1"],
                     shape="box 2.4 0.4 0.4", sweep=0.05, box=(-4, 8, -2, 2, -0.5, 2))
        states, contacts = [], []
        for ranks, grid in ((1, "1 1 1"), (2, "2 1 1")):
            r = run(full_precision(deck(COUPLED.format(g=G, every=5, contact="max_stretch 0.2") + """
thermo_style    custom step f_wg[1]
thermo          10
dump            d all custom 200 dump.s id x y z vx vy vz
run             200
""", processors=grid), "d"), np_ranks=ranks, workdir=made.workdir)
            self.assertRanCleanly(r)
            contacts.append(r.thermo()["wg[1]"])
            states.append(read_dump(r.path("dump.s")))
        print(f"\nrod of the other rank: contacts on 1 rank {contacts[0].max():.0f}, on 2 {contacts[1].max():.0f}")
        self.assertGreater(contacts[0].max(), 0)
        np.testing.assert_array_equal(contacts[1], contacts[0])
        for column in ("x", "y", "z", "vx", "vy", "vz"):
            np.testing.assert_allclose(states[1][column], states[0][column], rtol=0, atol=1e-12, err_msg=column)

    def test_restart_in_the_middle_of_a_sub_cycle_continues_the_straight_run(self):
        # N = 5; the restart file is written after step 233, three sub-steps into an NSCD
        # step; the straight run also stops and goes on at 233 (a run boundary: setup)
        made = three_cube_scene()
        body = COUPLED.format(g=G, every=5, contact="")
        straight = run(full_precision(deck(body + """
run             233
dump            d all custom 267 dump.s id x y z vx vy vz
run             267
"""), "d"), workdir=made.workdir)
        self.assertRanCleanly(straight)
        os.rename(made.path("dump.s"), made.path("dump.straight"))
        first = run(deck(body + """
run             233
write_restart   mid.restart
"""), workdir=made.workdir)
        self.assertRanCleanly(first)
        second = run(full_precision(HEADER + """
read_restart    mid.restart
group           grains type 1
group           wire type 2
""" + body + """
dump            d all custom 267 dump.s id x y z vx vy vz
run             267
""", "d"), workdir=made.workdir)
        self.assertRanCleanly(second)
        a, b = read_dump(made.path("dump.straight")), read_dump(made.path("dump.s"))
        for column in ("x", "y", "z", "vx", "vy", "vz"):
            np.testing.assert_allclose(b[column], a[column], rtol=0, atol=1e-13, err_msg=column)


class PairReuse(DeckTestCase):
    def test_the_pair_cache_gives_the_forces_of_a_search_every_step(self):
        # keyword skin: the (segment, grain) pairs kept while nothing moved more than the
        # skin; the pairs it evaluates include every touching one, in the same order, so
        # the trajectory is that of skin 0 (a full search every sub-step) to the last bit
        # (warm_geometry no, the default; with yes the cached pairs' GJK starts from their
        # last simplex: the same to GJK's tolerance, checked below).
        # The cubes slide and tumble under the falling wire, contacts open and close.
        made = three_cube_scene()
        states, evaluations = {}, {}
        for skin in (0, 0.05, 0.3, "0.05 warm"):
            contact = f"skin {skin} warm_geometry no" if skin != "0.05 warm" else "skin 0.05 warm_geometry yes"
            r = run(full_precision(deck(COUPLED.format(g=G, every=5, contact=contact) + f"""
set             group grains vx 0.4
set             group grains vy -0.2
variable        evaluations equal f_wg[7]
fix             count all ave/time 1 1 1 v_evaluations ave running
thermo_style    custom step f_wg[1] f_count
thermo          100
dump            d all custom 1200 dump.s id x y z vx vy vz
run             1200
"""), "d"), workdir=made.workdir)
            self.assertRanCleanly(r)
            t = r.thermo()
            self.assertGreater(t["wg[1]"].max(), 3)
            states[skin] = read_dump(r.path("dump.s"))
            evaluations[skin] = t["count"][-1]
        print(f"\nsegment–grain evaluations per step: skin 0 {evaluations[0]:.2f}, 0.05 {evaluations[0.05]:.2f}, "
              f"0.3 {evaluations[0.3]:.2f}")
        for skin in (0.05, 0.3):
            for column in ("x", "y", "z", "vx", "vy", "vz"):
                np.testing.assert_array_equal(states[skin][column], states[0][column], err_msg=f"skin {skin} {column}")
        self.assertLess(evaluations[0.05], evaluations[0])
        warm = max(np.max(np.abs(states["0.05 warm"][c] - states[0][c])) for c in ("x", "y", "z"))
        print(f"warm_geometry yes against the full search: positions within {warm:.2e}")
        self.assertLess(warm, 1e-10)


class Warnings(DeckTestCase):
    # The time step against the contact spring's stability limit, and overlaps beyond
    # 0.5 r_w (common/contact_checks.h), on one segment (beads 2 and 3) above or in a cube.
    BODY = """
fix             elastic wire wire/elastic m_elo 0.01 m_rot 0.01
fix             integr wire nve/gear
fix             nscd grains nscd/polyhedra wall 0 0 0 0 0 1
fix             wg wire wire/grain grains
timestep        {dt}
run             {steps}
"""

    def test_time_step_beyond_the_contact_limit(self):
        # Table 1: 1/E_wp = 1/100 + 0.91/1000, k = E_wp l π/4 = 14.4 on one bead (the grain
        # held), restitution 0.5 (ζ = 0.2155): gear5 limit 0.313 · 0.8075/ω = 0.00373
        made = scene([resting_cube(0, 0)], ["line -0.1 0.2 3 0.1 0.2 3"])
        r = run(deck(self.BODY.format(dt=0.004, steps=5)), workdir=made.workdir)
        self.assertRanCleanly(r)
        zeta = -math.log(0.5) / math.sqrt(math.pi ** 2 + math.log(0.5) ** 2)
        k = 1.0 / (1.0 / 100 + 0.91 / 1000) * 0.2 * math.pi / 4
        expected = contact_time_step_warning("fix wire/grain (id wg)", 0.004, k, 0.5 * math.pi * 0.01 * 0.2,
                                             "the lightest bead, the grain held", zeta, True)
        found = warning_lines(r.output)
        print("\n".join(found))
        self.assertEqual(found, [expected])
        self.assertIn("stable limit 0.00373", expected)
        quiet = run(deck(self.BODY.format(dt=0.0035, steps=5)), workdir=made.workdir)
        self.assertRanCleanly(quiet)
        self.assertNotIn("WARNING", quiet.output)

    def test_overlap_at_setup(self):
        # the segment's axis 0.14 above the face of a cube (edge 2, sweep 0.1, top face
        # at 2.2 with its sweep): overlap 0.06 = 0.6 r_w
        made = scene([resting_cube(0, 0)], ["line -0.1 0.2 2.24 0.1 0.2 2.24"])
        r = run(deck(self.BODY.format(dt=1e-4, steps=0)), workdir=made.workdir)
        self.assertRanCleanly(r)
        found = warning_lines(r.output)
        print("\n".join(found))
        self.assertEqual(found, [contact_overlap_warning("fix wire/grain (id wg)", 0, "the segment of bead 2 and grain 1",
                                                         0.06, 0.1, "stiffer materials (E_w, E_p)")])


class Errors(DeckTestCase):
    def check(self, body, message, made=None):
        made = made or Errors.made
        self.assertStopsWith(run(deck(body + "\nrun 1\n"), workdir=made.workdir), message)

    @classmethod
    def setUpClass(cls):
        cls.made = scene([resting_cube(0, 0)], ["line -0.5 0.2 2.3 0.5 0.2 2.3 segment 0.5 radius 0.1"])

    def test_bad_keywords(self):
        nscd = "fix nscd grains nscd/polyhedra\n"
        self.check(nscd + "fix wg wire wire/grain grains E_w -1",
                   "fix wire/grain (id wg): value of 'E_w' must be > 0, got -1")
        self.check(nscd + "fix wg wire wire/grain grains E_p 0",
                   "fix wire/grain (id wg): value of 'E_p' must be > 0, got 0")
        self.check(nscd + "fix wg wire wire/grain grains nu_p 0.5",
                   "fix wire/grain (id wg): value of 'nu_p' must be < 0.5")
        self.check(nscd + "fix wg wire wire/grain grains mu_s -0.1",
                   "fix wire/grain (id wg): value of 'mu_s' must be >= 0, got -0.1")
        self.check(nscd + "fix wg wire wire/grain grains mu_s 0.3 mu_d 0.4",
                   "fix wire/grain (id wg): mu_d (0.400000) must not exceed mu_s (0.300000)")
        self.check(nscd + "fix wg wire wire/grain grains max_stretch 0",
                   "fix wire/grain (id wg): value of 'max_stretch' must be > 0, got 0")
        self.check(nscd + "fix wg wire wire/grain grains skin -0.1",
                   "fix wire/grain (id wg): value of 'skin' must be >= 0, got -0.1")
        self.check(nscd + "fix wg wire wire/grain grains warm_geometry on",
                   "fix wire/grain (id wg): value of 'warm_geometry' must be yes or no, got 'on'")
        self.check(nscd + "fix wg wire wire/grain grains warm_geometry",
                   "fix wire/grain (id wg): missing value after 'warm_geometry'")
        self.check(nscd + "fix wg wire wire/grain grains stiffness 3",
                   "fix wire/grain (id wg): unknown keyword 'stiffness'; accepted: max_stretch, skin, warm_geometry, "
                   "E_w, nu_w, E_p, nu_p, mu_s, mu_d, restitution, damping_ratio, limit_force")
        self.check(nscd + "fix wg wire wire/grain grains mu_d",
                   "fix wire/grain (id wg): missing value after 'mu_d'")
        self.check(nscd + "fix wg wire wire/grain",
                   "fix wire/grain (id wg): expected the grain group after 'wire/grain'")
        self.check(nscd + "fix wg wire wire/grain pebbles",
                   "fix wire/grain (id wg): grain group 'pebbles' does not exist")

    def test_groups_and_the_nscd_fix(self):
        self.check("fix nscd grains nscd/polyhedra\nfix wg wire wire/grain wire",
                   "fix wire/grain (id wg): grain group 'wire' has no grains (polyhedra, or spheres of "
                   "atom_style sphere or granular, or superquadrics, in the hybrid)")
        self.check("fix nscd grains nscd/polyhedra\nfix wg grains wire/grain grains",
                   "fix wire/grain (id wg): wire group 'grains' has no wire beads")
        self.check("fix nscd grains nscd/polyhedra\nfix wg all wire/grain grains",
                   "fix wire/grain (id wg): wire group 'all' holds 1 grains (give the wire beads only)")
        self.check("fix wg wire wire/grain grains",
                   "fix wire/grain (id wg): needs a fix nscd/polyhedra that integrates all grains of group 'grains'")

    def test_nscd_time_step(self):
        self.check("timestep 1e-3\nfix nscd grains nscd/polyhedra timestep 2.5e-3",
                   "fix nscd/polyhedra (id nscd): value of 'timestep' (0.0025) must be an integer multiple of "
                   "the LIGGGHTS timestep (0.001)")
        self.check("timestep 1e-3\nfix nscd grains nscd/polyhedra timestep 5e-4",
                   "fix nscd/polyhedra (id nscd): value of 'timestep' (0.0005) must be an integer multiple of "
                   "the LIGGGHTS timestep (0.001)")
        self.check("fix nscd grains nscd/polyhedra every 2 timestep 2e-3",
                   "fix nscd/polyhedra (id nscd): give 'every' or 'timestep', not both")
        self.check("fix nscd grains nscd/polyhedra timestep -1",
                   "fix nscd/polyhedra (id nscd): value of 'timestep' must be > 0, got -1")

    def test_wall_fix(self):
        self.check("fix nscd grains nscd/polyhedra wall_fix floor",
                   "fix nscd/polyhedra (id nscd): wall_fix floor: no fix with this ID")
        self.check("fix g grains gravity 1 vector 0 0 -1\nfix nscd grains nscd/polyhedra wall_fix g",
                   "fix nscd/polyhedra (id nscd): wall_fix g: fix style is gravity, not wire/wall")
        self.check("fix floor wire wire/wall plane 0 0 0 0 0 1\n"
                   "fix nscd grains nscd/polyhedra wall_fix floor wall_velocity 1 0 0",
                   "fix nscd/polyhedra (id nscd): 'wall_velocity' does not apply to 'wall_fix floor' (the fix "
                   "moves the plane: fix_modify floor velocity ...)")
        self.check("fix floor wire wire/wall plane 0 0 0 0 0 1\nfix_modify floor velocity 1 0",
                   "fix_modify wire/wall (id floor): missing value after 'velocity'")

    def test_wrong_atom_style(self):
        text = """
units lj
atom_style wire
region box block -2 2 -2 2 -2 2
create_box 1 box
create_wire 1 line 0 0 0 1 0 0
fix wg all wire/grain all
"""
        self.assertStopsWith(run(text), "fix wire/grain (id wg): needs atom_style hybrid with wire and polyhedron "
                                        "(or sphere, granular, superquadric), not 'wire'")


def capstan_forces(X, ratio, rest, k_s, k_n, reach, mu, pull_in, pull_out):
    """Net force on each bead (N x 2) of a planar wire X (N x 2, its beads in order from the
    held end to the pulled one) over a circle of radius `reach` about the origin, every
    touching segment sliding towards the pulled end, by the law of
    docs/commands/fix_wire_elastic.md and fix_wire_grain.md (independently of the plugin):
    a spring k_s (|e| − rest) per segment e; a segment whose axis comes within `reach` of the
    centre is pushed out along the normal n by k_n ξ (ξ = reach − its distance) at its
    closest point t ∈ [0, 1] and held back by μ k_n ξ along the tangent there (the segment's
    direction), its beads taking (1 − t) and t of that force; the first bead pulled by
    `pull_in`, the last by ratio × `pull_out`. Returns the forces and which segments touch."""
    e = X[1:] - X[:-1]
    length = np.hypot(e[:, 0], e[:, 1])
    along = e / length[:, None]
    F = np.zeros_like(X)
    tension = (k_s * (length - rest))[:, None] * along
    F[:-1] += tension
    F[1:] -= tension
    t = np.clip(-np.einsum("ij,ij->i", X[:-1], e) / length ** 2, 0.0, 1.0)
    closest = X[:-1] + t[:, None] * e
    distance = np.hypot(closest[:, 0], closest[:, 1])
    normal = closest / distance[:, None]
    tangent = along - np.einsum("ij,ij->i", along, normal)[:, None] * normal
    tangent /= np.hypot(tangent[:, 0], tangent[:, 1])[:, None]
    touching = distance < reach
    push = np.where(touching, k_n * (reach - distance), 0.0)[:, None] * (normal - mu * tangent)
    F[:-1] += (1 - t)[:, None] * push
    F[1:] += t[:, None] * push
    F[0] += pull_in
    F[-1] += ratio * np.asarray(pull_out)
    return F, touching


def capstan_newton(X0, ratio0, gauge_bead, gauge_angle, law):
    """Newton's method on capstan_forces(**law) = 0 for the bead positions and T₂/T₁, with
    bead `gauge_bead` at the polar angle `gauge_angle`; the Jacobian by central differences,
    beads three apart perturbed together (a bead's force depends on its neighbours only);
    a least-squares step, halved until the residual falls."""
    n = len(X0)
    scale = float(np.max(np.abs(law["pull_in"])))

    def residual(u):
        X = u[:-1].reshape(n, 2)
        angle = math.atan2(X[gauge_bead, 1], X[gauge_bead, 0]) - gauge_angle
        return np.append(capstan_forces(X, u[-1], **law)[0].ravel(), scale * math.remainder(angle, 2 * math.pi))

    u = np.append(np.ravel(X0), ratio0)
    h = 1e-9
    for _ in range(400):
        r = residual(u)
        J = np.zeros((len(u), len(u)))
        for colour in range(3):
            beads = np.arange(colour, n, 3)
            for axis in range(2):
                du = np.zeros_like(u)
                du[2 * beads + axis] = h
                dr = (residual(u + du) - residual(u - du)) / (2 * h)
                for j in beads:
                    rows = np.r_[max(0, 2 * j - 2):min(2 * n, 2 * j + 4)]
                    J[rows, 2 * j + axis] = dr[rows]
                    if j == gauge_bead:
                        J[-1, 2 * j + axis] = dr[-1]
        du = np.zeros_like(u)
        du[-1] = h
        J[:, -1] = (residual(u + du) - residual(u - du)) / (2 * h)
        step = np.linalg.lstsq(J, -r, rcond=None)[0]
        norm, shrink = np.linalg.norm(r), 1.0
        while shrink > 1e-3 and np.linalg.norm(residual(u + shrink * step)) > (1 - 0.25 * shrink) * norm:
            shrink /= 2
        u = u + shrink * step
        if np.max(np.abs(step[:-1])) < 1e-14 and abs(step[-1]) < 1e-13 * abs(u[-1]):
            return u[-1], u[:-1].reshape(n, 2)
    raise AssertionError("the capstan's equilibrium did not converge")


def discrete_capstan(X0, ratio0, gauge_bead, gauge_angle, turn, **law):
    """The wire's equilibrium at gross slip, every contact on the Coulomb limit: T₂/T₁, the
    bead positions and the touching segments, with bead `gauge_bead` at the polar angle
    `gauge_angle` (the wire's place along the arc, which its discrete ends feel). From the
    unstretched polyline X0 (whose bead `gauge_bead` is placed there): first with the rest
    length shortened by T₁/k_s (a guess under tension: the unstretched legs have no lateral
    stiffness), then with the true one, then moved to `gauge_angle` in steps of an eighth of
    the arc's `turn` per bead."""
    start = math.atan2(X0[gauge_bead][1], X0[gauge_bead][0])
    tensioned = dict(law, rest=law["rest"] - float(np.max(np.abs(law["pull_in"]))) / law["k_s"])
    ratio, X = capstan_newton(X0, ratio0, gauge_bead, start, tensioned)
    ratio, X = capstan_newton(X, ratio, gauge_bead, start, law)
    steps = int(abs(math.remainder(gauge_angle - start, 2 * math.pi)) / (turn / 8)) + 1
    for j in range(1, steps + 1):
        angle = start + math.remainder(gauge_angle - start, 2 * math.pi) * j / steps
        ratio, X = capstan_newton(X, ratio, gauge_bead, angle, law)
    return ratio, X, capstan_forces(X, ratio, **law)[1]


class Capstan(DeckTestCase):
    """A wire (bending off, m_rot 0: the capstan's ideal string; no gravity) wrapped by θ
    over a fixed grain (a sphere of radius 1, or the rounded edge of a cube; 10⁶ times
    heavier than the wire), held by T₁ at one end while the other end's pull T₂ rises
    slowly: the whole arc slides (every contact on the Coulomb limit) at the capstan ratio.

    The discrete capstan. Each touching segment is pushed at its closest point to the grain,
    here its middle, by N along the normal (perpendicular to the segment) and, sliding
    towards the pulled end, held back by μN along the segment; each of its beads takes half.
    At a bead where the wire turns by φ from segment a (tension T_a) to b (T_b), with
    c = cos(φ/2), s = sin(φ/2), the balance along and across the bisector reads
        (T_b − T_a) c = ½ N_a (s + μc) − ½ N_b (s − μc),
        (T_a + T_b) s = ½ N_a (c − μs) + ½ N_b (c + μs).
    Along an arc turning by φ at every bead, T and N grow by one factor q per bead
    (T_b = q T_a, N_b = q N_a); eliminating N_a/T_a leaves q² − 2μ sin φ q − 1 = 0:
        q = μ sin φ + √(1 + μ² sin²φ) = exp(asinh(μ sin φ))
    (a string over sharp corners has (1 + μ tan(φ/2))/(1 − μ tan(φ/2)) instead), and a wire
    touching with K segments through θ = Kφ has T₂/T₁ = q^K = exp(K asinh(μ sin(θ/K))),
    e^{μθ} (1 − (1 + μ²) μθ φ²/6 + ...). The exact discrete ratio (the arc's ends, where a
    contact-free leg joins it; the stretch of the segments under T, which widens their turn;
    the overlaps) is that of the wire's static equilibrium with every contact on the limit,
    solved by Newton's method in discrete_capstan, at the wire's place along the arc that
    the run measured (the ratio moves within 5e-5 as the wire slides by a segment over the
    sphere, within 3e-3 over the edge's two segments). It is within 2.5e-5 of q^K on the
    sphere.

    The measurement. T₂/T₁ rises from 1 to 0.95 of the discrete ratio at the nominal place
    in 2 time units, then by 0.1 of it in 20 (0.005 of it per time unit); thermo every
    0.002. Gross slip is the first output from which every contact slides; the ratio is
    that of the tensions in the two leg segments next to the arc, k_s (l − l_0) from their
    lengths, so that the legs' damping and inertia drop out. Only the legs are damped (fix
    viscous): a drag on the arc's beads, which creep as the wire stretches, adds to friction.
    Measured on the half turn (Verlet at Δt_SP = 1e-3) against the discrete ratio, one
    setting changed at a time. Every bead damped (viscous 2e-4), the applied T₂/T₁ at the
    first output (every 0.01) with all contacts sliding, a ramp of 0.04 e^{μθ} per time
    unit from 0.8 e^{μθ}: +5.6e-3 (e^{μθ} +0.48 %); with the damping halved and quartered
    +2.8e-3 and +1.6e-3; the ramp 2 and 4 times slower +2.8e-3 and +1.4e-3; E_w × 2 and × 4
    (wire and contact) +3.1e-3 and +1.6e-3: the drag of the creeping wire, in proportion to
    damping × ramp rate / stiffness, goes to 0 (+4e-4 undamped, within the output's 4e-4
    steps). Undamped, though, the ramp's vibrations scatter the onset by ±6e-4. Legs damped,
    leg tensions, output every 0.01: +4.7e-4 and +9.6e-5 at 0.04 and 0.02 per time unit
    from 0.8; from 0.95, +2.0e-4, +8.5e-5 and −2e-6 at 0.01, 0.005 and 0.0025 (the
    tensions' ratio goes on rising after the onset, up to the next output); at 0.005 with
    output every 0.002 (these tests): −1.1e-6 to +4.4e-5; Gear-5 at Table 1's Δt_SP = 1e-4
    +3.8e-5 and Verlet at 5e-4 +6.5e-5 (output every 0.01). The tests' errors are below
    4.5e-5 (each test's comment); held to 2e-4. A case takes 5 to 7 s (1 to 4 s of loop time)."""

    WIRE_RADIUS = 0.02
    LEG = 10          # segments per straight leg
    T1 = 1e-3
    E_W, E_P, NU_P = 100.0, 1000.0, 0.3   # Table 1, written into the deck
    VISCOUS = 2e-4    # on the legs' beads
    EVERY = 0.002     # thermo, time units
    TOLERANCE = 2e-4  # the measured errors: each test's comment

    def arc_polyline(self, wrap, reach, k, start):
        """Beads on an arc about the origin at ρ_b = ρ / cos(β/2), β = θ/k, so that each of
        the k chords touches the circle ρ (= reach) at its middle, starting at the polar
        angle `start` and turning clockwise; legs of LEG chords tangent to the arc's ends."""
        beta = wrap / k
        rho_b = reach / np.cos(beta / 2)
        chord = 2 * rho_b * np.sin(beta / 2)
        arc = [(rho_b * np.cos(start - j * beta), rho_b * np.sin(start - j * beta)) for j in range(k + 1)]
        t_in = np.array([np.sin(start), -np.cos(start)])             # into the arc at its start
        end = start - k * beta
        t_out = np.array([np.sin(end), -np.cos(end)])                # along the arc at its end
        first = [arc[0] - j * chord * t_in for j in range(self.LEG, 0, -1)]
        last = [arc[-1] + j * chord * t_out for j in range(1, self.LEG + 1)]
        return np.array(first + [np.array(p) for p in arc] + last), chord, t_in, t_out

    def make_scene(self, grain, shape, sweep, polyline, chord):
        """The grain (atom 1, group grains) at the pose `grain` and the wire (atoms 2...,
        group wire) through `polyline`, as a data file; returns the run that wrote it."""
        return scene([grain], [f"polyline wire.txt segment {chord!r} radius {self.WIRE_RADIUS}"], shape=shape,
                     sweep=sweep, density=1e6, box=(-3, 3, -3, 3, -3, 3), files={"wire.txt": polyline})

    def make_deck(self, body):
        """The deck that reads the scene and runs `body` (which defines fix wg)."""
        return deck("fix             nscd grains nscd/polyhedra\n" + body)

    def slip(self, grain, shape, sweep, centre, reach, wrap, k, start, mu, timestep=1e-3, scheme="verlet"):
        """Wrap the wire over `grain` (pose; its contact circle of radius `reach` about
        `centre` in the xz plane), raise T₂ and return the measured and the discrete T₂/T₁
        at gross slip with what goes with them."""
        points, chord, t_in, t_out = self.arc_polyline(wrap, reach, k, start)
        r_w, t1 = self.WIRE_RADIUS, self.T1
        e_wp = 1.0 / (1.0 / self.E_W + (1 - self.NU_P ** 2) / self.E_P)
        law = dict(rest=chord, k_s=self.E_W * math.pi * r_w ** 2 / chord, k_n=math.pi / 4 * e_wp * chord,
                   reach=reach, mu=mu, pull_in=-t1 * t_in, pull_out=t1 * t_out)
        gauge = self.LEG + k // 2              # the arc's middle bead (index in points; atom gauge + 2)
        nominal, _, _ = discrete_capstan(points, math.exp(mu * wrap), gauge,
                                         math.atan2(points[gauge][1], points[gauge][0]), wrap / k, **law)
        # (half a chord more at the end: create_wire lays a node where the polyline reaches
        # l_w from the last one, which round-off may put just beyond the polyline's end)
        beyond = np.vstack([points, points[-1] + 0.5 * chord * t_out])
        polyline = "\n".join(f"{x + centre[0]!r} 0.0 {z + centre[1]!r}" for x, z in beyond) + "\n"
        made = self.make_scene(grain, shape, sweep, polyline, chord)
        settle, ramp = 2.0, 20.0
        low, rise = 0.95 * nominal, 0.1 * nominal / ramp
        steps = [int(round(t / timestep)) for t in (settle, ramp, self.EVERY)]
        last = len(points) + 1
        r = run(self.make_deck(f"""
group           pulled1 id 2
group           pulled2 id {last}
group           legs id 2:{self.LEG + 1} {self.LEG + k + 2}:{last}
group           middle id {gauge + 2}
group           leg_in id {self.LEG + 1}
group           leg_out id {self.LEG + k + 2}
fix             elastic wire wire/elastic m_rot 0 E {self.E_W}
fix             integr wire nve/gear scheme {scheme}
fix             wg wire wire/grain grains mu_s {mu} mu_d {mu} E_w {self.E_W} nu_w 0 E_p {self.E_P} nu_p {self.NU_P}
fix             calm legs viscous {self.VISCOUS}
timestep        {timestep!r}
variable        ratio equal 1.0+{(low - 1.0) / settle!r}*step*dt
variable        f1x equal {-t1 * t_in[0]!r}
variable        f1z equal {-t1 * t_in[1]!r}
variable        f2x equal {t1 * t_out[0]!r}*v_ratio
variable        f2z equal {t1 * t_out[1]!r}*v_ratio
fix             hold pulled1 addforce v_f1x 0.0 v_f1z
fix             pull pulled2 addforce v_f2x 0.0 v_f2z
compute         xm middle reduce max x
compute         zm middle reduce max z
compute         l_in leg_in reduce max f_elastic[3]
compute         l_out leg_out reduce max f_elastic[3]
thermo_style    custom step v_ratio f_wg[1] f_wg[8] c_xm c_zm c_l_in c_l_out
thermo_modify   format float %.15g
thermo          {steps[2]}
run             {steps[0]}
variable        ratio equal {low!r}+{rise!r}*(step*dt-{settle!r})
run             {steps[1]}
"""), workdir=made.workdir)
        self.assertRanCleanly(r)
        self.last_output = r.output  # for the benchmark's loop times
        self.assertIn(f"\n{len(points)} atoms in group wire\n", r.output)
        t = r.thermo()
        contacts, sliding = t["wg[1]"], t["wg[8]"]
        # gross slip: from here to the end every contact slides (the settling slid too, as
        # the loaded wire stretched over the grain)
        sticking = np.nonzero(sliding < contacts)[0]
        self.assertTrue(len(sticking) and sticking[-1] + 1 < len(sliding), "no gross slip")
        onset = sticking[-1] + 1
        measured = (t["l_out"][onset] - chord) / (t["l_in"][onset] - chord)
        place = math.atan2(t["zm"][onset] - centre[1], t["xm"][onset] - centre[0])
        discrete, _, touching = discrete_capstan(points, nominal, gauge, place, wrap / k, **law)
        beta = wrap / k
        closed_form = (mu * math.sin(beta) + math.sqrt(1 + (mu * math.sin(beta)) ** 2)) ** k
        target = math.exp(mu * wrap)
        print(f"\ncapstan θ = {wrap:.4f} over {k} segments, μ = {mu}: all {contacts[onset]:.0f} contacts slide at "
              f"T2/T1 = {measured:.7f} (leg tensions; applied {t['ratio'][onset]:.7f}); the discrete capstan "
              f"{discrete:.7f} ({measured / discrete - 1:+.2e}; {touching.sum()} contacts; {nominal:.7f} at the "
              f"nominal place), q^K {closed_form:.7f} ({discrete / closed_form - 1:+.2e}), e^(μθ) {target:.7f} "
              f"({discrete / target - 1:+.2e})")
        return dict(measured=measured, discrete=discrete, closed_form=closed_form, target=target,
                    contacts=contacts[onset], touching=touching.sum(), applied=t["ratio"][onset])

    def sphere(self, wrap, mu, timestep=1e-3, scheme="verlet"):
        """Over the sphere of radius 1 at the origin, 64 segments per π of arc, the arc
        starting at the top (quarter turn) or at the side (half turn)."""
        k = int(round(wrap / (np.pi / 64)))
        return self.slip((0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0), "sphere 1.0", None, (0.0, 0.0),
                         1.0 + self.WIRE_RADIUS, wrap, k, np.pi if wrap > 2 else np.pi / 2, mu, timestep, scheme)

    def check(self, result, closed_form_within):
        self.assertAlmostEqual(result["measured"] / result["discrete"], 1.0, delta=self.TOLERANCE)
        self.assertEqual(result["contacts"], result["touching"])
        self.assertAlmostEqual(result["discrete"] / result["closed_form"], 1.0, delta=closed_form_within)

    def test_half_turn(self):
        # measured +4.4e-5 (63 contacts); q^K off the discrete ratio by +2.2e-5, e^{μθ} by +8.1e-4
        self.check(self.sphere(np.pi, 0.5), 5e-5)

    def test_quarter_turn(self):
        # μ = 0.2: measured +3.5e-5 (32 contacts); q^K off the discrete ratio by −1.0e-5,
        # e^{μθ} by +1.2e-4
        self.check(self.sphere(np.pi / 2, 0.2), 5e-5)

    def test_over_a_cube_edge(self):
        # a cube (edge 1, sweep 0.1) turned by 45° about y, so that an edge lies along y at
        # its top; the wire crosses the edge's middle in the xz plane, turning by θ = π/3
        # around its rounded edge (a circle of radius r_p + r_w = 0.12 about the edge, the
        # faces at 45° below the horizontal, the legs at 30°: they touch no face) with two
        # segments of 0.064; μ = 0.3. The discrete ratio is 1.5 % below e^{μθ}.
        edge = 1.0
        top = edge / math.sqrt(2)
        result = self.slip((0.0, 0.0, 0.0, math.cos(math.pi / 8), 0.0, math.sin(math.pi / 8), 0.0),
                           f"cube {edge}", 0.1, (0.0, top), 0.1 + self.WIRE_RADIUS, np.pi / 3, 2,
                           np.pi / 2 + np.pi / 6, 0.3)
        # measured +8.6e-6 (2 contacts); q^K off the discrete ratio by −2.2e-4 (the ends, at
        # the measured place; −2.0e-3 to +1.1e-3 as the wire slides by a segment)
        self.check(result, 1e-3)
        self.assertLess(result["measured"] / result["target"], 1 - 10 * self.TOLERANCE)


class ContainerWalls(DeckTestCase):
    """One plane for grains and wire: fix wire/wall, used by fix nscd/polyhedra through
    wall_fix."""

    def test_a_cube_rests_on_a_wire_wall_floor_and_is_pushed_by_a_moving_one(self):
        # a cube (edge 2, sweep 0.1, mass m) on the floor z = 0, the side wall x = -3
        # standing still for 100 steps, then moving at +0.5 (fix_modify velocity) for 4000
        # steps of 1e-3: it reaches the cube's face (x = -1.1) at t = 3.8 and pushes it,
        # so at the end the face is at the wall, -3 + 0.5·4 = -1.0, within one NSCD step
        # of travel; the floor carries m g all along (frictionless floor for the grain)
        made = scene([resting_cube(0, 0)], ["line -0.5 2.0 0.3 0.5 2.0 0.3 segment 0.5 radius 0.1"])
        r = run(full_precision(deck(f"""
fix             g grains gravity {G} vector 0 0 -1
fix             floor wire wire/wall plane 0 0 0 0 0 1
fix             side wire wire/wall plane -3 0 0 1 0 0 mu_s 0 mu_d 0
fix             nscd grains nscd/polyhedra wall_fix floor wall_friction 0 wall_fix side wall_friction 0
timestep        1e-3
compute         xg grains reduce max x
thermo_style    custom step c_xg f_nscd[9]
thermo_modify   format float %.15g
thermo          100
run             100
fix_modify      side velocity 0.5 0 0
dump            d grains custom 4100 dump.g id mass x z
run             4000
"""), "d"), workdir=made.workdir)
        self.assertRanCleanly(r)
        t = r.thermo()
        d = read_dump(r.path("dump.g"))
        m = d["mass"][0]
        face = d["x"][0] - 1.1
        print(f"\ncontainer walls: cube face at {face:.9f} (wall at -1.0), floor force {-t['nscd[9]'][-1]:.12g} "
              f"(m g = {m * G:.12g}), height {d['z'][0]:.12g}")
        self.assertAlmostEqual(face, -1.0, delta=0.5 * 1e-3 + 1e-9)
        self.assertAlmostEqual(-t["nscd[9]"][-1] / (m * G), 1.0, delta=1e-7)  # NSCD tolerance 1e-4 (relative)
        self.assertAlmostEqual(d["z"][0], 1.1, delta=1e-9)


if __name__ == "__main__":
    main()
