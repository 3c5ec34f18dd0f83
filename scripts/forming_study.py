#!/usr/bin/env python3
"""Mesh and load-step study for benchmark 3 (sheet_forming, plane strain).

Runs parameters/sheet_forming/sheet_forming_mu<mu>.prm on meshes given as
THICKNESSxLENGTH (cells through the thickness x cells along the half
length), for element degree Q1 (F-bar) and Q2 (displacement), and with the
forming stage split into a multiple of its production steps (--step-factors;
1 is the production file's 57 steps). For each run it records DoFs, Newton
iterations, cutbacks and wall time, the forming angle and the angle after
release (flange chord s = 50..60 and end tangent), the peak punch force and
the force at full stroke, and the largest force-balance error. A run that
fails is recorded with its status ("failed") and no figures.

The reference of each series is its last (finest) run: the change of each
figure between the two last runs of a series is its error estimate, and the
issue's convergence test (angles within 0.3 deg, peak force within 1 %) is
printed for it. Writes forming_study.csv and plots of the angles and the
peak force against wall time.

Usage: scripts/forming_study.py [--build DIR] [--out DIR] [--mus 01342 0]
           [--meshes 2x30 2x60 4x120 8x120 4x240] [--degrees 1 2]
           [--step-factors 1] [--time-limit SECONDS]
"""
import argparse
import os
import subprocess

from study_tools import (ROOT, TimeLimitExceeded, loglog_plot,
                         run_variant_measured, write_table)

FIGURES = [
    # key in the row, label, unit, absolute (True) or relative change
    ("forming_angle_deg", "forming angle", "deg", True),
    ("angle_after_release_deg", "angle after release", "deg", True),
    ("peak_punch_force_N", "peak punch force", "N", False),
    ("punch_force_at_full_stroke_N", "punch force at full stroke", "N", False),
]
PRODUCTION_FORMING_STEPS = 57


def run_case(app, mu, degree, mesh, step_factor, out_dir, time_limit):
    """One run of the production file of mu on mesh "TxL" at a degree and
    with step_factor times the production forming steps."""
    thickness, length = (int(n) for n in mesh.split("x"))
    production = os.path.join(ROOT, f"parameters/sheet_forming/sheet_forming_mu{mu}.prm")
    name = f"mu{mu}_q{degree}_{mesh}_steps{step_factor}"
    case_dir = os.path.join(out_dir, "runs", name)
    overrides = {
        "Solid": {"Element technology": "F-bar" if degree == 1 else "displacement"},
        "Mesh": {"Element degree": degree,
                 "Number of cells through the thickness": thickness,
                 "Number of cells along the length": length},
        "Load program/Stage 1": {
            "Number of steps": PRODUCTION_FORMING_STEPS * step_factor},
    }
    row = {"mu": "0.1342" if mu == "01342" else "0", "degree": degree,
           "mesh": mesh, "cells_through_thickness": thickness,
           "cells_along_length": length, "forming_steps":
           PRODUCTION_FORMING_STEPS * step_factor}
    try:
        s, wall, _ = run_variant_measured(app, production, case_dir, overrides,
                                          time_limit=time_limit)
    except (subprocess.CalledProcessError, TimeLimitExceeded) as error:
        row["status"] = "failed" if isinstance(
            error, subprocess.CalledProcessError) else "time limit"
        return row
    r = s["results"]
    row.update({
        "status": "completed",
        "n_dofs": s["mesh"]["n_dofs"],
        "newton_iterations": s["newton"]["total_iterations"],
        "max_newton_per_step": s["newton"]["max_iterations_per_step"],
        "n_cutbacks": s["newton"]["n_cutbacks"],
        "wall_time_s": round(wall, 2),
        "forming_angle_deg": r["forming_angle_deg"],
        "forming_angle_end_tangent_deg": r["forming_angle_end_tangent_deg"],
        "angle_after_release_deg": r["angle_after_release_deg"],
        "angle_after_release_end_tangent_deg":
            r["angle_after_release_end_tangent_deg"],
        "springback_deg": r["springback_deg"],
        "peak_punch_force_N": r["peak_punch_force_N"],
        "punch_force_at_full_stroke_N": r["punch_force_at_full_stroke_N"],
        "max_force_balance_relative_error":
            r["max_force_balance_relative_error"],
    })
    return row


def print_change(title, coarse, fine):
    """The change of each figure from coarse to fine (the error estimate of
    fine) and the convergence test of the issue."""
    changes = []
    for key, label, unit, absolute in FIGURES:
        change = (f"{fine[key] - coarse[key]:+.3f} {unit}" if absolute else
                  f"{100 * (fine[key] / coarse[key] - 1):+.2f} %")
        changes.append(f"{label} {coarse[key]:.3f} -> {fine[key]:.3f} {unit} "
                       f"({change})")
    converged = (abs(fine["forming_angle_deg"] - coarse["forming_angle_deg"]) <= 0.3
                 and abs(fine["angle_after_release_deg"]
                         - coarse["angle_after_release_deg"]) <= 0.3
                 and abs(fine["peak_punch_force_N"] / coarse["peak_punch_force_N"]
                         - 1) <= 0.01)
    print(f"{title}: " + ", ".join(changes)
          + f"; converged (0.3 deg, 1 %): {'yes' if converged else 'no'}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build-release"))
    parser.add_argument("--out", default=os.path.join(ROOT, "results/studies/sheet_forming"))
    parser.add_argument("--mus", nargs="+", default=["01342"])
    parser.add_argument("--meshes", nargs="+",
                        default=["2x30", "2x60", "4x120", "8x120", "4x240"])
    parser.add_argument("--degrees", type=int, nargs="+", default=[1])
    parser.add_argument("--step-factors", type=int, nargs="+", default=[1])
    parser.add_argument("--time-limit", type=float, default=3600.)
    args = parser.parse_args()
    app = os.path.join(args.build, "sheet_forming", "sheet_forming")
    os.makedirs(args.out, exist_ok=True)

    rows = []
    for mu in args.mus:
        for degree in args.degrees:
            for factor in args.step_factors:
                for mesh in args.meshes:
                    row = run_case(app, mu, degree, mesh, factor, args.out,
                                   args.time_limit)
                    rows.append(row)
                    print(", ".join(f"{k} {v}" for k, v in row.items()), flush=True)
    write_table(os.path.join(args.out, "forming_study.csv"), rows)

    # Error estimates: the change between the two last completed runs of
    # each series (mu, degree, step factor), in the order of --meshes.
    for mu in args.mus:
        mu_label = "0.1342" if mu == "01342" else "0"
        for degree in args.degrees:
            for factor in args.step_factors:
                series = [r for r in rows if r["mu"] == mu_label
                          and r["degree"] == degree
                          and r["forming_steps"] == PRODUCTION_FORMING_STEPS * factor
                          and r["status"] == "completed"]
                if len(series) >= 2:
                    print_change(f"mu = {mu_label}, Q{degree}, "
                                 f"{PRODUCTION_FORMING_STEPS * factor} forming steps, "
                                 f"{series[-2]['mesh']} -> {series[-1]['mesh']}",
                                 series[-2], series[-1])

    # Figures against wall time, one file per series.
    plots = []
    for mu in args.mus:
        mu_label = "0.1342" if mu == "01342" else "0"
        for degree in args.degrees:
            series = [r for r in rows if r["mu"] == mu_label
                      and r["degree"] == degree and r["status"] == "completed"]
            if not series:
                continue
            name = f"mu{mu}_q{degree}.csv"
            write_table(os.path.join(args.out, name), series)
            plots.append((name, f"mu = {mu_label}, Q{degree}"))
    if not plots:
        return
    for key, label, unit, _ in FIGURES:
        # Column numbers of key and of the wall time in each series file.
        clauses = []
        for name, title in plots:
            with open(os.path.join(args.out, name)) as f:
                header = f.readline().strip().split(",")
            clauses.append(f"'{name}' using {header.index('wall_time_s') + 1}:"
                           f"{header.index(key) + 1} with linespoints title '{title}'")
        loglog_plot(args.out, f"forming_{key}", f"Benchmark 3: {label}",
                    "wall time [s]", f"{label} [{unit}]", clauses, logscale="x")


if __name__ == "__main__":
    main()
