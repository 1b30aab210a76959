#!/usr/bin/python3
"""Stress matrix: short decks pushed one parameter at a time far from the
defaults; each cell must either stay physical or say why not (a WARNING or an ERROR).

    bench/stress_matrix.py [--liggghts build/liggghts] [--quick] [--out stress_matrix.md]
        [--timeout 120] [--only PATTERN] [--keep DIR]

Three scenes, each a deck written to a temporary directory:
  a  wire alone: a double loop (R = 1.5, 94 segments of Table 1 wire) released 0.3 above a
     floor (fix wire/wall) with self-contact (pair wire/contact), both undamped and
     frictionless (restitution 1, mu 0) so that the total energy (kinetic + elastic +
     contact springs + m g z) is conserved and its drift measured; 1.5 time units (v0
     cells: until 0.08 after the impact, before the undamped rebound leaves the box);
  b  wire on grains: 9 Table 1 grains (create_grains layer, a 3 x 3 lattice of spacing 2)
     settled on the floor of a 6 x 6 box (NSCD walls; 1.5 time units, then 0.5 with NSCD
     damping 100), then a double loop of R = 2 (125 segments) laid 1.3 above the top grain
     centre falls onto the four edge grains (fix wire/grain, fix nscd/polyhedra every 10,
     fix wire/wall on the box, pair wire/contact; Table 1 contact damping); 2 time units
     (v0 cells 0.3);
  c  grain pile: 30 Table 1 grains poured into a 6 x 6 box (fix nscd/polyhedra, frictional
     floor, frictionless sides) from z = 1.1 to 9; 5 time units.

Axes (one at a time around the default cell of each scene):
  dt       the time step as a fraction of the stability estimate. fix wire/elastic prints
           its own (dt_crit = 2/omega_max and the gear5 limit 0.156 dt_crit: the script
           checks its own figure against that line); the contact styles warn only beyond
           theirs (core/contact/contact_time_step.h), so the script estimates each from the
           formulas of docs/design.md, "The wire: bead chain with soft contacts": an
           undamped spring k_n = E* l_w pi/4 on the lightest mass it can act on (wall: one
           bead; wire-wire: E* = E/2, half a bead; wire-grain: 1/E* = (1-nu_w^2)/E_w +
           (1-nu_p^2)/E_p, one bead, the grain held), gear5 limit 0.313/omega; the estimate
           is the smallest of them. NSCD is implicit and documents no limit: for scene c the
           script uses h_est = r_p / v_max
           (a grain at the largest fall speed moves its sweep radius in a step);
  E        E_w / E_p from 1e-3 to 1e3 (scene a: E_w / E of the wall; scene b: E_p of fix
           wire/grain, the wire kept at E_w = 100 so its elastic limit stays);
  m_elo, m_rot  of fix wire/elastic, 0.01 to 1;
  v0       a downward speed set at the start on the falling object(s), 10 and 100 x 1 (the
           default impact speeds are 0.8-4);
  nscd     tolerance 1e-1, max_iterations 1;
  a_min    a_min / a_max of create_grains down to 0.1;
  rho      density ratio 1e3 (scene b: grains 1e3 lighter than the wire; scene c: half the
           grains 1e3 heavier).

Recorded per cell: exit status, WARNING lines, the ERROR line, the largest overlap (wire:
pair wire/contact through compute wire/contacts, fix wire/wall f_ID[2], fix wire/grain
f_ID[2], sampled at the thermo steps, about 1000 per run; grains: fix nscd/polyhedra's
largest overlap of all steps), relative energy drift (scene a), atoms at the end against
the start, nan/inf in thermo, wall time, a timeout (--timeout, per cell).
Classes: physical; warned (a WARNING, nothing worse); error (stopped with an ERROR line);
VIOLATION: a hang, an exit without an ERROR line (crash), or, in a run that did not stop
with an ERROR, nan/inf in thermo, fewer atoms at the end, an overlap beyond 0.5 r_w (wire)
or 0.1 a_max (grains), or |energy drift| > 10 % (scene a), unless a WARNING named its
cause: the time step (any of them), an overlap (an overlap), lost atoms (a loss); other
warnings, e.g. the NSCD iteration cap or fix wire/grain's reach, explain none of them. Note LIGGGHTS' default `thermo_modify lost ignore`: the decks keep it, so a
lost atom is silent unless a style notices. --quick runs the default cell and the extreme
value of every axis (half the cells); dt 10 x est is beyond the sweep."""

import argparse
import math
import os
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))

# Table 1 wire and grains (create_wire, create_grains, fix wire/elastic defaults)
R_W, L_W, RHO_W, E_W = 0.1, 0.2, 0.5, 100.0
A_MAX, R_P, RHO_P, E_P, NU_P = 1.0, 0.1, 1.5, 1000.0, 0.3
GEAR5 = 0.313          # gear5 is stable for omega dt < 0.313 (docs/commands/fix_nve_gear.md)
G = 1.0
V_REF = 1.0            # impact speeds are set as multiples of this
WIRE_OVERLAP, GRAIN_OVERLAP, DRIFT = 0.5 * R_W, 0.1 * A_MAX, 0.10

# ---------------------------------------------------------------------------------------
# stability estimates


def bead_mass():
    return RHO_W * math.pi * R_W ** 2 * L_W


def elastic_limits(E=E_W, m_elo=1.0, m_rot=0.1):
    """(dt_crit, gear5 limit) of fix wire/elastic (core/wire/wire_elasticity.cpp)."""
    m = bead_mass()
    k_s = m_elo * E * math.pi * R_W ** 2 / L_W
    kappa = m_rot * E * math.pi * R_W ** 4 / 4.0 / L_W
    w2 = 4.0 * k_s / m + 16.0 * kappa / (m * L_W ** 2)
    dt_crit = 2.0 / math.sqrt(w2) if w2 > 0 else math.inf
    return dt_crit, dt_crit * GEAR5 / 2.0


def contact_limit(E_star, mass):
    """gear5 limit of an undamped contact spring k_n = E* l_w pi/4 on `mass`."""
    k = E_star * L_W * math.pi / 4.0
    return GEAR5 / math.sqrt(k / mass)


def wire_estimates(E=E_W, m_elo=1.0, m_rot=0.1, E_wall=None, E_p=None):
    """Each style's gear5 limit for the wire of scenes a and b."""
    m = bead_mass()
    est = {"wire/elastic": elastic_limits(E, m_elo, m_rot)[1],
           "wire/wall": contact_limit(E if E_wall is None else E_wall, m),
           "wire/contact": contact_limit(E / 2.0, m / 2.0)}
    if E_p is not None:
        est["wire/grain"] = contact_limit(1.0 / (1.0 / E + (1 - NU_P ** 2) / E_p), m)
    return est


def nscd_estimate(z_top, v0=0.0):
    """Scene c: no stability limit (implicit); a grain should not move more than its sweep
    radius in one step: h = r_p / v_max, v_max the speed after falling from z_top."""
    return R_P / math.sqrt(v0 ** 2 + 2.0 * G * z_top)


# ---------------------------------------------------------------------------------------
# decks

WIRE_THERMO = "compute ww wire wire/contacts"

SCENE_A = """
units           lj
atom_style      wire
boundary        f f f
newton          off
region          box block -3 3 -3 3 -3 12
create_box      1 box
create_wire     1 loop 0 0 0.4 1.5 2 0.25
group           wire type 1
set             group all vz {vz}
pair_style      wire/contact restitution 1 mu_s 0 mu_d 0
pair_coeff      * *
neighbor        0.1 bin
neigh_modify    delay 0
fix             elastic all wire/elastic m_elo {m_elo} m_rot {m_rot}
fix             integr all nve/gear
fix             gravity all gravity 1.0 vector 0 0 -1
fix             floor all wire/wall plane 0 0 0 0 0 1 E {E_wall} restitution 1 mu_s 0 mu_d 0
timestep        {dt}
compute         ww all wire/contacts
compute         ke all ke
compute         pe all pe
variable        pg equal mass(all)*xcm(all,z)
# the floor's spring energy: r_w - z overlap, k_n = E l_w pi/4 (fix wire/wall)
variable        xi atom ({r_w}-z)*(z<{r_w})
variable        ew atom 0.5*{k_wall}*v_xi*v_xi
compute         ew all reduce sum v_ew
thermo_style    custom step atoms c_ke c_pe f_elastic v_pg c_ew c_ww[2] f_floor[2]
thermo_modify   norm no format float %.10g
thermo          {every}
run             {steps}
"""
# columns after step and atoms
A_COLUMNS = ["ke", "pe_contact", "elastic", "pe_gravity", "e_wall", "ov_wire_wire", "ov_wire_wall"]

SCENE_B = """
units           lj
atom_style      hybrid polyhedron wire
atom_modify     map array sort 0 0.0
boundary        f f f
region          box block -3 3 -3 3 -3 12
create_box      2 box
region          fill block -3 3 -3 3 0 10
create_grains   1 9 layer fill 1.15 seed 7 spacing 2 a_min {a_min} density {rho_p}
group           grains type 1
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd grains nscd/polyhedra every 10 tolerance {tol} max_iterations {iters} &
                wall 0 0 0 0 0 1 &
                wall -3 0 0 1 0 0 wall_friction 0 wall 3 0 0 -1 0 0 wall_friction 0 &
                wall 0 -3 0 0 1 0 wall_friction 0 wall 0 3 0 0 -1 0 wall_friction 0
timestep        {dt}
pair_style      wire/contact
pair_coeff      * *
neighbor        0.1 bin
neigh_modify    delay 0
compute         top grains reduce max z
# (no thermo_modify before the second thermo_style: LIGGGHTS would warn)
thermo_style    custom step atoms f_nscd[1] f_nscd[24] c_top
thermo          {settle_every}
run             {settle_steps}
fix_modify      nscd damping 100
run             {quench_steps}
fix_modify      nscd damping 0

variable        zwire equal c_top+1.3
create_wire     2 loop 0 0 ${{zwire}} 2 2 0.25
group           wire type 2
set             group wire vz {vz}
fix             elastic wire wire/elastic m_elo {m_elo} m_rot {m_rot}
fix             integr wire nve/gear
fix             floor wire wire/wall plane 0 0 0 0 0 1
fix             wxlo wire wire/wall plane -3 0 0 1 0 0 mu_s 0 mu_d 0
fix             wxhi wire wire/wall plane 3 0 0 -1 0 0 mu_s 0 mu_d 0
fix             wylo wire wire/wall plane 0 -3 0 0 1 0 mu_s 0 mu_d 0
fix             wyhi wire wire/wall plane 0 3 0 0 -1 0 mu_s 0 mu_d 0
fix             wg wire wire/grain grains E_p {E_p}
compute         ww wire wire/contacts
compute         wbottom wire reduce min z
thermo_style    custom step atoms f_nscd[1] f_nscd[24] c_top c_ww[2] f_wg[2] f_wg[1] c_wbottom &
                f_floor[2] f_wxlo[2] f_wxhi[2] f_wylo[2] f_wyhi[2]
thermo_modify   norm no format float %.10g
thermo          {every}
run             {steps}
"""
B_COLUMNS = ["sweeps", "ov_grains", "top", "ov_wire_wire", "ov_wire_grain", "wg_contacts", "wire_bottom",
             "ov_wire_wall", "ov_wire_wall1", "ov_wire_wall2", "ov_wire_wall3", "ov_wire_wall4"]

SCENE_C = """
units           lj
atom_style      polyhedron
atom_modify     map array sort 0 0.0
boundary        f f f
region          box block -3 3 -3 3 0 16
create_box      2 box
region          fill block -1.9 1.9 -1.9 1.9 1.1 {z_top}
{grains}
fix             g all gravity 1.0 vector 0 0 -1
fix             nscd all nscd/polyhedra tolerance {tol} max_iterations {iters} &
                wall 0 0 0 0 0 1 &
                wall -3 0 0 1 0 0 wall_friction 0 wall 3 0 0 -1 0 0 wall_friction 0 &
                wall 0 -3 0 0 1 0 wall_friction 0 wall 0 3 0 0 -1 0 wall_friction 0
set             group all vz {vz}
timestep        {dt}
compute         zmax all reduce max z
compute         zmin all reduce min z
thermo_style    custom step atoms f_nscd[1] f_nscd[24] f_nscd[6] c_zmin c_zmax
thermo_modify   norm no format float %.10g
thermo          {every}
run             {steps}
"""
C_COLUMNS = ["sweeps", "ov_grains", "capped", "zmin", "zmax"]
C_Z_TOP = 9.0
C_GRAINS = 30

# ---------------------------------------------------------------------------------------
# cells

A_DEFAULT = dict(dt=1e-4, m_elo=1.0, m_rot=0.1, E_wall=E_W, v0=0.0, T=1.5)
B_DEFAULT = dict(dt=1e-4, m_elo=1.0, m_rot=0.1, E_p=E_P, v0=0.0, tol=1e-4, iters=1000, a_min=0.8,
                 rho_p=RHO_P, T=2.0, T_settle=1.5, T_quench=0.5)
C_DEFAULT = dict(dt=1e-3, tol=1e-4, iters=1000, a_min=0.8, rho_ratio=1.0, v0=0.0, T=5.0)


def a_estimate(p):
    est = wire_estimates(E_W, p["m_elo"], p["m_rot"], E_wall=p["E_wall"])
    return min(est.values()), est


def b_estimate(p):
    est = wire_estimates(E_W, p["m_elo"], p["m_rot"], E_p=p["E_p"])
    return min(est.values()), est


def cells():
    """(scene, axis, label, parameters, extreme) in run order."""
    out = []
    dflt_a, _ = a_estimate(A_DEFAULT)
    out.append(("a", "default", "Table 1, dt 1e-4", dict(A_DEFAULT), True))
    for f in (0.1, 0.5, 1.0, 2.0, 10.0):
        out.append(("a", "dt", f"dt {f:g} x est ({f * dflt_a:.3g})", dict(A_DEFAULT, dt=f * dflt_a), f == 2.0))
    # m_elo 0.01 moves the elastic limit above the contacts': 2 x the contact estimate is
    # still inside fix wire/elastic's own limit
    soft = dict(A_DEFAULT, m_elo=0.01)
    est_soft, parts = a_estimate(soft)
    out.append(("a", "dt", f"m_elo 0.01, dt 2 x contact est ({2 * est_soft:.3g}; "
                f"wire/elastic's {parts['wire/elastic']:.3g})", dict(soft, dt=2 * est_soft), True))
    for ratio in (1e-3, 1e-1, 1e1, 1e3):
        out.append(("a", "E", f"E_w/E_wall {ratio:g}", dict(A_DEFAULT, E_wall=E_W / ratio), ratio in (1e-3, 1e3)))
    for m in (0.01, 0.1):
        out.append(("a", "m_elo", f"m_elo {m:g}", dict(A_DEFAULT, m_elo=m), m == 0.01))
    for m in (0.01, 1.0):
        out.append(("a", "m_rot", f"m_rot {m:g}", dict(A_DEFAULT, m_rot=m), m == 0.01))
    for k in (10, 100):
        # until shortly after the impact: the undamped wire bounces back to v0^2/2g
        out.append(("a", "v0", f"v0 {k} x {V_REF:g}", dict(A_DEFAULT, v0=k * V_REF, T=0.3 / (k * V_REF) + 0.08),
                    k == 100))

    dflt_b, _ = b_estimate(B_DEFAULT)
    out.append(("b", "default", "Table 1, dt 1e-4, NSCD every 10", dict(B_DEFAULT), True))
    for f in (0.1, 0.5, 1.0, 2.0, 10.0):
        out.append(("b", "dt", f"dt {f:g} x est ({f * dflt_b:.3g})", dict(B_DEFAULT, dt=f * dflt_b), f == 2.0))
    for ratio in (1e-3, 1e1, 1e3):
        out.append(("b", "E", f"E_w/E_p {ratio:g}", dict(B_DEFAULT, E_p=E_W / ratio), ratio in (1e-3, 1e3)))
    out.append(("b", "m_elo", "m_elo 0.01", dict(B_DEFAULT, m_elo=0.01), True))
    out.append(("b", "m_rot", "m_rot 0.01", dict(B_DEFAULT, m_rot=0.01), True))
    out.append(("b", "m_rot", "m_rot 1", dict(B_DEFAULT, m_rot=1.0), False))
    for k in (10, 100):
        out.append(("b", "v0", f"v0 {k} x {V_REF:g}", dict(B_DEFAULT, v0=k * V_REF, T=0.3), k == 100))
    out.append(("b", "nscd", "tolerance 1e-1, max_iterations 1", dict(B_DEFAULT, tol=1e-1, iters=1), True))
    out.append(("b", "a_min", "a_min/a_max 0.1", dict(B_DEFAULT, a_min=0.1), True))
    out.append(("b", "rho", "rho_w/rho_p 1e3 (light grains)", dict(B_DEFAULT, rho_p=RHO_W / 1e3), True))

    dflt_c = nscd_estimate(C_Z_TOP)
    out.append(("c", "default", "Table 1, h 1e-3", dict(C_DEFAULT), True))
    for f in (0.1, 0.5, 1.0, 2.0, 10.0):
        out.append(("c", "dt", f"h {f:g} x est ({f * dflt_c:.3g})", dict(C_DEFAULT, dt=f * dflt_c), f == 2.0))
    out.append(("c", "nscd", "tolerance 1e-1", dict(C_DEFAULT, tol=1e-1), False))
    out.append(("c", "nscd", "max_iterations 1", dict(C_DEFAULT, iters=1), False))
    out.append(("c", "nscd", "tolerance 1e-1, max_iterations 1", dict(C_DEFAULT, tol=1e-1, iters=1), True))
    for a in (0.3, 0.1):
        out.append(("c", "a_min", f"a_min/a_max {a:g}", dict(C_DEFAULT, a_min=a), a == 0.1))
    out.append(("c", "rho", "density ratio 1e3 (half the grains)", dict(C_DEFAULT, rho_ratio=1e3), True))
    for k in (10, 100):
        out.append(("c", "v0", f"v0 {k} x {V_REF:g}", dict(C_DEFAULT, v0=k * V_REF), k == 100))
    return out


def thermo_every(steps):
    return max(1, steps // 1000)


def deck(scene, label, p):
    return f"# stress matrix, scene {scene}: {label}\n" + deck_text(scene, p)


def deck_text(scene, p):
    if scene == "a":
        steps = max(1, round(p["T"] / p["dt"]))
        text = SCENE_A.format(vz=-p["v0"], m_elo=p["m_elo"], m_rot=p["m_rot"], E_wall=p["E_wall"], dt=p["dt"],
                              r_w=R_W, k_wall=p["E_wall"] * L_W * math.pi / 4.0, every=thermo_every(steps),
                              steps=steps)
    elif scene == "b":
        steps = max(1, round(p["T"] / p["dt"]))
        settle = max(10, round(p["T_settle"] / p["dt"] / 10.0) * 10)
        quench = max(10, round(p["T_quench"] / p["dt"] / 10.0) * 10)
        text = SCENE_B.format(a_min=p["a_min"], rho_p=p["rho_p"], tol=p["tol"], iters=p["iters"], dt=p["dt"],
                              settle_every=settle, settle_steps=settle, quench_steps=quench, vz=-p["v0"],
                              m_elo=p["m_elo"],
                              m_rot=p["m_rot"], E_p=p["E_p"], every=thermo_every(steps), steps=steps)
    else:
        steps = max(1, round(p["T"] / p["dt"]))
        if p["rho_ratio"] != 1.0:
            half = C_GRAINS // 2
            grains = (f"create_grains   1 {half} random fill seed 7 a_min {p['a_min']} density {RHO_P}\n"
                      f"create_grains   2 {C_GRAINS - half} random fill seed 8 a_min {p['a_min']} "
                      f"density {RHO_P * p['rho_ratio']}")
        else:
            grains = f"create_grains   1 {C_GRAINS} random fill seed 7 a_min {p['a_min']}"
        text = SCENE_C.format(z_top=C_Z_TOP, grains=grains, tol=p["tol"], iters=p["iters"], vz=-p["v0"],
                              dt=p["dt"], every=thermo_every(steps), steps=steps)
    return text


# ---------------------------------------------------------------------------------------
# running and reading


def thermo_blocks(out):
    """Every thermo table of the output: a list of rows (lists of strings), each row
    starting with step and atoms. A table ends at 'Loop time' or at anything else."""
    blocks, rows, inside = [], None, False
    for line in out.splitlines():
        fields = line.split()
        if fields[:2] == ["Step", "Atoms"]:
            rows, inside = [], True
            blocks.append(rows)
            continue
        if not inside:
            continue
        if fields and re.fullmatch(r"\d+", fields[0]) and len(fields) >= 2:
            rows.append(fields)
        elif line.startswith("WARNING"):
            continue  # warnings may come between thermo rows
        else:
            inside = False
    return blocks


def number(text):
    try:
        return float(text)
    except ValueError:
        return math.nan


def run_cell(liggghts, scene, label, p, timeout, keep):
    work = tempfile.mkdtemp(prefix=f"stress-{scene}-", dir=keep)
    with open(os.path.join(work, "in.stress"), "w") as f:
        f.write(deck(scene, label, p))
    start = time.time()
    proc = subprocess.Popen([liggghts, "-in", "in.stress", "-log", "none"], cwd=work,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    try:
        raw, _ = proc.communicate(timeout=timeout)
        hang = False
    except subprocess.TimeoutExpired:
        proc.kill()
        raw, _ = proc.communicate()
        hang = True
    seconds = time.time() - start
    out = raw.decode(errors="replace")
    with open(os.path.join(work, "screen.txt"), "w") as f:
        f.write(out)
    return evaluate(scene, p, out, proc.returncode, hang, seconds, work)


def evaluate(scene, p, out, code, hang, seconds, work):
    r = dict(code=code, hang=hang, seconds=seconds, work=work)
    r["warnings"] = [l.strip() for l in out.splitlines() if l.startswith("WARNING")]
    errors = [l.strip() for l in out.splitlines() if l.startswith("ERROR")]
    r["error"] = errors[0] if errors else ""
    m = re.search(r"elastic critical time step ([0-9.eE+-]+) \(Verlet limit\), gear5 limit ([0-9.eE+-]+)", out)
    r["printed_gear5"] = float(m.group(2)) if m else None
    blocks = thermo_blocks(out)
    rows = [row for b in blocks for row in b]
    r["nan"] = any(re.search(r"nan|inf", tok, re.I) for row in rows for tok in row)
    # atoms: the last row of each table against its first (scene b adds the wire between tables)
    lost = 0
    for b in blocks:
        if len(b) >= 2:
            lost += int(number(b[0][1])) - int(number(b[-1][1]))
    r["lost"] = lost
    r["steps_done"] = int(rows[-1][0]) if rows else 0
    columns = {"a": A_COLUMNS, "b": B_COLUMNS, "c": C_COLUMNS}[scene]
    # the rows with every column (scene b: the wire's run, after the grains settled)
    wire_rows = [row for row in rows if len(row) >= 2 + len(columns)]

    def column(name, table):
        k = 2 + columns.index(name)
        return [number(row[k]) for row in table if len(row) > k]

    def largest(values):
        values = [v for v in values if not math.isnan(v)]
        return max(values) if values else math.nan

    r["ov_wire"] = math.nan
    r["ov_grain"] = math.nan
    r["drift"] = math.nan
    if scene in ("a", "b"):
        names = ["ov_wire_wire", "ov_wire_wall"] + (["ov_wire_grain"] if scene == "b" else [])
        walls = [c for c in columns if c.startswith("ov_wire_wall")]
        per = {n: largest(column(n, wire_rows)) for n in names if n != "ov_wire_wall"}
        per["ov_wire_wall"] = largest([largest(column(n, wire_rows)) for n in walls])
        r["ov_wire"] = largest(per.values())
        r["ov_wire_by"] = max(per, key=lambda n: -1 if math.isnan(per[n]) else per[n])[3:] if per else ""
    if scene in ("b", "c"):
        r["ov_grain"] = largest(column("ov_grains", [row for b in blocks for row in b]))
    if scene == "a" and len(wire_rows) >= 2:
        energy = [sum(number(row[2 + columns.index(n)]) for n in ("ke", "pe_contact", "elastic", "pe_gravity",
                                                                     "e_wall")) for row in wire_rows]
        r["drift"] = (energy[-1] - energy[0]) / abs(energy[0])
    classify(r)
    return r


# What a warning must name to explain each symptom (the NSCD iteration cap or fix
# wire/grain's reach explain none of them)
EXPLAINS = {"nan": r"time ?step", "lost": r"time ?step|lost", "overlap": r"time ?step|overlap",
            "drift": r"time ?step"}


def classify(r):
    def silent(symptom):
        return not r["error"] and not any(re.search(EXPLAINS[symptom], w, re.I) for w in r["warnings"])

    why = []
    if r["hang"]:
        why.append("hang")
    elif r["error"]:
        pass
    elif r["code"] != 0:
        why.append(f"exit {r['code']} without ERROR")
    if r["nan"] and silent("nan"):
        why.append("nan in thermo")
    if r["lost"] > 0 and silent("lost"):
        why.append(f"{r['lost']} atoms lost")
    if r["ov_wire"] > WIRE_OVERLAP and silent("overlap"):
        why.append(f"wire overlap {r['ov_wire'] / R_W:.2g} r_w ({r.get('ov_wire_by', '')})")
    if r["ov_grain"] > GRAIN_OVERLAP and silent("overlap"):
        why.append(f"grain overlap {r['ov_grain'] / A_MAX:.2g} a_max")
    if abs(r["drift"]) > DRIFT and silent("drift"):
        why.append(f"energy drift {r['drift']:+.2g}")
    if why and r["warnings"] and not r["hang"]:
        why.append("no warning names its cause")
    if why:
        r["class"] = "VIOLATION"
    elif r["error"]:
        r["class"] = "error"
    elif r["warnings"]:
        r["class"] = "warned"
    else:
        r["class"] = "physical"
    r["why"] = why


# ---------------------------------------------------------------------------------------
# table


def fmt(v, digits=2):
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return "–"
    return f"{v:.{digits}g}"


def shorten(text, n=110):
    text = re.sub(r"\s+\((?:\.\./|/|liggghts-staged/)[^()]*\.(?:cpp|h):\d+\)", "", text)
    return text if len(text) <= n else text[:n - 1] + "…"


def table(results):
    head = ("| # | scene | cell | class | overlap / r_w | overlap / a_max | drift | atoms lost | nan | s | "
            "message (first WARNING or ERROR; why VIOLATION) |")
    lines = [head, "|" + "---|" * 11]
    for k, (scene, axis, label, p, _, r) in enumerate(results, 1):
        message = r["error"] or (r["warnings"][0] + (f" (+{len(r['warnings']) - 1})" if len(r["warnings"]) > 1 else "")
                                 if r["warnings"] else "")
        note = "; ".join(r["why"])
        text = shorten(message) + (("; " if message else "") + "**" + note + "**" if note else "")
        cls = "**VIOLATION**" if r["class"] == "VIOLATION" else r["class"]
        lines.append(f"| {k} | {scene} | {label} | {cls} | {fmt(r['ov_wire'] / R_W)} | "
                     f"{fmt(r['ov_grain'] / A_MAX)} | {fmt(r['drift'])} | {r['lost'] if r['lost'] else ''} | "
                     f"{'yes' if r['nan'] else ''} | {r['seconds']:.1f}{' (timeout)' if r['hang'] else ''} | "
                     f"{text.replace('|', '/')} |")
    return "\n".join(lines)


def summary(results):
    n = len(results)
    counts = {c: sum(1 for *_, r in results if r["class"] == c) for c in ("physical", "warned", "error", "VIOLATION")}
    slow = max(results, key=lambda x: x[-1]["seconds"])
    total = sum(r["seconds"] for *_, r in results)
    parts = ", ".join(f"{c} {counts[c]}/{n} ({counts[c] / n:.0%})" for c in counts)
    return (f"{n} cells: {parts}. Slowest: {slow[0]} '{slow[2]}' {slow[-1]['seconds']:.1f} s; "
            f"all cells {total:.0f} s.")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--liggghts", default=os.path.join(HERE, "..", "build", "liggghts"))
    parser.add_argument("--quick", action="store_true", help="the default cell and each axis' extreme only")
    parser.add_argument("--out", default="stress_matrix.md")
    parser.add_argument("--timeout", type=float, default=120.0, help="seconds per cell")
    parser.add_argument("--only", default="", help="run only cells whose 'scene label' matches this regex")
    parser.add_argument("--keep", default=None, help="keep the cells' directories (deck, screen.txt) under DIR")
    args = parser.parse_args()
    liggghts = os.path.abspath(args.liggghts)
    if args.keep:
        os.makedirs(args.keep, exist_ok=True)
    chosen = [c for c in cells() if (c[4] or not args.quick) and re.search(args.only, f"{c[0]} {c[2]}")]
    _, est_a = a_estimate(A_DEFAULT)
    _, est_b = b_estimate(B_DEFAULT)
    estimates = ("Stability estimates (gear5 limits) at the defaults: scene a "
                 + ", ".join(f"{k} {v:.3g}" for k, v in est_a.items()) + "; scene b "
                 + ", ".join(f"{k} {v:.3g}" for k, v in est_b.items())
                 + f"; scene c (NSCD, no limit) r_p/v_max = {nscd_estimate(C_Z_TOP):.3g}.")
    print(estimates, flush=True)
    results = []
    for k, (scene, axis, label, p, extreme) in enumerate(chosen, 1):
        r = run_cell(liggghts, scene, label, p, args.timeout, args.keep)
        if r["printed_gear5"] and scene in "ab":
            mine = elastic_limits(E_W, p["m_elo"], p["m_rot"])[1]
            if abs(r["printed_gear5"] / mine - 1) > 1e-4:
                print(f"  note: fix wire/elastic printed gear5 limit {r['printed_gear5']:.6g}, script {mine:.6g}")
        results.append((scene, axis, label, p, extreme, r))
        print(f"[{k}/{len(chosen)}] {scene} {label}: {r['class']} {r['seconds']:.1f} s"
              + (f" ({'; '.join(r['why'])})" if r["why"] else "")
              + (f" {shorten(r['error'], 90)}" if r["error"] else ""), flush=True)
        if not args.keep:
            for name in os.listdir(r["work"]):
                path = os.path.join(r["work"], name)
                if os.path.isfile(path):
                    os.remove(path)
            try:
                os.rmdir(r["work"])
            except OSError:
                pass
    text = table(results)
    line = summary(results)
    print()
    print(text)
    print()
    print(line)
    with open(args.out, "w") as f:
        f.write(f"Stress matrix ({' '.join(sys.argv[1:]) or 'defaults'})\n\n{estimates}\n\n{line}\n\n{text}\n")
    print(f"written: {args.out}")


if __name__ == "__main__":
    main()
