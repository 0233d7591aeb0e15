#!/usr/bin/python3
"""scripts/study plot draws a run's load record, marks where a run was resumed from its checkpoint (and
says so), draws several runs into one picture with --out, and refuses bad input with one message
naming it.

    test_plot.py THIN_ICE SOURCE_DIR   (THIN_ICE: the thin_ice program)
"""
import json
import os
import sys
import tempfile

from quick_strip import refusal_problem, run_or_fail, strip_scenario


def main():
    thin_ice, source = sys.argv[1], sys.argv[2]
    run = [thin_ice, "run"]
    script = [os.path.join(source, "scripts", "study"), "plot"]
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        whole, split = os.path.join(tmp, "whole"), os.path.join(tmp, "split")
        run_or_fail(run + strip_scenario(source) + ["--until-time", "0.3", "--out", whole])
        run_or_fail(run + strip_scenario(source) + ["--until-time", "0.2", "--out", split])
        run_or_fail([thin_ice, "resume", split, "--until-time", "0.3"])
        with open(os.path.join(split, "summary.json")) as f:
            resumed_at = json.load(f)["resumed_at_m"]
        if len(resumed_at) != 1:
            sys.exit(f"FAIL: the resumed run's summary has resumed_at_m {resumed_at}, expected one length")

        done = run_or_fail(script + [whole, split], "plot")
        lines = done.stdout.strip().splitlines()
        expected = [f"wrote {os.path.join(whole, 'load.png')}",
                    f"wrote {os.path.join(split, 'load.png')} ({split} resumed at L = {resumed_at[0]:g} m)"]
        if lines != expected:
            failures.append(f"report {lines!r}, expected {expected!r}")
        for run in (whole, split):
            png = os.path.join(run, "load.png")
            if not (os.path.exists(png) and os.path.getsize(png) > 10000):
                failures.append(f"{png} missing or under 10 kB")
        both = os.path.join(tmp, "both.png")
        done = run_or_fail(script + [whole, split, "--out", both], "plot --out")
        if not os.path.getsize(both) > 10000 or "resumed at L" not in done.stdout:
            failures.append(f"--out: {os.path.getsize(both)} bytes, report {done.stdout.strip()!r}")

        for args, needle in (([os.path.join(tmp, "none")], "none"),
                             ([whole, "--out", os.path.join(tmp, "both.pgn")], "both.pgn"),
                             ([whole, "--out", os.path.join(tmp, "no_folder", "both.png")], "no_folder")):
            problem = refusal_problem(script + args, needle)
            if problem:
                failures.append(f"{args}: {problem}")
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("OK: scripts/study plot draws each run, marks its resumptions and names bad input in one line")


if __name__ == "__main__":
    main()
