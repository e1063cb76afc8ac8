#!/usr/bin/python3
"""Measure a 2D rising bubble's speed and nose radius against the large-bubble law (issue 16, item 5).

For each frame from --from to --to: the bubble is the enclosed gas (arrays `phase` = 1 and `enclosed` = 1 of the
frame; gas above --below is left out, so a bubble that has burst at the surface ends the window). Its top edge is
the highest gas particle in each column of width l0 across it, plus l0/2; the nose radius R is that of the circle
fitted (least squares, Kasa's algebraic fit) to the edge of the columns within 3/4 of the bubble's half-width of the
highest one.
Rise speeds: the least-squares slopes of the centroid's and the apex's height against time. The law for large
two-dimensional (cylindrical-cap) bubbles, U = 0.5 (g R)^(1/2) (Collins 1965), is evaluated at the median nose
radius and at --radius (the initial radius). With --windows W it also prints, per window of W seconds, the apex's
and the centroid's speed and their Froude numbers U/(g R)^(1/2) at the window's median nose radius (the law: 0.5),
which show whether the rise has a steady part at all. Prints a summary; exit codes: 0 done; 1 bad input, with a
one-line message on stderr. Needs Debian's python3-numpy (`make deps`); run it with /usr/bin/python3.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_frames import Parser, PlotError, read_case, read_pvd, read_vtp  # noqa: E402

import numpy as np  # noqa: E402

NOSE_SPAN = 0.75  # the edge columns fitted: within this fraction of the bubble's half-width of the highest one


def nose_radius(gas_points, l0):
    """(apex height, nose radius, half-width) of a bubble given its particles' (x, y); radius nan when flat."""
    x, y = gas_points[:, 0], gas_points[:, 1]
    xc = np.median(x)
    columns = np.round((x - xc) / l0).astype(int)
    keys = np.unique(columns)
    cx = xc + keys * l0
    top = np.array([y[columns == k].max() for k in keys]) + 0.5 * l0
    half = 0.5 * (cx.max() - cx.min() + l0)
    near = np.abs(cx - cx[np.argmax(top)]) <= NOSE_SPAN * half
    if near.sum() < 3 or np.ptp(top[near]) < 0.5 * l0:  # too narrow, or flat: no nose
        return top.max(), float("nan"), half
    # the circle x^2 + y^2 + D x + E y + F = 0 nearest the edge points (Kasa's algebraic fit)
    a = np.column_stack([cx[near], top[near], np.ones(near.sum())])
    d, e, f = np.linalg.lstsq(a, -(cx[near] ** 2 + top[near] ** 2), rcond=None)[0]
    centre_y = -0.5 * e
    r2 = 0.25 * (d * d + e * e) - f
    if r2 <= 0 or centre_y >= top.max() or np.sqrt(r2) > 10 * half:  # no curvature to speak of
        return top.max(), float("nan"), half
    return top.max(), float(np.sqrt(r2)), half


def froude_by_window(rows, width, gravity):
    """Per window of `width` seconds over the rows of measure(): (start, apex speed, centroid speed, median nose
    radius, apex Froude number U/(g R)^(1/2), centroid Froude number); windows with fewer than 4 frames or no nose
    radius are left out. The law's Froude number is 0.5."""
    t = rows[:, 0]
    out = []
    start = t[0]
    while start < t[-1] - 1e-12:
        inside = (t >= start - 1e-9) & (t < start + width - 1e-9)
        radius = np.nanmedian(rows[inside, 3]) if inside.sum() >= 4 and np.isfinite(rows[inside, 3]).any() else np.nan
        if np.isfinite(radius):
            apex = np.polyfit(t[inside], rows[inside, 2], 1)[0]
            centroid = np.polyfit(t[inside], rows[inside, 1], 1)[0]
            scale = np.sqrt(gravity * radius)
            out.append((start, apex, centroid, radius, apex / scale, centroid / scale))
        start += width
    return np.array(out).reshape(-1, 6)


def bubble_frames(run_dir, t_from, t_to):
    """(t, the frame's arrays, its points' (x, y), the enclosed gas's mask) of each frame in [t_from, t_to]."""
    for t, path in read_pvd(run_dir):
        if not t_from - 1e-9 <= t <= t_to + 1e-9:
            continue
        _, a = read_vtp(path)
        if "enclosed" not in a:
            raise PlotError(f"{path} has no 'enclosed' array (written before bubbles were marked)")
        yield t, a, a["Points"][:, :2], (a["phase"] == 1) & (a["kind"] == 0) & (a["enclosed"] == 1)


def measure(run_dir, t_from, t_to, below, spacing):
    rows = []  # (t, centroid y, apex y, nose radius, half-width)
    for t, _, points, enclosed in bubble_frames(run_dir, t_from, t_to):
        gas = enclosed & (points[:, 1] < below)
        if gas.sum() < 6:
            continue
        apex, radius, half = nose_radius(points[gas], spacing)
        rows.append((t, points[gas, 1].mean(), apex, radius, half))
    if len(rows) < 3:
        raise PlotError(f"fewer than 3 frames with a bubble between t = {t_from} and {t_to} s")
    return np.array(rows)


def main():
    ap = Parser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir")
    ap.add_argument("--from", dest="t_from", type=float, default=0.05, help="window start (s; default 0.05)")
    ap.add_argument("--to", dest="t_to", type=float, default=0.2, help="window end (s; default 0.2)")
    ap.add_argument("--below", type=float, default=0.145,
                    help="gas above this height (m) is left out (default 0.145: under bubble_rise's surface)")
    ap.add_argument("--radius", type=float, default=0.0225, help="the bubble's initial radius (m; default 0.0225)")
    ap.add_argument("--gravity", type=float, default=9.81, help="g (m/s^2; default 9.81)")
    ap.add_argument("--windows", type=float, default=0.0,
                    help="also print the apex's and the centroid's Froude number U/(g R)^(1/2) in windows of this "
                         "many seconds (the law: 0.5; default 0: none)")
    args = ap.parse_args()
    try:
        if not os.path.isdir(args.run_dir):
            raise PlotError(f"{args.run_dir} is not a directory")
        read_pvd(args.run_dir)  # a run directory at all
        _, dimension, spacing = read_case(args.run_dir)
        if dimension != 2 or spacing is None:
            raise PlotError(f"{args.run_dir}/case.toml: a 2D case with [numerics] particle_spacing is needed")
        if args.windows < 0:
            raise PlotError(f"--windows {args.windows}: a window is a positive number of seconds (0: none)")
        rows = measure(args.run_dir, args.t_from, args.t_to, args.below, spacing)
    except PlotError as e:
        print(f"bubble_rise: {e}", file=sys.stderr)
        sys.exit(1)
    t = rows[:, 0]
    centroid_speed = np.polyfit(t, rows[:, 1], 1)[0]
    apex_speed = np.polyfit(t, rows[:, 2], 1)[0]
    radius = np.nanmedian(rows[:, 3])
    q1, q3 = np.nanpercentile(rows[:, 3], [25, 75])
    print(f"frames {len(rows)} (t = {t[0]:.3f} .. {t[-1]:.3f} s), l0 = {spacing} m")
    print(f"rise speed      centroid {centroid_speed:.4f} m/s, apex {apex_speed:.4f} m/s")
    print(f"nose radius     median {radius * 100:.2f} cm (quartiles {q1 * 100:.2f}-{q3 * 100:.2f} cm); "
          f"half-width {np.median(rows[:, 4]) * 100:.2f} cm")
    for name, r in (("measured nose", radius), ("initial", args.radius)):
        law = 0.5 * np.sqrt(args.gravity * r)
        print(f"law 0.5 (g R)^(1/2), R = {name} radius {r * 100:.2f} cm: {law:.4f} m/s; "
              f"centroid {100 * (centroid_speed - law) / law:+.1f} %")
    law = 0.5 * np.sqrt(args.gravity * radius)
    print(f"law at the measured nose radius: apex {100 * (apex_speed - law) / law:+.1f} %")
    if args.windows > 0:
        print("window [s]      apex, centroid [m/s]  nose R [cm]  Froude apex, centroid (law 0.5)")
        for start, apex, centroid, r, fr_apex, fr_centroid in froude_by_window(rows, args.windows, args.gravity):
            print(f"{start:.3f}-{start + args.windows:.3f}   {apex:6.3f} {centroid:6.3f}        {r * 100:5.2f}"
                  f"        {fr_apex:6.3f} {fr_centroid:6.3f}")


if __name__ == "__main__":
    main()
