#!/usr/bin/python3
"""Fluid particles inside the walls of a run: the particles of a frame (water or air, kind fluid) that lie past the
face of a wall region of the case, in every frame from --from to --to.

A wall in mistfall is a region of wall and dummy particles (case.toml's [[region]] with material = "wall", a box or
a circle); fluid starts at least l0/2 from its faces, and the pressure and the collision model keep it out. A box
wall's face is taken half a spacing beyond its outermost row of particles (the lattice of [domain] min, points at
min + (k + 1/2) l0, a box holding those from its min up to below its max): the box's edge where the lattice is
aligned with it, as in the shipped 5 mm case, but half a spacing inside it where a lattice row falls on the edge,
as in the 1 cm case's channel bed (bed to y = 0.435 m, its top row at 0.425, the water's bottom row at 0.435). A
particle past a face has crept into the wall (the loss traced at the pool's corners, docs/waterfall.md): it may stay
there, at rest among the wall particles, or be thrown out of the domain by its next shift. This tool finds such
particles in the saved frames, which the particle counts of diagnostics.csv do not show while they stay.

Prints the frames read, the frames holding any fluid particle deeper than --depth in a wall (in l0, default 0.5: as
deep as the wall's first row of particles), the most in one frame, and the particles, each with the first frame it
was seen in a wall, the wall, its phase and its deepest reach (l0). The case file copy RUN_DIR/case.toml gives the
walls, the lattice's origin ([domain] min) and l0.

Usage: tools/water_in_walls.py RUN_DIR [--from T] [--to T] [--depth D] [--list N]
Exits 1 with a one-line message on bad input. Needs Debian's python3-numpy (`make deps`); run it with /usr/bin/python3.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from overfall_profile import case_spacing, frames_between, load_case_doc  # noqa: E402
from plot_frames import KIND_FLUID, PHASE_GAS, PHASE_LIQUID, Parser, PlotError, read_vtp  # noqa: E402

import numpy as np  # noqa: E402

PHASES = {PHASE_LIQUID: "water", PHASE_GAS: "air"}


def lattice_face(edge, origin, l0):
    """Where the particles of a box with this edge stop, half a spacing past the last lattice point below the edge:
    origin + i l0 for the smallest i >= 0 with origin + (i + 1/2) l0 at or past the edge (src/case/scene.cpp)."""
    return origin + max(0, math.ceil((edge - origin) / l0 - 0.5 - 1e-9)) * l0


def read_walls(run_dir):
    """[(name, depth_of(x, y))] for the wall regions of RUN_DIR/case.toml (depth_of: the depth past the face, > 0
    inside, of arrays of coordinates), and l0."""
    doc = load_case_doc(run_dir)
    l0 = case_spacing(doc, run_dir)
    origin = doc.get("domain", {}).get("min")
    if not isinstance(origin, list) or len(origin) < 2:
        raise PlotError(f"{os.path.join(run_dir, 'case.toml')}: [domain] min is missing (the lattice's origin)")
    walls = []
    for k, region in enumerate(doc.get("region", [])):
        if region.get("material") != "wall":
            continue
        name = region.get("name", f"region {k + 1}")
        if region.get("shape", "box") == "circle":
            (cx, cy), r = region["center"][:2], region["radius"]
            walls.append((name, lambda x, y, cx=cx, cy=cy, r=r: r - np.hypot(x - cx, y - cy)))
        else:
            (x0, y0), (x1, y1) = region["min"][:2], region["max"][:2]
            x0, x1 = (lattice_face(e, origin[0], l0) for e in (x0, x1))
            y0, y1 = (lattice_face(e, origin[1], l0) for e in (y0, y1))
            walls.append((name, lambda x, y, x0=x0, y0=y0, x1=x1, y1=y1:
                          np.minimum(np.minimum(x - x0, x1 - x), np.minimum(y - y0, y1 - y))))
    if not walls:
        raise PlotError(f"{os.path.join(run_dir, 'case.toml')}: the case has no wall region")
    return walls, l0


def main():
    ap = Parser(description=__doc__.split("\n\n")[0])
    ap.add_argument("run_dir", metavar="RUN_DIR")
    ap.add_argument("--from", dest="t_from", type=float, default=0.0, help="first frame time read (s; default 0)")
    ap.add_argument("--to", dest="t_to", type=float, default=None, help="last frame time read (s; default: last)")
    ap.add_argument("--depth", type=float, default=0.5,
                    help="how far past a wall's face a particle must be to count (l0; default 0.5: as deep as the "
                         "wall's first row of particles)")
    ap.add_argument("--list", type=int, default=10, help="particles listed, first seen first (default 10)")
    args = ap.parse_args()
    try:
        if args.depth < 0:
            raise PlotError(f"--depth {args.depth:g} must be 0 or more")
        if not os.path.isdir(args.run_dir):
            raise PlotError(f"{args.run_dir} is not a directory")
        walls, l0 = read_walls(args.run_dir)
        chosen = frames_between(args.run_dir, args.t_from, args.t_to)
        with_any = most = 0
        first_seen = {}  # particle -> [time, wall, phase, deepest (l0)]
        for t, path in chosen:
            a = read_vtp(path)[1]
            ids = a.get("id")
            fluid = np.flatnonzero(a["kind"] == KIND_FLUID)
            x, y = a["Points"][fluid, 0], a["Points"][fluid, 1]
            counted = np.zeros(fluid.size, dtype=bool)
            for name, depth_of in walls:
                depth = depth_of(x, y) / l0
                inside = depth > args.depth
                for k in np.flatnonzero(inside & ~counted):  # a particle counts in its first wall
                    i = fluid[k]
                    key = int(ids[i]) if ids is not None else f"#{i} of frame {t:g}"
                    seen = first_seen.setdefault(key, [t, name, PHASES.get(int(a["phase"][i]), "?"), depth[k]])
                    seen[3] = max(seen[3], depth[k])
                counted |= inside
            with_any += bool(counted.any())
            most = max(most, int(counted.sum()))
    except PlotError as e:
        print(f"water_in_walls: {e}", file=sys.stderr)
        sys.exit(1)
    print(f"frames {len(chosen)} (t = {chosen[0][0]:.3f} .. {chosen[-1][0]:.3f} s), walls {len(walls)}, l0 = {l0:g} m; "
          f"counted: fluid particles more than {args.depth:g} l0 past a wall's face")
    print(f"frames with fluid in a wall  {with_any} (most in one frame: {most}); particles {len(first_seen)}")
    for key, (t, name, phase, depth) in sorted(first_seen.items(), key=lambda kv: kv[1][0])[:args.list]:
        print(f"  particle {key}: {phase}, first in a wall at t = {t:g} s, in '{name}', deepest {depth:.2f} l0")


if __name__ == "__main__":
    main()
