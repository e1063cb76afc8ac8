#!/usr/bin/python3
"""Still-water figures of a hydrostatic tank run (cases/hydrostatic.toml and its resolution series).

Usage: tools/still_tank.py RUN_DIR [--bands 5] [--csv OUT.csv] [--quiet]

Per frame: max and rms fluid speed, kinetic energy per particle, escaped count, the height of the highest
particle above the initial surface, and where the fastest particle is (distance to the nearest side wall and
depth). At the last frame: the mean pressure over depth bands against rho g h, h the depth below the free
surface (top particle row + l0/2, the edge of the top particles' volume). Prints a table and a summary line
    still-tank: vmax <max over frames> m/s, rms(last) ..., lost N, worst band error E %
and exits 0 (the figures are judged by the caller: tests/tools and tools/validate.sh)."""
import argparse
import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_frames import PlotError, read_case, read_pvd, read_vtp  # noqa: E402

FLUID = 0
ESCAPED = 3


def band_errors(points, pressure, rho, g, l0, bands):
    """Mean p / (rho g h) per depth band (band 0 at the surface); h from the top row + l0/2."""
    y = points[:, 1]
    surface = y.max() + 0.5 * l0
    depth = surface - y
    total = surface - (y.min() - 0.5 * l0)
    ratios = []
    for b in range(bands):
        lo, hi = b * total / bands, (b + 1) * total / bands
        sel = (depth >= lo) & (depth < hi)
        if not sel.any():
            ratios.append(float("nan"))
            continue
        ratios.append(pressure[sel].sum() / (rho * g * depth[sel]).sum())
    return ratios


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir")
    ap.add_argument("--bands", type=int, default=5)
    ap.add_argument("--csv", help="write the per-frame table here")
    ap.add_argument("--quiet", action="store_true", help="print only the summary line and the band table")
    args = ap.parse_args()
    try:
        _, _, l0 = read_case(args.run_dir)
        if l0 is None:
            raise PlotError(f"{args.run_dir}/case.toml gives no numerics.particle_spacing")
        frames = read_pvd(args.run_dir)
        rho, g = 1000.0, 9.81  # the shipped tank's water and gravity
        rows = []
        first = None
        walls = None
        last = None
        for t, path in frames:
            _, a = read_vtp(path)
            kind = a["kind"]
            fluid = kind == FLUID
            pts = a["Points"][fluid]
            vel = a["velocity"][fluid]
            speed = np.linalg.norm(vel, axis=1)
            if first is None:
                first = pts[:, 1].max()
                walls = (pts[:, 0].min() - 0.5 * l0, pts[:, 0].max() + 0.5 * l0)
            k = int(np.argmax(speed)) if speed.size else 0
            wall_distance = min(pts[k, 0] - walls[0], walls[1] - pts[k, 0]) if speed.size else 0.0
            rows.append({
                "time": t, "max_speed": float(speed.max()) if speed.size else 0.0,
                "rms_speed": float(np.sqrt((speed ** 2).mean())) if speed.size else 0.0,
                "kinetic_energy": float(0.5 * (speed ** 2).mean()) if speed.size else 0.0,
                "escaped": int((kind == ESCAPED).sum()),
                "rise": float(pts[:, 1].max() - first) if speed.size else 0.0,
                "fastest_wall_distance": float(wall_distance),
                "fastest_depth": float(pts[:, 1].max() - pts[k, 1]) if speed.size else 0.0,
            })
            last = (pts, a["pressure"][fluid])
    except PlotError as e:
        print(f"still_tank.py: {e}", file=sys.stderr)
        return 1
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)
    if not args.quiet:
        print(f"{'t [s]':>7} {'max [m/s]':>10} {'rms [m/s]':>10} {'lost':>5} {'rise [mm]':>9} "
              f"{'fastest: wall [mm]':>18} {'depth [mm]':>10}")
        for r in rows:
            print(f"{r['time']:7.2f} {r['max_speed']:10.2e} {r['rms_speed']:10.2e} {r['escaped']:5d} "
                  f"{1e3 * r['rise']:9.2f} {1e3 * r['fastest_wall_distance']:18.1f} {1e3 * r['fastest_depth']:10.1f}")
    ratios = band_errors(last[0], last[1], rho, g, l0, args.bands)
    print("pressure / (rho g h) per depth band at t = %.2f s (band 1 at the surface): %s" %
          (rows[-1]["time"], ", ".join(f"{r:.4f}" for r in ratios)))
    worst = max(abs(r - 1.0) for r in ratios[1:]) if len(ratios) > 1 else float("nan")
    print(f"still-tank: vmax {max(r['max_speed'] for r in rows):.3e} m/s, rms(last) {rows[-1]['rms_speed']:.3e} m/s, "
          f"lost {rows[-1]['escaped']}, worst band error below the top band {100 * worst:.2f} %")
    return 0


if __name__ == "__main__":
    sys.exit(main())
