#!/usr/bin/env python3
"""Below capacity: how far the approximated object strays from the full-contact object under a load.

Issue 17 (docs/capacity.md, "Below capacity, every force direction"). For each thesis scenario and
each axis force: full contact's ramp slip onset F (`graspsim capacity`, the default rate), then the
scenario with one perturbation of FACTOR x F along that axis, switched on at the ramp's load start
and held 1 s, simulated in full contact and with the default approximation; the largest distance
between the two objects over the run (analysis/compare_trajectories.py), and whether each run held.
All on the linearly implicit stepper at 3e-4.

Usage: analysis/below_capacity.py [GRASPSIM [OUT [FACTOR]]]   (default build/bin/graspsim,
out/below-capacity, 0.75). Prints one Markdown table; every run's folder stays under OUT.
"""
import json
import os
import re
import subprocess
import sys

GRASPSIM = sys.argv[1] if len(sys.argv) > 1 else "build/bin/graspsim"
OUT = sys.argv[2] if len(sys.argv) > 2 else "out/below-capacity"
FACTOR = float(sys.argv[3]) if len(sys.argv) > 3 else 0.75
HERE = os.path.dirname(os.path.abspath(__file__))
COMMON = ["--integrator", "implicit", "--accuracy", "3e-4"]
HOLD = 1.0
AXES = {"x": (1, 0, 0), "-x": (-1, 0, 0), "y": (0, 1, 0), "-y": (0, -1, 0), "z": (0, 0, 1), "-z": (0, 0, -1)}


def ramp(scenario, direction, out):
    subprocess.run([GRASPSIM, "capacity", scenario, "--direction", direction] + COMMON + ["--out", out], check=True,
                   stdout=subprocess.DEVNULL)
    with open(out + "/capacity.json") as f:
        return json.load(f)["measurements"][0]


def write_loaded_scenario(scenario, force, start, path):
    """The built-in scenario's file with its perturbations replaced by one, "below"."""
    with open(os.path.join(HERE, "..", "models", "scenarios", scenario + ".yaml")) as f:
        text = f.read()
    block = "\nperturbations:\n  below: {force: [%.9g, %.9g, %.9g], start: %.9g, duration: %.9g}\n" % (force + (start, HOLD))
    text, count = re.subn(r"\nperturbations:\n(  .*\n)+", block, text)
    if count != 1:
        sys.exit("below_capacity.py: %s has no perturbations block to replace" % scenario)
    with open(path, "w") as f:
        f.write(text)


def simulate(path, mode, end, out):
    subprocess.run([GRASPSIM, "simulate", path, "--mode", mode, "--perturbation", "below", "--duration", "%.9g" % end,
                    "--out", out, "-q"] + COMMON, check=True, stdout=subprocess.DEVNULL)
    with open(out + "/summary.json") as f:
        return json.load(f)


def distance_mm(full, approx):
    text = subprocess.run([sys.executable, os.path.join(HERE, "compare_trajectories.py"), full, approx], check=True,
                          capture_output=True, text=True).stdout
    return float(re.search(r"object position ([0-9.e+-]+) mm", text).group(1))


print("| scene | load | ramp onset | constant load | full contact | approximation | largest distance |")
print("|---|---|---|---|---|---|---|")
for scenario in ["ball-clutch", "phone-pinch"]:
    for name, axis in AXES.items():
        folder = "%s/%s/%s" % (OUT, scenario, name)
        os.makedirs(folder, exist_ok=True)
        measured = ramp(scenario, name, folder + "/ramp")
        if measured["slip_onset_n"] is None:
            print("| %s | %s | no slip | | | | |" % (scenario, name))
            continue
        load = FACTOR * measured["slip_onset_n"]
        path = folder + "/scenario.yaml"
        write_loaded_scenario(scenario, tuple(load * a for a in axis), measured["load_start_s"], path)
        end = measured["load_start_s"] + HOLD
        runs = {m: simulate(path, m, end, folder + "/" + m) for m in ("full", "approx")}
        approx = "held" if runs["approx"]["held"] else "dropped"
        if runs["approx"].get("release_time_s") is not None:
            approx += ", released %.1f ms into the load" % (1000 * (runs["approx"]["release_time_s"] - measured["load_start_s"]))
        print("| %s | %s | %.4g N | %.4g N | %s | %s | %.3g mm |" % (
            scenario, name, measured["slip_onset_n"], load, "held" if runs["full"]["held"] else "dropped", approx,
            distance_mm(folder + "/full", folder + "/approx")))
