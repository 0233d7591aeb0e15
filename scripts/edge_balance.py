#!/usr/bin/python3
"""Vertical force balance of the front row of cells of a run, snapshot by snapshot.

    scripts/edge_balance.py RUN_DIR

RUN_DIR is a thin_ice_run output with --snapshots (cells_000000.csv, the sheet at rest, is needed
to find the front row and its bonds). The front row is every cell that touches the sheet's front
edge at rest; the cut is the set of bonds from it to the cells behind. For each snapshot this
prints the structure's vertical load on the ice (loads.csv, the mean over that output interval)
beside the two things that carry it while no bond has broken:
  - the elastic vertical force of the bonds across the cut, Eq. (12): K_v(dz) G_v h L_e / d dz
    with dz the front cell's height above the rear cell's;
  - the buoyancy the front row has lost by being lifted: rho_w g A clamp(z - z_float, -(h - draft),
    draft) per cell, which is the row's whole weight once it is out of the water.
The rest (bond damping, heave drag, inertia) is the difference. The material comes from the run's
scenario file and its ice.* / water.* overrides.
"""
import csv
import json
import math
import os
import sys

import yaml


def read_cells(path):
    cells = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            v = [float(t) for t in r["polygon_xy_m"].split()]
            cells[int(r["cell"])] = {"x": float(r["x_m"]), "y": float(r["y_m"]), "z": float(r["z_m"]),
                                     "poly": list(zip(v[0::2], v[1::2]))}
    return cells


def polygon_area(poly):
    n = len(poly)
    return 0.5 * abs(sum(poly[k][0] * poly[(k + 1) % n][1] - poly[(k + 1) % n][0] * poly[k][1] for k in range(n)))


def scenario_values(summary):
    """The scenario's sections with the run's overrides applied (numbers only)."""
    with open(summary["scenario"]["file"]) as f:
        s = yaml.safe_load(f)
    for o in summary["scenario"]["overrides"]:
        key, value = o.split("=", 1)
        section, name = key.split(".", 1)
        try:
            s.setdefault(section, {})[name] = float(value)
        except ValueError:
            s.setdefault(section, {})[name] = value
    return s


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: scripts/edge_balance.py RUN_DIR")
    run = sys.argv[1]
    with open(os.path.join(run, "summary.json")) as f:
        summary = json.load(f)
    s = scenario_values(summary)
    ice, water, sheet = s["ice"], s.get("water", {}), s["sheet"]
    h, rho_i = float(ice["thickness"]), float(ice["density"])
    rho_w, g = float(water.get("density", 1000.0)), float(water.get("gravity", 9.81))
    shear_v = float(ice["vertical_modulus"]) / (2.0 * (1.0 + float(ice["poisson_ratio"])))  # G_v [Pa]
    exponent_v = float(ice["smoothing_exponent_v"])
    draft = rho_i / rho_w * h
    z_float = 0.5 * h - draft
    front_x = float(sheet.get("x_min", 0.0)) + float(sheet["length"])

    rest = read_cells(os.path.join(run, "snapshots", "cells_000000.csv"))
    front = {k for k, c in rest.items() if max(p[0] for p in c["poly"]) > front_x - 1e-9}
    owners = {}  # rounded vertex -> cells: two cells that share two vertices share an edge
    key = lambda p: (round(p[0], 9), round(p[1], 9))
    for k, c in rest.items():
        for p in c["poly"]:
            owners.setdefault(key(p), set()).add(k)
    bonds = []  # (front cell, rear cell, vertical stiffness at K_v = 1 [N/m])
    for i in front:
        poly = rest[i]["poly"]
        for a in range(len(poly)):
            p, q = poly[a], poly[(a + 1) % len(poly)]
            for j in (owners[key(p)] & owners[key(q)]) - front:
                d = math.dist((rest[i]["x"], rest[i]["y"]), (rest[j]["x"], rest[j]["y"]))
                bonds.append((i, j, shear_v * h * math.dist(p, q) / d))
    rear = {j for _, j, _ in bonds}
    front_area = sum(polygon_area(rest[k]["poly"]) for k in front)
    print(f"front row: {len(front)} cells, {front_area:.3f} m^2, weight {rho_i * g * h * front_area:.0f} N; "
          f"{len(bonds)} bonds across the cut to {len(rear)} cells")

    with open(os.path.join(run, "loads.csv")) as f:
        loads = list(csv.DictReader(f))
    with open(os.path.join(run, "snapshots", "index.csv")) as f:
        index = list(csv.DictReader(f))
    print("| L [m] | structure's vertical load [N] | bonds across the cut [N] | buoyancy lost by the front row [N] "
          "| sum [N] | front row lift [mm] | row behind lift [mm] | broken bonds |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|")
    for entry in index:
        row = int(entry["file"][6:12])
        if row == 0:
            continue
        cells = read_cells(os.path.join(run, "snapshots", entry["file"]))
        bond_force = 0.0
        for i, j, stiffness in bonds:
            dz = cells[i]["z"] - cells[j]["z"]
            smoothing = max(0.0, 1.0 - abs(dz) / h) ** exponent_v
            bond_force += smoothing * stiffness * dz
        lost = sum(rho_w * g * polygon_area(rest[k]["poly"]) * min(max(cells[k]["z"] - z_float, -(h - draft)), draft)
                   for k in front)
        load = loads[row - 1]
        lost += 0.0  # no "-0" in the table
        print(f"| {float(load['pushed_length_m']):.4f} | {0.0 - float(load['vertical_raw_N']):.0f} | {bond_force:.0f} | "
              f"{lost:.0f} | {bond_force + lost:.0f} | "
              f"{1e3 * sum(cells[k]['z'] - z_float for k in front) / len(front):.1f} | "
              f"{1e3 * sum(cells[k]['z'] - z_float for k in rear) / len(rear):.1f} | {load['broken_bonds']} |")


if __name__ == "__main__":
    main()
