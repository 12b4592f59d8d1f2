#!/bin/sh
# Our three display maps beside three operators of Debian's pfstmo on the same render, each
# judged by the share of visible edges whose contrast it keeps within 5 %
# (docs/tonemap.md).
#   usage: bench/pfstmo_compare.sh VIEW.exr [VIEW.faceid.exr] [OUT_DIR] [BUILD_DIR]
# Needs pfstools and pfstmo (apt-get install pfstools pfstmo); skips them with a message if they
# are not installed, and still reports ours.
set -eu
exr=$1
faces=${2:-${exr%.exr}.faceid.exr}
out=${3:-out/pfstmo-compare}
build=${4:-build}
mkdir -p "$out"
penumbra=$build/penumbra
measure=$build/edge_contrast_tool
for method in clip linear constraint; do
  "$penumbra" tonemap "$exr" --faces "$faces" -o "$out/$method.png" --display "$method"
  printf '%-12s ' "$method"; "$measure" "$exr" "$faces" "$out/$method.png"
done
if ! command -v pfstmo_mantiuk08 >/dev/null 2>&1 || ! command -v pfsin >/dev/null 2>&1; then
  echo "pfstools/pfstmo not installed: skipping mantiuk08, reinhard02, drago03" >&2
  echo "  (apt-get install --no-install-recommends pfstools pfstmo)" >&2
  exit 0
fi
# mantiuk08 writes display-referred values; the other two write linear values, which are gamma
# encoded for the display (as their manual pages do).
pfsin "$exr" | pfstmo_mantiuk08 | pfsout "$out/mantiuk08.png"
pfsin "$exr" | pfstmo_reinhard02 | pfsgamma -g 2.2 | pfsout "$out/reinhard02.png"
pfsin "$exr" | pfstmo_drago03 | pfsgamma -g 2.2 | pfsout "$out/drago03.png"
for op in mantiuk08 reinhard02 drago03; do
  printf '%-12s ' "$op"; "$measure" "$exr" "$faces" "$out/$op.png"
done
