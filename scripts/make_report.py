#!/usr/bin/env python3
"""Write results/report.html: one self-contained page (images embedded, no
network) with, for each benchmark, its description, the headline numbers
beside the reference each is judged by, the plots, and the studies.

Each application folder holds a report.json (title, description, cases with
checks and plots, studies); results come from results/<app>/<case>/summary.json.

A check is one of two kinds:
  judged      the result against a reference that holds for the case, within
              a stated band: pass or FAIL. A FAIL means a regression.
  comparison  the result beside a reference that does not hold for the case
              (a finite body where the reference is a half-space, an
              under-resolved FE result): the difference is shown, with the
              reason, and there is no verdict.
Every check names its reference ("reference_label") and says why it applies
or why it is only compared ("why"). The reference is a number stated in
report.json ("reference_value", the benchmark's value with its source) or a
path into summary.json ("reference", e.g. the applied force). The band is
relative ("band": |value/reference - 1|) or absolute ("abs_band":
|value - reference|). "quick" gives the band for the coarse meshes of
`run_main.sh --quick` ({"band": ..., "why": ...} or {"abs_band": ...,
"why": ...}) or skips the check there with a reason ({"skip": "..."});
without it the production band applies to both.

Exit status: 0 if every judged check passes and every listed case was run,
1 otherwise.

Usage: scripts/make_report.py [--results DIR] [--quick] [--only APP/CASE ...]
"""
import argparse
import base64
import csv
import html
import json
import os
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
APPS = ["cgs_roller", "punch3d", "sheet_forming", "loaded_pin", "reynolds_roller"]

STYLE = """
body { font-family: sans-serif; max-width: 1200px; margin: 2em auto; color: #222; line-height: 1.45; }
h1 { border-bottom: 2px solid #446; padding-bottom: .3em; }
h2 { margin-top: 2em; border-bottom: 1px solid #ccd; }
table { border-collapse: collapse; margin: 1em 0; font-size: 0.92em; }
th, td { border: 1px solid #ccd; padding: .3em .6em; text-align: right; vertical-align: top; }
th { background: #eef; }
td.l, th.l { text-align: left; }
td { white-space: nowrap; }
td.l, td.why { white-space: normal; }
td.why { text-align: left; font-size: .9em; color: #444; max-width: 34em; }
tr.comparison td { background: #f7f7f7; color: #555; }
.pass { color: #075; font-weight: bold; }
.fail { color: #b00; font-weight: bold; }
.neutral { color: #556; }
.note { color: #777; font-style: italic; }
figure { margin: 1em 0; }
figcaption { font-size: .9em; color: #555; }
img { max-width: 100%; border: 1px solid #ddd; }
.summary { background: #f6f6fb; padding: .6em 1em; border-left: 4px solid #446; }
"""


class Tally:
    """Counts of judged checks, comparison rows, skipped checks and cases
    not run, and the console lines of the failures."""

    def __init__(self):
        self.passed = self.failed = self.compared = self.skipped = 0
        self.not_run = []
        self.failures = []

    def line(self):
        text = (f"{self.passed} checks pass, {self.failed} fail, "
                f"{self.compared} comparisons shown")
        if self.skipped:
            text += f", {self.skipped} skipped on the quick meshes"
        if self.not_run:
            text += f"; {len(self.not_run)} cases not run"
        return text

    def ok(self):
        return self.failed == 0 and not self.not_run


def lookup(summary, path):
    value = summary
    for key in path.split("."):
        value = value[key]
    return value


def image(path, caption):
    if not os.path.exists(path):
        return f"<p class='note'>plot not written: {html.escape(os.path.basename(path))}</p>"
    with open(path, "rb") as f:
        data = base64.b64encode(f.read()).decode()
    return (f"<figure><img alt='{html.escape(caption)}' src='data:image/png;base64,{data}'>"
            f"<figcaption>{html.escape(caption)}</figcaption></figure>")


def band_of(check, quick):
    """(kind of band, width), or ("skip", reason) on the quick meshes."""
    spec = check
    if quick and "quick" in check:
        spec = check["quick"]
        if "skip" in spec:
            return "skip", spec["skip"]
    if "abs_band" in spec:
        return "abs", spec["abs_band"]
    return "rel", spec["band"]


def difference(value, reference, absolute):
    """The difference, and as shown: absolute, or relative in percent (in
    scientific notation below 1e-4, as for a force balance)."""
    if absolute:
        return value - reference, f"{value - reference:+.4g}"
    ratio = value / reference - 1.0
    return ratio, f"{ratio:+.1e}" if abs(ratio) < 1e-4 else f"{ratio * 100:+.3g} %"


def check_row(check, summary, quick, tally, where):
    """One table row for a check; counts it in tally."""
    kind = check.get("kind", "judged")
    label = html.escape(check["label"])
    judged_by = (f"<b>{html.escape(check['reference_label'])}</b>. "
                 f"{html.escape(check['why'])}")
    try:
        value = float(lookup(summary, check["value"]))
        reference = float(check["reference_value"] if "reference_value" in check
                          else lookup(summary, check["reference"]))
    except (KeyError, TypeError, ValueError):
        # A result the summary should hold and does not: a regression too.
        missing = f"{check['value']} or its reference missing in summary.json"
        if kind == "comparison":
            tally.compared += 1
            verdict = "<td class='neutral'>comparison</td>"
        else:
            tally.failed += 1
            tally.failures.append(f"FAIL {where}: {check['label']}: {missing}")
            verdict = "<td class='fail'>FAIL</td>"
        return (f"<tr><td class='l'>{label}</td><td colspan='4'>{html.escape(missing)}</td>"
                f"{verdict}<td class='why'>{judged_by}</td></tr>")
    if kind == "comparison":
        absolute = check.get("difference", "relative") == "absolute"
        _, shown = difference(value, reference, absolute)
        tally.compared += 1
        return (f"<tr class='comparison'><td class='l'>{label}</td><td>{value:.6g}</td>"
                f"<td>{reference:.6g}</td><td>{shown}</td><td>&ndash;</td>"
                f"<td class='neutral'>comparison</td><td class='why'>{judged_by}</td></tr>")
    if kind != "judged":
        raise ValueError(f"{where}: unknown kind of check '{kind}'")
    band_kind, band = band_of(check, quick)
    if quick and "why" in check.get("quick", {}):
        judged_by += f" On the quick mesh: {html.escape(check['quick']['why'])}."
    if band_kind == "skip":
        tally.skipped += 1
        return (f"<tr><td class='l'>{label}</td><td>{value:.6g}</td><td>{reference:.6g}</td>"
                f"<td>{difference(value, reference, False)[1]}</td><td>&ndash;</td>"
                f"<td class='neutral'>not judged on the quick mesh</td>"
                f"<td class='why'>{judged_by} Not judged on the quick mesh: {html.escape(band)}.</td></tr>")
    absolute = band_kind == "abs"
    diff, shown = difference(value, reference, absolute)
    ok = abs(diff) <= band
    band_text = (f"{band:.2g}" if absolute
                 else f"{band:.0e}" if band < 1e-4 else f"{band * 100:.2g} %")
    if ok:
        tally.passed += 1
    else:
        tally.failed += 1
        tally.failures.append(
            f"FAIL {where}: {check['label']}: {value:.6g} against {reference:.6g} "
            f"({check['reference_label']}), difference {shown}, band +-{band_text}")
    return (f"<tr><td class='l'>{label}</td><td>{value:.6g}</td><td>{reference:.6g}</td>"
            f"<td>{shown}</td><td>&plusmn;{band_text}</td>"
            f"<td class='{'pass' if ok else 'fail'}'>{'pass' if ok else 'FAIL'}</td>"
            f"<td class='why'>{judged_by}</td></tr>")


def case_section(app, name, case, results, quick, tally):
    directory = os.path.join(results, app, name)
    summary_file = os.path.join(directory, "summary.json")
    out = [f"<h3>{html.escape(case['label'])} <small>({html.escape(name)})</small></h3>"]
    out += [f"<p>{html.escape(p)}</p>" for p in case.get("text", [])]
    if not os.path.exists(summary_file):
        tally.not_run.append(f"{app}/{name}")
        return out + ["<p class='fail'>not run: no summary.json</p>"]
    with open(summary_file) as f:
        summary = json.load(f)
    m = summary["mesh"]
    n = summary["newton"]
    t = summary["timing_s"]
    out.append(f"<p>{m['n_dofs']} degrees of freedom, {m['n_active_cells']} cells, "
               f"smallest cell in the contact zone {m['smallest_cell_in_contact_zone_mm']:.3g} mm; "
               f"Newton iterations per load step {n['iterations_per_step']}, "
               f"{n['n_cutbacks']} cutbacks; run time {t['total_s']:.2f} s.</p>")
    out.append("<table><tr><th class='l'>quantity</th><th>result</th><th>reference</th>"
               "<th>difference</th><th>band</th><th>verdict</th>"
               "<th class='l'>judged by, and why</th></tr>")
    for check in case["checks"]:
        out.append(check_row(check, summary, quick, tally, f"{app}/{name}"))
    out.append("</table>")
    for file, caption in case.get("plots", []):
        out.append(image(os.path.join(directory, file), caption))
    return out


def generic_table(rows, columns):
    """The study's table with the columns [key, label] its report.json names;
    numbers with a fraction are shown to 4 decimals."""
    out = ["<table><tr>" + "".join(f"<th>{html.escape(label)}</th>" for _, label in columns) + "</tr>"]
    for r in rows:
        cells = []
        for key, _ in columns:
            v = r.get(key, "")
            try:
                if "." in v or "e" in v:
                    v = f"{float(v):.4f}"
            except ValueError:
                pass
            cells.append(f"<td>{html.escape(str(v))}</td>")
        out.append("<tr>" + "".join(cells) + "</tr>")
    out.append("</table>")
    return out


def study_section(study, results):
    directory = os.path.join(results, study["directory"])
    out = [f"<h3>{html.escape(study['title'])}</h3>", f"<p>{html.escape(study['text'])}</p>"]
    table = os.path.join(directory, study["table"])
    if not os.path.exists(table):
        return out + ["<p class='note'>study not run</p>"]
    for file, caption in study["plots"]:
        out.append(image(os.path.join(directory, file), caption))
    with open(table) as f:
        rows = list(csv.DictReader(f))
    if "columns" in study:
        return out + generic_table(rows, study["columns"])
    # Time to reach 1 % error in p0, per element degree and enforcement.
    series = {}
    for r in rows:
        key = (r["degree"], r["enforcement"])
        if abs(float(r["error_p0"])) <= 0.01:
            t = float(r["wall_time_s"])
            series[key] = t if series.get(key) is None else min(series[key], t)
        else:
            series.setdefault(key, None)
    out.append("<table><tr><th class='l'>series</th><th>least wall time with |error p0| &le; 1 %</th></tr>")
    for (degree, enforcement), t in series.items():
        out.append(f"<tr><td class='l'>Q{degree}, {html.escape(enforcement)}</td>"
                   f"<td>{'not reached' if t is None else f'{t:.2f} s'}</td></tr>")
    out.append("</table>")
    columns = [("degree", "Q"), ("contact_refinements", "level"), ("enforcement", "enforcement"),
               ("n_dofs", "DoFs"), ("newton_iterations", "Newton"), ("wall_time_s", "wall [s]"),
               ("error_p0", "error p0"), ("error_a", "error a"),
               ("l2_error_pressure", "L2 error p")]
    out.append("<table><tr>" + "".join(f"<th>{c[1]}</th>" for c in columns) + "</tr>")
    for r in rows:
        cells = []
        for key, _ in columns:
            v = r[key]
            if key in ("error_p0", "error_a", "l2_error_pressure"):
                v = f"{float(v) * 100:+.3f} %"
            cells.append(f"<td>{html.escape(str(v))}</td>")
        out.append("<tr>" + "".join(cells) + "</tr>")
    out.append("</table>")
    return out


def robustness_section(results):
    """The robustness sweep (scripts/robustness_sweep.py, in
    results/robustness_sweep) and the fuzzed-input counts
    (scripts/fuzz_prm.py --summary results/fuzz_summary.json)."""
    out = ["<h2>Robustness: the neighbourhood of every case, and fuzzed input</h2>",
           "<p>Each application's coarse case varied one entry at a time (friction, stiffness "
           "ratio, rigid bodies, load steps, a first step of 1e-6 of the load, Q1/Q2, penalty, "
           "non-matching and perturbed meshes, initial gaps and overlaps). A run converges (Newton "
           "iterations, most in a step, cutbacks, and the change of the application's headline "
           "result against the coarse case or the variation named) or fails with one line naming the cause and no "
           "result files; a crash, a NaN, a hang or a force balance above 1e-6 is a defect. A run that "
           "needed the stabilized path in some step is run again without the springs: where that run "
           "fails at the minimum increment, no sequence of equilibria with the load advancing passes "
           "there, and the row reads 'unstable, stabilized' (physically unstable; the detail lists its "
           "stabilized steps, and the bound of 15 iterations per step applies to the others).</p>"]
    sweep = os.path.join(results, "robustness_sweep", "robustness_sweep.json")
    if not os.path.exists(sweep):
        out.append("<p class='note'>sweep not run (python3 scripts/robustness_sweep.py)</p>")
    else:
        with open(sweep) as f:
            data = json.load(f)
        out.append("<p>" + html.escape(", ".join(
            f"{n} {s}" for s, n in sorted(data["counts"].items()))) + ".</p>")
        runs = [{k: str(v) for k, v in run.items()} for run in data["runs"]]
        out += generic_table(runs, [
            ("app", "application"), ("variation", "variation"), ("status", "status"),
            ("newton_iterations", "Newton"), ("steps", "steps taken"),
            ("max_iterations_per_step", "most per step"),
            ("max_with_cutbacks", "most per step, cutbacks counted"),
            ("failed_attempt_iterations", "in failed attempts"),
            ("first_iteration_extra_solves", "extra first-iteration solves"),
            ("later_iterations_extra_solves", "extra later-iteration solves"),
            ("max_linear_solves_per_step_with_cutbacks",
             "most linear solves in a step"),
            ("max_stabilized_solves_per_step", "most stabilized solves in a step"),
            ("max_iterations_per_solve", "most iterations of one solve"),
            ("stabilization_energy_percent",
             "stabilization energy [% of forming work; the run warns above 5]"),
            ("cutbacks", "cutbacks"), ("wall_time_s", "wall [s]"),
            ("change_vs_coarse_percent", "headline change [%]"),
            ("change_against", "against"), ("detail", "detail")])
    fuzz_file = os.path.join(results, "fuzz_summary.json")
    if not os.path.exists(fuzz_file):
        out.append("<p class='note'>fuzzing not run (python3 scripts/fuzz_prm.py --summary "
                   "results/fuzz_summary.json)</p>")
    else:
        with open(fuzz_file) as f:
            fuzz = json.load(f)
        rows = [dict(app=app, **{k: str(v) for k, v in counts.items()})
                for app, counts in fuzz.items()]
        out.append("<p>Fuzzed parameter files: seeded mutations of each production file; "
                   "each must be refused with one line naming the entry, or run to finite "
                   "results.</p>")
        out += generic_table(rows, [("app", "application"), ("mutations", "mutations"),
                                    ("rejected", "refused"), ("ran", "ran"),
                                    ("running", "running at the time limit"),
                                    ("defects", "defects"), ("wall_time_s", "wall [s]")])
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", default=os.path.join(ROOT, "results"))
    parser.add_argument("--quick", action="store_true",
                        help="judge by the bands of the coarse meshes of run_main.sh --quick")
    parser.add_argument("--only", nargs="+", metavar="APP/CASE",
                        help="report these cases only (no studies)")
    args = parser.parse_args()

    known = set()
    body, tally = [], Tally()
    for app in APPS:
        meta_file = os.path.join(ROOT, app, "report.json")
        if not os.path.exists(meta_file):
            continue
        with open(meta_file) as f:
            meta = json.load(f)
        cases = {name: case for name, case in meta["cases"].items()
                 if not args.only or f"{app}/{name}" in args.only}
        known.update(f"{app}/{name}" for name in meta["cases"])
        if not cases:
            continue
        body.append(f"<h2>{html.escape(meta['title'])}</h2>")
        body += [f"<p>{html.escape(p)}</p>" for p in meta["description"]]
        for name, case in cases.items():
            body += case_section(app, name, case, args.results, args.quick, tally)
        if not args.only:
            for study in meta.get("studies", []):
                body += study_section(study, args.results)
    if not args.only:
        body += robustness_section(args.results)
    unknown = [c for c in args.only or [] if c not in known]
    if unknown:
        sys.exit(f"make_report: no such case in any report.json: {', '.join(unknown)}")

    bands = ("the bands of the coarse meshes of run_main.sh --quick" if args.quick
             else "the production bands")
    page = ["<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>",
            "<title>Contact benchmark suite: verification report</title>",
            f"<style>{STYLE}</style></head><body>",
            "<h1>Contact benchmark suite: verification report</h1>",
            f"<p class='summary'><b>{html.escape(tally.line())}.</b> "
            f"Judged by {bands}. A judged check compares a result with a reference that holds "
            "for the case, within a stated band; a failure means a regression. A comparison row "
            "shows a result beside a reference that does not hold for the case (a half-space "
            "solution for finite bodies, an under-resolved FE result), with the difference and "
            "the reason, and no verdict. "
            f"Generated {time.strftime('%Y-%m-%d %H:%M')} from {html.escape(os.path.abspath(args.results))}. "
            "Units: N, mm, MPa. Benchmarks: FENET/NAFEMS advanced contact benchmarks (Konter, NAFEMS R0094).</p>"]
    if tally.not_run:
        page.append("<p class='fail'>Not run: " + html.escape(", ".join(tally.not_run)) + "</p>")
    page += body
    page.append("</body></html>")
    os.makedirs(args.results, exist_ok=True)
    report = os.path.join(args.results, "report.html")
    with open(report, "w") as f:
        f.write("\n".join(page))
    for line in tally.failures:
        print(line)
    for case in tally.not_run:
        print(f"NOT RUN {case}: no summary.json")
    print(f"report: {report} ({tally.line()})")
    return 0 if tally.ok() else 1


if __name__ == "__main__":
    sys.exit(main())
