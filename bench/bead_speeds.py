#!/usr/bin/python3
"""Bead speeds of a wire from a LIGGGHTS text dump (`dump ID wire custom N FILE id vx vy vz`,
`dump_modify ID sort id`): how many beads move at r.m.s. speeds above 0.5 and 0.1, the
median r.m.s. speed, and for the fastest beads the main frequency of their velocity
(the r.m.s. and the spectrum over the samples after the first third, which is left out
as the transient of a change of setting).

    bench/bead_speeds.py DUMP --interval DT [--top 6]

DT: the time between two dumps (N × timestep). Used to find the beads that rattle under
damped contacts in the Table 1 column: in.column resumed from a restart with the dump above
added, once per setting."""

import argparse

import numpy as np


def read_dump(path):
    """Velocities of each complete frame (frames x beads x 3) and the bead ids."""
    frames, ids = [], None
    with open(path) as f:
        blocks = f.read().split("ITEM: TIMESTEP\n")[1:]
    for block in blocks:
        rows = block.split("\n")
        n = int(rows[2])
        if len(rows) < 8 + n or not rows[8 + n - 1].strip():
            break  # the last frame of a run still writing
        data = np.array([[float(w) for w in r.split()] for r in rows[8:8 + n]])
        frames.append(data[:, 1:4])
        ids = data[:, 0].astype(int)
    return np.array(frames), ids


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("dump")
    parser.add_argument("--interval", type=float, required=True)
    parser.add_argument("--top", type=int, default=6)
    args = parser.parse_args()
    velocity, ids = read_dump(args.dump)
    kept = velocity[len(velocity) // 3:]
    speed = np.linalg.norm(kept, axis=2)
    rms = np.sqrt((speed ** 2).mean(axis=0))
    print(f"{len(kept)} samples of {len(ids)} beads: r.m.s. speed > 0.5: {(rms > 0.5).sum()}, > 0.1: "
          f"{(rms > 0.1).sum()}, median {np.median(rms):.3g}, fastest sample {speed.max():.3g}")
    for b in np.argsort(-rms)[:args.top]:
        v = kept[:, b, :] - kept[:, b, :].mean(axis=0)
        power = (np.abs(np.fft.rfft(v, axis=0)) ** 2).sum(axis=1)
        frequency = np.fft.rfftfreq(len(v), args.interval)
        k = 1 + np.argmax(power[1:])
        print(f"  bead {ids[b]}: r.m.s. speed {rms[b]:.2f}, main frequency {frequency[k]:.1f} per time unit "
              f"({power[k] / power.sum():.0%} of the power)")


if __name__ == "__main__":
    main()
