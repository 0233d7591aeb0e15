#!/usr/bin/python3
"""scripts/study validate --strips: the runs of a strip matrix through the sweep that --slurm submits
(run here with --jobs 2, as the Slurm test runs the same tasks), checked against scripts/study strip,
the path scripts/strip_matrix takes, run independently on the same lines:

  1. each run's record holds its checkpoint and the strip's overrides, then the line's own --set;
     its loads.csv and checkpoint are those of `scripts/study strip` with the line's arguments, byte
     for byte; a line's --snapshots K over its sheet's length gives K snapshots over a fresh run;
  2. --resume carries the records on to a longer length: the resumed record's loads.csv is that of
     one unbroken strip run to that length, and the snapshots keep the line's spacing;
  3. bad input (a matrix line with an argument a strip run cannot take, --strips beside --seeds, a
     series without an experiment's length and no --until-length, a missing file) is refused with
     exit status 2 and one line naming it, and leaves the records as they were;
  4. without --records, --strips reads and writes docs/validation/strips.

    test_validate_strips.py THIN_ICE_DIR SOURCE_DIR   (THIN_ICE_DIR: the folder of the thin_ice program)
"""
import filecmp
import json
import os
import shutil
import subprocess
import sys
import tempfile

from quick_strip import refusal_problem

QUICK = "config/scenarios/quick.yaml"
# Two quick strips 1 m wide with a 2 m sheet: the ice meets the structure 0.3 m in, so 0.3 m of push
# takes a few seconds of wall time.
MATRIX = (f"# two quick strips\n"
          f"qa {QUICK} --width 1 --length 2 --snapshots 4\n"
          f"qb {QUICK} --width 1 --length 2 --set sheet.seed=2   # another sheet\n")
STRIP_OVERRIDES = ["sheet.width=1", "sheet.length=2", "structure.width=1", "structure.panels=2",
                   "structure.toe_x=2.3", "channel.width=1", "channel.friction=0"]


def main():
    bin_dir, source = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    study = os.path.join(source, "scripts", "study")
    thin_ice = os.path.join(bin_dir, "thin_ice")
    folder = tempfile.mkdtemp(prefix="thin_ice_validate_strips_")
    matrix = os.path.join(folder, "m.matrix")
    with open(matrix, "w") as f:
        f.write(MATRIX)
    records = os.path.join(folder, "records")
    where = ["--bin", bin_dir, "--work", os.path.join(folder, "work"), "--records", records,
             "--report", os.path.join(folder, "report.md")]
    failures = []

    def validate(*args):
        return subprocess.run(["/usr/bin/python3", study, "validate", "--strips", matrix, *args, *where],
                              capture_output=True, text=True, timeout=300)

    def strip_run(out, length, *args):
        # one thread, as the sweep's tasks with --jobs 2 and scripts/strip_matrix's runs take
        done = subprocess.run(["/usr/bin/python3", study, "strip", QUICK, "--width", "1", "--length", "2", *args,
                               "--set", "numerics.threads=1", "--bin", thin_ice, "--until-length", length, "--out", out],
                              capture_output=True, text=True, timeout=300, cwd=source)
        if done.returncode != 0:
            failures.append(f"scripts/study strip {' '.join(args)}: exit {done.returncode}: {done.stderr.strip()[-300:]}")

    def snapshots(run_dir):
        return sorted(n for n in os.listdir(os.path.join(run_dir, "snapshots")) if n.startswith("cells_"))

    # 1. The matrix to 0.3 m, against scripts/study strip on the same lines.
    done = validate("--until-length", "0.3", "--jobs", "2")
    if done.returncode != 0:
        failures.append(f"validate --strips: exit {done.returncode}: {done.stderr.strip()[-500:]}")
    strip_run(os.path.join(folder, "qa"), "0.3", "--snapshots", "4")
    strip_run(os.path.join(folder, "qb"), "0.3", "--set", "sheet.seed=2")
    for name, own in (("qa", []), ("qb", ["sheet.seed=2"])):
        record = os.path.join(records, name)
        try:
            with open(os.path.join(record, "summary.json")) as f:
                summary = json.load(f)
        except (OSError, ValueError) as e:
            failures.append(f"{name}: no record ({e})")
            continue
        overrides = [o for o in summary["scenario"]["overrides"] if not o.startswith("numerics.threads=")]
        if overrides != STRIP_OVERRIDES + own or summary["status"] != "completed" or summary["pushed_length_m"] != 0.3:
            failures.append(f"{name}: overrides {overrides}, status {summary['status']}, L {summary['pushed_length_m']}; "
                            f"expected {STRIP_OVERRIDES + own}, completed to 0.3 m")
        for f in ("loads.csv", "checkpoint.bin"):
            if not (os.path.isfile(os.path.join(record, f))
                    and filecmp.cmp(os.path.join(record, f), os.path.join(folder, name, f), shallow=False)):
                failures.append(f"{name}: {f} of the record differs from scripts/study strip's (or is missing)")
    qa_run = os.path.join(folder, "work", "validation", "qa")
    if os.path.isdir(qa_run) and len(snapshots(qa_run)) != 4:
        failures.append(f"qa: {len(snapshots(qa_run))} snapshots over its fresh run; expected the line's 4")

    # 2. --resume to 0.5 m: one unbroken run's loads; K x segment / sheet length = 4 x 0.2 / 2 -> 1 snapshot.
    done = validate("--until-length", "0.5", "--resume")
    if done.returncode != 0:
        failures.append(f"validate --strips --resume: exit {done.returncode}: {done.stderr.strip()[-500:]}")
    strip_run(os.path.join(folder, "qa_whole"), "0.5", "--snapshots", "4")
    resumed = os.path.join(records, "qa")
    with open(os.path.join(resumed, "summary.json")) as f:
        summary = json.load(f)
    if summary["resumed_at_m"] != [0.3] or summary["pushed_length_m"] != 0.5:
        failures.append(f"qa resumed: resumed at {summary['resumed_at_m']}, L {summary['pushed_length_m']}; "
                        "expected [0.3] and 0.5")
    if not filecmp.cmp(os.path.join(resumed, "loads.csv"), os.path.join(folder, "qa_whole", "loads.csv"), shallow=False):
        failures.append("qa resumed to 0.5 m: loads.csv differs from one strip run to 0.5 m")
    if len(snapshots(qa_run)) != 1:
        failures.append(f"qa resumed: {len(snapshots(qa_run))} snapshots over 0.3-0.5 m; expected 1")

    # 3. Bad input: one line naming it, exit 2, the records untouched.
    before = {n: open(os.path.join(records, "qa", n), "rb").read() for n in os.listdir(os.path.join(records, "qa"))}
    bad = os.path.join(folder, "bad.matrix")
    with open(bad, "w") as f:
        f.write(f"qa {QUICK} --width 1 --until-length 3\n")
    base = ["/usr/bin/python3", study, "validate"]
    cases = [
        (base + ["--strips", bad, "--until-length", "0.6"] + where, "--until-length"),
        (base + ["--strips", matrix, "--seeds", "2", "--until-length", "0.6"] + where, "--strips"),
        (base + ["--strips", matrix, "--resume"] + where, "quick has no experiment's length"),
        (base + ["--strips", os.path.join(folder, "none.matrix")] + where, "none.matrix"),
    ]
    for cmd, needle in cases:
        problem = refusal_problem(cmd, needle)
        if problem:
            failures.append(f"{' '.join(cmd[3:6])}...: {problem}; expected one line naming {needle!r}")
    after = {n: open(os.path.join(records, "qa", n), "rb").read() for n in os.listdir(os.path.join(records, "qa"))}
    if after != before:
        failures.append("a refused sweep changed the records")

    # 4. The default records: docs/validation/strips (asked to resume a run it does not hold, it says where it looked).
    done = subprocess.run(base + ["--strips", matrix, "--resume", "--until-length", "0.6", "--bin", bin_dir,
                                  "--work", os.path.join(folder, "work")], capture_output=True, text=True, timeout=120)
    looked = os.path.join(source, "docs", "validation", "strips", "qa", "checkpoint.bin")
    if looked not in done.stderr:
        failures.append(f"--strips without --records: stderr {done.stderr.strip()!r}; expected it to look for {looked}")

    if failures:
        for f in failures:
            print("FAIL: " + f)
        print(f"(kept: {folder})")
        sys.exit(1)
    shutil.rmtree(folder, ignore_errors=True)
    print("ok: validate --strips runs a strip matrix as scripts/study strip does, resumes it, refuses bad input")


if __name__ == "__main__":
    main()
