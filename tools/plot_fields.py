#!/usr/bin/python3
"""Draw the grid flow fields of a mistfall run (VTK ImageData, .vti) like Figs. 4 and 5 of Gotoh et al.

Reads one .vti file (or, with --all, every .vti file of a folder) holding the arrays gas_velocity,
liquid_velocity (3 components), gas_sps_k (SPS turbulence energy k, eqs. (25)-(26)), gas_coverage and
liquid_coverage (total MPS weight of nearby particles; 0 where there is none), as src/io/vti_file.cpp writes
them (binary-appended or ASCII). For each file NAME.vti it writes
  NAME_velocity.png    (Fig. 4) gas velocity arrows where gas is near, liquid velocity arrows in another colour,
                       over a light map of the liquid coverage;
  NAME_turbulence.png  (Fig. 5) the gas turbulence intensity sqrt(2k/3) [m/s] as a colour map, blank where no
                       gas is near, with the outline of the liquid.
2D grids only; for a 3D grid the middle slice along z is drawn (the title says so).
Images are written to a temporary file and renamed, so none is left half-written.
Exit codes: 0 done; 1 bad input (bad option, missing or unreadable file, folder without .vti files), with a
one-line message on stderr.
Needs Debian's python3-numpy and python3-matplotlib (installed by `make deps`); run it with /usr/bin/python3.
"""
import argparse
import os
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_frames import Parser, PlotError, read_vtk_xml, save  # noqa: E402  (same folder; exits cleanly without matplotlib)

import numpy as np  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402  (plot_frames has chosen the Agg backend)

REQUIRED = (("gas_velocity", 3), ("liquid_velocity", 3), ("gas_sps_k", 1), ("gas_coverage", 1),
            ("liquid_coverage", 1))
GAS_COLOUR, LIQUID_COLOUR = "crimson", "navy"


# ---- reading ----

def _numbers(text, count, what, path):
    try:
        values = [float(v) for v in (text or "").split()]
    except ValueError:
        values = []
    if len(values) != count:
        raise PlotError(f"unreadable grid {path}: bad {what}")
    return values


def read_vti(path):
    """Returns (grid, arrays): grid = dict(origin, spacing, dims (nx, ny, nz), time or None); arrays = dict
    name -> numpy array of shape (nz, ny, nx) or (nz, ny, nx, components)."""
    root, raw = read_vtk_xml(path, "ImageData", "grid")
    image = root.find("ImageData")
    extent = _numbers(image.get("WholeExtent"), 6, "WholeExtent", path)
    if any(extent[2 * k] != 0 or extent[2 * k + 1] < 0 or extent[2 * k + 1] != int(extent[2 * k + 1])
           for k in range(3)):
        raise PlotError(f"unreadable grid {path}: WholeExtent must be '0 nx-1 0 ny-1 0 nz-1'")
    dims = tuple(int(extent[2 * k + 1]) + 1 for k in range(3))
    grid = {"origin": _numbers(image.get("Origin"), 3, "Origin", path),
            "spacing": _numbers(image.get("Spacing"), 3, "Spacing", path), "dims": dims, "time": None}
    nodes = dims[0] * dims[1] * dims[2]

    arrays = {}
    for node in root.iter("DataArray"):
        name = node.get("Name", "")
        if node.get("type") != "Float64":
            raise PlotError(f"unreadable grid {path}: array '{name}' is not Float64")
        try:
            components = int(node.get("NumberOfComponents", "1"))
            if node.get("format") == "appended":
                offset = int(node.get("offset"))
                (nbytes,) = struct.unpack_from("<Q", raw, offset)
                if offset + 8 + nbytes > len(raw) or nbytes % 8:
                    raise ValueError("data lies past the end of the file (truncated?)")
                values = np.frombuffer(raw, dtype="<f8", count=nbytes // 8, offset=offset + 8)
            elif node.get("format") == "ascii":
                values = np.array((node.text or "").split(), dtype=float)
            else:
                raise ValueError(f"unsupported format '{node.get('format')}'")
        except (ValueError, TypeError, struct.error) as e:
            raise PlotError(f"unreadable grid {path}: array '{name}': {e}") from None
        if name in ("TimeValue", "TIME"):
            if grid["time"] is None and values.size:
                grid["time"] = float(values[0])
            continue
        if values.size != nodes * components:
            raise PlotError(f"unreadable grid {path}: array '{name}' holds {values.size} values, "
                            f"expected {nodes} x {components}")
        shape = (dims[2], dims[1], dims[0]) + ((components,) if components > 1 else ())
        arrays[name] = values.reshape(shape)
    for name, components in REQUIRED:
        if name not in arrays:
            raise PlotError(f"unreadable grid {path}: missing array '{name}'")
        if (arrays[name].shape[3] if arrays[name].ndim == 4 else 1) != components:
            raise PlotError(f"unreadable grid {path}: array '{name}' should have {components} components")
    return grid, arrays


def plane(grid, arrays):
    """The x-y plane to draw: (arrays cut to shape (ny, nx[, c]), x and y node coordinates, title note)."""
    nz = grid["dims"][2]
    k = nz // 2
    cut = {name: a[k] for name, a in arrays.items()}
    note = ""
    if nz > 1:
        note = f"   (3D grid: middle slice z = {grid['origin'][2] + k * grid['spacing'][2]:.4g} m)"
    x = grid["origin"][0] + grid["spacing"][0] * np.arange(grid["dims"][0])
    y = grid["origin"][1] + grid["spacing"][1] * np.arange(grid["dims"][1])
    return cut, x, y, note


# ---- drawing ----

def new_figure(x, y, dpi):
    span_x = max(x[-1] - x[0], 1e-12)
    span_y = max(y[-1] - y[0], 1e-12)
    height = float(np.clip(7.0 * span_y / span_x, 2.5, 9.0)) + 1.2
    fig, ax = plt.subplots(figsize=(8.5, height), layout="constrained", dpi=dpi)
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    return fig, ax


def image_extent(x, y, grid):
    hx, hy = grid["spacing"][0] / 2, grid["spacing"][1] / 2
    return (x[0] - hx, x[-1] + hx, y[0] - hy, y[-1] + hy)


def plot_velocity(grid, arrays, out_png, title, arrows, dpi):
    cut, x, y, note = plane(grid, arrays)
    fig, ax = new_figure(x, y, dpi)
    liquid = cut["liquid_coverage"]
    top = float(np.percentile(liquid[liquid > 0], 95)) if np.any(liquid > 0) else 1.0
    # Light map: the liquid coverage takes at most the lighter third of the colour map.
    ax.imshow(np.ma.masked_less_equal(liquid, 0.0), origin="lower", extent=image_extent(x, y, grid),
              cmap="Blues", vmin=0.0, vmax=3.0 * top, interpolation="nearest")
    stride = max(1, int(np.ceil(max(len(x), len(y)) / arrows)))
    xs, ys = np.meshgrid(x[::stride], y[::stride])
    speeds = [np.linalg.norm(cut[f"{phase}_velocity"][::stride, ::stride, :2], axis=-1)[
        cut[f"{phase}_coverage"][::stride, ::stride] > 0] for phase in ("gas", "liquid")]
    vmax = max((float(s.max()) for s in speeds if s.size), default=0.0)
    # One scale for both phases: the fastest arrow is as long as the distance between arrows.
    length = stride * min(grid["spacing"][0], grid["spacing"][1])
    scale = vmax / length if vmax > 0 else 1.0
    drawn = None
    for phase, colour in (("gas", GAS_COLOUR), ("liquid", LIQUID_COLOUR)):
        mask = cut[f"{phase}_coverage"][::stride, ::stride] > 0
        if not mask.any():
            continue
        u = cut[f"{phase}_velocity"][::stride, ::stride]
        drawn = ax.quiver(xs[mask], ys[mask], u[..., 0][mask], u[..., 1][mask], color=colour, angles="xy",
                          scale_units="xy", scale=scale, width=0.003, label=f"{phase} velocity")
    if drawn is not None:
        ax.legend(loc="upper right", fontsize="small")
    ax.set_title(f"arrow length: speed; the longest is {vmax:.3g} m/s (the distance between arrows)",
                 fontsize="small")
    left, right, bottom, top_y = image_extent(x, y, grid)
    ax.set_xlim(left, right)
    ax.set_ylim(bottom, top_y)
    fig.suptitle(f"{title}: velocity (gas {GAS_COLOUR}, liquid {LIQUID_COLOUR}){note}")
    save(fig, out_png, dpi)


def plot_turbulence(grid, arrays, out_png, title, dpi):
    cut, x, y, note = plane(grid, arrays)
    fig, ax = new_figure(x, y, dpi)
    intensity = np.sqrt(2.0 * np.clip(cut["gas_sps_k"], 0.0, None) / 3.0)
    shown = np.ma.masked_where(cut["gas_coverage"] <= 0.0, intensity)
    im = ax.imshow(shown, origin="lower", extent=image_extent(x, y, grid), cmap="inferno",
                   interpolation="nearest")
    fig.colorbar(im, ax=ax, label="gas turbulence intensity sqrt(2k/3) [m/s]", shrink=0.8)
    liquid = cut["liquid_coverage"]
    if len(x) > 1 and len(y) > 1 and liquid.max() > 0 and liquid.min() <= 0:
        ax.contour(x, y, (liquid > 0).astype(float), levels=[0.5], colors=LIQUID_COLOUR, linewidths=0.8)
    ax.set_facecolor("0.92")
    fig.suptitle(f"{title}: SPS turbulence of the gas{note}")
    save(fig, out_png, dpi)


# ---- command line ----

def main():
    parser = Parser(
        description=__doc__.split("\n\n")[0] + "\n\n" + __doc__.split("\n\n", 1)[1],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("input", metavar="VTI|DIR", help="a .vti grid file, or with --all a folder of them")
    parser.add_argument("--all", action="store_true", help="draw every .vti file of the folder INPUT")
    parser.add_argument("--out", metavar="DIR",
                        help="folder for the PNGs (default: 'plots' beside the input; created if needed)")
    parser.add_argument("--arrows", type=int, default=40,
                        help="at most this many velocity arrows along each axis (default 40)")
    parser.add_argument("--dpi", type=int, default=100, help="image resolution in dots per inch (default 100)")
    args = parser.parse_args()
    try:
        if args.dpi < 10 or args.dpi > 1000:
            raise PlotError(f"--dpi {args.dpi}: expected 10..1000")
        if args.arrows < 2 or args.arrows > 500:
            raise PlotError(f"--arrows {args.arrows}: expected 2..500")
        if args.all:
            if not os.path.isdir(args.input):
                raise PlotError(f"{args.input} is not a directory")
            files = sorted(os.path.join(args.input, f) for f in os.listdir(args.input) if f.endswith(".vti"))
            if not files:
                raise PlotError(f"{args.input} holds no .vti file")
            folder = args.input
        else:
            if not os.path.isfile(args.input):
                raise PlotError(f"{args.input} is not a file" +
                                (" (use --all for a folder)" if os.path.isdir(args.input) else ""))
            files = [args.input]
            folder = os.path.dirname(args.input) or "."
        out = args.out or os.path.join(folder, "plots")
        try:
            os.makedirs(out, exist_ok=True)
        except OSError as e:
            raise PlotError(f"cannot create {out}: {e.strerror}") from None
        for path in files:
            grid, arrays = read_vti(path)
            stem = os.path.splitext(os.path.basename(path))[0]
            title = stem if grid["time"] is None else f"{stem}   t = {grid['time']:.4f} s"
            for suffix, draw in (("velocity", lambda p: plot_velocity(grid, arrays, p, title, args.arrows, args.dpi)),
                                 ("turbulence", lambda p: plot_turbulence(grid, arrays, p, title, args.dpi))):
                png = os.path.join(out, f"{stem}_{suffix}.png")
                draw(png)
                print(png)
    except PlotError as e:
        print(f"plot_fields: {e}", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
