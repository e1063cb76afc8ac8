#!/usr/bin/python3
"""The bubbles' pressure against the water around them in a 2D mistfall run: P_B - P_water over a time window.

For each frame with FROM <= t <= TO (frames.pvd's times), the bubbles are the clusters of enclosed gas: fluid
particles (kind 0) of phase gas (1) with the `enclosed` flag (delta_gl) set, two of them in one cluster when closer
than the link radius (as the solver groups its gas regions, src/mps/enclosed_gas.hpp: numerics.gas_region_link l0
when the case sets it, else numerics.radius_number_density l0, 2.1 l0 by default; --link overrides). The frames
carry no region id, so the clusters are found again here. Clusters of fewer than --min-particles (default 6, the
solver's bubble_min_particles default) are left out. For each cluster left:
  P_B      the mean pressure of its gas particles;
  P_water  the mean pressure of the liquid fluid particles (kind 0, phase 0) within --water-within l0 (default 1.5)
           of any of its gas particles; a cluster with no such water is left out (and counted).
Each cluster in each frame is one bubble-frame (docs/waterfall.md: "the gas of each enclosed cluster of 6 or more
particles against the water within 1.5 l0 of it"). Prints the number of bubble-frames, the median of P_B - P_water
with its quartiles, as "median (q25..q75)", and the median of P_water; --csv FILE writes one row per bubble-frame.
l0 is the case's numerics.particle_spacing (RUN_DIR/case.toml).
Exit codes: 0 done; 1 bad input (not a run directory, no case.toml or particle_spacing, frames without the
`enclosed` array, no frame or no bubble in the window, bad option), with a one-line message on stderr.
Needs Debian's python3-numpy (`make deps`; plot_frames' reader also loads python3-matplotlib); run it with
/usr/bin/python3.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from overfall_profile import add_window_arguments, case_spacing, frames_between, load_case_doc  # noqa: E402
from plot_frames import KIND_FLUID, PHASE_GAS, PHASE_LIQUID, Parser, PlotError, read_vtp  # noqa: E402

import numpy as np  # noqa: E402


def read_bubble_case(run_dir):
    """(l0, link radius in l0) from RUN_DIR/case.toml: the solver's gas-region link (gas_region_link, 0 meaning
    radius_number_density, default 2.1)."""
    path = os.path.join(run_dir, "case.toml")
    doc = load_case_doc(run_dir)
    numerics = doc.get("numerics", {})
    spacing = case_spacing(doc, run_dir)
    if doc.get("case", {}).get("dimension", 2) != 2:
        raise PlotError(f"{path}: bubble_pressure_gap measures 2D runs only")
    link = float(numerics.get("gas_region_link", 0.0) or 0.0)
    if link <= 0.0:
        link = float(numerics.get("radius_number_density", 2.1))
    return float(spacing), link


def clusters(points, link):
    """Connected components of the points (n x 2), two points linked when closer than `link`: a list of index
    arrays, largest first."""
    n = len(points)
    parent = np.arange(n)

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for start in range(0, n, 256):  # 256 rows of distances at a time: a few MB for thousands of points
        block = points[start:start + 256]
        d2 = np.sum((block[:, None, :] - points[None, :, :]) ** 2, axis=2)
        rows, cols = np.nonzero(d2 < link * link)
        for i, j in zip(rows + start, cols):
            if i < j:
                a, b = root(i), root(j)
                if a != b:
                    parent[max(a, b)] = min(a, b)
    labels = np.array([root(i) for i in range(n)], dtype=int)
    groups = [np.flatnonzero(labels == r) for r in np.unique(labels)]
    return sorted(groups, key=len, reverse=True)


def bubbles_of_frame(a, l0, link, min_particles, water_within):
    """[(gas particles, centroid x, centroid y, P_B, water particles, P_water)] of one frame's arrays, and the number
    of clusters of min_particles or more with no water within water_within l0."""
    fluid = a["kind"] == KIND_FLUID
    pts = a["Points"][:, :2]
    gas = np.flatnonzero(fluid & (a["phase"] == PHASE_GAS) & (a["enclosed"] == 1))
    liquid = np.flatnonzero(fluid & (a["phase"] == PHASE_LIQUID))
    rows, dry = [], 0
    if gas.size < min_particles:
        return rows, dry
    reach = water_within * l0
    for members in clusters(pts[gas], link * l0):
        if len(members) < min_particles:
            break
        g = gas[members]
        lo, hi = pts[g].min(axis=0) - reach, pts[g].max(axis=0) + reach
        box = liquid[np.all((pts[liquid] >= lo) & (pts[liquid] <= hi), axis=1)]
        if box.size:
            d2 = np.sum((pts[box][:, None, :] - pts[g][None, :, :]) ** 2, axis=2)
            box = box[np.min(d2, axis=1) <= reach * reach * (1.0 + 1e-12)]
        if box.size == 0:
            dry += 1
            continue
        centre = pts[g].mean(axis=0)
        rows.append((len(g), centre[0], centre[1], float(a["pressure"][g].mean()), box.size,
                     float(a["pressure"][box].mean())))
    return rows, dry


def measure(run_dir, chosen, l0, link, min_particles, water_within):
    """[(t, gas particles, x, y, P_B, water particles, P_water)] over the frames `chosen`, and the dry clusters."""
    rows, dry = [], 0
    for t, path in chosen:
        _, a = read_vtp(path)
        if "enclosed" not in a:
            raise PlotError(f"{path} has no 'enclosed' array (written before bubbles were marked)")
        found, no_water = bubbles_of_frame(a, l0, link, min_particles, water_within)
        rows += [(t,) + r for r in found]
        dry += no_water
    return rows, dry


def main():
    ap = Parser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir", metavar="RUN_DIR")
    add_window_arguments(ap, default_from=2.0)
    ap.add_argument("--min-particles", metavar="N", type=int, default=6,
                    help="smallest cluster counted as a bubble (gas particles; default 6)")
    ap.add_argument("--link", metavar="R", type=float, default=None,
                    help="link radius of a cluster (of l0; default: the case's gas_region_link, else its "
                         "radius_number_density, else 2.1)")
    ap.add_argument("--water-within", metavar="R", type=float, default=1.5,
                    help="the water around a bubble: liquid within this distance of its gas (of l0; default 1.5)")
    ap.add_argument("--csv", metavar="FILE", help="also write one row per bubble-frame to this file")
    args = ap.parse_args()
    try:
        if not os.path.isdir(args.run_dir):
            raise PlotError(f"{args.run_dir} is not a directory")
        for name, value in (("--min-particles", args.min_particles), ("--link", args.link),
                            ("--water-within", args.water_within)):
            if value is not None and not value > 0:
                raise PlotError(f"{name} must be > 0, got {value}")
        l0, link = read_bubble_case(args.run_dir)
        link = args.link if args.link is not None else link
        chosen = frames_between(args.run_dir, args.t_from, args.t_to)
        rows, dry = measure(args.run_dir, chosen, l0, link, args.min_particles, args.water_within)
        if not rows:
            raise PlotError(f"no enclosed gas cluster of {args.min_particles} or more particles with water around it "
                            f"in the {len(chosen)} frames between t = {chosen[0][0]:g} and {chosen[-1][0]:g} s")
        if args.csv:
            tmp = args.csv + ".tmp"
            try:
                with open(tmp, "w") as f:
                    f.write("t,gas_particles,x,y,p_bubble,water_particles,p_water,gap\n")
                    for t, n, x, y, p_b, m, p_w in rows:
                        f.write(f"{t:.6g},{n},{x:.6g},{y:.6g},{p_b:.6g},{m},{p_w:.6g},{p_b - p_w:.6g}\n")
                os.replace(tmp, args.csv)
            except OSError as e:
                raise PlotError(f"cannot write {args.csv}: {e.strerror}") from None
    except PlotError as e:
        print(f"bubble_pressure_gap: {e}", file=sys.stderr)
        sys.exit(1)
    table = np.array([r[1:] for r in rows])
    gap = table[:, 3] - table[:, 5]
    q25, median, q75 = np.percentile(gap, [25, 50, 75])
    frames_with = len({r[0] for r in rows})
    print(f"frames {len(chosen)} (t = {chosen[0][0]:.3f} .. {chosen[-1][0]:.3f} s), l0 = {l0} m; bubbles: enclosed "
          f"gas linked within {link:g} l0, {args.min_particles} or more particles; "
          f"water within {args.water_within:g} l0")
    print(f"bubble-frames   {len(rows)} (in {frames_with} frames; gas particles median {np.median(table[:, 0]):g}, "
          f"largest {table[:, 0].max():g}; left out for no water around: {dry})")
    print(f"P_B - P_water   median {median:+.1f} ({q25:+.1f}..{q75:+.1f}) Pa")
    print(f"P_water         median {np.median(table[:, 5]):.1f} Pa")


if __name__ == "__main__":
    main()
