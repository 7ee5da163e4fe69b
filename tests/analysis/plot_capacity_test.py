"""Checks analysis/plot_capacity.py's figure (run by ctest with Debian's /usr/bin/python3).

Usage: python3 plot_capacity_test.py PATH/TO/plot_capacity.py

On made-up capacity.json files (the keys of include/graspsim/capacity/capacity_files.h; that the
C++ writer writes them is pinned by tests/capacity/capacity_plot_test.cpp), every artist of the
figure is inspected. Oracle: the files' numbers. A direction that slipped is a point of its run's
line at (its angle in the plane, its onset); a ramp that ended without slip is no point of the
line but an open marker, in its run's colour, at (its angle, the ramp's last load), in every plane
holding its axis; a torque likewise on its bar's place; the legend names the open marker once,
and only when some direction did not slip; a constant load without slip is no lower bound.
"""

import importlib.util
import json
import math
import os
import sys
import tempfile
import unittest

SCRIPT = None
FORCES = ["x", "-x", "y", "-y", "z", "-z"]
ANGLE = {"x": {"x": 0, "-x": math.pi, "y": math.pi / 2, "-y": 3 * math.pi / 2},
         "y": {"y": 0, "-y": math.pi, "z": math.pi / 2, "-z": 3 * math.pi / 2},
         "z": {"z": 0, "-z": math.pi, "x": math.pi / 2, "-x": 3 * math.pi / 2}}  # per plane, by its first axis
BOUND = "no slip up to (lower bound)"


def load_script():
    spec = importlib.util.spec_from_file_location("plot_capacity", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def ramp(direction, load, onset, last, method="ramp"):
    unit = "nm" if load == "torque" else "n"
    entry = {"direction": direction, "load": load, "method": method, "mode": "full", "realization": None,
             "slip_onset_" + unit: onset}
    if method == "ramp":
        entry["max_load_" + unit] = last
    else:
        entry.pop("slip_onset_" + unit)
        entry["load_" + unit] = last
    return entry


def write_run(folder, onsets, torque_onsets, last=2.0, last_torque=0.05, constant=()):
    os.makedirs(folder, exist_ok=True)
    measurements = [ramp(d, "force", onsets.get(d), last) for d in FORCES if d not in constant]
    measurements += [ramp(d, "force", None, last, "constant") for d in constant]
    measurements += [ramp(d, "torque", torque_onsets.get(d), last_torque) for d in "xyz"]
    with open(os.path.join(folder, "capacity.json"), "w") as f:
        json.dump({"scenario": "made-up", "measurements": measurements}, f)


class PlotCapacityTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.script = load_script()
        cls.tmp = tempfile.TemporaryDirectory()
        cls.full = os.path.join(cls.tmp.name, "full")
        cls.approx = os.path.join(cls.tmp.name, "approx")
        # full: -y and z did not slip within their 2 N ramps, torque z not within 0.05 N m
        write_run(cls.full, {"x": 0.8, "-x": 0.9, "y": 1.2, "-z": 1.1}, {"x": 0.03, "y": 0.036})
        # approx: everything slipped but -x, held as a constant load (no ramp, no bound)
        write_run(cls.approx, {"x": 0.7, "y": 1.1, "-y": 1.5, "z": 1.6, "-z": 1.0}, {"x": 0.02, "y": 0.03, "z": 0.01},
                  constant=("-x",))

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def figure(self, folders):
        return self.script.draw(self.script.load_runs(folders))

    @staticmethod
    def points(line):
        return [(t, r) for t, r in zip(line.get_xdata(), line.get_ydata()) if not math.isnan(r)]

    def open_markers(self, ax):
        return [line for line in ax.get_lines() if line.get_markerfacecolor() == "none"]

    def test_directions_without_slip_are_open_markers_at_the_ramps_last_load(self):
        fig = self.figure([self.full])
        for panel, (a, b) in zip(fig.axes[:3], self.script.PLANES):
            angle = ANGLE[a]
            lines = [line for line in panel.get_lines() if not line.get_label().startswith("_")]
            self.assertEqual(len(lines), 1)
            slipped = {d: v for d, v in {"x": 0.8, "-x": 0.9, "y": 1.2, "-z": 1.1}.items() if d in angle}
            self.assertEqual(sorted(p for p in self.points(lines[0]) if p[0] < 2 * math.pi - 1e-9),
                             sorted((angle[d], v) for d, v in slipped.items()), (a, b))
            unslipped = [d for d in ("-y", "z") if d in angle]
            markers = self.open_markers(panel)
            self.assertEqual(len(markers), 1 if unslipped else 0, (a, b))
            if unslipped:
                self.assertEqual(sorted(self.points(markers[0])), sorted((angle[d], 2.0) for d in unslipped), (a, b))
                self.assertEqual(markers[0].get_color(), lines[0].get_color())
                self.assertGreater(panel.get_rmax(), 2.0)  # off the rim
        bars = fig.axes[3]
        torque_markers = self.open_markers(bars)
        self.assertEqual(len(torque_markers), 1)
        self.assertEqual(self.points(torque_markers[0]), [(2.0, 0.05)])  # torque z, at its bar's place
        heights = [p.get_height() for p in bars.patches]
        self.assertEqual(heights[:2], [0.03, 0.036])
        self.assertTrue(math.isnan(heights[2]))
        self.assertEqual([t.get_text() for t in bars.get_legend().get_texts()], ["full", BOUND])

    def test_every_run_draws_its_own_bounds_in_its_colour(self):
        fig = self.figure([self.full, self.approx])
        xy = fig.axes[0]
        runs = [line for line in xy.get_lines() if not line.get_label().startswith("_")]
        self.assertEqual(len(runs), 2)
        self.assertNotEqual(runs[0].get_color(), runs[1].get_color())
        markers = self.open_markers(xy)
        self.assertEqual([m.get_color() for m in markers], [runs[0].get_color()])  # approx: no bound (-x held constant)
        self.assertEqual(self.points(markers[0]), [(3 * math.pi / 2, 2.0)])
        self.assertEqual([t.get_text() for t in fig.axes[3].get_legend().get_texts()], ["full", "approx", BOUND])

    def test_without_unslipped_directions_nothing_is_added(self):
        fig = self.figure([self.approx])
        for ax in fig.axes:
            self.assertEqual(self.open_markers(ax), [])
        self.assertEqual([t.get_text() for t in fig.axes[3].get_legend().get_texts()], ["full"])

    def test_main_writes_the_png(self):
        png = os.path.join(self.tmp.name, "capacity.png")
        self.script.main(["plot_capacity.py", png, self.full])
        with open(png, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")


if __name__ == "__main__":
    SCRIPT = sys.argv.pop(1)
    unittest.main()
