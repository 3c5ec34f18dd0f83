#!/usr/bin/env python3
"""Friction-coefficient sweep for benchmark 1 (cgs_roller, Coulomb friction).

Runs the production case parameters/cgs_roller/spence_mu01.prm for each
friction coefficient mu and compares the stick-zone ratio c/a with Spence's
relation beta/mu = K'(c/a)/K(c/a) for half-spaces under increasing load
(doc/references.md 1.3), as evaluated by the application itself
(summary.json, reference.stick_ratio_c_over_a).

Two loads are swept:
  full   the benchmark load, 35 kN/mm (a/R = 0.12): the finite cylinder and
         block are not half-spaces at this load;
  small  1/100 of it (a/R = 0.012) on a mesh scaled to the same a/h: the
         half-space limit of the same model, where the comparison with
         Spence isolates the discretisation and the exact normal-tangential
         coupling (which Spence's Goodman approximation neglects).
A run fails the sweep if it does not complete, or if it is a small-load run
(where Spence's half-space solution holds) with |c/a - Spence| > tolerance
(default 0.05). Full-load runs are shown beside Spence without a verdict
("finite body": the cylinder is no half-space at a/R = 0.12), and so are
the small-load runs of --quick ("quick mesh": its coarse contact mesh does
not resolve c/a to the tolerance). Load-step cutbacks are reported in the
table. The script exits non-zero if any run fails.

The table also gives c/a of the same half-space problem without the
Goodman approximation (boundary elements, summary.json
reference.coupled_stick_ratio_c_over_a), which the small-load runs should
approach. Writes friction_sweep.csv and stick_ratio_vs_mu.png (c/a against
mu with both half-space curves) to the output directory.

Usage: scripts/friction_sweep.py [--build DIR] [--out DIR] [--quick]
           [--mu 0.05 0.1 0.2 0.3 0.5 1.0] [--loads full small]
           [--level 8] [--steps 20] [--tolerance 0.05]
"""
import argparse
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PRODUCTION = os.path.join(ROOT, "parameters/cgs_roller/spence_mu01.prm")
# Values of the production file that the small-load runs scale.
FORCE = 35000.0          # N/mm
CONTACT_ZONE = 8.0       # mm
SEARCH_DISTANCE = 5.0    # mm


def run_case(app, mu, load, level, steps, out_dir):
    case_dir = os.path.join(out_dir, "runs", f"{load}_mu{mu:g}")
    os.makedirs(case_dir, exist_ok=True)
    # 1/100 of the load shrinks a by 10: the contact strip and the search
    # distance shrink with it, and three more halvings of the cells near
    # the contact keep a/h within 20 % of the full-load mesh.
    scale = 0.01 if load == "small" else 1.0
    length = math.sqrt(scale)
    extra = 3 if load == "small" else 0
    prm = os.path.join(case_dir, "case.prm")
    with open(prm, "w") as f:
        f.write(f"include {PRODUCTION}\n"
                "subsection Loading\n"
                f"  set Force per unit thickness = {FORCE * scale:g}\n"
                "end\n"
                "subsection Contact\n"
                f"  set Friction coefficient = {mu:g}\n"
                f"  set Search distance = {SEARCH_DISTANCE * length:g}\n"
                "end\n"
                "subsection Mesh\n"
                f"  set Number of contact refinements = {level + extra}\n"
                f"  set Contact zone length = {CONTACT_ZONE * length:g}\n"
                "end\n"
                "subsection Load program\n"
                "  subsection Stage 1\n"
                f"    set Number of steps = {steps}\n"
                "  end\n"
                "end\n"
                "subsection Output\n"
                f"  set Output directory = {case_dir}\n"
                "  set Write graphical output = false\n"
                "  set Write plots = false\n"
                "  set Verbosity = quiet\n"
                "end\n"
                "subsection Run control\n"
                "  set Measure contact cost = false\n"
                "end\n")
    start = time.time()
    summary = os.path.join(case_dir, "summary.json")
    if os.path.exists(summary):
        os.remove(summary)
    proc = subprocess.run([app, prm], stdout=subprocess.DEVNULL,
                          stderr=subprocess.PIPE, text=True)
    wall = time.time() - start
    row = {"load": load, "mu": mu, "completed": proc.returncode == 0,
           "wall_time_s": round(wall, 3)}
    if proc.returncode != 0 or not os.path.exists(summary):
        row["error"] = proc.stderr.strip().splitlines()[-1] if proc.stderr.strip() else "no summary"
        return row
    with open(summary) as f:
        s = json.load(f)
    row.update({
        "n_dofs": s["mesh"]["n_dofs"],
        "max_newton_per_step": s["newton"]["max_iterations_per_step"],
        "n_cutbacks": s["newton"]["n_cutbacks"],
        "c_over_a": s["results"]["stick_ratio_c_over_a"],
        "c_over_a_spence": s["reference"]["stick_ratio_c_over_a"],
        "c_over_a_coupled": s["reference"]["coupled_stick_ratio_c_over_a"],
        "peak_q_over_spence": s["ratios"]["peak_tangential_traction"],
        "p0_over_hertz": s["ratios"]["peak_pressure"],
        "a_over_hertz": s["ratios"]["contact_half_width"],
    })
    return row


def write_plot(out_dir, rows, loads):
    series = []
    for load in loads:
        name = f"series_{load}.csv"
        with open(os.path.join(out_dir, name), "w") as f:
            f.write("mu,c_over_a,c_over_a_spence,c_over_a_coupled\n")
            for r in rows:
                if r["load"] == load and r["completed"]:
                    f.write(f"{r['mu']},{r['c_over_a']},{r['c_over_a_spence']},"
                            f"{r['c_over_a_coupled']}\n")
        label = ("FE, full load (a/R = 0.12)" if load == "full"
                 else "FE, 1/100 load (a/R = 0.012)")
        series.append(f"'{name}' using 1:2 with linespoints lw 2 pt 7 title \"{label}\"")
    first = f"series_{loads[0]}.csv"
    series.insert(0, f"'{first}' using 1:3 with linespoints lw 2 dt 2 pt 6 "
                     "title \"Spence, half-spaces (K'/K = beta/mu)\"")
    series.insert(1, f"'{first}' using 1:4 with linespoints lw 2 dt 3 pt 4 "
                     "title \"half-spaces, exact coupling (boundary elements)\"")
    script = os.path.join(out_dir, "stick_ratio_vs_mu.gp")
    with open(script, "w") as f:
        f.write("set terminal pngcairo size 900,600 enhanced font 'Sans,11'\n"
                "set output 'stick_ratio_vs_mu.png'\n"
                "set datafile separator ','\n"
                "set logscale x\nset grid\nset key bottom right\n"
                "set yrange [0:1.05]\n"
                "set title \"Benchmark 1: stick zone under increasing load\"\n"
                "set xlabel \"friction coefficient mu\"\n"
                "set ylabel \"stick-zone ratio c/a\"\n"
                "plot " + ", \\\n     ".join(series) + "\n")
    if shutil.which("gnuplot"):
        subprocess.run(["gnuplot", os.path.basename(script)], cwd=out_dir, check=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build-release"))
    parser.add_argument("--out", default=os.path.join(ROOT, "results/studies/cgs_roller_friction_sweep"))
    parser.add_argument("--quick", action="store_true", help="level 6, 10 load steps")
    parser.add_argument("--mu", type=float, nargs="+", default=[0.05, 0.1, 0.2, 0.3, 0.5, 1.0])
    parser.add_argument("--loads", nargs="+", choices=["full", "small"], default=["full", "small"])
    parser.add_argument("--level", type=int, default=8, help="contact refinements at full load")
    parser.add_argument("--steps", type=int, default=20, help="load steps")
    parser.add_argument("--tolerance", type=float, default=0.05, help="on |c/a - Spence|")
    args = parser.parse_args()
    if args.quick:
        args.level, args.steps = 6, 10

    app = os.path.join(args.build, "cgs_roller/cgs_roller")
    if not os.access(app, os.X_OK):
        sys.exit(f"friction_sweep: no executable {app}; run scripts/build.sh Release first")
    os.makedirs(args.out, exist_ok=True)
    start = time.time()
    rows = []
    total = len(args.loads) * len(args.mu)
    for load in args.loads:
        for mu in args.mu:
            print(f"  [{time.time() - start:6.1f} s] run {len(rows) + 1} of {total}: "
                  f"{load} load, mu = {mu:g}", flush=True)
            rows.append(run_case(app, mu, load, args.level, args.steps, args.out))

    n_failed = 0
    print("load   mu     n_dofs  Newton max  cutbacks  c/a      Spence   diff     "
          "coupled  q/q_Sp   p0/p0_H  wall[s]  verdict")
    for r in rows:
        if not r["completed"]:
            n_failed += 1
            print(f"{r['load']:6s} {r['mu']:<6g} run failed: {r['error']}")
            continue
        diff = r["c_over_a"] - r["c_over_a_spence"]
        r["difference"] = diff
        if r["load"] != "small":
            r["verdict"] = "finite body"
        elif args.quick:
            r["verdict"] = "quick mesh"
        else:
            ok = abs(diff) <= args.tolerance
            r["verdict"] = "pass" if ok else "FAIL"
            n_failed += not ok
        print(f"{r['load']:6s} {r['mu']:<6g} {r['n_dofs']:6d} {r['max_newton_per_step']:10d} "
              f"{r['n_cutbacks']:9d}  {r['c_over_a']:.4f}   {r['c_over_a_spence']:.4f}   "
              f"{diff:+.4f}  {r['c_over_a_coupled']:.4f}   {r['peak_q_over_spence']:.4f}   "
              f"{r['p0_over_hertz']:.4f}   "
              f"{r['wall_time_s']:7.2f}  {r['verdict']}")

    table = os.path.join(args.out, "friction_sweep.csv")
    fields = ["load", "mu", "completed", "n_dofs", "max_newton_per_step", "n_cutbacks",
              "c_over_a", "c_over_a_spence", "difference", "c_over_a_coupled",
              "peak_q_over_spence",
              "p0_over_hertz", "a_over_hertz", "wall_time_s", "verdict", "error"]
    with open(table, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields)
        writer.writeheader()
        writer.writerows(rows)
    write_plot(args.out, rows, args.loads)
    print(f"table: {table}")
    print(f"plot: {os.path.join(args.out, 'stick_ratio_vs_mu.png')}")
    print(f"sweep wall time: {time.time() - start:.1f} s; "
          f"{len(rows) - n_failed} passed, {n_failed} failed (tolerance {args.tolerance})")
    sys.exit(1 if n_failed else 0)


if __name__ == "__main__":
    main()
