"""Plots of a `graspsim validate` output folder (run with Debian's /usr/bin/python3 + matplotlib).

Usage: /usr/bin/python3 analysis/plot_validation.py DIR

Reads DIR/results.csv and DIR/runs/<run>/{trajectory,contacts,events}.csv (formats in
include/graspsim/results/result_files.h and include/graspsim/validation/validation_report.h)
and writes, per experiment (scenario):
  DIR/<experiment>_trajectory.png  object centre of mass vs time, full contact vs approximation,
                                   one column per perturbation;
  DIR/<experiment>_quality.png     grasp quality vs time with the engaged intervals shaded;
  DIR/<experiment>_forces.png      summed contact normal force per hand body (full contact);
  DIR/<experiment>_error.png       object position error of each approximation vs full contact.
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


def plot_trajectories(directory, experiment, perturbations, out):
    fig, axes = plt.subplots(3, len(perturbations), figsize=(4.5 * len(perturbations), 7), squeeze=False, sharex=True)
    for col, (name, rows) in enumerate(sorted(perturbations.items())):
        for r in rows:
            t, p, _ = read_trajectory(os.path.join(directory, "runs", r["id"]))
            for k, axis in enumerate("xyz"):
                axes[k][col].plot(t, [1000 * v[k] for v in p], label=r["variant"],
                                  linestyle="-" if r["variant"] == "full" else "--")
                axes[k][col].set_ylabel("object %s (mm)" % axis)
        axes[0][col].set_title("%s, perturbation %s" % (experiment, name))
        axes[2][col].set_xlabel("time (s)")
    axes[0][0].legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def plot_quality(directory, experiment, perturbations, out):
    fig, axes = plt.subplots(len(perturbations), 1, figsize=(8, 2.6 * len(perturbations)), squeeze=False, sharex=True)
    for row, (name, rows) in enumerate(sorted(perturbations.items())):
        ax = axes[row][0]
        for r in rows:
            folder = os.path.join(directory, "runs", r["id"])
            t, _, q = read_trajectory(folder)
            ax.plot(t, q, label=r["variant"])
            for start, end in read_engaged_intervals(folder, t[-1]):
                ax.axvspan(start, end, alpha=0.15, color="tab:green")
        ax.set_ylabel("Q (N)")
        ax.set_title("%s, perturbation %s (shaded: approximation engaged)" % (experiment, name), fontsize="medium")
    axes[0][0].legend(fontsize="small")
    axes[-1][0].set_xlabel("time (s)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def plot_forces(directory, experiment, perturbations, out):
    fig, axes = plt.subplots(len(perturbations), 1, figsize=(8, 2.6 * len(perturbations)), squeeze=False, sharex=True)
    for row, (name, rows) in enumerate(sorted(perturbations.items())):
        full = [r for r in rows if r["variant"] == "full"]
        if not full:
            continue
        times, forces = read_normal_forces(os.path.join(directory, "runs", full[0]["id"]))
        for body, f in sorted(forces.items()):
            axes[row][0].plot(times, f, label=body)
        axes[row][0].set_ylabel("normal force (N)")
        axes[row][0].set_title("%s, perturbation %s, full contact" % (experiment, name), fontsize="medium")
        axes[row][0].legend(fontsize="x-small", ncol=3)
    axes[-1][0].set_xlabel("time (s)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def plot_errors(directory, experiment, perturbations, out):
    fig, ax = plt.subplots(figsize=(9, 4.5))
    for name, rows in sorted(perturbations.items()):
        full = [r for r in rows if r["variant"] == "full"]
        if not full:
            continue
        reference = read_trajectory(os.path.join(directory, "runs", full[0]["id"]))
        for r in rows:
            if r["variant"] == "full":
                continue
            t, e = position_error(reference, read_trajectory(os.path.join(directory, "runs", r["id"])))
            # Log scale: errors span micrometres (integrators) to metres (a dropped object).
            ax.plot(t, [max(v, 1e-5) for v in e], label="%s, %s" % (name, r["variant"]))
    ax.axhline(2.0, color="k", linestyle=":", label="2 mm bound (no perturbation)")
    ax.set_yscale("log")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("position error (mm)")
    ax.set_title("%s: approximation vs full contact" % experiment, fontsize="medium")
    ax.legend(fontsize="x-small", ncol=2)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main(argv):
    if len(argv) != 2:
        sys.stderr.write("usage: plot_validation.py DIR\n")
        return 2
    directory = argv[1]
    groups = group_runs(read_rows(os.path.join(directory, "results.csv")))
    for experiment, perturbations in sorted(groups.items()):
        for kind, plot in (("trajectory", plot_trajectories), ("quality", plot_quality),
                           ("forces", plot_forces), ("error", plot_errors)):
            name = "%s_%s.png" % (experiment, kind)
            plot(directory, experiment, perturbations, os.path.join(directory, name))
            print(name)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
