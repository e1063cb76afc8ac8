#!/usr/bin/python3
"""Draw a mistfall run's frames as PNG images (no ParaView needed).

Reads RUN_DIR/frames.pvd and the VTK PolyData frames it lists (binary-appended or ASCII, as
`mistfall simulate` writes them). 2D runs: an x-y scatter; 3D runs: a side view (x-z) and a top view (x-y).
Wall and dummy particles are grey; fluid particles are coloured by the chosen field.
Needs Debian's python3-numpy and python3-matplotlib (installed by `make deps`); run it with /usr/bin/python3.
"""
import argparse
import os
import struct
import sys
import xml.etree.ElementTree as ET

try:
    import numpy as np
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError as e:  # pragma: no cover
    sys.exit(f"plot_frames: {e}; install Debian's python3-numpy and python3-matplotlib (make deps)")

NUMPY_TYPE = {"Float64": "<f8", "Float32": "<f4", "UInt8": "u1", "Int32": "<i4", "Int64": "<i8", "UInt64": "<u8"}
KIND_FLUID = 0


def fail(message):
    print(f"plot_frames: {message}", file=sys.stderr)
    sys.exit(1)


def read_vtp(path):
    """Returns (time, dict name -> numpy array) for the Points and PointData arrays of one frame."""
    with open(path, "rb") as f:
        data = f.read()
    marker = data.find(b"<AppendedData")
    header = data if marker < 0 else data[:marker] + b"</VTKFile>"
    try:
        root = ET.fromstring(header)
    except ET.ParseError as e:
        fail(f"{path}: not a readable VTK file ({e})")
    raw = b""
    if marker >= 0:
        raw = data[data.index(b"_", marker) + 1:]
    arrays = {}
    time = float("nan")
    for node in root.iter("DataArray"):
        name = node.get("Name", "")
        dtype = np.dtype(NUMPY_TYPE.get(node.get("type"), "<f8"))
        if node.get("format") == "appended":
            offset = int(node.get("offset"))
            (nbytes,) = struct.unpack_from("<Q", raw, offset)
            values = np.frombuffer(raw, dtype=dtype, count=nbytes // dtype.itemsize, offset=offset + 8)
        else:
            values = np.array((node.text or "").split(), dtype=dtype)
        components = int(node.get("NumberOfComponents", "1"))
        if components > 1:
            values = values.reshape(-1, components)
        if name in ("TIME", "TimeValue"):
            time = float(values[0])
        elif name in ("Points", "points", "") and components == 3 and "Points" not in arrays:
            arrays["Points"] = values
        else:
            arrays[name] = values
    if "Points" not in arrays:
        fail(f"{path}: no particle positions found")
    return time, arrays


def read_pvd(run_dir):
    pvd = os.path.join(run_dir, "frames.pvd")
    if not os.path.isfile(pvd):
        fail(f"{pvd} does not exist (is {run_dir} a mistfall run directory?)")
    root = ET.parse(pvd).getroot()
    return [(float(d.get("timestep")), os.path.join(run_dir, d.get("file"))) for d in root.iter("DataSet")]


def case_name(run_dir):
    try:
        import tomllib
        with open(os.path.join(run_dir, "case.toml"), "rb") as f:
            return tomllib.load(f)["case"]["name"]
    except Exception:
        return os.path.basename(os.path.abspath(run_dir))


def colour_values(arrays, field):
    if field == "speed":
        return np.linalg.norm(arrays["velocity"], axis=1), "speed [m/s]"
    if field == "pressure":
        return arrays["pressure"], "pressure [Pa]"
    return arrays[field].astype(float), field


def plot_frame(path, out_png, title, field, dimension, dpi):
    time, arrays = read_vtp(path)
    x = arrays["Points"]
    fluid = arrays["kind"] == KIND_FLUID
    solid = ~fluid & (arrays["kind"] != 3)  # 3 = escaped: not drawn
    values, label = colour_values(arrays, field)
    views = [(0, 1, "x [m]", "y [m]")] if dimension == 2 else [(0, 2, "x [m]", "z [m]"), (0, 1, "x [m]", "y [m]")]
    fig, axes = plt.subplots(1, len(views), figsize=(7 * len(views), 5), squeeze=False)
    size = max(1.0, 4000.0 / max(1, len(x)))
    for ax, (a, b, la, lb) in zip(axes[0], views):
        ax.scatter(x[solid, a], x[solid, b], s=size, c="0.6", marker="s", linewidths=0)
        sc = ax.scatter(x[fluid, a], x[fluid, b], s=size * 2, c=values[fluid], cmap="viridis", linewidths=0)
        ax.set_aspect("equal")
        ax.set_xlabel(la)
        ax.set_ylabel(lb)
        fig.colorbar(sc, ax=ax, label=label, shrink=0.8)
    fig.suptitle(f"{title}   t = {time:.4f} s")
    save(fig, out_png, dpi)


def plot_diagnostics(run_dir, out_png, dpi):
    path = os.path.join(run_dir, "diagnostics.csv")
    if not os.path.isfile(path):
        fail(f"{path} does not exist")
    d = np.genfromtxt(path, delimiter=",", names=True)
    d = np.atleast_1d(d)
    fig, axes = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
    for ax, col, label in zip(axes, ["max_speed", "kinetic_energy", "ppe_iterations"],
                              ["max speed [m/s]", "kinetic energy [J (per m in 2D)]", "PPE iterations"]):
        ax.plot(d["time"], d[col], marker=".")
        ax.set_ylabel(label)
    axes[-1].set_xlabel("t [s]")
    fig.suptitle(case_name(run_dir))
    save(fig, out_png, dpi)


def save(fig, out_png, dpi):
    tmp = out_png + ".tmp.png"
    fig.savefig(tmp, dpi=dpi)
    plt.close(fig)
    os.replace(tmp, out_png)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run_dir", help="run directory written by `mistfall simulate --out`")
    parser.add_argument("--out", help="folder for the PNGs (default RUN_DIR/plots)")
    parser.add_argument("--color", choices=["pressure", "speed", "phase", "kind"], default="pressure",
                        help="field that colours the fluid particles (default pressure)")
    parser.add_argument("--frames", default="last",
                        help="'all', 'last' (default) or comma-separated frame indices, e.g. 0,10,20")
    parser.add_argument("--diagnostics", action="store_true", help="also plot diagnostics.csv to diagnostics.png")
    parser.add_argument("--dpi", type=int, default=80, help="image resolution (default 80)")
    args = parser.parse_args()

    if not os.path.isdir(args.run_dir):
        fail(f"{args.run_dir} is not a directory")
    frames = read_pvd(args.run_dir)
    if not frames:
        fail(f"{args.run_dir}/frames.pvd lists no frames")
    if args.frames == "all":
        chosen = list(range(len(frames)))
    elif args.frames == "last":
        chosen = [len(frames) - 1]
    else:
        try:
            chosen = [int(k) for k in args.frames.split(",")]
        except ValueError:
            fail(f"--frames {args.frames}: expected 'all', 'last' or indices like 0,10,20")
        bad = [k for k in chosen if not 0 <= k < len(frames)]
        if bad:
            fail(f"--frames: no frame {bad[0]} (the run has frames 0..{len(frames) - 1})")
    out = args.out or os.path.join(args.run_dir, "plots")
    os.makedirs(out, exist_ok=True)
    title = case_name(args.run_dir)
    _, first = read_vtp(frames[0][1])
    dimension = 3 if np.any(first["Points"][:, 2] != 0.0) else 2
    for k in chosen:
        png = os.path.join(out, f"frame_{k:05d}.png")
        plot_frame(frames[k][1], png, title, args.color, dimension, args.dpi)
        print(png)
    if args.diagnostics:
        png = os.path.join(out, "diagnostics.png")
        plot_diagnostics(args.run_dir, png, args.dpi)
        print(png)


if __name__ == "__main__":
    main()
