#!/usr/bin/env bash
# A contact sheet of a rendered run: the images of the frames at the given times side by side, each labelled.
# Usage: scripts/contact_sheet.sh RUN_DIR OUT.png TIME:LABEL [TIME:LABEL ...]
#   e.g. scripts/contact_sheet.sh out/demo out/demo/contact_sheet.png "7.6:t/T = 76/85" "8.5:t/T = 85/85"
# The frame of a time is the one RUN_DIR/frames.pvd lists at that time (within half a frame interval); its image
# is RUN_DIR/render/png/frame_NNNNN.png. Times without an image are left out with a note. Labels need the font of
# the Debian package fonts-dejavu-core (without it the images are unlabelled). Needs ffmpeg.
set -euo pipefail
run=$1
out=$2
shift 2
font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
look="x=12:y=h-34:fontsize=22:fontcolor=white:box=1:boxcolor=black@0.45:boxborderw=6"
inputs=()
filters=""
n=0
for spec in "$@"; do
  time=${spec%%:*}
  label=${spec#*:}
  file=$(awk -v t="$time" -F'"' '/<DataSet/ {
           for (i = 1; i < NF; i++) { if ($i ~ /timestep=$/) ts = $(i + 1); if ($i ~ /file=$/) f = $(i + 1) }
           d = ts - t; if (d < 0) d = -d; if (best == "" || d < bd) { best = f; bd = d } }
         END { if (bd < 0.01) print best }' "$run/frames.pvd")
  number=$(basename "${file:-none}" .vtp | sed 's/^frame_//')
  image="$run/render/png/frame_$number.png"
  if [ -z "$file" ] || [ ! -f "$image" ]; then
    echo "contact_sheet: no image of t = $time s in $run/render/png; left out" >&2
    continue
  fi
  inputs+=(-i "$image")
  if [ -f "$font" ]; then
    filters+="[$n:v]drawtext=fontfile=$font:text='$label':$look[v$n];"
  else
    filters+="[$n:v]null[v$n];"
  fi
  n=$((n + 1))
done
if [ "$n" -eq 0 ]; then
  echo "contact_sheet: no images; $out not written" >&2
  exit 0
fi
stack=""
for ((i = 0; i < n; i++)); do stack+="[v$i]"; done
if [ "$n" -gt 1 ]; then filters+="${stack}hstack=inputs=$n[out]"; else filters+="[v0]null[out]"; fi
ffmpeg -y -loglevel error "${inputs[@]}" -filter_complex "$filters" -map "[out]" -frames:v 1 "$out"
echo "contact_sheet: $out ($n frames)"
