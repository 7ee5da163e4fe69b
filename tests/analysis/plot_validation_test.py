"""Checks analysis/plot_validation.py's figures (run by ctest with Debian's /usr/bin/python3).

Usage: python3 plot_validation_test.py PATH/TO/plot_validation.py

On a made-up validation folder in which some variants and hand bodies appear in only some
panels (as full-cvode appears only without perturbation in the real suite), every line of every
panel of every figure is inspected: each variant (or hand body) keeps one colour and line style
everywhere, different ones never share a style, every panel's legend names each line it shows,
and both axes of every panel state a unit.
"""

import csv
import importlib.util
import os
import sys
import tempfile
import unittest

SCRIPT = None


def load_script():
    spec = importlib.util.spec_from_file_location("plot_validation", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def write_csv(path, header, rows):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(header)
        writer.writerows(rows)


# perturbation -> variants; full-cvode and approx-weld each appear in one perturbation only.
RUNS = {"none": ["full", "full-cvode", "approx-bushing"], "f1": ["full", "approx-bushing", "approx-weld"]}
# perturbation -> hand bodies touching in its full run; the thumb only under f1.
BODIES = {"none": ["index_distal", "middle_distal"], "f1": ["index_distal", "thumb_distal", "middle_distal"]}


def make_folder(root):
    results = []
    for perturbation, variants in RUNS.items():
        for k, variant in enumerate(variants):
            run_id = "cup_%s_%s" % (perturbation, variant)
            results.append([run_id, "cup", perturbation, variant])
            folder = os.path.join(root, "runs", run_id)
            times = [0.1 * i for i in range(11)]
            write_csv(os.path.join(folder, "trajectory.csv"),
                      ["time_s", "object_x_m", "object_y_m", "object_z_m", "grasp_quality_n"],
                      [[t, 0.001 * k * t, 0.1 - 0.002 * t, 0.0, 1 + k + t] for t in times])
            write_csv(os.path.join(folder, "contacts.csv"), ["time_s", "body_a", "normal_force_n"],
                      [[t, body, 1.0 + j] for t in times for j, body in enumerate(BODIES[perturbation])])
            if variant.startswith("approx"):
                write_csv(os.path.join(folder, "events.csv"), ["time_s", "event"], [[0.3, "engage"], [0.7, "release"]])
    write_csv(os.path.join(root, "results.csv"), ["id", "scenario", "perturbation", "variant"], results)


class PlotValidationTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.script = load_script()
        cls.tmp = tempfile.TemporaryDirectory()
        make_folder(cls.tmp.name)
        results = cls.script.read_rows(os.path.join(cls.tmp.name, "results.csv"))
        styles = cls.script.variant_styles(results)
        perturbations = cls.script.group_runs(results)["cup"]
        cls.figures = {kind: plot(cls.tmp.name, "cup", perturbations, styles) for kind, plot in cls.script.PLOTS}

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def lines(self, kinds):
        """(figure kind, panel index, label, (colour, line style)) of every labelled line."""
        from matplotlib.colors import to_rgba
        for kind in kinds:
            for i, ax in enumerate(self.figures[kind].axes):
                for line in ax.get_lines():
                    if not line.get_label().startswith("_"):
                        yield kind, i, line.get_label(), (to_rgba(line.get_color()), line.get_linestyle())

    def check_one_style_per_name(self, kinds, expected_names):
        styles = {}
        for kind, panel, label, style in self.lines(kinds):
            styles.setdefault(label, set()).add(style)
        for label, seen in styles.items():
            self.assertEqual(len(seen), 1, "%s is drawn in %d styles across panels: %s" % (label, len(seen), seen))
        self.assertTrue(expected_names <= set(styles), "missing lines: %s" % (expected_names - set(styles)))
        names = sorted(expected_names)
        for a in names:
            for b in names:
                if a < b:
                    self.assertNotEqual(styles[a], styles[b], "%s and %s share a colour and line style" % (a, b))

    def test_each_variant_keeps_its_colour_and_style_in_every_panel(self):
        variants = {v for vs in RUNS.values() for v in vs}
        self.check_one_style_per_name(["trajectory", "quality"], variants)
        self.check_one_style_per_name(["trajectory", "quality", "error"], variants - {"full"})

    def test_each_hand_body_keeps_its_colour_across_panels(self):
        self.check_one_style_per_name(["forces"], {b for bs in BODIES.values() for b in bs})

    def test_every_panel_names_each_line_in_its_legend_and_has_units(self):
        for kind, fig in self.figures.items():
            for i, ax in enumerate(fig.axes):
                shown = {line.get_label() for line in ax.get_lines() if not line.get_label().startswith("_")}
                legend = ax.get_legend()
                named = {t.get_text() for t in legend.get_texts()} if legend else set()
                self.assertTrue(shown, "%s panel %d draws no labelled line" % (kind, i))
                self.assertTrue(shown <= named, "%s panel %d: legend lacks %s" % (kind, i, shown - named))
                for axis_label in (ax.get_xlabel(), ax.get_ylabel()):
                    self.assertRegex(axis_label, r"\(.+\)", "%s panel %d: axis label without unit" % (kind, i))

    def test_main_writes_every_figure(self):
        self.assertEqual(self.script.main(["plot_validation.py", self.tmp.name]), 0)
        for kind, _ in self.script.PLOTS:
            self.assertTrue(os.path.exists(os.path.join(self.tmp.name, "cup_%s.png" % kind)), kind)


if __name__ == "__main__":
    SCRIPT = sys.argv.pop(1)
    unittest.main()
