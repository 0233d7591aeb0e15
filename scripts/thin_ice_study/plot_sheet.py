"""Draws an ice sheet's cells (cells.txt written by `thin_ice sheet`) as a PNG picture.

usage: scripts/study plot_sheet CELLS_TXT OUT_PNG
"""
import functools
import random

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

from .png_output import check_png_path, save_png  # noqa: E402
from .refusal import refuse

PROG = "scripts/study plot_sheet"
SUMMARY = "draws an ice sheet's cells (cells.txt of `thin_ice sheet`) as a PNG picture"


fail = functools.partial(refuse, PROG)  # bad input: one line, exit status 2


def read_cells(path):
    """Polygons of cells.txt: per line 'index n x1 y1 ... xn yn' (the format of `thin_ice sheet`)."""
    polygons = []
    try:
        with open(path) as f:
            for number, line in enumerate(f, 1):
                if line.startswith("#") or not line.strip():
                    continue
                fields = line.split()
                try:
                    n = int(fields[1])
                    xy = [float(v) for v in fields[2:2 + 2 * n]]
                except (IndexError, ValueError):
                    xy, n = [], 0
                if n < 3 or len(xy) != 2 * n:
                    fail(f"{path}, line {number}: '{line.strip()[:60]}' is not a cell; allowed: "
                         "'index n x1 y1 ... xn yn' with n >= 3 (the cells.txt of `thin_ice sheet`)")
                polygons.append(list(zip(xy[0::2], xy[1::2])))
    except OSError as e:
        fail(f"CELLS_TXT {path}: {e.strerror}")
    if not polygons:
        fail(f"CELLS_TXT {path} holds no cell")
    return polygons


def main(argv):
    if argv in (["-h"], ["--help"]):
        print(__doc__.strip())
        return 0
    if len(argv) != 2:
        fail(f"{len(argv)} arguments; allowed: CELLS_TXT OUT_PNG (see --help)")
    check_png_path(PROG, "OUT_PNG", argv[1])
    polygons = read_cells(argv[0])
    xs = [x for p in polygons for x, _ in p]
    ys = [y for p in polygons for _, y in p]
    width = max(xs) - min(xs)
    height = max(ys) - min(ys)
    fig, ax = plt.subplots(figsize=(12, max(2.5, 12 * height / width + 1)))
    shades = ["#e8f1f8", "#d6e6f2", "#c4dbec", "#f2f7fb"]
    pick = random.Random(0)  # shades at random, so neighbours rarely match (index order is a grid)
    ax.add_collection(PolyCollection(polygons, facecolors=[pick.choice(shades) for _ in polygons],
                                     edgecolors="#2c5577", linewidths=0.5))
    ax.set_xlim(min(xs), max(xs))
    ax.set_ylim(min(ys), max(ys))
    ax.set_aspect("equal")
    ax.set_facecolor("#0b3d5c")
    ax.set_xlabel("x [m] (towards the structure)")
    ax.set_ylabel("y [m]")
    ax.set_title(f"Voronoi ice sheet: {len(polygons)} cells")
    fig.tight_layout()
    save_png(fig, argv[1], dpi=110)
    print(f"wrote {argv[1]}")
