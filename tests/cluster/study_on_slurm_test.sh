#!/usr/bin/env bash
# A small study (8 cases of the ball clutch shortened to 0.2 s) submitted to a real one-node Slurm
# cluster as a job array of 4 tasks, collected, and compared with the same study run locally with
# --jobs 2: the same rows, byte-identical measures (wall time left out, the only column that
# depends on the machine's load); then a capacity study (4 phone ramps) the same way. Fails,
# saying why, when the cluster cannot start.
#
# Usage: study_on_slurm_test.sh GRASPSIM_EXECUTABLE   (ctest label: cluster)
set -euo pipefail

graspsim=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d /tmp/graspsim-slurm-test.XXXXXX)
cluster="$work/cluster"

fail() { echo "FAILED: $*" >&2; exit 1; }
cleanup() { "$here/slurm_cluster.sh" stop "$cluster" >/dev/null 2>&1 || true; rm -rf "$work"; }
trap cleanup EXIT

cat >"$work/study.yaml" <<'STUDY'
name: slurm-check
base: ball-clutch
set:
  controller.approach_time: 0.05
  simulation.settle_time: 0.1
  simulation.duration: 0.2
  perturbations: {f1: {force: [0, -9.5, 0], start: 0.12, duration: 0.08}}
  perturbation: f1
axes:
  subject.stature: [1.73, 1.75]   # near the reference 1.741 m: the hand-found grasp passes the set-up check
  contact.static_friction: [0.8, 0.9]
  mode: [full, approx]
measures: [held, object_displacement_m, max_penetration_m, q_at_engage_n, steps, wall_time_s]
STUDY

# Ports of its own, so that two checkouts testing at once on one machine do not meet.
export GRASPSIM_SLURMCTLD_PORT=$((20000 + ($$ % 5000) * 2))
export GRASPSIM_SLURMD_PORT=$((GRASPSIM_SLURMCTLD_PORT + 1))
start_output=$("$here/slurm_cluster.sh" start "$cluster" 2>&1) ||
  fail "the one-node Slurm cluster did not start, so the study could not be tested on it: $start_output"
export SLURM_CONF="$cluster/slurm.conf"

# --wait: sbatch returns once every array task has ended.
"$graspsim" study submit "$work/study.yaml" --out "$work/slurm" --array-size 4 --sbatch-arg=--wait ||
  fail "study submit (job array) failed; task logs: $(cat "$work"/slurm/slurm/task-*.log 2>/dev/null | tail -5)"
"$graspsim" study collect "$work/slurm" || fail "study collect found cases missing after the job array ended"
"$graspsim" study run "$work/study.yaml" --out "$work/local" --jobs 2 >/dev/null || fail "the local run failed"

# Both tables without the wall_time_s column.
strip_wall_time() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "wall_time_s") w = i }
           { line = ""; for (i = 1; i <= NF; i++) if (i != w) line = line (line == "" ? "" : ",") $i; print line }' "$1"
}
strip_wall_time "$work/slurm/results.csv" >"$work/slurm.csv"
strip_wall_time "$work/local/results.csv" >"$work/local.csv"
rows=$(($(wc -l <"$work/slurm.csv") - 1))
[ "$rows" -eq 8 ] || fail "the Slurm table has $rows rows, not 8"
ok=$(grep -c ',ok,' "$work/slurm.csv" || true)
[ "$ok" -eq 8 ] || fail "only $ok of 8 cases ran ok on Slurm: $(cat "$work/slurm.csv")"
for task in 0 1 2 3; do
  grep -q "shard $task/4: 2 cases" "$work/slurm/slurm/task-$task.log" || fail "array task $task did not run its shard of 2 cases"
done
cmp -s "$work/slurm.csv" "$work/local.csv" ||
  fail "the Slurm and local tables differ: $(diff "$work/slurm.csv" "$work/local.csv" | head -5 | tr '\n' ' ')"
echo "study on Slurm: 8 cases in 4 array tasks, table identical to the local --jobs 2 run (wall time excluded)"

# A capacity study (command: capacity) on the same cluster: four fast phone ramps in 2 tasks.
cat >"$work/capacity.yaml" <<'STUDY'
name: slurm-capacity
command: capacity
base: phone-pinch
set: {rate: 8, max_duration: 0.6, integrator: implicit}
axes:
  direction: [-y, x]
  mode: [full, approx]
measures: [slip_onset_n, drop_n, release_n, wall_time_s]
STUDY
"$graspsim" study submit "$work/capacity.yaml" --out "$work/slurm-capacity" --array-size 2 --sbatch-arg=--wait ||
  fail "the capacity study's job array failed; task logs: $(cat "$work"/slurm-capacity/slurm/task-*.log 2>/dev/null | tail -5)"
"$graspsim" study collect "$work/slurm-capacity" || fail "study collect found capacity cases missing"
"$graspsim" study run "$work/capacity.yaml" --out "$work/local-capacity" --jobs 2 >/dev/null || fail "the local capacity run failed"
strip_wall_time "$work/slurm-capacity/results.csv" >"$work/slurm-capacity.csv"
strip_wall_time "$work/local-capacity/results.csv" >"$work/local-capacity.csv"
ok=$(grep -c ',ok,' "$work/slurm-capacity.csv" || true)
[ "$ok" -eq 4 ] || fail "only $ok of 4 capacity cases ran ok on Slurm: $(cat "$work/slurm-capacity.csv")"
cmp -s "$work/slurm-capacity.csv" "$work/local-capacity.csv" ||
  fail "the Slurm and local capacity tables differ: $(diff "$work/slurm-capacity.csv" "$work/local-capacity.csv" | head -5 | tr '\n' ' ')"
echo "capacity study on Slurm: 4 ramps in 2 array tasks, table identical to the local run (wall time excluded)"
