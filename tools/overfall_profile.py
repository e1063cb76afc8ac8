#!/usr/bin/python3
"""Measure the free overfall of a 2D mistfall waterfall run against the classical results (issue 4).

Brink depth: the water over the last `--window` metres of the channel bed before its edge (the brink),
h_b = (liquid particles there, above the bed's top less l0/2) * l0^2 / window; also printed: the same over the last l0
only (the surface falls steeply into the brink, so the 2 l0 window reads about half a spacing's fall too deep) (on mistfall's lattice at l0 = 1 cm the
water's lowest row lies exactly on the bed's top edge, y = 0.435 m; counting only particles above the edge missed
about half of that row, a third of the depth, until 2026-11-25), averaged over the frames from --from to --to. Compared with the
critical depth h_c = (q^2/g)^(1/3) and with Rouse's (1936) brink depth for a free overfall, h_b = 0.715 h_c.
Nappe: for levels y from one l0 under the brink down to --sheet-bottom, the median x of the liquid downstream of
the brink in a slab of height l0, pooled over the same frames (the median ignores stray drops; the splash near the
pool is left out by stopping above it). Compared
with the ballistic path of a point leaving the brink's mid-depth y0 = bed + h_b/2 with the measured mean brink
velocity (U, V): x = x_b + U t, y = y0 + V t - g t^2 / 2, and with the path from Rouse's brink (U = q / h_b, V = 0).
Also with the path from the brink section itself, the last l0 before the edge (the window of the headline depth "over
the last l0"): y0 = bed + h_edge/2 and that water's mean velocity; the 2 l0 window's mean velocity lies below the
edge's, since the water accelerates into the brink.
Also the sheet as the first water met going downstream from the cavity: at each level of each frame the median x of
the water before the first gap wider than 2 l0, then the median over the frames. Where the plunge zone swells or
throws spray up to the sheet's lowest levels, the median of all the water there lies in that water, not in the sheet.
Also with the path of the jet's own horizontal velocity U_j = (sum of u^2 + p / rho) / (sum of u) over the brink
window's water in all the frames: the brink section's x-momentum flux, pressure included, over its mass flux. The
pressure at the brink is not yet the ambient (the streamlines still curve there), so the water goes on accelerating
past the brink until it is; past it no horizontal force acts on the falling sheet but the air's, and the sheet keeps
U_j (momentum balance of the free overfall: Rouse 1936; Hager 1983). U, the mean velocity at the
brink, lies below U_j by the pressure's share.

The case file copy RUN_DIR/case.toml gives l0, g, q (the sum of the [[inflow]] discharges) and the brink: the
upper downstream corner of the wall region named by --bed-region (default channel_bed). The pool level (the end
of the sheet) is --pool-y, by default the crest of the region named weir; the sheet is measured down to
--sheet-bottom, by default the pool level plus 35 % of the drop from the bed (above the splash).
Writes RUN_DIR/plots/overfall.png (the sheet of the last frame used, the measured and ballistic paths) and
RUN_DIR/plots/overfall.csv (y, measured x, ballistic x from the measured brink, ballistic x from Rouse, ballistic x
with the brink's momentum flux U_j, ballistic x from the brink section, the sheet's x from the cavity), and prints a
summary.
Channel energy: in bins of --energy-bin metres from the inflow's gate (the downstream edge of region 'gate', else
of the first [[inflow]] box) to the brink, the water's depth h (as at the brink: particles above the bed less l0/2,
times l0^2, over the bin's length), its mean velocity U and the specific energy E = h + U^2 / (2 g) against the
critical energy 1.5 h_c. Upstream of a free overfall the flow of a frictionless horizontal channel carries E = 1.5
h_c (its critical section lies a few h_c before the brink, Chow 1959); E above that, falling along the channel, is
head lost to friction, which for water over 0.3 m at Re ~ 10^4 is about 0.02 h_c.
Exit codes: 0 done; 1 bad input, with a one-line message on stderr.
Needs Debian's python3-numpy and python3-matplotlib (`make deps`); run it with /usr/bin/python3.
"""
import os
import sys
import tomllib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_frames import Parser, PlotError, read_pvd, read_vtp, save, KIND_FLUID  # noqa: E402

import numpy as np  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402  (plot_frames has chosen the Agg backend)

ROUSE_BRINK_RATIO = 0.715  # h_b / h_c for a free overfall from a horizontal channel (Rouse 1936)


def region_box(doc, name):
    for region in doc.get("region", []):
        if region.get("name") == name:
            return np.array(region["min"], float), np.array(region["max"], float)
    raise PlotError(f"case.toml has no [[region]] named '{name}'")


def load_case_doc(run_dir):
    """RUN_DIR/case.toml parsed (a dict); PlotError when it cannot be read (shared with bubble_pressure_gap.py)."""
    path = os.path.join(run_dir, "case.toml")
    try:
        with open(path, "rb") as f:
            return tomllib.load(f)
    except (OSError, tomllib.TOMLDecodeError) as e:
        raise PlotError(f"cannot read {path}: {getattr(e, 'strerror', None) or e}") from None


def case_spacing(doc, run_dir):
    """[numerics] particle_spacing of a parsed RUN_DIR/case.toml; PlotError when it is missing (shared with
    bubble_pressure_gap.py and water_in_walls.py)."""
    spacing = doc.get("numerics", {}).get("particle_spacing")
    if not isinstance(spacing, (int, float)) or spacing <= 0:
        raise PlotError(f"{os.path.join(run_dir, 'case.toml')}: [numerics] particle_spacing is missing")
    return float(spacing)


def read_overfall_case(run_dir, bed_region, pool_y):
    doc = load_case_doc(run_dir)
    path = os.path.join(run_dir, "case.toml")
    if doc.get("case", {}).get("dimension", 2) != 2:
        raise PlotError("overfall_profile measures 2D runs only")
    spacing = case_spacing(doc, run_dir)
    gravity = doc.get("physics", {}).get("gravity", [0.0, -9.81])
    q = sum(float(inflow.get("discharge", 0.0)) for inflow in doc.get("inflow", []))
    if q <= 0:
        raise PlotError(f"{path}: no [[inflow]] with a discharge > 0 (the overfall needs q)")
    _, bed_max = region_box(doc, bed_region)
    if pool_y is None:
        _, weir_max = region_box(doc, "weir")
        pool_y = float(weir_max[1])
    try:
        _, gate_max = region_box(doc, "gate")
        channel_start = float(gate_max[0])
    except PlotError:
        inflows = doc.get("inflow", [])
        channel_start = float(inflows[0]["max"][0]) if inflows and "max" in inflows[0] else float("nan")
    density = float(doc.get("physics", {}).get("liquid", {}).get("density", 1000.0))
    return (float(spacing), abs(float(gravity[1])), q, float(bed_max[0]), float(bed_max[1]), pool_y, channel_start,
            density)


def channel_energy(frames, l0, g, start, x_brink, y_bed, length):
    """[(x_mid, h, U, E)] averaged over `frames` (lists of liquid x, y, u) in bins of `length` from start to x_brink:
    h the water above y_bed less l0/2 (particles times l0^2 over the bin), U their mean x-velocity,
    E = h + U^2/(2g). Empty where start is unknown or the bins do not fit."""
    if not np.isfinite(start) or not 0.0 < length <= x_brink - start:
        return []
    edges = np.arange(start, x_brink + 1e-9, length)
    rows = []
    for lo, hi in zip(edges[:-1], edges[1:]):
        h, u = [], []
        for x, y, ux in frames:
            inside = (x >= lo) & (x < hi) & (y > y_bed - 0.5 * l0)
            if inside.any():
                h.append(inside.sum() * l0 * l0 / (hi - lo))
                u.append(ux[inside].mean())
        if h:
            depth, speed = float(np.mean(h)), float(np.mean(u))
            rows.append((0.5 * (lo + hi), depth, speed, depth + speed * speed / (2.0 * g)))
    return rows


def add_window_arguments(ap, default_from=None):
    """--from and --to: the frames averaged (shared with aeration_depth.py, bubble_pressure_gap.py, pool_air.py);
    --from defaults to `default_from`, or half the last frame's time."""
    ap.add_argument("--from", dest="t_from", type=float, default=default_from,
                    help="first frame time averaged (s; default: " +
                         ("half the last frame's time)" if default_from is None else
                          f"{default_from:g}, after the waterfall cases' start-up)"))
    ap.add_argument("--to", dest="t_to", type=float, default=None, help="last frame time averaged (s; default: last)")


def frames_between(run_dir, t_from, t_to):
    """[(time, frame path)] of the run's frames from t_from (default: half the last time) to t_to (default: last)."""
    frames = read_pvd(run_dir)
    t_last = frames[-1][0]
    t_from = t_from if t_from is not None else 0.5 * t_last
    t_to = t_to if t_to is not None else t_last
    chosen = [(t, path) for t, path in frames if t_from - 1e-9 <= t <= t_to + 1e-9]
    if not chosen:
        raise PlotError(f"no frame between t = {t_from} and {t_to} s")
    return chosen


def block_standard_error(times, values, block):
    """Standard error of the mean of `values` (one per frame at `times`) from the means of consecutive blocks of
    `block` seconds: std(block means, ddof 1) / sqrt(blocks). Neighbouring frames of a run are correlated (the brink
    oscillates over a few tenths of a second), so the spread of single frames over sqrt(frames) would understate it.
    Returns (error, blocks); error is nan below 2 blocks."""
    first = times[0]
    groups = {}
    for t, v in zip(times, values):
        groups.setdefault(int(np.floor((t - first) / block + 1e-9)), []).append(v)
    means = np.array([np.mean(g) for g in groups.values()])
    if len(means) < 2:
        return float("nan"), len(means)
    return float(np.std(means, ddof=1) / np.sqrt(len(means))), len(means)


def main():
    ap = Parser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir")
    add_window_arguments(ap)
    ap.add_argument("--window", type=float, default=None, help="length of the brink window (m; default 2 l0)")
    ap.add_argument("--bed-region", default="channel_bed", help="wall region whose upper downstream corner is the brink")
    ap.add_argument("--pool-y", type=float, default=None, help="pool level (m; default: the crest of region 'weir')")
    ap.add_argument("--sheet-bottom", type=float, default=None,
                    help="lowest level of the sheet measured (m; default: pool level + 0.35 x drop)")
    ap.add_argument("--energy-bin", type=float, default=0.04,
                    help="length of the channel bins of the specific-energy table (m; default 0.04)")
    ap.add_argument("--block", type=float, default=0.5,
                    help="length of the blocks whose means give the brink depth's standard error (s; default 0.5)")
    args = ap.parse_args()
    try:
        run(args)
    except PlotError as e:
        print(f"overfall_profile: {e}", file=sys.stderr)
        sys.exit(1)


def sheet_from_cavity(xs, l0):
    """The median x of the first run of water met going downstream from the cavity at one level of one frame: the
    water beyond the first gap wider than 2 l0 is splash or the plunge zone's mound, not the sheet."""
    xs = np.sort(xs)
    gaps = np.nonzero(np.diff(xs) > 2.0 * l0)[0]
    return float(np.median(xs[: gaps[0] + 1] if gaps.size else xs))


def run(args):
    l0, g, q, x_brink, y_bed, pool_y, channel_start, rho = read_overfall_case(args.run_dir, args.bed_region,
                                                                              args.pool_y)
    window = args.window or 2.0 * l0
    chosen = frames_between(args.run_dir, args.t_from, args.t_to)
    bottom = args.sheet_bottom if args.sheet_bottom is not None else pool_y + 0.35 * (y_bed - pool_y)
    if not pool_y < bottom < y_bed - l0:
        raise PlotError(f"--sheet-bottom {bottom} must lie between the pool level {pool_y} and the bed {y_bed} less l0")
    levels = np.arange(y_bed - l0, bottom - 1e-9, -l0)
    if not args.block > 0.0:
        raise PlotError(f"--block must be > 0 s, got {args.block}")
    if not args.energy_bin > 0.0:
        raise PlotError(f"--energy-bin must be > 0 m, got {args.energy_bin}")
    depth, edge_depth, u_mean, v_mean, edge_u, edge_v = [], [], [], [], [], []
    mass_flux, momentum_flux = 0.0, 0.0  # sums of u and of u^2 + p / rho over the brink window, all frames
    slab_x = [[] for _ in levels]
    first_x = [[] for _ in levels]  # per frame: the median x of the first water met from the cavity (sheet_from_cavity)
    channel_frames = []
    for _, path in chosen:
        _, a = read_vtp(path)
        liquid = (a["kind"] == KIND_FLUID) & (a["phase"] == 0)
        x, y = a["Points"][liquid, 0], a["Points"][liquid, 1]
        vel, pressure = a["velocity"][liquid], a["pressure"][liquid]
        at_brink = (x > x_brink - window) & (x <= x_brink) & (y > y_bed - 0.5 * l0)
        depth.append(at_brink.sum() * l0 * l0 / window)
        at_edge = at_brink & (x > x_brink - l0)
        edge_depth.append(at_edge.sum() * l0)
        if at_edge.any():
            edge_u.append(vel[at_edge, 0].mean())
            edge_v.append(vel[at_edge, 1].mean())
        if at_brink.any():
            u_mean.append(vel[at_brink, 0].mean())
            v_mean.append(vel[at_brink, 1].mean())
            mass_flux += vel[at_brink, 0].sum()
            momentum_flux += (vel[at_brink, 0] ** 2 + pressure[at_brink] / rho).sum()
        channel_frames.append((x, y, vel[:, 0]))
        sheet = x > x_brink
        for k, level in enumerate(levels):
            at_level = x[sheet & (np.abs(y - level) < 0.5 * l0)]
            slab_x[k].extend(at_level)
            if at_level.size:
                first_x[k].append(sheet_from_cavity(at_level, l0))
    if not u_mean:
        raise PlotError("no water at the brink in the frames chosen")
    h_b, u_b, v_b = float(np.mean(depth)), float(np.mean(u_mean)), float(np.mean(v_mean))
    h_c = (q * q / g) ** (1.0 / 3.0)
    error, blocks = block_standard_error([t for t, _ in chosen], depth, args.block)
    h_rouse = ROUSE_BRINK_RATIO * h_c

    def ballistic_x(y0, u, v, level):  # the later root of y0 + v t - g t^2 / 2 = level
        t = (v + np.sqrt(v * v + 2.0 * g * (y0 - level))) / g
        return x_brink + u * t

    measured = np.array([np.median(xs) if xs else np.nan for xs in slab_x])
    first = np.array([np.median(xs) if xs else np.nan for xs in first_x])
    from_brink = ballistic_x(y_bed + 0.5 * h_b, u_b, v_b, levels)
    from_rouse = ballistic_x(y_bed + 0.5 * h_rouse, q / h_rouse, 0.0, levels)
    u_jet = momentum_flux / mass_flux if mass_flux > 0.0 else float("nan")
    from_jet = ballistic_x(y_bed + 0.5 * h_b, u_jet, v_b, levels)
    h_edge = float(np.mean(edge_depth))
    u_edge, v_edge = (float(np.mean(edge_u)), float(np.mean(edge_v))) if edge_u else (float("nan"),) * 2
    from_edge = ballistic_x(y_bed + 0.5 * h_edge, u_edge, v_edge, levels)
    valid = ~np.isnan(measured)

    def offsets(path, sheet_x=measured):  # the nappe's x against a path: RMS, mean and scatter over the valid levels
        if not valid.any():
            return (float("nan"),) * 3
        off = sheet_x - path
        return float(np.sqrt(np.nanmean(off ** 2))), float(np.nanmean(off)), float(np.nanstd(off))

    rms_brink, rms_rouse, rms_edge = (offsets(path)[0] for path in (from_brink, from_rouse, from_edge))
    rms_jet, offset_jet, scatter_jet = offsets(from_jet)
    rms_first_edge, rms_first_brink = (offsets(path, first)[0] for path in (from_edge, from_brink))

    out_dir = os.path.join(args.run_dir, "plots")
    os.makedirs(out_dir, exist_ok=True)
    csv_path = os.path.join(out_dir, "overfall.csv")
    with open(csv_path + ".tmp", "w") as f:
        f.write("y,x_measured,x_ballistic_measured_brink,x_ballistic_rouse,x_ballistic_brink_momentum,"
                "x_ballistic_brink_section,x_sheet_from_cavity\n")
        for k, level in enumerate(levels):
            f.write(f"{level:.5f},{measured[k]:.5f},{from_brink[k]:.5f},{from_rouse[k]:.5f},{from_jet[k]:.5f},"
                    f"{from_edge[k]:.5f},{first[k]:.5f}\n")
    os.replace(csv_path + ".tmp", csv_path)

    _, a = read_vtp(chosen[-1][1])
    liquid = (a["kind"] == KIND_FLUID) & (a["phase"] == 0)
    fig, ax = plt.subplots(figsize=(6, 6))
    ax.scatter(a["Points"][liquid, 0], a["Points"][liquid, 1], s=6, c="lightsteelblue", label="water (last frame)")
    ax.plot(measured, levels, "o-", c="navy", ms=3, label="sheet, median x (measured)")
    ax.plot(first, levels, "s", c="purple", ms=3, mfc="none", label="sheet, first water from the cavity")
    ax.plot(from_brink, levels, "--", c="crimson", label=f"ballistic, measured brink (U={u_b:.2f}, V={v_b:.2f} m/s)")
    ax.plot(from_rouse, levels, ":", c="darkgreen", label=f"ballistic, Rouse brink (U={q / h_rouse:.2f} m/s)")
    ax.plot(from_jet, levels, "-.", c="darkorange", label=f"ballistic, brink momentum (U_j={u_jet:.2f} m/s)")
    ax.set_xlim(x_brink - 0.15, x_brink + 0.3)
    ax.set_ylim(pool_y - 0.05, y_bed + 0.08)
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(f"free overfall, t = {chosen[0][0]:.2f}-{chosen[-1][0]:.2f} s ({len(chosen)} frames)")
    ax.legend(fontsize=7, loc="upper right")
    png = os.path.join(out_dir, "overfall.png")
    save(fig, png, 110)
    plt.close(fig)

    print(f"frames averaged: {len(chosen)} (t = {chosen[0][0]:.3f} .. {chosen[-1][0]:.3f} s), l0 = {l0} m, q = {q} m^2/s")
    print(f"brink depth     measured {100 * h_b:.2f} cm (spread {100 * np.std(depth):.2f} cm); over the last l0 only "
          f"{100 * np.mean(edge_depth):.2f} cm = {np.mean(edge_depth) / h_c:.3f} h_c")
    print(f"critical depth  (q^2/g)^(1/3) = {100 * h_c:.2f} cm; measured/critical = {h_b / h_c:.3f} "
          f"(Rouse: {ROUSE_BRINK_RATIO})")
    if blocks >= 2:
        print(f"standard error  of measured/critical +- {error / h_c:.3f} ({blocks} blocks of {args.block:g} s: the "
              f"frames of a block are correlated, their means nearly not)")
    else:
        print(f"standard error  none: the frames span fewer than 2 blocks of {args.block:g} s (--block)")
    print(f"brink velocity  measured U = {u_b:.3f} m/s, V = {v_b:.3f} m/s; q/h_b(measured) = {q / h_b:.3f} m/s")
    print(f"nappe           {int(valid.sum())} levels; RMS of x against the ballistic path from the measured brink "
          f"{100 * rms_brink:.2f} cm, from Rouse's brink {100 * rms_rouse:.2f} cm")
    print(f"brink section   the last l0: U = {u_edge:.3f} m/s, V = {v_edge:.3f} m/s; nappe's x against the ballistic "
          f"path from its mid-depth: RMS {100 * rms_edge:.2f} cm")
    print(f"sheet from cavity the first water met from the cavity at each level (splash beyond it left out): RMS "
          f"{100 * rms_first_edge:.2f} cm from the brink section's path, {100 * rms_first_brink:.2f} cm from the "
          f"measured brink's")
    print(f"jet velocity    the brink's momentum flux (pressure included) over its mass flux U_j = {u_jet:.3f} m/s; "
          f"nappe's x against the ballistic path with U_j: RMS {100 * rms_jet:.2f} cm, mean {100 * offset_jet:+.2f} cm, "
          f"scatter about the mean {100 * scatter_jet:.2f} cm")
    energy = channel_energy(channel_frames, l0, g, channel_start, x_brink, y_bed, args.energy_bin)
    if energy:
        print(f"channel energy  x [m], depth h [cm], mean U [m/s], Froude U/sqrt(g h), E/h_c (critical: 1.5):")
        for x_mid, h, u, e in energy:
            print(f"                {x_mid:.3f}  {100 * h:5.2f}  {u:.3f}  {u / np.sqrt(g * h):.2f}  {e / h_c:.3f}")
    print(f"wrote {png} and {csv_path}")


if __name__ == "__main__":
    main()
