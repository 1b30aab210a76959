#!/usr/bin/python3
"""What in.column's early end of a phase (`ke_stop`) would do to a column, read from one run
that never stopped early: the run made with a ke_stop far below any kinetic energy, so that
both phases ran in chunks of t_check and the thermo output has the kinetic energy per grain
at the end of every chunk.

    mpirun -np 2 build/liggghts -in input_scripts/in.column -var ke_stop 1e-30 -var t_check 0.5 > out.txt
    postprocess/early_end.py out.txt --ke-stop 1e-4 1e-5 1e-6 [--ke-of grains|all] [--t-quiet 5]
        [--free-dist 2] [--v-wall 0.02] [--a-max 1] [--json]

For each ke_stop, the deck's rule (input_scripts/in.run_until_quiet) applied to the recorded
chunks (after every chunk: quiet += t_check if KE per grain < ke_stop, else quiet = 0; the
phase ends once quiet >= t_quiet, the wall phase not before the walls have moved free_dist
a_max), with the kinetic energy of the grains (thermo column ke_grain, the deck's default
ke_of) or of grains and wire (ke_all; the column ke_rel of a deck's output without ke_of):
  relaxation  the time it would have ended at and the share of its steps skipped; what the
              column does after an earlier start of the walls is another trajectory, so no
              observables are given for it (run the deck with that ke_stop);
  wall phase  the time it would have ended at, the share of its steps skipped, its loop time
              skipped (LIGGGHTS' "Loop time" of each chunk), and the observables at that time
              (the chunk's last thermo row: H_n, φ_p, U_s/L, z_wpc) against those at the end:
              along the same trajectory up to the stop, so these are exactly what the early
              end gives, if the relaxation ran to the same time.
t_check and the time step are read from the output (the chunks' length, the deck's
"in.column: dt_SP ..." line)."""

import argparse
import json
import re

OBSERVABLES = (("Hn", "H_n"), ("phi[1]", "phi_p"), ("Us", "U_s/L"), ("zwpc", "z_wpc"))


def chunks(text, ke_of="grains"):
    """The chunks of both phases: [(phase, end step, KE per grain, {column: value}, loop seconds)],
    phase 'relax' (a run whose thermo has the KE but no Hn, nor the deposition's wtop) or 'walls' (both): each run's
    last thermo row before its "Loop time" line (warnings between the rows are skipped).
    The KE is the column ke_grain or ke_all (ke_of), or ke_rel (grains and wire) in the
    output of a deck without ke_of."""
    # (LIGGGHTS cuts thermo column names to 8 characters: v_ke_grains is "ke_grain")
    wanted = tuple(name[:8] for name in (("ke_" + ke_of, "ke_rel") if ke_of == "all" else ("ke_" + ke_of,)))
    found, header, last = [], None, None
    for line in text.splitlines():
        words = line.split()
        if words[:1] == ["Step"]:
            header, last = words, None
        elif words[:2] == ["Loop", "time"]:
            column = next((c for c in wanted if header is not None and c in header), None)
            # (the deposition's thermo has the KE too, and the top of the wire, wtop, which tells it apart)
            if column is not None and last is not None and "wtop" not in header:
                row = dict(zip(header, last))
                found.append(("walls" if "Hn" in header else "relax", int(row["Step"]), row[column], row,
                              float(words[3])))
            header, last = None, None
        elif header is not None and len(words) == len(header) and re.fullmatch(r"-?\d+", words[0]):
            try:
                last = [float(w) for w in words]
            except ValueError:
                pass
    return found


def stop_index(series, ke_stop, t_check, t_quiet, first_allowed=0):
    """Index of the chunk after which the deck stops (its rule, in.column), or None."""
    quiet = 0.0
    for k, ke in enumerate(series):
        quiet = quiet + t_check if ke < ke_stop else 0.0
        if quiet >= t_quiet - 1e-9 and k >= first_allowed:
            return k
    return None


def analyse(text, ke_stops, t_quiet, free_dist, v_wall, a_max, ke_of="grains"):
    m = re.search(r"^in\.column: dt_SP (\S+), dt_NSCD", text, re.M)
    if not m:
        raise SystemExit("early_end.py: no 'in.column: dt_SP ...' line: not an in.column output")
    dt = float(m.group(1))
    found = chunks(text, ke_of)
    result = {"dt": dt, "phases": {}}
    for phase in ("relax", "walls"):
        part = [c for c in found if c[0] == phase]
        if len(part) < 2:
            raise SystemExit(f"early_end.py: the {phase} phase has {len(part)} chunks with a ke_{ke_of} column: run "
                             "the deck with ke_stop far below any kinetic energy (e.g. -var ke_stop 1e-30)")
        steps = [c[1] for c in part]
        chunk_steps = steps[1] - steps[0]
        t_check = chunk_steps * dt
        start = steps[0] - chunk_steps  # the phase's first step (its first chunk is full length)
        first_allowed = 0
        if phase == "walls":
            free_steps = round(free_dist * a_max / (v_wall * dt))
            first_allowed = next((k for k in range(len(steps)) if (k + 1) * chunk_steps >= free_steps), len(steps))
        rows = []
        for ke_stop in ke_stops:
            k = stop_index([c[2] for c in part], ke_stop, t_check, t_quiet, first_allowed)
            row = {"ke_stop": ke_stop, "stops": k is not None}
            end = part[k] if k is not None else part[-1]
            row["t"] = end[1] * dt
            row["steps_skipped"] = (steps[-1] - end[1]) / (steps[-1] - start)
            row["loop_seconds_skipped"] = sum(c[4] for c in part[k + 1:]) if k is not None else 0.0
            if phase == "walls":
                row["at_stop"] = {name: end[3][col] for col, name in OBSERVABLES}
            rows.append(row)
        info = {"t_start": start * dt, "t_end": steps[-1] * dt, "t_check": t_check, "chunks": len(part),
                "loop_seconds": sum(c[4] for c in part), "ke_rel": [[c[1] * dt, c[2]] for c in part],
                "candidates": rows}
        if phase == "walls":
            info["final"] = {name: part[-1][3][col] for col, name in OBSERVABLES}
        result["phases"][phase] = info
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("output", help="the screen output or log.liggghts of the run")
    parser.add_argument("--ke-stop", type=float, nargs="+", required=True)
    parser.add_argument("--ke-of", choices=("grains", "all"), default="grains",
                        help="whose kinetic energy: the grains' (default, as the deck) or everything's")
    parser.add_argument("--t-quiet", type=float, default=5.0)
    parser.add_argument("--free-dist", type=float, default=2.0)
    parser.add_argument("--v-wall", type=float, default=0.02)
    parser.add_argument("--a-max", type=float, default=1.0)
    parser.add_argument("--json", action="store_true", help="print the analysis as one JSON line at the end")
    args = parser.parse_args()
    with open(args.output, errors="replace") as f:
        text = f.read()
    result = analyse(text, args.ke_stop, args.t_quiet, args.free_dist, args.v_wall, args.a_max, args.ke_of)
    for phase, info in result["phases"].items():
        kes = [ke for _, ke in info["ke_rel"]]
        print(f"{phase}: t {info['t_start']:g} to {info['t_end']:g}, {info['chunks']} chunks of {info['t_check']:g}, "
              f"loop time {info['loop_seconds']:.0f} s; KE per grain (m g a_max) from {kes[0]:.3g} to {kes[-1]:.3g}, "
              f"lowest {min(kes):.3g}")
        for row in info["candidates"]:
            line = (f"  ke_stop {row['ke_stop']:g}: " +
                    (f"ends at t = {row['t']:g}, {100 * row['steps_skipped']:.1f} % of the steps skipped"
                     if row["stops"] else "does not end early"))
            if phase == "walls" and row["stops"]:
                line += f" ({row['loop_seconds_skipped']:.0f} s of loop time); " + ", ".join(
                    f"{name} {row['at_stop'][name]:.6g} (end {info['final'][name]:.6g})" for _, name in OBSERVABLES)
            print(line)
    if args.json:
        print(json.dumps(result))


if __name__ == "__main__":
    main()
