#!/usr/bin/env python3
"""Plots a study's results.csv: one PNG per measure, with one panel per varied axis showing the
measure against that axis (categorical axes as categories; finished cases only). Points are
coloured by another axis with at most six values, a categorical one first (e.g. mode: full vs
approx), so that the cases of one panel can be told apart.

Usage: plot_study.py STUDY_OUTPUT_FOLDER   (writes FOLDER/plots/<measure>.png and prints their names)
graspsim study run / collect run this script (compiled into the binary) themselves."""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def to_number(text):
    if text in ("true", "false"):
        return 1.0 if text == "true" else 0.0
    try:
        return float(text)
    except ValueError:
        return None


def read_table(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, rows = rows[0], rows[1:]
    status = header.index("status")
    axes = header[1:status]
    measures = header[status + 1:-1]
    return header, rows, axes, measures, status


def find_colour_axis(header, rows, axes, panel_axis):
    """A categorical axis (mode, contact, ...) first, else a numeric one with few values."""
    candidates = [a for a in axes if a != panel_axis and len({r[header.index(a)] for r in rows}) <= 6]
    categorical = [a for a in candidates if any(to_number(r[header.index(a)]) is None for r in rows)]
    return (categorical + candidates + [None])[0]


def plot_panel(panel, header, finished, axis, column, colour_axis):
    a = header.index(axis)
    numeric = all(to_number(r[a]) is not None for r in finished)
    categories = sorted({r[a] for r in finished})
    groups = sorted({r[header.index(colour_axis)] for r in finished}) if colour_axis else [None]
    values = [to_number(r[a]) for r in finished] if numeric else [0, len(categories) - 1]
    dodge = 0.015 * ((max(values) - min(values)) or 1.0)  # groups side by side, not on top of each other
    for g, group in enumerate(groups):
        members = [r for r in finished if group is None or r[header.index(colour_axis)] == group]
        shift = (g - (len(groups) - 1) / 2) * dodge
        xs = [(to_number(r[a]) if numeric else categories.index(r[a])) + shift for r in members]
        label = None if group is None else "%s = %s" % (colour_axis, group)
        panel.scatter(xs, [to_number(r[column]) for r in members], s=22, alpha=0.75, label=label)
    if not numeric:
        panel.set_xticks(range(len(categories)))
        panel.set_xticklabels(categories, rotation=20)
    if colour_axis:
        panel.legend(fontsize=7)


def plot_measure(folder, header, rows, axes, measure, status):
    column = header.index(measure)
    finished = [r for r in rows if r[status] in ("ok", "incomplete") and r[column] != ""]
    if not finished:
        return None
    fig, panels = plt.subplots(1, len(axes), figsize=(4.2 * len(axes), 3.4), squeeze=False)
    for panel, axis in zip(panels[0], axes):
        plot_panel(panel, header, finished, axis, column, find_colour_axis(header, rows, axes, axis))
        panel.set_xlabel(axis)
        panel.set_ylabel(measure)
        panel.grid(alpha=0.3)
    fig.tight_layout()
    name = "plots/%s.png" % measure
    fig.savefig(os.path.join(folder, name), dpi=90)
    plt.close(fig)
    return name


def main():
    folder = sys.argv[1]
    header, rows, axes, measures, status = read_table(os.path.join(folder, "results.csv"))
    os.makedirs(os.path.join(folder, "plots"), exist_ok=True)
    for measure in measures:
        name = plot_measure(folder, header, rows, axes, measure, status)
        if name:
            print(name)


if __name__ == "__main__":
    main()
