#!/usr/bin/env python3
"""Accuracy against time for benchmark 1 (cgs_roller, frictionless, Hertz).

Sweeps contact refinement level x element degree (Q1, Q2) x enforcement
(Lagrange multipliers; penalty at two stiffnesses), full load in one step,
and writes one row per run: DoFs, Newton iterations, wall time, error in p0,
error in a, relative L2 error of the pressure profile, cost of contact.
Writes the table as CSV and log-log plots of error against wall time (PNG,
gnuplot). Times come from one machine in one run: compare them as ratios.

Usage: scripts/accuracy_time_study.py [--build DIR] [--out DIR] [--quick]
           [--levels 5 6 7 8 9] [--degrees 1 2]
           [--enforcements lm penalty:1e5 penalty:1e6]
"""
import argparse
import os
import sys
import time

from study_tools import (ROOT, contact_overrides, enforcement_label, enforcement_tag,
                         loglog_plot, run_variant, write_table)

PRODUCTION = os.path.join(ROOT, "parameters/cgs_roller/hertz_frictionless.prm")


def run_case(app, degree, level, enforcement, out_dir):
    case_dir = os.path.join(out_dir, "runs", f"q{degree}_level{level}_{enforcement_tag(enforcement)}")
    s, wall = run_variant(app, PRODUCTION, case_dir, {
        "Contact": contact_overrides(enforcement),
        "Mesh": {"Element degree": degree, "Number of contact refinements": level},
        "Load program/Stage 1": {"Number of steps": 1},
        "Run control": {"Measure contact cost": "true"}})
    return {
        "degree": degree,
        "contact_refinements": level,
        "enforcement": enforcement,
        "n_dofs": s["mesh"]["n_dofs"],
        "h_contact_mm": s["mesh"]["smallest_cell_in_contact_zone_mm"],
        "newton_iterations": s["newton"]["total_iterations"],
        "wall_time_s": round(wall, 4),
        "contact_solve_s": round(s["timing_s"]["contact_solve_s"], 4),
        "error_p0": s["ratios"]["peak_pressure"] - 1.0,
        "error_a": s["ratios"]["contact_half_width"] - 1.0,
        "l2_error_pressure": s["results"]["pressure_l2_relative_error"],
        "contact_cost_ratio": round(s["timing_s"]["contact_cost_ratio"], 3),
    }


def write_plots(out_dir, rows, degrees, enforcements):
    """Log-log error against wall time, one curve per degree x enforcement."""
    styles = {"lm": "lw 2 pt 7", "penalty": "lw 1.5 dt 2 pt 6"}
    for quantity, col, label in (
            ("p0", 2, "relative error of the peak pressure p0"),
            ("l2", 3, "relative L2 error of the pressure")):
        series = []
        for d in degrees:
            for e in enforcements:
                name = f"series_q{d}_{enforcement_tag(e)}.csv"
                with open(os.path.join(out_dir, name), "w") as f:
                    f.write("wall_time_s,abs_error_p0,l2_error_pressure\n")
                    for r in rows:
                        if r["degree"] == d and r["enforcement"] == e:
                            f.write(f"{r['wall_time_s']},{max(abs(r['error_p0']), 1e-6)},"
                                    f"{r['l2_error_pressure']}\n")
                style = styles["lm" if e == "lm" else "penalty"]
                series.append(f"'{name}' every ::1 using 1:{col} with linespoints {style} "
                              f"title \"Q{d}, {enforcement_label(e)}\"")
        loglog_plot(out_dir, f"error_{quantity}_vs_time",
                    "Benchmark 1 (Hertz): accuracy against wall time",
                    "wall time of the run [s]", label, series,
                    "set arrow from graph 0, first 0.01 to graph 1, first 0.01 nohead dt 3\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build-release"))
    parser.add_argument("--out", default=os.path.join(ROOT, "results/studies/cgs_roller_accuracy_time"))
    parser.add_argument("--quick", action="store_true", help="levels 5 to 7 only")
    parser.add_argument("--levels", type=int, nargs="+", default=[5, 6, 7, 8, 9])
    parser.add_argument("--degrees", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--enforcements", nargs="+", default=["lm", "penalty:1e5", "penalty:1e6"])
    args = parser.parse_args()
    if args.quick:
        args.levels = [l for l in args.levels if l <= 7]

    app = os.path.join(args.build, "cgs_roller/cgs_roller")
    if not os.access(app, os.X_OK):
        sys.exit(f"accuracy_time_study: no executable {app}; run scripts/build.sh Release first")
    # A discarded warm-up run, so that the first timed run does not pay for
    # cold file caches.
    run_case(app, args.degrees[0], args.levels[0], "lm", os.path.join(args.out, "warm_up"))
    start = time.time()
    rows = []
    total = len(args.degrees) * len(args.enforcements) * len(args.levels)
    for d in args.degrees:
        for e in args.enforcements:
            for l in args.levels:
                print(f"  [{time.time() - start:6.1f} s] run {len(rows) + 1} of {total}: "
                      f"Q{d}, level {l}, {enforcement_label(e)}", flush=True)
                rows.append(run_case(app, d, l, e, args.out))

    print("degree  level  enforcement            n_dofs  h[mm]   Newton  wall[s]  "
          "err p0     err a      L2 err p   cost")
    for r in rows:
        print(f"Q{r['degree']:<6d} {r['contact_refinements']:5d}  "
              f"{enforcement_label(r['enforcement']):22s} {r['n_dofs']:6d} "
              f"{r['h_contact_mm']:7.4f} {r['newton_iterations']:6d} {r['wall_time_s']:8.2f} "
              f"{r['error_p0']:+9.4%} {r['error_a']:+9.4%} {r['l2_error_pressure']:9.4%} "
              f"{r['contact_cost_ratio']:6.2f}")
    os.makedirs(args.out, exist_ok=True)
    table = os.path.join(args.out, "accuracy_time.csv")
    write_table(table, rows)
    write_plots(args.out, rows, args.degrees, args.enforcements)
    print(f"table: {table}")
    print(f"plots: {args.out}/error_p0_vs_time.png, {args.out}/error_l2_vs_time.png")
    print(f"study wall time: {time.time() - start:.1f} s")


if __name__ == "__main__":
    main()
