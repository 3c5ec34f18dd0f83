#!/usr/bin/env python3
"""Convergence of benchmark 1 (cgs_roller, frictionless) against Hertz.

Runs the production case for Q1 and Q2 at several contact refinement levels,
full load in one step, and prints one table row per run: DoFs, Newton
iterations, wall time, error in p0, error in a, relative L2 error of the
pressure profile, cost of contact. Writes the table as CSV.

Usage: scripts/convergence_study.py [--build DIR] [--levels 5 6 7 8 9]
                                    [--out results/studies]
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run_case(app, degree, level, out_dir):
    case_dir = os.path.join(out_dir, f"q{degree}_level{level}")
    os.makedirs(case_dir, exist_ok=True)
    prm = os.path.join(case_dir, "case.prm")
    production = os.path.join(ROOT, "parameters/cgs_roller/hertz_frictionless.prm")
    with open(prm, "w") as f:
        f.write(f"include {production}\n"
                "subsection Mesh\n"
                f"  set Element degree = {degree}\n"
                f"  set Number of contact refinements = {level}\n"
                "end\n"
                "subsection Output\n"
                f"  set Output directory = {case_dir}\n"
                "  set Write graphical output = false\n"
                "  set Write plots = false\n"
                "  set Verbosity = quiet\n"
                "end\n"
                "subsection Run control\n"
                "  set Measure contact cost = true\n"
                "end\n")
    start = time.time()
    subprocess.run([app, prm], check=True, stdout=subprocess.DEVNULL)
    wall = time.time() - start
    with open(os.path.join(case_dir, "summary.json")) as f:
        s = json.load(f)
    return {
        "degree": degree,
        "contact_refinements": level,
        "n_dofs": s["mesh"]["n_dofs"],
        "h_contact_mm": s["mesh"]["smallest_cell_in_contact_zone_mm"],
        "newton_iterations": s["newton"]["total_iterations"],
        "wall_time_s": wall,
        "solve_time_s": s["timing_s"]["contact_solve_s"],
        "error_p0": s["ratios"]["peak_pressure"] - 1.0,
        "error_a": s["ratios"]["contact_half_width"] - 1.0,
        "l2_error_pressure": s["results"]["pressure_l2_relative_error"],
        "contact_cost_ratio": s["timing_s"]["contact_cost_ratio"],
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build-release"))
    parser.add_argument("--levels", type=int, nargs="+", default=[5, 6, 7, 8, 9])
    parser.add_argument("--out", default=os.path.join(ROOT, "results/studies/cgs_roller_convergence"))
    args = parser.parse_args()

    app = os.path.join(args.build, "cgs_roller/cgs_roller")
    if not os.access(app, os.X_OK):
        sys.exit(f"convergence_study: no executable {app}; run scripts/build.sh Release first")
    start = time.time()
    rows = [run_case(app, d, l, args.out) for d in (1, 2) for l in args.levels]

    header = ("degree  level   n_dofs  h[mm]    Newton  wall[s]  err p0     err a      "
              "L2 err p   cost")
    print(header)
    for r in rows:
        print(f"Q{r['degree']:<6d} {r['contact_refinements']:5d} {r['n_dofs']:8d} "
              f"{r['h_contact_mm']:7.4f} {r['newton_iterations']:7d} {r['wall_time_s']:8.2f} "
              f"{r['error_p0']:+9.4%} {r['error_a']:+9.4%} {r['l2_error_pressure']:9.4%} "
              f"{r['contact_cost_ratio']:6.2f}")
    os.makedirs(args.out, exist_ok=True)
    table = os.path.join(args.out, "convergence.csv")
    with open(table, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    print(f"table: {table}")
    print(f"study wall time: {time.time() - start:.1f} s")


if __name__ == "__main__":
    main()
