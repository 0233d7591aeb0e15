"""Counts, in every snapshot of a run, the ice that has left the sheet's level, and tells the
pushed sheet apart from the broken ice: is the broken ice going under the sheet or on top of it,
and is the sheet pressed down? A cell counts as below (above) when its centroid is more than h/2
below (above) the level at which a cell floats at rest, z_rest = h/2 - (rho_i / rho_w) h
(Archimedes; the model's cells do not tilt). The sheet is the largest piece held together by
intact bonds (snapshot column piece_cells; older snapshots lack it); every other cell is broken
ice. The side view (scripts/study plot_side_view) shows one snapshot; this gives the history as numbers.

usage: scripts/study ice_layers RUN_DIR... [--earlier CSV] [--csv OUT] [--plot OUT_PNG] [--slice-width W]
  RUN_DIR  an output folder of `thin_ice run` with summary.json and snapshots/ (--snapshots N); h, rho_i
           and rho_w come from its scenario file (path in summary.json, relative to the repository
           root) with the run's --set overrides applied
  --earlier  an earlier --csv of the same runs (matched by folder name): its rows at shorter pushed
           length than a run's first snapshot come first, so that a run resumed in a fresh folder
           (its earlier legs' snapshots no longer kept) is counted and drawn over its whole length
  --csv    also write the tables as CSV to OUT (one row per run and snapshot)
  --plot   also draw, for every run, the mean horizontal load F_cal per 0.1 m of pushed length
           (from its loads.csv) above the counts of broken ice below and above the sheet's level
           and of sheet cells pressed down
  --slice-width  also count, in every snapshot, the broken ice below and above the level in
           slices W [m] wide across the structure's width (from y = -width/2; the last slice may
           be narrower): where across the width the ice goes, say beside the walls or away from
           them, on the slices a strip of width W would cut from the full width

Columns: pushed length L [m]; cells below the level, and how many of them are the sheet's; the same
above; free blocks (cells with no bond left); cells in the sheet; the farthest a broken cell below
the level lies in front of the structure's toe [m]; how far the sheet's cell nearest the toe lies in
front of it [m] (small: the sheet has pushed under the rubble up to the structure rather than
failing in front of the pile). Snapshots without piece_cells give "-" where the sheet must be
known, and the farthest of all cells below.
"""
import functools
import argparse
import csv
import math
import os

from . import run_record
from .png_output import check_png_path, save_png
from .run_summary import floating_level, sheet_size
from .refusal import refuse

PROG = "scripts/study ice_layers"
SUMMARY = "per snapshot, the broken ice under and over the sheet's level and the sheet pressed down"

COLUMNS = ["run", "pushed_length_m", "cells_below", "sheet_cells_below", "cells_above", "sheet_cells_above",
           "free_blocks", "sheet_cells", "farthest_broken_below_from_toe_m", "sheet_nearest_to_toe_m"]
# The table's first version, without the last column: still read by --earlier (it is left empty).
EARLIER_COLUMNS = COLUMNS[:-1]


fail = functools.partial(refuse, PROG)  # bad input: one line, exit status 2


def layers(cells_csv, h, z_rest, toe_x, slices=None):
    """{column: value} of one snapshot; the sheet's columns are None when it has no piece_cells.
    With `slices` (y_min [m], slice width [m], count), also "slices": per slice, [broken cells below,
    broken cells above] (every cell off the level where the sheet is not known)."""
    cells = run_record.read_cells_file(cells_csv)
    size = sheet_size(cells)
    known = size is not None
    counts = {"cells_below": 0, "sheet_cells_below": 0, "cells_above": 0, "sheet_cells_above": 0,
              "free_blocks": 0, "sheet_cells": 0, "farthest_broken_below_from_toe_m": 0.0,
              "sheet_nearest_to_toe_m": None}
    if slices:
        counts["slices"] = [[0, 0] for _ in range(slices[2])]
    for c in cells:
        z = float(c[run_record.Z])
        in_sheet = known and int(c[run_record.PIECE_CELLS]) == size
        if slices and not in_sheet and abs(z - z_rest) > 0.5 * h:
            y = float(c[run_record.Y])
            k = min(int((y - slices[0]) // slices[1]), slices[2] - 1)  # a cell at y = +width/2: the last slice
            if slices[0] <= y <= -slices[0]:
                counts["slices"][k][z > z_rest] += 1
        counts["sheet_cells"] += in_sheet
        if in_sheet:
            gap = toe_x - float(c[run_record.X])
            nearest = counts["sheet_nearest_to_toe_m"]
            counts["sheet_nearest_to_toe_m"] = gap if nearest is None else min(nearest, gap)
        counts["free_blocks"] += c[run_record.IN_INTACT_SHEET] != "1"
        if z < z_rest - 0.5 * h:
            counts["cells_below"] += 1
            counts["sheet_cells_below"] += in_sheet
            if not in_sheet:
                counts["farthest_broken_below_from_toe_m"] = max(counts["farthest_broken_below_from_toe_m"],
                                                                 toe_x - float(c[run_record.X]))
        elif z > z_rest + 0.5 * h:
            counts["cells_above"] += 1
            counts["sheet_cells_above"] += in_sheet
    if not known:
        for key in ("sheet_cells_below", "sheet_cells_above", "sheet_cells"):
            counts[key] = None
    return counts


def slice_bounds(summary, slice_width):
    """(y_min [m], slice width [m], count) of slices `slice_width` wide across the structure."""
    width = summary[run_record.STRUCTURE]["width_m"]
    return -0.5 * width, slice_width, max(1, math.ceil(width / slice_width - 1e-9))


def run_table(run, slice_width=None):
    """(summary, rows) of one run: per snapshot, {column: value} with its pushed length (and, with
    `slice_width`, the broken ice below and above the level per slice across the width)."""
    try:
        summary = run_record.read_summary(run)
        index = run_record.read_snapshot_index(run)
    except (OSError, ValueError) as e:
        fail(f"{run} is not a finished run with snapshots ({e})")
    if summary is None:
        fail(f"{run} is not a finished run with snapshots (no {run_record.SUMMARY_FILE})")
    if run_record.STRUCTURE not in summary:
        fail(f"{run}/summary.json has no structure geometry (older `thin_ice run` records lack it)")
    try:
        h, z_rest = floating_level(summary)
    except ValueError as e:
        fail(str(e))
    toe_x = summary[run_record.STRUCTURE]["toe_x_m"]
    slices = slice_bounds(summary, slice_width) if slice_width else None
    rows = []
    for e in index:
        row = layers(run_record.snapshot_path(run, e[run_record.FILE]), h, z_rest, toe_x, slices)
        row["pushed_length_m"] = float(e[run_record.PUSHED_LENGTH])
        rows.append(row)
    show = lambda v: "-" if v is None else str(v)  # noqa: E731
    metres = lambda v: "-" if v is None else f"{v:.2f}"  # noqa: E731
    print(f"ice_layers: {run}: h = {h:g} m, cells at rest float with their centroid at z = {z_rest:.4f} m; "
          f"below / above: centroid more than h/2 under / over that")
    print("| L [m] | below | of which the sheet | above | of which the sheet | free blocks | sheet cells "
          "| farthest broken ice below, in front of the toe [m] | the sheet's nearest cell, in front of the toe [m] |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        print(f"| {r['pushed_length_m']:.3f} | {r['cells_below']} | {show(r['sheet_cells_below'])} | {r['cells_above']} "
              f"| {show(r['sheet_cells_above'])} | {r['free_blocks']} | {show(r['sheet_cells'])} "
              f"| {r['farthest_broken_below_from_toe_m']:.2f} | {metres(r['sheet_nearest_to_toe_m'])} |")
    if slices:
        y_min, step, count = slices
        edges = [(y_min + k * step, min(y_min + (k + 1) * step, -y_min)) for k in range(count)]
        print(f"ice_layers: {run}: broken ice below / above the level, in slices {step:g} m wide across the width "
              f"(every cell off the level where the sheet is not known)")
        print("| L [m] | " + " | ".join(f"y {a:+.2f} to {b:+.2f} m" for a, b in edges) + " |")
        print("|---:|" + "---:|" * count)
        for r in rows:
            print(f"| {r['pushed_length_m']:.3f} | " + " | ".join(f"{below} / {above}" for below, above in r["slices"])
                  + " |")
    return summary, rows


def load_windows(run, width=0.1):
    """(window centres [m], mean F_cal [N]) of the run's kept record (load_bins.csv) over windows
    `width` long: the bins whose end length falls in each, weighted by the time they cover."""
    bins = run_record.read_load_bins(run)
    sums = {}
    for length, mean, duration in zip(bins[run_record.PUSHED_LENGTH], bins[run_record.CALIBRATED_MEAN],
                                      bins[run_record.DURATION]):
        k = int(length / width)
        weighted, covered = sums.get(k, (0.0, 0.0))
        sums[k] = (weighted + mean * duration, covered + duration)
    # A window covering less than half the time of a full one (the record's last, cut short) is
    # left out: its mean is of a few bins, not of the window.
    full = max((covered for _, covered in sums.values()), default=0.0)
    keys = sorted(k for k in sums if 2 * sums[k][1] >= full)
    return [(k + 0.5) * width for k in keys], [sums[k][0] / sums[k][1] for k in keys]


def read_earlier(path):
    """{run name: rows} of an earlier --csv; empty fields (sheet unknown) become None."""
    def value(column, text):
        if text == "":
            return None
        return float(text) if column.endswith("_m") else int(text)
    earlier = {}
    try:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            if reader.fieldnames not in (COLUMNS, EARLIER_COLUMNS):
                fail(f"--earlier {path}: columns {reader.fieldnames}; allowed: {COLUMNS} (or without the last)")
            for row in reader:
                earlier.setdefault(row["run"], []).append({c: value(c, row.get(c, "")) for c in COLUMNS if c != "run"})
    except (OSError, ValueError) as e:
        fail(f"--earlier {path}: {e}")
    return earlier


def with_earlier(rows, earlier_rows):
    """The earlier rows before the first snapshot of `rows`, then `rows`."""
    first = min((r["pushed_length_m"] for r in rows), default=float("inf"))
    return sorted((r for r in earlier_rows if r["pushed_length_m"] < first - 1e-9),
                  key=lambda r: r["pushed_length_m"]) + rows


def broken_at_gaps(lengths, values):
    """(lengths, values) with a gap (NaN) wherever two snapshots lie more than twice the usual
    (median) spacing apart, so that a stretch without snapshots is not drawn as a straight line."""
    steps = sorted(b - a for a, b in zip(lengths, lengths[1:]))
    if not steps:
        return lengths, values
    usual = steps[len(steps) // 2]
    xs, ys = [lengths[0]], [values[0]]
    for a, b, v in zip(lengths, lengths[1:], values[1:]):
        if b - a > 2.0 * usual:
            xs.append(0.5 * (a + b))
            ys.append(float("nan"))
        xs.append(b)
        ys.append(v)
    return xs, ys


def plot(tables, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (load, count) = plt.subplots(2, 1, figsize=(10, 7.5), sharex=True)
    for k, (run, summary, rows) in enumerate(tables):
        colour = f"C{k}"
        overrides = summary[run_record.SCENARIO].get("overrides", [])
        name = os.path.basename(os.path.normpath(run))
        label = f"{name} ({summary[run_record.SCENARIO]['name']}"
        label += (", " + ", ".join(overrides) + ")") if overrides else ")"
        x, f = load_windows(run)
        load.plot(x, f, "-", color=colour, label=label)
        lengths = [r["pushed_length_m"] for r in rows]
        known = all(r["sheet_cells"] is not None for r in rows)
        broken = lambda r, key: r[key] - (r["sheet_" + key] if known else 0)  # noqa: E731
        what = "broken ice" if known else "all cells"
        count.plot(*broken_at_gaps(lengths, [broken(r, "cells_below") for r in rows]), "o-", ms=3, color=colour,
                   label=f"{name}: {what} below")
        count.plot(*broken_at_gaps(lengths, [broken(r, "cells_above") for r in rows]), "s--", ms=3, color=colour,
                   label=f"{name}: {what} above")
        if known:
            count.plot(*broken_at_gaps(lengths, [r["sheet_cells_below"] for r in rows]), "^:", ms=3, color=colour,
                       label=f"{name}: sheet pressed down")
    load.set_ylabel("mean F_cal per 0.1 m of L [N]")
    load.legend(fontsize=8)
    load.grid(alpha=0.3)
    count.set_ylabel("cells more than h/2 from the sheet's level")
    count.set_xlabel("pushed length L [m]")
    count.legend(fontsize=7, ncol=len(tables), loc="upper left")
    count.grid(alpha=0.3)
    load.set_title("Load, and where the ice that left the sheet's level went (under or over it)", fontsize=10)
    fig.tight_layout()
    save_png(fig, out, dpi=90)
    print(f"ice_layers: wrote {out}")


def main(argv):
    p = argparse.ArgumentParser(prog=PROG, description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("runs", nargs="+", metavar="RUN_DIR")
    p.add_argument("--earlier")
    p.add_argument("--csv")
    p.add_argument("--plot")
    p.add_argument("--slice-width", type=float)
    a = p.parse_args(argv)
    if a.slice_width is not None and not (math.isfinite(a.slice_width) and a.slice_width > 0):
        fail(f"--slice-width {a.slice_width:g}; allowed: a width > 0 [m]")
    if a.plot:
        check_png_path(PROG, "--plot", a.plot)
    earlier = read_earlier(a.earlier) if a.earlier else {}
    tables = []
    for run in a.runs:
        summary, rows = run_table(run, a.slice_width)
        tables.append((run, summary, with_earlier(rows, earlier.get(os.path.basename(os.path.normpath(run)), []))))
    if a.csv:
        with open(a.csv + ".new", "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(COLUMNS)
            for run, _, rows in tables:
                for r in rows:
                    values = dict(r, run=os.path.basename(os.path.normpath(run)))
                    values["pushed_length_m"] = f"{r['pushed_length_m']:.4f}"
                    values["farthest_broken_below_from_toe_m"] = f"{r['farthest_broken_below_from_toe_m']:.3f}"
                    if r["sheet_nearest_to_toe_m"] is not None:
                        values["sheet_nearest_to_toe_m"] = f"{r['sheet_nearest_to_toe_m']:.3f}"
                    w.writerow(["" if values[c] is None else values[c] for c in COLUMNS])
        os.replace(a.csv + ".new", a.csv)
    if a.plot:
        plot(tables, a.plot)
