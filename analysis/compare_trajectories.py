#!/usr/bin/env python3
"""Largest difference between two runs' trajectories (e.g. one scenario before and after a change).

Usage: compare_trajectories.py BASE_RUN_DIR NEW_RUN_DIR
Reads DIR/trajectory.csv of two `graspsim simulate` runs with the same output times and prints the
largest object position difference (mm), object orientation difference (deg, the angle of the
relative rotation) and joint angle difference (rad, with the joint and time). Exit 2 on bad usage
or mismatched samples. Nothing here computes a pass/fail; analysis/compare_runs.sh compares bytes.
"""
import csv
import math
import sys


def load(folder):
    with open(folder + "/trajectory.csv", newline="") as f:
        return list(csv.DictReader(f))


def position(row):
    return [float(row[k]) for k in ("object_x_m", "object_y_m", "object_z_m")]


def angle_deg(a, b):
    keys = ("object_qw", "object_qx", "object_qy", "object_qz")
    dot = abs(sum(float(a[k]) * float(b[k]) for k in keys))
    return math.degrees(2 * math.acos(min(1.0, dot)))


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    base, new = load(argv[1]), load(argv[2])
    if len(base) != len(new) or any(abs(float(a["time_s"]) - float(b["time_s"])) > 1e-12 for a, b in zip(base, new)):
        print("the runs' output times differ", file=sys.stderr)
        return 2
    dp = max(1000 * math.dist(position(a), position(b)) for a, b in zip(base, new))
    da = max(angle_deg(a, b) for a, b in zip(base, new))
    joints = [k for k in base[0] if k.endswith("_rad")]
    dj = max((abs(float(a[k]) - float(b[k])), k, a["time_s"]) for a, b in zip(base, new) for k in joints)
    print(f"{len(base)} samples: object position {dp:.3f} mm, orientation {da:.3f} deg; "
          f"joint angles {dj[0]:.4f} rad ({dj[1]} at t = {float(dj[2]):.3f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
