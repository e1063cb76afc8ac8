"""Frames of a run directory made by hand, for the tool tests (tests/tools/*.sh): ASCII VTK PolyData frames with
the arrays mistfall writes (kind, phase, velocity, pressure; optionally others, such as enclosed) and the frames.pvd
that lists them."""
import os


def _array(name, typ, comps, values):
    return (f'<DataArray type="{typ}" Name="{name}" NumberOfComponents="{comps}" format="ascii">'
            + " ".join(str(x) for x in values) + "</DataArray>\n")


def write_frames(run, times, points, velocities, pressures=None, arrays=None):
    """Writes one frame per time into run/frames and run/frames.pvd. points: [(x, y, kind, phase)];
    velocities: [(u, v)] of the same length, the same in every frame. Or, for frames that differ, points and
    velocities are lists of such lists, one per time. pressures: [p] per point, the same in every frame (default 0),
    or a list of such lists, one per time. arrays: {name: (VTK type, values)} of further
    one-component point arrays (e.g. {"enclosed": ("UInt8", [0, 1, ...])}), values per point as pressures are."""
    os.makedirs(os.path.join(run, "frames"), exist_ok=True)
    per_frame = isinstance(points[0], list)
    all_points, all_velocities = points, velocities

    def this_frame(values, k):  # pressures and arrays: a list of lists holds one list per frame
        return values[k] if isinstance(values[0], list) else values

    datasets = ""
    for k, t in enumerate(times):
        points = all_points[k] if per_frame else all_points
        velocities = all_velocities[k] if per_frame else all_velocities
        n = len(points)
        extra = "".join(_array(name, typ, 1, this_frame(values, k)) for name, (typ, values) in (arrays or {}).items())
        body = ('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian">\n'
                '<PolyData>\n<FieldData>' + _array("TIME", "Float64", 1, [t]) + '</FieldData>\n'
                f'<Piece NumberOfPoints="{n}" NumberOfVerts="0">\n<Points>'
                + _array("Points", "Float64", 3, [c for p in points for c in (p[0], p[1], 0.0)])
                + '</Points>\n<PointData>\n'
                + _array("kind", "UInt8", 1, [p[2] for p in points])
                + _array("phase", "UInt8", 1, [p[3] for p in points])
                + _array("velocity", "Float64", 3, [c for w in velocities for c in (w[0], w[1], 0.0)])
                + _array("pressure", "Float64", 1, this_frame(pressures, k) if pressures is not None else [0.0] * n)
                + extra
                + '</PointData>\n</Piece>\n</PolyData>\n</VTKFile>\n')
        name = f"frame_{k:05d}.vtp"
        with open(os.path.join(run, "frames", name), "w") as f:
            f.write(body)
        datasets += f'<DataSet timestep="{t}" group="" part="0" file="frames/{name}"/>\n'
    with open(os.path.join(run, "frames.pvd"), "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="1.0">\n<Collection>\n' + datasets
                + '</Collection>\n</VTKFile>\n')
