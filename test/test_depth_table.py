#!/usr/bin/python3
"""scripts/thin_ice_study/depth_table.py, the table of docs/validation.md on the water depth over the
false bottom: hand-made strip runs whose numbers are worked out here. The strips at another depth
are listed with the strips of the same series at the scenarios' depth and no others; a run
recorded at alpha = 1 is rescaled to the paper's 0.63; a span the run has not pushed past is left
empty; the window is the one the run's summary holds.

    test_depth_table.py SOURCE_DIR
"""
import csv
import json
import math
import os
import sys
import tempfile

COLUMNS = ["bin", "time_s", "pushed_length_m", "duration_s", "samples", "horizontal_calibrated_mean_N",
           "horizontal_calibrated_least_N", "horizontal_calibrated_greatest_N", "vertical_raw_mean_N",
           "pusher_force_mean_N", "intact_bonds", "broken_bonds"]


def write_run(folder, alpha, length, raw, depth, window=None):
    """A 2 m strip recorded at `alpha`, pushed to `length` [m] at a constant raw load `raw` [N], the
    false bottom `depth` m deep (None: no bottom), and the rule's window [begin, end] or none."""
    os.makedirs(folder)
    load = {"steady_found": window is not None, "steady_window_m": window or [0.75 * length, length],
            "steady_mean_N": alpha * raw}
    summary = {"schema_version": 1, "pushed_length_m": length, "structure_width_m": 2.0, "calibration_factor": alpha,
               "load": load, "false_bottom": None if depth is None else {"depth_m": depth,
                                                                          "distance_from_structure_m": 4.0}}
    with open(os.path.join(folder, "summary.json"), "w") as f:
        json.dump(summary, f)
    with open(os.path.join(folder, "load_bins.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for k in range(int(math.ceil(length / 0.035 - 1e-9))):
            end = min((k + 1) * 0.035, length)
            w.writerow([k, 20.0 * end, round(end, 9), 0.7, 70, alpha * raw, alpha * raw, alpha * raw, 0.0, 0.0, 0, 0])


def main():
    sys.path.insert(0, os.path.join(sys.argv[1], "scripts"))
    from thin_ice_study.depth_table import depth_table

    with tempfile.TemporaryDirectory() as root:
        strips = os.path.join(root, "strips")
        # W-3 at the scenarios' 0.25 m, to 9 m at 1000 N raw: 0.63 x 1000 / 2 = 315 N/m over 2-5
        # and 5-8 m; 8-10 m not reached.
        write_run(os.path.join(strips, "W-3-s1"), 0.63, 9.0, 1000.0, 0.25)
        # W-3 at 0.15 m, recorded at alpha = 1, to 10.5 m at 1200 N raw: 0.63 x 1200 / 2 = 378 N/m in
        # every span; its window 7-10.5 m at the same load.
        write_run(os.path.join(strips, "W-3-s2-bottom0.15"), 1.0, 10.5, 1200.0, 0.15, [7.0, 10.5])
        # Left out: a series with no run at another depth, a run without the bottom, a folder
        # that is not a run.
        write_run(os.path.join(strips, "M-2-s1"), 0.63, 6.0, 900.0, 0.25)
        write_run(os.path.join(strips, "W-3-s3"), 0.63, 6.0, 900.0, None)
        os.makedirs(os.path.join(strips, "W-3-s4"))
        lines = depth_table(root)
        with tempfile.TemporaryDirectory() as empty:
            nothing = depth_table(empty)
    expected = [
        "| series | seed | depth [m] | L [m] | alpha F 2-5 m [N/m] | alpha F 5-8 m [N/m] | alpha F 8-10 m [N/m] "
        "| steady window at the end |",
        "|---|---:|---:|---:|---:|---:|---:|---|",
        "| W-3 | 2 | 0.15 | 10.50 | 378 | 378 | 378 | 7.00-10.50 m, 378 N/m |",
        "| W-3 | 1 | 0.25 | 9.00 | 315 | 315 | - | none |",
    ]
    failures = []
    if lines != expected:
        failures.append("table:\n" + "\n".join(lines) + "\nexpected:\n" + "\n".join(expected))
    if nothing != []:
        failures.append(f"a folder without runs gave {nothing!r}, expected no lines")
    if failures:
        sys.exit("FAIL: " + "\n".join(failures))
    print("OK: depth_table lists the strips at another depth beside their series' strips at the scenarios' depth, "
          "rescaled to alpha = 0.63, each span only where the run passed its end")


if __name__ == "__main__":
    main()
