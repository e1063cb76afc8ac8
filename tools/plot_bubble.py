#!/usr/bin/python3
"""Draw the bubble test's Fig. 2 (Gotoh et al.): a bubble's mean pressure against time, for one or more runs.

Reads RUN_DIR/bubbles.csv of each run (written by `mistfall simulate` for cases with gas: one row per enclosed
gas region per output time) and draws, per run, the mean pressure and the centroid height of its largest bubble
against time, in two panels of one PNG. A run that diverged ends where its last output was written; its
divergence time (from RUN_DIR/diverged.txt when present, else the last output time) is marked with a cross.
The legend names each run by its case name (RUN_DIR/case.toml) or, with --label, by the given labels.
For the paper's Fig. 1 (particle snapshots coloured by phase) use tools/plot_frames.py --color phase.
The image is written to a temporary file and renamed, so none is left half-written.
Exit codes: 0 done; 1 bad input (bad option, missing run directory or bubbles.csv, unreadable file), with a
one-line message on stderr.
Needs Debian's python3-numpy and python3-matplotlib (installed by `make deps`); run it with /usr/bin/python3.
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_frames import Parser, PlotError, read_case, save  # noqa: E402  (same folder; exits cleanly without matplotlib)

import matplotlib.pyplot as plt  # noqa: E402  (plot_frames has chosen the Agg backend)

COLUMNS = ("time", "bubble", "particles", "mean_pressure", "centroid_x", "centroid_y", "centroid_z", "size")


def largest_bubble_series(run_dir):
    """Returns (times, mean pressures, centroid heights) of the largest bubble at each output time."""
    path = os.path.join(run_dir, "bubbles.csv")
    if not os.path.isfile(path):
        raise PlotError(f"{path} does not exist (is {run_dir} a run of a case with gas?)")
    best = {}  # time -> (particles, pressure, height)
    try:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            if reader.fieldnames is None or any(c not in reader.fieldnames for c in COLUMNS):
                raise PlotError(f"{path}: expected the columns {','.join(COLUMNS)}")
            for line, row in enumerate(reader, start=2):
                try:
                    t, n = float(row["time"]), int(row["particles"])
                    value = (n, float(row["mean_pressure"]), float(row["centroid_y"]))
                except (TypeError, ValueError):
                    raise PlotError(f"{path}:{line}: not a number") from None
                if t not in best or n > best[t][0]:
                    best[t] = value
    except OSError as e:
        raise PlotError(f"cannot read {path}: {e.strerror}") from None
    if not best:
        raise PlotError(f"{path} holds no bubble (no gas region was enclosed at any output time)")
    times = sorted(best)
    return times, [best[t][1] for t in times], [best[t][2] for t in times]


def divergence_time(run_dir):
    """The time in RUN_DIR/diverged.txt ('time = T' line), or None when the run did not diverge."""
    path = os.path.join(run_dir, "diverged.txt")
    if not os.path.isfile(path):
        return None
    try:
        with open(path) as f:
            for line in f:
                key, _, value = line.partition("=")
                if key.strip() == "time":
                    return float(value)
    except (OSError, ValueError):
        return None
    return None


def main():
    parser = Parser(
        description=__doc__.split("\n\n")[0] + "\n\n" + __doc__.split("\n\n", 1)[1],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run_dirs", metavar="RUN_DIR", nargs="+", help="run directories of `mistfall simulate`")
    parser.add_argument("--out", metavar="PNG", default="bubble_pressure.png",
                        help="image to write (default bubble_pressure.png)")
    parser.add_argument("--label", action="append", metavar="TEXT",
                        help="legend label of each run, in the order of RUN_DIR (repeat; default: case names)")
    parser.add_argument("--dpi", type=int, default=100, help="image resolution in dots per inch (default 100)")
    args = parser.parse_args()
    try:
        if args.dpi < 10 or args.dpi > 1000:
            raise PlotError(f"--dpi {args.dpi}: expected 10..1000")
        if args.label and len(args.label) != len(args.run_dirs):
            raise PlotError(f"{len(args.label)} --label for {len(args.run_dirs)} run directories")
        fig, (ax_p, ax_y) = plt.subplots(2, 1, figsize=(7, 7), sharex=True, layout="constrained", dpi=args.dpi)
        for k, run_dir in enumerate(args.run_dirs):
            if not os.path.isdir(run_dir):
                raise PlotError(f"{run_dir} is not a directory")
            times, pressure, height = largest_bubble_series(run_dir)
            label = args.label[k] if args.label else read_case(run_dir)[0]
            diverged = divergence_time(run_dir)
            if diverged is not None:
                label += f" (diverged at t = {diverged:.4g} s)"
            line, = ax_p.plot(times, pressure, marker=".", label=label)
            ax_y.plot(times, height, marker=".", color=line.get_color())
            if diverged is not None:
                ax_p.plot([times[-1]], [pressure[-1]], marker="x", markersize=10, color=line.get_color())
        ax_p.set_ylabel("mean pressure in the bubble [Pa]")
        ax_p.set_title("largest enclosed gas region (bubble)")
        ax_p.legend()
        ax_p.grid(alpha=0.3)
        ax_y.set_ylabel("bubble centroid height [m]")
        ax_y.set_xlabel("t [s]")
        ax_y.grid(alpha=0.3)
        folder = os.path.dirname(os.path.abspath(args.out))
        if not os.path.isdir(folder):
            raise PlotError(f"cannot write {args.out}: folder {folder} does not exist")
        save(fig, args.out, args.dpi)
        print(args.out)
    except PlotError as e:
        print(f"plot_bubble: {e}", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
