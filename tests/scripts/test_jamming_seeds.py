#!/usr/bin/env python3
"""scripts/jamming_seeds.py: its sign test against the binomial closed
form, fits equal to round-off taken as ties; on a tiny bed, one table row
per seed and toughness, paired differences equal to the ones recomputed
from that table, a resumed ensemble that keeps finished seeds and sets an
interrupted one aside, and bad input refused with exit 2 and no output
folder.

Usage: test_jamming_seeds.py COMPAX WORKDIR
"""

import csv
import pathlib
import shutil
import statistics
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent.parent
SCRIPT = ROOT / "scripts" / "jamming_seeds.py"

TINY = """subsection Packing
  set Number of particles = 80
  set Die diameter        = 2e-3
end
subsection Protocol
  set Final relative density = 0.72
  set Compaction steps       = 20
  set Unloading points       =
end
subsection Jamming
  set Protocols             = bonded-path
  set Compare without bonds = true
end
"""


def run(compax, *args):
    return subprocess.run([sys.executable, str(SCRIPT), *map(str, args),
                           "--compax", str(compax)],
                          capture_output=True, text=True, check=False)


def fail(message):
    print(f"FAILED: {message}")
    sys.exit(1)


def check_sign_test():
    """The exact two-sided binomial tail in closed form."""
    sys.dont_write_bytecode = True  # no __pycache__ in the source tree
    sys.path.insert(0, str(SCRIPT.parent))
    from jamming_seeds import sign_test
    for split, p in (((7, 0), 2 / 2**7),            # 2 * 0.5^7
                     ((9, 1), 2 * (10 + 1) / 2**10),  # 2 * (C(10,9) + C(10,10)) / 2^10
                     ((2, 8), 2 * (45 + 10 + 1) / 2**10),
                     ((5, 5), 1.0)):
        if abs(sign_test(*split) - p) > 1e-15:
            fail(f"sign_test{split} = {sign_test(*split)}, closed form {p}")
    # Fits that agree to their round-off are a tie, not a sign.
    from jamming_seeds import paired_difference
    for none, bonded, expected in ((0.6147672459, 0.6147672457, 0.0),
                                   (0.6157, 0.6152, 0.6157 - 0.6152),
                                   (4.23, 4.17, 4.23 - 4.17)):
        if paired_difference(none, bonded) != expected:
            fail(f"paired_difference({none}, {bonded}) = "
                 f"{paired_difference(none, bonded)}, expected {expected}")


def main():
    check_sign_test()
    compax, work = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    prm = work / "tiny.prm"
    prm.write_text(TINY)

    out = work / "out"
    r = run(compax, prm, out, "--seeds", "1,2", "--jobs", "2")
    if r.returncode != 0:
        fail(f"exit {r.returncode}: {r.stderr}")
    with open(out / "jamming_seeds.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    seeds = sorted((row["seed"], float(row["fracture_toughness"]) == 0)
                   for row in rows)
    if seeds != [("1", False), ("1", True), ("2", False), ("2", True)]:
        fail(f"one row per seed and toughness expected, got {seeds}")
    # Each deposit is its own draw: the two seeds' inputs differ in the seed.
    for s in ("1", "2"):
        text = (out / f"seed-{s}" / "input.prm").read_text()
        if not text.rstrip().endswith(f"set Seed = {s}\nend"):
            fail(f"seed-{s}/input.prm does not end by setting its seed")
    by = {(row["seed"], float(row["fracture_toughness"]) == 0):
          float(row["rho_jammed"]) for row in rows}
    diffs = [by[(s, True)] - by[(s, False)] for s in ("1", "2")]
    expected = (f"| material1 | bonded-path | rho_jammed | 2 | "
                f"{statistics.fmean(diffs):.4g} | {statistics.median(diffs):.4g} | "
                f"{statistics.stdev(diffs):.3g} |")
    if expected not in (out / "jamming_seeds.md").read_text():
        fail(f"paired difference row '{expected}' not in jamming_seeds.md")

    # An interrupted ensemble: seed 3 started and never finished.
    kept_log = (out / "seed-1" / "compax.log").stat().st_mtime_ns
    (out / "seed-3").mkdir()
    (out / "seed-3" / "input.prm").write_text(
        (out / "seed-1" / "input.prm").read_text().replace("Seed = 1", "Seed = 3"))
    r = run(compax, prm, out, "--seeds", "1-3", "--resume")
    if r.returncode != 0:
        fail(f"--resume: exit {r.returncode}: {r.stderr}")
    if (out / "seed-1" / "compax.log").stat().st_mtime_ns != kept_log:
        fail("--resume ran a seed that had finished")
    if len(list(out.glob("seed-3.interrupted-*"))) != 1:
        fail("--resume did not keep the interrupted seed's folder aside")
    with open(out / "jamming_seeds.csv", newline="") as f:
        if sorted({row["seed"] for row in csv.DictReader(f)}) != ["1", "2", "3"]:
            fail("the resumed table does not hold seeds 1-3")
    # Another study's folder is refused, not overwritten.
    (out / "seed-2" / "input.prm").write_text(TINY)
    r = run(compax, prm, out, "--seeds", "1-3", "--resume")
    if r.returncode != 2 or "another study" not in r.stderr:
        fail(f"--resume on another study: exit {r.returncode}, '{r.stderr}'")

    for args, what in (((prm, out), "a non-empty OUTDIR"),
                       ((prm, work / "bad1", "--seeds", "3-1"), "seeds 3-1"),
                       ((prm, work / "bad2", "--jobs", "0"), "--jobs 0"),
                       ((work / "missing.prm", work / "bad3"), "a missing PRM")):
        r = run(compax, *args)
        if r.returncode != 2 or "jamming_seeds.py:" not in r.stderr:
            fail(f"{what}: exit {r.returncode}, stderr '{r.stderr}'")
    for name in ("bad1", "bad2", "bad3"):
        if (work / name).exists():
            fail(f"bad input left the folder {name}")
    print("OK")


if __name__ == "__main__":
    main()
