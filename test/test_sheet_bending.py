#!/usr/bin/python3
"""scripts/sheet_bending on a hand-made snapshot whose sheet is the parabola z = -A x^2 (x from the
toe): its curvature, steepest slope over 1 m windows, depth, the bond stress across that slope and
the two thresholds are worked out here by hand, for an ice whose bonds no offset alone can break
and for one whose bonds break at a slope; a short strip at the face and a floe are left out; bad
input is named in one line.

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
# h 0.1 m, rho_i 900 on rho_w 1000: z_rest = 0.05 - 0.09 = -0.04 m. E 1e8 Pa, nu 0.3, d = 0.2 m.
SCENARIO = ("ice:\n  thickness: 0.1\n  density: 900\n  flexural_strength: {sigma_f}\n  youngs_modulus: 1.0e8\n"
            "  poisson_ratio: 0.3\n  vertical_modulus: {vertical}\n  smoothing_exponent_v: {n}\n"
            "  vertical_stress: bending\nwater:\n  density: 1000\nsheet:\n  cell_size: 0.2\n")
# Strips of 0.2 m from 6 m in front of the toe: centres -5.9 ... -0.3 with five sheet cells each;
# the strip at -0.1 holds one sheet cell, high on the face (fewer than half the usual: left out).
# The steepest 1 m window is the first, six strips -5.9 ... -4.9 about -5.4: slope 2 A 5.4 = 0.054,
# so a bond across it has dz = 0.054 d = 0.0108 m = 0.108 h.
# Deepest: the strip at -5.9, z = -0.005 34.81 = -0.17405, under z_rest by 0.134 m.
# Curvature 2 A = 0.01 1/m; a plate breaks at kappa = 2 (1 - 0.09) sigma_f / (1e8 0.1).
CASES = [
    # sigma_f 1e5 Pa, E_v 2.6e5 Pa: G_v = 1e5 Pa; n = 1: sigma_v / sigma_f = 3 (1 - u) u G_v / sigma_f,
    # at most 3 / 4 = 0.75 (u = 1/2): never 1. At u = 0.108: 3 0.892 0.108 = 0.289.
    # Plate: 0.0182 1/m, 0.01 / 0.0182 = 0.549.
    ({"sigma_f": "1.0e5", "vertical": "2.6e5", "n": "1.0"},
     "no offset alone brings it to sigma_f (at most 0.75 sigma_f, at dz = h/2)",
     "curvature of 0.0182",
     "| 0.500 | 0.134 | 0.0540 | 0.29 | 0.0100 (+- 0.0000) | 0.5 |"),
    # sigma_f 27e3 Pa, E_v 166.4e3 Pa: G_v = 64e3 Pa; n = 2: 3 (64/27) u (1 - u)^2 = 1 at u = 1/4
    # (3 0.25 0.5625 = 27/64), below the top at u = 1/3: slope 0.25 h / d = 0.125.
    # At u = 0.108: 3 (64/27) 0.108 0.892^2 = 0.611. Plate: 0.004914 1/m, 0.01 / 0.004914 = 2.03.
    ({"sigma_f": "27.0e3", "vertical": "166.4e3", "n": "2.0"},
     "it reaches sigma_f at a slope of 0.125 (dz = 0.250 h)",
     "curvature of 0.0049",
     "| 0.500 | 0.134 | 0.0540 | 0.61 | 0.0100 (+- 0.0000) | 2.0 |"),
]


def write_run(folder, ice):
    os.makedirs(os.path.join(folder, "snapshots"))
    scenario = os.path.join(folder, "scenario.yaml")
    with open(scenario, "w") as f:
        f.write(SCENARIO.format(**ice))
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
        for k, (ice, header, plate, expected) in enumerate(CASES):
            run = os.path.join(tmp, f"run{k}")
            write_run(run, ice)
            done = subprocess.run([script, run], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                  timeout=60)
            if done.returncode != 0 or expected not in done.stdout.splitlines():
                failures.append(f"case {k}: exit status {done.returncode}, expected {expected!r} in {done.stdout!r} "
                                f"(stderr {done.stderr.strip()!r})")
            if header not in done.stdout or plate not in done.stdout:
                failures.append(f"case {k}: thresholds: {done.stdout.splitlines()[:1]}")
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
