#!/usr/bin/python3
"""scripts/study sheet_bending on a hand-made snapshot whose sheet is the parabola z = -A x^2 (x from the
toe): its curvature, steepest slope over 1 m windows, depth, the bond stress across that slope and
the two thresholds are worked out here by hand, for an ice whose bonds no offset alone can break
and for one whose bonds break at a slope; a short strip at the face and a floe are left out; bad
input is named in one line. The thresholds come from `thin_ice probe bond-offset` (the engine's
bond law), so the hand-worked numbers check that probe as well.

    test_sheet_bending.py THIN_ICE SOURCE_DIR   (THIN_ICE: the thin_ice program)
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
# W-3's scenario with the ice made round: h 0.05 m (A/h^2 = 16 at d = 0.2 m), rho_i 900 on rho_w 1000:
# z_rest = 0.025 - 0.045 = -0.02 m. E 1e8 Pa, nu 0.3, d = 0.2 m.
OVERRIDES = ["ice.thickness=0.05", "ice.density=900", "ice.flexural_strength={sigma_f}", "ice.youngs_modulus=1.0e8",
             "ice.poisson_ratio=0.3", "ice.vertical_modulus={vertical}", "ice.smoothing_exponent_v={n}",
             "water.density=1000", "sheet.cell_size=0.2"]
# Strips of 0.2 m from 6 m in front of the toe: centres -5.9 ... -0.3 with five sheet cells each;
# the strip at -0.1 holds one sheet cell, high on the face (fewer than half the usual: left out).
# The steepest 1 m window is the first, six strips -5.9 ... -4.9 about -5.4: slope 2 A 5.4 = 0.054,
# so a bond across it has dz = 0.054 d = 0.0108 m = 0.216 h.
# Deepest: the strip at -5.9, z = -0.005 34.81 = -0.17405, under z_rest by 0.154 m.
# Curvature 2 A = 0.01 1/m; a plate breaks at kappa = 2 (1 - 0.09) sigma_f / (1e8 0.05).
# The bond law: sigma_v = 6 M / (L_e h^2) with M = F_v d / 2 and F_v = K_v G_v h L_e dz / d,
# so sigma_v / sigma_f = 3 (1 - u)^n u G_v / sigma_f at a step dz = u h (G_v = E_v / 2.6).
CASES = [
    # sigma_f 1e5 Pa, E_v 2.6e5 Pa: G_v = 1e5 Pa; n = 1: 3 (1 - u) u, at most 3 / 4 = 0.75 (u = 1/2):
    # never 1. At u = 0.216: 3 0.784 0.216 = 0.508. Plate: 1.82e5 / 5e6 = 0.0364 1/m; 0.01 / 0.0364 = 0.27.
    ({"sigma_f": "1.0e5", "vertical": "2.6e5", "n": "1.0"},
     "no slope alone brings it to sigma_f (at most 0.75 sigma_f, at a slope of 0.125, dz = 0.500 h)",
     "curvature of 0.0364",
     "| 0.500 | 0.154 | 0.0540 | 0.51 | 0.0100 (+- 0.0000) | 0.3 |"),
    # sigma_f 38.4e3 Pa, E_v 2.6e5 Pa: G_v = 1e5 Pa; n = 2: 3 (100/38.4) u (1 - u)^2 = 1 at u = 0.2
    # (3 0.2 0.64 = 0.384), below the top at u = 1/3 (1.157): a slope of 0.2 h / d = 0.05.
    # At u = 0.216: 3 (100/38.4) 0.216 0.784^2 = 1.037. Plate: 1.82 38.4e3 / 5e6 = 0.013978 1/m;
    # 0.01 / 0.013978 = 0.72.
    ({"sigma_f": "38.4e3", "vertical": "2.6e5", "n": "2.0"},
     "it reaches sigma_f at a slope of 0.050 (dz = 0.200 h)",
     "curvature of 0.0140",
     "| 0.500 | 0.154 | 0.0540 | 1.04 | 0.0100 (+- 0.0000) | 0.7 |"),
]


def write_run(folder, source, ice):
    os.makedirs(os.path.join(folder, "snapshots"))
    scenario = os.path.join(source, "config", "scenarios", "W-3.yaml")
    overrides = [o.format(**ice) for o in OVERRIDES]
    with open(os.path.join(folder, "summary.json"), "w") as f:
        json.dump({"scenario": {"name": "hand", "file": scenario, "overrides": overrides},
                   "structure": {"toe_x_m": TOE_X}}, f)
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
    tool, source = sys.argv[1], sys.argv[2]
    script = [os.path.join(source, "scripts", "study"), "sheet_bending"]
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        for k, (ice, header, plate, expected) in enumerate(CASES):
            run = os.path.join(tmp, f"run{k}")
            write_run(run, source, ice)
            done = subprocess.run(script + [run, "--tool", tool], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                  text=True, timeout=120)
            if done.returncode != 0 or expected not in done.stdout.splitlines():
                failures.append(f"case {k}: exit status {done.returncode}, expected {expected!r} in {done.stdout!r} "
                                f"(stderr {done.stderr.strip()!r})")
            if header not in done.stdout or plate not in done.stdout:
                failures.append(f"case {k}: thresholds: {done.stdout.splitlines()[:1]}")
        for args, needle in (([os.path.join(tmp, "none")], "not a run with snapshots"),
                             ([run, "--window", "0"], "--window 0"),
                             ([run, "--reach", "1"], "--reach 1"),
                             ([run, "--tool", os.path.join(tmp, "none")], "cannot start")):
            args = args if "--tool" in args else args + ["--tool", tool]
            problem = refusal_problem(script + args, needle)
            if problem:
                failures.append(f"{args}: {problem}")
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("OK: sheet_bending measures a hand-made parabola's slope and curvature against the thresholds worked out by hand")


if __name__ == "__main__":
    main()
