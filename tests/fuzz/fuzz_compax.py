#!/usr/bin/env python3
"""Seeded mutation fuzzer for compax's inputs (issue #14).

It mutates parameter files (the shipped apps/parameters/*.prm and small
studies of die, rve, database and tablet) and the checkpoint files of die,
rve, database and tablet runs (bit flips, truncation, appended or zeroed
bytes, files swapped between kinds, random entry values), runs
`compax <command> file --check` and, for checkpoints, the resumed run, each
with a time limit, and fails on

  - an exit code other than 0, 2 or 3 (1 is an internal error),
  - a signal (a crash) or a time-out (a hang),
  - MPI_ABORT text in the output,
  - an exit-2 message of more than one line,
  - a staging folder (.<OUTDIR>.partial-<pid>) or lock file left behind.

Every case is reproducible from (seed, index): `--replay INDEX` runs one
case again and keeps its folder. Only the Python standard library is used.

  python3 tests/fuzz/fuzz_compax.py --compax build/apps/compax \
      --source . --work build/fuzz --seconds 180 --seed 1
"""

import argparse
import json
import os
import random
import re
import shutil
import subprocess
import sys
import time

# --------------------------------------------------------------------------
# Small studies whose checkpoints are mutated (a few seconds each).

DIE_STUDY = """subsection Packing
 set Number of particles = 60
 set Die diameter = 2e-3
end
subsection Protocol
 set Final relative density = 0.7
 set Compaction steps = 6
 set Unloading points = 0.62, 0.7
 set Checkpoint interval = 2
end
"""

RVE_STUDY = """subsection Packing
 set Number of particles = 60
 set Seed = 4
end
subsection Strain path
 set Target relative density = 0.7
 set Loading steps = 6
 set Unloading strain step = 5e-3
end
subsection Output
 set Tangent interval = 2
 set Finite-difference check interval = 0
 set Snapshot interval = 3
end
subsection Checkpoints
 set Checkpoint interval = 3
end
"""

DATABASE_STUDY = """subsection Packing
 set Number of particles = 60
 set Seed = 5
end
subsection Paths
 set Final relative density = 0.74
 set Branch densities = 0.70, 0.74
 set Shear steps = 4
 set Radial strain ratios =
end
subsection Validation
 set Held-out packing = false
end
"""

TABLET_STUDY = """subsection Mesh
  set Radial cells = 2
end
subsection Process
  set Compaction steps = 6
  set Unloading steps = 2
  set Ejection steps = 2
end
subsection Output
  set Checkpoint interval = 4
  set Field interval = 3
end
"""

# command, study, subsection of Resume from, the checkpoint in the run
# folder (the tablet resumes from the folder itself), extra entries of the
# run that writes the checkpoint (stopped part-way, so that a resumed run
# has work left)
STUDIES = {
    "die": (DIE_STUDY, "Protocol", "checkpoints/compaction.h5",
            "subsection Protocol\n set Stop after compaction steps = 4\nend\n"),
    "rve": (RVE_STUDY, "Checkpoints", "checkpoints/rve.h5",
            "subsection Checkpoints\n set Stop after steps = 3\nend\n"),
    "database": (DATABASE_STUDY, "Checkpoints", "checkpoints/database.h5",
                 "subsection Checkpoints\n set Stop after branches = 1\nend\n"),
    "tablet": (TABLET_STUDY, "Output", "checkpoint/tablet.h5", ""),
}

# Values that parsers and checks must survive.
VALUES = ["", "0", "-0", "1", "-1", "2", "0.5", "1e308", "-1e308", "1e-320",
          "nan", "inf", "-inf", "NaN", "1e999", "2147483648", "-2147483649",
          "99999999999999999999", "abc", "1,2", "1, 2, 3", ",", "0.5,",
          "true", "false", "yes", "2e-4", "0.87", "1e7", "100000", "1e-300",
          "0x10", " ", "\\", "/", ".", "..", "/dev/null", "/nonexistent/x",
          "\u00e9", "1 2", "=", "#", "end", "subsection", "3e-3", "0.99",
          "uniaxial", "csv", "elastic", "nonlocal", "multiscale-fe2"]

ABORT_TEXT = re.compile(r"MPI_ABORT|MPI_Abort|mpi_abort", re.IGNORECASE)


class Fuzzer:
    def __init__(self, args):
        self.args = args
        self.compax = os.path.abspath(args.compax)
        self.source = os.path.abspath(args.source)
        self.work = os.path.abspath(args.work)
        self.corpus = os.path.join(self.work, "corpus")
        self.cases = os.path.join(self.work, "cases")
        self.failures = os.path.join(self.work, "failures")
        self.stats = {"cases": 0, "runs": 0, "failures": 0, "kinds": {},
                      "exit_codes": {}, "failed": []}

    # ------------------------------------------------------------------
    def run(self, argv, cwd, timeout, env=None):
        """Runs compax; returns (code, out, err); code None on a time-out."""
        self.stats["runs"] += 1
        try:
            p = subprocess.run([self.compax] + argv, cwd=cwd, timeout=timeout,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               env=env, start_new_session=True)
            return (p.returncode, p.stdout.decode("utf-8", "replace"),
                    p.stderr.decode("utf-8", "replace"))
        except subprocess.TimeoutExpired as e:
            # The whole process group (mpirun-free, but be thorough).
            return (None, (e.stdout or b"").decode("utf-8", "replace"),
                    (e.stderr or b"").decode("utf-8", "replace"))

    # ------------------------------------------------------------------
    def setup(self):
        if os.path.exists(self.work) and self.args.replay is None:
            shutil.rmtree(self.work)
        os.makedirs(self.corpus, exist_ok=True)
        os.makedirs(self.cases, exist_ok=True)
        os.makedirs(self.failures, exist_ok=True)
        ready = os.path.join(self.corpus, "ready")
        if os.path.exists(ready):
            self.load_corpus()
            return
        # Shipped parameter files, relative file names made absolute.
        prm_dir = os.path.join(self.corpus, "prm")
        os.makedirs(prm_dir, exist_ok=True)
        shipped = os.path.join(self.source, "apps", "parameters")
        for name in sorted(os.listdir(shipped)):
            if not name.endswith(".prm"):
                continue
            text = open(os.path.join(shipped, name)).read()

            def absolute(m):
                path = os.path.normpath(os.path.join(shipped, m.group(2)))
                return m.group(1) + (path if os.path.exists(path)
                                     else m.group(2))
            text = re.sub(r"(set [^=\n]*(?:file|table)\s*=\s*)(\S+\.(?:csv|msh))",
                          absolute, text)
            open(os.path.join(prm_dir, name), "w").write(text)
        # The small studies, run once: their output folders hold the
        # checkpoints that are mutated.
        runs = os.path.join(self.corpus, "runs")
        os.makedirs(runs, exist_ok=True)
        for command, (study, _, checkpoint, extra) in STUDIES.items():
            prm = os.path.join(prm_dir, command + "_small.prm")
            open(prm, "w").write(study)
            open(os.path.join(runs, command + ".prm"), "w").write(study + extra)
            code, out, err = self.run([command, command + ".prm", "-o",
                                       command], runs, 600)
            if code != 0 or not os.path.exists(
                    os.path.join(runs, command, checkpoint)):
                sys.exit("fuzz set-up: the %s study failed (exit %s):\n%s%s"
                         % (command, code, out[-2000:], err[-2000:]))
        open(ready, "w").write("ok\n")
        self.load_corpus()

    def load_corpus(self):
        prm_dir = os.path.join(self.corpus, "prm")
        self.prms = [os.path.join(prm_dir, n) for n in sorted(os.listdir(prm_dir))]
        self.runs = os.path.join(self.corpus, "runs")
        self.checkpoints = {c: os.path.join(self.runs, c, s[2])
                            for c, s in STUDIES.items()}
        self.archive_files = []
        for root, _, files in os.walk(self.runs):
            for f in files:
                if f.endswith(".h5") or f.endswith(".bin"):
                    self.archive_files.append(os.path.join(root, f))
        self.archive_files.sort()

    # ------------------------------------------------------------------
    # Mutations.

    @staticmethod
    def mutate_bytes(rng, data, others):
        """A damaged copy of `data` and what was done to it."""
        choice = rng.random()
        n = len(data)
        if choice < 0.35 and n:
            data = bytearray(data)
            flips = rng.choice([1, 1, 1, 2, 3, 8, 32])
            for _ in range(flips):
                k = rng.randrange(n)
                data[k] ^= 1 << rng.randrange(8)
            return bytes(data), "flip %d bit(s)" % flips
        if choice < 0.55:
            keep = rng.choice([0, 1, 8, 511, 512, 513, n // 2, n - 1,
                               rng.randrange(n + 1)])
            return data[:max(0, min(keep, n))], "truncate to %d" % keep
        if choice < 0.62:
            extra = bytes(rng.randrange(256) for _ in range(rng.choice([1, 16, 4096])))
            return data + extra, "append %d bytes" % len(extra)
        if choice < 0.72 and n:
            start = rng.randrange(n)
            length = rng.choice([1, 8, 64, 512, 4096])
            data = bytearray(data)
            data[start:start + length] = bytes(min(length, n - start))
            return bytes(data), "zero %d bytes at %d" % (length, start)
        if choice < 0.80 and n > 1024:
            # Swap two blocks.
            a, b = sorted(rng.sample(range(0, n - 256), 2))
            data = bytearray(data)
            data[a:a + 256], data[b:b + 256] = data[b:b + 256], data[a:a + 256]
            return bytes(data), "swap blocks %d and %d" % (a, b)
        if choice < 0.95 and others:
            other = rng.choice(others)
            return open(other, "rb").read(), "replaced by " + os.path.basename(
                os.path.dirname(os.path.dirname(other))) + "/" + os.path.basename(other)
        return data, "intact"

    @staticmethod
    def mutate_text(rng, text):
        """A mutated parameter file and what was done to it."""
        lines = text.split("\n")
        what = []
        for _ in range(rng.choice([1, 1, 1, 2, 3])):
            sets = [i for i, l in enumerate(lines)
                    if l.strip().startswith("set ")]
            r = rng.random()
            if r < 0.55 and sets:
                i = rng.choice(sets)
                head = lines[i].split("=", 1)[0]
                value = rng.choice(VALUES)
                if rng.random() < 0.2:
                    value = str(rng.choice([-1, 1]) * rng.random()
                                * 10 ** rng.randrange(-12, 12))
                lines[i] = head + "= " + value
                what.append("%s= %r" % (head.strip(), value))
            elif r < 0.65 and lines:
                i = rng.randrange(len(lines))
                del lines[i]
                what.append("delete line %d" % i)
            elif r < 0.72 and lines:
                i = rng.randrange(len(lines))
                lines.insert(i, rng.choice(["end", "subsection Nowhere",
                                            "set Unknown = 1", "set =",
                                            "subsection Material",
                                            "\x00", "set Seed = 1 = 2"]))
                what.append("insert line %d" % i)
            elif r < 0.82:
                joined = "\n".join(lines)
                if joined:
                    k = rng.randrange(len(joined))
                    joined = joined[:k] + chr(rng.randrange(1, 128)) + joined[k + 1:]
                    lines = joined.split("\n")
                    what.append("character %d" % k)
            elif r < 0.9 and lines:
                k = rng.randrange(len(lines) + 1)
                lines = lines[:k]
                what.append("truncate at line %d" % k)
            elif sets:
                a, b = rng.choice(sets), rng.choice(sets)
                lines[a], lines[b] = lines[b], lines[a]
                what.append("swap lines %d %d" % (a, b))
        return "\n".join(lines), "; ".join(what)

    # ------------------------------------------------------------------
    # Checks.

    def check(self, case, label, argv, cwd, result, problems):
        code, out, err = result
        self.stats["exit_codes"][str(code)] = \
            self.stats["exit_codes"].get(str(code), 0) + 1
        if code is None:
            problems.append("%s: hang (no exit within the time limit)" % label)
        elif code < 0:
            problems.append("%s: signal %d" % (label, -code))
        elif code not in (0, 2, 3):
            problems.append("%s: exit code %d: %s" % (label, code,
                                                      err.strip()[-500:]))
        if ABORT_TEXT.search(out) or ABORT_TEXT.search(err):
            problems.append("%s: MPI_ABORT text" % label)
        if code == 2 and err.count("\n") != 1:
            problems.append("%s: exit-2 message of %d lines: %s"
                            % (label, err.count("\n"), err[-500:]))
        for root, dirs, files in os.walk(cwd):
            for name in dirs + files:
                if ".partial-" in name or name.endswith(".lock"):
                    problems.append("%s: left behind %s" % (
                        label, os.path.relpath(os.path.join(root, name), cwd)))
            # The corpus copies inside a case are not searched deeper.
            dirs[:] = [d for d in dirs if ".partial-" not in d]

    # ------------------------------------------------------------------
    # Cases.

    def case_prm_check(self, rng, folder):
        source = rng.choice(self.prms)
        command = os.path.basename(source).split("_")[0]
        text, what = self.mutate_text(rng, open(source, encoding="utf-8",
                                                errors="replace").read())
        with open(os.path.join(folder, "case.prm"), "w",
                  encoding="utf-8", errors="replace") as f:
            f.write(text)
        argv = [command, "case.prm", "--check"]
        return [(argv, self.args.timeout)], "%s: %s" % (
            os.path.basename(source), what)

    def case_checkpoint(self, rng, folder):
        command = rng.choice(sorted(STUDIES))
        study, subsection, checkpoint, _ = STUDIES[command]
        # The run folder next to the case, so that the files the checkpoint
        # lists are there; then one of its files damaged.
        run = os.path.join(folder, "run")
        shutil.copytree(os.path.join(self.runs, command), run)
        target = os.path.join(run, checkpoint)
        if command == "tablet" and rng.random() < 0.4:
            names = sorted(n for n in os.listdir(os.path.dirname(target)))
            target = os.path.join(os.path.dirname(target), rng.choice(names))
        elif command in ("die", "rve") and rng.random() < 0.1:
            snaps = os.path.join(run, "snapshots")
            if os.path.isdir(snaps) and os.listdir(snaps):
                target = os.path.join(snaps, rng.choice(sorted(os.listdir(snaps))))
        others = [f for f in self.archive_files
                  if os.path.basename(f) != os.path.basename(target)]
        data, what = self.mutate_bytes(rng, open(target, "rb").read(), others)
        open(target, "wb").write(data)
        resume = "run" if command == "tablet" else os.path.join("run", checkpoint)
        text = study + "subsection %s\n set Resume from = %s\nend\n" % (
            subsection, resume)
        open(os.path.join(folder, "case.prm"), "w").write(text)
        return ([([command, "case.prm", "--check"], self.args.timeout),
                 ([command, "case.prm", "-o", "out"], self.args.run_timeout)],
                "%s %s: %s" % (command, os.path.relpath(target, run), what))

    def case_resume_prm(self, rng, folder):
        """An intact checkpoint resumed with mutated parameters (--check)."""
        command = rng.choice(sorted(STUDIES))
        study, subsection, checkpoint, _ = STUDIES[command]
        os.symlink(os.path.join(self.runs, command), os.path.join(folder, "run"))
        resume = "run" if command == "tablet" else os.path.join("run", checkpoint)
        text, what = self.mutate_text(
            rng, study + "subsection %s\n set Resume from = %s\nend\n" % (
                subsection, resume))
        open(os.path.join(folder, "case.prm"), "w").write(text)
        return ([([command, "case.prm", "--check"], self.args.timeout)],
                "%s resume prm: %s" % (command, what))

    def one_case(self, index):
        rng = random.Random(self.args.seed * 1000003 + index)
        folder = os.path.join(self.cases, "%06d" % index)
        if os.path.exists(folder):
            shutil.rmtree(folder)
        os.makedirs(folder)
        r = rng.random()
        if r < 0.45:
            kind, make = "prm-check", self.case_prm_check
        elif r < 0.85:
            kind, make = "checkpoint", self.case_checkpoint
        else:
            kind, make = "resume-prm", self.case_resume_prm
        runs, what = make(rng, folder)
        problems = []
        log = []
        for argv, limit in runs:
            result = self.run(argv, folder, limit)
            log.append({"argv": argv, "exit": result[0],
                        "stderr": result[2][-2000:]})
            self.check(index, " ".join(argv), argv, folder, result, problems)
        self.stats["cases"] += 1
        self.stats["kinds"][kind] = self.stats["kinds"].get(kind, 0) + 1
        if problems:
            self.stats["failures"] += 1
            self.stats["failed"].append({"case": index, "kind": kind,
                                         "what": what, "problems": problems})
            keep = os.path.join(self.failures, "%06d" % index)
            if os.path.exists(keep):
                shutil.rmtree(keep)
            shutil.copytree(folder, keep, symlinks=True)
            json.dump({"what": what, "problems": problems, "runs": log},
                      open(os.path.join(keep, "case.json"), "w"), indent=1)
            print("FAIL case %d (%s, %s):\n  %s" % (
                index, kind, what, "\n  ".join(problems)), flush=True)
        if self.args.replay is None:
            shutil.rmtree(folder, ignore_errors=True)
        return problems

    # ------------------------------------------------------------------
    def main(self):
        self.setup()
        if self.args.replay is not None:
            problems = self.one_case(self.args.replay)
            print("case %d: %s" % (self.args.replay,
                                   "; ".join(problems) or "ok"))
            return 1 if problems else 0
        start = time.time()
        index = 0
        while True:
            if self.args.cases and index >= self.args.cases:
                break
            if self.args.seconds and time.time() - start >= self.args.seconds:
                break
            self.one_case(index)
            index += 1
            if index % 50 == 0:
                print("%d cases, %d failures, %.0f s" % (
                    index, self.stats["failures"], time.time() - start),
                    flush=True)
        self.stats["seconds"] = round(time.time() - start, 1)
        self.stats["seed"] = self.args.seed
        json.dump(self.stats, open(os.path.join(self.work, "summary.json"), "w"),
                  indent=1)
        print("fuzz: %d cases (%s), %d compax runs, exit codes %s, "
              "%d failures, %.0f s (seed %d)" % (
                  self.stats["cases"],
                  ", ".join("%s %d" % kv for kv in sorted(self.stats["kinds"].items())),
                  self.stats["runs"],
                  ", ".join("%s: %d" % kv for kv in sorted(self.stats["exit_codes"].items())),
                  self.stats["failures"], self.stats["seconds"], self.args.seed))
        return 1 if self.stats["failures"] else 0


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--compax", required=True, help="the compax executable")
    p.add_argument("--source", required=True, help="the repository root")
    p.add_argument("--work", required=True, help="working folder (replaced)")
    p.add_argument("--seconds", type=float, default=0,
                   help="start no case after this many seconds")
    p.add_argument("--cases", type=int, default=0, help="number of cases")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--timeout", type=float, default=60,
                   help="time limit of a --check run [s]")
    p.add_argument("--run-timeout", type=float, default=300,
                   help="time limit of a resumed run [s]")
    p.add_argument("--replay", type=int, default=None,
                   help="run this case index only and keep its folder")
    args = p.parse_args()
    if not args.seconds and not args.cases and args.replay is None:
        args.cases = 100
    return Fuzzer(args).main()


if __name__ == "__main__":
    sys.exit(main())
