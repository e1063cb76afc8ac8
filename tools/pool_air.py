#!/usr/bin/python3
"""The air held in a 2D mistfall waterfall's pool and the water standing above its level, a frame, over a time window.

For each frame with FROM <= t <= TO (frames.pvd's times), counts
  air in the pool         the gas fluid particles (kind 0, phase 1) under y = --air-below with --x-from <= x <=
                          --x-to, plus every entrained bubble point (kind 5, numerics.entrained_bubble_diameter),
                          wherever it lies;
  water above the pool    the liquid fluid particles (kind 0, phase 0) above y = --water-above with --x-from <= x <=
                          --x-to (no upper bound: the falling sheet's water in that span counts too);
  the pool's packing     the fluid particles of both phases (kind 0) between the floor, y = 0, and y =
                          --packing-below with --x-from <= x <= --x-to, times l0^2 over that box's area: 1 for a box
                          full of particles at their spacing, less where the particles leave space that neither phase
                          fills (l0: [numerics] particle_spacing of RUN_DIR/case.toml; the line is left out without it);
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
from plot_frames import KIND_FLUID, KIND_POINT, PHASE_GAS, PHASE_LIQUID, Parser, PlotError, read_case, read_vtp  # noqa: E402

import numpy as np  # noqa: E402


def count_frame(a, x_from, x_to, air_below, water_above, packing_below):
    """(gas particles in the pool, bubble points, water above the pool, water and gas particles in the packing's box)
    of one frame's arrays."""
    fluid = a["kind"] == KIND_FLUID
    x, y = a["Points"][:, 0], a["Points"][:, 1]
    span = (x >= x_from) & (x <= x_to)
    gas = int(np.sum(fluid & (a["phase"] == PHASE_GAS) & span & (y < air_below)))
    points = int(np.sum(a["kind"] == KIND_POINT))
    water = int(np.sum(fluid & (a["phase"] == PHASE_LIQUID) & span & (y > water_above)))
    box = fluid & span & (y >= 0.0) & (y < packing_below)
    packed_water = int(np.sum(box & (a["phase"] == PHASE_LIQUID)))
    packed_gas = int(np.sum(box & (a["phase"] == PHASE_GAS)))
    return gas, points, water, packed_water, packed_gas


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
    ap.add_argument("--packing-below", metavar="Y", type=float, default=0.10,
                    help="the pool's packing counts the fluid particles between the floor (y = 0) and this height "
                         "(m; default 0.10, under the waterfall cases' weir crest, so always under water)")
    args = ap.parse_args()
    try:
        if not os.path.isdir(args.run_dir):
            raise PlotError(f"{args.run_dir} is not a directory")
        if not args.x_from < args.x_to:
            raise PlotError(f"--x-from {args.x_from} must lie below --x-to {args.x_to}")
        if not args.packing_below > 0:
            raise PlotError(f"--packing-below {args.packing_below} must be above the floor, y = 0")
        chosen = frames_between(args.run_dir, args.t_from, args.t_to)
        counts = np.array([count_frame(read_vtp(path)[1], args.x_from, args.x_to, args.air_below, args.water_above,
                                           args.packing_below) for _, path in chosen], dtype=float)
    except PlotError as e:
        print(f"pool_air: {e}", file=sys.stderr)
        sys.exit(1)
    gas, points, water, packed_water, packed_gas = (counts[:, k] for k in range(5))
    air = gas + points
    span = f"x {args.x_from:g}-{args.x_to:g} m"
    print(f"frames {len(chosen)} (t = {chosen[0][0]:.3f} .. {chosen[-1][0]:.3f} s)")
    print(f"air in the pool        {air.mean():.1f} a frame (gas particles under y = {args.air_below:g} m, {span}: "
          f"{gas.mean():.1f}; bubble points: {points.mean():.1f}); least {air.min():g}, most {air.max():g}")
    print(f"water above the pool   {water.mean():.1f} a frame (liquid particles above y = {args.water_above:g} m, "
          f"{span}); least {water.min():g}, most {water.max():g}")
    spacing = read_case(args.run_dir)[2]
    if spacing is not None:
        cells = (args.x_to - args.x_from) * args.packing_below / spacing**2
        packing = (packed_water + packed_gas) / cells
        print(f"the pool's packing     {packing.mean():.3f} (fluid particles x l0^2 / area, y 0-{args.packing_below:g} m, "
              f"{span}, l0 = {spacing:g} m: water {packed_water.mean() / cells:.3f}, air {packed_gas.mean() / cells:.3f}); "
              f"least {packing.min():.3f}, most {packing.max():.3f}")


if __name__ == "__main__":
    main()
