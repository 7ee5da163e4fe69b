"""Polar-style plot of `graspsim capacity --direction all` outputs (Debian's /usr/bin/python3 + matplotlib).

Usage: /usr/bin/python3 analysis/plot_capacity.py OUT.png DIR [DIR ...]

Reads DIR/capacity.json (format in include/graspsim/capacity/capacity_files.h) from each folder
(e.g. one full-contact run and one approx run; with several, each is labelled by its folder's
name) and draws, per folder, the slip-onset force of the
six axis directions on three polar panels (the x-y, y-z and z-x planes of G: each axis direction
at its angle in the plane, its load as the radius; a direction that did not slip within its ramp
is left out), and the three torques as bars. Nothing here computes a pass/fail.
"""

import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

PLANES = [("x", "y"), ("y", "z"), ("z", "x")]


def load(folder):
    with open(os.path.join(folder, "capacity.json")) as f:
        data = json.load(f)
    forces, torques = {}, {}
    for m in data["measurements"]:
        key = "slip_onset_nm" if m["load"] == "torque" else "slip_onset_n"
        # `graspsim validate` names its torques "torque x" ...; `graspsim capacity` names them "x" ...
        direction = m["direction"].removeprefix("torque ")
        (torques if m["load"] == "torque" else forces)[direction] = m.get(key)
    label = data["measurements"][0]["mode"] if data["measurements"] else folder
    real = data["measurements"][0].get("realization") if data["measurements"] else None
    return (label + (" (" + real + ")" if real else "")), forces, torques


def main(argv):
    if len(argv) < 3:
        sys.exit("usage: plot_capacity.py OUT.png DIR [DIR ...]")
    runs = [load(d) for d in argv[2:]]
    if len(runs) > 1:  # several runs: each labelled with its folder's name (e.g. the variant)
        runs = [(os.path.basename(os.path.normpath(d)),) + r[1:] for d, r in zip(argv[2:], runs)]
    fig = plt.figure(figsize=(13, 3.6))
    for k, (a, b) in enumerate(PLANES):
        ax = fig.add_subplot(1, 4, k + 1, projection="polar")
        for label, forces, _ in runs:
            names = [a, b, "-" + a, "-" + b, a]
            angles = [0, math.pi / 2, math.pi, 3 * math.pi / 2, 2 * math.pi]
            # A direction that did not slip within the ramp has no onset: a gap, not a zero.
            radii = [math.nan if forces.get(n) is None else forces[n] for n in names]
            ax.plot(angles, radii, marker="o", label=label)
        ax.set_xticks([0, math.pi / 2, math.pi, 3 * math.pi / 2])
        ax.set_xticklabels([a, b, "-" + a, "-" + b])
        ax.set_title(f"slip onset (N), {a}-{b} plane", fontsize=9)
    ax = fig.add_subplot(1, 4, 4)
    width = 0.8 / max(1, len(runs))
    for i, (label, _, torques) in enumerate(runs):
        ax.bar([j + i * width for j in range(3)], [math.nan if torques.get(n) is None else torques[n] for n in ("x", "y", "z")],
               width, label=label)
    ax.set_xticks([j + 0.4 - width / 2 for j in range(3)])
    ax.set_xticklabels(["torque x", "torque y", "torque z"])
    ax.set_ylabel("slip onset (N m)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(argv[1], dpi=110)


if __name__ == "__main__":
    main(sys.argv)
