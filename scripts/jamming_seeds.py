#!/usr/bin/env python3
"""Runs one `compax jamming` study on several deposits and pairs the results.

One deposit is one draw: the jamming onset of a loose bed is chaotic (the
rounding of a force sum moves it; doc/benchmarks.md, "One measurement is
one draw"), so whether K_Ic = 0 jams later than K_Ic > 0 cannot be read
from one seed.
This script runs the study of a parameter file once per `Packing/Seed`,
collects every `jamming.csv` into one table with a `seed` column, and pairs
the two toughnesses of each seed and protocol: the difference
(K_Ic = 0) - (K_Ic > 0) of rho_c_Z, Z_c, theta and rho_jammed, with its
mean, median, sample standard deviation, standard error and the numbers of
seeds where it is positive and negative, and the two-sided exact sign
test's p of that split (it needs no assumption on the spread of the
Eq. 14 fits, whose outliers move the mean). Two values within 1e-6 of each
other (relative) count as equal: a tie, left out of the sign test.

Usage:
  scripts/jamming_seeds.py PRM OUTDIR [--seeds 1-10] [--jobs 1] [--resume]
      [--compax build/apps/compax]

PRM must set `Jamming/Compare without bonds = true` for the pairs (without
it the table is still written). OUTDIR must not exist or be empty. Each run
goes to OUTDIR/seed-<N>/ (its input.prm, compax.log, exit_code and
compax's own output folder run/); with --jobs > 1 the runs go in parallel
with one thread each. --resume continues an interrupted ensemble in its
OUTDIR: seeds that exited 0 are kept, the folder of any other seed is
renamed to seed-<N>.interrupted-<time> (nothing is deleted) and the seed
runs again; a seed whose input.prm differs from what PRM gives is refused.
Writes OUTDIR/jamming_seeds.csv (`seed` then the columns of jamming.csv) and
OUTDIR/jamming_seeds.md (the paired differences).

Exit status: 0 when every run exited 0, 1 when one did not (named on
stderr; the table holds the others), 2 on bad input.
"""

import argparse
import concurrent.futures
import csv
import io
import math
import os
import pathlib
import statistics
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
PAIRED = ["rho_c_Z", "Z_c", "theta", "rho_jammed"]


def bad_input(message):
    print(f"jamming_seeds.py: {message}", file=sys.stderr)
    sys.exit(2)


def parse_seeds(text):
    """'1-10' or '1,4,7' (or both, '1-3,8') to a sorted list of seeds >= 0."""
    seeds = set()
    try:
        for part in text.split(","):
            if "-" in part:
                first, last = (int(v) for v in part.split("-"))
                if first > last:
                    raise ValueError
                seeds.update(range(first, last + 1))
            else:
                seeds.add(int(part))
    except ValueError:
        bad_input(f"--seeds '{text}' is not a list of seeds such as 1-10 or 1,4,7")
    if not seeds or min(seeds) < 0:
        bad_input(f"--seeds '{text}': seeds are whole numbers >= 0")
    return sorted(seeds)


def seed_input(prm_text, seed):
    """PRM with Packing/Seed = seed: a later `set` of the same entry
    overrides the earlier one."""
    return prm_text + f"\nsubsection Packing\n  set Seed = {seed}\nend\n"


def finished(folder):
    exit_code = folder / "exit_code"
    return exit_code.is_file() and exit_code.read_text().strip() == "0"


def run_seed(compax, prm_text, folder, seed, threads):
    """Writes folder/input.prm, runs it, and records its exit code."""
    folder.mkdir(parents=True)
    (folder / "input.prm").write_text(seed_input(prm_text, seed))
    env = dict(os.environ)
    if threads:
        env["OMP_NUM_THREADS"] = str(threads)
    with open(folder / "compax.log", "w") as log:
        code = subprocess.run(
            [str(compax), "jamming", "input.prm", "-o", "run"],
            cwd=folder, stdout=log, stderr=subprocess.STDOUT, env=env,
            check=False).returncode
    (folder / "exit_code").write_text(f"{code}\n")
    return code


def read_rows(folder, seed):
    path = folder / "run" / "jamming.csv"
    if not path.is_file():
        return []
    with open(path, newline="") as f:
        return [dict(row, seed=str(seed)) for row in csv.DictReader(f)]


def write_whole(path, text):
    """Writes a table next to `path` and renames it there: a reader never
    sees half a file, and a crash leaves the earlier one."""
    partial = path.with_name(f".{path.name}.partial")
    partial.write_text(text)
    os.replace(partial, path)


def number(text):
    try:
        value = float(text)
    except (TypeError, ValueError):
        return None
    return value if math.isfinite(value) else None


# Two fits of one deposit that differ by less than this fraction of their
# value are the same fit: both toughnesses follow the same states up to the
# first resolved force, and a difference of 1e-10 in rho_c_Z is the fit's
# round-off, not a sign.
TIE = 1e-6


def paired_difference(none, bonded):
    """none - bonded, or 0 where the two agree to TIE of their value."""
    if abs(none - bonded) <= TIE * max(abs(none), abs(bonded)):
        return 0.0
    return none - bonded


def paired_differences(rows):
    """{(material, protocol, column): [K_Ic=0 minus K_Ic>0, one per seed]}."""
    by_case = {}
    for row in rows:
        toughness = number(row.get("fracture_toughness"))
        if toughness is None:
            continue
        key = (row["material"], row["protocol"], row["seed"])
        by_case.setdefault(key, {})["none" if toughness == 0 else "bonded"] = row
    pairs = {}
    for (material, protocol, _), case in sorted(by_case.items()):
        if "none" not in case or "bonded" not in case:
            continue
        for column in PAIRED:
            a = number(case["none"].get(column))
            b = number(case["bonded"].get(column))
            if a is not None and b is not None:
                pairs.setdefault((material, protocol, column), []).append(
                    paired_difference(a, b))
    return pairs


def sign_test(positive, negative):
    """Two-sided exact sign test: the chance of a split at least this
    uneven if either sign were equally likely (ties are left out)."""
    n = positive + negative
    if n == 0:
        return float("nan")
    tail = sum(math.comb(n, k) for k in range(max(positive, negative), n + 1))
    return min(1.0, 2.0 * tail / 2**n)


def summary_table(pairs):
    lines = [
        "| material | protocol | quantity | seeds | mean difference"
        " | median difference | sample SD | standard error"
        " | seeds with difference > 0 | seeds with difference < 0"
        " | sign test p |",
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for (material, protocol, column), d in sorted(pairs.items()):
        sd = statistics.stdev(d) if len(d) > 1 else float("nan")
        se = sd / math.sqrt(len(d)) if len(d) > 1 else float("nan")
        positive, negative = sum(v > 0 for v in d), sum(v < 0 for v in d)
        lines.append(
            f"| {material} | {protocol} | {column} | {len(d)} | "
            f"{statistics.fmean(d):.4g} | {statistics.median(d):.4g} | "
            f"{sd:.3g} | {se:.3g} | {positive} | {negative} | "
            f"{sign_test(positive, negative):.2g} |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("prm", type=pathlib.Path)
    parser.add_argument("outdir", type=pathlib.Path)
    parser.add_argument("--seeds", default="1-10")
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--resume", action="store_true")
    parser.add_argument("--compax", type=pathlib.Path,
                        default=ROOT / "build" / "apps" / "compax")
    args = parser.parse_args()

    if not args.prm.is_file():
        bad_input(f"PRM '{args.prm}' is not a file")
    if not args.compax.is_file():
        bad_input(f"--compax '{args.compax}' is not a file (build compax first)")
    if args.jobs < 1:
        bad_input(f"--jobs {args.jobs}: at least 1")
    if args.outdir.exists() and not args.outdir.is_dir():
        bad_input(f"OUTDIR '{args.outdir}' is not a folder")
    if args.outdir.exists() and any(args.outdir.iterdir()) and not args.resume:
        bad_input(f"OUTDIR '{args.outdir}' is not empty (--resume continues"
                  " an interrupted ensemble there)")
    seeds = parse_seeds(args.seeds)
    compax = args.compax.resolve()
    check = subprocess.run([str(compax), "jamming", str(args.prm), "--check"],
                           capture_output=True, text=True, check=False)
    if check.returncode != 0:
        bad_input(f"PRM '{args.prm}': {check.stderr.strip() or check.stdout.strip()}")
    prm_text = args.prm.read_text()
    args.outdir.mkdir(parents=True, exist_ok=True)

    folders = {s: args.outdir / f"seed-{s}" for s in seeds}
    for s, folder in folders.items():
        given = folder / "input.prm"
        if given.is_file() and given.read_text() != seed_input(prm_text, s):
            bad_input(f"--resume: '{given}' is another study's (it differs"
                      f" from PRM '{args.prm}' with seed {s})")
    kept = [s for s in seeds if finished(folders[s])]
    to_run = [s for s in seeds if s not in kept]
    for s in to_run:
        if folders[s].exists():
            aside = folders[s].with_name(
                f"{folders[s].name}.interrupted-{time.strftime('%Y%m%d-%H%M%S')}")
            folders[s].rename(aside)
            print(f"jamming_seeds.py: seed {s} did not finish; its folder is"
                  f" now {aside.name}, running it again", file=sys.stderr)
    if kept:
        print(f"jamming_seeds.py: keeping seeds {kept}, finished earlier",
              file=sys.stderr)

    threads = 1 if args.jobs > 1 else None
    codes = {s: 0 for s in kept}
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        codes.update(zip(to_run, pool.map(
            lambda s: run_seed(compax, prm_text, folders[s], s, threads),
            to_run)))
    failed = [s for s in seeds if codes[s] != 0]
    for s in failed:
        print(f"jamming_seeds.py: seed {s} exited {codes[s]} "
              f"(see {folders[s] / 'compax.log'})", file=sys.stderr)

    rows = [row for s in seeds for row in read_rows(folders[s], s)]
    if rows:
        table = io.StringIO()
        writer = csv.DictWriter(
            table, fieldnames=["seed"] + [c for c in rows[0] if c != "seed"],
            lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
        write_whole(args.outdir / "jamming_seeds.csv", table.getvalue())
    pairs = paired_differences(rows)
    write_whole(
        args.outdir / "jamming_seeds.md",
        f"# `compax jamming` on {len(seeds)} deposits\n\n"
        f"Parameters: `{args.prm}`, seeds {args.seeds}"
        f"{', failed: ' + str(failed) if failed else ''}.\n\n"
        "Paired differences, (K_Ic = 0) minus (K_Ic > 0) of the same"
        " deposit and protocol (values within 1e-6 of each other, relative,"
        " count as equal):\n\n" + summary_table(pairs) + "\n")
    print((args.outdir / "jamming_seeds.md").read_text())
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
