#!/usr/bin/env bash
# Full compliant contact against MuJoCo's full contact on the same scenes, timed back to back in
# one run (docs/performance.md, "Against MuJoCo").
#
#   bash analysis/mujoco_ratio.sh BUILD_DIR [PEER_DIR] [ROUNDS]
#
# PEER_DIR: the MuJoCo peer (grasp_bench.c and its models; default ../shared/peers/mujoco), built
# here with Debian's libmujoco-dev. Per round and scene it prints MuJoCo's mean step (1 ms steps from
# the settled keyframe: its s per simulated s) and graspsim's default full-contact run, s of wall
# time per simulated s (medians of five runs): "held" is the marginal cost of simulated seconds 2-5 (the grasp held, the
# phase MuJoCo's bench times), "whole" a 3 s run from the open hand (closing, landing and hold).
set -euo pipefail
build=${1:?usage: mujoco_ratio.sh BUILD_DIR [PEER_DIR] [ROUNDS]}
here=$(cd "$(dirname "$0")/.." && pwd)
peer=${2:-$here/../shared/peers/mujoco}
rounds=${3:-3}
graspsim=$(cd "$build" && pwd)/bin/graspsim
[[ -x $graspsim ]] || { echo "mujoco_ratio.sh: $graspsim not found; build graspsim first" >&2; exit 2; }
[[ -f $peer/grasp_bench.c ]] || { echo "mujoco_ratio.sh: no MuJoCo peer at $peer (grasp_bench.c)" >&2; exit 2; }
dpkg -s libmujoco-dev >/dev/null 2>&1 || { echo "mujoco_ratio.sh: needs Debian's libmujoco-dev (bash .ci/install --peers)" >&2; exit 2; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake -S "$peer" -B "$work/peer" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/peer" >/dev/null

# MuJoCo: mean ns per step (median of three repetitions of 3000 steps after 1000 warm-up steps).
mujoco_step_ns() {
    (cd "$peer" && "$work/peer/grasp_bench" bench --steps 3000 --warm 1000 --reps 3 --dt 0.001 "m=$1") |
        awk -F'|' '$3 ~ / m / { gsub(/ /, "", $4); print $4 }'
}

# graspsim: the run's own wall time (summary.json's wall_time_s, the simulation without start-up),
# the median of five runs.
graspsim_wall() {
    for rep in 1 2 3 4 5; do
        "$graspsim" simulate "$1" --duration "$2" -q --out "$work/run" >/dev/null
        sed -n 's/.*"wall_time_s": *\([0-9.eE+-]*\).*/\1/p' "$work/run/summary.json"
    done | sort -g | sed -n 3p
}

printf '%-5s %-12s %12s %12s %12s %8s %8s\n' round scene mujoco held whole held/mj whole/mj
for ((round = 1; round <= rounds; ++round)); do
    for pair in ball-clutch:ball_A_contact.xml phone-pinch:phone_A_contact.xml; do
        scene=${pair%%:*} model=${pair#*:}
        mujoco=$(awk -v ns="$(mujoco_step_ns "$model")" 'BEGIN { print ns * 1e-6 }')
        w2=$(graspsim_wall "$scene" 2) w5=$(graspsim_wall "$scene" 5) w3=$(graspsim_wall "$scene" 3)
        awk -v r="$round" -v s="$scene" -v m="$mujoco" -v w2="$w2" -v w5="$w5" -v w3="$w3" 'BEGIN {
            held = (w5 - w2) / 3; whole = w3 / 3
            printf "%-5d %-12s %12.4f %12.4f %12.4f %7.2fx %7.2fx\n", r, s, m, held, whole, held / m, whole / m }'
    done
done
echo "(s of wall time per simulated s; MuJoCo 2.2.2, 1 ms Euler steps, elliptic cones, Newton; graspsim's defaults)"
