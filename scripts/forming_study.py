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

With --bending-stroke D the runs stop at a punch displacement D small
enough for the strip to stay elastic (0.5 mm: the largest bending stress
is 72 MPa against the yield stress 194 MPa), and the punch force is
compared with the three-point bending force of a Timoshenko beam
(three_point_bending_force()): a check of the element's bending stiffness
that needs no reference solution. Writes bending_study.csv; with
--max-bending-error the exit code is 1 when a run fails or misses the
theory by more than that relative error.

Usage: scripts/forming_study.py [--build DIR | --app PATH] [--out DIR]
           [--mus 01342 0] [--meshes 2x30 2x60 4x120 8x120 4x240]
           [--degrees 1 2] [--step-factors 1] [--time-limit SECONDS]
           [--bending-stroke MM [--max-bending-error RELATIVE]]
"""
import argparse
import math
import os
import re
import subprocess
import sys

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


def prm_value(path, key):
    """The value of the first "set key = value" line of a parameter file, as
    a float (comments stripped)."""
    with open(path) as f:
        for line in f:
            match = re.match(rf"\s*set\s+{re.escape(key)}\s*=\s*([^#]+)", line)
            if match:
                return float(match.group(1))
    raise KeyError(f"{path}: no entry '{key}'")


def three_point_bending_force(stroke, production):
    """Punch force (N, full strip) that bends the flat strip of a production
    file elastically by a punch displacement stroke (mm): a simply
    supported Timoshenko beam in plane strain (E' = E/(1 - nu^2), shear
    modulus E/(2(1 + nu)), shear factor 5/6) of the strip's width and
    thickness, loaded at its centre, whose supports lie where the strip's
    bottom touches the die's shoulder fillets: at x = R2 + R3 - R3 sin(phi)
    on each side, with phi the beam's slope there (solved by fixed-point
    iteration). Neglected: the friction at the supports and the local
    indentation under the punch and on the fillets (together well below
    0.5 % at a stroke of 0.5 mm)."""
    E = prm_value(production, "Young's modulus")
    nu = prm_value(production, "Poisson's ratio")
    t = prm_value(production, "Sheet thickness")
    b = prm_value(production, "Sheet width")
    R2 = prm_value(production, "Die radius")
    R3 = prm_value(production, "Die shoulder radius")
    E_plane = E / (1. - nu ** 2)
    G = E / (2. * (1. + nu))
    I, A = b * t ** 3 / 12., b * t
    span = 2. * (R2 + R3)
    for _ in range(100):
        force = stroke / (span ** 3 / (48. * E_plane * I)
                          + span / (4. * 5. / 6. * G * A))
        slope = force * span ** 2 / (16. * E_plane * I)
        span = 2. * (R2 + R3 - R3 * math.sin(slope))
    return force


def run_bending(app, mu, degree, mesh, stroke, out_dir, time_limit):
    """One elastic run to the punch displacement stroke (two forming steps,
    two held steps in the production file's later stages, no release) on mesh "TxL" at a degree; its punch force
    against three_point_bending_force()."""
    thickness, length = (int(n) for n in mesh.split("x"))
    production = os.path.join(ROOT, f"parameters/sheet_forming/sheet_forming_mu{mu}.prm")
    name = f"bending_mu{mu}_q{degree}_{mesh}"
    overrides = {
        "Solid": {"Element technology": "F-bar" if degree == 1 else "displacement"},
        "Mesh": {"Element degree": degree,
                 "Number of cells through the thickness": thickness,
                 "Number of cells along the length": length},
        "Load program/Stage 1": {"Number of steps": 2,
                                 "Punch displacement": stroke},
        "Load program/Stage 2": {"Number of steps": 1,
                                 "Punch displacement": stroke,
                                 "Die displacement": 0},
        "Load program/Stage 3": {"Number of steps": 1,
                                 "Punch displacement": stroke,
                                 "Die displacement": 0},
        "Release": {"Release stage": 0},
    }
    theory = three_point_bending_force(stroke, production)
    row = {"mu": "0.1342" if mu == "01342" else "0", "degree": degree,
           "mesh": mesh, "cells_through_thickness": thickness,
           "cells_along_length": length, "stroke_mm": stroke,
           "theory_force_N": theory}
    try:
        s, wall, _ = run_variant_measured(app, production,
                                          os.path.join(out_dir, "runs", name),
                                          overrides, time_limit=time_limit)
    except (subprocess.CalledProcessError, TimeLimitExceeded) as error:
        row["status"] = "failed" if isinstance(
            error, subprocess.CalledProcessError) else "time limit"
        return row
    force = s["results"]["punch_force_at_full_stroke_N"]
    row.update({"status": "completed", "n_dofs": s["mesh"]["n_dofs"],
                "wall_time_s": round(wall, 2), "force_N": force,
                "relative_error": force / theory - 1.})
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
    parser.add_argument("--app", help="the sheet_forming executable "
                        "(default: BUILD/sheet_forming/sheet_forming)")
    parser.add_argument("--bending-stroke", type=float,
                        help="elastic bending check at this punch "
                        "displacement (mm) instead of the full program")
    parser.add_argument("--max-bending-error", type=float,
                        help="with --bending-stroke: largest accepted "
                        "relative error of the punch force")
    args = parser.parse_args()
    app = args.app or os.path.join(args.build, "sheet_forming", "sheet_forming")
    os.makedirs(args.out, exist_ok=True)

    if args.bending_stroke is not None:
        rows = [run_bending(app, mu, degree, mesh, args.bending_stroke,
                            args.out, args.time_limit)
                for mu in args.mus for degree in args.degrees
                for mesh in args.meshes]
        write_table(os.path.join(args.out, "bending_study.csv"), rows)
        failed = False
        for row in rows:
            if row["status"] != "completed":
                print(f"mu = {row['mu']}, Q{row['degree']}, {row['mesh']}: "
                      f"{row['status']}")
                failed = True
                continue
            within = (args.max_bending_error is None
                      or abs(row["relative_error"]) <= args.max_bending_error)
            failed = failed or not within
            print(f"mu = {row['mu']}, Q{row['degree']}, {row['mesh']}: punch "
                  f"force {row['force_N']:.4f} N, beam {row['theory_force_N']:.4f}"
                  f" N, error {100 * row['relative_error']:+.2f} %, "
                  f"{row['wall_time_s']} s"
                  + ("" if args.max_bending_error is None else
                     f" ({'ok' if within else 'FAILED'}: limit "
                     f"{100 * args.max_bending_error:.2f} %)"), flush=True)
        sys.exit(1 if failed else 0)

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
