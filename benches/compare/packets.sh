#!/usr/bin/env bash
# This project's traversal, one ray at a time, against Embree 3's single
# rays and packets of 8 and 16 on the same rays, one core.
#
#   benches/compare/packets.sh SCENE.dae [MITSUBA_PYTHON]
#
# The rays come from `examples/render_rays.rs` (camera rays, 16 a pixel,
# and a cosine bounce from each hit). Embree is the build inside the
# Mitsuba 3 wheel of MITSUBA_PYTHON (default /tmp/mv/bin/python:
# `python3 -m venv /tmp/mv && /tmp/mv/bin/pip install mitsuba numpy`),
# the one Mitsuba traces with; its headers are in the wheel, and g++
# builds `embree_packets.cpp` against it. For development only.
set -euo pipefail
cd "$(dirname "$0")/../.."
scene=${1:?usage: packets.sh SCENE.dae [MITSUBA_PYTHON]}
python=${2:-/tmp/mv/bin/python}
mitsuba=$("$python" -c 'import mitsuba, os; print(os.path.dirname(mitsuba.__file__))')
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
namespace=$(grep -q "namespace mitsuba" "$mitsuba/include/embree3/rtcore_config.h" && echo -DEMBREE_IN_MITSUBA_NAMESPACE || true)
g++ -O2 $namespace -o "$work/embree_packets" benches/compare/embree_packets.cpp \
    -I"$mitsuba/include" -L"$mitsuba" -lembree3 -Wl,-rpath,"$mitsuba"
cargo build --release --example render_rays >/dev/null
taskset -c 0 target/release/examples/render_rays "$scene" "$work"
for robust in 1 0; do
    for coherent in 1 0; do
        taskset -c 0 "$work/embree_packets" "$work" "$robust" "$coherent"
    done
done
