#!/bin/sh
# The tone map on real renders of the example office: the view from-door rendered at
# 640x360, 1280x720 and 1920x1080, then `penumbra tonemap` on each, with its solve time (from
# <view>.tonemap.json) and its peak memory (/usr/bin/time -v, when installed).
#   usage: bench/tonemap_office.sh [BUILD_DIR] [OUT_DIR]
set -eu
build=${1:-build}
out=${2:-out/tonemap-office}
mkdir -p "$out"
for size in 640x360 1280x720 1920x1080; do
  w=${size%x*}
  h=${size#*x}
  sed "s/size: \[1280, 720\]/size: [$w, $h]/" data/office.yaml > "$out/office-$size.yaml"
  cp data/sensors.pts "$out/" 2>/dev/null || true
  "$build/penumbra" render "$out/office-$size.yaml" --view from-door -o "$out/$size" -q
  if [ -x /usr/bin/time ]; then
    /usr/bin/time -v "$build/penumbra" tonemap "$out/$size/from-door.exr" -o "$out/$size/tm.png" \
      2> "$out/$size/time.txt" > /dev/null
    rss=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$out/$size/time.txt")
  else
    "$build/penumbra" tonemap "$out/$size/from-door.exr" -o "$out/$size/tm.png" > /dev/null
    rss=unknown
  fi
  json="$out/$size/tm.tonemap.json"
  printf '%-10s variables=%s outer_iterations=%s solve_s=%s total_s=%s peak_rss_kB=%s\n' "$size" \
    "$(sed -n 's/^  "variables": \([0-9]*\).*/\1/p' "$json")" \
    "$(sed -n 's/^  "outer_iterations": \([0-9]*\).*/\1/p' "$json")" \
    "$(sed -n 's/^    "solve": \([0-9.e-]*\).*/\1/p' "$json")" \
    "$(sed -n 's/^    "total": \([0-9.e-]*\).*/\1/p' "$json")" "$rss"
done
