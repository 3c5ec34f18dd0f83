#!/usr/bin/env python3
"""Cook's membrane study: locking of the finite-strain elements, tip displacement against mesh and time.

Runs the Release build of tests/common/finite_strain_solid_04 (nearly
incompressible Cook's membrane, plane strain, split neo-Hookean law with
nu = 0.4999, 100 N shear load in 10 steps) for the plain Q1, the F-bar Q1
and the mixed Q2-P1 elements on N x N meshes up to --finest (Q2: half of
it), and writes cook_membrane.csv (element, N, DoFs, tip u_y, Newton
iterations, wall time, difference from the finest Q2-P1 tip) and the plots
tip_vs_dofs.png and tip_vs_time.png. Plain Q1 stays far below the others
(volumetric locking); F-bar Q1 and Q2-P1 converge to the same tip.
"""
import argparse
import os
import subprocess
import tempfile

from study_tools import ROOT, loglog_plot, write_table

ELEMENTS = ["Q1", "Q1 F-bar", "Q2-P1"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build-release"))
    parser.add_argument("--out", default=os.path.join(ROOT, "results/studies/cook_membrane"))
    parser.add_argument("--finest", type=int, default=64,
                        help="finest Q1 mesh N (a power of 2); Q2 goes to N/2")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)

    target = "common.finite_strain_solid_04.release"
    subprocess.run(["make", target], cwd=args.build, check=True,
                   stdout=subprocess.DEVNULL)
    name = "finite_strain_solid_04.release"
    binary = os.path.join(args.build, "tests", "common", name, name)
    env = dict(os.environ, COOK_FINEST=str(args.finest))
    with tempfile.TemporaryDirectory() as work:
        run = subprocess.run([binary], cwd=work, env=env, check=True,
                             capture_output=True, text=True)

    rows = []
    for line in run.stdout.splitlines():
        if not line.startswith("cook,"):
            continue
        _, element, n, dofs, tip, iterations, wall = line.split(",")
        rows.append({"element": element, "n": int(n), "dofs": int(dofs),
                     "tip_uy_mm": float(tip), "newton_iterations": int(iterations),
                     "wall_s": float(wall)})
    reference = max((r for r in rows if r["element"] == "Q2-P1"),
                    key=lambda r: r["n"])["tip_uy_mm"]
    for r in rows:
        r["relative_difference_from_finest_q2"] = abs(r["tip_uy_mm"] - reference) / reference
        print(f"{r['element']:9s} {r['n']:3d} x {r['n']:<3d} {r['dofs']:7d} DoFs: "
              f"tip {r['tip_uy_mm']:.5f} mm, difference {r['relative_difference_from_finest_q2']:.2e}, "
              f"Newton {r['newton_iterations']}, {r['wall_s']:.2f} s", flush=True)

    for element in ELEMENTS:
        write_table(os.path.join(args.out, element.replace(" ", "_").replace("-", "_") + ".csv"),
                    [r for r in rows if r["element"] == element])
    write_table(os.path.join(args.out, "cook_membrane.csv"), rows)

    def series(x):
        return [f"'{e.replace(' ', '_').replace('-', '_')}.csv' using {x}:4 "
                f"with linespoints lw 2 title '{e}'" for e in ELEMENTS]

    loglog_plot(args.out, "tip_vs_dofs",
                "Cook's membrane, nu = 0.4999: tip displacement", "DoFs",
                "tip u_y (mm)", series(3), logscale="x")
    loglog_plot(args.out, "tip_vs_time",
                "Cook's membrane, nu = 0.4999: tip displacement against wall time",
                "wall time (s)", "tip u_y (mm)", series(6), logscale="x")


if __name__ == "__main__":
    main()
