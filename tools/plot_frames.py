#!/usr/bin/python3
"""Draw a mistfall run's frames as PNG images (no ParaView needed).

Reads RUN_DIR/frames.pvd and the VTK PolyData frames it lists (binary-appended or ASCII, as
`mistfall simulate` writes them). 2D runs: an x-y scatter; 3D runs: a side view (x-z) and a top view (x-y)
side by side. Wall and dummy particles are grey (escaped particles are not drawn), entrained bubble points
(numerics.entrained_bubble_diameter) black rings; fluid particles are
coloured by the chosen field (--color category: the six categories of `mistfall classify`, inflow water dark
grey). Writes DIR/frame_NNNNN.png (NNNNN = the frame's index in frames.pvd) and,
with --diagnostics, DIR/diagnostics.png (max speed, kinetic energy and PPE iterations against time).
Images are written to a temporary file and renamed, so none is left half-written.
Exit codes: 0 done; 1 bad input (bad option, missing directory or file, unreadable frame), with a one-line
message on stderr.
Needs Debian's python3-numpy and python3-matplotlib (installed by `make deps`); run it with /usr/bin/python3.
"""
import argparse
import os
import re
import struct
import sys
import xml.etree.ElementTree as ET

try:
    import numpy as np
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError as e:  # pragma: no cover
    print(f"plot_frames: {e}; install Debian's python3-numpy and python3-matplotlib (make deps) "
          "and run the tool with /usr/bin/python3", file=sys.stderr)
    sys.exit(1)

NUMPY_TYPE = {"Float64": "<f8", "Float32": "<f4", "UInt8": "u1", "Int8": "i1", "Int32": "<i4", "UInt32": "<u4",
              "Int64": "<i8", "UInt64": "<u8"}
KIND_FLUID, KIND_WALL, KIND_DUMMY, KIND_ESCAPED, KIND_INFLOW, KIND_POINT = 0, 1, 2, 3, 4, 5  # ParticleKind (particles.hpp)
PHASE_LIQUID, PHASE_GAS = 0, 1  # Phase (particles.hpp)
COLOR_FIELDS = ("pressure", "speed", "phase", "kind", "category")
# The six-category classification (src/classify/classification.hpp): 1..6; a colour each.
CATEGORY_LABEL = "category\n1 liquid bulk, 2 liquid surface, 3 droplet\n4 gas bulk, 5 gas surface, 6 bubble"
CATEGORY_COLOURS = ("#1f4e9c", "#5fa8e8", "#d62728", "#d8d0f0", "#e0a030", "#2ca02c")


class PlotError(Exception):
    """Bad input: reported as one line on stderr, exit code 1."""


class Parser(argparse.ArgumentParser):
    """The tools' argument parser: usage errors exit 1 like every other bad input (argparse's default is 2), with
    the message prefixed by the tool's name (its script name without .py)."""
    def error(self, message):
        self.print_usage(sys.stderr)
        print(f"{os.path.splitext(self.prog)[0]}: {message}", file=sys.stderr)
        sys.exit(1)


# ---- reading ----

def read_vtk_xml(path, vtk_type, what):
    """Opens a VTK XML file of type `vtk_type` ("PolyData", "ImageData") as mistfall writes them. Returns (root
    element of the XML part, raw appended bytes after the '_' marker or b""). `what` names the file in
    messages ("frame", "grid")."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise PlotError(f"cannot read {what} {path}: {e.strerror}") from None
    if not data.rstrip().endswith(b"</VTKFile>"):
        raise PlotError(f"unreadable {what} {path}: missing </VTKFile> (truncated?)")
    # The raw appended bytes may contain anything, so only the part before <AppendedData> is parsed as XML.
    marker = data.find(b"<AppendedData")
    header = data if marker < 0 else data[:marker] + b"</VTKFile>"
    try:
        root = ET.fromstring(header)
    except ET.ParseError as e:
        raise PlotError(f"unreadable {what} {path}: not a VTK XML file ({e})") from None
    if root.tag != "VTKFile" or root.get("type") != vtk_type or root.find(vtk_type) is None:
        raise PlotError(f"unreadable {what} {path}: not a VTK {vtk_type} file")
    raw = b""
    if marker >= 0:
        ad = re.match(rb"<AppendedData([^>]*)>", data[marker:])
        if not ad or b'encoding="raw"' not in ad.group(1):
            raise PlotError(f"unreadable {what} {path}: only raw appended data is supported")
        if root.get("byte_order", "LittleEndian") != "LittleEndian" or root.get("header_type") != "UInt64":
            raise PlotError(f"unreadable {what} {path}: only little-endian files with UInt64 headers are supported")
        underscore = data.find(b"_", marker + ad.end())
        if underscore < 0:
            raise PlotError(f"unreadable {what} {path}: appended data has no '_' marker")
        raw = data[underscore + 1:]
    return root, raw


def read_vtp(path):
    """Returns (time or None, dict name -> numpy array) for the Points and PointData arrays of one frame."""
    time, arrays = read_vtp_arrays(path)
    n = arrays["Points"].shape[0] if "Points" in arrays else -1
    for name, components in (("Points", 3), ("kind", 1), ("phase", 1), ("velocity", 3), ("pressure", 1)):
        if name not in arrays:
            raise PlotError(f"unreadable frame {path}: missing array '{name}'")
        expected = (n, components) if components > 1 else (n,)
        if arrays[name].shape != expected:
            raise PlotError(f"unreadable frame {path}: array '{name}' has shape {arrays[name].shape}, "
                            f"expected {expected}")
    return time, arrays


def read_vtp_arrays(path, what="frame"):
    """Returns (time or None, dict name -> numpy array) of any VTK PolyData point cloud mistfall writes."""
    root, raw = read_vtk_xml(path, "PolyData", what)
    piece = root.find("./PolyData/Piece")
    try:
        n = int(piece.get("NumberOfPoints"))
    except (AttributeError, TypeError, ValueError):
        raise PlotError(f"unreadable frame {path}: no <Piece NumberOfPoints=...>") from None

    arrays = {}
    time = None
    for node in root.iter("DataArray"):
        name = node.get("Name", "")
        vtk_type = node.get("type")
        if vtk_type not in NUMPY_TYPE:
            raise PlotError(f"unreadable frame {path}: array '{name}' has unsupported type {vtk_type}")
        dtype = np.dtype(NUMPY_TYPE[vtk_type])
        try:
            if node.get("format") == "appended":
                offset = int(node.get("offset"))
                (nbytes,) = struct.unpack_from("<Q", raw, offset)
                if offset + 8 + nbytes > len(raw) or nbytes % dtype.itemsize:
                    raise ValueError("data lies past the end of the file (truncated?)")
                values = np.frombuffer(raw, dtype=dtype, count=nbytes // dtype.itemsize, offset=offset + 8)
            elif node.get("format") == "ascii":
                values = np.array((node.text or "").split(), dtype=float).astype(dtype)
            else:
                raise ValueError(f"unsupported format '{node.get('format')}'")
            components = int(node.get("NumberOfComponents", "1"))
            if components > 1:
                values = values.reshape(-1, components)
        except (ValueError, TypeError, struct.error) as e:
            raise PlotError(f"unreadable frame {path}: array '{name}': {e}") from None
        if name in ("TIME", "TimeValue"):
            if time is None and values.size:
                time = float(values.reshape(-1)[0])
        elif name == "Points":
            arrays["Points"] = values
        else:
            arrays[name] = values
    if "Points" in arrays and arrays["Points"].shape != (n, 3):
        raise PlotError(f"unreadable {what} {path}: Points has shape {arrays['Points'].shape}, expected ({n}, 3)")
    return time, arrays


def read_pvd(run_dir):
    """Returns [(time, frame path)] in the order frames.pvd lists them."""
    return read_pvd_file(os.path.join(run_dir, "frames.pvd"), f"is {run_dir} a mistfall run directory?")


def read_pvd_file(pvd, hint):
    """Returns [(time, path)] in the order the collection `pvd` lists them (paths relative to its folder); `hint`
    goes into the message when it does not exist."""
    if not os.path.isfile(pvd):
        raise PlotError(f"{pvd} does not exist ({hint})")
    try:
        root = ET.parse(pvd).getroot()
        frames = [(float(d.get("timestep")), os.path.join(os.path.dirname(pvd), d.get("file")))
                  for d in root.iter("DataSet")]
    except (OSError, ET.ParseError, TypeError, ValueError) as e:
        raise PlotError(f"cannot read {pvd}: {e}") from None
    if not frames:
        raise PlotError(f"{pvd} lists no frames")
    return frames


def read_case(run_dir):
    """Returns (name, dimension or None, particle spacing or None) from RUN_DIR/case.toml ([case] name and
    dimension, [numerics] particle_spacing); the name falls back to the folder's name."""
    name, dimension, spacing = os.path.basename(os.path.abspath(run_dir)), None, None
    path = os.path.join(run_dir, "case.toml")
    try:
        with open(path, "rb") as f:
            text = f.read()
    except OSError:
        return name, dimension, spacing
    try:
        import tomllib  # Python >= 3.11
        doc = tomllib.loads(text.decode("utf-8"))
    except ImportError:  # minimal fallback: key = value lines inside [table] headers
        doc, section = {}, None
        for line in text.decode("utf-8", "replace").splitlines():
            line = line.split("#", 1)[0].strip()
            if line.startswith("["):
                section = doc.setdefault(line.strip("[] "), {})
            elif section is not None and "=" in line:
                key, value = (s.strip() for s in line.split("=", 1))
                try:
                    section[key] = float(value) if "." in value or "e" in value.lower() else int(value)
                except ValueError:
                    section[key] = value.strip('"')
    except (UnicodeDecodeError, ValueError):
        return name, dimension, spacing
    case, numerics = doc.get("case", {}), doc.get("numerics", {})
    if isinstance(case, dict) and isinstance(case.get("name"), str):
        name = case["name"]
    if isinstance(case, dict) and case.get("dimension") in (2, 3):
        dimension = case["dimension"]
    if isinstance(numerics, dict) and isinstance(numerics.get("particle_spacing"), (int, float)):
        spacing = float(numerics["particle_spacing"]) if numerics["particle_spacing"] > 0 else None
    return name, dimension, spacing


def estimate_spacing(points):
    """Smallest gap between distinct x coordinates: the lattice spacing for a run's first frame."""
    gaps = np.diff(np.unique(np.round(points[:, 0], 9)))
    gaps = gaps[gaps > 0]
    return float(gaps.min()) if gaps.size else 1.0


# ---- drawing ----

def save(fig, out_png, dpi):
    tmp = os.path.join(os.path.dirname(out_png), "." + os.path.basename(out_png) + ".tmp.png")
    try:
        fig.savefig(tmp, dpi=dpi)
        os.replace(tmp, out_png)
    except OSError as e:
        raise PlotError(f"cannot write {out_png}: {e.strerror}") from None
    finally:
        plt.close(fig)
        if os.path.exists(tmp):
            os.remove(tmp)


def colour_values(arrays, field, path):
    """Returns (values, colour-bar label, colour map, (vmin, vmax) or None)."""
    if field == "category":
        if "category" not in arrays:
            raise PlotError(f"frame {path} has no 'category' array (run `mistfall classify RUN_DIR` first)")
        cmap = matplotlib.colors.ListedColormap(CATEGORY_COLOURS)
        cmap.set_under("0.35")  # 0: inflow water (not classified), dark grey
        return arrays["category"].astype(float), CATEGORY_LABEL, cmap, (0.5, 6.5)
    if field == "speed":
        return np.linalg.norm(arrays["velocity"], axis=1), "speed [m/s]", "viridis", None
    if field == "pressure":
        return arrays["pressure"], "pressure [Pa]", "viridis", None
    if field == "phase":
        return arrays["phase"].astype(float), "phase (0 liquid, 1 gas)", "coolwarm", (0.0, 1.0)
    return arrays["kind"].astype(float), "kind (0 fluid, 1 wall, 2 dummy, 4 inflow)", "viridis", (0.0, 4.0)


def plot_frame(path, out_png, title, pvd_time, field, dimension, spacing, dpi):
    time, arrays = read_vtp(path)
    if time is None:
        time = pvd_time
    x = arrays["Points"]
    kind = arrays["kind"]
    fluid = (kind == KIND_FLUID) | (kind == KIND_INFLOW)  # inflow buffers are water driven at the inflow speed
    solid = (kind == KIND_WALL) | (kind == KIND_DUMMY)
    point = kind == KIND_POINT  # entrained bubbles moved as points (numerics.entrained_bubble_diameter): black rings
    values, label, cmap, limits = colour_values(arrays, field, path)
    vmin, vmax = limits if limits else (None, None)
    if dimension == 2:
        views = [(0, 1, "x [m]", "y [m]", None)]
    else:
        views = [(0, 2, "x [m]", "z [m]", "side (x-z)"), (0, 1, "x [m]", "y [m]", "top (x-y)")]
    # Figure height from the drawn extents (equal aspect), so the panels fill the image.
    shown = x[fluid | solid] if np.any(fluid | solid) else x
    span = np.ptp(shown, axis=0) if len(shown) else np.ones(3)
    ratio = max(span[b] / span[a] if span[a] > 0 else 1.0 for a, b, *_ in views)
    panel_width = 6.0 if dimension == 2 else 5.5
    height = float(np.clip(panel_width * ratio, 2.5, 9.0)) + 1.0
    fig, axes = plt.subplots(1, len(views), figsize=(panel_width * len(views) + 1.5, height), squeeze=False,
                             layout="constrained", dpi=dpi)
    sc = None
    drawn = []
    for ax, (a, b, la, lb, view_title) in zip(axes[0], views):
        walls = ax.scatter(x[solid, a], x[solid, b], c="0.65", marker="s", linewidths=0)
        sc = ax.scatter(x[fluid, a], x[fluid, b], c=values[fluid], cmap=cmap, vmin=vmin, vmax=vmax, linewidths=0)
        rings = ax.scatter(x[point, a], x[point, b], facecolors="none", edgecolors="k", linewidths=0.6)
        drawn.append((ax, walls, sc, rings))
        ax.set_aspect("equal")
        ax.set_xlabel(la)
        ax.set_ylabel(lb)
        if view_title:
            ax.set_title(view_title)
    fig.colorbar(sc, ax=list(axes[0]), label=label, shrink=0.8)
    points_note = f", {int(point.sum())} entrained bubble points" if point.any() else ""
    fig.suptitle(f"{title}   t = {time:.4f} s   ({int(fluid.sum())} fluid particles{points_note})")
    # Marker size = particle spacing on screen (at least 1 point), known once the layout has run.
    fig.canvas.draw()
    for ax, walls, fluid_dots, rings in drawn:
        x0, x1 = ax.get_xlim()
        points_per_metre = ax.bbox.width * 72.0 / fig.dpi / abs(x1 - x0)
        diameter = spacing * points_per_metre
        walls.set_sizes([max(1.0, 0.8 * diameter) ** 2])
        fluid_dots.set_sizes([max(1.0, 0.95 * diameter) ** 2])
        rings.set_sizes([max(1.0, 0.8 * diameter) ** 2])
    save(fig, out_png, dpi)


def plot_diagnostics(run_dir, out_png, title, dpi):
    path = os.path.join(run_dir, "diagnostics.csv")
    if not os.path.isfile(path):
        raise PlotError(f"{path} does not exist")
    columns = ["time", "max_speed", "kinetic_energy", "ppe_iterations"]
    try:
        d = np.atleast_1d(np.genfromtxt(path, delimiter=",", names=True, invalid_raise=False))
        if d.dtype.names is None or any(c not in d.dtype.names for c in columns):
            raise ValueError(f"expected columns {', '.join(columns)}")
        if d.size == 0:
            raise ValueError("no rows")
    except (OSError, ValueError) as e:
        raise PlotError(f"cannot read {path}: {e}") from None
    fig, axes = plt.subplots(3, 1, figsize=(7, 8), sharex=True, layout="constrained")
    for ax, col, label in zip(axes, columns[1:],
                              ["max speed [m/s]", "kinetic energy [J] (2D: per m)", "PPE iterations"]):
        ax.plot(d["time"], d[col], marker=".")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel("t [s]")
    fig.suptitle(f"{title}: diagnostics")
    save(fig, out_png, dpi)


# ---- command line ----

def parse_frames(spec, count):
    if spec == "all":
        return list(range(count))
    if spec == "last":
        return [count - 1]
    try:
        chosen = [int(k) for k in spec.split(",")]
    except ValueError:
        raise PlotError(f"--frames {spec}: expected 'all', 'last' or indices like 0,10,20") from None
    bad = [k for k in chosen if not 0 <= k < count]
    if bad:
        raise PlotError(f"--frames: no frame {bad[0]} (the run has frames 0..{count - 1})")
    return chosen


def main():
    parser = Parser(
        description=__doc__.split("\n\n")[0] + "\n\n" + __doc__.split("\n\n", 1)[1],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run_dir", metavar="RUN_DIR", help="run directory written by `mistfall simulate --out`")
    parser.add_argument("--out", metavar="DIR", help="folder for the PNGs (default RUN_DIR/plots; created if needed)")
    parser.add_argument("--color", choices=COLOR_FIELDS, default="pressure",
                        help="field that colours the fluid particles (default pressure)")
    parser.add_argument("--frames", default="last", metavar="all|last|N,M,...",
                        help="'all', 'last' (default) or comma-separated frame indices in frames.pvd "
                             "(0-based), e.g. 0,10,20")
    parser.add_argument("--diagnostics", action="store_true",
                        help="also plot RUN_DIR/diagnostics.csv to DIR/diagnostics.png")
    parser.add_argument("--dpi", type=int, default=100, help="image resolution in dots per inch (default 100)")
    args = parser.parse_args()

    try:
        if args.dpi < 10 or args.dpi > 1000:
            raise PlotError(f"--dpi {args.dpi}: expected 10..1000")
        if not os.path.isdir(args.run_dir):
            raise PlotError(f"{args.run_dir} is not a directory")
        frames = read_pvd(args.run_dir)
        chosen = parse_frames(args.frames, len(frames))
        title, dimension, spacing = read_case(args.run_dir)
        if dimension is None or spacing is None:  # no usable case.toml: look at the first frame
            _, first = read_vtp(frames[0][1])
            if dimension is None:  # 2D runs write z = 0 for every particle
                dimension = 3 if np.any(first["Points"][:, 2] != 0.0) else 2
            if spacing is None:
                spacing = estimate_spacing(first["Points"])
        out = args.out or os.path.join(args.run_dir, "plots")
        try:
            os.makedirs(out, exist_ok=True)
        except OSError as e:
            raise PlotError(f"cannot create {out}: {e.strerror}") from None
        for k in chosen:
            png = os.path.join(out, f"frame_{k:05d}.png")
            plot_frame(frames[k][1], png, title, frames[k][0], args.color, dimension, spacing, args.dpi)
            print(png)
        if args.diagnostics:
            png = os.path.join(out, "diagnostics.png")
            plot_diagnostics(args.run_dir, png, title, args.dpi)
            print(png)
    except PlotError as e:
        print(f"plot_frames: {e}", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
