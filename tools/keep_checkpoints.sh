#!/bin/bash
# Keeps a copy of a run directory at every checkpoint, beside a long run, so that a loss or a divergence can be
# replayed from the checkpoint before it (`mistfall simulate --resume COPY`, after setting output.end_time in the
# copy's case.toml). Each copy is SNAPDIR/tT.TT (T: the last diagnostics row's time): frames and fields hard-linked,
# checkpoint.bin, diagnostics.csv, frames.pvd, bubbles.csv, vents.csv and case.toml copied. Stops when no
# `mistfall simulate` of RUN is running. Usage: tools/keep_checkpoints.sh RUN_DIR SNAPDIR &
set -u
if [ $# -ne 2 ]; then echo "usage: $0 RUN_DIR SNAPDIR" >&2; exit 1; fi
run=$1; snap=$2; last=""
mkdir -p "$snap"
running() { pgrep -f "simulate.*--resume $run( |$)" >/dev/null || pgrep -f "simulate $run.toml" >/dev/null || pgrep -f "simulate .* --out $run( |$)" >/dev/null; }
while true; do
  if [ -f "$run/checkpoint.bin" ]; then
    m=$(stat -c %Y "$run/checkpoint.bin")
    if [ "$m" != "$last" ]; then
      sleep 5  # the checkpoint is written after the frame and the rows
      t=$(tail -1 "$run/diagnostics.csv" | cut -d, -f1 | awk '{printf "%.2f", $1}')
      d=$snap/t$t; rm -rf "$d"; mkdir -p "$d"
      for sub in frames fields; do [ -d "$run/$sub" ] && cp -al "$run/$sub" "$d/$sub"; done
      for f in checkpoint.bin diagnostics.csv frames.pvd bubbles.csv vents.csv case.toml; do
        [ -f "$run/$f" ] && cp "$run/$f" "$d/"
      done
      last=$m
    fi
  fi
  running || { sleep 30; running || exit 0; }
  sleep 20
done
