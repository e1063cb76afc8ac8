#!/usr/bin/python3
"""Draw the texture stage of a mistfall run: the mist cloud's extent over time and snapshots (issue 5).

Reads RUN_DIR/texture/texture.pvd with the point clouds it lists (`mistfall texture` or simulate with
[texture] inline = true: arrays kind 0 droplet, 1 mist, 2 bubble, 3 micro-bubble, diameter, velocity) and, for the
snapshots, the matching RUN_DIR/frames/frame_NNNNN.vtp (the water, drawn behind). Writes to RUN_DIR/plots
(or --out DIR):
  texture_extent.png  against time: the counts of mist and micro-bubble representatives, the mist's horizontal
                      extent (5th-95th percentile of x) and heights (median and 95th percentile of y), and
                      the micro-bubbles' median height;
  texture_extent.csv  the same numbers;
  texture_NNNNN.png   for each frame asked with --frames: water (light blue), mist (grey), droplets (black),
                      micro-bubbles (orange), bubbles (red), in the x-y plane.
Exit codes: 0 done; 1 bad input, with a one-line message on stderr.
Needs Debian's python3-numpy and python3-matplotlib (`make deps`); run it with /usr/bin/python3.
"""
import glob
import os
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_frames import Parser, PlotError, read_pvd_file, read_vtp, read_vtp_arrays, save, KIND_FLUID  # noqa: E402

import numpy as np  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402  (plot_frames has chosen the Agg backend)

DROPLET, MIST, BUBBLE, MICRO_BUBBLE = 0, 1, 2, 3  # TextureKind in src/texture/texture_kind.hpp


def read_texture_pvd(run_dir):
    """[(time, path)] of the texture's frames: the .vtp files texture.pvd lists or, when the run wrote none
    ([texture] vtp = false), the texture_NNNNN.bin files."""
    entries = []
    try:
        entries = read_pvd_file(os.path.join(run_dir, "texture", "texture.pvd"),
                                f"run `mistfall texture {run_dir}` first")
    except PlotError as e:
        if "lists no frames" not in str(e):
            raise
    if entries:
        return entries
    bins = sorted(glob.glob(os.path.join(run_dir, "texture", "texture_*.bin")))
    if not bins:
        raise PlotError(f"{run_dir}/texture has no texture frames (.vtp or .bin)")
    return [(read_texture_bin(b)[0], b) for b in bins]


def read_texture_bin(path):
    """(time, arrays with Points and kind) of a texture_NNNNN.bin (format: src/io/texture_files.hpp)."""
    with open(path, "rb") as f:
        data = f.read()
    if len(data) < 32 or data[:8] != b"MFTEXTR1":
        raise PlotError(f"unreadable texture file {path}: not a mistfall texture file")
    time, n = struct.unpack_from("<dQ", data, 16)
    need = 32 + n * (3 * 8 + 3 * 8 + 8 + 1 + 8)
    if len(data) < need:
        raise PlotError(f"unreadable texture file {path}: truncated ({len(data)} of {need} bytes)")
    pos = np.frombuffer(data, "<f8", 3 * n, 32).reshape(-1, 3)
    kind = np.frombuffer(data, np.uint8, n, 32 + n * 56)
    return time, {"Points": pos, "kind": kind}


def read_texture_frame(path):
    return read_texture_bin(path)[1] if path.endswith(".bin") else read_vtp_arrays(path, "texture frame")[1]


def extent_row(time, arrays):
    kind = arrays.get("kind", np.zeros(0, np.uint8))
    pts = arrays.get("Points", np.zeros((0, 3)))
    mist, micro = pts[kind == MIST], pts[kind == MICRO_BUBBLE]
    row = [time, len(mist), len(micro)]
    if len(mist):
        row += [np.percentile(mist[:, 0], 5), np.percentile(mist[:, 0], 95), np.median(mist[:, 1]),
                np.percentile(mist[:, 1], 95)]
    else:
        row += [np.nan] * 4
    row.append(np.median(micro[:, 1]) if len(micro) else np.nan)
    return row


def main():
    ap = Parser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir")
    ap.add_argument("--frames", default="", help="comma-separated frame indices to draw as snapshots")
    ap.add_argument("--out", default=None, help="output folder (default RUN_DIR/plots)")
    args = ap.parse_args()
    try:
        run(args)
    except PlotError as e:
        print(f"plot_texture: {e}", file=sys.stderr)
        sys.exit(1)


def run(args):
    entries = read_texture_pvd(args.run_dir)
    out_dir = args.out or os.path.join(args.run_dir, "plots")
    os.makedirs(out_dir, exist_ok=True)
    rows = []
    for time, path in entries:
        arrays = read_texture_frame(path)
        rows.append(extent_row(time, arrays))
    table = np.array(rows, dtype=float)
    header = "time,mist,micro_bubbles,mist_x05,mist_x95,mist_y50,mist_y95,micro_bubble_y50"
    csv_path = os.path.join(out_dir, "texture_extent.csv")
    np.savetxt(csv_path + ".tmp", table, delimiter=",", header=header, comments="", fmt="%.6g")
    os.replace(csv_path + ".tmp", csv_path)

    t = table[:, 0]
    fig, (a1, a2, a3) = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
    a1.plot(t, table[:, 1], label="mist (representatives)")
    a1.plot(t, table[:, 2], label="micro-bubbles (representatives)")
    a1.set_ylabel("count")
    a1.legend(fontsize=8)
    a2.fill_between(t, table[:, 3], table[:, 4], alpha=0.3, label="mist x, 5th-95th percentile")
    a2.set_ylabel("x [m]")
    a2.legend(fontsize=8)
    a3.plot(t, table[:, 5], label="mist height, median")
    a3.plot(t, table[:, 6], label="mist height, 95th percentile")
    a3.plot(t, table[:, 7], label="micro-bubble height, median")
    a3.set_ylabel("y [m]")
    a3.set_xlabel("t [s]")
    a3.legend(fontsize=8)
    fig.suptitle("texture: the mist cloud and the micro-bubbles")
    save(fig, os.path.join(out_dir, "texture_extent.png"), 100)
    plt.close(fig)

    for spec in filter(None, args.frames.split(",")):
        try:
            k = int(spec)
            time, path = entries[k]
        except (ValueError, IndexError):
            raise PlotError(f"--frames: no texture frame {spec!r} (there are {len(entries)})") from None
        cloud = read_texture_frame(path)
        fig, ax = plt.subplots(figsize=(8, 5))
        frame = os.path.join(args.run_dir, "frames", f"frame_{k:05d}.vtp")
        if os.path.isfile(frame):
            _, water = read_vtp(frame)
            liquid = (water["kind"] == KIND_FLUID) & (water["phase"] == 0)
            ax.scatter(water["Points"][liquid, 0], water["Points"][liquid, 1], s=4, c="lightblue", label="water")
            walls = water["kind"] != KIND_FLUID
            ax.scatter(water["Points"][walls, 0], water["Points"][walls, 1], s=2, c="lightgrey")
        for kind, colour, size, label in ((MIST, "dimgrey", 0.5, "mist"), (DROPLET, "black", 6, "droplets"),
                                          (MICRO_BUBBLE, "orange", 0.5, "micro-bubbles"),
                                          (BUBBLE, "red", 6, "bubbles")):
            sel = cloud.get("kind", np.zeros(0)) == kind
            if sel.any():
                ax.scatter(cloud["Points"][sel, 0], cloud["Points"][sel, 1], s=size, c=colour, label=label)
        ax.set_aspect("equal")
        ax.set_title(f"texture at t = {time:.3f} s")
        ax.legend(fontsize=7, loc="upper right", markerscale=3)
        save(fig, os.path.join(out_dir, f"texture_{k:05d}.png"), 110)
        plt.close(fig)
    print(f"plot_texture: wrote {len(entries)} rows to {csv_path} and the plots in {out_dir}")


if __name__ == "__main__":
    main()
