#!/usr/bin/env bash
# Benchmark (not a test): wall time of a 16-case study (the ball clutch shortened to 0.3 s) with
# --jobs 1 and --jobs 2, alternated `rounds` times, and the speed-up. Reports the load average,
# since on a shared machine other processes take cores from either run.
#
# Usage: tests/benchmarks/study_jobs_bench.sh GRASPSIM_EXECUTABLE [rounds (default 2)]
set -euo pipefail

graspsim=$1
rounds=${2:-2}
work=$(mktemp -d /tmp/graspsim-study-bench.XXXXXX)
trap 'rm -rf "$work"' EXIT

cat >"$work/study.yaml" <<'STUDY'
name: jobs-bench
base: ball-clutch
set:
  controller.approach_time: 0.05
  simulation.settle_time: 0.1
  simulation.duration: 0.3
  perturbations: {f1: {force: [0, -9.5, 0], start: 0.15, duration: 0.1}}
  perturbation: f1
axes:
  subject.stature: [1.6, 1.7, 1.8, 1.9]
  contact.static_friction: [0.8, 0.9]
  mode: [full, approx]
measures: [held, wall_time_s]
STUDY

calc() { awk "BEGIN { print $1 }"; }

run_once() {  # jobs round -> wall seconds; the CPU seconds of the run and its cases go to stderr
  local TIMEFORMAT="%R %U %S" times
  times=$( { time "$graspsim" study run "$work/study.yaml" --out "$work/out-$1-$2" --jobs "$1" >/dev/null; } 2>&1)
  read -r wall user sys <<<"$times"
  printf "  --jobs %d: wall %.2f s, CPU %.2f s\n" "$1" "$wall" "$(calc "$user + $sys")" >&2
  echo "$wall"
}

echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg), cores: $(nproc)"
total1=0
total2=0
for round in $(seq "$rounds"); do
  t1=$(run_once 1 "$round")
  t2=$(run_once 2 "$round")
  printf "round %d: --jobs 1 %.2f s, --jobs 2 %.2f s, speed-up %.2f\n" "$round" "$t1" "$t2" "$(calc "$t1 / $t2")"
  total1=$(calc "$total1 + $t1")
  total2=$(calc "$total2 + $t2")
done
printf "16 cases: --jobs 1 %.2f s, --jobs 2 %.2f s (mean of %d), speed-up %.2f\n" \
  "$(calc "$total1 / $rounds")" "$(calc "$total2 / $rounds")" "$rounds" "$(calc "$total1 / $total2")"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
