#!/usr/bin/env python3
"""Model choices of benchmark 5 (reynolds_roller): DX(A) after the full turn for each.

Each run is the production file (parameters/reynolds_roller/
reynolds_roller_mu03.prm: rigid roller, Q2-P1 75 x 5 cells, exactly
incompressible rubber, 4-degree steps) with one change: the rotation
increment (2 and 1 degrees), the rubber's incompressibility as a penalty
(nu = 0.499 and 0.49), the element (Q1 F-bar on cells of half the size, at
nu = 0.499, the same DoFs), and the elastic steel roller
(reynolds_roller_mu03_elastic.prm). The table gives DX(A), its difference
from the production run, the creep ratio, Newton iterations, cutbacks and
wall time; rolling_choices.csv and a plot of DX(A) against wall time.

The 3D extrusion is not run here: it is the plane-strain problem solved in
3D (u_z = 0 on both z faces) and reproduces the plane-strain run step by
step (test reynolds_roller/extrusion_3d), at some 22 times its cost.

With --quick every run is on 60 x 3 cells (Q1 F-bar on 120 x 6) and turns
a quarter turn, for the main job's quick mode; the differences are then
those of the quarter turn.

Usage: scripts/rolling_choices.py [--build DIR] [--out DIR] [--quick]
                                  [--time-limit SECONDS]
"""
import argparse
import os
import subprocess
import sys

from study_tools import (ROOT, TimeLimitExceeded, loglog_plot,
                         run_variant_measured, write_table)

PRODUCTION = os.path.join(ROOT, "parameters/reynolds_roller/reynolds_roller_mu03.prm")
ELASTIC = os.path.join(ROOT, "parameters/reynolds_roller/reynolds_roller_mu03_elastic.prm")
PRODUCTION_ROLLING_STEPS = 90


def choices(quick):
    """(name, description, production file, overrides) of every run."""
    mesh = {"Number of cells along the length": 60,
            "Number of cells through the thickness": 3} if quick else {}
    fine = ({"Number of cells along the length": 120,
             "Number of cells through the thickness": 6} if quick else
            {"Number of cells along the length": 150,
             "Number of cells through the thickness": 10})
    turn = 90 if quick else 360
    steps = PRODUCTION_ROLLING_STEPS * turn // 360

    def stage(factor):
        return {"Load program/Stage 3": {"Number of steps": steps * factor,
                                         "Roller angle": turn}}

    def with_mesh(overrides, cells=None):
        result = dict(overrides)
        cells = mesh if cells is None else cells
        if cells:
            result["Mesh"] = {**result.get("Mesh", {}), **cells}
        return result

    return [
        ("production", "rigid roller, Q2-P1, nu = 0.5 exactly, 4-degree steps",
         PRODUCTION, with_mesh(stage(1))),
        ("steps_2deg", "2-degree steps", PRODUCTION, with_mesh(stage(2))),
        ("steps_1deg", "1-degree steps", PRODUCTION, with_mesh(stage(4))),
        ("penalty_0499", "penalty nu = 0.499 (Q2-P1)", PRODUCTION,
         with_mesh({**stage(1), "Rubber material": {"Poisson's ratio": 0.499}})),
        ("penalty_049", "penalty nu = 0.49 (Q2-P1)", PRODUCTION,
         with_mesh({**stage(1), "Rubber material": {"Poisson's ratio": 0.49}})),
        ("q1_fbar_0499", "Q1 F-bar, cells of half the size, nu = 0.499",
         PRODUCTION,
         with_mesh({**stage(1), "Rubber material": {"Poisson's ratio": 0.499},
                    "Solid": {"Element technology": "F-bar"},
                    "Mesh": {"Element degree": 1}}, fine)),
        ("elastic_roller", "elastic steel roller (Q2 ring, 48 x 2 cells)",
         ELASTIC, with_mesh(stage(1))),
    ]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build-release"))
    parser.add_argument("--out", default=os.path.join(ROOT, "results/studies/reynolds_roller"))
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--time-limit", type=float, default=1800.)
    args = parser.parse_args()
    app = os.path.join(args.build, "reynolds_roller", "reynolds_roller")
    os.makedirs(args.out, exist_ok=True)

    rows = []
    for name, description, production, overrides in choices(args.quick):
        row = {"choice": name, "description": description}
        try:
            summary, wall, _ = run_variant_measured(
                app, production, os.path.join(args.out, "runs", name),
                overrides, time_limit=args.time_limit)
            results, newton = summary["results"], summary["newton"]
            row.update(status="completed",
                       dx_A_mm=results["dx_A_mm"],
                       creep_ratio=results["creep_ratio"],
                       newton_iterations=newton["total_iterations"],
                       max_newton_per_step=newton["max_iterations_per_step"],
                       n_cutbacks=newton["n_cutbacks"],
                       wall_time_s=round(wall, 2))
        except TimeLimitExceeded:
            row["status"] = f"stopped after {args.time_limit:.0f} s"
        except subprocess.CalledProcessError as error:
            row["status"] = f"failed (exit {error.returncode})"
        rows.append(row)
        print(", ".join(f"{k} {v}" for k, v in row.items()), flush=True)

    reference = next((r for r in rows if r["choice"] == "production"
                      and r["status"] == "completed"), None)
    for row in rows:
        if reference is not None and row["status"] == "completed":
            row["difference_mm"] = row["dx_A_mm"] - reference["dx_A_mm"]
    columns = ["choice", "description", "status", "dx_A_mm", "difference_mm",
               "creep_ratio", "newton_iterations", "max_newton_per_step",
               "n_cutbacks", "wall_time_s"]
    write_table(os.path.join(args.out, "rolling_choices.csv"),
                [{c: r.get(c, "") for c in columns} for r in rows])
    completed = [r for r in rows if r["status"] == "completed"]
    if completed:
        with open(os.path.join(args.out, "rolling_choices_points.csv"), "w") as f:
            f.write("wall_time_s,dx_A_mm,choice\n")
            for r in completed:
                f.write(f"{r['wall_time_s']},{r['dx_A_mm']},{r['choice']}\n")
        loglog_plot(args.out, "rolling_choices",
                    "Benchmark 5: DX(A) of each model choice against wall time",
                    "wall time [s]", "DX(A) [mm]",
                    ["'rolling_choices_points.csv' using 1:2:3 with labels "
                     "point pt 7 offset 0.5,0.5 notitle"], logscale="x")
    sys.exit(0 if len(completed) == len(rows) else 1)


if __name__ == "__main__":
    main()
