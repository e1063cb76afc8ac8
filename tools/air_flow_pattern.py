#!/usr/bin/python3
"""The air flow a waterfall drives, averaged over a time window (the steady pattern of Gotoh et al.'s Figs. 4, 5).

Reads the grid fields of a mistfall run (RUN_DIR/fields/fields_*.vti, written when output.field_spacing > 0),
averages them over the frames with FROM <= t <= TO (the gas velocity over the frames in which gas covers the node,
likewise the liquid's), and measures the three features the paper describes, on a 2D run:
  sheet      the mean vertical air velocity beside the falling sheet, on each face, over the rows between the
             brink and the pool (the sheet: the liquid-covered nodes of each row right of the brink): negative
             when the sheet drags the air down;
  cavity     the circulation of the mean air velocity around the cavity behind the sheet (from the back wall's
             face to 2 nodes short of the sheet in each row, from the pool to the channel bed; the sum of the
             circulations around its grid cells), and the mean vertical air velocity along the back wall:
             a recirculation turns clockwise (negative circulation, air rising at the back wall);
  plunge     the mean vertical air velocity in front of the plunge point (downstream of where the sheet meets
             the pool, just above the pool): positive when the air rises there.
It prints the table and writes, in OUT (default RUN_DIR/plots): air_flow.csv (the table), mean_velocity.png and
mean_turbulence.png (the averaged fields drawn as tools/plot_fields.py draws one frame).
The geometry defaults are those of cases/waterfall*.toml (brink at x = 0.30 m, y = 0.435 m under a bed whose
underside is y = 0.395 m; pool surface y = 0.15 m; the back wall's face at x = 0).
Exit codes: 0 done; 1 bad input (no fields, empty window, bad option), with a one-line message on stderr.
Needs Debian's python3-numpy and python3-matplotlib; run it with /usr/bin/python3.
"""
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_fields  # noqa: E402
from plot_frames import Parser, PlotError  # noqa: E402


def mean_fields(paths, t_from, t_to):
    """Mean arrays over the files with t_from <= time <= t_to: (grid, arrays, frame count)."""
    total, count, grid = None, 0, None
    for path in paths:
        g, a = plot_fields.read_vti(path)
        if g["time"] is None or not (t_from - 1e-9 <= g["time"] <= t_to + 1e-9):
            continue
        cut, x, y, _ = plot_fields.plane(g, a)
        if total is None:
            grid, total = g, {"gas_n": 0.0, "liquid_n": 0.0}
            for name in cut:
                total[name] = np.zeros_like(cut[name])
        for phase in ("gas", "liquid"):
            present = (cut[f"{phase}_coverage"] > 0).astype(float)
            total[f"{phase}_n"] = total[f"{phase}_n"] + present
            total[f"{phase}_velocity"] += cut[f"{phase}_velocity"] * present[..., None]
        total["gas_sps_k"] += cut["gas_sps_k"] * (cut["gas_coverage"] > 0)
        total["gas_coverage"] += cut["gas_coverage"]
        total["liquid_coverage"] += cut["liquid_coverage"]
        count += 1
    if count == 0:
        raise PlotError(f"no field frame with {t_from} <= t <= {t_to} s")
    mean = {}
    for phase in ("gas", "liquid"):
        n = np.maximum(total[f"{phase}_n"], 1.0)
        mean[f"{phase}_velocity"] = total[f"{phase}_velocity"] / n[..., None]
        mean[f"{phase}_coverage"] = total[f"{phase}_coverage"] / count
    mean["gas_sps_k"] = total["gas_sps_k"] / np.maximum(total["gas_n"], 1.0)
    # The node holds gas (or liquid) on average when it did in at least half the frames.
    mean["gas_present"] = total["gas_n"] >= 0.5 * count
    mean["liquid_present"] = total["liquid_n"] >= 0.5 * count
    return grid, mean, count


def measure(grid, mean, brink, bed, pool, back_wall=0.0):
    h = grid["spacing"][0]
    x = grid["origin"][0] + h * np.arange(grid["dims"][0])
    y = grid["origin"][1] + grid["spacing"][1] * np.arange(grid["dims"][1])
    vy = mean["gas_velocity"][..., 1]
    gas, liquid = mean["gas_present"], mean["liquid_present"]
    behind, front, sheet_left = [], [], {}
    plunge_x = None
    for j, yj in enumerate(y):
        if not (pool + 2 * h <= yj <= brink[1] - 2 * h):
            continue
        cols = np.where(liquid[j] & (x > brink[0] - h))[0]
        if cols.size == 0:
            continue
        first = cols[0]
        last = first
        while last + 1 < len(x) and liquid[j, last + 1]:
            last += 1
        sheet_left[j] = x[first]
        for k in (first - 1, first - 2):
            if k >= 0 and gas[j, k]:
                behind.append(vy[j, k])
        for k in (last + 1, last + 2):
            if k < len(x) and gas[j, k]:
                front.append(vy[j, k])
        if yj <= pool + 3 * h:
            plunge_x = x[last] if plunge_x is None else max(plunge_x, x[last])
    if not sheet_left:
        raise PlotError("no falling sheet found between the brink and the pool (is this a waterfall run?)")
    # The cavity behind the sheet: from the back wall's face to 2 nodes short of the sheet in each row (the sheet leans
    # downstream as it falls, so the cavity widens downwards), from the pool to the channel bed. Its circulation is
    # the sum over the grid cells inside it of the circulation around each cell (trapezoidal edges): by Stokes, the
    # line integral around its staircase boundary. Until the twenty-second session the cavity stopped at a vertical
    # line 2 nodes short of the sheet's highest (leftmost) point, and the back wall's default was the grid's second
    # node, inside the wall of the shipped cases (x = -0.03 m on waterfall.toml's grid, -0.02 m on waterfall_small's),
    # where no air moves: at 5 mm it read 0.000.
    left = back_wall - 1e-9
    jc = [j for j in range(len(y)) if pool + 2 * h <= y[j] <= bed - h]
    edge = {j: sheet_left[j] - 2 * h for j in jc if j in sheet_left}
    fallback = min(edge.values()) if edge else brink[0] - 2 * h
    inside = np.zeros(gas.shape, dtype=bool)
    for j in jc:
        inside[j] = (x >= left) & (x <= edge.get(j, fallback) + 1e-9)
    u = mean["gas_velocity"][..., 0]
    cells = inside[:-1, :-1] & inside[:-1, 1:] & inside[1:, :-1] & inside[1:, 1:]
    around = h * (0.5 * (u[:-1, :-1] + u[:-1, 1:]) - 0.5 * (u[1:, :-1] + u[1:, 1:])
                  + 0.5 * (vy[:-1, 1:] + vy[1:, 1:]) - 0.5 * (vy[:-1, :-1] + vy[1:, :-1]))
    circulation = float(np.sum(around[cells]))
    ic = np.where(x >= left)[0]
    back = [vy[j, i] for j in jc for i in ic[:2] if gas[j, i]]
    plunge = []
    if plunge_x is not None:
        for j, yj in enumerate(y):
            if pool + h <= yj <= pool + 4 * h:
                plunge += [vy[j, i] for i in np.where((x > plunge_x + h) & (x <= plunge_x + 8 * h))[0]
                           if gas[j, i]]
    avg = lambda v: float(np.mean(v)) if len(v) else float("nan")  # noqa: E731
    return [
        ("sheet", "air beside the sheet, behind it: mean v_y [m/s]", avg(behind), len(behind), "< 0"),
        ("sheet", "air beside the sheet, in front: mean v_y [m/s]", avg(front), len(front), "< 0"),
        ("cavity", "circulation around the cavity behind the sheet [m^2/s]", circulation, int(cells.sum()), "< 0"),
        ("cavity", "air along the back wall: mean v_y [m/s]", avg(back), len(back), "> 0"),
        ("plunge", "air in front of the plunge point: mean v_y [m/s]", avg(plunge), len(plunge), "> 0"),
    ]


def main():
    parser = Parser(description=__doc__.split("\n")[0], epilog=None)
    parser.add_argument("run_dir", metavar="RUN_DIR")
    parser.add_argument("--from", dest="t_from", type=float, default=2.0, help="window start [s] (default 2)")
    parser.add_argument("--to", dest="t_to", type=float, default=float("inf"), help="window end [s] (default: last)")
    parser.add_argument("--brink", type=float, nargs=2, default=[0.30, 0.435], metavar=("X", "Y"))
    parser.add_argument("--bed", type=float, default=0.395, help="underside of the channel bed [m]")
    parser.add_argument("--pool", type=float, default=0.15, help="pool surface [m]")
    parser.add_argument("--back-wall", type=float, default=0.0,
                        help="x of the back wall's face [m]; the cavity's columns start at the first node at or past it "
                             "(default 0)")
    parser.add_argument("--out", help="folder for the table and PNGs (default RUN_DIR/plots)")
    parser.add_argument("--dpi", type=int, default=100)
    try:
        args = parser.parse_args()
        paths = sorted(glob.glob(os.path.join(args.run_dir, "fields", "fields_*.vti")))
        if not paths:
            raise PlotError(f"no grid fields in {args.run_dir}/fields (set output.field_spacing > 0)")
        grid, mean, count = mean_fields(paths, args.t_from, args.t_to)
        rows = measure(grid, mean, args.brink, args.bed, args.pool, args.back_wall)
    except PlotError as e:
        print(f"air_flow_pattern.py: {e}", file=sys.stderr)
        return 1
    out = args.out or os.path.join(args.run_dir, "plots")
    os.makedirs(out, exist_ok=True)
    print(f"mean over {count} frames, t = {args.t_from:g} to {args.t_to:g} s")
    print(f"{'feature':8} {'quantity':58} {'value':>10} {'nodes':>6} expected")
    lines = ["feature,quantity,value,nodes,expected"]
    for feature, what, value, nodes, expected in rows:
        print(f"{feature:8} {what:58} {value:10.4f} {nodes:6d} {expected}")
        lines.append(f"{feature},\"{what}\",{value:.6g},{nodes},{expected}")
    tmp = os.path.join(out, ".air_flow.csv.tmp")
    with open(tmp, "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(tmp, os.path.join(out, "air_flow.csv"))
    arrays = {k: v[None] for k, v in mean.items() if not k.endswith("_present")}
    arrays["gas_coverage"] = mean["gas_present"][None].astype(float)
    arrays["liquid_coverage"] = mean["liquid_coverage"][None] * mean["liquid_present"][None]
    flat = dict(grid, dims=(grid["dims"][0], grid["dims"][1], 1))
    title = f"{os.path.basename(os.path.normpath(args.run_dir))}, mean t = {args.t_from:g}-{args.t_to:g} s"
    plot_fields.plot_velocity(flat, arrays, os.path.join(out, "mean_velocity.png"), title, 40, args.dpi)
    plot_fields.plot_turbulence(flat, arrays, os.path.join(out, "mean_turbulence.png"), title, args.dpi)
    return 0


if __name__ == "__main__":
    sys.exit(main())
