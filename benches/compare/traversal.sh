#!/usr/bin/env bash
# Traversal and build against Intel Embree, one core, in one run.
#
#   benches/compare/traversal.sh [ROUNDS] [EMBREE_PYTHON]
#
# Each round runs, back to back on core 0: Embree's robust (watertight)
# mode, this project's wide BVH, its binary BVH, Embree's default mode.
# Embree's side is the maintainers' script ../shared/tools/embree/bench.py
# (outside this repository), run by EMBREE_PYTHON, a Python with embreex
# and numpy (default /tmp/ev/bin/python:
# `python3 -m venv /tmp/ev && /tmp/ev/bin/pip install embreex numpy`).
# Prints the lines that hold the rates (Mrays/s) and build times; the
# machine is shared, so compare the ratios within a round.
set -euo pipefail
cd "$(dirname "$0")/../.."
rounds=${1:-2}
python=${2:-/tmp/ev/bin/python}
embree=../shared/tools/embree/bench.py
cargo build --release --bin part2-bvh >/dev/null
for round in $(seq 1 "$rounds"); do
    echo "== round $round, load: $(cut -d' ' -f1-3 /proc/loadavg)"
    echo "-- Embree robust"
    "$python" "$embree" --threads 1 --robust --reps 3 | grep -E "^build|DISTANCE"
    for accel in wide binary; do
        echo "-- this project, $accel BVH"
        taskset -c 0 target/release/part2-bvh --bench -t 1 --accel "$accel" | grep -E "build|1T"
    done
    echo "-- Embree default"
    "$python" "$embree" --threads 1 --reps 3 | grep -E "^build|DISTANCE"
done
