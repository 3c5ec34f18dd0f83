#!/usr/bin/env python3
"""Fuzzed input: mutations of an application's production parameter file.

For each application, generates --count mutations (seeded: the same --seed
gives the same files) of its production .prm, runs the executable on each,
one run at a time, with a time limit and a memory limit, and classifies
the outcome:

  rejected  exit code != 0, exactly one line on standard error,
            '<app>: error: ...', that names the mutated entry or the
            problem (see "Naming"), and no result file that looks valid
            (summary.json, a CSV file named *profile*, a PNG plot) anywhere
            in the run's directory;
  ran       exit code 0, results/summary.json present and valid JSON, no
            NaN or inf in it or in any CSV file; for the mutations that
            must not change the results (expectation 'same' below), the
            same summary as the unmutated file's (timings aside);
  running   a valid mutation whose run is still making progress at the time
            limit (its standard output grew in the last third of the time
            limit, or it used processor time for at least a quarter of that
            third): accepted input that takes long, e.g. a million load
            steps; stopped, and not a defect;
  DEFECT    anything else, by class:
              crash             killed by a signal;
              stderr            exit != 0 without exactly one line
                                '<app>: error: ...' on standard error;
              results left      a refused or failed run left summary.json,
                                a profile CSV or a PNG;
              naming            the line names neither the entry nor the
                                problem;
              non-finite solve  accepted input made the solution non-finite
                                (the line reports it, naming no entry): an
                                unchecked value;
              not converged     the solution of accepted input failed (no
                                Newton convergence, linear solver failure),
                                the line naming no entry;
              no summary        exit 0 without summary.json;
              non-finite        a NaN or inf in an output of a run that
                                succeeded (those of the unmutated file are
                                reported once, as its own defect, not with
                                every mutation);
              accepted          input that must be refused runs, or a
                                malformed value runs with results other
                                than the unmutated file's (it was read as
                                something);
              hang              stopped at the time limit without progress;
              memory            stopped at --memory-limit;
              huge mesh         a huge mesh not refused within
                                --huge-time-limit, or stopped at the memory
                                limit.

The unmutated file. Production meshes run for minutes, so the mutations are
applied to the production file with the entries of the application's
coarse test case set in it (tests/<app>/*coarse*.prm.in; for sheet_forming
the mesh and step size of tests/sheet_forming/extrapolated_initial_guess.sh
over the first 1 mm of the stroke; table APPS): the production file's text,
comments and order, with those values replaced. Its Output subsection is
set to write into the run's directory ('Output directory = results',
relative to the run's working directory, which is the run's directory, so
that the default of a deleted or truncated entry lands there too), with
plots, without ParaView files. This file runs first (in seconds; a failure
stops the script): its summary is the reference of the 'same' mutations.
A valid value that makes a run long (many steps, the production mesh
restored by deleting a coarse entry) is stopped at --time-limit as
'running' while it makes progress.

Mutation kinds (share of --count; each kind at least once):

  value       a number set to -1, 0, -0, 1e-308, 1e308, -1e308, a million
              times its value (expectation 'either'), nan, inf, -inf, 1e309
              ('same'); an integer to -1, 0, 1000000, 4294967296 ('either')
              (35 %);
  type        a word, a number with a unit, '1,5', '0x10' or 'true' for a
              number; 2.5, 1e3, a word or two numbers for an integer; a
              number, a misspelt, upper-case or extended word for a
              selection; yes, 1, maybe, TRUE for a boolean; an empty value
              ('same'; an empty number where empty is valid and free text
              'either') (15 %);
  key         a misspelt key, a key in other case, an unknown key, a key of
              another subsection ('reject') (8 %);
  subsection  a misspelt or unknown subsection ('reject') (5 %);
  structure   an 'end' deleted or added, a 'set' without '= value', a line
              of garbage, an include of a missing file ('reject') (7 %);
  duplicate   an entry repeated with the same value, or after another valid
              value, a subsection repeated ('same'). deal.II's
              ParameterHandler takes the last value of a duplicated entry
              without a warning; that is accepted input here, and the run
              must give the unmutated file's results (7 %);
  delete      an entry or a subsection deleted ('either': its defaults
              apply, which is valid input) (10 %);
  file        the empty file and a file of comments only ('reject': must
              not run on the defaults), binary garbage ('reject'), the file
              truncated at a random byte ('either') (5 %);
  huge        the mesh counts at 1e6 and 2^32, and every mesh count at its
              largest allowed value with 'Grading factor' = 1e6, so that
              every cell is refined at every graded step (table APPS)
              ('refuse').

Expectations: 'reject' must be refused; 'either' may be refused or run;
'same' may be refused, or run with the unmutated file's results (the
malformed value belongs to an entry the case does not read); 'refuse' must
be refused within --huge-time-limit by a size check, not by running out of
memory.

Naming. The error line must contain (case-insensitive) one of the
mutation's names: the mutated entry's key (a stage's entry may also be
named by its stage, 'Load program/Stage 2'; a boundary id entry by its
value, 'Boundary id 7 does not exist'), the unknown key or subsection,
'subsection' or 'end' for an unbalanced file (deal.II's messages), 'line
<' for garbage, the key of any entry a truncated file lost, and 'empty',
'no entr' or 'missing' for an empty file (or one cut before its first
entry).

--ci selects a subset of the --count mutations for the test suite (at
least 30: the huge meshes of a single entry and the first one within the
bounds, then every kind in turn in the order drawn, leaving out the
mutations expected to run long); tests/fuzz runs it against the Debug
executables.

Prints one line per mutation, then per application a summary line (counts
per class) and every defect with its mutation and the run's directory
(case.prm, stdout.txt, stderr.txt); exits non-zero if any defect is found.

Usage: scripts/fuzz_prm.py [--app cgs_roller punch3d loaded_pin sheet_forming]
           [--build DIR | --executable FILE] [--production FILE]
           [--count 200] [--seed 1] [--time-limit 60] [--huge-time-limit 15]
           [--memory-limit 4000] [--ci] [--only N ...] [--list]
           [--work-dir DIR] [--summary FILE]
"""
import argparse
import csv
import json
import math
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import zlib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Per application: the production file (below parameters/), the entries of
# its coarse test case set into it (path, key, value; the path's parts are
# joined by '/'), and the huge meshes (a list of entry sets). The bounds of
# sheet_forming's mesh entries (at most 32 x 4000 cells) are a size check:
# its huge meshes are beyond them.
APPS = {
    "cgs_roller": {
        "production": "cgs_roller/hertz_frictionless.prm",
        "coarse": [("Mesh", "Number of contact refinements", "5"),
                   ("Run control", "Measure contact cost", "false"),
                   ("Load program/Stage 1", "Number of steps", "1")],
        "huge": [
            [("Mesh", "Number of global refinements", "1000000")],
            [("Mesh", "Number of contact refinements", "1000000")],
            [("Mesh", "Number of contact refinements", "4294967296")],
            [("Mesh", "Number of global refinements", "6"),
             ("Mesh", "Number of contact refinements", "14"),
             ("Mesh", "Grading factor", "1e6")],
        ],
    },
    "punch3d": {
        "production": "punch3d/punch_axisym_mu0.prm",
        "coarse": [("Mesh", "Number of contact refinements", "3"),
                   ("Mesh", "Number of edge refinements", "2")],
        "huge": [
            [("Mesh", "Number of global refinements", "1000000")],
            [("Mesh", "Number of edge refinements", "1000000")],
            [("Mesh", "Number of contact refinements", "4294967296")],
            [("Mesh", "Number of global refinements", "6"),
             ("Mesh", "Number of contact refinements", "12"),
             ("Mesh", "Number of edge refinements", "12"),
             ("Mesh", "Grading factor", "1e6")],
            [("Model", "Dimension", "3d quarter"),
             ("Mesh", "Number of global refinements", "6"),
             ("Mesh", "Grading factor", "1e6")],
        ],
    },
    "loaded_pin": {
        "production": "loaded_pin/loaded_pin_mu0.prm",
        "coarse": [("Mesh", "Element degree", "1"),
                   ("Mesh", "Number of contact refinements", "1")],
        "huge": [
            [("Mesh", "Number of global refinements", "1000000")],
            [("Mesh", "Number of pin layers", "1000000")],
            [("Mesh", "Number of sheet layers", "4294967296")],
            [("Mesh", "Number of global refinements", "6"),
             ("Mesh", "Number of contact refinements", "8"),
             ("Mesh", "Number of sheet layers", "16"),
             ("Mesh", "Number of pin layers", "32"),
             ("Mesh", "Grading factor", "1e6")],
        ],
    },
    "sheet_forming": {
        "production": "sheet_forming/sheet_forming_mu01342.prm",
        # As tests/sheet_forming/extrapolated_initial_guess.sh (2 x 30
        # cells, forming, then a hold step, no release), at its step size
        # but over the first 1 mm of the stroke instead of 4 mm: 2 steps.
        "coarse": [("Mesh", "Number of cells through the thickness", "2"),
                   ("Mesh", "Number of cells along the length", "30"),
                   ("Load program/Stage 1", "Number of steps", "2"),
                   ("Load program/Stage 1", "Punch displacement", "1"),
                   ("Load program/Stage 2", "Name", "hold"),
                   ("Load program/Stage 2", "Number of steps", "1"),
                   ("Load program/Stage 2", "Punch displacement", "1"),
                   ("Load program/Stage 2", "Die displacement", "0"),
                   ("Release", "Release stage", "0")],
        "huge": [
            [("Mesh", "Number of cells along the length", "1000000")],
            [("Mesh", "Number of cells through the thickness", "1000000")],
            [("Mesh", "Number of cells along the length", "4294967296")],
            [("Mesh", "Number of cells along the length", "1000000"),
             ("Mesh", "Number of cells through the thickness", "1000000")],
        ],
    },
    "reynolds_roller": {
        "production": "reynolds_roller/reynolds_roller_mu03.prm",
        # Pressing 1 mm in 2 steps, the bottom's release in 1 step and 2
        # degrees of the turn in 1 step on 30 x 2 cells (10 mm). A face is
        # paired only if all of it lies within the search distance of the
        # roller: with the production's 5 mm the faces beyond x = 10 mm
        # stay unpaired, inside the contact zone (half-width about 7.7 mm
        # at 1 mm), which then ends at the search region's edge; 10 mm
        # pairs the faces up to 20 mm.
        "coarse": [("Mesh", "Number of cells along the length", "30"),
                   ("Mesh", "Number of cells through the thickness", "2"),
                   ("Contact", "Search distance", "10"),
                   ("Load program/Stage 1", "Number of steps", "2"),
                   ("Load program/Stage 1", "Indentation", "1"),
                   ("Load program/Stage 2", "Number of steps", "1"),
                   ("Load program/Stage 2", "Indentation", "1"),
                   ("Load program/Stage 3", "Number of steps", "1"),
                   ("Load program/Stage 3", "Roller angle", "2")],
        "huge": [
            [("Mesh", "Number of cells along the length", "1000000")],
            [("Mesh", "Number of cells through the thickness", "1000000")],
            [("Mesh", "Number of cells along the length", "4294967296")],
            [("Mesh", "Number of cells along the length", "4000"),
             ("Mesh", "Number of cells through the thickness", "200")],
        ],
    },
}

OUTPUT = [("Output", "Output directory", "results"),
          ("Output", "Write graphical output", "false"),
          ("Output", "Write plots", "true"),
          ("Output", "Verbosity", "normal")]

# Entries that take free text (any value is valid), and entries whose
# value is a number or empty; the others are typed by their default.
FREE_TEXT = {"Name"}
NUMBER_OR_EMPTY = {"Load factor", "Punch displacement", "Die displacement", "Indentation",
                   "Roller angle"}
INTEGER_KEY = re.compile(r"^(Number of .*|Maximum (number of )?(iterations|augmentations)"
                         r"|Element degree|.*boundary id|Release stage|Bottom free in x from stage)$")
STRUCTURE_NAMES = ["subsection", "'end'"]
# An empty file is refused as empty, or for an entry it lacks.
EMPTY_NAMES = ["empty", "no entr", "missing"]

SHARES = [("value", 0.35), ("type", 0.15), ("key", 0.08), ("subsection", 0.05),
          ("structure", 0.07), ("duplicate", 0.07), ("delete", 0.10), ("file", 0.05)]


# ---------------------------------------------------------------------------
# Parameter files as lines

class Line:
    """One line of a parameter file: its text, its kind ('set',
    'subsection', 'end', 'other'), and for 'set' the subsection path, key
    and value; for 'subsection' the path of the subsection it opens."""

    def __init__(self, text, kind="other", path=(), key=None, value=None):
        self.text, self.kind, self.path, self.key, self.value = text, kind, path, key, value


def parse_lines(text):
    """The lines of a parameter file, with the subsection path of each."""
    lines, path = [], []
    for raw in text.split("\n"):
        body = raw.split("#", 1)[0].strip()
        words = body.split(None, 1)
        if words and words[0] == "subsection" and len(words) == 2:
            path.append(words[1].strip())
            lines.append(Line(raw, "subsection", tuple(path)))
        elif body == "end":
            lines.append(Line(raw, "end", tuple(path)))
            if path:
                path.pop()
        elif words and words[0] == "set" and "=" in body:
            key, value = body[3:].split("=", 1)
            lines.append(Line(raw, "set", tuple(path), key.strip(), value.strip()))
        else:
            lines.append(Line(raw, "other", tuple(path)))
    return lines


def render(lines):
    """The text of lines."""
    return "\n".join(line.text for line in lines)


def subsection_range(lines, path):
    """(index of the 'subsection' line, index of its 'end') of the first
    block of path, or None."""
    for i, line in enumerate(lines):
        if line.kind == "subsection" and line.path == path:
            depth = 0
            for j in range(i, len(lines)):
                if lines[j].kind == "subsection":
                    depth += 1
                elif lines[j].kind == "end":
                    depth -= 1
                    if depth == 0:
                        return i, j
    return None


def set_entry(lines, path, key, value):
    """Set key = value in subsection path: replace the value of its last
    'set' line (keeping the comment), or add a line at the end of the
    subsection, or add the subsection at the end of the file."""
    matches = [i for i, l in enumerate(lines) if l.kind == "set" and l.path == path
               and l.key == key]
    if matches:
        line = lines[matches[-1]]
        indent = line.text[:len(line.text) - len(line.text.lstrip())]
        comment = line.text.split("#", 1)[1] if "#" in line.text else None
        text = f"{indent}set {key} = {value}"
        if comment is not None:
            text += f"  #{comment}"
        lines[matches[-1]] = Line(text, "set", path, key, value)
        return lines
    for depth in range(len(path), 0, -1):
        found = subsection_range(lines, path[:depth])
        if found:
            _, end = found
            new = [Line("  " * (depth + k) + f"subsection {p}", "subsection",
                        path[:depth + k + 1]) for k, p in enumerate(path[depth:])]
            new.append(Line("  " * len(path) + f"set {key} = {value}", "set", path, key,
                            value))
            new += [Line("  " * (len(path) - k - 1) + "end", "end", path[:len(path) - k])
                    for k in range(len(path) - depth)]
            return lines[:end] + new + lines[end:]
    new = [Line("  " * k + f"subsection {p}", "subsection", path[:k + 1])
           for k, p in enumerate(path)]
    new.append(Line("  " * len(path) + f"set {key} = {value}", "set", path, key, value))
    new += [Line("  " * (len(path) - k - 1) + "end", "end", path[:len(path) - k])
            for k in range(len(path))]
    return lines + new


def base_text(production, coarse):
    """The production file with the coarse entries and the Output entries
    set in it."""
    with open(production) as f:
        lines = parse_lines(f.read().rstrip("\n"))
    for path, key, value in coarse + OUTPUT:
        lines = set_entry(lines, tuple(path.split("/")), key, value)
    return render(lines) + "\n"


def declared_entries(executable):
    """Every entry the application declares (--print-parameters): a list
    of (path, key, default)."""
    text = subprocess.run([executable, "--print-parameters"], capture_output=True,
                          text=True, check=True).stdout
    return [(l.path, l.key, l.value) for l in parse_lines(text) if l.kind == "set"]


# ---------------------------------------------------------------------------
# Mutations

class Mutation:
    """One mutated file: kind, a one-line description, the file's bytes,
    the names one of which a refusal must contain, and the expectation:
    'reject' (must be refused), 'either' (refused or runs), 'same'
    (refused, or runs with the results of the unmutated file: a malformed
    value of an entry the case does not read, or a duplicate whose last
    value is the original one) or 'refuse' (a huge mesh: refused quickly,
    no time or memory limit reached). long_run: a valid value that may
    make the run long (left out of the CI subset)."""

    def __init__(self, kind, description, data, names, expect, long_run=False,
                 first=False):
        self.kind, self.description, self.data = kind, description, data
        self.names, self.expect, self.long_run = names, expect, long_run
        # Drawn before the others of its kind.
        self.first = first


def format_path(path, key=None):
    return "/".join(path + ((key,) if key else ()))


def entry_type(key, default):
    if key in FREE_TEXT:
        return "text"
    if key in NUMBER_OR_EMPTY:
        return "number or empty"
    if default in ("true", "false"):
        return "bool"
    if INTEGER_KEY.match(key):
        return "integer"
    if default == "" and key == "Total force":
        return "number"
    try:
        float(default)
        return "number"
    except ValueError:
        pass
    if key in ("Hardening table", "Reaction boundary ids", "Output directory"):
        return "list"
    return "selection"


def entry_names(key, value, path=()):
    """The names a message about entry key (in subsection path) with value
    may use."""
    names = [key]
    if path and path[-1].startswith("Stage "):
        names.append(format_path(path))
    if key.endswith("boundary id") and value not in (None, ""):
        names.append(f"boundary id {value}")
    return names


def misspell(word, rng):
    """word with one letter dropped, doubled or swapped with the next (an
    empty word becomes a letter)."""
    if not word:
        return "x"
    letters = [i for i, c in enumerate(word) if c.isalpha()]
    i = rng.choice(letters) if letters else 0
    how = rng.choice(["drop", "double", "swap"])
    if how == "drop" and len(word) > 1:
        return word[:i] + word[i + 1:]
    if how == "swap" and i + 1 < len(word) and word[i] != word[i + 1]:
        return word[:i] + word[i + 1] + word[i] + word[i + 2:]
    return word[:i] + word[i] + word[i:]


def value_candidates(key, default, kind):
    """(value, expectation, long run) of the kind 'value' for an entry; a
    million times the value, or a million, may make a valid run long."""
    out = []
    if kind in ("number", "number or empty"):
        try:
            scaled = "%.6g" % (float(default) * 1e6) if float(default) != 0 else "1e6"
        except ValueError:
            scaled = "1e6"
        out += [(v, "either", False) for v in ["-1", "0", "-0", "1e-308", "1e308", "-1e308"]]
        out.append((scaled, "either", True))
        out += [(v, "same", False) for v in ["nan", "inf", "-inf", "1e309"]]
    elif kind == "integer":
        out += [("-1", "either", False), ("0", "either", False),
                ("1000000", "either", True), ("4294967296", "either", True)]
    return out


def type_candidates(key, default, kind, rng):
    """(value, expectation) pairs of the kind 'type' for an entry."""
    if kind in ("number", "number or empty"):
        out = [("abc", "same"), ((default or "100") + " mm", "same"), ("1,5", "same"),
               ("0x10", "same"), ("true", "same")]
        out.append(("", "either" if kind == "number or empty" or default == "" else "same"))
    elif kind == "integer":
        out = [("2.5", "same"), ("1e3", "same"), ("two", "same"), ("", "same"),
               ("3 4", "same")]
    elif kind == "bool":
        out = [("yes", "same"), ("1", "same"), ("maybe", "same"), ("TRUE", "same"),
               ("", "same")]
    elif kind == "selection":
        out = [(misspell(default, rng), "same"), ("1", "same"),
               (default.upper(), "same"), ("", "same"), (default + " x", "same")]
    elif kind == "list":
        out = [("abc", "same"), ("1:2:3", "same"), ("-1", "same")]
    else:
        out = [("\u00e4\u00f6\u00fc \u2603", "either"), ("x" * 5000, "either")]
    return out


def with_entry(base, path, key, value):
    return render(set_entry(parse_lines(base.rstrip("\n")), path, key, value)) + "\n"


def generate(app, base, entries, count, seed):
    """count mutations of base (the coarse production text) for app;
    entries: the declared entries."""
    rng = random.Random(seed * 1000003 + zlib.crc32(app.encode()))
    lines = parse_lines(base.rstrip("\n"))
    base_values = {(l.path, l.key): l.value for l in lines if l.kind == "set"}
    # The load program's stages up to one beyond those the file counts.
    n_stages = int(base_values.get((("Load program",), "Number of stages"), 1))
    targets = [(p, k, d) for p, k, d in entries if p != ("Output",) and not (
        p[-1].startswith("Stage ") and int(p[-1].split()[1]) > n_stages + 1)]
    set_lines = [i for i, l in enumerate(lines) if l.kind == "set" and l.path != ("Output",)]
    subsections = sorted({l.path for l in lines if l.kind == "subsection"})
    pools = {name: [] for name, _ in SHARES}
    defaults = {(p, k): d for p, k, d in entries}
    coarse = {(tuple(p.split("/")), k) for p, k, _ in APPS[app]["coarse"]}

    def effective(path, key, default):
        return base_values.get((path, key), default)

    for path, key, default in targets:
        kind = entry_type(key, default)
        value = effective(path, key, default)
        for v, expect, long_run in value_candidates(key, value, kind):
            pools["value"].append(Mutation(
                "value", f"{format_path(path, key)} = {v}",
                with_entry(base, path, key, v), entry_names(key, v, path), expect, long_run))
        for v, expect in type_candidates(key, value, kind, rng):
            shown = v if len(v) < 40 else v[:10] + f"... ({len(v)} characters)"
            pools["type"].append(Mutation(
                "type", f"{format_path(path, key)} = {shown!r}",
                with_entry(base, path, key, v), entry_names(key, v, path), expect))

    for i in set_lines:
        line = lines[i]
        # Misspelt key, key in the wrong case.
        wrong = misspell(line.key, rng)
        text = lines[:i] + [Line(line.text.replace(line.key, wrong, 1))] + lines[i + 1:]
        pools["key"].append(Mutation("key", f"{format_path(line.path, line.key)} misspelt "
                                     f"'{wrong}'", render(text) + "\n", [wrong], "reject"))
        lower = line.key.lower() if line.key != line.key.lower() else line.key.upper()
        text = lines[:i] + [Line(line.text.replace(line.key, lower, 1))] + lines[i + 1:]
        pools["key"].append(Mutation("key", f"{format_path(line.path, line.key)} as "
                                     f"'{lower}'", render(text) + "\n", [lower], "reject"))
        # Duplicates: the same line again; another valid value first.
        text = lines[:i + 1] + [line] + lines[i + 1:]
        pools["duplicate"].append(Mutation(
            "duplicate", f"{format_path(line.path, line.key)} twice",
            render(text) + "\n", entry_names(line.key, line.value), "same"))
        try:
            other = "%.6g" % (2 * float(line.value))
            if float(other) == float(line.value):
                raise ValueError(other)
            first = Line(line.text.replace(line.value, other, 1) if line.value else
                         line.text + other)
            text = lines[:i] + [first] + lines[i:]
            pools["duplicate"].append(Mutation(
                "duplicate", f"{format_path(line.path, line.key)} = {other}, then "
                f"= {line.value} (the last value holds)", render(text) + "\n",
                entry_names(line.key, line.value), "same"))
        except ValueError:
            pass
        # Deleted: the default applies (for the coarse entries, the fine
        # production mesh or load program may come back: a long run).
        default = defaults.get((line.path, line.key))
        text = lines[:i] + lines[i + 1:]
        pools["delete"].append(Mutation(
            "delete", f"{format_path(line.path, line.key)} deleted (default {default!r})",
            render(text) + "\n", entry_names(line.key, default), "either",
            long_run=(line.path, line.key) in coarse))
        # A 'set' without '='.
        text = lines[:i] + [Line(line.text.split("=")[0].rstrip())] + lines[i + 1:]
        pools["structure"].append(Mutation(
            "structure", f"{format_path(line.path, line.key)} without '= value'",
            render(text) + "\n", [line.key, "'set'"], "reject"))

    # Unknown key, key in another subsection.
    for path in subsections:
        start, end = subsection_range(lines, path)
        unknown = rng.choice(["Colour", "Number of cellz", "Youngs modulus", "Tolerence"])
        text = lines[:end] + [Line(f"  set {unknown} = 1")] + lines[end:]
        pools["key"].append(Mutation("key", f"{format_path(path)}: unknown key '{unknown}'",
                                     render(text) + "\n", [unknown], "reject"))
        declared_here = {k for p, k, _ in entries if p == path}
        foreign = sorted({k for p, k, _ in entries if p != path and k not in declared_here})
        if foreign:
            key = rng.choice(foreign)
            text = lines[:end] + [Line(f"  set {key} = 1")] + lines[end:]
            pools["key"].append(Mutation("key", f"{format_path(path)}: key '{key}' of "
                                         "another subsection", render(text) + "\n", [key],
                                         "reject"))
        # Misspelt subsection name.
        wrong = misspell(path[-1], rng)
        text = (lines[:start] + [Line(lines[start].text.replace(path[-1], wrong, 1))] +
                lines[start + 1:])
        pools["subsection"].append(Mutation(
            "subsection", f"subsection {format_path(path)} misspelt '{wrong}'",
            render(text) + "\n", [wrong], "reject"))
        # Whole subsection deleted; whole subsection repeated.
        if len(path) == 1 and path != ("Output",):
            text = lines[:start] + lines[end + 1:]
            names = [path[-1]]
            for l in lines[start:end]:
                if l.kind == "set":
                    names += entry_names(l.key, defaults.get((l.path, l.key)))
            pools["delete"].append(Mutation(
                "delete", f"subsection {format_path(path)} deleted",
                render(text) + "\n", names, "either",
                long_run=any(p[:1] == path for p, _ in coarse)))
            text = lines[:end + 1] + lines[start:end + 1] + lines[end + 1:]
            pools["duplicate"].append(Mutation(
                "duplicate", f"subsection {format_path(path)} twice", render(text) + "\n",
                [path[-1]], "same"))
        # Unknown subsection inside this one.
        name = rng.choice(["Solver", "Meshes", "Stage 7", "Contact", "Output"])
        if name not in {p[-1] for p, _, _ in entries if p[:-1] == path}:
            text = lines[:end] + [Line(f"  subsection {name}"), Line("    set Value = 1"),
                                  Line("  end")] + lines[end:]
            pools["subsection"].append(Mutation(
                "subsection", f"unknown subsection {format_path(path + (name,))}",
                render(text) + "\n", [name], "reject"))
    for name in ["Materials", "Friction", "Geometrie", "mesh"]:
        at = rng.choice([i for i, l in enumerate(lines) if l.kind == "subsection"
                         and len(l.path) == 1])
        text = lines[:at] + [Line(f"subsection {name}"), Line("  set Young's modulus = 1"),
                             Line("end")] + lines[at:]
        pools["subsection"].append(Mutation(
            "subsection", f"unknown subsection {name}", render(text) + "\n", [name],
            "reject"))

    # Structure: an 'end' deleted or added, a line of garbage.
    ends = [i for i, l in enumerate(lines) if l.kind == "end"]
    last, middle = ends[-1], rng.choice(ends[:-1])
    for i in ends:
        text = lines[:i] + lines[i + 1:]
        pools["structure"].append(Mutation(
            "structure", f"'end' of subsection {format_path(lines[i].path)} (line {i + 1}) "
            "deleted", render(text) + "\n", STRUCTURE_NAMES, "reject", first=i == last))
        text = lines[:i + 1] + [Line("end")] + lines[i + 1:]
        pools["structure"].append(Mutation(
            "structure", f"extra 'end' after line {i + 1}", render(text) + "\n",
            STRUCTURE_NAMES, "reject", first=i == middle))
    for garbage in ["subsection", "set = 1", "= 1", "sett Tolerance = 1", "end end",
                    "include does_not_exist.prm"]:
        at = rng.choice(set_lines)
        text = lines[:at] + [Line("  " + garbage)] + lines[at:]
        names = ["does_not_exist.prm"] if "include" in garbage else ["line <"]
        pools["structure"].append(Mutation(
            "structure", f"line '{garbage}' before line {at + 1}", render(text) + "\n",
            names, "reject"))

    # Files.
    data = base.encode()
    pools["file"].append(Mutation("file", "empty file", b"", EMPTY_NAMES, "reject",
                                  first=True))
    pools["file"].append(Mutation(
        "file", "comments and blank lines only",
        b"".join(b"# " + l.text.encode() + b"\n\n" for l in lines[:20]),
        EMPTY_NAMES, "reject", first=True))
    for size in [4096, 64]:
        garbage = bytes(rng.getrandbits(8) for _ in range(size))
        pools["file"].append(Mutation(
            "file", f"binary file ({size} random bytes, seed {seed})", garbage,
            ["line <", "binary"], "reject", first=True))
    for k in range(8):
        cut = rng.randrange(1, len(data))
        kept = data[:cut].decode(errors="replace").split("\n")
        names = STRUCTURE_NAMES + ["line <"]
        for l in lines[len(kept) - 1:]:
            if l.kind == "set":
                names += entry_names(l.key, defaults.get((l.path, l.key)))
        # Cut before its first entry, the file is as good as empty.
        if all(l.kind != "set" for l in lines[:len(kept) - 1]):
            names += EMPTY_NAMES
        pools["file"].append(Mutation(
            "file", f"truncated after byte {cut} of {len(data)} ('{kept[-1].strip()[-30:]}')",
            data[:cut], names, "either"))

    # Huge meshes.
    huge = []
    for entries_set in APPS[app]["huge"]:
        text = base
        for path, key, value in entries_set:
            text = with_entry(text, tuple(path.split("/")), key, value)
        huge.append(Mutation(
            "huge", ", ".join(f"{format_path(tuple(p.split('/')), k)} = {v}"
                              for p, k, v in entries_set),
            text.encode(), sum((entry_names(k, v) for _, k, v in entries_set), []),
            "refuse"))

    # Draw: every huge mesh, then each kind's share of the rest.
    mutations = list(huge)
    rest = max(count - len(huge), len(SHARES))
    quotas = {name: max(1, int(round(share * rest))) for name, share in SHARES}
    quotas["value"] += rest - sum(quotas.values())
    for name, _ in SHARES:
        pool = pools[name]
        rng.shuffle(pool)
        pool.sort(key=lambda m: not m.first)
        mutations += pool[:quotas[name]]
    for m in mutations:
        if isinstance(m.data, str):
            m.data = m.data.encode()
    return mutations


def ci_subset(mutations, size):
    """At least size mutations: the huge meshes made of a single entry of
    1e6 or more and the first huge mesh within the bounds, then every
    kind in turn, in the order drawn, skipping those expected to run
    long."""
    huge = [m for m in mutations if m.kind == "huge"]
    chosen = [m for m in huge if len(m.description.split(",")) == 1]
    chosen += [m for m in huge if m not in chosen][:1]
    queues = {name: [m for m in mutations if m.kind == name and not m.long_run]
              for name, _ in SHARES}
    while len(chosen) < size and any(queues.values()):
        for name, _ in SHARES:
            if queues[name] and len(chosen) < size:
                chosen.append(queues[name].pop(0))
    return sorted(chosen, key=mutations.index)


# ---------------------------------------------------------------------------
# Running and classifying

RESULT_FILE = re.compile(r"(^summary\.json$|profile.*\.csv$|\.png$)")
SOLVER_FAILURE = re.compile(r"did not converge|did not reach the relative residual|"
                            r"minimum increment")


def resident_mb(pid):
    """Resident memory of process pid in MB (0 if it has ended)."""
    try:
        with open(f"/proc/{pid}/statm") as f:
            return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 2**20
    except (OSError, IndexError, ValueError):
        return 0.


def processor_s(pid):
    """Processor time (user and system) of process pid in seconds."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            fields = f.read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    except (OSError, IndexError, ValueError):
        return 0.


def run(executable, case_dir, time_limit, memory_limit, env=None):
    """Run executable on case_dir/case.prm in case_dir (with the environment
    env, default this process's), stopped (with its
    process group) at time_limit seconds or memory_limit MB. Returns (exit
    code or None if stopped, why stopped: None, 'time' or 'memory',
    whether a run stopped at the time limit was making progress in the
    last third of it (its standard output grew, or it used processor time
    for at least a quarter of that third; a run waiting idle does not),
    wall time)."""
    stdout_path = os.path.join(case_dir, "stdout.txt")
    with open(stdout_path, "wb") as out, \
         open(os.path.join(case_dir, "stderr.txt"), "wb") as err:
        start = time.time()
        process = subprocess.Popen([executable, "case.prm"], cwd=case_dir, stdout=out,
                                   stderr=err, stdin=subprocess.DEVNULL,
                                   start_new_session=True, env=env)
        last_size, last_growth, stopped, samples = 0, start, None, []
        while process.poll() is None:
            now = time.time()
            size = os.path.getsize(stdout_path)
            if size != last_size:
                last_size, last_growth = size, now
            samples.append((now, processor_s(process.pid)))
            if resident_mb(process.pid) > memory_limit:
                stopped = "memory"
            elif now - start > time_limit:
                stopped = "time"
            if stopped:
                os.killpg(process.pid, signal.SIGKILL)
                process.wait()
                break
            time.sleep(0.05)
        wall = time.time() - start
    progressing = False
    if stopped == "time":
        window = time_limit / 3
        then = next(cpu for t, cpu in samples if t >= samples[-1][0] - window)
        progressing = (samples[-1][0] - last_growth < window or
                       samples[-1][1] - then >= window / 4)
    return (None if stopped else process.returncode), stopped, progressing, wall


def non_finite_in_outputs(case_dir):
    """The NaN and inf values in the output files of a run (summary.json,
    CSV files), and the JSON files that do not parse: a list of
    (file relative to case_dir, place in the file, value)."""
    found = []
    for folder, _, files in os.walk(case_dir):
        for name in sorted(files):
            path = os.path.join(folder, name)
            relative = os.path.relpath(path, case_dir)
            if name.endswith(".json"):
                bad = []
                try:
                    with open(path) as f:
                        json.load(f, parse_constant=lambda token: bad.append(token))
                except ValueError as error:
                    found.append((relative, "", f"not valid JSON ({error})"))
                found += [(relative, "", token) for token in bad]
            elif name.endswith(".csv"):
                with open(path, newline="", errors="replace") as f:
                    for r, row in enumerate(csv.reader(f), 1):
                        for c, cell in enumerate(row, 1):
                            try:
                                value = float(cell)
                            except ValueError:
                                continue
                            if not math.isfinite(value):
                                found.append((relative, f"line {r}, column {c}", cell.strip()))
    return found


def read_summary(case_dir):
    """results/summary.json of a run without its timings."""
    with open(os.path.join(case_dir, "results", "summary.json")) as f:
        summary = json.load(f)
    summary.pop("timing_s", None)
    return summary


def differences(reference, other, path=""):
    """The keys (paths) whose values differ between two summaries."""
    if isinstance(reference, dict) and isinstance(other, dict):
        return sum((differences(reference.get(k), other.get(k), f"{path}/{k}")
                    for k in sorted(set(reference) | set(other))), [])
    if isinstance(reference, list) and isinstance(other, list) and len(reference) == len(
            other):
        return sum((differences(a, b, f"{path}[{i}]")
                    for i, (a, b) in enumerate(zip(reference, other))), [])
    if (isinstance(reference, (int, float)) and isinstance(other, (int, float))
            and not isinstance(reference, bool)):
        return [] if math.isclose(reference, other, rel_tol=1e-9) else [
            f"{path} {reference:g} -> {other:g}"]
    return [] if reference == other else [f"{path} {reference!r} -> {other!r}"]


def classify(app, mutation, case_dir, code, stopped, progressing, base_summary,
             base_non_finite):
    """(class, detail): class 'rejected', 'ran', 'running' or a defect
    class: 'crash', 'stderr' (not one line '<app>: error: ...'),
    'results left', 'naming' (the line names neither the entry nor the
    problem), 'non-finite solve' and 'not converged' (the line reports that
    the solution of accepted input became non-finite or did not converge,
    without naming an entry), 'no summary', 'non-finite' (a NaN or inf in
    an output), 'accepted' (input that must be refused runs, or a
    malformed value is read), 'hang', 'memory', 'huge mesh'.
    base_summary: the unmutated file's summary (read_summary());
    base_non_finite: its NaN and inf values (non_finite_in_outputs()),
    which are reported once, not with each mutation."""
    with open(os.path.join(case_dir, "stderr.txt"), "rb") as f:
        stderr = f.read().decode(errors="replace")
    lines = [l for l in stderr.split("\n") if l.strip()]
    left = sorted(os.path.relpath(os.path.join(folder, name), case_dir)
                  for folder, _, files in os.walk(case_dir) for name in files
                  if RESULT_FILE.search(name))
    if stopped == "memory":
        return ("huge mesh" if mutation.kind == "huge" else "memory",
                "stopped at the memory limit")
    if stopped == "time":
        if mutation.kind == "huge":
            return "huge mesh", "not refused: still running at the time limit"
        if progressing and mutation.expect == "either":
            return "running", ("still making progress at the time limit (output or "
                               "processor time)")
        if progressing:
            return "accepted", "must be refused, but runs (still running at the time limit)"
        return "hang", "no progress printed in the last third of the time limit"
    if code < 0:
        return "crash", f"killed by signal {signal.Signals(-code).name}" + (
            f"; stderr: {lines[-1][:200]}" if lines else "")
    if code == 0:
        if mutation.expect in ("reject", "refuse"):
            return "accepted", "must be refused, but exits 0"
        if not os.path.isfile(os.path.join(case_dir, "results", "summary.json")):
            return "no summary", "exit 0 without results/summary.json"
        bad = [b for b in non_finite_in_outputs(case_dir) if b not in base_non_finite]
        if bad:
            return "non-finite", "; ".join(f"{f} {where}: {value}".replace(" :", ":")
                                           for f, where, value in bad[:3])
        if mutation.expect == "same":
            changed = sorted(differences(base_summary, read_summary(case_dir)),
                             key=lambda d: not d.startswith("/results"))
            if changed:
                return "accepted", (f"runs, with {len(changed)} values of summary.json other "
                                    "than the unmutated file's (the value is read): "
                                    + "; ".join(changed[:3]))
        return "ran", ""
    if len(lines) != 1 or stderr.count("\n") > 1:
        return "stderr", f"exit {code}, {len(lines)} lines on stderr: " + " | ".join(
            l[:160] for l in lines[:4])
    line = lines[0]
    if not line.startswith(f"{app}: error: "):
        return "stderr", f"exit {code}, line not of the form '{app}: error: ...': {line[:200]}"
    if left:
        return "results left", f"{', '.join(left[:4])} after: {line[:200]}"
    lower = " ".join(line.lower().split())
    if any(" ".join(name.lower().split()) in lower for name in mutation.names):
        return "rejected", line[len(app) + 9:][:160]
    if "non-finite" in lower:
        return "non-finite solve", line[:240]
    if SOLVER_FAILURE.search(lower):
        return "not converged", line[:240]
    return "naming", f"names none of {mutation.names[:3]}: {line[:240]}"


def fuzz_app(app, executable, production, args):
    """Generate, run and classify the mutations of one application.
    Returns the list of (index, mutation, class, detail, wall time)."""
    base = base_text(production, APPS[app]["coarse"])
    entries = declared_entries(executable)
    mutations = generate(app, base, entries, args.count, args.seed)
    indices = list(range(1, len(mutations) + 1))
    if args.ci:
        subset = ci_subset(mutations, max(30, args.ci_count))
        indices = [mutations.index(m) + 1 for m in subset]
    if args.only:
        indices = [i for i in indices if i in args.only]
    if args.list:
        for i in indices:
            m = mutations[i - 1]
            print(f"{app} [{i}] {m.kind} ({m.expect}): {m.description}")
        return []
    work = os.path.join(args.work_dir, app)
    os.makedirs(work, exist_ok=True)
    outcomes = []
    width = len(str(len(mutations)))
    print(f"{app}: {len(indices)} of {len(mutations)} mutations (seed {args.seed}) of "
          f"{os.path.relpath(production, ROOT)} with its coarse test entries, "
          f"{executable}, time limit {args.time_limit:g} s", flush=True)

    # The unmutated file must run: its results are the reference of the
    # mutations expected to leave them unchanged.
    case_dir = os.path.join(work, "base")
    shutil.rmtree(case_dir, ignore_errors=True)
    os.makedirs(case_dir)
    with open(os.path.join(case_dir, "case.prm"), "w") as f:
        f.write(base)
    code, stopped, _, wall = run(executable, case_dir, args.time_limit, args.memory_limit)
    if code != 0 or not os.path.isfile(os.path.join(case_dir, "results", "summary.json")):
        sys.exit(f"{app}: the unmutated file {case_dir}/case.prm does not run "
                 f"(exit {code}, {stopped or 'not stopped'}); see stderr.txt there")
    base_summary = read_summary(case_dir)
    base_non_finite = non_finite_in_outputs(case_dir)
    if base_non_finite:
        detail = "; ".join(f"{f} {where}: {value}".replace(" :", ":")
                           for f, where, value in base_non_finite[:3])
        unmutated = Mutation("base", "the unmutated file", base.encode(), [], "either")
        outcomes.append((0, unmutated, "non-finite", detail, wall, case_dir))
        print(f"  [{'base':>{width}}] {'DEFECT non-finite':20s} {wall:6.1f} s  the unmutated "
              f"file  -> {detail}", flush=True)
    else:
        print(f"  [{'base':>{width}}] {'ran':20s} {wall:6.1f} s  the unmutated file",
              flush=True)
    for i in indices:
        mutation = mutations[i - 1]
        case_dir = os.path.join(work, f"{i:0{width}d}_{mutation.kind}")
        shutil.rmtree(case_dir, ignore_errors=True)
        os.makedirs(case_dir)
        with open(os.path.join(case_dir, "case.prm"), "wb") as f:
            f.write(mutation.data)
        with open(os.path.join(case_dir, "mutation.txt"), "w") as f:
            f.write(f"{mutation.kind}: {mutation.description}\nexpect: {mutation.expect}\n"
                    f"names: {mutation.names}\n")
        limit = args.huge_time_limit if mutation.expect == "refuse" else args.time_limit
        code, stopped, progressing, wall = run(executable, case_dir, limit,
                                               args.memory_limit)
        status, detail = classify(app, mutation, case_dir, code, stopped, progressing,
                                  base_summary, base_non_finite)
        outcomes.append((i, mutation, status, detail, wall, case_dir))
        label = status if status in ("rejected", "ran", "running") else f"DEFECT {status}"
        print(f"  [{i:{width}d}] {label:20s} {wall:6.1f} s  {mutation.kind}: "
              f"{mutation.description[:90]}" + (f"  -> {detail[:150]}" if detail else ""),
              flush=True)
    return outcomes


def summarise(app, outcomes):
    """Print the summary line of app and its defects (those of the
    unmutated file, number 0, included); return the number of defects."""
    counts = {}
    for _, _, status, _, _, _ in outcomes:
        counts[status] = counts.get(status, 0) + 1
    defects = [o for o in outcomes if o[2] not in ("rejected", "ran", "running")]
    wall = sum(o[4] for o in outcomes)
    n_mutations = sum(1 for o in outcomes if o[0] > 0)
    print(f"{app}: {n_mutations} mutations, {counts.get('rejected', 0)} rejected, "
          f"{counts.get('ran', 0)} ran, {counts.get('running', 0)} running at the time "
          f"limit (accepted), {len(defects)} defects"
          + ("" if not defects else " (" + ", ".join(
              f"{counts[c]} {c}" for c in sorted(counts)
              if c not in ("rejected", "ran", "running")) + ")")
          + f", {wall:.0f} s")
    for i, mutation, status, detail, _, case_dir in defects:
        print(f"  DEFECT {status} [{i or 'base'}] {mutation.kind}: {mutation.description}\n"
              f"         {detail}\n         {case_dir}/case.prm")
    return len(defects)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--app", nargs="+", choices=sorted(APPS), default=list(APPS))
    parser.add_argument("--build", default=os.path.join(ROOT, "build-release"),
                        help="build directory holding <app>/<app>")
    parser.add_argument("--executable", help="the executable (with a single --app)")
    parser.add_argument("--production", help="the production .prm (with a single --app); "
                        "default: the table APPS")
    parser.add_argument("--count", type=int, default=200,
                        help="mutations per application")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--time-limit", type=float, default=60., help="seconds per run")
    parser.add_argument("--huge-time-limit", type=float, default=15.,
                        help="seconds within which a huge mesh must be refused")
    parser.add_argument("--memory-limit", type=float, default=4000.,
                        help="resident memory per run, MB")
    parser.add_argument("--ci", action="store_true",
                        help="only the CI subset of the --count mutations")
    parser.add_argument("--ci-count", type=int, default=30,
                        help="size of the CI subset (at least 30)")
    parser.add_argument("--only", type=int, nargs="+",
                        help="only these mutation numbers (as printed)")
    parser.add_argument("--list", action="store_true",
                        help="print the mutations (number, kind, description) and stop")
    parser.add_argument("--work-dir", help="where the runs go (default: a temporary "
                        "directory, removed at the end if no defect is found)")
    parser.add_argument("--summary", help="write the counts per application (mutations, "
                        "rejected, ran, running, defects, wall time) to this JSON file, "
                        "as the report's robustness section reads them; the applications not run "
                        "keep their entries")
    args = parser.parse_args()
    if (args.executable or args.production) and len(args.app) != 1:
        parser.error("--executable and --production need a single --app")
    for app in args.app:
        executable = args.executable or os.path.join(args.build, app, app)
        if not os.access(executable, os.X_OK):
            parser.error(f"no executable {executable}")
    temporary = args.work_dir is None
    if temporary:
        args.work_dir = tempfile.mkdtemp(prefix="fuzz_prm_")
    args.work_dir = os.path.abspath(args.work_dir)

    results = {}
    for app in args.app:
        executable = os.path.abspath(args.executable or os.path.join(args.build, app, app))
        production = os.path.abspath(args.production or os.path.join(
            ROOT, "parameters", APPS[app]["production"]))
        results[app] = fuzz_app(app, executable, production, args)
    if args.list:
        return
    print()
    n_defects = sum(summarise(app, outcomes) for app, outcomes in results.items())
    if args.summary:
        # The applications not run keep their earlier counts.
        table = {}
        if os.path.exists(args.summary):
            with open(args.summary) as f:
                table = json.load(f)
        for app, outcomes in results.items():
            statuses = [o[2] for o in outcomes if o[0] > 0]
            table[app] = {
                "mutations": len(statuses),
                "rejected": statuses.count("rejected"),
                "ran": statuses.count("ran"),
                "running": statuses.count("running"),
                "defects": sum(1 for o in outcomes
                               if o[2] not in ("rejected", "ran", "running")),
                "wall_time_s": round(sum(o[4] for o in outcomes), 1),
                "ci_subset": bool(args.ci),
                "seed": args.seed}
        os.makedirs(os.path.dirname(os.path.abspath(args.summary)), exist_ok=True)
        with open(args.summary, "w") as f:
            json.dump(table, f, indent=1)
    if temporary and n_defects == 0:
        shutil.rmtree(args.work_dir, ignore_errors=True)
    elif temporary:
        print(f"runs kept in {args.work_dir}")
    sys.exit(1 if n_defects else 0)


if __name__ == "__main__":
    main()
