#!/usr/bin/python3
"""thin_ice_run --resume: a run stopped at t = 0.4 s and resumed to 0.8 s writes the same loads.csv,
byte for byte, as the run made in one go, and a summary whose statistics cover the whole history;
a directory that cannot be resumed is refused with exit status 2 and left as it was.

    test_run_resume.py THIN_ICE_RUN SOURCE_DIR
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile


def run(tool, args):
    return subprocess.run([tool] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=600)


def main():
    tool, source = sys.argv[1], sys.argv[2]
    # quick.yaml cut to a 1 m strip that meets the structure at ~0.27 s and breaks bonds by 0.4 s.
    scenario = ["--scenario", os.path.join(source, "config/scenarios/quick.yaml"), "--set", "sheet.length=1.0",
                "--set", "structure.toe_x=1.1", "--set", "bottom.distance_from_structure=0.5",
                "--output-interval", "0.02"]
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        whole, split = os.path.join(tmp, "whole"), os.path.join(tmp, "split")
        for args in (scenario + ["--until-time", "0.8", "--out", whole],
                     scenario + ["--until-time", "0.4", "--out", split],
                     ["--resume", split, "--until-time", "0.8"]):
            done = run(tool, args)
            if done.returncode != 0:
                sys.exit(f"FAIL: {' '.join(args)}: exit status {done.returncode}: {done.stderr.strip()}")
        with open(os.path.join(whole, "loads.csv")) as a, open(os.path.join(split, "loads.csv")) as b:
            if a.read() != b.read():
                failures.append("the resumed loads.csv differs from the run made in one go")
        sw, ss = (json.load(open(os.path.join(d, "summary.json"))) for d in (whole, split))
        if ss["status"] != "completed" or ss["resumed_at_m"] != [0.08] or sw["resumed_at_m"] != []:
            failures.append(f"status {ss['status']}, resumed_at_m {ss['resumed_at_m']} (whole: {sw['resumed_at_m']}), "
                            "expected completed, [0.08] ([])")
        if ss["steps"] != sw["steps"] or ss["broken_bonds"] != sw["broken_bonds"]:
            failures.append(f"steps {ss['steps']} / {sw['steps']}, broken bonds {ss['broken_bonds']} / {sw['broken_bonds']}")
        # The old rows are read back from their nine significant digits.
        for key in ("peak_N", "steady_mean_N", "phase1_slope_N_per_m"):
            a, b = sw["load"][key], ss["load"][key]
            if abs(a - b) > 1e-7 * max(1.0, abs(a)):
                failures.append(f"load.{key} {b} after resuming, {a} in one go")
        if ss["load"]["peak_at_m"] != sw["load"]["peak_at_m"]:
            failures.append(f"peak at {ss['load']['peak_at_m']} m after resuming, {sw['load']['peak_at_m']} in one go")

        # Refusals: nothing in the directory changes.
        before = {f: open(os.path.join(split, f), "rb").read() for f in ("loads.csv", "summary.json", "checkpoint.bin")}
        corrupt = os.path.join(tmp, "corrupt")
        shutil.copytree(split, corrupt)
        with open(os.path.join(corrupt, "checkpoint.bin"), "r+b") as f:
            f.truncate(100)
        no_checkpoint = os.path.join(tmp, "no_checkpoint")
        shutil.copytree(split, no_checkpoint)
        os.remove(os.path.join(no_checkpoint, "checkpoint.bin"))
        cases = [(["--resume", split, "--until-time", "0.8"], "already at t = 0.8"),
                 (["--resume", split, "--until-time", "1", "--out", tmp], "give none of them"),
                 (["--resume", split, "--until-time", "1", "--set", "ice.density=900"], "give none of them"),
                 (["--resume", corrupt, "--until-time", "1"], "truncated"),
                 (["--resume", no_checkpoint, "--until-time", "1"], "has no checkpoint.bin"),
                 (scenario + ["--until-time", "1", "--out", tmp, "--accept-changed-scenario"], "with --resume DIR only")]
        for args, expected in cases:
            done = run(tool, args)
            if done.returncode != 2 or expected not in done.stderr:
                failures.append(f"{' '.join(args[-4:])}: exit status {done.returncode}, stderr {done.stderr.strip()!r}; "
                                f"expected 2 and {expected!r}")
        after = {f: open(os.path.join(split, f), "rb").read() for f in before}
        if after != before:
            failures.append("a refused resumption changed the run directory")
        if os.path.exists(os.path.join(corrupt, "loads.csv.partial")):
            failures.append("a refused resumption left loads.csv.partial")
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("OK: resumed run identical to the run in one go; six bad resumptions refused with exit status 2")


if __name__ == "__main__":
    main()
