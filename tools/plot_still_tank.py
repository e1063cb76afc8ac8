#!/usr/bin/python3
"""Draws the still tank's maximum and rms fluid speed against time for every run of tools/validate_still_tank.sh
(one colour per resolution; solid: stabilised scheme, dashed: the paper's MPS), log scale.

Usage: tools/plot_still_tank.py DIR [--out PNG]   (DIR holds the <scheme>_<l0>mm.csv tables of tools/still_tank.py)"""
import argparse
import csv
import glob
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("dir")
    ap.add_argument("--out", help="PNG to write (default DIR/still_tank_speed.png)")
    args = ap.parse_args()
    tables = sorted(glob.glob(os.path.join(args.dir, "*_*mm.csv")))
    if not tables:
        print(f"plot_still_tank.py: no <scheme>_<l0>mm.csv tables in {args.dir}", file=sys.stderr)
        return 1
    colours = {"8": "tab:blue", "4": "tab:orange", "2": "tab:green"}
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
    for path in tables:
        m = re.match(r"(\w+?)_(\d+)mm\.csv$", os.path.basename(path))
        if not m:
            continue
        scheme, mm = m.groups()
        with open(path) as f:
            rows = list(csv.DictReader(f))
        t = [float(r["time"]) for r in rows[1:]]
        for ax, key in zip(axes, ("max_speed", "rms_speed")):
            ax.semilogy(t, [max(float(r[key]), 1e-9) for r in rows[1:]], color=colours.get(mm, "k"),
                        linestyle="-" if scheme == "stabilised" else "--", linewidth=1.0,
                        label=f"{scheme}, l0 = {mm} mm")
    for ax, title in zip(axes, ("max fluid speed", "rms fluid speed")):
        ax.axhline(0.01, color="grey", linewidth=0.8, linestyle=":")
        ax.set_xlabel("t [s]")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("speed [m/s]")
    axes[0].legend(fontsize=7, loc="lower right")
    fig.suptitle("still tank (cases/hydrostatic.toml, 0.2 m of water), 10 s; dotted: the 1 cm/s target")
    fig.tight_layout()
    out = args.out or os.path.join(args.dir, "still_tank_speed.png")
    fig.savefig(out, dpi=90)
    print(f"plot_still_tank.py: wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
