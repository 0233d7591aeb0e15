#!/usr/bin/python3
"""scripts/study reanalyse with `thin_ice analyse` against the summary `thin_ice run` wrote: the statistics
worked out again from a finished run's loads.csv must be those the run wrote at its end (to the
nine digits of loads.csv), the first failure included, and scripts/study steady_by_length's last row too; a summary whose statistics were spoiled
gets them back; a directory that is not a finished run is refused and left alone.

    test_reanalyse.py THIN_ICE SOURCE_DIR   (THIN_ICE: the thin_ice program)
"""
import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile

from quick_strip import run_or_fail, strip_scenario


def close(a, b):
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(close(x, y) for x, y in zip(a, b))
    if isinstance(a, float) or isinstance(b, float):
        return isinstance(a, (int, float)) and isinstance(b, (int, float)) and abs(a - b) <= 1e-7 * max(abs(b), 1e-3)
    return a == b


def main():
    thin_ice, source = sys.argv[1:3]
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        run = os.path.join(tmp, "run")
        run_or_fail([thin_ice, "run"] + strip_scenario(source) + ["--until-time", "0.6", "--out", run])
        path = os.path.join(run, "summary.json")
        original = json.load(open(path))
        if original["load"].get("first_failure_m") is None:
            sys.exit("FAIL: no bond broke in the strip run: the first failure would not be tested")

        spoiled = dict(original)
        spoiled["load"] = {"peak_N": 0.0}
        spoiled["experiment"] = None
        json.dump(spoiled, open(path, "w"))
        reanalyse = [sys.executable, os.path.join(source, "scripts/study"), "reanalyse", "--tool", thin_ice,
                     "--reason", "test"]
        done = subprocess.run(reanalyse + [run], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=120)
        if done.returncode != 0:
            failures.append(f"reanalyse failed: {done.stderr.strip()}")
        again = json.load(open(path))
        for block in ("load", "experiment"):
            want, got = original.get(block), again.get(block)
            if want is None or got is None:
                if want != got:
                    failures.append(f"{block}: {got} against {want}")
                continue
            for key in want:
                if not close(got.get(key), want[key]):
                    failures.append(f"{block}.{key}: {got.get(key)} against the run's {want[key]}")
        if (again.get("reanalyses") or [{}])[-1].get("why") != "test":
            failures.append(f"reanalyses: {again.get('reanalyses')}")
        if any(again.get(k) != original.get(k) for k in original if k not in ("load", "experiment")):
            failures.append("a part of summary.json other than load and experiment changed")

        # scripts/study steady_by_length: cuts at a third and two thirds of the record, then its end. The
        # end's row is the run's own verdict; a cut's peak is the largest F_cal up to the cut, read
        # here from loads.csv.
        end = original["pushed_length_m"]
        step = end / 3.0
        by_length = subprocess.run([sys.executable, os.path.join(source, "scripts/study"), "steady_by_length", run,
                                    "--step", repr(step), "--tool", thin_ice],
                                   stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=300)
        table = [line for line in by_length.stdout.splitlines() if line.startswith("| ") and line[2].isdigit()]
        if by_length.returncode != 0 or len(table) != 3:
            failures.append(f"steady_by_length: exit {by_length.returncode}, rows {table}, {by_length.stderr.strip()!r}")
        else:
            cells = [[c.strip() for c in line.strip("|").split("|")] for line in table]
            with open(os.path.join(run, "loads.csv")) as f:
                rows = list(csv.DictReader(f))
            first_peak = max(float(r["horizontal_calibrated_N"]) for r in rows
                             if float(r["pushed_length_m"]) <= step + 1e-9)
            want_end = ["found" if original["load"]["steady_found"] else "none",
                        f"{original['load']['steady_mean_N']:.0f}", f"{original['load']['peak_N']:.0f}"]
            if [cells[2][1], cells[2][3], cells[2][5]] != want_end:
                failures.append(f"steady_by_length at the end: {cells[2]} against the run's {want_end}")
            if first_peak >= original["load"]["peak_N"]:
                failures.append("the strip's peak lies in its first third: a cut that is ignored would not be seen")
            if cells[0][5] != f"{first_peak:.0f}" or abs(float(cells[0][0]) - step) > 1e-3:
                failures.append(f"steady_by_length at {step:.3f} m: {cells[0]}, peak up to the cut {first_peak:.0f}")

        # A --tool that is not there: one message naming the key and the value, no traceback.
        missing_tool = os.path.join(tmp, "no_such_thin_ice")
        refused = subprocess.run([sys.executable, os.path.join(source, "scripts/study"), "steady_by_length", run,
                                  "--tool", missing_tool],
                                 stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=60)
        if refused.returncode == 0 or "Traceback" in refused.stderr or missing_tool not in refused.stderr:
            failures.append(f"steady_by_length with a missing --tool: exit {refused.returncode}, {refused.stderr.strip()!r}")

        # Refused, and left alone: a run still writing, and a directory without a summary.
        partial = os.path.join(tmp, "partial")
        shutil.copytree(run, partial)
        open(os.path.join(partial, "loads.csv.partial"), "w").close()
        before = open(os.path.join(partial, "summary.json")).read()
        empty = os.path.join(tmp, "empty")
        os.mkdir(empty)
        done = subprocess.run(reanalyse + [partial, empty], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                              timeout=120)
        if done.returncode != 2 or "loads.csv.partial" not in done.stderr or "summary.json" not in done.stderr:
            failures.append(f"bad directories: exit {done.returncode}, {done.stderr.strip()!r}")
        if open(os.path.join(partial, "summary.json")).read() != before:
            failures.append("a refused run was changed")
        # steady_by_length would otherwise cut the record of an earlier stop without a word.
        done = subprocess.run([sys.executable, os.path.join(source, "scripts/study"), "steady_by_length", partial,
                               "--tool", thin_ice], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=60)
        if done.returncode != 2 or "loads.csv.partial" not in done.stderr or "Traceback" in done.stderr:
            failures.append(f"steady_by_length on a run still writing: exit {done.returncode}, {done.stderr.strip()!r}")
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("OK: the statistics worked out again from loads.csv are those the run wrote")


if __name__ == "__main__":
    main()
