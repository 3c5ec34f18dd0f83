#!/usr/bin/env python3
"""Requirement: the exact properties of benchmark 4 hold for the discrete
model (doc/references.md 4, Dundurs and Stippes). With zero clearance the
contact is receding: the contact arc and the stick/slip partition do not
depend on the load, and pressure, traction and relative displacement scale
with it. Runs the coarse Q1 quarter model at 100 kN and at 10 kN, for
mu = 0 (one step) and mu = 0.1 (five proportional steps), and checks:
  (a) the x resultant of the contact tractions equals the applied force to
      1e-8 (relative), in every run;
  (b) the contact arc end and the stick zone end agree to 1e-6 degrees, the
      status of every node agrees, and p/F, q/F and s/F agree at every node
      to 1e-6 of the largest p/F (for p and q) or s/F (for s), the Newton
      tolerance of the runs;
  (c) the solution is continuous in the clearance: a clearance of 1e-6 mm
      (2e-8 of the hole radius), mu = 0, 100 kN, leaves the status of
      every node as at zero clearance, moves the pin centre by less than 3
      times the clearance (rigid travel across it and a slightly shorter
      arc: 1.5 times, measured) and changes the pressure at every node by
      less than 1e-4 of the largest (9e-6 measured; the clearance is
      2.5e-6 of the pin's travel). A clearance that left faces at
      the symmetry plane uncovered unpaired their nodes and moved the pin
      centre by a third.
Usage: exact_checks.py <loaded_pin executable> <source dir> <work dir>
"""
import csv
import json
import os
import subprocess
import sys

app, source, work = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
production = os.path.join(source, "parameters", "loaded_pin")
failures = []


def run(mu, force, clearance=None):
    name = "mu%s_%dkN" % (mu, force // 1000)
    if clearance is not None:
        name += "_clearance_%g" % clearance
    directory = os.path.join(work, name)
    prm = os.path.join(work, name + ".prm")
    with open(prm, "w") as f:
        f.write("include %s/loaded_pin_mu%s.prm\n" % (production, mu))
        f.write("subsection Loading\n  set Total force = %d\nend\n" % force)
        if clearance is not None:
            f.write("subsection Geometry\n  set Clearance = %.17g\nend\n"
                    % clearance)
        f.write("subsection Mesh\n  set Element degree = 1\n"
                "  set Number of contact refinements = 1\nend\n")
        f.write("subsection Output\n  set Output directory = %s\n"
                "  set Write graphical output = false\n"
                "  set Write plots = false\nend\n" % directory)
    subprocess.run([app, prm], check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(directory, "summary.json")) as f:
        summary = json.load(f)
    lines = {}
    for line in ("contact_profile.csv", "contact_profile_sheet_face.csv"):
        with open(os.path.join(directory, line)) as f:
            lines[line] = list(csv.DictReader(f))
    return summary, lines


def check(condition, text):
    print(("PASS " if condition else "FAIL ") + text)
    if not condition:
        failures.append(text)


for mu in ("0", "01"):
    runs = {force: run(mu, force) for force in (100000, 10000)}
    for force, (summary, _) in runs.items():
        error = summary["results"]["force_balance_relative_error"]
        check(error <= 1e-8,
              "mu%s, %d N: resultant = applied force, relative error %.2e"
              % (mu, force, error))
    (big, big_lines), (small, small_lines) = runs[100000], runs[10000]
    for line in ("mid_plane", "sheet_face"):
        for key in ("arc_end_theta_deg", "stick_end_theta_deg"):
            if key in big["results"][line]:
                a, b = big["results"][line][key], small["results"][line][key]
                check(abs(a - b) <= 1e-6,
                      "mu%s, %s: %s %.6f deg at 100 kN, %.6f at 10 kN"
                      % (mu, line, key, a, b))
    for line in big_lines:
        rows_a, rows_b = big_lines[line], small_lines[line]
        check(len(rows_a) == len(rows_b) and
              all(a["status"] == b["status"] for a, b in zip(rows_a, rows_b)),
              "mu%s, %s: same node status at both loads" % (mu, line))
        # Tractions on the scale of the peak pressure (without friction q
        # is round-off), displacements on their own.
        peak = {}
        for column in ("pressure", "q_theta", "slip_theta"):
            a = [float(r[column]) / 100000. for r in rows_a]
            b = [float(r[column]) / 10000. for r in rows_b]
            peak[column] = max(abs(v) for v in a)
            scale = peak["pressure" if column == "q_theta" else column]
            difference = max(abs(x - y) for x, y in zip(a, b)) / scale
            check(difference <= 1e-6,
                  "mu%s, %s: %s/F differs by %.2e of the peak %s/F"
                  % (mu, line, column, difference,
                     "pressure" if column == "q_theta" else column))

    if mu == "0":
        clearance = 1e-6
        (gap, gap_lines) = run(mu, 100000, clearance)
        shift = (gap["results"]["pin_centre_ux_mm"]
                 - big["results"]["pin_centre_ux_mm"])
        check(0. <= shift <= 3. * clearance,
              "mu0, clearance %g mm: pin centre moves by %.3g mm"
              % (clearance, shift))
        for line in big_lines:
            rows_a, rows_b = big_lines[line], gap_lines[line]
            check(len(rows_a) == len(rows_b) and
                  all(a["status"] == b["status"] for a, b in zip(rows_a, rows_b)),
                  "mu0, clearance %g mm, %s: node status as at zero clearance"
                  % (clearance, line))
            a = [float(r["pressure"]) for r in rows_a]
            b = [float(r["pressure"]) for r in rows_b]
            difference = (max(abs(x - y) for x, y in zip(a, b))
                          / max(abs(v) for v in a))
            check(difference <= 1e-4,
                  "mu0, clearance %g mm, %s: pressure differs by %.2e of the peak"
                  % (clearance, line, difference))

print("FAIL: %d checks" % len(failures) if failures else "PASS")
sys.exit(1 if failures else 0)
