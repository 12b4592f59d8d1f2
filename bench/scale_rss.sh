#!/usr/bin/env bash
# Peak host memory of `penumbra grid` against the number of grid points ("scale without
# surprise"; the figures in docs/reliability.md "Scale"). Generates the scenes with
# bench/scale_scene, runs each under /usr/bin/time -v, and prints one row per run:
# points, peak RSS, wall time, and bytes a point (peak RSS over the points).
#
#   bench/scale_rss.sh [BUILD_DIR] [POINTS...]       default: build, 1e5 1e6 1e7
#   SOLIDS=10000 bench/scale_rss.sh build 1e5 1e6    the same in a hall of 10^4 boxes
#
# Needs GNU time (/usr/bin/time, Debian package `time`). The output folders go to a temporary
# directory, removed at the end.
set -euo pipefail

build=${1:-build}
shift || true
points=("$@")
[ ${#points[@]} -gt 0 ] || points=(1e5 1e6 1e7)
solids=${SOLIDS:-0}

for tool in "$build/penumbra" "$build/scale_scene"; do
  [ -x "$tool" ] || { echo "scale_rss.sh: $tool is missing; build it first" >&2; exit 1; }
done
[ -x /usr/bin/time ] || { echo "scale_rss.sh: /usr/bin/time (GNU time) is missing" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

printf '%-12s %8s %12s %10s %10s %10s\n' points solids "peak RSS" wall setup "B/point"
for n in "${points[@]}"; do
  "$build/scale_scene" "$n" "$solids" > "$work/scene.yaml"
  /usr/bin/time -v "$build/penumbra" grid "$work/scene.yaml" -o "$work/out" --device cpu -q \
    2> "$work/time.txt" || { cat "$work/time.txt" >&2; exit 1; }
  rss_kb=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$work/time.txt")
  wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {print $2}' "$work/time.txt")
  count=$(grep -o '"points": [0-9]*' "$work/out/summary.json" | awk '{s += $2} END {print s}')
  setup=$(grep -o '"setup_s": [0-9.e-]*' "$work/out/summary.json" | awk '{printf "%.2f s", $2}')
  awk -v n="$count" -v s="$solids" -v kb="$rss_kb" -v w="$wall" -v st="$setup" 'BEGIN {
    printf "%-12d %8d %9.0f MB %10s %10s %10.1f\n", n, s, kb * 1024 / 1e6, w, st, kb * 1024 / n
  }'
  rm -rf "$work/out"
done
