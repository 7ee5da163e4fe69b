#!/usr/bin/env python3
"""Slip-onset times under a constant load above capacity, full contact against the approximation.

Issue 17 (docs/capacity.md, "Constant loads above capacity"). For each thesis scenario and each load
(six axis forces, three axis torques): full contact's ramp slip onset F, then a constant load of
1.25 F held 1 s in full contact, on the thesis's approximation (bushing, merged, thesis limits,
`--release-at none`), with the compliance limits, and on the default approximation (the thesis
limits released at the compliance model's limits, `--release-at compliance`), all on the linearly
implicit stepper at 3e-4 (`graspsim capacity`).

Usage: analysis/overload_times.py [GRASPSIM [OUT]]   (default build/bin/graspsim, out/overload)
Prints one Markdown table per scenario; every run's capacity.json/.csv stays under OUT.
"""
import json
import subprocess
import sys

GRASPSIM = sys.argv[1] if len(sys.argv) > 1 else "build/bin/graspsim"
OUT = sys.argv[2] if len(sys.argv) > 2 else "out/overload"
COMMON = ["--integrator", "implicit", "--accuracy", "3e-4"]
FACTOR = 1.25
VARIANTS = [("full", []), ("thesis", ["--mode", "approx", "--release-at", "none"]),
            ("compliance", ["--mode", "approx", "--limits", "compliance", "--release-at", "none"]),
            ("release", ["--mode", "approx", "--release-at", "compliance"])]


def measure(scenario, args, out):
    subprocess.run([GRASPSIM, "capacity", scenario] + args + COMMON + ["--out", out], check=True, stdout=subprocess.DEVNULL)
    with open(out + "/capacity.json") as f:
        return json.load(f)["measurements"][0]


def cell(m):
    """Onset ms (release ms) / drop ms after the load's start."""
    if m["slip_onset_time_s"] is None:
        return "no slip"
    text = "%.1f" % (1000 * m["slip_onset_time_s"])
    if m.get("release_time_s") is not None:
        text += " (rel. %.1f)" % (1000 * m["release_time_s"])
    if m["drop_time_s"] is not None:
        text += " / %.0f" % (1000 * m["drop_time_s"])
    return text


def difference(m, full):
    if m["slip_onset_time_s"] is None or full["slip_onset_time_s"] is None:
        return "-"
    return "%+.0f %%" % (100 * (m["slip_onset_time_s"] - full["slip_onset_time_s"]) / full["slip_onset_time_s"])


for scenario in ["ball-clutch", "phone-pinch"]:
    print("#### %s\n" % scenario)
    print("| load | ramp onset | constant load | full | approx, thesis switch | diff | approx, compliance limits | diff | approx, default (release at compliance) | diff |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for name in ["x", "-x", "y", "-y", "z", "-z", "torque x", "torque y", "torque z"]:
        torque = name.startswith("torque ")
        args = ["--direction", name.split()[-1]] + (["--torque"] if torque else [])
        unit = "nm" if torque else "n"
        folder = "%s/%s/%s" % (OUT, scenario, name.replace(" ", "-"))
        onset = measure(scenario, args, folder + "/ramp")["slip_onset_" + unit]
        if onset is None:
            print("| %s | no slip | | | | | | | | |" % name)
            continue
        load = "%.6g" % (FACTOR * onset)
        runs = {v: measure(scenario, args + ["--method", "constant", "--load", load] + extra, folder + "/" + v) for v, extra in VARIANTS}
        print("| %s | %.4g | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            name, onset, load, cell(runs["full"]), cell(runs["thesis"]), difference(runs["thesis"], runs["full"]),
            cell(runs["compliance"]), difference(runs["compliance"], runs["full"]),
            cell(runs["release"]), difference(runs["release"], runs["full"])))
    print()
