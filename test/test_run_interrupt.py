#!/usr/bin/python3
"""`thin_ice run` stopped by SIGTERM keeps what it reached: exit status 4, loads.csv with the rows so
far (no loads.csv.partial left), summary.json with status "interrupted" and the pushed length
reached, a last snapshot of that state and a checkpoint to resume from. Three times: a SIGTERM
sent once, the same sent twice 50 ms apart, and a wall budget of GNU timeout, which delivers its
SIGTERM twice (to the command and to its process group): a repeat within 1 s is the same request,
not a second one that kills.

    test_run_interrupt.py THIN_ICE SOURCE_DIR   (THIN_ICE: the thin_ice program)
"""
import csv
import json
import os
import signal
import subprocess
import sys
import tempfile
import time


def stopped_run(thin_ice, source, out, how):
    """Starts quick.yaml pushed for 1000 s of simulated time (hours of stepping, so the signal
    always comes before the target), and stops it with SIGTERM once two rows are written: sent
    here once ("once"), twice 50 ms apart ("twice", what timeout may do), or by GNU timeout after
    3 s of wall time ("timeout")."""
    under_timeout = how == "timeout"
    cmd = [thin_ice, "run", "--scenario", os.path.join(source, "config/scenarios/quick.yaml"), "--until-time", "1000",
           # "twice": an interval of 0.2 s takes long enough (~0.1 s of wall) that the repeat comes
           # while the first request is still being honoured.
           "--output-interval", "0.2" if how == "twice" else "0.01", "--snapshots", "3", "--out", out]
    if under_timeout:
        # --preserve-status: timeout exits with the command's own status, 4 when it kept its output.
        cmd = ["timeout", "--preserve-status", "-s", "TERM", "3"] + cmd
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
    if not under_timeout:
        proc.send_signal(signal.SIGTERM)
    if how == "twice":
        time.sleep(0.05)
        proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=120)
    return proc, err


def main():
    thin_ice, source = sys.argv[1], sys.argv[2]
    for how in ("once", "twice", "timeout"):
        with tempfile.TemporaryDirectory() as out:
            check(*stopped_run(thin_ice, source, out, how), out, "SIGTERM " + how)


def check(proc, err, out, how):
        partial = os.path.join(out, "loads.csv.partial")
        failures = []
        if proc.returncode != 4:
            failures.append(f"exit status {proc.returncode}, expected 4 (stderr: {err.strip()})")
        if os.path.exists(partial):
            failures.append("loads.csv.partial left behind")
        missing = [f for f in ("loads.csv", "summary.json") if not os.path.exists(os.path.join(out, f))]
        if missing:
            sys.exit(f"FAIL ({how}): " + "; ".join(failures + [f"no {f} written" for f in missing]))
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
            sys.exit(f"FAIL ({how}): " + "; ".join(failures))
        print(f"OK ({how}): stopped at t = {summary['simulated_time_s']} s after {len(rows)} rows, exit status 4")


if __name__ == "__main__":
    main()
