#!/usr/bin/env python3
"""Mesh study for benchmark 4 (loaded_pin, 3D quarter model).

Runs parameters/loaded_pin/loaded_pin_mu0.prm and loaded_pin_mu01.prm for
element degree Q1 and Q2 and several refinement levels: level L sets
'Number of contact refinements' = L (each halves the cells at the hole).
For each run it records DoFs, Newton iterations, wall time, peak memory,
and on the sheet's mid-plane: the contact arc end angle, the peak pressure
and its angle (largest nodal value, and the vertex of the parabola through
it and its neighbours), the peak circumferential traction and the largest
relative displacement; on the sheet face the arc end angle and the peak
pressure. The reference of each friction coefficient is its finest Q2
run (self-convergence: no published result exists); the change of the arc
end angle and of the peak pressure (parabola) between the two finest Q2
levels is the error estimate of the converged figures. Writes pin_mesh_study.csv,
and plots of each quantity's difference from the reference against wall
time (log-log), and of the arc end angle and peak pressure against DoFs.

With --arc-end-refinements, a second series of Q2 runs (column 'series'
= 'arc end') adds that many 'Number of arc end refinements' toward theta =
--arc-end-angle on level --arc-end-base-level: the node spacing at the arc
end halves with each, and the change between its two finest runs is the
error estimate of the arc end. Those meshes have hanging nodes on the
contact surface where the refinement levels meet, so their peak pressure
is not judged; the series is left out of the differences and plots of the
uniform levels.

Usage: scripts/pin_mesh_study.py [--build DIR] [--out DIR]
           [--levels 1 2 3] [--degrees 1 2] [--mus 0 01]
           [--arc-end-refinements 2 3] [--arc-end-base-level 1]
           [--arc-end-angle 89]
"""
import argparse
import os

from study_tools import ROOT, loglog_plot, run_variant_measured, write_table

QUANTITIES = [
    # key in the row, label, unit, absolute (True) or relative difference
    ("arc_end_mid_deg", "contact arc end, mid-plane", "deg", True),
    ("peak_pressure_mid_MPa", "peak pressure, mid-plane", "MPa", False),
    ("fitted_peak_pressure_mid_MPa", "peak pressure (parabola), mid-plane", "MPa", False),
    ("peak_traction_mid_MPa", "peak traction, mid-plane", "MPa", False),
    ("max_slip_mid_mm", "largest relative displacement, mid-plane", "mm", False),
    ("arc_end_face_deg", "contact arc end, sheet face", "deg", True),
]


def run_case(app, mu, degree, level, out_dir, arc_end=0, angle=89.):
    """One run of the production file of mu at a degree and a level, with
    arc_end refinements toward theta = angle (degrees)."""
    production = os.path.join(ROOT, f"parameters/loaded_pin/loaded_pin_mu{mu}.prm")
    name = f"mu{mu}_q{degree}_level{level}" + (f"_arc{arc_end}" if arc_end else "")
    case_dir = os.path.join(out_dir, "runs", name)
    mesh = {"Element degree": degree, "Number of contact refinements": level}
    if arc_end:
        mesh.update({"Number of arc end refinements": arc_end, "Arc end angle": angle})
    s, wall, memory = run_variant_measured(app, production, case_dir, {"Mesh": mesh})
    mid, face = s["results"]["mid_plane"], s["results"]["sheet_face"]
    return {
        "series": "arc end" if arc_end else "uniform",
        "mu": "0.1" if mu == "01" else "0", "degree": degree, "level": level,
        "arc_end_refinements": arc_end,
        "n_dofs": s["mesh"]["n_dofs"],
        "h_contact_mm": s["mesh"]["smallest_cell_in_contact_zone_mm"],
        "newton_iterations": s["newton"]["total_iterations"],
        "max_newton_per_step": s["newton"]["max_iterations_per_step"],
        "n_cutbacks": s["newton"]["n_cutbacks"],
        "wall_time_s": round(wall, 2), "peak_memory_MB": round(memory, 1),
        "arc_end_mid_deg": mid["arc_end_theta_deg"],
        "peak_pressure_mid_MPa": mid["peak_pressure_MPa"],
        "peak_pressure_theta_mid_deg": mid["peak_pressure_theta_deg"],
        "fitted_peak_pressure_mid_MPa": mid["fitted_peak_pressure_MPa"],
        "fitted_peak_pressure_theta_mid_deg": mid["fitted_peak_pressure_theta_deg"],
        "peak_traction_mid_MPa": mid["peak_traction_MPa"],
        "max_slip_mid_mm": mid["max_slip_mm"],
        "arc_end_face_deg": face["arc_end_theta_deg"],
        "peak_pressure_face_MPa": face["peak_pressure_MPa"],
        "pin_centre_ux_mm": s["results"]["pin_centre_ux_mm"],
        "force_balance_relative_error": s["results"]["force_balance_relative_error"],
    }


def print_change(title, series, step_key, quantities):
    """Print the change of each quantity (label, key, unit, absolute)
    between the two last rows of series, the error estimate."""
    if len(series) < 2:
        return
    coarse, fine = series[-2:]
    changes = []
    for label, key, unit, absolute in quantities:
        change = (f"{fine[key] - coarse[key]:+.3f} {unit}" if absolute else
                  f"{100 * (fine[key] / coarse[key] - 1):+.2f} %")
        changes.append(f"{label} {coarse[key]:.3f} -> {fine[key]:.3f} {unit} "
                       f"(change {change})")
    print(f"{title} {coarse[step_key]} -> {fine[step_key]}: " + ", ".join(changes))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build-release"))
    parser.add_argument("--out", default=os.path.join(ROOT, "results/studies/loaded_pin_mesh"))
    parser.add_argument("--levels", type=int, nargs="+", default=[1, 2, 3])
    parser.add_argument("--degrees", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--mus", nargs="+", default=["0", "01"])
    parser.add_argument("--arc-end-refinements", type=int, nargs="*", default=[])
    parser.add_argument("--arc-end-base-level", type=int, default=1)
    parser.add_argument("--arc-end-angle", type=float, default=89.)
    args = parser.parse_args()
    app = os.path.join(args.build, "loaded_pin", "loaded_pin")
    os.makedirs(args.out, exist_ok=True)

    rows = []
    for mu in args.mus:
        for degree in args.degrees:
            for level in args.levels:
                row = run_case(app, mu, degree, level, args.out)
                rows.append(row)
                print(", ".join(f"{k} {v}" for k, v in row.items()), flush=True)
    arc_rows = []
    for mu in args.mus:
        for n in args.arc_end_refinements:
            row = run_case(app, mu, max(args.degrees), args.arc_end_base_level,
                           args.out, n, args.arc_end_angle)
            arc_rows.append(row)
            print(", ".join(f"{k} {v}" for k, v in row.items()), flush=True)

    # Differences from the finest Q2 run of each mu (or the finest run).
    for mu in sorted({r["mu"] for r in rows}):
        group = [r for r in rows if r["mu"] == mu]
        best = [r for r in group if r["degree"] == max(args.degrees)]
        reference = max(best, key=lambda r: r["level"])
        for r in group:
            for key, _, _, absolute in QUANTITIES:
                d = r[key] - reference[key]
                r[f"{key}_difference"] = abs(d) if absolute else abs(d / reference[key])
        print_change(f"mu = {mu}, Q{max(args.degrees)} levels",
                     sorted(best, key=lambda r: r["level"]), "level",
                     [("arc end (mid-plane)", "arc_end_mid_deg", "deg", True),
                      ("peak pressure (parabola)", "fitted_peak_pressure_mid_MPa", "MPa",
                       False)])
    for mu in sorted({r["mu"] for r in arc_rows}):
        print_change(f"mu = {mu}, Q{max(args.degrees)} level {args.arc_end_base_level} "
                     "graded toward the arc end, arc end refinements",
                     sorted((r for r in arc_rows if r["mu"] == mu),
                            key=lambda r: r["arc_end_refinements"]),
                     "arc_end_refinements",
                     [("arc end (mid-plane)", "arc_end_mid_deg", "deg", True),
                      ("arc end (sheet face)", "arc_end_face_deg", "deg", True)])
    write_table(os.path.join(args.out, "pin_mesh_study.csv"), rows + arc_rows)

    # Plots: one CSV per series, then difference against wall time.
    series_files = {}
    for mu in sorted({r["mu"] for r in rows}):
        for degree in args.degrees:
            group = [r for r in rows if r["mu"] == mu and r["degree"] == degree]
            if not group:
                continue
            name = f"series_mu{mu.replace('.', '')}_q{degree}.csv"
            write_table(os.path.join(args.out, name), group)
            series_files[(mu, degree)] = (name, list(group[0].keys()))
    for key, label, unit, absolute in QUANTITIES:
        # A single level has no difference to plot.
        if not any(r[f"{key}_difference"] > 0 for r in rows):
            continue
        clauses = []
        for (mu, degree), (name, columns) in series_files.items():
            x = columns.index("wall_time_s") + 1
            y = columns.index(f"{key}_difference") + 1
            clauses.append(f"'{name}' using {x}:(${y} > 0 ? ${y} : 1/0) with linespoints "
                           f"title 'Q{degree}, mu = {mu}'")
        loglog_plot(args.out, f"{key}_difference_vs_time",
                    f"Loaded pin: {label}, difference from the finest Q2 run",
                    "wall time [s]",
                    f"|difference| [{unit}]" if absolute else "relative difference",
                    clauses)
    for key, label, unit in [("arc_end_mid_deg", "contact arc end, mid-plane", "deg"),
                             ("peak_pressure_mid_MPa", "peak pressure, mid-plane", "MPa")]:
        clauses = []
        for (mu, degree), (name, columns) in series_files.items():
            x = columns.index("n_dofs") + 1
            y = columns.index(key) + 1
            clauses.append(f"'{name}' using {x}:{y} with linespoints "
                           f"title 'Q{degree}, mu = {mu}'")
        loglog_plot(args.out, f"{key}_vs_dofs", f"Loaded pin: {label}",
                    "degrees of freedom", f"{label} [{unit}]", clauses, logscale="x")


if __name__ == "__main__":
    main()
