#!/usr/bin/python3
"""scripts/sheet_bending on a hand-made snapshot whose sheet is the parabola z = -A x^2 (x from the
toe): its curvature, steepest slope over 1 m windows, depth and the two thresholds are worked out
here by hand; a short strip at the face and a floe are left out; bad input is named in one line.

    test_sheet_bending.py SOURCE_DIR
"""
import csv
import json
import os
import subprocess
import sys
import tempfile

from quick_strip import refusal_problem

A = 0.005        # [1/m]: curvature 2 A = 0.01 1/m
TOE_X = 10.0
# h 0.1 m, rho_i 900 on rho_w 1000: z_rest = 0.05 - 0.09 = -0.04 m. sigma_f 1e5 Pa, E 1e8 Pa,
# nu 0.3, E_v 2.6e5 Pa: G_v = 2.6e5 / 2.6 = 1e5 Pa; d = 0.2 m.
SCENARIO = ("ice:\n  thickness: 0.1\n  density: 900\n  flexural_strength: 1.0e5\n  youngs_modulus: 1.0e8\n"
            "  poisson_ratio: 0.3\n  vertical_modulus: 2.6e5\n  vertical_stress: bending\n"
            "water:\n  density: 1000\nsheet:\n  cell_size: 0.2\n")
# Strips of 0.2 m from 6 m in front of the toe: centres -5.9 ... -0.3 with five sheet cells each;
# the strip at -0.1 holds one sheet cell, high on the face (fewer than half the usual: left out).
# The steepest 1 m window is the first, six strips -5.9 ... -4.9 about -5.4: slope 2 A 5.4 = 0.054;
# bond breaks at sigma_f h / (3 G_v d) = 1e4 / 6e4 = 0.1667: 0.054 / 0.1667 = 0.32.
# Plate breaks at 2 (1 - 0.09) 1e5 / (1e8 0.1) = 0.0182 1/m: 0.01 / 0.0182 = 0.5 (0.549).
# Deepest: the strip at -5.9, z = -0.005 34.81 = -0.17405, under z_rest by 0.134 m.
EXPECTED = "| 0.500 | 0.134 | 0.0540 | 0.32 | 0.0100 (+- 0.0000) | 0.5 |"


def write_run(folder):
    os.makedirs(os.path.join(folder, "snapshots"))
    scenario = os.path.join(folder, "scenario.yaml")
    with open(scenario, "w") as f:
        f.write(SCENARIO)
    with open(os.path.join(folder, "summary.json"), "w") as f:
        json.dump({"scenario": {"name": "hand", "file": scenario, "overrides": []}, "structure": {"toe_x_m": TOE_X}}, f)
    with open(os.path.join(folder, "snapshots", "index.csv"), "w") as f:
        f.write("file,time_s,pushed_length_m\ncells_000010.csv,10,0.5\n")
    rows = []
    for k in range(29):
        x = -5.9 + 0.2 * k
        rows += [(x, y, -A * x * x, 146) for y in (-2.0, -1.0, 0.0, 1.0, 2.0)]
    rows.append((-0.1, 0.0, 0.3, 146))   # the sheet's ragged front, up the face
    rows.append((-3.0, 3.0, 0.5, 2))     # a floe on the pile: not the sheet
    rows.append((-3.0, 3.2, 0.5, 2))
    with open(os.path.join(folder, "snapshots", "cells_000010.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["cell", "x_m", "y_m", "z_m", "yaw_rad", "in_intact_sheet", "piece_cells", "polygon_xy_m"])
        for k, (x, y, z, piece) in enumerate(rows):
            w.writerow([k, TOE_X + x, y, z, 0.0, 1, piece, ""])


def main():
    script = os.path.join(sys.argv[1], "scripts", "sheet_bending")
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        run = os.path.join(tmp, "run")
        write_run(run)
        done = subprocess.run([script, run], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=60)
        if done.returncode != 0 or EXPECTED not in done.stdout.splitlines():
            failures.append(f"exit status {done.returncode}, expected {EXPECTED!r} in {done.stdout!r} "
                            f"(stderr {done.stderr.strip()!r})")
        if "slope of 0.167" not in done.stdout or "curvature of 0.0182" not in done.stdout:
            failures.append(f"thresholds: {done.stdout.splitlines()[:1]}")
        for args, needle in (([os.path.join(tmp, "none")], "not a run with snapshots"),
                             ([run, "--window", "0"], "--window 0"),
                             ([run, "--reach", "1"], "--reach 1")):
            problem = refusal_problem([script] + args, needle)
            if problem:
                failures.append(f"{args}: {problem}")
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("OK: sheet_bending measures a hand-made parabola's slope and curvature against the thresholds worked out by hand")


if __name__ == "__main__":
    main()
