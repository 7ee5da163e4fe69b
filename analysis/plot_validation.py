"""Plots of a `graspsim validate` output folder (run with Debian's /usr/bin/python3 + matplotlib).

Usage: /usr/bin/python3 analysis/plot_validation.py DIR

Reads DIR/results.csv and DIR/runs/<run>/{trajectory,contacts,events}.csv (formats in
include/graspsim/results/result_files.h and include/graspsim/validation/validation_report.h)
and writes, per experiment (scenario):
  DIR/<experiment>_trajectory.png  object centre of mass vs time, full contact vs approximation,
                                   one column per perturbation;
  DIR/<experiment>_quality.png     grasp quality vs time with the engaged intervals shaded;
  DIR/<experiment>_forces.png      summed contact normal force per hand body (full contact);
  DIR/<experiment>_error.png       object position error of each variant vs full contact, one
                                   panel per perturbation.
Each variant has one colour and line style in every panel of every figure (make_styles), every
panel has its own legend naming each line it shows, and every axis says its unit;
tests/analysis/plot_validation_test.py checks this.
The graspsim CLI runs this script after the suite (`graspsim validate`); it can also be rerun by
hand on an existing folder. Nothing here computes a pass/fail: the bounds live in the C++ suite.
"""

import csv
import math
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend choice)


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def read_trajectory(folder):
    rows = read_rows(os.path.join(folder, "trajectory.csv"))
    t = [float(r["time_s"]) for r in rows]
    p = [[float(r["object_%s_m" % a]) for a in "xyz"] for r in rows]
    q = [float(r["grasp_quality_n"]) for r in rows]
    return t, p, q


def read_engaged_intervals(folder, end_time):
    path = os.path.join(folder, "events.csv")
    if not os.path.exists(path):
        return []
    intervals, start = [], None
    for r in read_rows(path):
        if r["event"] == "engage":
            start = float(r["time_s"])
        elif r["event"] == "release" and start is not None:
            intervals.append((start, float(r["time_s"])))
            start = None
    if start is not None:
        intervals.append((start, end_time))
    return intervals


def read_normal_forces(folder):
    """Summed normal force per hand body at each output time."""
    per_body = defaultdict(lambda: defaultdict(float))
    times = set()
    for r in read_rows(os.path.join(folder, "contacts.csv")):
        t = float(r["time_s"])
        times.add(t)
        per_body[r["body_a"]][t] += float(r["normal_force_n"])
    times = sorted(times)
    return times, {b: [f.get(t, 0.0) for t in times] for b, f in per_body.items()}


def position_error(reference, candidate):
    ref = {round(t, 9): p for t, p in zip(reference[0], reference[1])}
    ts, errors = [], []
    for t, p in zip(candidate[0], candidate[1]):
        r = ref.get(round(t, 9))
        if r is not None:
            ts.append(t)
            errors.append(1000 * math.dist(p, r))
    return ts, errors


def group_runs(results):
    """experiment -> perturbation -> list of result rows (full first)."""
    groups = defaultdict(lambda: defaultdict(list))
    for r in results:
        if r["id"].endswith("_long-hold"):
            continue
        groups[r["scenario"]][r["perturbation"]].append(r)
    for experiment in groups.values():
        for rows in experiment.values():
            rows.sort(key=lambda r: r["variant"] != "full")
    return groups


# One colour and line style per variant (or per hand body), the same in every panel of every
# figure: assigned once from the sorted names of everything that is plotted, never from the order
# in which a panel happens to draw its lines (a variant missing from one panel must not shift the
# colours of the others).
COLOURS = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown", "tab:pink",
           "tab:olive", "tab:cyan", "tab:gray"]
DASHES = ["-", "--", "-.", ":"]


def make_styles(names, first=None):
    """name -> {"color", "linestyle"}: distinct for every name; `first` (if present) gets the first style."""
    ordered = sorted(set(names), key=lambda n: (n != first, n))
    return {n: {"color": COLOURS[i % len(COLOURS)], "linestyle": DASHES[(i // len(COLOURS) + i) % len(DASHES)]}
            for i, n in enumerate(ordered)}


def variant_styles(results):
    return make_styles([r["variant"] for r in results], first="full")


def finish_panel(ax, xlabel, ylabel, title, **legend):
    """Units on both axes and a legend naming every line of this panel."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize="medium")
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize="x-small", **legend)


def plot_trajectories(directory, experiment, perturbations, styles):
    fig, axes = plt.subplots(3, len(perturbations), figsize=(4.5 * len(perturbations), 8), squeeze=False, sharex=True)
    for col, (name, rows) in enumerate(sorted(perturbations.items())):
        for r in rows:
            t, p, _ = read_trajectory(os.path.join(directory, "runs", r["id"]))
            for k in range(3):
                axes[k][col].plot(t, [1000 * v[k] for v in p], label=r["variant"], **styles[r["variant"]])
        for k, axis in enumerate("xyz"):
            finish_panel(axes[k][col], "time (s)", "object %s (mm)" % axis, "%s, perturbation %s" % (experiment, name))
    fig.tight_layout()
    return fig


def plot_quality(directory, experiment, perturbations, styles):
    fig, axes = plt.subplots(len(perturbations), 1, figsize=(8, 3 * len(perturbations)), squeeze=False, sharex=True)
    for row, (name, rows) in enumerate(sorted(perturbations.items())):
        ax = axes[row][0]
        for r in rows:
            folder = os.path.join(directory, "runs", r["id"])
            t, _, q = read_trajectory(folder)
            ax.plot(t, q, label=r["variant"], **styles[r["variant"]])
            for k, (start, end) in enumerate(read_engaged_intervals(folder, t[-1])):
                ax.axvspan(start, end, alpha=0.08, color=styles[r["variant"]]["color"],
                           label="%s engaged" % r["variant"] if k == 0 else None)
        finish_panel(ax, "time (s)", "grasp quality Q (N)", "%s, perturbation %s (shaded: approximation engaged)"
                     % (experiment, name), ncol=2)
    fig.tight_layout()
    return fig


def plot_forces(directory, experiment, perturbations, styles):
    """Summed normal force per hand body of the full-contact run; one style per body."""
    fig, axes = plt.subplots(len(perturbations), 1, figsize=(8, 3 * len(perturbations)), squeeze=False, sharex=True)
    runs = {}
    for name, rows in perturbations.items():
        full = [r for r in rows if r["variant"] == "full"]
        if full:
            runs[name] = read_normal_forces(os.path.join(directory, "runs", full[0]["id"]))
    body_styles = make_styles([b for _, forces in runs.values() for b in forces])
    for row, name in enumerate(sorted(perturbations)):
        ax = axes[row][0]
        if name in runs:
            times, forces = runs[name]
            for body, f in sorted(forces.items()):
                ax.plot(times, f, label=body, **body_styles[body])
        finish_panel(ax, "time (s)", "normal force (N)", "%s, perturbation %s, full contact" % (experiment, name), ncol=3)
    fig.tight_layout()
    return fig


def plot_errors(directory, experiment, perturbations, styles):
    """Position error of each variant against full contact, one panel per perturbation."""
    fig, axes = plt.subplots(len(perturbations), 1, figsize=(8, 3 * len(perturbations)), squeeze=False, sharex=True)
    for row, (name, rows) in enumerate(sorted(perturbations.items())):
        ax = axes[row][0]
        full = [r for r in rows if r["variant"] == "full"]
        if full:
            reference = read_trajectory(os.path.join(directory, "runs", full[0]["id"]))
            for r in rows:
                if r["variant"] == "full":
                    continue
                t, e = position_error(reference, read_trajectory(os.path.join(directory, "runs", r["id"])))
                # Log scale: errors span micrometres (integrators) to metres (a dropped object).
                ax.plot(t, [max(v, 1e-5) for v in e], label=r["variant"], **styles[r["variant"]])
        if name == "none":
            ax.axhline(2.0, color="k", linestyle=(0, (1, 3)), label="2 mm bound")
        ax.set_yscale("log")
        finish_panel(ax, "time (s)", "position error (mm)", "%s, perturbation %s: against full contact"
                     % (experiment, name), ncol=2)
    fig.tight_layout()
    return fig


PLOTS = (("trajectory", plot_trajectories), ("quality", plot_quality), ("forces", plot_forces), ("error", plot_errors))


def main(argv):
    if len(argv) != 2:
        sys.stderr.write("usage: plot_validation.py DIR\n")
        return 2
    directory = argv[1]
    results = read_rows(os.path.join(directory, "results.csv"))
    styles = variant_styles(results)
    for experiment, perturbations in sorted(group_runs(results).items()):
        for kind, plot in PLOTS:
            name = "%s_%s.png" % (experiment, kind)
            fig = plot(directory, experiment, perturbations, styles)
            fig.savefig(os.path.join(directory, name), dpi=110)
            plt.close(fig)
            print(name)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
