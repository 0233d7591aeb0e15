#!/usr/bin/python3
"""`thin_ice run --stall-report S` says on stderr when the run has finished no output row for S
seconds of wall time: what it was doing and where it last was. The full-width M-2 scenario (6000
cells) takes longer than 20 ms to set up and to step one 0.01 s row, so with S = 0.02 s both
phases are reported; with the default (120 s) a short run says nothing of the kind. A value that
is not a time > 0 is refused naming the flag.

    test_stall_report.py THIN_ICE SOURCE_DIR   (THIN_ICE: the thin_ice program)
"""
import os
import re
import subprocess
import sys
import tempfile


def run(thin_ice, source, out, extra):
    cmd = [thin_ice, "run", "--scenario", os.path.join(source, "config/scenarios/M-2.yaml"), "--until-time", "0.02",
           "--set", "numerics.threads=1", "--out", out] + extra
    return subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=300)


def main():
    thin_ice, source = sys.argv[1], sys.argv[2]
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        watched = run(thin_ice, source, os.path.join(tmp, "watched"), ["--stall-report", "0.02"])
        lines = [line for line in watched.stderr.splitlines() if "nothing has moved" in line]
        if watched.returncode != 0:
            failures.append(f"--stall-report 0.02: exit status {watched.returncode}: {watched.stderr[-300:]!r}")
        if not any(re.search(r"nothing has moved for \S+ while setting up .*; no row finished yet$", line)
                   for line in lines):
            failures.append(f"no report while setting up in {lines!r}")
        if not any(re.search(r"while stepping; the last row: t = 0\.01 s, L = 0\.0005 m$", line) for line in lines):
            failures.append(f"no report while stepping, after the first row (t = 0.01 s), in {lines!r}")
        quiet = run(thin_ice, source, os.path.join(tmp, "quiet"), [])
        if quiet.returncode != 0 or "nothing has moved" in quiet.stderr:
            failures.append(f"the default: exit status {quiet.returncode}, stderr {quiet.stderr[-300:]!r}")
        for value in ("0", "-1", "soon"):
            refused = run(thin_ice, source, os.path.join(tmp, "refused"), ["--stall-report", value])
            if refused.returncode != 2 or f"--stall-report '{value}' is invalid" not in refused.stderr:
                failures.append(f"--stall-report {value}: exit status {refused.returncode}, {refused.stderr[:200]!r}")
            if os.path.exists(os.path.join(tmp, "refused")):
                failures.append(f"--stall-report {value}: the refused run left a folder")
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("OK: a run silent for --stall-report seconds says what it was doing and where it last was")


if __name__ == "__main__":
    main()
