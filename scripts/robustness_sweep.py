#!/usr/bin/env python3
"""Robustness sweep: the neighbourhood of every application's production case.

For each application, runs a table of variations of its production file
(with the entries of its coarse test case set in it, as scripts/fuzz_prm.py
does: table fuzz_prm.APPS) and classifies each run:

  converged  exit 0, results/summary.json with finite values only, no NaN or
             inf in any CSV file, and the force balance of summary.json
             (results/force_balance_relative_error, or
             results/max_force_balance_relative_error) at most 1e-6; the
             Newton iterations (total, most per step, and most per step
             with cutbacks counted: a step's accepted attempt and the failed
             attempts cut back before it) and the cutbacks are listed, and a
             step of more than 15 iterations, cutbacks counted, is marked;
             beside them the most linear solves in a step ('solves': its
             Newton iterations with cutbacks and the further solves of
             active-set iterations on a linearisation, 'Active-set solves
             in the first iteration' and 'in later iterations'), the
             stabilized solves (springs to the last state, in steps with
             no equilibrium near it: total, and most in a step) and the
             most Newton iterations of one solve, plain or stabilized;
  unstable, stabilized
             converged as above, with the stabilized path in some step,
             and the same variation without the springs (Nonlinear
             solver/Stabilization factor = 0, run in the case directory
             + '-unstabilized') fails cleanly at the minimum increment: no
             sequence of equilibria with the load advancing passes there,
             the variation is physically unstable, and the stabilized path
             carries it across (check_instability()); its stabilized steps
             are listed with their iterations and solves, and the bound of
             15 iterations per step applies to the other steps; where the
             run without springs converges, the row stays 'converged';
  failed     exit != 0 with one line '<app>: error: ...' on standard error
             and no result file (summary.json, profile CSV, PNG): a clean
             refusal or a solver failure reported as such;
  DEFECT     anything else: a crash (signal), several lines on standard
             error, results left by a failed run, a NaN or inf in an output,
             a force balance above 1e-6, exit 0 without a summary, a run
             still going at the time limit without progress (hang) or
             stopped at the memory limit.

A run gets the time limit of --time-limit, or the longer one its application
gives it in VARIATIONS[app]["time_limits"] (seconds, by variation name): a
variation whose clean failure is known to take longer than the limit.

A new application joins by adding its variations to VARIATIONS (and its
production file and coarse entries to fuzz_prm.APPS). The variations
follow the robustness issue: friction coefficient mu in {0, 0.05, 0.3, 1, 5}
where the case has friction; the stiffness ratio of the two bodies from
1e-4 to 1e4 (where there are two deformable bodies); 1, 2, 5 and 50 load
steps; a first step of 1e-6 of the load; Q1 and Q2; penalty enforcement at
10, 100 and 1000 E/h (E the Young's modulus of the softer body at the
contact, h the smallest contact cell of the coarse case); non-matching meshes (cell size ratios
1/8 to 8 across the contact, Mesh/Contact size ratio); interior nodes moved
at random by up to 30 % of the cell (Mesh/Interior node perturbation);
initial gaps and overlaps of 1e-8 and 1e-3 of the smallest contact cell of
the coarse case (each application's first run). Variations an application
cannot express are listed as 'not available' with the reason.

Usage:
  python3 scripts/robustness_sweep.py [--apps APP ...] [--build DIR]
      [--work-dir DIR] [--time-limit 120] [--memory-limit 4000]
      [--only NAME ...] [--list]

Each converged run also gives its headline result (HEADLINE) and its change
in percent against the coarse case, or against the variation a row names
(a third element of its entry in VARIATIONS): the variations of the mesh,
the gaps, the load steps and the enforcement should leave it nearly
unchanged.

Writes robustness_sweep.csv and robustness_sweep.json into the work
directory (default results/robustness_sweep) and prints the table; exits
non-zero if a run is a defect.
"""

import argparse
import concurrent.futures
import csv
import importlib.util
import json
import math
import os
import shutil
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

_spec = importlib.util.spec_from_file_location("fuzz_prm", os.path.join(HERE, "fuzz_prm.py"))
fuzz = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(fuzz)

MAX_ITERATIONS_PER_STEP = 15

# One result of each application's summary.json (section, key) that every
# converged variation reports as its change against the coarse case: a
# variation that should not change the answer (meshes, gaps, load steps,
# enforcement) shows here if it does.
HEADLINE = {
    "cgs_roller": ("results", "peak_pressure_MPa"),
    "punch3d": ("results", "pressure_at_centre_MPa"),
    "loaded_pin": ("results", "pin_centre_ux_mm"),
    "sheet_forming": ("results", "angle_after_release_deg"),
    "reynolds_roller": ("results", "dx_A_mm"),
}
FORCE_BALANCE_TOLERANCE = 1e-6


def friction(mu):
    """Coulomb friction mu (frictionless for mu = 0)."""
    if mu == 0:
        return [("Contact", "Friction law", "frictionless")]
    return [("Contact", "Friction law", "coulomb"),
            ("Contact", "Friction coefficient", f"{mu:g}")]


def moduli(first, second, ratio, modulus=210000.):
    """Young's moduli of two bodies (subsections first and second) with
    E_first / E_second = ratio, the larger one at modulus (MPa)."""
    e_first = modulus if ratio >= 1 else modulus * ratio
    e_second = modulus if ratio <= 1 else modulus / ratio
    return [(first, "Young's modulus", f"{e_first:g}"),
            (second, "Young's modulus", f"{e_second:g}")]


def steps(n):
    return [("Load program/Stage 1", "Number of steps", str(n))]


def staged_program(stages):
    """The entries of a load program of the given stages, each a list of
    (key, value) pairs of its subsection "Load program/Stage k"."""
    entries = [("Load program", "Number of stages", str(len(stages)))]
    for k, stage in enumerate(stages, start=1):
        entries += [(f"Load program/Stage {k}", key, value) for key, value in stage]
    return entries


def tiny_first_step(channel, value, n_steps):
    """A first stage to 1e-6 of the load in one step, then the load in
    n_steps steps (the channel's end value is value)."""
    return staged_program([[("Number of steps", "1"), (channel, f"{1e-6 * value:g}")],
                           [("Number of steps", str(n_steps)), (channel, f"{value:g}")]])


def degree(p):
    return [("Mesh", "Element degree", str(p))]


def penalty(factor, modulus):
    """Penalty enforcement with the stiffness factor E/h (MPa/mm): E the
    Young's modulus of the softer body at the contact (MPa), h the smallest
    cell at the contact of the coarse case (PER_CELL)."""
    return [("Contact", "Enforcement", "penalty"),
            ("Contact", "Penalty stiffness", (factor * modulus, PER_CELL))]


def elastic_roller(modulus):
    """reynolds_roller's elastic roller (a ring from a hub of radius 15 mm
    to the rim, neo-Hookean in its volumetric-isochoric split, nu = 0.3)
    with Young's modulus modulus (MPa), as in reynolds_roller_mu03_elastic.prm."""
    return [("Geometry", "Roller", "elastic"),
            ("Geometry", "Roller hub radius", "15"),
            ("Roller material", "Young's modulus", f"{modulus:g}"),
            ("Roller material", "Poisson's ratio", "0.3"),
            ("Roller material", "Finite strain model", "neo-Hookean split")]


MUS = [0, 0.05, 0.3, 1, 5]
RATIOS = [1e-4, 1e-2, 1, 1e2, 1e4]
STEPS = [1, 2, 5, 50]
# Penalty stiffnesses a decade apart in units of E/h, the stiffness of a
# layer of the softer body one contact cell thick: a penalty means the same
# to rubber (E = 10 MPa) as to aluminium (70 GPa) only in those units
# (10 E/h is Abaqus's default "10 times the underlying element's
# stiffness"; at 1000 E/h the penetration is 1e-3 of the cell's strain).
PENALTY_FACTORS = [10, 100, 1000]

SIZE_RATIOS = ["1/8", "1/2", "2", "8"]
GAPS = [1e-8, -1e-8, 1e-3, -1e-3]
# The placeholder of an initial gap in cells: replaced by the value times
# the smallest cell at the contact of the application's first run (the
# coarse case without variation, "coarse case").
CELL = "cells at the contact"
# The placeholder of a value divided by that cell (a penalty factor times
# E, divided by h).
PER_CELL = "MPa over the smallest cell at the contact"


def mesh_variations():
    """Non-matching meshes (Mesh/Contact size ratio) and perturbed
    interior nodes (Mesh/Interior node perturbation, 30 % of the cell)."""
    return ([(f"contact size ratio {r}", [("Mesh", "Contact size ratio", r)])
             for r in SIZE_RATIOS]
            + [("interior nodes perturbed 30 %",
                [("Mesh", "Interior node perturbation", "0.3")])])


def gap_variations(path, key, sign=1.):
    """Initial gaps (positive) and overlaps of 1e-8 and 1e-3 of the contact
    cell size, set by the entry path/key (sign -1 where the entry is an
    overlap)."""
    return [(f"initial {'gap' if g > 0 else 'overlap'} {abs(g):g} cell",
             [(path, key, (sign * g, CELL))]) for g in GAPS]


def standard(first=None, second=None, channel="Load factor", value=1., n_steps=1,
             with_rigid=(), gap=(), modulus=70000.):
    """The variations of an application with a load factor: the coarse case
    itself, friction, stiffness ratio (first/second: the material
    subsections of the two bodies), load steps, a tiny first step, Q1/Q2,
    penalty, non-matching and perturbed meshes and the initial gaps of
    gap (gap_variations())."""
    table = [("coarse case", [])]
    table += [(f"mu {mu:g}", friction(mu)) for mu in MUS]
    if first and second:
        table += [(f"E ratio {r:g}", moduli(first, second, r)) for r in RATIOS]
    table += list(with_rigid)
    table += [(f"{n} load steps", steps(n)) for n in STEPS]
    table.append(("first step 1e-6 of the load", tiny_first_step(channel, value, n_steps)))
    table += [(f"Q{p}", degree(p)) for p in (1, 2)]
    table += [(f"penalty {f:g} E/h", penalty(f, modulus)) for f in PENALTY_FACTORS]
    table += mesh_variations() + list(gap)
    return table


# Young's moduli of the softer body at the contact (MPa), the E of the
# penalty factors: aluminium (the block, foundation and plate of
# cgs_roller, punch3d and loaded_pin: standard()'s default), the sheet's
# aluminium and the strip's rubber.
SHEET_MODULUS = 70500.
RUBBER_MODULUS = 10.

VARIATIONS = {
    "cgs_roller": {
        "runs": standard("Roller material", "Block material", n_steps=5,
                         gap=gap_variations("Geometry", "Initial gap")),
        "not_available": [("rigid roller", "cgs_roller models both bodies as elastic")],
    },
    "punch3d": {
        "runs": standard("Punch material", "Foundation material",
                         with_rigid=[("rigid punch", [("Model", "Punch", "rigid")]),
                                     ("rigid punch surface",
                                      [("Model", "Punch", "rigid surface")])],
                         gap=gap_variations("Geometry", "Initial gap")),
        "not_available": [],
    },
    "loaded_pin": {
        # A gap is a clearance, an overlap an interference fit. The coarse
        # case's Q1 faces are chords of 22.5 degrees, 0.96 mm inside the
        # circle at their middle; a body refined toward the contact follows
        # the circle, so that non-matching Q1 meshes overlap or open by
        # that much, 2.4 times the pin's travel. Q2 faces follow the circle to
        # 2e-3 mm: non-matching Q2 meshes, against Q2 on matching ones.
        "runs": standard("Pin material", "Sheet material",
                         gap=gap_variations("Geometry", "Clearance"))
        + [(f"Q2, contact size ratio {r}",
            degree(2) + [("Mesh", "Contact size ratio", r)], "Q2")
           for r in ("1/2", "2")],
        "not_available": [("rigid pin", "loaded_pin models both bodies as elastic")],
    },
    "sheet_forming": {
        # The forming and release over the whole stroke on 2 x 60 cells:
        # cells of 1 mm along the strip, a quarter of the die shoulder's
        # radius (R3 = 4 mm).
        "base": [("Mesh", "Number of cells through the thickness", "2"),
                 ("Mesh", "Number of cells along the length", "60")],
        "runs": [("coarse case", [])]
        + [(f"mu {mu:g}", friction(mu)) for mu in MUS]
        + [(f"{n} forming steps", steps(n)) for n in STEPS]
        + [("Q2", degree(2) + [("Solid", "Element technology", "displacement")]),
           ("Q1, displacement element", [("Solid", "Element technology",
                                          "displacement")])]
        # Penalty enforcement is frictionless only, and the frictionless
        # sheet is unstable on the convex tools from 75 % of the stroke
        # (sheet_forming/README.md, "Status"): these rows fail cleanly
        # after minutes of stabilized solves and cutbacks, on 2 x 30 cells
        # (2 x 60: 100 and 1000 E/h failed after 365 and 492 s, 10 E/h was
        # still running at 120 s), which keeps the sweep within its time.
        # h is the coarse case's cell (1.12 mm), so that the stiffnesses
        # in MPa/mm are those of the 2 x 60 cells; on their own 2 x 30
        # cells (2.06 mm) they are 18, 184 and 1840 E/h.
        + [(f"penalty {f:g} E/h, mu 0, 2 x 30 cells",
            penalty(f, SHEET_MODULUS) + friction(0)
            + [("Mesh", "Number of cells along the length", "30")])
           for f in PENALTY_FACTORS]
        + [("interior nodes perturbed 30 %",
            [("Mesh", "Interior node perturbation", "0.3")])]
        + [("nodal tool gap", [("Contact", "Rigid tool gap", "nodal")]),
           ("nodal tool gap, mu 0",
            [("Contact", "Rigid tool gap", "nodal")] + friction(0))]
        # A first stage of 1e-6 of the stroke in one step, then the
        # production program (forming, release, withdrawal).
        + [("first step 1e-6 of the stroke",
            staged_program([
                [("Name", "first step"), ("Number of steps", "1"),
                 ("Punch displacement", "2.85e-05"), ("Die displacement", "0")],
                [("Name", "forming"), ("Number of steps", "57"),
                 ("Punch displacement", "28.5"), ("Die displacement", "0")],
                [("Name", "release"), ("Number of steps", "20"),
                 ("Punch displacement", "28"), ("Die displacement", "0.5")],
                [("Name", "withdrawal"), ("Number of steps", "160"),
                 ("Punch displacement", "-1.5"), ("Die displacement", "30")]])
            + [("Release", "Release stage", "3")])]
        # The punch raised above the strip or pressed into it.
        + gap_variations("Geometry", "Initial punch gap"),
        # The penalties fail cleanly after minutes of iterations,
        # stabilized solves and cutbacks (10 and 100 E/h after 99 and
        # 176 s beside another run: the set alternates between two
        # equilibria at 80 % of the stroke, an iterate carries a node
        # through the die at 73 %; 1000 E/h ran past 600 s beside two).
        "time_limits": {f"penalty {f:g} E/h, mu 0, 2 x 30 cells": 900.
                        for f in PENALTY_FACTORS},
        "not_available": [
            ("non-matching meshes", "the tools are rigid analytic surfaces: "
             "there is one mesh"),
            ("stiffness ratio of the two bodies", "the tools are rigid")],
    },
    "reynolds_roller": {
        # The fuzz harness's coarse case: 30 x 2 cells pressed 1 mm (the
        # bottom held in x), its support released, then 2 degrees of the
        # turn. Without friction nothing holds the strip in
        # x but its bottom.
        "runs": [("coarse case", [])]
        + [(f"mu {mu:g}", friction(mu) + ([("Supports", "Bottom free in x from stage", "0")]
                                          if mu == 0 else []))
           for mu in MUS]
        + [(f"{n} rolling steps", [("Load program/Stage 3", "Number of steps", str(n))])
           for n in STEPS]
        + [("first step 1e-6 of the indentation",
            staged_program([
                [("Number of steps", "1"), ("Indentation", "1e-06")],
                [("Name", "pressing"), ("Number of steps", "2"), ("Indentation", "1"),
                 ("Roller angle", "0"), ("Bottom x release", "0")],
                [("Name", "release"), ("Number of steps", "1"), ("Indentation", "1"),
                 ("Roller angle", "0"), ("Bottom x release", "1")],
                [("Name", "rolling"), ("Number of steps", "1"), ("Roller angle", "2")]])
            + [("Supports", "Bottom free in x from stage", "3")])]
        + [(f"Q{p}", degree(p)) for p in (1, 2)]
        + [(f"penalty {f:g} E/h, mu 0",
            penalty(f, RUBBER_MODULUS) + friction(0)
            + [("Supports", "Bottom free in x from stage", "0")])
           for f in PENALTY_FACTORS]
        + [("nodal tool gap", [("Contact", "Rigid tool gap", "nodal")]),
           ("interior nodes perturbed 30 %",
            [("Mesh", "Interior node perturbation", "0.3")])]
        # The coarse case's roller is rigid (the specification's S2 model);
        # the elastic roller (reynolds_roller_mu03_elastic.prm) spans the
        # stiffness ratio, E of the roller over that of the rubber (10 MPa):
        # steel is 2.1e4.
        + [(f"elastic roller, E ratio {r:g}", elastic_roller(r * RUBBER_MODULUS))
           for r in RATIOS]
        # Non-matching meshes: the steel ring's rim faces (2 pi 30 mm / n;
        # 48 cells, 3.9 mm, in the production file) against the strip's
        # 10 mm cells of the coarse case, their headline against the same
        # ring with 48 cells; a ring of fewer than 8 cells (a ratio above
        # 2.4) is refused.
        + [("elastic steel roller", elastic_roller(210000.))]
        + [(f"elastic steel roller, rim faces {label} of the strip's cells",
            elastic_roller(210000.) + [("Mesh", "Number of cells around the roller", str(n))],
            "elastic steel roller")
           for label, n in (("1/8", 151), ("1/2", 38), ("2", 9))]
        # Rim faces 8 times the strip's cells: the coarsest ring (9 cells,
        # 20.9 mm faces) on a strip of 115 cells along its 300 mm (2.61 mm).
        + [("elastic steel roller, rim faces 8 of the strip's cells",
            elastic_roller(210000.) + [("Mesh", "Number of cells around the roller", "9"),
                                       ("Mesh", "Number of cells along the length", "115")],
            "elastic steel roller")]
        # The roller raised above the strip or pressed into it: the rigid
        # roller of the coarse case and the elastic steel one.
        + gap_variations("Geometry", "Initial gap")
        + [(f"elastic steel roller, {name}", elastic_roller(210000.) + entries,
            "elastic steel roller")
           for name, entries in gap_variations("Geometry", "Initial gap")],
    },
}


def resolve(entries, cell_size):
    """entries with the values (factor, CELL) replaced by factor times
    cell_size (mm) and (value, PER_CELL) by value divided by cell_size;
    None if one needs cell_size and it is unknown."""
    resolved = []
    for path, key, value in entries:
        if isinstance(value, tuple):
            if cell_size is None:
                return None
            scaled = value[0] / cell_size if value[1] == PER_CELL else value[0] * cell_size
            value = f"{scaled:.17g}"
        resolved.append((path, key, value))
    return resolved


def prm_text(app, entries):
    """The production file with the app's base entries (its own, or the
    fuzz harness's coarse entries), the Output entries and entries set."""
    production = os.path.join(ROOT, "parameters", fuzz.APPS[app]["production"])
    base = VARIATIONS[app].get("base", fuzz.APPS[app]["coarse"])
    with open(production) as f:
        lines = fuzz.parse_lines(f.read().rstrip("\n"))
    for path, key, value in base + fuzz.OUTPUT + entries:
        lines = fuzz.set_entry(lines, tuple(path.split("/")), key, value)
    return fuzz.render(lines) + "\n"


def force_balance(summary):
    results = summary.get("results", {})
    for key in ("force_balance_relative_error", "max_force_balance_relative_error"):
        if key in results:
            return results[key]
    return None


def classify(app, case_dir, code, stopped, progressing):
    """(status, detail, newton record) of one run."""
    with open(os.path.join(case_dir, "stderr.txt"), "rb") as f:
        stderr = f.read().decode(errors="replace")
    lines = [l for l in stderr.split("\n") if l.strip()]
    left = sorted(os.path.relpath(os.path.join(folder, name), case_dir)
                  for folder, _, files in os.walk(case_dir) for name in files
                  if fuzz.RESULT_FILE.search(name))
    if stopped == "memory":
        return "DEFECT memory", "stopped at the memory limit", {}
    if stopped == "time":
        if progressing:
            return "running", "still making progress at the time limit", {}
        return "DEFECT hang", "no progress in the last third of the time limit", {}
    if code < 0:
        return "DEFECT crash", f"killed by signal {-code}", {}
    if code != 0:
        if len(lines) != 1 or not lines[0].startswith(f"{app}: error: "):
            return "DEFECT stderr", " | ".join(l[:160] for l in lines[:4]), {}
        if left:
            return "DEFECT results left", ", ".join(left[:4]), {}
        return "failed", lines[0][len(app) + 9:], {}
    summary_path = os.path.join(case_dir, "results", "summary.json")
    if not os.path.isfile(summary_path):
        return "DEFECT no summary", "exit 0 without results/summary.json", {}
    bad = fuzz.non_finite_in_outputs(case_dir)
    if bad:
        return "DEFECT non-finite", "; ".join(f"{f} {w}: {v}" for f, w, v in bad[:3]), {}
    with open(summary_path) as f:
        summary = json.load(f)
    newton = summary.get("newton", {})
    balance = force_balance(summary)
    if balance is not None and not balance <= FORCE_BALANCE_TOLERANCE:
        return "DEFECT force balance", f"relative error {balance:.2e}", newton
    detail = "" if balance is None else f"force balance {balance:.1e}"
    if most_per_step(newton) > MAX_ITERATIONS_PER_STEP:
        detail = (detail + "; " if detail else "") + (
            f"more than {MAX_ITERATIONS_PER_STEP} Newton iterations in a step "
            "(cutbacks counted)")
    return "converged", detail, newton


def check_instability(app, executable, case_dir, entries, time_limit, memory_limit,
                      newton, detail):
    """(status, detail) of a converged run that took the stabilized path in
    some step: the variation runs again without the springs
    (Nonlinear solver/Stabilization factor = 0), in case_dir + '-unstabilized'.
    If that run fails cleanly at the minimum increment, no sequence of
    equilibria with the load advancing passes there (the step is cut back
    down to 1e-4 of its stage and still has no equilibrium near the last
    state): the variation is physically unstable, status 'unstable,
    stabilized', and the bound of 15 Newton iterations applies to the steps
    that needed no springs, marked where a step exceeds it; the stabilized
    steps are listed with their solves and the most iterations of one
    solve. If the run without springs converges, the springs were not
    needed and the run stays 'converged' with its marks; a defect of the
    run without springs is the row's defect."""
    companion = case_dir + "-unstabilized"
    shutil.rmtree(companion, ignore_errors=True)
    os.makedirs(companion)
    with open(os.path.join(companion, "case.prm"), "w") as f:
        f.write(prm_text(app, entries + [("Nonlinear solver", "Stabilization factor", "0")]))
    tmp = companion + "-tmp"
    shutil.rmtree(tmp, ignore_errors=True)
    os.makedirs(tmp)
    code, stopped, progressing, _ = fuzz.run(
        executable, companion, time_limit, memory_limit, env=dict(os.environ, TMPDIR=tmp))
    shutil.rmtree(tmp, ignore_errors=True)
    status, why, _ = classify(app, companion, code, stopped, progressing)
    if status.startswith("DEFECT"):
        return status, f"without the springs: {why}"
    if status != "failed" or "minimum increment" not in why:
        return "converged", detail + (
            "; without the springs: " + (status if status != "failed" else why)[:120])
    where = why.split(" (")[0]
    steps = newton.get("iterations_per_step", [])
    failed = newton.get("failed_attempt_iterations_per_step", [0] * len(steps))
    springs = newton.get("stabilized_solves_per_step", [])
    plain = [n + f for n, f, k in zip(steps, failed, springs) if k == 0]
    stabilized = [(n + f, k) for n, f, k in zip(steps, failed, springs) if k > 0]
    most_plain = max(plain, default=0)
    text = (f"physically unstable: without the springs '{where}' at the minimum "
            f"increment; {len(stabilized)} stabilized steps ("
            + ", ".join(f"{n} it/{k} solves" for n, k in stabilized)
            + f"), at most {newton.get('max_iterations_per_solve', '')} per solve; "
            f"the other steps at most {most_plain}, cutbacks counted")
    if most_plain > MAX_ITERATIONS_PER_STEP:
        text += (f"; more than {MAX_ITERATIONS_PER_STEP} Newton iterations in a step "
                 "without springs")
    balance = detail.split(";")[0] if detail.startswith("force balance") else ""
    return "unstable, stabilized", (balance + "; " if balance else "") + text


def most_per_step(newton):
    """The most Newton iterations of a step with its cutbacks counted: the
    accepted attempt and the failed attempts before it (summary.json's
    max_iterations_per_step_with_cutbacks; max_iterations_per_step where an
    older summary lacks it)."""
    return newton.get("max_iterations_per_step_with_cutbacks",
                      newton.get("max_iterations_per_step", 0))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--apps", nargs="+", default=list(VARIATIONS),
                        choices=list(VARIATIONS))
    parser.add_argument("--build", default=os.path.join(ROOT, "build-release"),
                        help="build directory with the executables")
    parser.add_argument("--work-dir", default=os.path.join(ROOT, "results",
                                                           "robustness_sweep"))
    parser.add_argument("--time-limit", type=float, default=120.,
                        help="seconds per run (default 120)")
    parser.add_argument("--jobs", type=int, default=1,
                        help="variations run at once (default 1; at most the "
                        "number of cores, since the time limits are wall time)")
    parser.add_argument("--memory-limit", type=float, default=4000.,
                        help="MB of resident memory per run (default 4000)")
    parser.add_argument("--only", nargs="+", default=[],
                        help="run only the variations whose name contains one of these")
    parser.add_argument("--list", action="store_true", help="list the variations")
    args = parser.parse_args()

    rows, n_defects = [], 0
    for app in args.apps:
        # The coarse case runs first whenever a selected variation needs its
        # contact cell size.
        # (name, entries, the variation its headline is compared with)
        table = [(run[0], run[1], run[2] if len(run) > 2 else "coarse case")
                 for run in VARIATIONS[app]["runs"]
                 if not args.only or any(o in run[0] for o in args.only)]
        # A variation runs after the one it is compared with.
        for name, _, against in list(table):
            if (against != "coarse case"
                    and all(other != against for other, _, _ in table)):
                reference = next(run for run in VARIATIONS[app]["runs"]
                                 if run[0] == against)
                table.insert(0, (reference[0], reference[1], "coarse case"))
        needs_cell = any(isinstance(v, tuple) for _, entries, _ in table
                         for _, _, v in entries)
        if needs_cell and all(name != "coarse case" for name, _, _ in table):
            table.insert(0, ("coarse case", [], "coarse case"))
        if args.list:
            for name, entries, against in table:
                print(f"{app}: {name}: " + "; ".join(
                f"{p}/{k} = " + (f"{v[0]:g} {v[1]}" if isinstance(v, tuple) else v)
                for p, k, v in entries))
            for name, why in VARIATIONS[app].get("not_available", []):
                print(f"{app}: {name}: not available ({why})")
            continue
        executable = os.path.abspath(os.path.join(args.build, app, app))
        if not os.access(executable, os.X_OK):
            sys.exit(f"robustness_sweep: no executable {executable}; build the target {app}")

        def run_variation(number, name, entries):
            """Run one variation in its own directory; (status, detail,
            Newton record, summary or None, wall time)."""
            case_dir = os.path.join(args.work_dir, app, f"{number:02d}")
            shutil.rmtree(case_dir, ignore_errors=True)
            os.makedirs(case_dir)
            with open(os.path.join(case_dir, "case.prm"), "w") as f:
                f.write(prm_text(app, entries))
            with open(os.path.join(case_dir, "variation.txt"), "w") as f:
                f.write(name + "\n")
            time_limit = max(args.time_limit,
                             VARIATIONS[app].get("time_limits", {}).get(name, 0.))
            # Each run keeps its MPI session files in a directory of its
            # own, apart from runs beside it.
            tmp = os.path.join(args.work_dir, app, f"tmp{number:02d}")
            shutil.rmtree(tmp, ignore_errors=True)
            os.makedirs(tmp)
            code, stopped, progressing, wall = fuzz.run(
                executable, case_dir, time_limit, args.memory_limit,
                env=dict(os.environ, TMPDIR=tmp))
            shutil.rmtree(tmp, ignore_errors=True)
            status, detail, newton = classify(app, case_dir, code, stopped, progressing)
            if status == "converged" and newton.get("stabilized_solves", 0):
                status, detail = check_instability(
                    app, executable, case_dir, entries, time_limit,
                    args.memory_limit, newton, detail)
            summary = None
            if status in ("converged", "unstable, stabilized"):
                with open(os.path.join(case_dir, "results", "summary.json")) as f:
                    summary = json.load(f)
            return case_dir, status, detail, newton, summary, wall

        # The smallest cell at the contact, from the coarse case's summary:
        # the unit of the initial gaps. The coarse case runs first, alone;
        # the other variations run --jobs at a time.
        cell_size = None
        results = {}
        if table and table[0][0] == "coarse case":
            results[0] = run_variation(1, *table[0][:2])
            if results[0][1] == "converged":
                cell_size = results[0][4].get("mesh", {}).get(
                    "smallest_cell_in_contact_zone_mm")
        pending = {}
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            for index, (name, entries, _) in enumerate(table):
                if index in results:
                    continue
                entries = resolve(entries, cell_size)
                if entries is not None:
                    pending[index] = pool.submit(run_variation, index + 1, name, entries)
            headlines = {}
            for index, (name, _, against) in enumerate(table):
                if index not in results and index not in pending:
                    print(f"{app:14s} {name:30s} skipped: the coarse case gave no contact "
                          "cell size")
                    continue
                if index not in results:
                    results[index] = pending[index].result()
                case_dir, status, detail, newton, summary, wall = results[index]
                headline = None
                if summary is not None:
                    section, key = HEADLINE[app]
                    headline = summary.get(section, {}).get(key)
                headlines[name] = headline
                # The stabilization springs' share of the work done on the
                # model, where the application reports it (sheet_forming).
                stabilization_share = ""
                if summary is not None:
                    share = summary.get("results", {}).get(
                        "stabilization_energy_fraction_of_forming_work")
                    if share is not None:
                        stabilization_share = f"{100. * share:.3g}"
                change = ""
                if (headline is not None and name != against
                        and headlines.get(against) not in (None, 0)):
                    change = f"{100. * (headline / headlines[against] - 1.):+.3g}"
                n_defects += status.startswith("DEFECT")
                row = {"app": app, "variation": name, "status": status,
                       "newton_iterations": newton.get("total_iterations", ""),
                       "steps": len(newton.get("iterations_per_step", [])) if newton else "",
                       "max_iterations_per_step": newton.get("max_iterations_per_step", ""),
                       "max_with_cutbacks": most_per_step(newton) if newton else "",
                       "failed_attempt_iterations": newton.get("failed_attempt_iterations", ""),
                       "first_iteration_extra_solves":
                           newton.get("first_iteration_extra_solves", ""),
                       "later_iterations_extra_solves":
                           newton.get("later_iterations_extra_solves", ""),
                       "max_linear_solves_per_step_with_cutbacks":
                           newton.get("max_linear_solves_per_step_with_cutbacks", ""),
                       "stabilized_solves": newton.get("stabilized_solves", ""),
                       "max_stabilized_solves_per_step":
                           newton.get("max_stabilized_solves_per_step", ""),
                       "max_iterations_per_solve": newton.get("max_iterations_per_solve", ""),
                       "stabilization_energy_percent": stabilization_share,
                       "cutbacks": newton.get("n_cutbacks", ""), "wall_time_s": round(wall, 1),
                       "headline": "" if headline is None else headline,
                       "change_vs_coarse_percent": change, "change_against": against,
                       "detail": detail, "case": os.path.relpath(case_dir, ROOT)}
                rows.append(row)
                print(f"{app:14s} {name:30s} {status:22s} it {str(row['newton_iterations']):>5s} "
                      f"steps {str(row['steps']):>4s} "
                      f"max {str(row['max_iterations_per_step']):>3s} "
                      f"({str(row['max_with_cutbacks']):>3s}) solves "
                      f"{str(row['max_linear_solves_per_step_with_cutbacks']):>3s} "
                      f"stabilized {str(row['max_stabilized_solves_per_step']):>3s} "
                      f"per solve {str(row['max_iterations_per_solve']):>3s} "
                      + (f"energy {stabilization_share:>5s} % "
                         if stabilization_share else "")
                      + f"cutbacks "
                      f"{str(row['cutbacks']):>3s} {wall:7.1f} s {change:>8s} %  {detail[:100]}",
                      flush=True)
        for name, why in VARIATIONS[app].get("not_available", []):
            rows.append({"app": app, "variation": name, "status": "not available",
                         "newton_iterations": "", "steps": "", "max_iterations_per_step": "",
                         "max_with_cutbacks": "", "failed_attempt_iterations": "",
                         "first_iteration_extra_solves": "", "cutbacks": "", "wall_time_s": "", "headline": "",
                         "change_vs_coarse_percent": "", "change_against": "",
                         "detail": why, "case": ""})
    if args.list:
        return 0
    os.makedirs(args.work_dir, exist_ok=True)
    with open(os.path.join(args.work_dir, "robustness_sweep.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    counts = {}
    for row in rows:
        counts[row["status"]] = counts.get(row["status"], 0) + 1
    with open(os.path.join(args.work_dir, "robustness_sweep.json"), "w") as f:
        json.dump({"counts": counts, "runs": rows}, f, indent=1)
    print("robustness sweep: " + ", ".join(f"{n} {s}" for s, n in sorted(counts.items()))
          + f"; results in {os.path.relpath(args.work_dir, ROOT)}")
    return 1 if n_defects else 0


if __name__ == "__main__":
    sys.exit(main())
