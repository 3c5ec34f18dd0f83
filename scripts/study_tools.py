"""Helpers shared by the study scripts (accuracy against time, mesh studies).

A study runs one application on variants of a production parameter file
(the variant includes the production file and overrides a few entries),
reads each run's summary.json, and writes a CSV table and log-log gnuplot
plots of error against wall time.
"""
import csv
import json
import os
import shutil
import signal
import subprocess
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def enforcement_label(enforcement):
    """'lm' or 'penalty:<stiffness>' as a legend label."""
    if enforcement == "lm":
        return "Lagrange multipliers"
    return "penalty %s MPa/mm" % enforcement.split(":")[1]


def enforcement_tag(enforcement):
    """'lm' or 'penalty:<stiffness>' as part of a file name."""
    return enforcement.replace(":", "")


def run_variant(app, production, case_dir, overrides):
    """Run app on production with the subsections in overrides.

    overrides maps a subsection name to a dict of entries (a nested
    subsection is named with its path, "Load program/Stage 1"); the Output
    subsection (directory case_dir, no graphical output, no plots, quiet)
    is added. Returns (summary.json as a dict, wall time in seconds).
    """
    summary, wall, _ = run_variant_measured(app, production, case_dir, overrides)
    return summary, wall


class TimeLimitExceeded(Exception):
    """A run stopped at its time limit (run_variant_measured())."""


def run_variant_measured(app, production, case_dir, overrides, launcher=(),
                         time_limit=None):
    """As run_variant(), and also the run's peak resident memory (MB).

    launcher: a command prefix, e.g. ("mpirun", "-np", "2"); the peak memory
    is then that of the largest process. time_limit: seconds after which the
    run (its whole process group) is killed and TimeLimitExceeded raised.
    Returns (summary.json as a dict, wall time in seconds, peak memory in MB).
    """
    os.makedirs(case_dir, exist_ok=True)
    sections = dict(overrides)
    sections["Output"] = {"Output directory": case_dir,
                          "Write graphical output": "false",
                          "Write plots": "false",
                          "Verbosity": "quiet"}
    text = f"include {production}\n"
    for name, entries in sections.items():
        path = name.split("/")
        text += "".join(f"subsection {part}\n" for part in path)
        text += "".join(f"  set {k} = {v}\n" for k, v in entries.items())
        text += "end\n" * len(path)
    prm = os.path.join(case_dir, "case.prm")
    with open(prm, "w") as f:
        f.write(text)
    start = time.time()
    process = subprocess.Popen([*launcher, app, prm], stdout=subprocess.DEVNULL,
                               start_new_session=True)
    while True:
        pid, status, usage = os.wait4(process.pid, os.WNOHANG)
        if pid != 0:
            break
        if time_limit is not None and time.time() - start > time_limit:
            os.killpg(process.pid, signal.SIGKILL)
            os.wait4(process.pid, 0)
            raise TimeLimitExceeded(f"{app} {prm}: stopped after {time_limit} s")
        time.sleep(0.2)
    wall = time.time() - start
    process.returncode = os.waitstatus_to_exitcode(status)
    if process.returncode != 0:
        raise subprocess.CalledProcessError(process.returncode, [app, prm])
    with open(os.path.join(case_dir, "summary.json")) as f:
        return json.load(f), wall, usage.ru_maxrss / 1024.


def contact_overrides(enforcement):
    """The Contact subsection entries selecting an enforcement."""
    if enforcement == "lm":
        return {"Enforcement": "lagrange multiplier"}
    return {"Enforcement": "penalty",
            "Penalty stiffness": enforcement.split(":")[1]}


def write_table(path, rows):
    """Write rows (dicts) as CSV: the columns are every key, in the order of
    first appearance; a row without a key leaves its cell empty."""
    fieldnames = []
    for row in rows:
        fieldnames += [key for key in row if key not in fieldnames]
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fieldnames, restval="")
        writer.writeheader()
        writer.writerows(rows)


def loglog_plot(out_dir, stem, title, xlabel, ylabel, series, extra="", logscale="xy"):
    """Write <stem>.gp and, if gnuplot exists, <stem>.png in out_dir.

    series: gnuplot plot clauses ("'file.csv' using 1:2 with ... title ...");
    extra: further gnuplot commands before the plot; logscale: the axes
    with a logarithmic scale ("xy", or "x" for a linear y axis).
    """
    script = os.path.join(out_dir, f"{stem}.gp")
    with open(script, "w") as f:
        f.write("set terminal pngcairo size 900,600 enhanced font 'Sans,11'\n"
                f"set output '{stem}.png'\n"
                "set datafile separator ','\n"
                f"set logscale {logscale}\nset grid\nset key outside right top\n"
                "set format y \"%g\"\n"
                f"set title \"{title}\"\n"
                f"set xlabel \"{xlabel}\"\n"
                f"set ylabel \"{ylabel}\"\n" + extra +
                "plot " + ", \\\n     ".join(series) + "\n")
    if shutil.which("gnuplot"):
        subprocess.run(["gnuplot", os.path.basename(script)], cwd=out_dir, check=True)
