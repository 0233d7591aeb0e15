#!/usr/bin/python3
"""scripts/study validation_report judges issue #6's targets per ice type on the longest run of the
type: hand-made summaries whose errors are chosen on either side of each tolerance (+-10 % steady mean,
+-25 % peak and phase-1 slope) must come out met or missed as worked out here, a run without a
steady window must not be judged on its tail mean, and weak against medium is the ratio of the
two longest runs' steady means.

    test_validation_report.py SOURCE_DIR
"""
import json
import os
import subprocess
import sys
import tempfile

EXPERIMENT = {"W": (8600.0, 15790.0), "M": (7820.0, 12700.0), "S": (13750.0, 20560.0)}


def write_run(root, name, kind, length, steady, mean, peak, slope):
    folder = os.path.join(root, name)
    os.makedirs(folder)
    exp_mean, exp_peak = EXPERIMENT[kind]
    summary = {"pushed_length_m": length, "cells": 6000, "backend": "cpu", "time_step_s": 4e-05,
               "structure_width_m": 10, "calibration_factor": 1,
               "load": {"steady_found": steady, "steady_mean_N": mean, "peak_N": peak,
                        "phase1_slope_N_per_m": slope, "first_failure_m": 0.06},
               "experiment": {"width_scale": 1, "steady_mean_N": exp_mean, "peak_N": exp_peak}}
    with open(os.path.join(folder, "summary.json"), "w") as f:
        json.dump(summary, f)


def main():
    script = os.path.join(sys.argv[1], "scripts", "study")
    with tempfile.TemporaryDirectory() as tmp:
        runs = os.path.join(tmp, "runs")
        # Weak: the 0.5 m run is shorter, so W-3-long is judged. Steady mean +9 % (met), peak -26 %
        # (missed), slope +24 % (met).
        write_run(runs, "W-3", "W", 0.5, False, 4000.0, 7000.0, 5000.0)
        write_run(runs, "W-3-long", "W", 5.5, True, 9374.0, 11684.6, 1860.0)
        # Medium: steady mean -11 % (missed), peak +24 % (met), slope -26 % (missed).
        write_run(runs, "M-2-long", "M", 3.5, True, 6959.8, 15748.0, 1110.0)
        # A variant is not a series run: never the one judged, though it is the longest.
        write_run(runs, "M-2-fine", "M", 9.0, True, 7820.0, 12700.0, 1500.0)
        # Strong: no steady window, so neither its tail mean nor its slope is judged.
        write_run(runs, "S-1", "S", 0.5, False, 13750.0, 20560.0, 1500.0)
        # The hand-written account of the misses goes right under the table it explains.
        with open(os.path.join(runs, "misses.md"), "w") as f:
            f.write("### Why each miss\n\nthe account\n")
        # Phase 2's account follows the misses it works on.
        with open(os.path.join(runs, "phase2.md"), "w") as f:
            f.write("### Phase 2\n\nthe readings\n")
        # The procedure follows it, before the tables; the dated notes come last, after the plots.
        with open(os.path.join(runs, "procedure.md"), "w") as f:
            f.write("## Calibration procedure\n\nthe procedure\n")
        with open(os.path.join(runs, "calibration.md"), "w") as f:
            f.write("## Calibration notes, newest first\n\nthe notes\n")
        out = os.path.join(tmp, "validation.md")
        done = subprocess.run([sys.executable, script, "validation_report", "--runs", runs, "--out", out],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=120)
        if done.returncode != 0:
            sys.exit(f"FAIL: exit status {done.returncode}: {done.stderr.strip()}")
        text = open(out).read()
    expected = [
        "| weak | W-3-long | 5.50 | 9374 (8600) | +9.0 % | met | 11685 (15790) | -26.0 % | missed "
        "| 1860 (1500) | +24.0 % | met |",
        "| medium | M-2-long | 3.50 | 6960 (7820) | -11.0 % | missed | 15748 (12700) | +24.0 % | met "
        "| 1110 (1500) | -26.0 % | missed |",
        "| strong | S-1 | 0.50 | tail mean 13750 (13750) | +0.0 % | no steady window | 20560 (20560) | +0.0 % | met "
        "| 1500 (1500) | - | no steady window |",
        # 9374 / 6959.8 = 1.347
        "Weak above medium in steady state: W-3-long / M-2-long = 1.35 (met; the experiment: 1.10).",
    ]
    missing = [line for line in expected if line not in text.splitlines()]
    account = text.find("### Why each miss")
    phase2 = text.find("### Phase 2")
    procedure = text.find("## Calibration procedure")
    if not (text.find("Weak above medium in steady state:") < account < phase2 < procedure < text.find("## Table 6")):
        missing.append("misses.md, phase2.md, then procedure.md, between 'Targets at a glance' and 'Table 6'")
    # The dated notes are linked after the load histories, not copied in.
    if not (0 < text.find("## Load histories") < text.find("## Calibration notes")
            and "(runs/calibration.md)" in text and "the notes" not in text.splitlines()):
        missing.append("a link to calibration.md after 'Load histories', its text not copied in")
    if missing:
        section = text[text.find("## Targets at a glance"):text.find("## Table 6")]
        sys.exit("FAIL: missing lines " + repr(missing) + " in:\n" + section)
    # Bad input: one message, exit status 2, and the report already there left as it was.
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "validation.md")
        with open(out, "w") as f:
            f.write("the old report")
        empty, broken = os.path.join(tmp, "empty"), os.path.join(tmp, "broken")
        os.makedirs(empty)
        os.makedirs(os.path.join(broken, "W-3"))
        with open(os.path.join(broken, "W-3", "summary.json"), "w") as f:
            f.write("{\"load\": ")
        for runs, needle in ((os.path.join(tmp, "no_such"), "no such folder"), (empty, "holds no run"),
                             (broken, "is not JSON")):
            done = subprocess.run([sys.executable, script, "validation_report", "--runs", runs, "--out", out],
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=120)
            if done.returncode != 2 or needle not in done.stderr or "Traceback" in done.stderr:
                sys.exit(f"FAIL: --runs {runs}: exit status {done.returncode}, stderr {done.stderr.strip()!r}; "
                         f"expected 2 and {needle!r}")
            if open(out).read() != "the old report":
                sys.exit(f"FAIL: --runs {runs} replaced the report already there")
    print("OK: validation_report judges each ice type's longest run against the tolerances as worked out by hand, "
          "puts misses.md under that table and procedure.md after it, the dated notes last, and refuses a missing, empty or broken --runs folder without touching the report")


if __name__ == "__main__":
    main()
