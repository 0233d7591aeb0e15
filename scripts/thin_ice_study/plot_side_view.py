"""Draws a cell snapshot of a run near the structure, seen from the side (x, z) and from above
(x, y): every cell's centroid, blue in the pushed sheet (the largest piece held together by intact
bonds), green in a smaller bonded piece (a floe), red when it has no bond left (a free block).
Older snapshots have no piece sizes (no piece_cells column): there blue is any bonded cell, sheet or
floe. The side view shows what the rubble profiles (above the water only) do not: ice under the
waterline and under the incoming sheet.

usage: scripts/study plot_side_view RUN_DIR OUT_PNG [--snapshot FILE] [--reach M] [--profiles CSV]
  RUN_DIR     an output folder of `thin_ice run` with summary.json and snapshots/ (--snapshots N)
  --snapshot  a file in RUN_DIR/snapshots/ (default: the last one in snapshots/index.csv)
  --reach     how far in front of the toe to draw [m] (default 3.5)
  --profiles  the rubble pile's profiles of the same snapshot (`thin_ice probe profiles RUN_DIR
              --snapshot FILE` writes them), drawn over the cells: the side profile (the highest
              pile cell's top above the water in each 0.1 m of x) and the top profile (how far in
              front of the toe the pile reaches in each 0.1 m of y), what a camera beside and
              above the basin sees (paper Section 5.1.2, Figs. 13 and 15)
"""
import argparse
import csv
import functools
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from . import run_record  # noqa: E402
from .png_output import check_png_path, save_png  # noqa: E402
from .run_summary import sheet_size  # noqa: E402
from .refusal import refuse

PROG = "scripts/study plot_side_view"
SUMMARY = "draws a run's snapshot near the structure, from the side and from above"


fail = functools.partial(refuse, PROG)  # bad input: one line, exit status 2


def snapshot_entry(run, name=None):
    """(file, pushed length [m]) of snapshot `name` in RUN/snapshots/index.csv, or of its last one."""
    index = run_record.snapshot_index_path(run)
    if not os.path.exists(index):
        fail(f"RUN_DIR {run} has no snapshots/index.csv; allowed: the folder a `thin_ice run` with --snapshots N "
             "wrote (docs/validation/ copies keep no snapshots: give the run's own folder)")
    rows = run_record.read_snapshot_index(run)
    if name is not None:
        rows = [row for row in rows if row[run_record.FILE] == name]
        if not rows:
            sys.exit(f"{PROG}: --snapshot {name} is not listed in {run}/snapshots/index.csv")
    if not rows:
        sys.exit(f"{PROG}: {run}/snapshots/index.csv lists no snapshot")
    return rows[-1][run_record.FILE], float(rows[-1][run_record.PUSHED_LENGTH])


def read_profiles(path):
    """(side [(x, height)], top [(y, extent)]) [m] of a profiles.csv (profile,coordinate_m,value_m)."""
    side, top = [], []
    try:
        with open(path, newline="") as f:
            reader = csv.reader(f)
            if next(reader, None) != ["profile", "coordinate_m", "value_m"]:
                fail(f"--profiles {path}: its header is not profile,coordinate_m,value_m; allowed: the file "
                     "`thin_ice probe profiles` writes")
            for number, row in enumerate(reader, 2):
                try:
                    kind, coordinate, value = row[0], float(row[1]), float(row[2])
                except (IndexError, ValueError):
                    kind = None
                if kind not in ("side", "top"):
                    fail(f"--profiles {path}: line {number} '{','.join(row)}'; allowed: side|top,coordinate,value")
                (side if kind == "side" else top).append((coordinate, value))
    except OSError as e:
        fail(f"--profiles {path}: cannot read it ({e.strerror}); allowed: the file `thin_ice probe profiles` writes")
    return side, top


def main(argv):
    p = argparse.ArgumentParser(prog=PROG, description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("run")
    p.add_argument("out")
    p.add_argument("--snapshot")
    p.add_argument("--reach", type=float, default=3.5)
    p.add_argument("--profiles")
    a = p.parse_args(argv)
    if not a.reach > 0:
        fail(f"--reach {a.reach}; allowed: a length > 0 [m]")
    check_png_path(PROG, "OUT_PNG", a.out)
    profiles = read_profiles(a.profiles) if a.profiles else None
    summary_path = run_record.summary_path(a.run)
    try:
        summary = run_record.require_summary(a.run)
    except OSError as e:
        fail(f"RUN_DIR {a.run}: cannot read summary.json ({e.strerror}); allowed: a finished (or interrupted) "
             "folder of `thin_ice run`")
    except json.JSONDecodeError as e:
        fail(f"{summary_path} is not JSON ({e})")
    except ValueError as e:  # a layout this mirror does not know: the reason names the file
        fail(str(e))
    if run_record.STRUCTURE not in summary or run_record.FALSE_BOTTOM not in summary:
        sys.exit(f"{PROG}: {a.run}/summary.json has no structure or false_bottom geometry "
                 "(older `thin_ice run` records lack it); run the scenario again")
    # A run without the false bottom has "false_bottom": null: the side view then draws none.
    structure, bottom = summary[run_record.STRUCTURE], summary[run_record.FALSE_BOTTOM]
    toe, angle = structure["toe_x_m"], math.radians(structure["angle_deg"])
    name, length = snapshot_entry(a.run, a.snapshot)
    rows = run_record.read_snapshot_cells(a.run, name)
    size = sheet_size(rows)
    pieces = size is not None

    # (x, y, z, kind): kind 0 the sheet (or any bonded cell without piece sizes), 1 a floe, 2 a free block
    def kind(r):
        if r[run_record.IN_INTACT_SHEET] != "1":
            return 2
        return 1 if pieces and int(r[run_record.PIECE_CELLS]) < size else 0

    cells = [(float(r[run_record.X]), float(r[run_record.Y]), float(r[run_record.Z]), kind(r)) for r in rows]
    near = [c for c in cells if c[0] > toe - a.reach]
    fig, (side, top) = plt.subplots(2, 1, figsize=(11, 7.5), sharex=True)
    kinds = ((0, "tab:blue", "the sheet (largest bonded piece)" if pieces else "bonded to a neighbour (sheet or floe)"),
             (1, "tab:green", "floe (a smaller bonded piece)"),
             (2, "tab:red", "no bond left (free block)"))
    for kind, colour, label in kinds:
        if kind == 1 and not pieces:
            continue
        sel = [c for c in near if c[3] == kind]
        side.plot([c[0] - toe for c in sel], [c[2] for c in sel], ".", ms=3, color=colour,
                  label=f"{label} ({len(sel)})")
        top.plot([c[0] - toe for c in sel], [c[1] for c in sel], ".", ms=3, color=colour)
    # Without a false bottom the face is drawn down to the deepest cell shown (at least 0.25 m).
    depth = bottom["depth_m"] if bottom else max(0.25, -min((c[2] for c in near), default=0.0) + 0.05)
    foot = -depth / math.tan(angle)
    side.plot([foot, structure["height_m"] / math.tan(angle)], [-depth, structure["height_m"]], "k-", lw=2,
              label=f"structure face ({structure['angle_deg']:g} deg)")
    side.axhline(0.0, color="tab:cyan", lw=0.8, label="waterline")
    if profiles:
        # A bin where no pile is seen holds 0: drawn as a gap, not as a profile at the waterline.
        side_profile, top_profile = profiles
        side.step([x - toe for x, _ in side_profile], [z if z > 0 else math.nan for _, z in side_profile], "k--",
                  where="mid", lw=1, label="the pile's side profile above the water (--profiles)")
        # The top profile as an outline: each y bin's reach held over the bin's width.
        half_bin = 0.5 * (top_profile[1][0] - top_profile[0][0]) if len(top_profile) > 1 else 0.05
        outline_x = [-e if e > 0 else math.nan for _, e in top_profile for _ in (0, 1)]
        outline_y = [y + sign * half_bin for y, _ in top_profile for sign in (-1, 1)]
        top.plot(outline_x, outline_y, "k-", lw=0.8,
                 label="the pile's top profile: its reach in front of the toe (--profiles)")
        top.legend(fontsize=8, loc="upper left")
    if bottom:
        side.axhline(-depth, color="tab:brown", lw=0.8,
                     label=f"false bottom ({bottom['distance_from_structure_m']:g} m and more in front of the toe)")
    side.set_ylabel("z of the cell centroid [m]")
    side.set_ylim(-depth - 0.05, max(0.3, max((c[2] for c in near), default=0.0) + 0.1))
    side.legend(fontsize=8, loc="upper left")
    top.axvline(0.0, color="k", lw=2)
    top.set_xlabel("x - toe [m]")
    top.set_ylabel("y [m]")
    top.set_xlim(-a.reach, max(0.5, structure["height_m"] / math.tan(angle) + 0.1))
    scenario = summary[run_record.SCENARIO]["name"]
    side.set_title(f"{os.path.basename(os.path.normpath(a.run))} ({scenario}): cells at L = {length:.3f} m, "
                   f"from the side (above) and from above (below)", fontsize=10)
    fig.tight_layout()
    save_png(fig, a.out, dpi=90)
    print(f"plot_side_view: wrote {a.out} ({name}, L = {length:.3f} m, {len(near)} cells drawn)")
