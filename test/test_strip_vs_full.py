#!/usr/bin/python3
"""scripts/study strip_vs_full: hand-made strip and full-width runs whose loads per metre of width are
worked out here. The table's means and windows, the seed-spread verdict, and --sections (the full
width cut into strip-wide sections of adjacent panels); rows past the span count nowhere; a full
width with only its kept record, strips of two widths, and a section that is not a whole number of
panels are each refused in one line naming the run or the widths.

    test_strip_vs_full.py SOURCE_DIR
"""
import csv
import json
import os
import subprocess
import sys
import tempfile

LOAD_COLUMNS = ["time_s", "pushed_length_m", "horizontal_raw_N", "horizontal_calibrated_N", "vertical_raw_N",
                "pusher_force_N", "intact_bonds", "broken_bonds", "contacts"]
BIN_COLUMNS = ["bin", "time_s", "pushed_length_m", "duration_s", "samples", "horizontal_calibrated_mean_N",
               "horizontal_calibrated_least_N", "horizontal_calibrated_greatest_N", "vertical_raw_mean_N",
               "pusher_force_mean_N", "intact_bonds", "broken_bonds"]
ALPHA = 0.63


def write_run(folder, width, panel_loads, length=3.0, rows=True):
    """A run of `width` m with one panel per metre, recorded at alpha = 0.63, pushed to `length` m
    in rows 0.1 m apart: each panel's raw load [N] is `panel_loads` up to L = 2 m and ten times it
    past 2 m (so a span of 2 m that counted any later row would show it). Without `rows` the run
    has its kept record instead, as a clone of a resumed run: load_bins.csv, 35 mm bins at the
    panels' summed load (no panel columns), and no loads.csv."""
    os.makedirs(folder)
    panels = len(panel_loads)
    summary = {"schema_version": 1, "pushed_length_m": length, "structure_width_m": width,
               "calibration_factor": ALPHA, "loads_csv_from_s": 0.0 if rows else 40.0,
               "structure": {"toe_x_m": 10.0, "angle_deg": 60, "width_m": width, "height_m": 1, "panels": panels}}
    with open(os.path.join(folder, "summary.json"), "w") as f:
        json.dump(summary, f)
    if not rows:
        with open(os.path.join(folder, "load_bins.csv"), "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(BIN_COLUMNS)
            for k in range(int(round(length / 0.035 + 0.5))):
                end = min((k + 1) * 0.035, length)
                total = ALPHA * sum(panel_loads)
                w.writerow([k, 20.0 * end, round(end, 9), 0.7, 70, total, total, total, 0.0, 0.0, 0, 0])
        return
    with open(os.path.join(folder, "loads.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(LOAD_COLUMNS + ["panel_%d_N" % k for k in range(1, panels + 1)])
        for k in range(1, int(round(length / 0.1)) + 1):
            pushed = round(0.1 * k, 9)
            loads = [p * (1 if pushed <= 2.0 + 1e-9 else 10) for p in panel_loads]
            w.writerow([2.0 * pushed, pushed, sum(loads), ALPHA * sum(loads), 0, 0, 0, 0, 0] + loads)


def study(source, *args):
    return subprocess.run(["/usr/bin/python3", os.path.join(source, "scripts", "study"), "strip_vs_full"] + list(args),
                          capture_output=True, text=True)


def main():
    source = sys.argv[1]
    failures = []
    with tempfile.TemporaryDirectory() as root:
        run = lambda name: os.path.join(root, name)  # noqa: E731
        # Strips 2 m wide: 0.63 x 1000 / 2 = 315 and 0.63 x 1400 / 2 = 441 N/m; mean 378, range 126.
        write_run(run("strip-a"), 2.0, [600.0, 400.0])
        write_run(run("strip-b"), 2.0, [700.0, 700.0])
        # Full width of four 1 m panels: 0.63 x 1540 / 4 = 242.55 N/m, 135.45 under the strips' mean:
        # outside the range of 126 (-35.8 %). Sections of 2 m: panels 1-2 0.63 x 1200 / 2 = 378 (within
        # 315-441), 2-3 0.63 x 600 / 2 = 189, 3-4 0.63 x 340 / 2 = 107.1.
        write_run(run("full"), 4.0, [700.0, 500.0, 100.0, 240.0])
        done = study(source, "--span", "2", "--window", "1", "--sections", "--full", run("full"),
                     "--strips", run("strip-a"), run("strip-b"))
        expected = [
            "| full | full | 243 | 243 | 243 |",
            "| strip-a | strip | 315 | 315 | 315 |",
            "| strip-b | strip | 441 | 441 | 441 |",
            "Strips: mean 378 N/m, seed range 315-441 N/m (126, 33.3 % of the mean); full width: 243 N/m "
            "(-35.8 % of the strips' mean): outside the seed spread.",
            "full in sections of 2 m (panels 1-2, 2-3, 3-4): 378, 189, 107 N/m over 0-2.0 m; 107-378 N/m, "
            "1 of 3 within the strips' range.",
        ]
        lines = done.stdout.splitlines()
        missing = [line for line in expected if line not in lines]
        if done.returncode != 0 or missing:
            failures.append("sections: exit %d, missing %r in:\n%s%s" % (done.returncode, missing, done.stdout,
                                                                       done.stderr))
        # Sections 1 m wide (one panel each) against 1 m strips: 0.63 x 700 / 1 = 441, then 315, 63, 151.2.
        write_run(run("strip-narrow"), 1.0, [1000.0])
        done = study(source, "--span", "2", "--sections", "--full", run("full"), "--strips", run("strip-narrow"))
        if ("full in sections of 1 m (panels 1, 2, 3, 4): 441, 315, 63, 151 N/m over 0-2.0 m; 63-441 N/m, "
                "0 of 4 within the strips' range.") not in done.stdout.splitlines():
            failures.append("one-panel sections: exit %d:\n%s%s" % (done.returncode, done.stdout, done.stderr))

        # Bad input: each refused in one line on stderr, exit status 2, nothing on stdout.
        write_run(run("full-bins-only"), 4.0, [700.0, 500.0, 100.0, 240.0], rows=False)
        write_run(run("strip-wide"), 1.5, [500.0, 500.0])
        refusals = [
            (["--full", run("full-bins-only"), "--strips", run("strip-a")], ["full-bins-only", "--sections"]),
            (["--full", run("full"), "--strips", run("strip-a"), run("strip-narrow")], ["1, 2 m wide"]),
            (["--full", run("full"), "--strips", run("strip-wide")], ["full", "1.5 m", "4 panels of 1 m"]),
        ]
        for args, words in refusals:
            # A strip of 1.5 m has rows to 3 m like the others; only the span the full width covers counts.
            done = study(source, "--span", "2", "--sections", *args)
            err = done.stderr.strip()
            if done.returncode != 2 or done.stdout or "\n" in err or not all(w in err for w in words):
                failures.append("refusal %r: exit %d, stdout %r, stderr %r (wanted %r)"
                                % (args, done.returncode, done.stdout, err, words))
    if failures:
        sys.exit("FAIL:\n" + "\n".join(failures))
    print("OK: strip_vs_full's means, verdict and strip-wide sections of the full width as worked out by hand; "
          "three bad inputs refused in one line each")


if __name__ == "__main__":
    main()
