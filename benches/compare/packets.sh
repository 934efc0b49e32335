#!/usr/bin/env bash
# This project's traversal, one ray at a time, against Embree 3's single
# rays and packets of 8 and 16 on the same rays, one core.
#
#   benches/compare/packets.sh SCENE.dae [MITSUBA_PYTHON]
#
# The rays come from `examples/render_rays.rs` (camera rays, 16 a pixel,
# and a uniform hemisphere bounce from each hit). Embree is the build inside the
# Mitsuba 3 wheel of MITSUBA_PYTHON (default /tmp/mv/bin/python:
# `python3 -m venv /tmp/mv && /tmp/mv/bin/pip install mitsuba numpy`),
# the one Mitsuba traces with (its scene set up as Mitsuba sets its own:
# default flags, high build quality); its headers are in the wheel, and
# g++ builds `embree_packets.cpp` against it. The bounce rays are made
# up (a uniform bounce about each camera hit's geometric normal, glass
# included), not a render's own. For development only.
set -euo pipefail
scene=$(realpath "${1:?usage: packets.sh SCENE.dae [MITSUBA_PYTHON]}")
python=${2:-/tmp/mv/bin/python}
cd "$(dirname "$0")/../.."
mitsuba=$("$python" -c 'import mitsuba, os; print(os.path.dirname(mitsuba.__file__))')
if [ ! -f "$mitsuba/include/embree3/rtcore.h" ]; then
    echo "packets.sh: no Embree 3 headers in $mitsuba/include (the Mitsuba wheel's)" >&2
    exit 1
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
g++ -O2 -o "$work/embree_packets" benches/compare/embree_packets.cpp \
    -I"$mitsuba/include" -L"$mitsuba" -lembree3 -Wl,-rpath,"$mitsuba"
taskset -c 0 cargo run -q --release --example render_rays -- "$scene" "$work"
for robust in 1 0; do
    for coherent in 1 0; do
        taskset -c 0 "$work/embree_packets" "$work" "$robust" "$coherent"
    done
done
