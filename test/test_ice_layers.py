#!/usr/bin/python3
"""scripts/study ice_layers counts the cells under and over the sheet's level in a hand-made run folder
whose answer is worked out below (the sheet told apart from the broken ice by its bonded piece), applies the run's --set overrides, tables and draws two runs
together, counts the broken ice in slices across the width, and names bad input in one line.

    test_ice_layers.py SOURCE_DIR
"""
import csv
import json
import os
import subprocess
import sys
import tempfile

from quick_strip import refusal_problem

# Ice of h = 0.1 m, rho_i = 900 kg/m^3 on water of 1000 kg/m^3: draft 0.09 m, so a cell at rest has
# its centroid at z_rest = 0.05 - 0.09 = -0.04 m; below: z < -0.09 m, above: z > +0.01 m.
# With the override ice.thickness=0.2 instead: z_rest = 0.1 - 0.18 = -0.08 m; below: z < -0.18 m,
# above: z > +0.02 m.
COLUMNS = ["run", "pushed_length_m", "cells_below", "sheet_cells_below", "cells_above", "sheet_cells_above",
           "free_blocks", "sheet_cells", "farthest_broken_below_from_toe_m", "sheet_nearest_to_toe_m"]
SCENARIO = "ice:\n  thickness: 0.1\n  density: 900\nwater:\n  density: 1000\n"
TOE_X = 10.0
# (x [m], z [m], bonded, cells in its bonded piece). The sheet is the largest piece: cells 0, 5, 6.
CELLS = [(5.0, -0.04, True, 3),    # the sheet at rest: neither
         (9.0, -0.10, False, 1),   # broken, below for h = 0.1 only (-0.10 > -0.18), 1.0 m from the toe, free
         (7.5, -0.20, True, 2),    # broken (a floe of 2), below for both, 2.5 m from the toe
         (9.8, 0.015, False, 1),   # broken, above for h = 0.1 only (0.015 < 0.02), free
         (9.9, 0.05, True, 2),     # broken (the floe's other cell), above for both
         (6.0, -0.085, True, 3),   # the sheet, neither for h = 0.1 (-0.085 > -0.09)
         (8.0, -0.095, True, 3)]   # the sheet, pressed down for h = 0.1 only, 2.0 m from the toe
# h = 0.1: below 1, 2, 6 (one the sheet's); above 3, 4; free 1, 3; sheet 3 cells; farthest broken
# below 2.5 m (cell 6 at 2.0 m is the sheet's); the sheet's cell nearest the toe is cell 6, 2.0 m in
# front of it. The "thick" run's snapshot is written without piece_cells, as older snapshots were:
# below 2 only, above 4 only, the sheet unknown, farthest 2.5 m.
EXPECTED_ROW = "| 0.500 | 3 | 1 | 2 | 0 | 2 | 3 | 2.50 | 2.00 |"
EXPECTED_ROW_THICK = "| 0.500 | 1 | - | 1 | - | 2 | - | 2.50 | - |"


# --slice-width over a structure 3 m wide (y from -1.5 to +1.5 m): the cells' y [m], in CELLS' order.
# Broken ice below: cell 1 (y -1.2) and cell 2 (+0.3); above: cells 3 (+1.4) and 4 (+1.5, on the
# edge: the last slice); the sheet's cells (0, 5 and 6, pressed down) are not broken ice. In 1 m
# slices: 1/0, 1/0, 0/2; in 2 m slices (the second only 1 m wide): 2/0, 0/2.
SLICE_YS = [0.0, -1.2, 0.3, 1.4, 1.5, 0.0, -1.0]
EXPECTED_SLICES = {"1": "| 0.500 | 1 / 0 | 1 / 0 | 0 / 2 |", "2": "| 0.500 | 2 / 0 | 0 / 2 |"}
EXPECTED_SLICE_HEADERS = {"1": "| L [m] | y -1.50 to -0.50 m | y -0.50 to +0.50 m | y +0.50 to +1.50 m |",
                          "2": "| L [m] | y -1.50 to +0.50 m | y +0.50 to +1.50 m |"}


def make_run(folder, overrides, with_pieces=True, ys=None, width=None):
    os.makedirs(os.path.join(folder, "snapshots"))
    scenario = os.path.join(folder, "scenario.yaml")
    with open(scenario, "w") as f:
        f.write(SCENARIO)
    with open(os.path.join(folder, "summary.json"), "w") as f:
        json.dump({"scenario": {"name": "hand", "file": scenario, "overrides": overrides},
                   "structure": dict({"toe_x_m": TOE_X}, **({"width_m": width} if width else {}))}, f)
    with open(os.path.join(folder, "snapshots", "index.csv"), "w") as f:
        f.write("file,time_s,pushed_length_m\ncells_000010.csv,10,0.5\n")
    with open(os.path.join(folder, "load_bins.csv"), "w") as f:  # the kept record: two bins of 5 s
        f.write("bin,time_s,pushed_length_m,duration_s,samples,horizontal_calibrated_mean_N,horizontal_calibrated_least_N,"
                "horizontal_calibrated_greatest_N,vertical_raw_mean_N,pusher_force_mean_N,intact_bonds,broken_bonds\n"
                "7,5,0.25,5,500,100,90,110,0,0,10,0\n14,10,0.5,5,500,300,290,310,0,0,9,1\n")
    with open(os.path.join(folder, "snapshots", "cells_000010.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["cell", "x_m", "y_m", "z_m", "yaw_rad", "in_intact_sheet"] + (["piece_cells"] if with_pieces else [])
                   + ["polygon_xy_m"])
        for k, (x, z, bonded, piece) in enumerate(CELLS):
            y = ys[k] if ys else 0.0
            w.writerow([k, x, y, z, 0.0, 1 if bonded else 0] + ([piece] if with_pieces else []) + [""])


def run(script, args):
    return subprocess.run(script + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=60)


def main():
    script = [os.path.join(sys.argv[1], "scripts", "study"), "ice_layers"]
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, overrides, expected in (("plain", [], EXPECTED_ROW),
                                          ("thick", ["ice.thickness=0.2", "ice.smoothing_exponent_h=1"],
                                           EXPECTED_ROW_THICK)):
            folder = os.path.join(tmp, name)
            make_run(folder, overrides, with_pieces=name == "plain")
            out_csv = os.path.join(tmp, name + ".csv")
            done = run(script, [folder, "--csv", out_csv])
            if done.returncode != 0 or expected not in done.stdout.splitlines():
                failures.append(f"{name}: exit status {done.returncode}, expected row {expected!r} in {done.stdout!r}"
                                f" (stderr {done.stderr.strip()!r})")
            elif not os.path.exists(out_csv) or len(open(out_csv).read().splitlines()) != 2:
                failures.append(f"{name}: --csv did not write a header and one row")
        # Both runs at once: one CSV row per run and snapshot, and the comparison plot.
        both_csv, png = os.path.join(tmp, "both.csv"), os.path.join(tmp, "both.png")
        done = run(script, [os.path.join(tmp, "plain"), os.path.join(tmp, "thick"), "--csv", both_csv, "--plot", png])
        if done.returncode != 0:
            failures.append(f"two runs: exit status {done.returncode}, stderr {done.stderr.strip()!r}")
        else:
            lines = open(both_csv).read().splitlines()
            if lines[1:] != ["plain,0.5000,3,1,2,0,2,3,2.500,2.000", "thick,0.5000,1,,1,,2,,2.500,"]:
                failures.append(f"two runs: CSV {lines}")
            if not os.path.exists(png) or os.path.getsize(png) < 10000:
                failures.append("two runs: --plot wrote no picture")
        # --earlier: a resumed run's earlier legs come from an earlier --csv (rows of that run at
        # shorter L than its first snapshot, in order; a row at or past it and other runs' rows are
        # left out), and a CSV with other columns is refused.
        earlier_csv, merged_csv = os.path.join(tmp, "earlier.csv"), os.path.join(tmp, "merged.csv")
        # (written before the last column was added: still read, that column left empty)
        with open(earlier_csv, "w") as f:
            f.write(",".join(COLUMNS[:-1]) + "\n" + "plain,0.3000,1,0,0,0,0,5,0.000\n"
                    + "plain,0.1000,0,0,0,0,0,6,0.000\n" + "plain,0.5000,9,9,9,9,9,9,9.000\n"
                    + "other,0.2000,7,7,7,7,7,7,7.000\n")
        done = run(script, [os.path.join(tmp, "plain"), "--earlier", earlier_csv, "--csv", merged_csv, "--plot", png])
        if done.returncode != 0:
            failures.append(f"--earlier: exit status {done.returncode}, stderr {done.stderr.strip()!r}")
        else:
            lines = open(merged_csv).read().splitlines()
            if lines[1:] != ["plain,0.1000,0,0,0,0,0,6,0.000,", "plain,0.3000,1,0,0,0,0,5,0.000,",
                             "plain,0.5000,3,1,2,0,2,3,2.500,2.000"]:
                failures.append(f"--earlier: CSV {lines}")
        with open(earlier_csv, "w") as f:
            f.write("run,pushed_length_m\nplain,0.1\n")
        problem = refusal_problem(script + [os.path.join(tmp, "plain"), "--earlier", earlier_csv], "--earlier")
        if problem:
            failures.append(f"--earlier with other columns: {problem}")
        # Where across the width the broken ice lies, in slices.
        wide = os.path.join(tmp, "wide")
        make_run(wide, [], ys=SLICE_YS, width=3.0)
        for width, row in EXPECTED_SLICES.items():
            done = run(script, [wide, "--slice-width", width])
            lines = done.stdout.splitlines()
            if done.returncode != 0 or row not in lines or EXPECTED_SLICE_HEADERS[width] not in lines:
                failures.append(f"--slice-width {width}: exit status {done.returncode}, expected {row!r} under "
                                f"{EXPECTED_SLICE_HEADERS[width]!r} in {done.stdout!r} (stderr {done.stderr.strip()!r})")
        problem = refusal_problem(script + [wide, "--slice-width", "0"], "--slice-width 0")
        if problem:
            failures.append(f"--slice-width 0: {problem}")
        bad = os.path.join(tmp, "bad")
        make_run(bad, ["water.density=800"])  # lighter than the ice: nothing floats
        for args, needle in (([os.path.join(tmp, "none")], "not a finished run"),
                             ([bad], "water.density 800")):
            problem = refusal_problem(script + args, needle)
            if problem:
                failures.append(f"{args}: {problem}")
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("OK: ice_layers counts the cells under and over the sheet's level as worked out by hand")


if __name__ == "__main__":
    main()
