#!/usr/bin/env python3
"""Write results/report.html: one self-contained page (images embedded, no
network) with, for each benchmark, its description, the headline numbers
beside their references with ratios and pass/fail against stated bands, the
plots, and the studies.

Each application folder holds a report.json (title, description, cases with
checks and plots, studies); results come from results/<app>/<case>/summary.json.

Usage: scripts/make_report.py [--results DIR]
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
body { font-family: sans-serif; max-width: 1100px; margin: 2em auto; color: #222; line-height: 1.45; }
h1 { border-bottom: 2px solid #446; padding-bottom: .3em; }
h2 { margin-top: 2em; border-bottom: 1px solid #ccd; }
table { border-collapse: collapse; margin: 1em 0; font-size: 0.92em; }
th, td { border: 1px solid #ccd; padding: .3em .6em; text-align: right; }
th { background: #eef; }
td.l, th.l { text-align: left; }
.pass { color: #075; font-weight: bold; }
.fail { color: #b00; font-weight: bold; }
figure { margin: 1em 0; }
figcaption { font-size: .9em; color: #555; }
img { max-width: 100%; border: 1px solid #ddd; }
.summary { background: #f6f6fb; padding: .6em 1em; border-left: 4px solid #446; }
"""


def lookup(summary, path):
    value = summary
    for key in path.split("."):
        value = value[key]
    return value


def image(path, caption):
    if not os.path.exists(path):
        return f"<p class='fail'>missing plot: {html.escape(os.path.basename(path))}</p>"
    with open(path, "rb") as f:
        data = base64.b64encode(f.read()).decode()
    return (f"<figure><img alt='{html.escape(caption)}' src='data:image/png;base64,{data}'>"
            f"<figcaption>{html.escape(caption)}</figcaption></figure>")


def case_section(app, name, case, results):
    directory = os.path.join(results, app, name)
    summary_file = os.path.join(directory, "summary.json")
    out = [f"<h3>{html.escape(case['label'])} <small>({html.escape(name)})</small></h3>"]
    if not os.path.exists(summary_file):
        out.append("<p class='fail'>not run: no summary.json</p>")
        return out, 0, 1
    with open(summary_file) as f:
        summary = json.load(f)
    m = summary["mesh"]
    n = summary["newton"]
    t = summary["timing_s"]
    out.append(f"<p>{m['n_dofs']} degrees of freedom, {m['n_active_cells']} cells, "
               f"smallest cell in the contact zone {m['smallest_cell_in_contact_zone_mm']:.3g} mm; "
               f"Newton iterations per load step {n['iterations_per_step']}, "
               f"{n['n_cutbacks']} cutbacks; run time {t['total_s']:.2f} s"
               + (f", cost of contact {t['contact_cost_ratio']:.2f} x one fixed-set solve"
                  if "contact_cost_ratio" in t else "") + ".</p>")
    out.append("<table><tr><th class='l'>quantity</th><th>result</th><th>reference</th>"
               "<th>ratio</th><th>band</th><th>verdict</th></tr>")
    passed = failed = 0
    for check in case["checks"]:
        value = lookup(summary, check["value"])
        reference = lookup(summary, check["reference"])
        ratio = value / reference
        ok = abs(ratio - 1.0) <= check["band"]
        passed += ok
        failed += not ok
        out.append(f"<tr><td class='l'>{html.escape(check['label'])}</td><td>{value:.6g}</td>"
                   f"<td>{reference:.6g}</td><td>{ratio:.5f}</td><td>&plusmn;{check['band']:.2g}</td>"
                   f"<td class='{'pass' if ok else 'fail'}'>{'pass' if ok else 'FAIL'}</td></tr>")
    out.append("</table>")
    for file, caption in case.get("plots", []):
        out.append(image(os.path.join(directory, file), caption))
    return out, passed, failed


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
        return out + ["<p class='fail'>study not run</p>"]
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
               ("l2_error_pressure", "L2 error p"), ("contact_cost_ratio", "cost")]
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


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", default=os.path.join(ROOT, "results"))
    args = parser.parse_args()

    body, total_pass, total_fail = [], 0, 0
    for app in APPS:
        meta_file = os.path.join(ROOT, app, "report.json")
        if not os.path.exists(meta_file):
            continue
        with open(meta_file) as f:
            meta = json.load(f)
        body.append(f"<h2>{html.escape(meta['title'])}</h2>")
        body += [f"<p>{html.escape(p)}</p>" for p in meta["description"]]
        for name, case in meta["cases"].items():
            lines, p, fl = case_section(app, name, case, args.results)
            body += lines
            total_pass += p
            total_fail += fl
        for study in meta.get("studies", []):
            body += study_section(study, args.results)

    page = ["<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>",
            "<title>Contact benchmark suite: verification report</title>",
            f"<style>{STYLE}</style></head><body>",
            "<h1>Contact benchmark suite: verification report</h1>",
            f"<p class='summary'>{total_pass} checks pass, {total_fail} fail. "
            f"Generated {time.strftime('%Y-%m-%d %H:%M')} from {html.escape(os.path.abspath(args.results))}. "
            "Units: N, mm, MPa. Benchmarks: FENET/NAFEMS advanced contact benchmarks (Konter, NAFEMS R0094).</p>"]
    page += body
    page.append("</body></html>")
    os.makedirs(args.results, exist_ok=True)
    report = os.path.join(args.results, "report.html")
    with open(report, "w") as f:
        f.write("\n".join(page))
    print(f"report: {report} ({total_pass} checks pass, {total_fail} fail)")
    return 0 if total_fail == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
