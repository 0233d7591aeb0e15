#!/usr/bin/python3
"""scripts/study recalibrate against the independent answer: a run made at alpha = 0.63 and brought to
1.7 must say what a run made at 1.7 says (loads.csv and the load statistics of summary.json);
the run's own --set of alpha wins over the scenario file; a run with a checkpoint goes only to the
alpha a resumed run would write; bad input is refused whole.

    test_recalibrate.py THIN_ICE SOURCE_DIR   (THIN_ICE: the thin_ice program)
"""
import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile

from quick_strip import run_or_fail, strip_scenario

STATISTICS = ("peak_N", "phase1_slope_N_per_m", "steady_mean_N", "steady_std_N")
WINDOWS = ("peak_at_m", "first_failure_m", "steady_found", "steady_window_m", "steady_samples", "phase1_range_m")


def run(thin_ice, source, out, alpha):
    run_or_fail([thin_ice, "run"] + strip_scenario(source) +
                ["--until-time", "0.6", "--set", f"structure.calibration_factor={alpha}", "--out", out])


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def tool(source, thin_ice, *args):
    return subprocess.run([sys.executable, os.path.join(source, "scripts/study"), "recalibrate", "--tool", thin_ice,
                           *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=60)


def relative(a, b):
    return abs(a - b) / max(abs(b), 1e-300)


def main():
    thin_ice, source = sys.argv[1:3]
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        low, high = os.path.join(tmp, "low"), os.path.join(tmp, "high")
        run(thin_ice, source, low, 0.63)
        run(thin_ice, source, high, 1.7)
        before = rows(os.path.join(low, "loads.csv"))
        if max(float(r["horizontal_raw_N"]) for r in before) < 10.0:
            sys.exit("FAIL: the strip never loaded the structure: the comparison would test nothing")

        # The run's own --set of alpha wins over the scenario file's value.
        done = tool(source, thin_ice, low)
        if done.returncode != 0 or "already at alpha = 0.63" not in done.stdout:
            failures.append(f"default alpha: expected the run's --set 0.63 to be kept, got {done.stdout!r}")

        # Bad alpha: refused with the value named, nothing written.
        summary_text = open(os.path.join(low, "summary.json")).read()
        for bad in ("0", "-1", "nan"):
            done = tool(source, thin_ice, low, "--alpha", bad)
            if done.returncode != 2 or "alpha must be a finite number > 0" not in done.stderr:
                failures.append(f"--alpha {bad}: exit {done.returncode}, {done.stderr.strip()!r}")
        if open(os.path.join(low, "summary.json")).read() != summary_text or rows(os.path.join(low, "loads.csv")) != before:
            failures.append("a refused --alpha changed the run")

        # A run still being written is refused.
        partial = os.path.join(tmp, "partial")
        shutil.copytree(low, partial)
        open(os.path.join(partial, "loads.csv.partial"), "w").close()
        if tool(source, thin_ice, partial, "--alpha", "1.7").returncode != 2:
            failures.append("a directory with loads.csv.partial was not refused")

        # Without a --set of alpha the scenario file's value is taken (quick.yaml's, read here).
        from_file = os.path.join(tmp, "from_file")
        shutil.copytree(low, from_file)
        path = os.path.join(from_file, "summary.json")
        summary = json.load(open(path))
        summary["scenario"]["overrides"] = [o for o in summary["scenario"]["overrides"]
                                            if not o.startswith("structure.calibration_factor=")]
        json.dump(summary, open(path, "w"))
        import yaml
        alpha_file = float(yaml.safe_load(open(os.path.join(source, "config/scenarios/quick.yaml")))
                           ["structure"]["calibration_factor"])
        done = tool(source, thin_ice, from_file)
        got = json.load(open(path)).get("calibration_factor")
        if done.returncode != 0 or got != alpha_file:
            failures.append(f"alpha from the scenario file: {got} against quick.yaml's {alpha_file} ({done.stderr.strip()})")

        # A run that can be resumed goes only to the alpha its resumed rows would carry.
        done = tool(source, thin_ice, low, "--alpha", "1.7")
        if done.returncode != 2 or "has a checkpoint" not in done.stderr:
            failures.append(f"--alpha 1.7 on a run with a checkpoint at 0.63: exit {done.returncode}, {done.stderr.strip()!r}")
        # ... and when its scenario cannot be loaded, the message says why --alpha is not enough.
        lost = os.path.join(tmp, "lost")
        shutil.copytree(low, lost)
        path = os.path.join(lost, "summary.json")
        summary = json.load(open(path))
        summary["scenario"]["file"] = os.path.join(tmp, "no_such_scenario.yaml")
        json.dump(summary, open(path, "w"))
        done = tool(source, thin_ice, lost, "--alpha", "1.7")
        if done.returncode != 2 or "checkpoint.bin" not in done.stderr or "give --alpha" in done.stderr:
            failures.append(f"--alpha on a run with a checkpoint and no scenario: exit {done.returncode}, "
                            f"{done.stderr.strip()!r}")
        os.remove(os.path.join(low, "checkpoint.bin"))

        # 0.63 brought to 1.7 against the run made at 1.7.
        done = tool(source, thin_ice, low, "--alpha", "1.7")
        if done.returncode != 0:
            failures.append(f"recalibrate 0.63 -> 1.7 failed: {done.stderr.strip()}")
        after, reference = rows(os.path.join(low, "loads.csv")), rows(os.path.join(high, "loads.csv"))
        if len(after) != len(reference):
            failures.append(f"{len(after)} rows against {len(reference)}")
        for a, b, old in zip(after, reference, before):
            if relative(float(a["horizontal_calibrated_N"]), float(b["horizontal_calibrated_N"])) > 1e-8 and \
                    abs(float(b["horizontal_calibrated_N"])) > 1e-6:
                failures.append(f"t = {a['time_s']}: F_cal {a['horizontal_calibrated_N']} against {b['horizontal_calibrated_N']}")
                break
            if any(a[k] != old[k] for k in a if k != "horizontal_calibrated_N"):
                failures.append(f"t = {a['time_s']}: a column other than F_cal changed")
                break
        s, ref = (json.load(open(os.path.join(d, "summary.json"))) for d in (low, high))
        # The statistics come from the kept record's bins: their means, written at nine significant
        # digits and rescaled, against those of the run made at 1.7 (two roundings of 5e-10 each);
        # the scatter is a difference of such means, ten times smaller than them, so 1e-7.
        for key in STATISTICS:
            got, want = s["load"].get(key), ref["load"].get(key)
            if (got is None) != (want is None) or (want is not None and relative(got, want) > 1e-7):
                failures.append(f"load.{key}: {got} against {want} from the run at 1.7")
        for key in WINDOWS:
            if s["load"].get(key) != ref["load"].get(key):
                failures.append(f"load.{key}: {s['load'].get(key)} against {ref['load'].get(key)}")
        for key in ("steady_mean_error_percent", "peak_error_percent"):
            got, want = (s.get("experiment") or {}).get(key), (ref.get("experiment") or {}).get(key)
            if (got is None) != (want is None) or (want is not None and abs(got - want) > 1e-6):
                failures.append(f"experiment.{key}: {got} against {want}")
        if s["calibration_factor"] != 1.7 or s.get("recalibrations", [{}])[-1].get("from_alpha") != 0.63:
            failures.append(f"calibration_factor {s['calibration_factor']}, recalibrations {s.get('recalibrations')}")
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("OK: a run brought from alpha 0.63 to 1.7 says what the run made at 1.7 says")


if __name__ == "__main__":
    main()
