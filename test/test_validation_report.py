#!/usr/bin/python3
"""scripts/study validation_report over hand-made runs of the scenarios' reading (docs/validation's
strips/ and full/): issue #31's targets judged as worked out here (a steady mean, phase-1 slope and
weak against medium only where the rule found a window; the peak on every run), the hand-written
files in their places, and bad input refused with one message and the old report left as it was.

    test_validation_report.py SOURCE_DIR
"""
import json
import os
import subprocess
import sys
import tempfile

BIN_COLUMNS = ("bin,time_s,pushed_length_m,duration_s,samples,horizontal_calibrated_mean_N,horizontal_calibrated_least_N,"
               "horizontal_calibrated_greatest_N,vertical_raw_mean_N,pusher_force_mean_N,intact_bonds,broken_bonds")


def write_run(root, folder, width, length, window, mean, peak, slope, experiment):
    """A run recorded at alpha = 0.63 with the statistics given (per run, not per metre) and a kept
    record of 35 mm bins at the steady mean."""
    path = os.path.join(root, folder)
    os.makedirs(path)
    summary = {"pushed_length_m": length, "structure_width_m": width, "calibration_factor": 0.63,
               "load": {"steady_found": window is not None, "steady_window_m": window or [length * 0.75, length],
                        "steady_mean_N": mean, "peak_N": peak, "peak_at_m": 1.0, "phase1_slope_N_per_m": slope},
               "experiment": experiment}
    with open(os.path.join(path, "summary.json"), "w") as f:
        json.dump(summary, f)
    with open(os.path.join(path, "load_bins.csv"), "w") as f:
        f.write(BIN_COLUMNS + "\n")
        for k in range(int(length / 0.035)):
            end = (k + 1) * 0.035
            f.write(f"{k},{end * 20:.9g},{end:.9g},0.7,70,{mean},{mean},{mean},0,0,10,0\n")


def main():
    script = os.path.join(sys.argv[1], "scripts", "study")
    with tempfile.TemporaryDirectory() as tmp:
        runs = os.path.join(tmp, "runs")
        # Weak, a 2 m strip: 1800 / 2 = 900 N/m against 860 (+4.7 %, met); peak 1500 against 1579
        # (-5.0 %, met); slope 200 N/m per m against 150 (+33.3 %).
        write_run(runs, "strips/W-3-s1", 2.0, 6.0, [3.0, 6.0], 1800.0, 3000.0, 400.0,
                  {"width_scale": 0.2, "steady_mean_N": 1720.0, "peak_N": 3158.0})
        # Medium: 750 against 782 (-4.1 %, met); peak 1000 against 1270 (-21.3 %, met); slope 125 (-16.7 %).
        write_run(runs, "strips/M-2-s1", 2.0, 5.0, [2.0, 5.0], 1500.0, 2000.0, 250.0,
                  {"width_scale": 0.2, "steady_mean_N": 1564.0, "peak_N": 2540.0})
        # Strong at full width: no window, so neither its tail mean nor its slope is judged; peak
        # 15000 / 10 = 1500 against 2056 (-27.0 %, missed).
        write_run(runs, "full/S-1", 10.0, 3.0, None, 9000.0, 15000.0, 999.0,
                  {"width_scale": 1.0, "steady_mean_N": 13750.0, "peak_N": 20560.0})
        # A run of a series not in Table 5's list, and a folder that is not a run: left out.
        os.makedirs(os.path.join(runs, "strips", "W-3-s1-old"))
        with open(os.path.join(runs, "phase2_why.md"), "w") as f:
            f.write("**Why the loads miss** the account\n")
        with open(os.path.join(runs, "bench.md"), "w") as f:
            f.write("## How the runs are made\n\nthe bench\n")
        out = os.path.join(tmp, "validation.md")
        done = subprocess.run([sys.executable, script, "validation_report", "--runs", runs, "--out", out],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=120)
        if done.returncode != 0:
            sys.exit(f"FAIL: exit status {done.returncode}: {done.stderr.strip()}")
        text = open(out).read()
    expected = [
        "- A steady window starting before L = 8 m in every series: found in 2 of 3 runs (3 series): W-3 strip, seed 1 "
        "from 3.00 m, M-2 strip, seed 1 from 2.00 m.",
        "- Steady mean within +-10 %: W-3 strip, seed 1 +4.7 % (met); M-2 strip, seed 1 -4.1 % (met).",
        "- Peak within +-25 %: met in 2 of 3 runs (W-3 strip, seed 1, M-2 strip, seed 1); most runs have not reached "
        "the experiment's length, and a peak can still come.",
        "- Phase-1 slope within +-25 % of 1500 N/m on the experiments' 10 m structure (150 N/m per metre of width): "
        "W-3 strip, seed 1 +33.3 %; M-2 strip, seed 1 -16.7 %.",
        "- Weak above medium in steady state: 900 against 750 N/m (met).",
        "- S-1's rubble profile at L = 16 m beside the paper's Fig. 15: not yet (the longest S-1 run has reached 3.00 m).",
        "| S-1 | full, seed 1 | 3.00 (25.7) | none | tail mean 900, not steady (1375) | - | not judged | 1429 "
        "| 1500 (2056) at 1.00 m | -27.0 % | missed | - | not judged |",
    ]
    missing = [line for line in expected if line not in text.splitlines()]
    order = [text.find(s) for s in ("| W-3 | strip, seed 1", "- A steady window", "**Why the loads miss**",
                                    "## How the runs are made", "## Records and history")]
    if -1 in order or order != sorted(order):
        missing.append(f"the table, the targets, phase2_why.md, bench.md and the records in that order ({order})")
    if "W-3-s1-old" in text:
        missing.append("W-3-s1-old is not a run and must be left out")
    if missing:
        sys.exit("FAIL: missing " + repr(missing) + " in:\n" + text)
    # Bad input: one message, exit status 2 (3: nothing to report), and the report already there left as it was.
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "validation.md")
        with open(out, "w") as f:
            f.write("the old report")
        empty, broken, unbinned = (os.path.join(tmp, d) for d in ("empty", "broken", "unbinned"))
        os.makedirs(empty)
        os.makedirs(os.path.join(broken, "strips", "W-3-s1"))
        with open(os.path.join(broken, "strips", "W-3-s1", "summary.json"), "w") as f:
            f.write("{\"load\": ")
        write_run(unbinned, "strips/W-3-s1", 2.0, 1.0, None, 1.0, 1.0, 1.0, {})
        os.remove(os.path.join(unbinned, "strips", "W-3-s1", "load_bins.csv"))
        for runs, code, needle in ((os.path.join(tmp, "no_such"), 2, "no such folder"),
                                   (empty, 3, "holds no run of Table 5's series"), (broken, 2, "is not JSON"),
                                   (unbinned, 2, "has no load_bins.csv")):
            done = subprocess.run([sys.executable, script, "validation_report", "--runs", runs, "--out", out],
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=120)
            if done.returncode != code or needle not in done.stderr or "Traceback" in done.stderr:
                sys.exit(f"FAIL: --runs {runs}: exit status {done.returncode}, stderr {done.stderr.strip()!r}; "
                         f"expected {code} and {needle!r}")
            if open(out).read() != "the old report":
                sys.exit(f"FAIL: --runs {runs} replaced the report already there")
    print("OK: validation_report judges issue #31's targets over the runs as worked out by hand, puts the hand-written "
          "files in their places, and refuses a missing, empty, broken or unbinned --runs folder without touching the report")


if __name__ == "__main__":
    main()
