#!/usr/bin/python3
"""Benchmark: a 4242-segment wire lying on a pile of 900 Table 1 grains (fix wire/grain with
NSCD sub-cycling): time per wire sub-step of the wire-grain contacts against the wire-wire
contacts and the elastic forces, exact segment-grain evaluations per second, and the cost
of one NSCD step with and without the coupling. All cases start from the same state, one
after the other in this invocation; prints a table and the ratios.

    bench/wire_grain_contacts.py [--liggghts build/liggghts] [--steps 2000] [--drop 2000] [--np 1]
        [--skins 0 0.02 0.05 0.1 0.2]

The scene (atom_style hybrid polyhedron wire, Table 1 defaults everywhere):
  1. pile: 900 grains from two paper-style particle layers (create_grains layer, 450 each,
     lattice spacing 1.875 in a 30 x 30 region) in a 31 x 31 box with NSCD walls (frictional
     floor, frictionless sides), collapsed into a pile 2-3 grains deep under a raised gravity
     (g = 20 for 1 time unit, to keep the set-up short), quenched with fix_modify damping
     (100, then 10 at g = 1); Delta t = 1e-3, one NSCD step per LIGGGHTS step.
  2. wire: one wire laid as an Archimedean spiral (arms 0.72 apart, from radius 14 inwards)
     draped over the pile: this script reads the grains' shapes (create_grains write_shapes)
     and settled poses (write_dump), computes the height of the pile's top surface under the
     spiral (hull faces sampled every 0.08, swept by r_p + r_w + 0.015: the wire starts
     0.01-0.015 above the highest grains), rounds the profile from above with parabolas of
     radius 0.5 (the wire cannot follow sharp dips), and cuts the path where create_wire's
     resampling gives 4242 segments of l_w = 0.2. The wire then falls onto the pile for
     `--drop` sub-steps (Delta t_SP = 1e-4, fix nscd/polyhedra timestep 1e-3: 10 sub-steps per
     NSCD step) with everything coupled, starting at 0.2 downwards, and the state goes to a restart file.
  3. timed runs of `--steps` sub-steps from that restart, all with gravity and the NSCD
     grains; LIGGGHTS' per-fix timers (modify_timing on) and Pair/Neigh times:
       a  coupled: fix wire/elastic + nve/gear + 5 fix wire/wall + pair wire/contact
          + fix wire/grain
       b  as a without fix wire/grain (the wire does not touch the grains)
       c  as a without pair wire/contact
       d  the grains alone (no wire fix, no pair: the beads stay where they are)
     Per sub-step: wire-grain = fix wire/grain's timer (the exact evaluations, the broad
     phase, the tangential springs, and once per NSCD step holding the rank's grains in
     the grid: everything the coupling costs apart from the NSCD solve), wire-wire = Pair
     time + Neigh time (the neighbour lists only the pair needs), elastic = fix wire/elastic.
     The loop-time differences a - b and a - c cross-check those timers. NSCD step: fix
     nscd/polyhedra's timer per NSCD step and its own split (f_nscd[22], f_nscd[23]: seconds
     of gathering + detection and of the solve, 5 walls) averaged over the run; b and d move
     the grains identically (in b the wire does not act on them), so their difference is
     noise. Contacts and evaluations are sampled at the NSCD steps (every 10th sub-step).
  4. case a again for each `--skins` value (fix wire/grain skin: the pair cache, 0 = a full
     search every sub-step): fix wire/grain's time per sub-step, evaluations, ratio to skin 0.

The machine is shared (another job may run tests meanwhile): expect +-30 % between
invocations; the per-style timers of one run are more reliable than loop-time differences.
About 2 1/4 minutes on one core with the defaults (set-up 1 1/4, the four cases 1)."""

import argparse
import math
import os
import re
import subprocess
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))

HALF = 15.5          # box half-width; NSCD walls and wire walls on its sides
SEGMENTS = 4242      # the wire, l_w = 0.2 (create_wire's default)
L_W, R_W = 0.2, 0.1

HEADER = """
units           lj
atom_style      hybrid polyhedron wire
atom_modify     map array sort 0 0.0
boundary        f f f
"""

NSCD = f"""
fix             nscd grains nscd/polyhedra timestep 1e-3 &
                wall 0 0 0 0 0 1 &
                wall -{HALF} 0 0 1 0 0 wall_friction 0 wall {HALF} 0 0 -1 0 0 wall_friction 0 &
                wall 0 -{HALF} 0 0 1 0 wall_friction 0 wall 0 {HALF} 0 0 -1 0 wall_friction 0
"""

PILE = HEADER + f"""
region          box block -{HALF} {HALF} -{HALF} {HALF} 0 20
create_box      2 box
region          fill block -15 15 -15 15 0 20
create_grains   1 450 layer fill 1.15 seed {{seed}} spacing 1.875 write_shapes shapes1.txt
create_grains   1 450 layer fill 5.15 seed {{seed2}} spacing 1.875 write_shapes shapes2.txt
group           grains type 1
fix             g all gravity 20.0 vector 0 0 -1
{NSCD}
timestep        1e-3
compute         top grains reduce max z
thermo_style    custom step atoms f_nscd[1] f_nscd[3] c_top ke
thermo_modify   norm no
thermo          500
run             1000
fix_modify      nscd damping 100
run             300
fix             g all gravity 1.0 vector 0 0 -1
fix_modify      nscd damping 10
run             200
fix_modify      nscd damping 0
compute         rot grains grain/rotation
write_dump      grains custom grains.dump id x y z c_rot[1] c_rot[2] c_rot[3] c_rot[4]
write_restart   pile.restart
"""

WIRE_FIXES = f"""
fix             elastic wire wire/elastic
fix             integr wire nve/gear
fix             floor wire wire/wall plane 0 0 0 0 0 1
fix             wxlo wire wire/wall plane -{HALF} 0 0 1 0 0 mu_s 0 mu_d 0
fix             wxhi wire wire/wall plane {HALF} 0 0 -1 0 0 mu_s 0 mu_d 0
fix             wylo wire wire/wall plane 0 -{HALF} 0 0 1 0 mu_s 0 mu_d 0
fix             wyhi wire wire/wall plane 0 {HALF} 0 0 -1 0 mu_s 0 mu_d 0
"""

PAIR = """
pair_style      wire/contact
pair_coeff      * *
neighbor        0.1 bin
neigh_modify    delay 0
"""

DROP = HEADER + f"""
read_restart    pile.restart
group           grains type 1
fix             g all gravity 1.0 vector 0 0 -1
{NSCD}
# after the fix that takes its per-atom state from the restart file (new atoms have none)
create_wire     2 polyline wire.txt
group           wire type 2
velocity        wire set 0 0 -0.2
timestep        1e-4
{PAIR}
{WIRE_FIXES}
fix             wg wire wire/grain grains
compute         ww wire wire/contacts
compute         wbottom wire reduce min z
compute         wtop wire reduce max z
thermo_style    custom step f_nscd[3] f_wg[1] f_wg[3] f_wg[7] c_ww[1] c_wbottom c_wtop
thermo_modify   norm no
thermo          500
run             {{drop}}
write_restart   scene.restart
"""

MEASURE = HEADER + f"""
read_restart    scene.restart
group           grains type 1
group           wire type 2
fix             g {{gravity_group}} gravity 1.0 vector 0 0 -1
{NSCD}
timestep        1e-4
{{pair}}
{{wire}}
modify_timing   on
{{stats}}
thermo_modify   norm no
thermo          10
run             {{steps}}
"""

NSCD_STATS = "f_nscd[1] f_nscd[3] f_nscd[22] f_nscd[23]"

CASES = [  # key, label, pair wire/contact, the wire's fixes, fix wire/grain
    ("a", "coupled", True, True, True),
    ("b", "without fix wire/grain", True, True, False),
    ("c", "without pair wire/contact", False, True, True),
    ("d", "grains alone", False, False, False),
]


def liggghts(args, work, name, text):
    with open(os.path.join(work, name), "w") as f:
        f.write(text)
    cmd = [args.liggghts, "-in", name, "-log", "none"]
    if args.np > 1:
        cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(args.np)] + cmd
    out = subprocess.run(cmd, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT).stdout.decode()
    if "ERROR" in out or "Loop time" not in out:
        raise SystemExit(f"{name} failed in {work}:\n" + out[-3000:])
    return out


# ---------------------------------------------------------------------------------------
# the wire's path: a spiral draped over the pile's top surface

def read_shapes(path):
    """tag -> (body-frame vertices, faces, sweep radius) from a create_grains write_shapes file."""
    shapes = {}
    with open(path) as f:
        lines = [l.split() for l in f if not l.startswith("#")]
    k = 0
    while k < len(lines):
        head = lines[k]
        tag, sweep, nv, nf = int(head[1]), float(head[3]), int(head[-2]), int(head[-1])
        vertices = np.array([[float(v) for v in l] for l in lines[k + 1:k + 1 + nv]])
        faces = [[int(i) for i in l[1:]] for l in lines[k + 1 + nv:k + 1 + nv + nf]]
        shapes[tag] = (vertices, faces, sweep)
        k += 1 + nv + nf
    return shapes


def rotation(q):
    w, x, y, z = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def surface_samples(vertices, faces, spacing):
    """Points on the hull's faces (fan triangles, barycentric grids), at most `spacing` apart."""
    points = [vertices]
    for face in faces:
        for t in range(1, len(face) - 1):
            a, b, c = vertices[face[0]], vertices[face[t]], vertices[face[t + 1]]
            n = max(1, math.ceil(max(np.linalg.norm(b - a), np.linalg.norm(c - a), np.linalg.norm(c - b)) / spacing))
            i, j = np.meshgrid(np.arange(n + 1), np.arange(n + 1), indexing="ij")
            keep = i + j <= n
            u, v = i[keep] / n, j[keep] / n
            points.append(a + np.outer(u, b - a) + np.outer(v, c - a))
    return np.vstack(points)


def wire_path(work, segments):
    """The spiral's points (x y z) draped over the pile, cut at `segments` segments of l_w."""
    shapes = {}
    for name in ("shapes1.txt", "shapes2.txt"):
        shapes.update(read_shapes(os.path.join(work, name)))
    with open(os.path.join(work, "grains.dump")) as f:
        rows = f.read().split("ITEM: ATOMS")[1].splitlines()[1:]
    poses = {int(r.split()[0]): np.array([float(v) for v in r.split()[1:8]]) for r in rows if r.strip()}

    # the spiral in the plane: r = 14 - 0.72 theta / 2 pi, a point every 0.05 of arc
    step, r_out, pitch = 0.05, 14.0, 0.72
    xy, theta = [], 0.0
    while True:
        r = r_out - pitch * theta / (2 * math.pi)
        if r < 0.5:
            break
        xy.append((r * math.cos(theta), r * math.sin(theta)))
        theta += step / r
    xy = np.array(xy)

    # the top of every grain swept by r_p + r_w + clearance, over the spiral's points
    clearance = 0.015
    height = np.full(len(xy), R_W + clearance)  # the floor
    for tag, (vertices, faces, sweep) in shapes.items():
        pose = poses[tag]
        reach = sweep + R_W + clearance
        world = surface_samples(vertices, faces, 0.08) @ rotation(pose[3:7]).T + pose[0:3]
        bound = np.max(np.linalg.norm(world[:, :2] - pose[0:2], axis=1)) + reach
        near = np.nonzero(np.sum((xy - pose[0:2]) ** 2, axis=1) < bound * bound)[0]
        if len(near) == 0:
            continue
        d2 = np.sum((xy[near, None, :] - world[None, :, :2]) ** 2, axis=2)
        top = np.where(d2 < reach * reach, world[None, :, 2] + np.sqrt(np.maximum(reach * reach - d2, 0.0)), -1.0)
        height[near] = np.maximum(height[near], top.max(axis=1))

    # round the profile from above: z(s) = max over s' of h(s') - (s - s')^2 / (2 rho)
    rho = 0.5
    z = height.copy()
    for k in range(1, int(math.sqrt(2 * rho * 4.0) / step) + 1):
        drop = (k * step) ** 2 / (2 * rho)
        z[k:] = np.maximum(z[k:], height[:-k] - drop)
        z[:-k] = np.maximum(z[:-k], height[k:] - drop)

    path = np.column_stack([xy, z])
    end = polyline_end(path, segments, L_W)
    return path[:end + 1], float(np.mean(z[:end + 1] - height[:end + 1]))


def polyline_end(points, segments, l_w):
    """The index of the last point to keep so that create_wire's resampling (core/wire/
    wire_layout.cpp wire_polyline: each node the first point further along the polyline at
    distance l_w from the previous one) makes exactly `segments` segments."""
    node, piece, count = points[0], 0, 0
    while count < segments:
        for s in range(piece, len(points) - 1):
            b = points[s + 1]
            if np.dot(b - node, b - node) < l_w * l_w:
                continue
            a = node if s == piece else points[s]
            d, w = b - a, a - node
            qa, qb, qc = np.dot(d, d), np.dot(w, d), np.dot(w, w) - l_w * l_w
            root = math.sqrt(max(0.0, qb * qb - qa * qc))
            u = -qc / (qb + root) if qb > 0.0 else (root - qb) / qa
            node, piece, count = a + min(1.0, max(0.0, u)) * d, s, count + 1
            break
        else:
            raise SystemExit("the spiral is too short for the wire")
    return piece + 1  # the rest of the last piece is shorter than l_w


# ---------------------------------------------------------------------------------------
# reading LIGGGHTS' output

def loop_time(out):
    seconds, steps, atoms = re.findall(
        r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms", out)[-1]
    return float(seconds), int(steps), int(atoms)


def timers(out):
    """Pair, Neigh, Comm, Modfy, Outpt, Other time and every fix's time (modify_timing) of the last run."""
    last = out[out.rfind("Loop time of"):]
    t = {k: float(v) for k, v in re.findall(r"^(Pair|Neigh|Comm|Modfy|Outpt|Other)\s+time \(%\) = ([0-9.eE+-]+)", last, re.M)}
    for fix_id, style, v in re.findall(r"^Fix (\S+) (\S+) time \(%\) = ([0-9.eE+-]+)", last, re.M):
        t["fix " + fix_id] = float(v)
    return t


def thermo_rows(out, ncols):
    block = out[:out.rfind("Loop time of")]
    block = block[block.rfind("Step"):]
    number = r"([0-9.eE+-]+)"
    rows = re.findall(r"^\s*\d+" + r"\s+" * 1 + r"\s+".join([number] * ncols) + r"\s*$", block, re.M)
    return np.array([[float(v) for v in r] for r in rows])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--liggghts", default=os.path.join(HERE, "..", "build", "liggghts"))
    parser.add_argument("--steps", type=int, default=2000, help="timed wire sub-steps per case (multiple of 10)")
    parser.add_argument("--drop", type=int, default=2000, help="sub-steps of the wire's fall before the timing")
    parser.add_argument("--seed", type=int, default=11)
    parser.add_argument("--np", type=int, default=1)
    parser.add_argument("--skins", type=float, nargs="*", default=[0.0, 0.02, 0.05, 0.1, 0.2],
                        help="fix wire/grain skin of the extra coupled cases (the pair cache; 0: search every sub-step)")
    args = parser.parse_args()
    args.liggghts = os.path.abspath(args.liggghts)
    work = tempfile.mkdtemp(prefix="wiregrain-bench-")

    liggghts(args, work, "in.pile", PILE.format(seed=args.seed, seed2=args.seed + 1))
    path, gap = wire_path(work, SEGMENTS)
    np.savetxt(os.path.join(work, "wire.txt"), path, fmt="%.9f")
    drop = liggghts(args, work, "in.drop", DROP.format(drop=args.drop))
    beads = int(re.search(r"create_wire: (\d+) beads", drop).group(1))
    drop_rows = thermo_rows(drop, 7)

    results = {}
    for key, label, pair, wire, coupled in CASES:
        columns = NSCD_STATS
        if coupled:
            columns += " f_wg[1] f_wg[7]"
        if pair:
            columns += " c_ww[1] c_ww[4]"
        stats = ("compute ww wire wire/contacts\n" if pair else "") + "thermo_style    custom step " + columns
        fixes = (WIRE_FIXES if wire else "") + ("fix             wg wire wire/grain grains\n" if coupled else "")
        out = liggghts(args, work, f"in.{key}", MEASURE.format(
            gravity_group="all" if wire else "grains", pair=PAIR if pair else "pair_style      none",
            wire=fixes, stats=stats, steps=args.steps))
        seconds, steps, atoms = loop_time(out)
        rows = thermo_rows(out, len(columns.split()))[1:]  # the setup row is not a timed step
        results[key] = dict(label=label, loop=seconds, steps=steps, t=timers(out),
                            stats=dict(zip(columns.split(), rows.mean(axis=0))))

    # the coupled case again for each skin (keyword skin of fix wire/grain: the pair cache)
    skin_results = []
    columns = NSCD_STATS + " f_wg[1] f_wg[7]"
    for skin in args.skins:
        out = liggghts(args, work, f"in.skin{skin}", MEASURE.format(
            gravity_group="all", pair=PAIR, wire=WIRE_FIXES + f"fix             wg wire wire/grain grains skin {skin}\n",
            stats="thermo_style    custom step " + columns, steps=args.steps))
        seconds, steps, _ = loop_time(out)
        rows = thermo_rows(out, len(columns.split()))[1:]
        skin_results.append((skin, seconds / steps * 1e3, timers(out)["fix wg"] / steps * 1e3,
                             dict(zip(columns.split(), rows.mean(axis=0)))))

    a, b, c, d = (results[k] for k in "abcd")
    steps = a["steps"]
    nscd_steps = steps / 10
    ms = 1e3 / steps

    def per_sub(r, key):
        return r["t"].get(key, 0.0) * ms

    print(f"ranks: {args.np}; {atoms} atoms: 900 grains, {beads} beads ({beads - 1} segments); "
          f"{steps} sub-steps timed per case ({nscd_steps:.0f} NSCD steps; dt_SP = 1e-4, dt_NSCD = 1e-3)")
    print(f"wire laid {gap:.2f} above the pile surface on average (rounded profile), fell for {args.drop} "
          f"sub-steps: {drop_rows[-1][1]:.0f} wire-grain contacts at the end; work dir {work}")
    print()
    print(f"{'case':<28}{'loop':>8}{'wire/grain':>11}{'(evals)':>8}{'pair':>8}{'neigh':>8}{'elastic':>9}{'gear':>7}"
          f"{'walls':>7}{'nscd':>7}   {'nscd/NSCD step':>14}{'detect':>8}{'solve':>7}{'sweeps':>7}{'points':>7}")
    print(f"{'':<28}{'ms per sub-step':^71}   {'ms per NSCD step':^29}")
    for key in "abcd":
        r = results[key]
        walls = sum(per_sub(r, "fix " + w) for w in ("floor", "wxlo", "wxhi", "wylo", "wyhi"))
        s = r["stats"]
        print(f"{key + ' ' + r['label']:<28}{r['loop'] * ms:8.3f}{per_sub(r, 'fix wg'):11.3f}"
              f"{s.get('f_wg[7]', 0.0):8.0f}{per_sub(r, 'Pair'):8.3f}"
              f"{per_sub(r, 'Neigh'):8.3f}{per_sub(r, 'fix elastic'):9.3f}{per_sub(r, 'fix integr'):7.3f}"
              f"{walls:7.3f}{per_sub(r, 'fix nscd'):7.3f}   {r['t']['fix nscd'] / nscd_steps * 1e3:14.2f}"
              f"{s['f_nscd[22]'] * 1e3:8.2f}{s['f_nscd[23]'] * 1e3:7.2f}{s['f_nscd[1]']:7.1f}{s['f_nscd[3]']:7.0f}")

    wg = per_sub(a, "fix wg")
    ww = per_sub(a, "Pair") + per_sub(a, "Neigh")
    el = per_sub(a, "fix elastic")
    wg_contacts, wg_evals = a["stats"]["f_wg[1]"], a["stats"]["f_wg[7]"]
    ww_contacts, ww_evals = a["stats"]["c_ww[1]"], a["stats"]["c_ww[4]"]
    print()
    print(f"per sub-step (case a): wire-grain {wg:.3f} ms ({wg_contacts:.0f} contacts, {wg_evals:.0f} exact "
          f"segment-grain evaluations, {wg_evals / (beads - 1):.2f} per segment), wire-wire {ww:.3f} ms (pair {per_sub(a, 'Pair'):.3f} + neighbour lists "
          f"{per_sub(a, 'Neigh'):.3f}; {ww_contacts:.0f} contacts, {ww_evals:.0f} segment-pair evaluations), "
          f"elastic {el:.3f} ms")
    print(f"ratios: wire-grain / wire-wire {wg / ww:.2f}, wire-grain / elastic {wg / el:.2f}, "
          f"wire-wire / elastic {ww / el:.2f}")
    print(f"cross-check by loop time: a - b = {(a['loop'] - b['loop']) * ms:.3f} ms (wire/grain timer "
          f"{wg:.3f}), a - c = {(a['loop'] - c['loop']) * ms:.3f} ms (pair + neighbour timers {ww:.3f})")
    print(f"exact segment-grain evaluations per second: {wg_evals / (wg * 1e-3):.3g} "
          f"(fix wire/grain's whole time: {wg * 1e6 / max(wg_evals, 1):.0f} ns per evaluation, "
          f"{wg * 1e6 / (beads - 1):.0f} ns per segment); segment-pair evaluations per second (pair time): "
          f"{ww_evals / (per_sub(a, 'Pair') * 1e-3):.3g}")
    nscd = {k: results[k]["t"]["fix nscd"] / nscd_steps * 1e3 for k in "abd"}
    print(f"one NSCD step (fix nscd/polyhedra): coupled {nscd['a']:.2f} ms, wire not coupled (b) {nscd['b']:.2f} ms, "
          f"grains alone {nscd['d']:.2f} ms; ratio coupled / alone {nscd['a'] / nscd['d']:.2f} "
          f"(b / d = {nscd['b'] / nscd['d']:.2f} is noise: the same grain motion)")
    if skin_results:
        print()
        print("the pair cache (fix wire/grain skin), the coupled case a again per skin, one after the other:")
        print(f"{'skin':>6}{'loop ms':>9}{'wire/grain ms':>15}{'evals':>8}{'contacts':>10}{'wire/grain / skin 0':>21}")
        base = skin_results[0][2] if skin_results[0][0] == 0 else None
        for skin, loop_ms, wg_ms, st in skin_results:
            ratio = f"{wg_ms / base:21.2f}" if base else f"{'':>21}"
            print(f"{skin:6g}{loop_ms:9.3f}{wg_ms:15.3f}{st['f_wg[7]']:8.0f}{st['f_wg[1]']:10.0f}{ratio}")
    coupled_step = nscd["a"] + 10 * wg
    whole_a, whole_d = a["loop"] / nscd_steps * 1e3, d["loop"] / nscd_steps * 1e3
    print(f"the grains' step with the coupling (NSCD + 10 sub-steps of fix wire/grain): {coupled_step:.2f} ms, "
          f"{coupled_step / nscd['d']:.2f} x the grains alone; the whole coupled system per NSCD step "
          f"(10 wire sub-steps + NSCD): {whole_a:.2f} ms against {whole_d:.2f} ms for the grains alone "
          f"({whole_a / whole_d:.1f} x)")


if __name__ == "__main__":
    main()
