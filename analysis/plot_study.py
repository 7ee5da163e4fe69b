#!/usr/bin/env python3
"""Plots a study's results.csv: one PNG per measure, with one panel per varied axis showing the
measure against that axis (categorical axes as categories; finished cases only).

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


def plot_measure(folder, header, rows, axes, measure, status):
    column = header.index(measure)
    finished = [r for r in rows if r[status] in ("ok", "incomplete") and r[column] != ""]
    if not finished:
        return None
    fig, panels = plt.subplots(1, len(axes), figsize=(4.2 * len(axes), 3.4), squeeze=False)
    for panel, axis in zip(panels[0], axes):
        a = header.index(axis)
        xs = [r[a] for r in finished]
        ys = [to_number(r[column]) for r in finished]
        numeric = all(to_number(x) is not None for x in xs)
        if numeric:
            panel.scatter([to_number(x) for x in xs], ys, s=18)
        else:
            categories = sorted(set(xs))
            panel.scatter([categories.index(x) for x in xs], ys, s=18)
            panel.set_xticks(range(len(categories)))
            panel.set_xticklabels(categories, rotation=20)
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
