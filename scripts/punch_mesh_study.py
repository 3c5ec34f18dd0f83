#!/usr/bin/env python3
"""Mesh study for benchmark 2 (punch3d, axisymmetric, frictionless).

Runs parameters/punch3d/punch_axisym_mu0.prm for element degree Q1 and Q2
and several refinement levels: level L sets 'Number of contact refinements'
= L and 'Number of edge refinements' = L - 2 (so the cells at the contact
edge are 2^(2L-2) times smaller than the coarse 25 mm cells). For each run
it records DoFs, wall time, the centre pressure, the peak pressure and its
radius, the contact radius and the foundation's u_z on the axis, and the
errors of the peak pressure and of u_z against the finest Q2 run (the
self-convergence reference; the half-space and MSC.Marc values are printed
beside them). Writes punch_mesh_study.csv and a log-log plot of those
errors against wall time.

Usage: scripts/punch_mesh_study.py [--build DIR] [--out DIR] [--quick]
           [--levels 3 4 5 6] [--degrees 1 2]
"""
import argparse
import csv
import json
import os
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PRODUCTION = os.path.join(ROOT, "parameters/punch3d/punch_axisym_mu0.prm")


def run_case(app, degree, level, out_dir):
    case_dir = os.path.join(out_dir, "runs", f"q{degree}_level{level}")
    os.makedirs(case_dir, exist_ok=True)
    prm = os.path.join(case_dir, "case.prm")
    with open(prm, "w") as f:
        f.write(f"include {PRODUCTION}\n"
                "subsection Mesh\n"
                f"  set Element degree = {degree}\n"
                f"  set Number of contact refinements = {level}\n"
                f"  set Number of edge refinements = {max(0, level - 2)}\n"
                "end\n"
                "subsection Output\n"
                f"  set Output directory = {case_dir}\n"
                "  set Write graphical output = false\n"
                "  set Write plots = false\n"
                "  set Verbosity = quiet\n"
                "end\n")
    start = time.time()
    subprocess.run([app, prm], check=True, stdout=subprocess.DEVNULL)
    wall = time.time() - start
    with open(os.path.join(case_dir, "summary.json")) as f:
        s = json.load(f)
    r = s["results"]
    return {
        "degree": degree,
        "level": level,
        "n_dofs": s["mesh"]["n_dofs"],
        "h_contact_mm": s["mesh"]["smallest_cell_in_contact_zone_mm"],
        "wall_time_s": round(wall, 3),
        "pressure_at_centre_MPa": r["pressure_at_centre_MPa"],
        "peak_pressure_MPa": r["peak_pressure_MPa"],
        "peak_pressure_radius_mm": r["peak_pressure_radius_mm"],
        "contact_radius_mm": r["contact_radius_mm"],
        "foundation_top_axis_uz_mm": r["foundation_top_axis_uz_mm"],
        "force_balance_relative_error": r["force_balance_relative_error"],
        "half_space_contact_radius_mm": s["reference"]["half_space_contact_radius_mm"],
        "marc_uz_mm": s["reference"].get("marc_foundation_top_axis_uz_mm", float("nan")),
    }


def write_plot(out_dir, rows, degrees):
    series = []
    for d in degrees:
        name = f"series_q{d}.csv"
        with open(os.path.join(out_dir, name), "w") as f:
            f.write("wall_time_s,error_peak,error_uz\n")
            for r in rows:
                if r["degree"] == d and r["error_peak"] > 0:
                    f.write(f"{r['wall_time_s']},{r['error_peak']},{max(r['error_uz'], 1e-7)}\n")
        series.append(f"'{name}' using 1:2 with linespoints lw 2 pt 7 title \"Q{d}, peak pressure\"")
        series.append(f"'{name}' using 1:3 with linespoints lw 2 dt 2 pt 6 title \"Q{d}, u_z on the axis\"")
    script = os.path.join(out_dir, "error_vs_time.gp")
    with open(script, "w") as f:
        f.write("set terminal pngcairo size 900,600 enhanced font 'Sans,11'\n"
                "set output 'error_vs_time.png'\n"
                "set datafile separator ','\n"
                "set logscale xy\nset grid\nset key outside right top\n"
                "set format y \"%g\"\n"
                "set title \"Benchmark 2 (axisymmetric, mu = 0): error against wall time\"\n"
                "set xlabel \"wall time of the run [s]\"\n"
                "set ylabel \"relative error against the finest Q2 run\"\n"
                "plot " + ", \\\n     ".join(series) + "\n")
    if shutil.which("gnuplot"):
        subprocess.run(["gnuplot", os.path.basename(script)], cwd=out_dir, check=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build-release"))
    parser.add_argument("--out", default=os.path.join(ROOT, "results/studies/punch3d_mesh"))
    parser.add_argument("--quick", action="store_true", help="levels 3 to 5 only")
    parser.add_argument("--levels", type=int, nargs="+", default=[3, 4, 5, 6, 7])
    parser.add_argument("--degrees", type=int, nargs="+", default=[1, 2])
    args = parser.parse_args()
    if args.quick:
        args.levels = [l for l in args.levels if l <= 5]
    if len(args.levels) < 3:
        sys.exit("punch_mesh_study: give at least three levels")

    app = os.path.join(args.build, "punch3d/punch3d")
    if not os.access(app, os.X_OK):
        sys.exit(f"punch_mesh_study: no executable {app}; run scripts/build.sh Release first")
    os.makedirs(args.out, exist_ok=True)
    start = time.time()
    rows = []
    total = len(args.degrees) * len(args.levels)
    for d in args.degrees:
        for l in args.levels:
            print(f"  [{time.time() - start:6.1f} s] run {len(rows) + 1} of {total}: Q{d}, level {l}",
                  flush=True)
            rows.append(run_case(app, d, l, args.out))

    finest = max((r for r in rows if r["degree"] == max(args.degrees)),
                 key=lambda r: r["level"])
    for r in rows:
        r["error_peak"] = abs(r["peak_pressure_MPa"] / finest["peak_pressure_MPa"] - 1.)
        r["error_uz"] = abs(r["foundation_top_axis_uz_mm"] / finest["foundation_top_axis_uz_mm"] - 1.)

    print("degree level  n_dofs  h[mm]    wall[s]  p(0)[MPa]  peak[MPa]  at r[mm]  a[mm]    "
          "u_z[mm]     err peak   err u_z")
    for r in rows:
        print(f"Q{r['degree']:<5d} {r['level']:5d} {r['n_dofs']:7d} {r['h_contact_mm']:7.4f} "
              f"{r['wall_time_s']:8.2f}  {r['pressure_at_centre_MPa']:9.3f}  {r['peak_pressure_MPa']:9.2f}  "
              f"{r['peak_pressure_radius_mm']:8.3f}  {r['contact_radius_mm']:7.3f}  "
              f"{r['foundation_top_axis_uz_mm']:.6f}  {r['error_peak']:9.2e}  {r['error_uz']:9.2e}")
    print(f"references: half-space contact radius {finest['half_space_contact_radius_mm']:.3f} mm, "
          f"MSC.Marc u_z {finest['marc_uz_mm']} mm; errors are against the finest Q2 run")
    table = os.path.join(args.out, "punch_mesh_study.csv")
    with open(table, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    write_plot(args.out, rows, args.degrees)
    print(f"table: {table}")
    print(f"plot: {os.path.join(args.out, 'error_vs_time.png')}")
    print(f"study wall time: {time.time() - start:.1f} s")


if __name__ == "__main__":
    main()
