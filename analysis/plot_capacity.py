"""Polar-style plot of `graspsim capacity --direction all` outputs (Debian's /usr/bin/python3 + matplotlib).

Usage: /usr/bin/python3 analysis/plot_capacity.py OUT.png DIR [DIR ...]

Reads DIR/capacity.json (format in include/graspsim/capacity/capacity_files.h) from each folder
(e.g. one full-contact run and one approx run; with several, each is labelled by its folder's
name) and draws, per folder, the slip-onset force of the
six axis directions on three polar panels (the x-y, y-z and z-x planes of G: each axis direction
at its angle in the plane, its load as the radius), and the three torques as bars. A direction
whose ramp ended without slip has no onset: it is drawn as an open marker at the ramp's last load
(max_load_n / max_load_nm), a lower bound of its capacity, in its run's colour. Nothing here
computes a pass/fail.
"""

import collections
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.lines import Line2D

PLANES = [("x", "y"), ("y", "z"), ("z", "x")]
TORQUES = ("x", "y", "z")
BOUND_LABEL = "no slip up to (lower bound)"
BOUND_STYLE = dict(linestyle="none", marker="o", markersize=9, markerfacecolor="none", markeredgewidth=1.5)

# forces, torques: direction -> slip onset (None: no onset); force_bounds, torque_bounds:
# direction -> the last load of a ramp that did not slip.
Run = collections.namedtuple("Run", "label forces torques force_bounds torque_bounds")


def load(folder):
    with open(os.path.join(folder, "capacity.json")) as f:
        data = json.load(f)
    forces, torques, force_bounds, torque_bounds = {}, {}, {}, {}
    for m in data["measurements"]:
        torque = m["load"] == "torque"
        unit = "nm" if torque else "n"
        # `graspsim validate` names its torques "torque x" ...; `graspsim capacity` names them "x" ...
        direction = m["direction"].removeprefix("torque ")
        onset = m.get("slip_onset_" + unit)
        (torques if torque else forces)[direction] = onset
        reached = m.get("max_load_" + unit)
        if onset is None and m.get("method", "ramp") == "ramp" and reached is not None:
            (torque_bounds if torque else force_bounds)[direction] = reached
    label = data["measurements"][0]["mode"] if data["measurements"] else folder
    real = data["measurements"][0].get("realization") if data["measurements"] else None
    return Run(label + (" (" + real + ")" if real else ""), forces, torques, force_bounds, torque_bounds)


def draw_plane(ax, runs, a, b):
    names = [a, b, "-" + a, "-" + b, a]
    angles = [0, math.pi / 2, math.pi, 3 * math.pi / 2, 2 * math.pi]
    bounded_here = False
    for run in runs:
        # A direction that did not slip within the ramp has no onset: a gap in the line, not a zero.
        radii = [math.nan if run.forces.get(n) is None else run.forces[n] for n in names]
        (line,) = ax.plot(angles, radii, marker="o", label=run.label)
        bounded = [(t, run.force_bounds[n]) for t, n in zip(angles[:4], names[:4]) if n in run.force_bounds]
        if bounded:
            ax.plot([t for t, _ in bounded], [r for _, r in bounded], color=line.get_color(), label="_" + BOUND_LABEL,
                    **BOUND_STYLE)
            bounded_here = True
    if bounded_here:  # the open markers sit at the largest load: not on the rim, half hidden
        ax.set_rmax(ax.get_rmax() * 1.1)
    ax.set_xticks(angles[:4])
    ax.set_xticklabels(names[:4])
    ax.set_title(f"slip onset (N), {a}-{b} plane", fontsize=9)


def draw_torques(ax, runs, bounded_anywhere):
    width = 0.8 / max(1, len(runs))
    for i, run in enumerate(runs):
        x = [j + i * width for j in range(3)]
        bars = ax.bar(x, [math.nan if run.torques.get(n) is None else run.torques[n] for n in TORQUES], width, label=run.label)
        bounded = [(x[j], run.torque_bounds[n]) for j, n in enumerate(TORQUES) if n in run.torque_bounds]
        if bounded:
            ax.plot([p for p, _ in bounded], [r for _, r in bounded], color=bars.patches[0].get_facecolor(),
                    label="_" + BOUND_LABEL, **BOUND_STYLE)
    ax.set_xticks([j + 0.4 - width / 2 for j in range(3)])
    ax.set_xticklabels(["torque " + n for n in TORQUES])
    ax.set_ylabel("slip onset (N m)")
    handles, labels = ax.get_legend_handles_labels()
    if bounded_anywhere:  # one entry for the open markers of every panel and run, above the bars
        handles.append(Line2D([], [], color="0.3", label=BOUND_LABEL, **BOUND_STYLE))
        labels.append(BOUND_LABEL)
        ax.set_ylim(0, ax.get_ylim()[1] * 1.3)
    ax.legend(handles, labels, fontsize=7)


def draw(runs):
    fig = plt.figure(figsize=(13, 3.6))
    for k, (a, b) in enumerate(PLANES):
        draw_plane(fig.add_subplot(1, 4, k + 1, projection="polar"), runs, a, b)
    bounded_anywhere = any(run.force_bounds or run.torque_bounds for run in runs)
    draw_torques(fig.add_subplot(1, 4, 4), runs, bounded_anywhere)
    fig.tight_layout()
    return fig


def load_runs(folders):
    runs = [load(d) for d in folders]
    if len(runs) > 1:  # several runs: each labelled with its folder's name (e.g. the variant)
        runs = [r._replace(label=os.path.basename(os.path.normpath(d))) for d, r in zip(folders, runs)]
    return runs


def main(argv):
    if len(argv) < 3:
        sys.exit("usage: plot_capacity.py OUT.png DIR [DIR ...]")
    draw(load_runs(argv[2:])).savefig(argv[1], dpi=110)


if __name__ == "__main__":
    main(sys.argv)
