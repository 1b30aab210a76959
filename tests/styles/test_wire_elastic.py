"""The elastic wire (atom_style wire, create_wire, fix wire/elastic, fix nve/gear)
against beam theory, wave propagation, the catenary, and its error messages."""

import math
import os

import numpy as np

from liggghts_run import DeckTestCase, main, read_dump, run

HEADER = """
units           lj
atom_style      wire
boundary        f f f
region          box block -30 30 -30 30 -30 30
create_box      1 box
"""


def data_file(positions, rest, radius, mass, box=30.0):
    """A LIGGGHTS data file of one open chain through `positions` (N x 3)."""
    n = len(positions)
    lines = ["wire chain written by test_wire_elastic.py", "", f"{n} atoms", "1 atom types",
             f"{-box} {box} xlo xhi", f"{-box} {box} ylo yhi", f"{-box} {box} zlo zhi", "",
             "Atoms", ""]
    for k, (x, y, z) in enumerate(positions):
        prev = k if k > 0 else 0
        nxt = k + 2 if k + 1 < n else 0
        r = rest if k + 1 < n else 0.0
        lines.append(f"{k + 1} 1 {prev} {nxt} {r!r} {radius!r} {mass!r} {x!r} {y!r} {z!r}")
    return "\n".join(lines) + "\n"


def bead_mass(density, radius, length):
    return density * math.pi * radius ** 2 * length


def chain_step_deck(E, m_elo, columns, formats):
    """A deck that reads chain.data under fix wire/elastic (id el) and dumps `columns` of
    its beads, sorted by id, once (run 0) to dump.f."""
    return f"""
units lj
atom_style wire
boundary f f f
read_data chain.data
fix el all wire/elastic E {E} m_elo {m_elo} m_rot 0.1
dump d all custom 1 dump.f {columns}
dump_modify d sort id format "{formats}"
run 0
"""


class AxialStretch(DeckTestCase):
    # A straight chain stretched uniformly by strain eps: the end beads feel the tension
    # m_elo E A eps, inner beads nothing.
    def test_force_extension(self):
        for m_elo in (1.0, 0.3):
            eps, E, r, l, n = 1e-3, 100.0, 0.1, 0.2, 10
            pos = [(k * l * (1 + eps), 0.0, 0.0) for k in range(n + 1)]
            deck = chain_step_deck(E, m_elo, "id x fx fy fz", "%d %.17g %.17g %.17g %.17g")
            res = run(deck, files={"chain.data": data_file(pos, l, r, 1.0)})
            self.assertRanCleanly(res)
            d = read_dump(res.path("dump.f"))
            tension = m_elo * E * math.pi * r * r * eps
            self.assertAlmostEqual(d["fx"][0] / tension, 1.0, delta=1e-10)
            self.assertAlmostEqual(d["fx"][-1] / tension, -1.0, delta=1e-10)
            self.assertLess(np.max(np.abs(d["fx"][1:-1])), 1e-10 * tension)

    # Each segment stretched by its own strain eps_k carries the tension m_elo E A eps_k
    # (compressed: negative), written with its first bead as the per-atom f_ID[4], next to
    # its length f_ID[3]; the last bead has no segment (0, 0). On 2 ranks the same.
    def test_tension_per_segment(self):
        E, r, l, m_elo = 100.0, 0.1, 0.2, 0.7
        strains = [1e-3, -2e-3, 5e-3, 0.0, 3e-2, -1e-2, 2e-3, 4e-3]
        xs = np.concatenate([[0.0], np.cumsum([l * (1 + e) for e in strains])])
        pos = [(x - xs[-1] / 2, 0.0, 0.0) for x in xs]
        deck = chain_step_deck(E, m_elo, "id f_el[3] f_el[4]", "%d %.17g %.17g")
        tension = [m_elo * E * math.pi * r * r * e for e in strains] + [0.0]
        length = [l * (1 + e) for e in strains] + [0.0]
        for ranks in (1, 2):
            res = run(deck, files={"chain.data": data_file(pos, l, r, 1.0)}, np_ranks=ranks)
            self.assertRanCleanly(res)
            d = read_dump(res.path("dump.f"))
            np.testing.assert_allclose(d["f_el[4]"], tension, rtol=0, atol=1e-12 * max(map(abs, tension)))
            np.testing.assert_allclose(d["f_el[3]"], length, rtol=0, atol=1e-14)


def relax_run(deck, files, free_group, damping, dt, t_end, scheme="verlet"):
    """Integrate `free_group` with viscous damping until t_end; returns the run."""
    steps = int(round(t_end / dt))
    text = deck + f"""
fix int {free_group} nve/gear scheme {scheme}
fix damp {free_group} viscous {damping!r}
timestep {dt!r}
dump d all custom {steps} dump.relax id x y z vx vy vz fx fy
dump_modify d format "%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g"
thermo {max(steps // 10, 1)}
run {steps}
"""
    return run(text, files=files)


def chain_forces(X, rest, k_s, kappa, load):
    """Forces on the beads of a planar chain (X: N x 2), independently of the plugin: the
    axial springs U = ½ k_s (|e| − rest)² of its segments e, the bends U = ½ κ θ² at its
    inner beads (θ the signed angle from e_a = x_j − x_{j−1} to e_b = x_{j+1} − x_j,
    θ = atan2(c, d), c = e_a × e_b, d = e_a · e_b: the law of docs/commands/fix_wire_elastic.md
    in the plane), and the external `load` (N x 2). F = −∇U, with
    ∂θ/∂e_a = (d (e_b,y, −e_b,x) − c e_b)/(c² + d²), ∂θ/∂e_b = (d (−e_a,y, e_a,x) − c e_a)/(c² + d²)."""
    e = X[1:] - X[:-1]
    length = np.hypot(e[:, 0], e[:, 1])
    tension = (k_s * (length - rest) / length)[:, None] * e
    F = np.array(load, dtype=float)
    F[:-1] += tension
    F[1:] -= tension
    if np.any(kappa):
        a, b = e[:-1], e[1:]
        c = a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]
        d = a[:, 0] * b[:, 0] + a[:, 1] * b[:, 1]
        w = (kappa * np.arctan2(c, d) / (c * c + d * d))[:, None]
        grad_a = w * (d[:, None] * np.stack([b[:, 1], -b[:, 0]], 1) - c[:, None] * b)   # ∂U/∂e_a
        grad_b = w * (d[:, None] * np.stack([-a[:, 1], a[:, 0]], 1) - c[:, None] * a)   # ∂U/∂e_b
        F[:-2] += grad_a
        F[1:-1] -= grad_a - grad_b
        F[2:] -= grad_b
    return F


def chain_equilibrium(X0, free, forces, reach):
    """The static equilibrium of the beads `free` (boolean mask) of a planar chain from the
    guess X0 (N x 2), the others held: Newton's method on forces(X) = 0, the Jacobian by
    central differences (the force on a bead depends on the beads within `reach` of it only,
    so beads 2 reach + 1 apart are perturbed together); stops when the step is below 1e-15
    of the chain's size (round-off)."""
    X = np.array(X0, dtype=float)
    idx = np.flatnonzero(free)
    n = len(idx)
    size = np.max(np.abs(X))
    h = 1e-7 * size
    for _ in range(50):
        F = forces(X)[idx].ravel()
        J = np.zeros((2 * n, 2 * n))
        for colour in range(2 * reach + 1):
            together = np.arange(colour, n, 2 * reach + 1)
            for axis in range(2):
                D = np.zeros_like(X)
                D[idx[together], axis] = h
                dF = (forces(X + D)[idx] - forces(X - D)[idx]).ravel() / (2 * h)
                for k in together:
                    rows = slice(max(0, 2 * (k - reach)), min(2 * n, 2 * (k + reach + 1)))
                    J[rows, 2 * k + axis] = dF[rows]
        step = np.linalg.solve(J, -F)
        X[idx] += step.reshape(n, 2)
        if np.max(np.abs(step)) < 1e-15 * size:
            return X
    raise AssertionError("the chain's equilibrium did not converge")


class Cantilever(DeckTestCase):
    # Tip load P on a cantilever of N free segments (two clamped beads set the root
    # slope). Continuum: PL^3/3EI. Discrete chain, small deflections: the moment P(L - x_j)
    # at node j bends it by θ_j = M_j l/EI (U = ½ κ θ², κ = EI/l), so
    # δ = P l^3/EI Σ k² = PL^3/3EI (1 + 3/(2N) + 1/(2N²)). Exactly: the chain's static
    # equilibrium (chain_equilibrium), which the run reaches to 2.2e-11 of δ at N = 10 and
    # 5e-13 at N = 20..80 (the damped relaxation's rest); held to 1e-10 (δ and every bead).
    E, r, rho, length = 1.0e4, 0.02, 1.0, 1.0

    def deflection(self, n):
        E, r, rho, L = self.E, self.r, self.rho, self.length
        l = L / n
        EI = E * math.pi * r ** 4 / 4
        load = 3 * EI * 0.005 * L / L ** 3           # continuum tip deflection 0.005 L
        pos = [((k - 1) * l, 0.0, 0.0) for k in range(n + 2)]
        mass = bead_mass(rho, r, l)
        omega1 = 3.516 * math.sqrt(EI / (rho * math.pi * r * r * L ** 4))
        deck = f"""
units lj
atom_style wire
boundary f f f
read_data chain.data
group clamp id 1 2
group free subtract all clamp
group tip id {n + 2}
fix el all wire/elastic E {E} m_elo 1 m_rot 1
fix load tip addforce 0.0 {-load!r} 0.0
"""
        k_ax = 2 * math.sqrt(E / rho) / l
        k_b = 4 * math.sqrt(EI / (rho * math.pi * r * r)) / l ** 2
        dt = 0.5 * 2 / math.hypot(k_ax, k_b)
        res = relax_run(deck, {"chain.data": data_file(pos, l, r, mass)}, "free",
                        damping=2 * omega1 * mass, dt=dt, t_end=16.0)
        self.assertRanCleanly(res)
        d = read_dump(res.path("dump.relax"))
        # at rest: residual motion below 1e-6 of the deflection per unit time 1/ω1
        self.assertLess(np.max(np.abs(d["vy"])), 1e-6 * 0.005 * L * omega1)
        # the chain's exact equilibrium (finite rotations and the stretch included): n bends
        # at the beads 2..n+1 of κ = EI/l, springs k_s = EA/l, the two root beads held
        tip = np.zeros((n + 2, 2))
        tip[-1, 1] = -load
        chain = chain_equilibrium(np.array(pos)[:, :2], np.arange(n + 2) >= 2,
                                  lambda X: chain_forces(X, l, E * math.pi * r * r / l, np.full(n, EI / l), tip),
                                  reach=2)
        shape = np.max(np.hypot(d["x"] - chain[:, 0], d["y"] - chain[:, 1]))
        return -d["y"][-1], load * L ** 3 / (3 * EI), -chain[-1, 1], shape

    def test_tip_deflection_converges_first_order(self):
        errors = {}
        for n in (10, 20, 40, 80):
            delta, continuum, exact, shape = self.deflection(n)
            discrete = continuum * (1 + 1.5 / n + 0.5 / n ** 2)
            errors[n] = delta / continuum - 1
            print(f"cantilever N={n}: tip deflection {delta:.10e}, the chain's equilibrium {exact:.10e} "
                  f"({delta / exact - 1:+.2e}; bead positions off it by {shape / exact:.1e} of the deflection), "
                  f"the small-deflection formula {discrete:.10e} ({exact / discrete - 1:+.2e} from it), "
                  f"PL^3/3EI {continuum:.6e} (relative error {errors[n]:.4%})")
            self.assertAlmostEqual(delta / exact, 1.0, delta=1e-10)
            self.assertLess(shape / exact, 1e-10)
            # the finite rotations (tip slope 0.0075) take −2.6e-5 to −3.1e-5 off the linear answer
            self.assertAlmostEqual(exact / discrete, 1.0, delta=5e-5)
        orders = [math.log2(errors[n] / errors[2 * n]) for n in (10, 20, 40)]
        print("observed orders", ", ".join(f"{o:.3f}" for o in orders))
        for o in orders:
            self.assertAlmostEqual(o, 1.0, delta=0.1)
        self.assertLess(abs(errors[80]), 0.02)


class Buckling(DeckTestCase):
    # Pinned–pinned chain of N segments under an end load P. The discrete critical load is
    # P_cr = (4EI/l²) sin²(π/2N): below it a lateral perturbation stays small, above it grows.
    E, r, rho, length, n = 1.0e4, 0.02, 1.0, 1.0, 20

    def lateral_growth(self, load_factor):
        E, r, rho, L, n = self.E, self.r, self.rho, self.length, self.n
        l = L / n
        EI = E * math.pi * r ** 4 / 4
        EA = E * math.pi * r * r
        p_cr = 4 * EI / l ** 2 * math.sin(math.pi / (2 * n)) ** 2
        load = load_factor * p_cr
        strain = load / EA                         # start in axial equilibrium
        amplitude = 1e-6 * L
        pos = [(k * l * (1 - strain), amplitude * math.sin(math.pi * k / n), 0.0)
               for k in range(n + 1)]
        mass = bead_mass(rho, r, l)
        deck = f"""
units lj
atom_style wire
boundary f f f
read_data chain.data
group pin id 1
group roller id {n + 1}
group free subtract all pin
fix el all wire/elastic E {E} m_elo 1 m_rot 1
fix guide roller setforce NULL 0.0 0.0
fix load roller addforce {-load!r} 0.0 0.0
"""
        k_ax = 2 * math.sqrt(E / rho) / l
        k_b = 4 * math.sqrt(EI / (rho * math.pi * r * r)) / l ** 2
        dt = 0.5 * 2 / math.hypot(k_ax, k_b)
        res = relax_run(deck, {"chain.data": data_file(pos, l, r, mass)}, "free",
                        damping=1.0 * mass, dt=dt, t_end=20.0)
        self.assertRanCleanly(res)
        d = read_dump(res.path("dump.relax"))
        return np.max(np.abs(d["y"])) / amplitude

    def test_critical_load_within_one_percent(self):
        below, above = self.lateral_growth(0.99), self.lateral_growth(1.01)
        print(f"lateral amplitude after t=20: {below:.3g} x initial at 0.99 P_cr, "
              f"{above:.3g} x initial at 1.01 P_cr")
        self.assertLess(below, 1.0)
        self.assertGreater(above, 100.0)


class AxialWave(DeckTestCase):
    # A Gaussian axial displacement splits into two pulses moving at c = sqrt(E/rho), less
    # the bead chain's dispersion: mode k travels at the group velocity c cos(k l/2), and the
    # pulse's energy (∝ k² exp(−k² w²/2), w the Gaussian's width) moves at the weighted mean
    # c (1 − l²⟨k⁴⟩/(8⟨k²⟩)) = c (1 − 3 l²/(8 w²)) to O(l⁴). Exactly, the chain of N + 1
    # equal beads m joined by springs k_s = E A/l with free ends has the modes
    # cos(π p (j + ½)/(N + 1)) at ω_p = 2 sqrt(k_s/m) sin(π p/(2(N + 1))), p = 0..N (its
    # discrete dispersion relation): the bead velocities at t_end from them are the
    # reference for the deck's, and the pulse speed measured on them for the deck's.
    def test_wave_speed(self):
        E, rho, r, l, n = 100.0, 1.0, 0.1, 0.05, 400
        c = math.sqrt(E / rho)
        x0, width, u0 = 10.0, 1.0, 1e-4
        rest = np.arange(n + 1) * l
        u_start = u0 * np.exp(-((rest - x0) / width) ** 2)
        pos = [(k * l + u_start[k], 0.0, 0.0) for k in range(n + 1)]
        t_end, dt = 0.5, 1e-4
        mass = bead_mass(rho, r, l)
        deck = f"""
units lj
atom_style wire
boundary f f f
read_data chain.data
fix el all wire/elastic E {E} m_elo 1 m_rot 0
fix int all nve/gear
timestep {dt}
dump d all custom {int(round(t_end / dt))} dump.w id x vx
dump_modify d format "%d %.17g %.17g"
run {int(round(t_end / dt))}
"""
        res = run(deck, files={"chain.data": data_file(pos, l, r, mass)})
        self.assertRanCleanly(res)
        d = read_dump(res.path("dump.w"))
        np.testing.assert_array_equal(d["id"], np.arange(1, n + 2))

        def pulse_speed(vx):
            right = rest > x0
            w = vx[right] ** 2
            return (np.sum(rest[right] * w) / np.sum(w) - x0) / t_end

        # the exact motion of the chain, started at rest: u(t) = Σ_p a_p cos(ω_p t) φ_p
        j, p = np.arange(n + 1), np.arange(n + 1)
        modes = np.cos(np.pi * np.outer(j + 0.5, p) / (n + 1))
        modes /= np.linalg.norm(modes, axis=0)
        omega = 2 * math.sqrt(E * math.pi * r * r / l / mass) * np.sin(np.pi * p / (2 * (n + 1)))
        v_chain = -modes @ ((modes.T @ u_start) * omega * np.sin(omega * t_end))
        speed, chain = pulse_speed(d["vx"]), pulse_speed(v_chain)
        continuum = c * (1 - 3 * l ** 2 / (8 * width ** 2))
        field = np.max(np.abs(d["vx"] - v_chain)) / np.max(np.abs(v_chain))
        print(f"axial pulse speed {speed:.12f}, the chain's exact {chain:.12f} (error {speed / chain - 1:.1e}); "
              f"velocities off the chain's by {field:.1e} of the largest; sqrt(E/rho) = {c:.5f}, with the leading "
              f"dispersion term {continuum:.7f} (the chain's exact speed off it by {chain / continuum - 1:.2e})")
        # measured 1.4e-11: Gear's time error and round-off; the velocities 1.1e-7, the
        # round-off of positions x ~ 10 against displacements of 1e-4 (it grows when dt is
        # halved, as round-off does)
        self.assertAlmostEqual(speed / chain, 1.0, delta=1e-10)
        self.assertLess(field, 5e-7)
        # the O(l⁴) terms left out of c (1 − 3 l²/(8 w²)): 6.35e-7
        self.assertAlmostEqual(chain / continuum, 1.0, delta=2e-6)


class Catenary(DeckTestCase):
    # A flexible (m_rot = 0), nearly inextensible chain hanging between two fixed points
    # at distance S comes to rest with about the sag of the catenary of its length L:
    # L = 2a sinh(S/2a), sag = a (cosh(S/2a) - 1); exactly, in the static equilibrium of its
    # 23 free beads on their springs (chain_equilibrium), 1.29e-3 lower. The run reaches that
    # equilibrium to 2.1e-12 of the sag (every bead) and the pulls on the held ends to
    # 6.5e-11 of the largest (the damped relaxation's rest, e^-25 after 25 time units);
    # held to 1e-11 and 3e-10. The vertical pulls add up to the free beads' weight.
    def test_sag(self):
        E, rho, r, l = 1.0e4, 1.0, 0.05, 0.1
        arm, span = 12, 2.0
        h = math.sqrt((arm * l) ** 2 - (span / 2) ** 2)
        pos = [(-1.0 + k * (span / 2) / arm, -h * k / arm, 0.0) for k in range(arm + 1)]
        pos += [(k * (span / 2) / arm, -h * (arm - k) / arm, 0.0) for k in range(1, arm + 1)]
        length = 2 * arm * l
        lo, hi = 0.1, 100.0                       # solve L = 2a sinh(S/2a) for a
        for _ in range(200):
            a = 0.5 * (lo + hi)
            if 2 * a * math.sinh(span / (2 * a)) > length:
                lo = a
            else:
                hi = a
        sag = a * (math.cosh(span / (2 * a)) - 1)
        mass = bead_mass(rho, r, l)
        deck = f"""
units lj
atom_style wire
boundary f f f
read_data chain.data
group ends id 1 {2 * arm + 1}
group free subtract all ends
fix el all wire/elastic E {E} m_elo 1 m_rot 0
fix g free gravity 1.0 vector 0 -1 0
"""
        res = relax_run(deck, {"chain.data": data_file(pos, l, r, mass)}, "free",
                        damping=2.0 * mass, dt=2e-4, t_end=25.0)
        self.assertRanCleanly(res)
        d = read_dump(res.path("dump.relax"))
        measured = -np.min(d["y"])
        # the chain's own equilibrium: 23 free beads of weight m g on springs k_s = EA/l,
        # from the continuous catenary stretched a little (a guess with tension)
        n = 2 * arm
        s = np.linspace(-arm * l, arm * l, n + 1)
        x = a * np.arcsinh(s / a)
        guess = np.stack([x, a * np.cosh(x / a) - a * math.cosh(span / (2 * a))], 1)
        guess[[0, -1]] = [(-span / 2, 0.0), (span / 2, 0.0)]
        weight = np.zeros((n + 1, 2))
        weight[1:-1, 1] = -mass * 1.0
        k_s = E * math.pi * r * r / l
        chain = chain_equilibrium(guess, np.arange(n + 1) % n != 0,
                                  lambda X: chain_forces(X, l, k_s, np.zeros(n - 1), weight), reach=1)
        pull = chain_forces(chain, l, k_s, np.zeros(n - 1), np.zeros((n + 1, 2)))[[0, -1]]
        sag_chain = -np.min(chain[:, 1])
        shape = np.max(np.hypot(d["x"] - chain[:, 0], d["y"] - chain[:, 1]))
        ends = np.stack([d["fx"][[0, -1]], d["fy"][[0, -1]]], 1)
        print(f"catenary sag {measured:.12f}, the chain's equilibrium {sag_chain:.12f} ({measured / sag_chain - 1:+.2e}; "
              f"bead positions off it by {shape / sag_chain:.1e} of the sag), continuous catenary {sag:.12f} "
              f"(the chain's off it by {sag_chain / sag - 1:+.2e}); pull on the ends {ends.tolist()}, the chain's "
              f"{pull.tolist()} (largest difference {np.max(np.abs(ends - pull)) / np.max(np.abs(pull)):.1e}), "
              f"their vertical sum over the weight {ends[:, 1].sum() / np.sum(weight[:, 1]) - 1:+.1e} + 1")
        self.assertLess(np.max(np.abs(d["vy"])), 1e-8)
        self.assertAlmostEqual(measured / sag_chain, 1.0, delta=1e-11)
        self.assertLess(shape / sag_chain, 1e-11)
        np.testing.assert_allclose(ends, pull, rtol=0, atol=3e-10 * np.max(np.abs(pull)))
        # the ends carry the weight of the free beads (the balance of the whole chain)
        self.assertAlmostEqual(ends[:, 1].sum() / np.sum(weight[:, 1]), 1.0, delta=3e-10)
        # the discrete, slightly stretched chain hangs 1.29e-3 lower than the continuous catenary
        self.assertAlmostEqual(sag_chain / sag, 1.0, delta=2e-3)


class EnergyConservation(DeckTestCase):
    """An undamped free loop: the drift of kinetic + elastic energy over t = 100 (1e5 steps
    at dt = 1e-3) for both schemes at two time steps. Started from rest with displaced beads (jerk 0 at t = 0,
    as in a deposition) and started with velocities (the Gear history then starts with an
    unknown jerk, which leaves an O(dt^2) velocity error)."""

    START = {
        "rest": """
variable        dx atom x+0.01*sin(7.0*y)
variable        dz atom z+0.01*cos(5.0*x)
set             group all x v_dx z v_dz
""",
        "moving": """
variable        vx0 atom 0.3*sin(3.1*y)
variable        vy0 atom 0.3*cos(2.3*x)
variable        vz0 atom 0.2*sin(1.7*x+0.4*y)
set             group all vx v_vx0 vy v_vy0 vz v_vz0
""",
    }

    def energy_error(self, scheme, dt, start, t_end=100.0):
        steps = int(round(t_end / dt))
        deck = HEADER + f"""
create_wire     1 loop 0 0 0 1.5 1 0.0 segment 0.2
{self.START[start]}
fix             el all wire/elastic E 100 m_elo 1 m_rot 1
fix             int all nve/gear scheme {scheme}
compute         ke all ke
variable        etot equal c_ke+f_el[3]
timestep        {dt!r}
thermo_style    custom step v_etot
thermo_modify   format float %.15g norm no
thermo          {steps // 200}
run             {steps}
"""
        res = run(deck)
        self.assertRanCleanly(res)
        e = res.thermo()["etot"]
        return np.max(np.abs(e - e[0])) / e[0]

    def errors(self, start):
        # dt_crit of this wire is 0.0137; Gear is stable below 0.156 of it (0.0021).
        err = {(s, dt): self.energy_error(s, dt, start) for s in ("gear5", "verlet")
               for dt in (1e-3, 5e-4)}
        for s in ("gear5", "verlet"):
            order = math.log2(err[s, 1e-3] / err[s, 5e-4])
            print(f"start {start}, {s}: max relative energy error over t=100: {err[s, 1e-3]:.3e} "
                  f"(dt 1e-3), {err[s, 5e-4]:.3e} (dt 5e-4), observed order {order:.2f}")
        return err

    def test_from_rest(self):
        err = self.errors("rest")
        self.assertAlmostEqual(math.log2(err["verlet", 1e-3] / err["verlet", 5e-4]), 2.0, delta=0.2)
        # Gear drifts (not symplectic) but at fifth order: measured 4.86, 24x below Verlet
        self.assertGreater(math.log2(err["gear5", 1e-3] / err["gear5", 5e-4]), 4.0)
        self.assertLess(err["gear5", 5e-4], 0.1 * err["verlet", 5e-4])

    def test_with_initial_velocities(self):
        err = self.errors("moving")
        # the start-up error makes Gear second order too (measured 2.00; Verlet 1.74, the
        # maximum of an oscillating error)
        for s in ("gear5", "verlet"):
            self.assertAlmostEqual(math.log2(err[s, 1e-3] / err[s, 5e-4]), 2.0, delta=0.35)
            self.assertLess(err[s, 5e-4], 1e-5)


class TimeStepWarning(DeckTestCase):
    # Table 1 wire: dt_crit = 0.013969; the gear5 limit is 0.156 of it (0.00219).
    def run_with(self, scheme, dt):
        res = run(HEADER + f"""
create_wire 1 line 0 0 0 4 0 0
fix el all wire/elastic
fix int all nve/gear scheme {scheme}
timestep {dt}
run 10
""")
        self.assertRanCleanly(res)
        return res.output

    def test_estimate_and_warning(self):
        out = self.run_with("gear5", 1e-4)
        self.assertIn("elastic critical time step 0.0139686 (Verlet limit), gear5 limit 0.00218609", out)
        self.assertNotIn("WARNING", out)
        self.assertIn("WARNING: fix wire/elastic (id el): timestep 0.003 exceeds the stable limit "
                      "0.00218609 of the gear5 integrator", self.run_with("gear5", 0.003))
        self.assertNotIn("WARNING", self.run_with("verlet", 0.003))

    def test_wire_laid_after_the_first_run(self):
        # in.column lays its wire after the first run: the estimate waits for a segment
        # (it printed 1e+300 for the empty group, and never again)
        res = run(HEADER + """
fix el all wire/elastic
fix int all nve/gear
timestep 1e-4
run 0
create_wire 1 line 0 0 0 4 0 0
run 10
""")
        self.assertRanCleanly(res)
        self.assertNotIn("1e+300", res.output)
        self.assertEqual(res.output.count("elastic critical time step 0.0139686 (Verlet limit), gear5 limit 0.00218609"), 1)


class BadInput(DeckTestCase):
    def check(self, body, message, files=None):
        self.assertStopsWith(run(HEADER + body + "\nrun 1\n", files=files), message)

    def test_nonpositive_modulus(self):
        self.check("create_wire 1 line 0 0 0 1 0 0\nfix el all wire/elastic E 0",
                   "fix wire/elastic (id el): value of 'E' must be > 0, got 0")
        self.check("create_wire 1 line 0 0 0 1 0 0\nfix el all wire/elastic E -5",
                   "fix wire/elastic (id el): value of 'E' must be > 0, got -5")

    def test_negative_multiplier(self):
        self.check("create_wire 1 line 0 0 0 1 0 0\nfix el all wire/elastic m_rot -0.1",
                   "fix wire/elastic (id el): value of 'm_rot' must be >= 0, got -0.1")

    def test_nonpositive_geometry(self):
        self.check("create_wire 1 line 0 0 0 1 0 0 radius 0",
                   "command create_wire (id -): value of 'radius' must be > 0, got 0")
        self.check("create_wire 1 line 0 0 0 1 0 0 segment -0.2",
                   "command create_wire (id -): value of 'segment' must be > 0, got -0.2")
        self.check("create_wire 1 line 0 0 0 1 0 0 density 0",
                   "command create_wire (id -): value of 'density' must be > 0, got 0")

    def test_missing_value(self):
        self.check("create_wire 1 line 0 0 0 1 0 0\nfix el all wire/elastic E",
                   "fix wire/elastic (id el): missing value after 'E'")
        self.check("create_wire 1 loop 0 0 0 1 2",
                   "command create_wire (id -): missing value after 'pitch'")

    def test_unknown_keyword(self):
        self.check("create_wire 1 line 0 0 0 1 0 0\nfix el all wire/elastic stiffness 3",
                   "fix wire/elastic (id el): unknown keyword 'stiffness'; accepted: E, m_elo, m_rot")

    def test_polyline_with_repeated_point(self):
        self.check("create_wire 1 polyline path.txt",
                   "command create_wire (id -): 'points'",
                   files={"path.txt": "0 0 0\n1 0 0\n1 0 0\n2 0 0\n"})

    def test_zero_length_line(self):
        self.check("create_wire 1 line 1 1 1 1 1 1", "command create_wire (id -):")

    def test_malformed_data_file(self):
        # non-finite and malformed numbers in the Atoms and Velocities sections; two beads at
        # one position (a zero-length segment has no stretching direction)
        read = "\nunits lj\natom_style wire\nboundary f f f\nread_data chain.data\n"
        chain = data_file([(0, 0, 0), (0.2, 0, 0), (0.4, 0, 0)], 0.2, 0.1, 1.0)
        for column, word, message in (
                (6, "1e400", "mass must be a finite number > 0, got '1e400'"),
                (6, "inf", "mass must be a finite number > 0, got 'inf'"),
                (5, "nan", "radius must be a finite number > 0, got 'nan'"),
                (4, "inf", "rest-length must be a finite number >= 0, got 'inf'")):
            lines = chain.splitlines()
            k = lines.index("Atoms") + 2
            words = lines[k].split()
            words[column] = word
            lines[k] = " ".join(words)
            self.assertStopsWith(run(read + "run 0\n", files={"chain.data": "\n".join(lines) + "\n"}),
                                 "atom_style wire: Atoms section of data file: " + message)
        velocities = chain + "\nVelocities\n\n1 0 0 0\n2 1.0x 0 0\n3 0 0 0\n"
        self.assertStopsWith(run(read + "run 0\n", files={"chain.data": velocities}),
                             "atom_style wire: Velocities section of data file: vx of atom 2 must be a finite number, "
                             "got '1.0x'")
        same = data_file([(0, 0, 0), (0.2, 0, 0), (0.2, 0, 0)], 0.2, 0.1, 1.0)
        self.assertStopsWith(run(read + "fix el all wire/elastic\nrun 0\n", files={"chain.data": same}),
                             "fix wire/elastic (id el): the segment from bead 2 to bead 3 has zero length at step 0 "
                             "(rest length 0.2): two beads at one position")

    def test_wire_outside_box(self):
        self.check("create_wire 1 line 0 0 0 50 0 0", "beads lie outside the simulation box")

    def test_wrong_atom_style(self):
        text = """
units lj
atom_style granular
boundary f f f
region box block -1 1 -1 1 -1 1
create_box 1 box
fix el all wire/elastic
run 1
"""
        self.assertStopsWith(run(text), "fix wire/elastic (id el): needs atom_style wire")
        self.assertStopsWith(run(text.replace("fix el all wire/elastic", "create_wire 1 line 0 0 0 1 0 0")),
                             "command create_wire (id -): needs atom_style wire")


if __name__ == "__main__":
    main()
