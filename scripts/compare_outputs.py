#!/usr/bin/env python3
"""Runs the same compax cases with two binaries and compares their outputs.

For a refactoring (issue #16) the outputs must be equal: bit for bit where
the arithmetic is unchanged, otherwise within the solvers' tolerances. This
script runs every case with the reference binary and the candidate binary
into separate folders, then compares every CSV file the reference wrote,
column by column: a column is "identical" when every cell has the same text,
"close" when every number differs by at most --rtol relative to the
column's largest magnitude, and "DIFFERENT" otherwise. Timing columns and
files (wall_seconds, timing.csv, time_s ...) are skipped: they measure the
machine, not the physics. Other files (Markdown, HDF5, VTU) are compared
byte-wise and reported, but do not fail the comparison (they hold times and
paths).

Usage:
  scripts/compare_outputs.py REFERENCE_COMPAX CANDIDATE_COMPAX WORKDIR
      [--cases quick|all|NAME,...] [--rtol 1e-6] [--jobs 1]

Exit status: 0 when every CSV column is identical or close, 1 otherwise,
2 on bad input.
"""

import argparse
import csv
import filecmp
import math
import os
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
PRM = ROOT / "apps" / "parameters"

# name: (command, parameter file or None for the built-in default).
# "quick" cases run in about a minute each on two cores; "all" adds the
# shipped studies that take longer.
QUICK = {
    "contact-default": ("contact", None),
    "contact-material1": ("contact", "contact_material1_pair.prm"),
    "die-default": ("die", None),
    "rve-default": ("rve", None),
    "rve-hydrostatic": ("rve", "rve_hydrostatic.prm"),
    "rve-csv-path": ("rve", "rve_csv_path.prm"),
    "database-default": ("database", None),
    "tablet-default": ("tablet", None),
    "tablet-multiscale": ("tablet", "tablet_multiscale.prm"),
    "tablet-elastic-janssen": ("tablet", "tablet_elastic_janssen.prm"),
    "compare-default": ("compare", None),
    "crystal-default": ("crystal", None),
}
LONGER = {
    "die-nonlocal-elastic": ("die", "die_nonlocal_elastic.prm"),
    "rve-uniaxial-material1": ("rve", "rve_uniaxial_material1.prm"),
    "rve-size-study": ("rve", "rve_size_study.prm"),
    "tablet-mcc-default": ("tablet", "tablet_mcc_default.prm"),
    "compare-database-only": ("compare", "compare_database_only.prm"),
}

SKIPPED_FILES = {"timing.csv"}
SKIPPED_COLUMNS = {"wall_seconds", "time_s", "wall_time", "seconds", "time [s]"}


def run_case(binary, command, prm, folder):
    args = [binary, command]
    if prm is not None:
        args.append(str(PRM / prm))
    args += ["-o", str(folder)]
    with open(str(folder) + ".log", "w") as log:
        return subprocess.call(args, stdout=log, stderr=subprocess.STDOUT)


def as_number(text):
    try:
        return float(text)
    except ValueError:
        return None


def compare_csv(ref, new, rtol):
    """List of (column, verdict, largest relative difference)."""
    with open(ref, newline="") as f:
        a = list(csv.reader(f))
    with open(new, newline="") as f:
        b = list(csv.reader(f))
    if not a or not b or a[0] != b[0]:
        return [("<header>", "DIFFERENT", math.inf)]
    if len(a) != len(b):
        return [("<rows %d vs %d>" % (len(a), len(b)), "DIFFERENT", math.inf)]
    out = []
    for c, name in enumerate(a[0]):
        if name in SKIPPED_COLUMNS:
            continue
        col_a = [r[c] if c < len(r) else "" for r in a[1:]]
        col_b = [r[c] if c < len(r) else "" for r in b[1:]]
        if col_a == col_b:
            out.append((name, "identical", 0.0))
            continue
        scale = 0.0
        for x in col_a:
            v = as_number(x)
            if v is not None and math.isfinite(v):
                scale = max(scale, abs(v))
        worst = 0.0
        for x, y in zip(col_a, col_b):
            if x == y:
                continue
            u, v = as_number(x), as_number(y)
            if u is None or v is None:
                worst = math.inf
                break
            if math.isnan(u) and math.isnan(v):
                continue
            d = abs(u - v) / scale if scale > 0 else abs(u - v)
            worst = max(worst, d if math.isfinite(d) else math.inf)
        out.append((name, "close" if worst <= rtol else "DIFFERENT", worst))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("reference")
    ap.add_argument("candidate")
    ap.add_argument("workdir")
    ap.add_argument("--cases", default="quick")
    ap.add_argument("--rtol", type=float, default=1e-6)
    a = ap.parse_args()

    cases = dict(QUICK)
    if a.cases == "all":
        cases.update(LONGER)
    elif a.cases != "quick":
        every = {**QUICK, **LONGER}
        names = [n.strip() for n in a.cases.split(",") if n.strip()]
        unknown = [n for n in names if n not in every]
        if unknown:
            print("compare_outputs: unknown case(s) %s; known: %s"
                  % (", ".join(unknown), ", ".join(sorted(every))),
                  file=sys.stderr)
            return 2
        cases = {n: every[n] for n in names}
    for b in (a.reference, a.candidate):
        if not os.access(b, os.X_OK):
            print("compare_outputs: %s is not an executable" % b,
                  file=sys.stderr)
            return 2

    work = pathlib.Path(a.workdir)
    work.mkdir(parents=True, exist_ok=True)
    failed = False
    for name, (command, prm) in cases.items():
        ref_dir, new_dir = work / name / "reference", work / name / "candidate"
        for d in (ref_dir, new_dir):
            if d.exists():
                subprocess.call(["rm", "-rf", str(d)])
        (work / name).mkdir(parents=True, exist_ok=True)
        rc_ref = run_case(a.reference, command, prm, ref_dir)
        rc_new = run_case(a.candidate, command, prm, new_dir)
        print("== %s (compax %s %s): exit %d / %d"
              % (name, command, prm or "<built-in default>", rc_ref, rc_new))
        if rc_ref != rc_new:
            failed = True
            print("   DIFFERENT exit codes")
        if not ref_dir.is_dir():
            continue
        for ref in sorted(ref_dir.rglob("*")):
            if not ref.is_file() or ref.name in SKIPPED_FILES:
                continue
            rel = ref.relative_to(ref_dir)
            new = new_dir / rel
            if not new.is_file():
                print("   %s: missing in the candidate's output" % rel)
                failed = failed or ref.suffix == ".csv"
                continue
            if ref.suffix == ".csv":
                rows = compare_csv(ref, new, a.rtol)
                bad = [r for r in rows if r[1] == "DIFFERENT"]
                close = [r for r in rows if r[1] == "close"]
                if bad:
                    failed = True
                verdict = ("DIFFERENT" if bad else
                           "close" if close else "identical")
                print("   %s: %s" % (rel, verdict))
                for col, v, worst in bad + close:
                    print("      %-36s %-9s largest relative difference %.3g"
                          % (col, v, worst))
            elif not filecmp.cmp(ref, new, shallow=False):
                print("   %s: bytes differ (not compared further)" % rel)
    print("compare_outputs: %s" % ("DIFFERENCES FOUND" if failed
                                   else "every CSV column identical or close"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
