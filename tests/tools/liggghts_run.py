"""Run build/liggghts on a deck and read what it wrote; shared by the styles and
regression tests. Paths come from the environment that ctest sets:
LIGGGHTS (the executable), MPIEXEC (mpirun), WIREGRAIN_SOURCE (repository root),
WIREGRAIN_DECK_TIMEOUT (seconds one liggghts run may take; the sanitized tests set it)."""

import math
import os
import re
import shutil
import subprocess
import tempfile
import unittest

import numpy as np

LIGGGHTS = os.environ.get("LIGGGHTS", "liggghts")
MPIEXEC = os.environ.get("MPIEXEC", "mpirun")
SOURCE = os.environ.get("WIREGRAIN_SOURCE", os.path.join(os.path.dirname(__file__), "..", ".."))
TIMEOUT = float(os.environ.get("WIREGRAIN_DECK_TIMEOUT", "600"))
# The first line of a report of AddressSanitizer, LeakSanitizer or UndefinedBehaviorSanitizer
# (a sanitized build, docs/install.md, "Sanitizers"): a deck test fails on any of them, also
# where the deck is meant to stop with an ERROR.
SANITIZER_REPORT = re.compile(r"^==\d+==ERROR: (Address|Leak)Sanitizer|^\S+:\d+:\d+: runtime error: "
                              r"|^SUMMARY: (Address|Leak|UndefinedBehavior)Sanitizer", re.M)


class Run:
    """The outcome of one liggghts run: return code, screen output, working directory."""

    def __init__(self, returncode, output, workdir):
        self.returncode = returncode
        self.output = output
        self.workdir = workdir

    def path(self, name):
        return os.path.join(self.workdir, name)

    def errors(self):
        return [line for line in self.output.splitlines() if line.startswith("ERROR")]

    def sanitizer_reports(self):
        """The lines that open a sanitizer report (none in a build without sanitizers)."""
        return [m.group(0) for m in SANITIZER_REPORT.finditer(self.output)]

    def thermo(self, which=-1):
        """The thermo table of a run (default the last; 0 the first) as {column: numpy array}."""
        lines = self.output.splitlines()
        heads = [k for k, line in enumerate(lines) if line.split()[:1] == ["Step"]]
        if not heads:
            raise AssertionError("no thermo output found:\n" + self.output[-3000:])
        header = lines[heads[which]].split()
        rows = []
        for line in lines[heads[which] + 1:]:
            if line.startswith("WARNING"):   # warnings may come between thermo rows
                continue
            words = line.split()
            if len(words) != len(header):
                break
            try:
                rows.append([float(w) for w in words])
            except ValueError:
                break
        data = np.array(rows)
        # LIGGGHTS prints c_ID[1] as "ID": later columns of the same name become "ID#2", ...
        names, seen = [], {}
        for name in header:
            seen[name] = seen.get(name, 0) + 1
            names.append(name if seen[name] == 1 else f"{name}#{seen[name]}")
        return {name: data[:, k] for k, name in enumerate(names)}


def run(deck_text, np_ranks=1, variables=None, workdir=None, files=None, extra_args=()):
    """Write deck_text to in.deck in a fresh directory (or workdir) and run it.
    files: {name: text} written next to the deck."""
    workdir = workdir or tempfile.mkdtemp(prefix="wiregrain-")
    # (UTF-8 whatever the locale: decks hold §, μ, ...; a library imported by a test, e.g.
    # matplotlib, may set the C locale, whose default encoding is ASCII)
    with open(os.path.join(workdir, "in.deck"), "w", encoding="utf-8") as f:
        f.write(deck_text)
    for name, text in (files or {}).items():
        with open(os.path.join(workdir, name), "w", encoding="utf-8") as f:
            f.write(text)
    cmd = [LIGGGHTS, "-echo", "screen", "-log", "log.liggghts", "-in", "in.deck"]
    for key, value in (variables or {}).items():
        cmd += ["-var", key, str(value)]
    cmd += list(extra_args)
    if np_ranks > 1:
        cmd = [MPIEXEC, "--allow-run-as-root", "--oversubscribe", "-np", str(np_ranks)] + cmd
    # (Open MPI's temporary directory in the run's own folder: runs started at once by
    # ctest -j raced to create the shared /tmp/ompi.HOST.UID and one stopped with "File exists")
    env = dict(os.environ, OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_orte_tmpdir_base=workdir)
    proc = subprocess.run(cmd, cwd=workdir, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          stdin=subprocess.DEVNULL, timeout=TIMEOUT, env=env)
    return Run(proc.returncode, proc.stdout.decode(errors="replace"), workdir)


def deck_head(style, processors=None):
    """The first lines of a test deck: LJ units, the atom style, an atom map without sorting,
    a non-periodic box, and `processors` when given (e.g. "* 1 1": one rank per x slab)."""
    text = (f"units           lj\natom_style      {style}\natom_modify     map array sort 0 0.0\n"
            "boundary        f f f\n")
    return text + (f"processors      {processors}\n" if processors else "")


def deck_box(style, xy, z, types):
    """deck_head(style) and a box [-xy, xy]^2 x [z0, z1] with `types` atom types."""
    return deck_head(style) + (f"region          box block -{xy} {xy} -{xy} {xy} {z[0]} {z[1]}\n"
                               f"create_box      {types} box\n")


_created_grains = {}  # (shape, count, density, sweep, box) -> the create_grains run


def grains_data(shape, poses, density=1.0, sweep=0.0, box=(-30, 30, -30, 30, -1, 60)):
    """Run create_grains for len(poses) grains of one fixed shape (e.g. "cube 1") and
    rewrite the data file with the given poses [(x, y, z, qw, qi, qj, qk), ...].
    Returns the run (its workdir holds grains.data and grains.shapes). A sphere ("sphere R")
    takes no sweep (its radius is its sweep radius). The grains of one (shape, count,
    density, sweep, box) are created once per test process and copied into a fresh
    directory for every call, so a caller may rewrite its files."""
    key = (shape, len(poses), density, sweep, tuple(box))
    if key not in _created_grains:
        sweep_words = "" if shape.startswith("sphere") else f" sweep {sweep}"
        _created_grains[key] = run(f"""
units lj
atom_style polyhedron
atom_modify map array sort 0 0.0
boundary f f f
region box block {' '.join(map(str, box))}
create_box 1 box
create_grains 1 {len(poses)} random box seed 7 shape {shape}{sweep_words} density {density}
write_data grains.data
grain_shapes write grains.shapes
""")
    created = _created_grains[key]
    made = Run(created.returncode, created.output, tempfile.mkdtemp(prefix="wiregrain-"))
    for name in ("grains.data", "grains.shapes"):
        if os.path.exists(created.path(name)):
            shutil.copy(created.path(name), made.path(name))
    if created.returncode != 0:
        return made
    with open(made.path("grains.data")) as f:
        lines = f.read().splitlines()
    k = next(i for i, line in enumerate(lines) if line.startswith("Atoms")) + 2
    for n, pose in enumerate(poses):
        words = lines[k + n].split()
        x, y, z, qw, qi, qj, qk = pose
        words[4:8] = [repr(qw), repr(qi), repr(qj), repr(qk)]
        words[8:11] = [repr(x), repr(y), repr(z)]
        lines[k + n] = " ".join(words)
    with open(made.path("grains.data"), "w") as f:
        f.write("\n".join(lines) + "\n")
    return made


def warning_lines(output, text=""):
    """The WARNING lines containing `text`, without 'WARNING: ' and the source location."""
    return [re.sub(r" \([^()]*:\d+\)$", "", line[len("WARNING: "):]) for line in output.splitlines()
            if line.startswith("WARNING: ") and text in line]


def contact_time_step_warning(style, dt, k, m, mass_name, zeta, gear5):
    """The time-step warning of a wire contact style (common/contact_checks.h), its numbers
    computed here: a spring k on a mass m with damping ratio ζ, ω = √(k/m); velocity Verlet dt_crit = 2/ω (√(1+ζ²) − ζ),
    gear5 0.313/ω (√(1+ζ²) − ζ), and at most 0.075/(ζ ω)."""
    omega = math.sqrt(k / m)
    damped = math.sqrt(1 + zeta * zeta) - zeta
    critical = 2 / omega * damped
    limit = min(0.313 / omega * damped, 0.075 / (zeta * omega) if zeta > 0 else math.inf) if gear5 else critical
    return (f"{style}: timestep {dt:.6g} exceeds the stable limit {limit:.6g} of the "
            f"{'gear5' if gear5 else 'verlet'} integrator for its contact springs (k {k:.6g} on mass {m:.6g}, "
            f"{mass_name}, damping ratio {zeta:.3g}: contact critical time step {critical:.6g}); "
            f"use a smaller timestep")


def contact_overlap_warning(style, step, which, overlap, r_w, remedy):
    """The large-overlap warning of a wire contact style (common/contact_checks.h)."""
    return (f"{style}: at step {step} {which} overlap by {overlap:.3g} ({overlap / r_w:.4g} r_w, beyond 0.5 r_w: "
            f"the soft contact assumes small overlaps); use a smaller timestep or {remedy}")


def last_snapshot(path, item):
    """The last snapshot of a LAMMPS dump text file: its column names (from the line
    'ITEM: <item> ...') and its rows as an array (empty when it has none)."""
    with open(path) as f:
        lines = f.read().splitlines()
    starts = [k for k, line in enumerate(lines) if line.startswith("ITEM: TIMESTEP")]
    if not starts:
        raise AssertionError(f"{path}: no snapshot")
    block = lines[starts[-1]:]
    count = int(block[3])
    k = next(k for k, line in enumerate(block) if line.startswith("ITEM: " + item))
    names = block[k].split()[2:]
    data = np.array([[float(w) for w in line.split()] for line in block[k + 1:k + 1 + count]])
    return names, data.reshape(count, len(names))


def read_dump(path, columns=None):
    """Last snapshot of a LAMMPS 'dump custom' text file as {column: array}, sorted by id."""
    names, data = last_snapshot(path, "ATOMS")
    if "id" in names:
        data = data[np.argsort(data[:, names.index("id")])]
    return {name: data[:, j] for j, name in enumerate(names)}


def dump_frames(path):
    """Every snapshot of a LAMMPS 'dump custom' text file: [(step, {column: array})], each
    sorted by id when it has one."""
    with open(path) as f:
        lines = f.read().splitlines()
    frames = []
    for k, line in enumerate(lines):
        if line.startswith("ITEM: TIMESTEP"):
            count = int(lines[k + 3])
            names = lines[k + 8].split()[2:]
            data = np.array([[float(w) for w in row.split()] for row in lines[k + 9:k + 9 + count]])
            data = data.reshape(count, len(names))
            if "id" in names:
                data = data[np.argsort(data[:, names.index("id")])]
            frames.append((int(lines[k + 1]), {name: data[:, j] for j, name in enumerate(names)}))
    return frames


def read_local_dump(path):
    """Last snapshot of a LAMMPS 'dump local' text file as {column: array} (rows in the
    file's order; empty arrays when the snapshot has no entries)."""
    names, data = last_snapshot(path, "ENTRIES")
    return {name: data[:, j] for j, name in enumerate(names)}


def align_by_position(reference, other, columns=("x", "y", "z")):
    """Reorder the snapshot `other` so that atom k is the one nearest to atom k of
    `reference` (atom ids from create_atoms depend on the MPI decomposition)."""
    p = np.column_stack([reference[c] for c in columns])
    q = np.column_stack([other[c] for c in columns])
    assert len(p) == len(q), (len(p), len(q))
    d2 = ((p[:, None, :] - q[None, :, :]) ** 2).sum(axis=2)
    order = np.argmin(d2, axis=1)
    assert len(set(order.tolist())) == len(order), "positions do not match one to one"
    return {name: values[order] for name, values in other.items()}


def full_precision(text, dump_id):
    """Deck text with `dump_modify <dump_id> format` set to 17 significant digits for the
    custom dump <dump_id> (id first, then floats), so dumps compare at round-off."""
    lines = text.splitlines()
    for k, line in enumerate(lines):
        words = line.split()
        if words[:2] == ["dump", dump_id] and words[3] == "custom":
            columns = words[6:]
            fmt = " ".join("%d" if c in ("id", "type", "ix", "iy", "iz") else "%.17g" for c in columns)
            lines.insert(k + 1, f'dump_modify {dump_id} format "{fmt}"')
            return "\n".join(lines) + "\n"
    raise AssertionError(f"no custom dump {dump_id!r} in the deck")


def static_contact_measurement(group, displacement, steps=100, dt=1e-3):
    """Deck lines that measure a contact's stiffness statically on `group` (the atoms that
    touch something at a known overlap, no gravity): the summed force at rest (first
    thermo table, normal spring), then the group moved by `displacement` along x at a
    constant speed with fix move and stopped (last table: tangential spring, no damping).
    Thermo columns c_f[1..3] = the group's summed fx fy fz, not normalised."""
    return f"""
timestep        {dt!r}
compute         f {group} reduce sum fx fy fz
thermo_style    custom step c_f[1] c_f[2] c_f[3]
thermo_modify   format float %.17g norm no
thermo          1
run             0
fix             mv {group} move linear {displacement / (steps * dt)!r} 0 0
run             {steps}
unfix           mv
velocity        {group} set 0 0 0
run             0
"""


def loaded_contact_measurement(group, ids, normal_force, tangential_force, steps, dt):
    """Deck lines that measure a contact's stiffness under load (the complement of
    static_contact_measurement, which imposes the displacement): every atom of `group` is
    pushed by the constant force `normal_force` (fx, fy, fz) and left `steps` steps to
    settle (first thermo table), then `tangential_force` is added on top and it settles
    again (last table). The deck must damp the contact (a dashpot, no other damping, so
    the rest state is exactly spring = load). Thermo columns, full precision: for each
    atom id k in `ids`, x{k} y{k} z{k} and its speed s{k}; rows at the start and end of
    each run."""
    lines = [f"timestep        {dt!r}"]
    columns = []
    for k in ids:
        for c in "xyz":
            lines.append(f"variable        {c}{k} equal {c}[{k}]")
            columns.append(f"v_{c}{k}")
        lines.append(f"variable        s{k} equal sqrt(vx[{k}]^2+vy[{k}]^2+vz[{k}]^2)")
        columns.append(f"v_s{k}")
    total = [n + t for n, t in zip(normal_force, tangential_force)]
    lines += [f"thermo_style    custom step {' '.join(columns)}",
              "thermo_modify   format float %.17g norm no",
              f"thermo          {steps}",
              f"fix             load {group} addforce {' '.join(repr(float(f)) for f in normal_force)}",
              f"run             {steps}",
              f"fix             load {group} addforce {' '.join(repr(float(f)) for f in total)}",
              f"run             {steps}"]
    return "\n" + "\n".join(lines) + "\n"


def deck(name):
    """Text of a deck shipped in the repository (path relative to the repository root)."""
    with open(os.path.join(SOURCE, name), encoding="utf-8") as f:
        return f.read()


class DeckTestCase(unittest.TestCase):
    """Assertions shared by deck tests."""

    def assertNoSanitizerReport(self, result):
        if result.sanitizer_reports():
            self.fail(f"sanitizer report in {result.workdir}:\n" + result.output[-12000:])

    def assertRanCleanly(self, result):
        self.assertNoSanitizerReport(result)
        if result.returncode != 0 or result.errors():
            self.fail(f"liggghts failed (exit {result.returncode}) in {result.workdir}:\n"
                      + result.output[-4000:])

    def assertStopsWith(self, result, message):
        """The run must stop with 'ERROR: <message>' (and not crash or hang)."""
        self.assertNoSanitizerReport(result)
        errors = result.errors()
        self.assertNotEqual(result.returncode, 0, "run did not fail:\n" + result.output[-2000:])
        self.assertTrue(errors, "no ERROR line; output:\n" + result.output[-2000:])
        self.assertTrue(any(message in line for line in errors),
                        f"expected an ERROR line containing {message!r}, got {errors}")
        for crash in ("Segmentation fault", "Aborted", "core dumped", "signal"):
            self.assertNotIn(crash, result.output)


def main():
    unittest.main(verbosity=2)
