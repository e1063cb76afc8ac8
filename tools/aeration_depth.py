#!/usr/bin/python3
"""Measure the plunging sheet of a 2D mistfall waterfall run under the pool: the jet and the air it carries down.

Issue 16, item 3: the plunge-zone aeration against a plunging-jet correlation. The sheet enters the pool as a
plane jet. Its thickness and speed at the pool are those of the falling water: V0 = sqrt(U^2 + 2 g drop), with U
= q / h the brink velocity (Rouse's brink, h = 0.715 h_c, from mid-depth), and B = q / V0. A plane turbulent jet
keeps its momentum flux, and its centreline speed decays as u_c = K V0 (B / s)^(1/2) with the distance s from where
it enters (Albertson, Dai, Jensen & Rouse 1950: K = 2.28; Rajaratnam 1976, "Turbulent Jets": K = 2.47, both with B
the slot width), past its potential core, s = K^2 B (5.2-6.1 B), in which it keeps V0: the correlation used is
min(K V0 (B / s)^(1/2), V0). Air bubbles go down with the jet to where u_c has fallen to their rise speed u_t:
H = B (K V0 / u_t)^2 (the plane-jet form of Clanet & Lasheras' (1997) argument for round jets), with u_t the
case's numerics.entrained_gas_rise_speed (default 0.23 m/s).

Measured, per frame from --from to --to:
* the pool level y_s: the floor plus the water's area over the level window (default the last 35 cm of the pool
  before the weir, less 5 cm) per unit length, counted below twice the weir's crest height;
* the air under it: gas particles (and entrained points) of the pool's span below y_s - l0 whose fluid neighbours (within 2.1 l0) are at
  least half water, at depth d = y_s - y; their number, deepest and 90th-percentile depth;
* the jet: in each frame, the fastest downward water particle in each band of depth l0 over the pool's span; the
  median over the frames is the measured u_c (at the paper's l0 = 5 mm the sheet, q / V0 = 6.3 mm, is about one
  particle thick: its fastest particle is its centreline), against K V0 (B / s)^(1/2) with s = d / sin(theta) the
  distance along the jet's axis (theta its angle to the horizontal at the pool). The correlation holds for a
  submerged jet far from walls (s of several B); near the floor the floor stops the jet.

Writes RUN_DIR/plots/aeration.csv (depth, measured u_c, the correlation's u_c with K = 2.28 and 2.47, and the
share of the entrained air's particle-frames in that depth band) and prints a summary. Exit codes: 0 done;
1 bad input, with a one-line message on stderr. Needs Debian's python3-numpy (`make deps`); run it with /usr/bin/python3.
"""
import math
import os
import sys
import warnings

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from overfall_profile import (ROUSE_BRINK_RATIO, add_window_arguments, frames_between,  # noqa: E402
                              read_overfall_case, region_box)
from plot_frames import Parser, PlotError, read_vtp, KIND_FLUID, KIND_POINT  # noqa: E402

import numpy as np  # noqa: E402
import tomllib  # noqa: E402

PLANE_JET_K = (2.28, 2.47)  # u_c / V0 = K (B / s)^(1/2): Albertson et al. (1950), Rajaratnam (1976)


def read_case_extra(run_dir):
    with open(os.path.join(run_dir, "case.toml"), "rb") as f:
        doc = tomllib.load(f)
    floor_min, floor_max = region_box(doc, "floor")
    weir_min, weir_max = region_box(doc, "weir")
    rise = float(doc.get("numerics", {}).get("entrained_gas_rise_speed", 0.0)) or 0.23
    return float(floor_max[1]), float(weir_min[0]), float(weir_max[1]), rise


def main():
    ap = Parser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir")
    add_window_arguments(ap)
    args = ap.parse_args()
    try:
        run(args)
    except PlotError as e:
        print(f"aeration_depth: {e}", file=sys.stderr)
        sys.exit(1)


def run(args):
    l0, g, q, x_brink, y_bed, _, _, _ = read_overfall_case(args.run_dir, "channel_bed", None)
    y_floor, x_weir, y_crest, u_t = read_case_extra(args.run_dir)
    chosen = frames_between(args.run_dir, args.t_from, args.t_to)
    level_lo, level_hi = x_weir - 0.40, x_weir - 0.05
    cap = y_floor + 2.0 * (y_crest - y_floor)
    depth_bins = np.arange(0.0, cap - y_floor + l0, l0)
    levels, counts, deepest, p90, all_depths, peaks = [], [], [], [], [], []
    for _, path in chosen:
        _, a = read_vtp(path)
        fluid = a["kind"] == KIND_FLUID
        pts = a["Points"][:, :2]
        liquid, gas = fluid & (a["phase"] == 0), fluid & (a["phase"] == 1)
        # entrained air moved as points (numerics.entrained_bubble_diameter): air under water, and the water keeps
        # a particle for each point's volume
        point = a["kind"] == KIND_POINT
        xl, yl = pts[liquid, 0], pts[liquid, 1]
        window = liquid.copy()
        window[liquid] = (xl > level_lo) & (xl < level_hi) & (yl < cap)
        in_window = point & (pts[:, 0] > level_lo) & (pts[:, 0] < level_hi) & (pts[:, 1] < cap)
        y_s = y_floor + (window.sum() - in_window.sum()) * l0 * l0 / (level_hi - level_lo)
        levels.append(y_s)
        # the air under the surface, among water
        cand = np.flatnonzero((gas | point) & (pts[:, 0] > 0.0) & (pts[:, 0] < x_weir) & (pts[:, 1] < y_s - l0))
        near = fluid & (pts[:, 1] < y_s + 2.1 * l0)
        near_pts, near_water = pts[near], a["phase"][near] == 0
        depths = []
        for i in cand:
            r2 = np.sum((near_pts - pts[i]) ** 2, axis=1)
            within = (r2 < (2.1 * l0) ** 2) & (r2 > 0.0)
            if within.any() and near_water[within].mean() >= 0.5:
                depths.append(y_s - pts[i, 1])
        counts.append(len(depths))
        if depths:
            deepest.append(max(depths))
            p90.append(float(np.percentile(depths, 90)))
            all_depths.extend(depths)
        # the jet: the fastest downward water particle in each depth band
        in_pool = (xl > 0.0) & (xl < x_weir)
        band = np.digitize(y_s - yl[in_pool], depth_bins) - 1
        down = -a["velocity"][liquid][in_pool, 1]
        peak = np.full(len(depth_bins) - 1, np.nan)
        ok = (band >= 0) & (band < len(peak))
        np.fmax.at(peak, band[ok], down[ok])
        peaks.append(peak)
    y_s = float(np.mean(levels))
    pool_depth = y_s - y_floor
    h = ROUSE_BRINK_RATIO * (q * q / g) ** (1.0 / 3.0)
    u_b, drop = q / h, y_bed + 0.5 * h - y_s
    v_b = math.sqrt(2.0 * g * drop)
    v0 = math.hypot(u_b, v_b)
    theta = math.atan2(v_b, u_b)
    b0 = q / v0
    centres = 0.5 * (depth_bins[1:] + depth_bins[:-1])
    with warnings.catch_warnings():  # depth bands below the water in every frame stay NaN
        warnings.simplefilter("ignore", RuntimeWarning)
        u_c = np.nanmedian(np.array(peaks), axis=0)
    s = centres / math.sin(theta)
    # Within the potential core (s < K^2 B, about 5-6 B) the centreline keeps V0: the decay law would exceed it there.
    corr = [np.minimum(k * v0 * np.sqrt(b0 / s), v0) for k in PLANE_JET_K]
    share, _ = np.histogram(all_depths, bins=depth_bins)
    share = share / max(1, len(all_depths))

    out_dir = os.path.join(args.run_dir, "plots")
    os.makedirs(out_dir, exist_ok=True)
    csv_path = os.path.join(out_dir, "aeration.csv")
    with open(csv_path + ".tmp", "w") as f:
        f.write("depth,u_c_measured,u_c_albertson,u_c_rajaratnam,air_share\n")
        for k, d in enumerate(centres):
            f.write(f"{d:.5f},{u_c[k]:.5f},{corr[0][k]:.5f},{corr[1][k]:.5f},{share[k]:.5f}\n")
    os.replace(csv_path + ".tmp", csv_path)

    penetration = [b0 * (k * v0 / u_t) ** 2 for k in PLANE_JET_K]
    quarter = np.array(all_depths) > 0.75 * pool_depth if all_depths else np.array([])
    print(f"frames averaged: {len(chosen)} (t = {chosen[0][0]:.3f} .. {chosen[-1][0]:.3f} s), l0 = {l0} m")
    print(f"pool level      {100 * y_s:.2f} cm (spread {100 * np.std(levels):.2f} cm), depth {100 * pool_depth:.2f} cm")
    print(f"plane jet       V0 = {v0:.2f} m/s at {math.degrees(theta):.0f} deg, B = q/V0 = {1000 * b0:.2f} mm; "
          f"bubble rise u_t = {u_t} m/s")
    print(f"correlation     bubble penetration H = B (K V0/u_t)^2 = {penetration[0]:.2f}-{penetration[1]:.2f} m "
          f"(K = 2.28-2.47): {penetration[0] / pool_depth:.0f}-{penetration[1] / pool_depth:.0f} pool depths")
    print(f"air under water {np.mean(counts):.1f} particles a frame (0 in {sum(c == 0 for c in counts)} of "
          f"{len(counts)} frames); deepest {100 * np.mean(deepest) if deepest else float('nan'):.2f} cm "
          f"(mean over frames), 90th pct {100 * np.mean(p90) if p90 else float('nan'):.2f} cm; "
          f"in the lowest quarter of the pool: {100 * quarter.mean() if quarter.size else 0.0:.1f} %")
    ratio = u_c / corr[1]
    mid = (centres > 0.25 * pool_depth) & (centres < 0.5 * pool_depth)
    print(f"jet             measured u_c / Rajaratnam's over 1/4-1/2 of the pool depth: {np.nanmean(ratio[mid]):.2f}")
    for frac in (0.25, 0.5, 0.75):
        k = int(np.argmin(np.abs(centres - frac * pool_depth)))
        print(f"jet at {100 * centres[k]:5.2f} cm  u_c measured {u_c[k]:.2f} m/s, "
              f"correlation "
              f"{corr[0][k]:.2f}-{corr[1][k]:.2f} m/s")
    print(f"wrote {csv_path}")


if __name__ == "__main__":
    main()
