"""How far the intact sheet is pressed down in front of the structure, and whether the model's bond
law could break it there, per snapshot of a run.

The sheet (the largest piece held together by intact bonds, snapshot column piece_cells) is
averaged across its width in strips of one cell size along x (a strip with fewer than half the
usual number of cells, at the sheet's ragged front, is left out); this profile z(x) gives
  - the greatest depth under the level at which a cell floats at rest, z_rest = h/2 - (rho_i/rho_w) h;
  - the steepest slope |dz/dx|, from least-squares lines over windows of WINDOW metres;
  - the greatest curvature |d2z/dx2|, from least-squares parabolas over windows of 2 WINDOW metres,
    with its standard error (from the scatter of the strip means about the parabola).
Against two thresholds, both worked out by the engine's own laws for the run's scenario and
overrides (`thin_ice probe bond-offset`, so that nothing here restates a law):
  - sigma_v / sigma_f of Eq. (13) that the model's bond law gives a bond across the measured slope,
    (sigma_v the bending stress of the engine's bond law): a height step dz = slope d between its two cells, d being
    the length of the sheet's bond nearest sheet.cell_size, with no horizontal strain. A ratio >= 1
    breaks the bond (without compression). The smoothing K_v of Eq. (6) falls as the step grows, so sigma_v has a top; where
    that top is below sigma_f no step alone breaks a bond, and the header says so. The model senses
    the slope of the sheet, not its curvature;
  - the curvature at which an elastic plate of the same E, nu and h reaches sigma_f at its surface,
    kappa_break = 2 (1 - nu^2) sigma_f / (E h).
A sheet bent past kappa_break would break as a plate and does not in the model.

usage: scripts/study sheet_bending RUN_DIR [--window M] [--reach M] [--every K] [--tool PATH]
  RUN_DIR  a folder of `thin_ice run` with summary.json and snapshots/ (--snapshots N)
  --window length of the slope windows [m] (default 1.0; curvature windows are twice as long)
  --reach  how far in front of the structure's toe the profile is taken [m] (default 6)
  --every  every K-th snapshot (default 1: all)
  --tool   the thin_ice program, whose `probe bond-offset` is used (default: the catkin build's,
           else the plain CMake build's, under .ws)
Prints a Markdown table, one row per snapshot.
"""
import functools
import argparse
import json
import math
import os
import subprocess

import numpy as np

from . import ROOT, run_record
from .run_summary import default_tool, scenario_of_run, sheet_size
from .refusal import refuse

PROG = "scripts/study sheet_bending"
SUMMARY = "the intact sheet in front of the structure: its depth, slope and curvature against what breaks it"


fail = functools.partial(refuse, PROG)  # bad input: one line, exit status 2


def fit(xs, zs, degree):
    """Least-squares polynomial coefficients (highest first, numpy's order) of degree 1 or 2, and the
    standard error of the highest one; None where the points cannot fix it."""
    x, z = np.asarray(xs, float), np.asarray(zs, float)
    if len(x) <= degree + 1:
        return None
    design = np.vander(x - x.mean(), degree + 1)
    coefficients, _, rank, _ = np.linalg.lstsq(design, z, rcond=None)
    if rank < degree + 1:
        return None
    residual = z - design @ coefficients
    variance = float(residual @ residual) / (len(x) - degree - 1)
    return coefficients, math.sqrt(max(variance * np.linalg.inv(design.T @ design)[0, 0], 0.0))


def bond_law(tool, summary, slopes):
    """The answer (JSON) of `thin_ice probe bond-offset` (tool: the thin_ice program) for the run's
    scenario file and overrides, with sigma_v / sigma_f at each of `slopes`; run from the
    repository root, where the runs' relative scenario paths start."""
    command = [os.path.abspath(tool), "probe", "bond-offset", "--scenario", summary[run_record.SCENARIO]["file"]]
    for override in summary[run_record.SCENARIO].get("overrides", []):
        command += ["--set", override]
    for slope in slopes:
        command += ["--slope", repr(float(slope))]
    try:
        done = subprocess.run(command, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                              timeout=600)
    except OSError as e:
        fail(f"cannot start {tool}: {e.strerror}")
    except subprocess.TimeoutExpired:
        fail(f"{tool} gave no answer within 600 s")
    if done.returncode != 0:
        fail(done.stderr.strip() or f"{tool}: exit status {done.returncode}")
    try:
        return json.loads(done.stdout)
    except ValueError as e:
        fail(f"{tool} probe bond-offset did not answer in JSON ({e}): is {tool} the thin_ice program?")


def strip_means(points, width):
    """(x, mean z) of the sheet in strips `width` long across the sheet; a strip holding fewer than
    half the cells of the usual (median) strip is left out (the sheet's ragged front at the face)."""
    strips = {}
    for x, z in points:
        strips.setdefault(math.floor(x / width), []).append(z)
    counts = sorted(len(v) for v in strips.values())
    usual = counts[len(counts) // 2]
    return [((k + 0.5) * width, sum(v) / len(v)) for k, v in sorted(strips.items()) if 2 * len(v) >= usual]


def profile_row(cells_csv, toe_x, reach, window, strip):
    """(lowest z [m], slope [-], (curvature [1/m], its standard error)) of the sheet in one snapshot,
    from its mean height in strips `strip` long."""
    cells = run_record.read_cells_file(cells_csv)
    size = sheet_size(cells)
    if size is None:
        return None
    points = [(float(c[run_record.X]) - toe_x, float(c[run_record.Z]))
              for c in cells if int(c[run_record.PIECE_CELLS]) == size]
    profile = strip_means([(x, z) for x, z in points if -reach <= x <= 0.0], strip)
    if len(profile) < 4:
        return None
    lowest = min(z for _, z in profile)
    steepest = curviest = None
    for first in range(len(profile)):
        for length, degree in ((window, 1), (2 * window, 2)):
            inside = [(x, z) for x, z in profile[first:] if x <= profile[first][0] + length + 1e-9]
            if len(inside) < degree + 3 or inside[-1][0] - inside[0][0] < length - strip - 1e-9:
                continue
            result = fit([x for x, _ in inside], [z for _, z in inside], degree)
            if result is None:
                continue
            coefficients, error = result
            leading = abs(float(coefficients[0]))
            if degree == 1 and (steepest is None or leading > steepest):
                steepest = leading
            if degree == 2 and (curviest is None or 2 * leading > curviest[0]):
                curviest = (2 * leading, 2 * error)
    return lowest, steepest, curviest


def main(argv):
    p = argparse.ArgumentParser(prog=PROG, description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("run", metavar="RUN_DIR")
    p.add_argument("--window", type=float, default=1.0)
    p.add_argument("--reach", type=float, default=6.0)
    p.add_argument("--every", type=int, default=1)
    p.add_argument("--tool", help="path of the thin_ice program")
    a = p.parse_args(argv)
    if not a.window > 0:
        fail(f"--window {a.window:g}; allowed: a length > 0 m")
    if not a.reach > 2 * a.window:
        fail(f"--reach {a.reach:g}; allowed: a length > twice --window ({2 * a.window:g} m)")
    if a.every < 1:
        fail(f"--every {a.every}; allowed: a whole number >= 1")
    tool = a.tool or default_tool(PROG)
    try:
        summary = run_record.read_summary(a.run)
        index = run_record.read_snapshot_index(a.run)
    except (OSError, ValueError) as e:
        fail(f"RUN_DIR {a.run} is not a run with snapshots ({e})")
    if summary is None:
        fail(f"RUN_DIR {a.run} is not a run with snapshots (no {run_record.SUMMARY_FILE})")
    try:
        d = float(scenario_of_run(summary)["sheet"]["cell_size"])
        toe_x = float(summary[run_record.STRUCTURE]["toe_x_m"])
    except (OSError, KeyError, TypeError, ValueError) as e:
        fail(f"cannot read the sheet and structure of {a.run} from its scenario and summary ({e})")
    rows = []
    for e in index[::a.every]:
        rows.append((float(e[run_record.PUSHED_LENGTH]),
                     profile_row(run_record.snapshot_path(a.run, e[run_record.FILE]), toe_x, a.reach, a.window, d)))
    slopes = [row[1] for _, row in rows if row is not None and row[1] is not None]
    law = bond_law(tool, summary, slopes)  # one call: the sheet is generated once
    h, z_rest = law["thickness_m"], law["floating_centroid_z_m"]
    ratios = dict(zip(slopes, (s["stress_ratio"] for s in law["slopes"])))
    curvature_break = law["plate_breaking_curvature_per_m"]
    bond_length = law["bond"]["distance_m"]
    name = os.path.basename(os.path.normpath(a.run))
    if law["breaking_slope"] is None:
        reach = (f"no slope alone brings it to sigma_f (at most {law['largest_stress_ratio']:.2f} sigma_f, at a "
                 f"slope of {law['largest_at_slope']:.3f}, dz = {law['largest_at_slope'] * bond_length / h:.3f} h); "
                 "only compression (k sigma_c) or tension can break it")
    else:
        slope = law["breaking_slope"]
        reach = f"it reaches sigma_f at a slope of {slope:.3f} (dz = {slope * bond_length / h:.3f} h)"
    print(f"{name}: the sheet within {a.reach:g} m of the toe; the model's bond law (a bond "
          f"{bond_length:.3f} m long across the slope): {reach}; an elastic plate "
          f"breaks at a curvature of {curvature_break:.4f} 1/m (2 (1 - nu^2) sigma_f / (E h))")
    print("")
    print("| L [m] | deepest below rest [m] | steepest slope | sigma_v / sigma_f of a bond across it | greatest "
          "curvature [1/m] (+- standard error) | / curvature at which a plate breaks |")
    print("|---:|---:|---:|---:|---:|---:|")
    for length, row in rows:
        if row is None:
            print(f"| {length:.3f} | - | - | - | - | - |")
            continue
        lowest, slope, curvature = row
        depth = z_rest - lowest
        slope_text = f"{slope:.4f} | {ratios[slope]:.2f}" if slope is not None else "- | -"
        curvature_text = (f"{curvature[0]:.4f} (+- {curvature[1]:.4f}) | {curvature[0] / curvature_break:.1f}"
                          if curvature is not None else "- | -")
        print(f"| {length:.3f} | {depth:.3f} | {slope_text} | {curvature_text} |")
