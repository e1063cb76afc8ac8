#!/usr/bin/env python3
"""The numerical guards of a run: how often each fired, and the case key that sets it.

A guard is a cap, a clamp or a threshold that is not physics (the developers' brief): each one counts its firings in
diagnostics.csv, "since the previous row". This sums them over a run's rows (from --from), with the rows in which each
fired and the first and last of them, next to the value the run's case.toml gives its key (or "default"). A cut or a
stop whose key the case sets and that never fired over a run changed nothing in that run: without the key the run is
the same to the bit, and the table's last line names such keys (not the thresholds and models that count something
else, such as entrained_bubble_diameter's point_wall_stops).

    guard_counts.py RUN_DIR [--from T] [--all]

--all lists the guards that did not fire and whose key the case does not set too. The diagnostics that are not guards
but tell how near one came (largest_shift, long_respacings) are printed below the table.
"""
import argparse
import csv
import pathlib
import sys
import tomllib

# (diagnostics column, the case keys under [numerics] that set or govern it, whether the key is a guard that does
# nothing where it does not fire: then a run in which it is silent is the same without it). The keys are those of
# docs/case-file.md, where each guard's row says what one firing is, why it exists and what it is measured against.
GUARDS = [
    ("gas_correction_capped", ["gas_correction_limit"], True),
    ("gas_speed_capped", ["gas_speed_limit"], True),
    ("dispersed_gas", ["dispersed_gas_fraction"], True),
    ("entrained_swaps", ["entrained_gas_rise_speed"], True),
    ("regularised_rows", ["bubble_regularisation"], False),
    ("collisions", ["collision_distance", "collision_passes"], False),
    ("gradient_fallbacks", ["gradient_correction_min_determinant"], False),
    ("thin_support", ["liquid_support_fraction"], False),
    ("neighbour_surfaces", ["surface_neighbour_fraction", "surface_asymmetry"], False),
    ("shift_cuts", ["shift_limit"], True),
    ("shift_bounded", ["shift_stability"], True),
    ("shift_wall_stops", ["shift_wall_stop"], True),
    ("respacing_wall_stops", ["respacing_walls", "shift_wall_stop", "bubble_gas_wall_stop"], False),
    ("respacing_cuts", ["respacing_limit"], True),
    ("respacing_fluid_stops", ["respacing_stop"], True),
    ("bubble_gas_wall_stops", ["bubble_gas_wall_stop"], True),
    ("collision_wall_limits", ["collision_wall_limit"], True),
    ("liquid_wall_collisions", ["liquid_collision_after_correction"], True),
    ("vent_liquid_stops", ["vent_liquid_stop"], True),
    ("vent_crowded_out", ["vent_crowding_at_mouth"], False),
    ("gap_water_floors", ["gap_water_floor"], True),
    ("point_wall_stops", ["entrained_bubble_diameter"], False),
    ("points_unpaired", ["entrained_bubble_diameter"], False),
    ("points_coalesced", ["entrained_bubble_diameter"], False),
    ("curvature_unfitted", ["bubble_surface_tension"], False),
]
NEAR_MISSES = [("largest_shift", max, "the largest shift of a step [l0]"),
               ("long_respacings", sum, "re-spacings longer than one spacing as solved")]


def key_values(case_file):
    """The [numerics] keys the case sets, as text."""
    try:
        numerics = tomllib.loads(case_file.read_text()).get("numerics", {})
    except (OSError, tomllib.TOMLDecodeError) as error:
        sys.exit(f"guard_counts: cannot read {case_file}: {error}")
    return {k: (f'"{v}"' if isinstance(v, str) else str(v).lower() if isinstance(v, bool) else str(v))
            for k, v in numerics.items()}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("run", type=pathlib.Path)
    parser.add_argument("--from", dest="start", type=float, default=0.0, help="first row's time [s] (default 0)")
    parser.add_argument("--all", action="store_true", help="list the silent guards whose key is not set too")
    args = parser.parse_args()
    diagnostics = args.run / "diagnostics.csv"
    if not diagnostics.is_file():
        sys.exit(f"guard_counts: {diagnostics} not found")
    with diagnostics.open() as f:
        rows = [r for r in csv.DictReader(f) if float(r["time"]) >= args.start - 1e-12]
    if not rows:
        sys.exit(f"guard_counts: no row of {diagnostics} at or after {args.start} s")
    keys = key_values(args.run / "case.toml")
    first_t, last_t = float(rows[0]["time"]), float(rows[-1]["time"])
    print(f"{args.run}: rows {first_t:.2f}-{last_t:.2f} s ({len(rows)}), steps to {rows[-1]['step']}, "
          f"escaped {rows[-1]['escaped']}")
    print(f"{'guard (diagnostics.csv)':24} {'total':>10} {'rows':>5} {'first':>6} {'last':>6}  key(s) as the case sets them")
    silent_set = []
    for column, guard_keys, no_op_when_silent in GUARDS:
        if column not in rows[0]:
            continue
        fired = [(float(r["time"]), float(r[column])) for r in rows if float(r[column]) != 0.0]
        total = sum(v for _, v in fired)
        set_keys = [f"{k} = {keys[k]}" for k in guard_keys if k in keys]
        if not fired and not set_keys and not args.all:
            continue
        if not fired and set_keys and no_op_when_silent:
            silent_set.extend(k for k in guard_keys if k in keys)
        when = f"{fired[0][0]:6.2f} {fired[-1][0]:6.2f}" if fired else f"{'-':>6} {'-':>6}"
        print(f"{column:24} {total:10.0f} {len(fired):5d} {when}  {', '.join(set_keys) or 'default'}")
    for column, reduce, what in NEAR_MISSES:
        if column in rows[0]:
            values = [float(r[column]) for r in rows]
            worst = max(values)
            row = rows[values.index(worst)]
            named = ""
            if column == "largest_shift" and int(row.get("largest_shift_id", "-1")) >= 0:
                named = f": particle id {row['largest_shift_id']}, in the step from {float(row['largest_shift_time']):.6f} s"
            print(f"{column}: {reduce(values):g} ({what}; the most in a row {worst:g} at {float(row['time']):.2f} s{named})")
    if silent_set:
        print("guards the case sets that did not fire over these rows (the same trajectory without them): "
              + ", ".join(silent_set))


if __name__ == "__main__":
    main()
