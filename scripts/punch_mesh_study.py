#!/usr/bin/env python3
"""Mesh study for benchmark 2 (punch3d, axisymmetric, frictionless).

Runs parameters/punch3d/punch_axisym_mu0.prm for element degree Q1 and Q2,
contact enforcement by Lagrange multipliers and by penalty at two
stiffnesses, and several refinement levels: level L sets 'Number of contact refinements'
= L and 'Number of edge refinements' = L - 2 (so the cells at the contact
edge are 2^(2L-2) times smaller than the coarse 25 mm cells). For each run
it records DoFs, wall time, the centre pressure, the peak pressure and its
radius, the contact radius and the foundation's u_z on the axis, and the
errors of the peak pressure and of u_z against the finest Q2 Lagrange-
multiplier run (the self-convergence reference; the half-space and MSC.Marc values are printed
beside them). Writes punch_mesh_study.csv and log-log plots of those
errors against wall time.

A second series runs the same file on uniform meshes (no local
refinement; 'Number of global refinements' = 2 to 5, cells of 6.25 to
0.78 mm), Q1 and Q2 with Lagrange multipliers, as a coarse reference
model would be meshed: the FE references of the benchmark report have
nodes 2.6 to 4 mm apart along the contact. It records the centre pressure
and u_z against the cell size and writes uniform_mesh_study.csv and the
plots centre_pressure_vs_h.png and uz_vs_h.png, with the MSC.Marc values
on the same axes.

Usage: scripts/punch_mesh_study.py [--build DIR] [--out DIR] [--quick]
           [--levels 3 4 5 6] [--degrees 1 2]
           [--enforcements lm penalty:1e5 penalty:1e6]
           [--uniform-levels 2 3 4 5]
"""
import argparse
import os
import sys
import time

from study_tools import (ROOT, contact_overrides, enforcement_label, enforcement_tag,
                         loglog_plot, run_variant, write_table)

PRODUCTION = os.path.join(ROOT, "parameters/punch3d/punch_axisym_mu0.prm")


def run_mesh_variant(app, out_dir, name, degree, enforcement, mesh):
    """Run the production file with element degree, enforcement and the
    Mesh entries in mesh; return the row of results every series records."""
    s, wall = run_variant(app, PRODUCTION, os.path.join(out_dir, "runs", name), {
        "Contact": contact_overrides(enforcement),
        "Mesh": {"Element degree": degree, **mesh}})
    r = s["results"]
    return {
        "n_dofs": s["mesh"]["n_dofs"],
        "h_contact_mm": s["mesh"]["smallest_cell_in_contact_zone_mm"],
        "newton_iterations": s["newton"]["total_iterations"],
        "wall_time_s": round(wall, 3),
        "pressure_at_centre_MPa": r["pressure_at_centre_MPa"],
        "centre_node_radius_mm": r["centre_node_radius_mm"],
        "peak_pressure_MPa": r["peak_pressure_MPa"],
        "peak_pressure_radius_mm": r["peak_pressure_radius_mm"],
        "contact_radius_mm": r["contact_radius_mm"],
        "foundation_top_axis_uz_mm": r["foundation_top_axis_uz_mm"],
        "force_balance_relative_error": r["force_balance_relative_error"],
        "half_space_contact_radius_mm": s["reference"]["half_space_contact_radius_mm"],
        "marc_pressure_at_centre_MPa": s["reference"]["marc_pressure_at_centre_MPa"],
        "marc_uz_mm": s["reference"]["marc_foundation_top_axis_uz_mm"],
    }


def run_case(app, degree, level, enforcement, out_dir):
    """A graded mesh: level contact refinements, two fewer edge refinements."""
    return {"degree": degree, "level": level, "enforcement": enforcement,
            **run_mesh_variant(app, out_dir, f"q{degree}_level{level}_{enforcement_tag(enforcement)}",
                               degree, enforcement,
                               {"Number of contact refinements": level,
                                "Number of edge refinements": max(0, level - 2)})}


def run_uniform_case(app, degree, level, out_dir):
    """A uniform mesh: level global refinements, no local ones."""
    return {"degree": degree, "global_refinements": level,
            **run_mesh_variant(app, out_dir, f"q{degree}_uniform{level}", degree, "lm",
                               {"Number of global refinements": level,
                                "Number of contact refinements": 0,
                                "Number of edge refinements": 0})}


def write_uniform_plots(out_dir, rows, degrees, converged):
    """Centre pressure and u_z against the cell size on uniform meshes, one
    curve per degree, with MSC.Marc's value (a horizontal line) and the
    converged value of the graded Q2 study."""
    for d in degrees:
        with open(os.path.join(out_dir, f"uniform_q{d}.csv"), "w") as f:
            f.write("h_contact_mm,pressure_at_centre_MPa,foundation_top_axis_uz_mm\n")
            for r in rows:
                if r["degree"] == d:
                    f.write(f"{r['h_contact_mm']},{r['pressure_at_centre_MPa']},"
                            f"{r['foundation_top_axis_uz_mm']}\n")
    marc = rows[0]
    for stem, col, quantity, unit, key, marc_value in (
            ("centre_pressure_vs_h", 2, "pressure at the centre", "MPa",
             "pressure_at_centre_MPa", marc["marc_pressure_at_centre_MPa"]),
            ("uz_vs_h", 3, "u_z of the foundation top on the axis", "mm",
             "foundation_top_axis_uz_mm", marc["marc_uz_mm"])):
        series = [f"'uniform_q{d}.csv' using 1:{col} with linespoints lw 2 pt 7 "
                  f"lc rgb '{COLOURS[i % len(COLOURS)]}' title \"Q{d}, uniform mesh\""
                  for i, d in enumerate(degrees)]
        series.append(f"{marc_value} with lines lw 2 dt 2 lc rgb 'black' title \"MSC.Marc\"")
        if converged is not None:
            series.append(f"{converged[key]} with lines lw 1 dt 3 lc rgb '#666666' "
                          f"title \"converged (graded Q2, finest level)\"")
        loglog_plot(out_dir, stem,
                    f"Benchmark 2, mu = 0, uniform meshes: {quantity}",
                    "cell size along the contact [mm]", f"{quantity} [{unit}]", series,
                    extra="set key outside below center horizontal\n"
                          "set xrange [8:0.5] reverse\nset xtics (0.5, 1, 2, 4, 8)\n"
                          "set samples 200\n", logscale="x")


COLOURS = ["#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e"]


def write_plots(out_dir, rows, degrees, enforcements):
    """Two log-log plots (peak pressure, u_z): error against wall time, one
    curve per degree x enforcement; colour = enforcement, solid = highest
    degree."""
    names = {}
    for d in degrees:
        for e in enforcements:
            names[(d, e)] = f"series_q{d}_{enforcement_tag(e)}.csv"
            with open(os.path.join(out_dir, names[(d, e)]), "w") as f:
                f.write("wall_time_s,error_peak,error_uz\n")
                for r in rows:
                    if r["degree"] == d and r["enforcement"] == e and r["error_peak"] > 0:
                        f.write(f"{r['wall_time_s']},{r['error_peak']},{max(r['error_uz'], 1e-7)}\n")
    for stem, col, quantity in (("error_peak_vs_time", 2, "peak pressure"),
                                ("error_uz_vs_time", 3, "u_z of the foundation top on the axis")):
        series = []
        for i, e in enumerate(enforcements):
            for d in degrees:
                style = "lw 2 pt 7" if d == max(degrees) else "lw 1.5 dt 2 pt 6"
                series.append(f"'{names[(d, e)]}' using 1:{col} with linespoints {style} "
                              f"lc rgb '{COLOURS[i % len(COLOURS)]}' "
                              f"title \"Q{d}, {enforcement_label(e)}\"")
        loglog_plot(out_dir, stem,
                    f"Benchmark 2 (axisymmetric, mu = 0): {quantity}",
                    "wall time of the run [s]",
                    "relative error against the finest Q2 Lagrange-multiplier run", series)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build-release"))
    parser.add_argument("--out", default=os.path.join(ROOT, "results/studies/punch3d_mesh"))
    parser.add_argument("--quick", action="store_true", help="levels 3 to 5 only")
    parser.add_argument("--levels", type=int, nargs="+", default=[3, 4, 5, 6, 7])
    parser.add_argument("--degrees", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--enforcements", nargs="+", default=["lm", "penalty:1e5", "penalty:1e6"])
    parser.add_argument("--uniform-levels", type=int, nargs="*", default=[2, 3, 4, 5],
                        help="global refinements of the uniform-mesh series (none: skip it)")
    args = parser.parse_args()
    if args.quick:
        args.levels = [l for l in args.levels if l <= 5]
        args.uniform_levels = [l for l in args.uniform_levels if l <= 4]
    if len(args.levels) < 3:
        sys.exit("punch_mesh_study: give at least three levels")

    app = os.path.join(args.build, "punch3d/punch3d")
    if not os.access(app, os.X_OK):
        sys.exit(f"punch_mesh_study: no executable {app}; run scripts/build.sh Release first")
    os.makedirs(args.out, exist_ok=True)
    start = time.time()
    rows = []
    total = len(args.degrees) * len(args.enforcements) * len(args.levels)
    for d in args.degrees:
        for e in args.enforcements:
            for l in args.levels:
                print(f"  [{time.time() - start:6.1f} s] run {len(rows) + 1} of {total}: "
                      f"Q{d}, level {l}, {enforcement_label(e)}", flush=True)
                rows.append(run_case(app, d, l, e, args.out))

    # The self-convergence reference: the finest run of the highest degree,
    # with Lagrange multipliers if they were run (penalty solutions carry
    # a penetration error that refinement does not remove).
    reference_enforcement = "lm" if "lm" in args.enforcements else args.enforcements[0]
    finest = max((r for r in rows if r["degree"] == max(args.degrees)
                  and r["enforcement"] == reference_enforcement),
                 key=lambda r: r["level"])
    for r in rows:
        r["error_peak"] = abs(r["peak_pressure_MPa"] / finest["peak_pressure_MPa"] - 1.)
        r["error_uz"] = abs(r["foundation_top_axis_uz_mm"] / finest["foundation_top_axis_uz_mm"] - 1.)

    print("degree level  enforcement            n_dofs  h[mm]   Newton  wall[s]  p(0)[MPa]  "
          "peak[MPa]  at r[mm]  a[mm]    u_z[mm]     err peak   err u_z")
    for r in rows:
        print(f"Q{r['degree']:<5d} {r['level']:5d}  {enforcement_label(r['enforcement']):22s} "
              f"{r['n_dofs']:6d} {r['h_contact_mm']:7.4f} {r['newton_iterations']:6d} "
              f"{r['wall_time_s']:8.2f}  {r['pressure_at_centre_MPa']:9.3f}  "
              f"{r['peak_pressure_MPa']:9.2f}  {r['peak_pressure_radius_mm']:8.3f}  "
              f"{r['contact_radius_mm']:7.3f}  {r['foundation_top_axis_uz_mm']:.6f}  "
              f"{r['error_peak']:9.2e}  {r['error_uz']:9.2e}")
    print(f"references: half-space contact radius {finest['half_space_contact_radius_mm']:.3f} mm, "
          f"MSC.Marc u_z {finest['marc_uz_mm']} mm; errors are against the finest "
          f"Q{finest['degree']} {enforcement_label(finest['enforcement'])} run")
    table = os.path.join(args.out, "punch_mesh_study.csv")
    write_table(table, rows)
    write_plots(args.out, rows, args.degrees, args.enforcements)
    print(f"table: {table}")
    print(f"plots: {args.out}/error_peak_vs_time.png, {args.out}/error_uz_vs_time.png")

    if args.uniform_levels:
        uniform = []
        for d in args.degrees:
            for l in args.uniform_levels:
                print(f"  [{time.time() - start:6.1f} s] uniform mesh: Q{d}, "
                      f"{l} global refinements", flush=True)
                uniform.append(run_uniform_case(app, d, l, args.out))
        converged = finest if finest["enforcement"] == "lm" else None
        print("uniform meshes, Lagrange multipliers:")
        print("degree  refinements  h[mm]   n_dofs  wall[s]  p(0)[MPa] (node r[mm])  u_z[mm]")
        for r in uniform:
            print(f"Q{r['degree']:<6d} {r['global_refinements']:11d} {r['h_contact_mm']:6.3f} {r['n_dofs']:8d} "
                  f"{r['wall_time_s']:8.2f}  {r['pressure_at_centre_MPa']:9.3f} ({r['centre_node_radius_mm']:5.2f})"
                  f"       {r['foundation_top_axis_uz_mm']:.6f}")
        print(f"MSC.Marc: p(0) {uniform[0]['marc_pressure_at_centre_MPa']} MPa, "
              f"u_z {uniform[0]['marc_uz_mm']} mm (nodes 2.6 to 4 mm apart)")
        write_table(os.path.join(args.out, "uniform_mesh_study.csv"), uniform)
        write_uniform_plots(args.out, uniform, args.degrees, converged)
        print(f"table: {args.out}/uniform_mesh_study.csv")
        print(f"plots: {args.out}/centre_pressure_vs_h.png, {args.out}/uz_vs_h.png")
    print(f"study wall time: {time.time() - start:.1f} s")


if __name__ == "__main__":
    main()
