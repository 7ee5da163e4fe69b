#!/usr/bin/env bash
# Compares two output trees of graspsim runs (e.g. two `graspsim validate --out DIR` runs) byte
# for byte: every run folder's trajectory.csv, contacts.csv and events.csv. The simulations are
# deterministic, so a refactor that keeps the behaviour writes identical files.
#
# Usage: analysis/compare_runs.sh BASE_DIR NEW_DIR
# Prints "N runs identical" or the list of differing / missing files; exits 0 only when every
# compared file is identical and both trees hold the same run folders (1 on a difference,
# 2 on bad usage).
set -euo pipefail

if [[ $# -ne 2 || ! -d "$1" || ! -d "$2" ]]; then
    echo "usage: $0 BASE_DIR NEW_DIR (two existing output directories)" >&2
    exit 2
fi
base=$1
new=$2
files=(trajectory.csv contacts.csv events.csv)

# Run folders: every directory holding a trajectory.csv, relative to its tree.
list_runs() { (cd "$1" && find . -name trajectory.csv -printf '%h\n' | sort); }

mapfile -t base_runs < <(list_runs "$base")
mapfile -t new_runs < <(list_runs "$new")
if [[ ${#base_runs[@]} -eq 0 ]]; then
    echo "no run folder (no trajectory.csv) under $base" >&2
    exit 2
fi

differences=()
while read -r run; do
    differences+=("missing in $new: $run")
done < <(comm -23 <(printf '%s\n' "${base_runs[@]}") <(printf '%s\n' "${new_runs[@]}"))
while read -r run; do
    differences+=("missing in $base: $run")
done < <(comm -13 <(printf '%s\n' "${base_runs[@]}") <(printf '%s\n' "${new_runs[@]}"))

identical=0
compared=0
for run in "${base_runs[@]}"; do
    [[ -d "$new/$run" ]] || continue
    compared=$((compared + 1))
    same=1
    for f in "${files[@]}"; do
        a="$base/$run/$f"
        b="$new/$run/$f"
        if [[ ! -e "$a" && ! -e "$b" ]]; then continue; fi
        if [[ ! -e "$a" || ! -e "$b" ]]; then
            differences+=("only in one tree: $run/$f")
            same=0
        elif ! cmp -s "$a" "$b"; then
            differences+=("differs: $run/$f")
            same=0
        fi
    done
    identical=$((identical + same))
done

echo "$identical of $compared runs identical (${files[*]})"
if [[ ${#differences[@]} -gt 0 ]]; then
    printf '%s\n' "${differences[@]}"
    exit 1
fi
