#!/usr/bin/python3
"""Measure a 2D bubble's void, the space the water leaves it, against eq. (17)'s compressed equilibrium (issue 16,
item 1).

A bubble is the space enclosed by the water. Its gas particles mark it, but they need not fill it: where the water
moves away faster than the gas follows, an empty cavity opens that no particle covers. The measure of
tests/test_bubble_area.cpp, the sum over the bubble's gas of l0^2 n0 / n_i, sees such a cavity only through the
number density of the gas at its edge, so it can read a bubble whose void has doubled as 2 % too large. This tool
measures the void itself, on a grid of samples (spacing l0 / --sample) around the bubble:
  * the gas's cells: samples whose nearest active particle (any kind but escaped and entrained points) is the
    bubble's gas and lies within CELL l0 (CELL = 0.75: a sample of a square lattice lies within l0/2^(1/2) of its
    particle), i.e. the gas's Voronoi cells;
  * the cavity: samples with no particle within CELL l0 that are connected (through such samples, side by side on the
    grid) to the gas's cells.
The void is their sum, against A_eq = N l0^2 (1 - (P_B - P_0) / (rho_g c_g^2)) (N: the bubble's gas particles, P_B
its pressure from bubbles.csv, P_0 the pressure at which its gas sits at the lattice spacing: --p0, default the
bubble's pressure at the window's first frame; rho_g and c_g from case.toml's [physics.gas]). The grid grows until
the cavity stays inside it; a cavity that reaches --reach l0 past the gas is reported open.
The bubble is the largest enclosed gas region of each frame (arrays `phase` = 1, `kind` = 0, `enclosed` = 1, linked
within 2.1 l0), and its pressure that of bubbles.csv's row with the same particle count at that time.
Prints a row per frame and the largest |void / A_eq - 1|; exit codes: 0 done; 1 bad input, with a one-line message
on stderr. Needs Debian's python3-numpy (`make deps`); run it with /usr/bin/python3.
Usage: tools/bubble_void.py RUN_DIR [--from T] [--to T] [--p0 P] [--sample K] [--reach R]
"""
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bubble_rise import bubble_frames  # noqa: E402
from plot_frames import Parser, PlotError, read_case, read_pvd  # noqa: E402

import numpy as np  # noqa: E402

CELL = 0.75   # a sample farther than CELL l0 from every particle is empty
LINK = 2.1    # gas particles within LINK l0 belong to one bubble (the number-density radius)
KIND_ESCAPED, KIND_POINT = 3, 5


def largest_bubble(points, gas, l0):
    """Indices (into points) of the largest group of gas particles linked within LINK l0."""
    index = np.flatnonzero(gas)
    label = -np.ones(len(index), dtype=int)
    groups = []
    for seed in range(len(index)):
        if label[seed] >= 0:
            continue
        label[seed] = len(groups)
        members, stack = [seed], [seed]
        while stack:
            k = stack.pop()
            near = np.flatnonzero((np.hypot(*(points[index] - points[index[k]]).T) < LINK * l0) & (label < 0))
            label[near] = len(groups)
            members.extend(near)
            stack.extend(near)
        groups.append(members)
    return index[max(groups, key=len)] if groups else index


def covering(origin, h, shape, points, radius):
    """(index into points of the nearest point within radius, or -1; that distance, or inf) for each sample of the
    grid origin + (k + 1/2) h (shape (ny, nx)): each point marks the samples within radius of it."""
    ny, nx = shape
    best = np.full(shape, np.inf)
    which = -np.ones(shape, dtype=int)
    span = int(np.ceil(radius / h)) + 1
    for k, (px, py) in enumerate(points):
        ci, cj = int((px - origin[0]) / h), int((py - origin[1]) / h)
        i0, i1, j0, j1 = max(ci - span, 0), min(ci + span + 1, nx), max(cj - span, 0), min(cj + span + 1, ny)
        if i0 >= i1 or j0 >= j1:
            continue
        sx = origin[0] + (np.arange(i0, i1) + 0.5) * h
        sy = origin[1] + (np.arange(j0, j1) + 0.5) * h
        d = np.hypot(sx[None, :] - px, sy[:, None] - py)
        patch = best[j0:j1, i0:i1]
        closer = (d < patch) & (d <= radius)
        patch[closer] = d[closer]
        which[j0:j1, i0:i1][closer] = k
    return which, best


def void_area(points, bubble, active, l0, sample=6, reach=40.0):
    """(area of the gas's cells, area of the cavity, open) of the bubble (indices into points) among the active
    particles (a boolean mask); see the module's text."""
    h = l0 / sample
    lo, hi = points[bubble].min(0), points[bubble].max(0)
    margin = 4.0 * l0
    while True:
        x0, x1 = lo - margin, hi + margin
        nx, ny = (np.ceil((x1 - x0) / h)).astype(int)
        near = active & np.all((points > x0 - 2 * l0) & (points < x1 + 2 * l0), axis=1)
        candidates = np.flatnonzero(near)
        which, distance = covering(x0, h, (ny, nx), points[candidates], CELL * l0)
        in_bubble = np.zeros(len(points), dtype=bool)
        in_bubble[bubble] = True
        covered = which >= 0
        cell = np.zeros((ny, nx), dtype=bool)
        cell[covered] = in_bubble[candidates[which[covered]]]
        empty = ~covered
        # the cavity: empty samples connected side by side to the gas's cells (a flood fill on the grid)
        reached = cell.copy()
        while True:
            grown = reached.copy()
            grown[1:, :] |= reached[:-1, :]
            grown[:-1, :] |= reached[1:, :]
            grown[:, 1:] |= reached[:, :-1]
            grown[:, :-1] |= reached[:, 1:]
            grown &= cell | empty
            if (grown == reached).all():
                break
            reached = grown
        cavity = reached & empty
        touches = cavity[0, :].any() or cavity[-1, :].any() or cavity[:, 0].any() or cavity[:, -1].any()
        if not touches:
            return cell.sum() * h * h, cavity.sum() * h * h, False
        if margin >= reach * l0:
            return cell.sum() * h * h, cavity.sum() * h * h, True
        margin *= 2.0


def gas_properties(run_dir):
    """(rho_g, c_g) from RUN_DIR/case.toml's [physics.gas] (defaults 1.2 kg/m^3 and 340 m/s, docs/case-file.md)."""
    import tomllib
    try:
        with open(os.path.join(run_dir, "case.toml"), "rb") as f:
            gas = tomllib.load(f).get("physics", {}).get("gas", {})
    except (OSError, tomllib.TOMLDecodeError) as e:
        raise PlotError(f"{run_dir}/case.toml: {e}") from None
    c = gas.get("sound_speed", 340.0)
    c = float("inf") if c == "inf" else float(c)
    return float(gas.get("density", 1.2)), c


def bubble_pressures(run_dir):
    """{time rounded to 1e-6: {particle count: mean pressure}} from bubbles.csv."""
    path = os.path.join(run_dir, "bubbles.csv")
    out = {}
    try:
        with open(path, newline="") as f:
            for row in csv.DictReader(f):
                out.setdefault(round(float(row["time"]), 6), {})[int(row["particles"])] = float(row["mean_pressure"])
    except (OSError, KeyError, ValueError) as e:
        raise PlotError(f"{path}: {e}") from None
    return out


def measure(run_dir, t_from, t_to, l0, sample, reach):
    """Rows (t, N, P_B, gas cells' area, cavity's area, open) of the frames in [t_from, t_to] holding a bubble."""
    pressures = bubble_pressures(run_dir)
    rows = []
    for t, a, points, gas in bubble_frames(run_dir, t_from, t_to):
        if gas.sum() == 0:
            continue
        bubble = largest_bubble(points, gas, l0)
        pressure = pressures.get(round(t, 6), {}).get(len(bubble), float("nan"))
        active = (a["kind"] != KIND_ESCAPED) & (a["kind"] != KIND_POINT)
        cells, cavity, is_open = void_area(points, bubble, active, l0, sample, reach)
        rows.append((t, len(bubble), pressure, cells, cavity, is_open))
    if not rows:
        raise PlotError(f"no frame with a bubble between t = {t_from} and {t_to} s")
    return rows


def main():
    ap = Parser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir")
    ap.add_argument("--from", dest="t_from", type=float, default=0.0, help="window start (s; default 0)")
    ap.add_argument("--to", dest="t_to", type=float, default=float("inf"), help="window end (s; default: the last)")
    ap.add_argument("--p0", type=float, default=None,
                    help="P_0, the pressure at which the gas sits at the lattice spacing (Pa; default: the bubble's "
                         "pressure at the window's first frame after t = 0)")
    ap.add_argument("--sample", type=int, default=6, help="samples per spacing along each axis (default 6)")
    ap.add_argument("--reach", type=float, default=40.0,
                    help="a cavity reaching this many spacings past the gas is reported open (default 40)")
    args = ap.parse_args()
    try:
        if not os.path.isdir(args.run_dir):
            raise PlotError(f"{args.run_dir} is not a directory")
        read_pvd(args.run_dir)
        _, dimension, l0 = read_case(args.run_dir)
        if dimension != 2 or l0 is None:
            raise PlotError(f"{args.run_dir}/case.toml: a 2D case with [numerics] particle_spacing is needed")
        if args.sample < 1:
            raise PlotError(f"--sample {args.sample}: at least 1 sample per spacing")
        rho, c = gas_properties(args.run_dir)
        rows = measure(args.run_dir, args.t_from, args.t_to, l0, args.sample, args.reach)
    except PlotError as e:
        print(f"bubble_void: {e}", file=sys.stderr)
        sys.exit(1)
    stiffness = rho * c * c
    p0 = args.p0
    if p0 is None:
        p0 = next((r[2] for r in rows if r[0] > 0 and np.isfinite(r[2])), 0.0)
    print(f"frames {len(rows)} (t = {rows[0][0]:.3f} .. {rows[-1][0]:.3f} s), l0 = {l0} m, "
          f"rho_g c_g^2 = {stiffness:.4g} Pa, P_0 = {p0:.1f} Pa")
    print("t [s]     N   P_B [Pa]   cells/A_eq  cavity/A_eq  void/A_eq - 1")
    worst = 0.0
    for t, n, pressure, cells, cavity, is_open in rows:
        equilibrium = n * l0 * l0 * (1.0 - (pressure - p0) / stiffness)
        departure = (cells + cavity) / equilibrium - 1.0
        if np.isfinite(departure):
            worst = max(worst, abs(departure))
        print(f"{t:.4f} {n:5d} {pressure:10.1f}   {cells / equilibrium:10.4f}  {cavity / equilibrium:11.4f}  "
              f"{departure:+13.4f}{'  open' if is_open else ''}")
    print(f"largest |void / A_eq - 1|: {worst:.4f}")


if __name__ == "__main__":
    main()
