#!/usr/bin/env python3
"""Linear solvers compared on one case: time, memory and answer.

Runs one production parameter file (by default the 3D quarter model of
benchmark 2, parameters/punch3d/punch_3d_quarter_mu0.prm, 160 000 DoFs)
with each linear solver of the 'Linear solver' subsection: MUMPS with a
new factorisation per Newton iteration, MUMPS with reused factors, and
the Krylov solvers with smoothed-aggregation multigrid on the rigid-body
modes ('cg amg' for frictionless cases, 'gmres amg' also with friction).
For each run it records the Newton iterations, the linear-solve and total
wall times, the peak resident memory, and the results (u_z on the axis,
the centre pressure, the contact radius), with their relative difference
from the first solver's. Writes linear_solver_study.csv. With --ranks N
the runs use N MPI ranks (mpirun), and the memory is the largest rank's.
With --levels, each solver runs at each of these numbers of contact
refinements, so that the table shows how time and memory grow with the
DoFs; a run past --time-limit seconds is stopped and listed as such.
For benchmark 4: --app loaded_pin --prm parameters/loaded_pin/
loaded_pin_mu01.prm --solvers "mumps reuse" "gmres amg" --levels 1 2 3
(level 3 is the finest Q2 mesh of the mesh study).

Usage: scripts/linear_solver_study.py [--build DIR] [--out DIR]
           [--prm FILE] [--app punch3d|cgs_roller|loaded_pin] [--ranks N]
           [--solvers "mumps" "mumps reuse" "cg amg" "gmres amg"]
           [--mesh "Number of contact refinements=1" ...]
           [--levels 1 2 3] [--time-limit SECONDS]
"""
import argparse
import os

from study_tools import ROOT, TimeLimitExceeded, run_variant_measured, write_table

RESULT_KEYS = {
    "punch3d": ["foundation_top_axis_uz_mm", "pressure_at_centre_MPa",
                "contact_radius_mm"],
    "cgs_roller": ["peak_pressure_MPa", "contact_half_width_mm",
                   "peak_tangential_traction_MPa"],
    # Nested keys of summary.json "results" are joined by dots.
    "loaded_pin": ["mid_plane.arc_end_theta_deg", "mid_plane.peak_pressure_MPa",
                   "pin_centre_ux_mm"],
}


def result(summary, key):
    """The value of a (dotted) key of summary.json's results block."""
    value = summary["results"]
    for part in key.split("."):
        value = value[part]
    return value


def solver_overrides(solver):
    """The 'Linear solver' entries selecting one solver label."""
    if solver == "mumps reuse":
        return {"Solver type": "mumps", "Reuse factorisation": "true"}
    return {"Solver type": solver, "Reuse factorisation": "false"}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build-release"))
    parser.add_argument("--out", default=os.path.join(ROOT, "results/studies/linear_solvers"))
    parser.add_argument("--prm", default=os.path.join(
        ROOT, "parameters/punch3d/punch_3d_quarter_mu0.prm"))
    parser.add_argument("--app", default="punch3d", choices=sorted(RESULT_KEYS))
    parser.add_argument("--solvers", nargs="+",
                        default=["mumps", "mumps reuse", "cg amg"])
    parser.add_argument("--ranks", type=int, default=1,
                        help="MPI ranks (mpirun -np)")
    parser.add_argument("--mesh", nargs="*", default=[],
                        help="'Mesh' entries to override, as 'name=value'")
    parser.add_argument("--levels", type=int, nargs="*", default=[],
                        help="numbers of contact refinements to run each solver at")
    parser.add_argument("--time-limit", type=float, default=None,
                        help="seconds after which a run is stopped")
    args = parser.parse_args()

    app = os.path.join(args.build, args.app, args.app)
    prm = os.path.abspath(args.prm)
    mesh = dict(entry.split("=", 1) for entry in args.mesh)
    os.makedirs(args.out, exist_ok=True)
    rows = []
    first = {}
    launcher = ("mpirun", "-np", str(args.ranks)) if args.ranks > 1 else ()
    for level, solver in [(level, solver) for level in (args.levels or [None])
                          for solver in args.solvers]:
        tag = solver.replace(" ", "_") + ("" if level is None else f"_level{level}")
        case_dir = os.path.join(args.out, "runs", tag)
        overrides = {"Linear solver": solver_overrides(solver)}
        level_mesh = dict(mesh)
        if level is not None:
            level_mesh["Number of contact refinements"] = level
        if level_mesh:
            overrides["Mesh"] = level_mesh
        try:
            summary, wall, memory = run_variant_measured(
                app, prm, case_dir, overrides, launcher, args.time_limit)
        except TimeLimitExceeded:
            row = {"solver": solver, "mpi_ranks": args.ranks, "level": level,
                   "n_dofs": "", "newton_iterations": "",
                   "linear_solve_s": "", "wall_time_s": f"> {args.time_limit:g}",
                   "peak_memory_MB": ""}
            rows.append(row)
            print(", ".join(f"{k} {v}" for k, v in row.items()), flush=True)
            continue
        row = {"solver": solver, "mpi_ranks": args.ranks, "level": level,
               "n_dofs": summary["mesh"]["n_dofs"],
               "newton_iterations": summary["newton"]["total_iterations"],
               "linear_solve_s": round(summary["timing_s"]["linear_solve_s"], 2),
               "wall_time_s": round(wall, 2),
               "peak_memory_MB": round(memory, 1)}
        for key in RESULT_KEYS[args.app]:
            row[key] = result(summary, key)
        # Differences from the first solver's run on the same mesh.
        reference = first.setdefault(level, row)
        for key in RESULT_KEYS[args.app]:
            row[f"{key}_difference"] = "%.2e" % (row[key] / reference[key] - 1.)
        rows.append(row)
        print(", ".join(f"{k} {v}" for k, v in row.items()), flush=True)
    write_table(os.path.join(args.out, "linear_solver_study.csv"), rows)


if __name__ == "__main__":
    main()
