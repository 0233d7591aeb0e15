#!/usr/bin/python3
"""thin_ice_run stopped by SIGTERM keeps what it reached: exit status 4, loads.csv with the rows so
far (no loads.csv.partial left), summary.json with status "interrupted" and the pushed length
reached, a last snapshot of that state and a checkpoint to resume from.

    test_run_interrupt.py THIN_ICE_RUN SOURCE_DIR
"""
import csv
import json
import os
import signal
import subprocess
import sys
import tempfile
import time


def main():
    run_tool, source = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as out:
        # quick.yaml pushed for 1000 s of simulated time: hours of stepping, so the signal always
        # comes before the target.
        cmd = [run_tool, "--scenario", os.path.join(source, "config/scenarios/quick.yaml"), "--until-time", "1000",
               "--output-interval", "0.01", "--snapshots", "3", "--out", out]
        proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        partial = os.path.join(out, "loads.csv.partial")
        deadline = time.monotonic() + 120.0
        while time.monotonic() < deadline:  # wait for the header and two rows
            if os.path.exists(partial) and sum(1 for _ in open(partial)) >= 3:
                break
            time.sleep(0.05)
        else:
            proc.kill()
            sys.exit("FAIL: no rows within 120 s")
        proc.send_signal(signal.SIGTERM)
        _, err = proc.communicate(timeout=120)
        failures = []
        if proc.returncode != 4:
            failures.append(f"exit status {proc.returncode}, expected 4 (stderr: {err.strip()})")
        if os.path.exists(partial):
            failures.append("loads.csv.partial left behind")
        missing = [f for f in ("loads.csv", "summary.json") if not os.path.exists(os.path.join(out, f))]
        if missing:
            sys.exit("FAIL: " + "; ".join(failures + [f"no {f} written" for f in missing]))
        rows = list(csv.DictReader(open(os.path.join(out, "loads.csv"))))
        summary = json.load(open(os.path.join(out, "summary.json")))
        if summary["status"] != "interrupted":
            failures.append(f"summary status {summary['status']!r}, expected 'interrupted'")
        if len(rows) < 2:
            failures.append(f"{len(rows)} rows kept, expected at least the 2 seen before the signal")
        elif abs(float(rows[-1]["time_s"]) - summary["simulated_time_s"]) > 1e-9:
            failures.append(f"last row at t = {rows[-1]['time_s']} s, summary at {summary['simulated_time_s']} s")
        if not 0.0 < summary["simulated_time_s"] < 1000.0:
            failures.append(f"simulated_time_s {summary['simulated_time_s']}, expected between 0 and the target")
        if not os.path.exists(os.path.join(out, "checkpoint.bin")):
            failures.append("no checkpoint.bin to resume from")
        index = list(csv.DictReader(open(os.path.join(out, "snapshots", "index.csv"))))
        if not index or abs(float(index[-1]["time_s"]) - summary["simulated_time_s"]) > 1e-9:
            failures.append("no snapshot of the state reached")
        if failures:
            sys.exit("FAIL: " + "; ".join(failures))
        print(f"OK: stopped at t = {summary['simulated_time_s']} s after {len(rows)} rows, exit status 4")


if __name__ == "__main__":
    main()
