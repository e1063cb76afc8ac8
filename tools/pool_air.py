#!/usr/bin/python3
"""The air held in a 2D mistfall waterfall's pool and the water standing above its level, a frame, over a time window.

For each frame with FROM <= t <= TO (frames.pvd's times), counts
  air in the pool         the gas fluid particles (kind 0, phase 1) under y = --air-below with --x-from <= x <=
                          --x-to, plus every entrained bubble point (kind 5, numerics.entrained_bubble_diameter),
                          wherever it lies;
  water above the pool    the liquid fluid particles (kind 0, phase 0) above y = --water-above with --x-from <= x <=
                          --x-to (no upper bound: the falling sheet's water in that span counts too);
and prints the mean of each a frame (with the gas particles and the points apart, and the least and most in a
frame). These are the columns "air in the pool a frame (gas particles under y = 0.14 m, x 0.3-1.0 m, and every
bubble point)" and "water above y = 0.15 m in the pool a frame" of docs/waterfall.md; the defaults are the
waterfall cases' (cases/waterfall*.toml: the pool between the brink at x = 0.30 m and the weir at x = 1.0 m, its
surface at y = 0.15 m).
Exit codes: 0 done; 1 bad input (not a run directory, no frame in the window, bad option), with a one-line message
on stderr. Needs Debian's python3-numpy (`make deps`; plot_frames' reader also loads python3-matplotlib); run it
with /usr/bin/python3.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from overfall_profile import add_window_arguments, frames_between  # noqa: E402
from plot_frames import KIND_FLUID, KIND_POINT, PHASE_GAS, PHASE_LIQUID, Parser, PlotError, read_vtp  # noqa: E402

import numpy as np  # noqa: E402


def count_frame(a, x_from, x_to, air_below, water_above):
    """(gas particles in the pool, bubble points, water above the pool) of one frame's arrays."""
    fluid = a["kind"] == KIND_FLUID
    x, y = a["Points"][:, 0], a["Points"][:, 1]
    span = (x >= x_from) & (x <= x_to)
    gas = int(np.sum(fluid & (a["phase"] == PHASE_GAS) & span & (y < air_below)))
    points = int(np.sum(a["kind"] == KIND_POINT))
    water = int(np.sum(fluid & (a["phase"] == PHASE_LIQUID) & span & (y > water_above)))
    return gas, points, water


def main():
    ap = Parser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir", metavar="RUN_DIR")
    add_window_arguments(ap, default_from=2.0)
    ap.add_argument("--x-from", metavar="X", type=float, default=0.3,
                    help="the pool's span starts here (m; default 0.3, the waterfall cases' brink)")
    ap.add_argument("--x-to", metavar="X", type=float, default=1.0,
                    help="the pool's span ends here (m; default 1.0, the waterfall cases' weir)")
    ap.add_argument("--air-below", metavar="Y", type=float, default=0.14,
                    help="gas under this height is air in the pool (m; default 0.14, a centimetre under the "
                         "waterfall cases' pool surface)")
    ap.add_argument("--water-above", metavar="Y", type=float, default=0.15,
                    help="water above this height stands above the pool (m; default 0.15, the waterfall cases' "
                         "pool surface)")
    args = ap.parse_args()
    try:
        if not os.path.isdir(args.run_dir):
            raise PlotError(f"{args.run_dir} is not a directory")
        if not args.x_from < args.x_to:
            raise PlotError(f"--x-from {args.x_from} must lie below --x-to {args.x_to}")
        chosen = frames_between(args.run_dir, args.t_from, args.t_to)
        counts = np.array([count_frame(read_vtp(path)[1], args.x_from, args.x_to, args.air_below, args.water_above)
                           for _, path in chosen], dtype=float)
    except PlotError as e:
        print(f"pool_air: {e}", file=sys.stderr)
        sys.exit(1)
    gas, points, water = counts[:, 0], counts[:, 1], counts[:, 2]
    air = gas + points
    span = f"x {args.x_from:g}-{args.x_to:g} m"
    print(f"frames {len(chosen)} (t = {chosen[0][0]:.3f} .. {chosen[-1][0]:.3f} s)")
    print(f"air in the pool        {air.mean():.1f} a frame (gas particles under y = {args.air_below:g} m, {span}: "
          f"{gas.mean():.1f}; bubble points: {points.mean():.1f}); least {air.min():g}, most {air.max():g}")
    print(f"water above the pool   {water.mean():.1f} a frame (liquid particles above y = {args.water_above:g} m, "
          f"{span}); least {water.min():g}, most {water.max():g}")


if __name__ == "__main__":
    main()
