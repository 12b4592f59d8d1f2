#!/bin/sh
# TMQI (S, N, Q) and halos of every display map on the office renders and on a synthetic step
# (docs/tonemap.md, "TMQI"): both views of data/office.yaml, with interreflection and
# --direct-only, at the sizes given; our clip, linear, constraint and, when pfstools/pfstmo are
# installed, mantiuk08, reinhard02, drago03, durand02, fattal02. One line per image and map.
#   usage: bench/tmqi_office.sh [BUILD_DIR] [OUT_DIR] [SIZES]   (SIZES: "640x360 1280x720")
set -eu
build=${1:-build}
out=${2:-out/tmqi-office}
sizes=${3:-640x360 1280x720}
penumbra=$build/penumbra
tool=$build/tmqi_tool
mkdir -p "$out"
have_pfs=yes
if ! command -v pfstmo_mantiuk08 >/dev/null 2>&1 || ! command -v pfsin >/dev/null 2>&1; then
  have_pfs=no
  echo "pfstools/pfstmo not installed: ours only" >&2
  echo "  (apt-get install --no-install-recommends pfstools pfstmo)" >&2
fi

# judge NAME EXR FACES: every map on one HDR image.
judge() {
  name=$1 exr=$2 faces=$3 maps=$out/maps/$1
  mkdir -p "$maps"
  for method in clip linear constraint; do
    "$penumbra" tonemap "$exr" --faces "$faces" -o "$maps/$method.png" --display "$method" > /dev/null
  done
  ops=""
  if [ "$have_pfs" = yes ]; then
    # mantiuk08 and fattal02 write display-encoded values; the other three linear ones, encoded
    # with gamma 2.2 as their manual pages do.
    # An operator that fails on an input (mantiuk08 aborts on the step's black band) leaves no
    # image; the row says so.
    rm -f "$maps"/mantiuk08.png "$maps"/fattal02.png "$maps"/reinhard02.png "$maps"/drago03.png \
      "$maps"/durand02.png
    (pfsin "$exr" | pfstmo_mantiuk08 | pfsout "$maps/mantiuk08.png") 2>/dev/null || true
    (pfsin "$exr" | pfstmo_fattal02 | pfsout "$maps/fattal02.png") 2>/dev/null || true
    for op in reinhard02 drago03 durand02; do
      (pfsin "$exr" | "pfstmo_$op" | pfsgamma -g 2.2 | pfsout "$maps/$op.png") 2>/dev/null || true
    done
    ops="mantiuk08 reinhard02 drago03 durand02 fattal02"
  fi
  # Halos on what the display emits: ours through the display model they are encoded for
  # (sRGB, black 0.02 of white), the others' through a gamma-2.2 display.
  for method in clip linear constraint $ops; do
    printf '%-28s %-11s ' "$name" "$method"
    decode="--decode-gamma 2.2"
    case $method in clip | linear | constraint) decode=--decode-display ;; esac
    if [ -s "$maps/$method.png" ]; then
      # shellcheck disable=SC2086 # the option and its value are two words
      "$tool" "$exr" "$faces" "$maps/$method.png" $decode
    else
      echo "no image (the operator failed on this input)"
    fi
  done
}

"$tool" --write-step "$out"
judge step-1to100 "$out/step.exr" "$out/step.faceid.exr"
for size in $sizes; do
  w=${size%x*}
  h=${size#*x}
  sed "s/size: \[1280, 720\]/size: [$w, $h]/" data/office.yaml > "$out/office-$size.yaml"
  cp data/sensors.pts "$out/"
  for light in total direct; do
    flag=""
    [ "$light" = direct ] && flag=--direct-only
    dir=$out/$size-$light
    [ -f "$dir/from-window.exr" ] || "$penumbra" render "$out/office-$size.yaml" -o "$dir" -q $flag
    for view in from-door from-window; do
      judge "$view-$size-$light" "$dir/$view.exr" "$dir/$view.faceid.exr"
    done
  done
done
