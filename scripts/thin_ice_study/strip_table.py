"""Tabulates strip runs (scripts/study strip, scripts/strip_matrix) per metre of width, for comparing
readings of the paper (issue #31).

usage: scripts/study strip_table RUN_DIR... [--alpha A] [--window W] [--markdown]
  RUN_DIR     output folders of `thin_ice run` (loads.csv, summary.json, snapshots/)
  --alpha     the structure's calibration factor of Eq. (18) applied to the raw load (default the
              paper's, as the scenarios' base file gives it); the raw load is always shown beside it
  --window    the length of the windows of the means [m] (default 0.5)
  --upto      read each record only to this pushed length [m] (to compare runs over the same span,
              e.g. a strip against a full-width run over the first 2 m); also prints the mean over it

Per run: the length reached, the mean of alpha F per window in N per metre of structure width, the
peak, the project's steady-state verdict (summary.json, the rule in the code), and where the
intact sheet's front stands: the distance from the toe to the centroid of the sheet's cell
nearest to it, in each snapshot (negative: under or past the toe).
"""
import argparse
import math
import os
import sys

from . import run_record
from .experiments import ALPHA, PEAK, STEADY_MEAN, per_metre
from .strip_loads import read_run, window_means

PROG = "scripts/study strip_table"
SUMMARY = "tabulates strip runs per metre of width: window means, peak, steady verdict, the sheet's front"

# Table 6 (the paper's alpha applied) per metre of the experiments' structure [N/m]: steady mean, peak.
EXPERIMENT_PER_METRE = {k: (per_metre(STEADY_MEAN[k]), per_metre(PEAK[k])) for k in STEADY_MEAN}


def front_distances(path, toe_x):
    """(pushed length, toe - x of the intact sheet's cell nearest the toe) per snapshot."""
    if not os.path.exists(run_record.snapshot_index_path(path)):
        return []
    out = []
    for entry in run_record.read_snapshot_index(path):
        front = -math.inf
        for cell in run_record.read_snapshot_cells(path, entry[run_record.FILE]):
            if cell[run_record.IN_INTACT_SHEET] == "1":
                front = max(front, float(cell[run_record.X]))
        out.append((float(entry[run_record.PUSHED_LENGTH]), toe_x - front))
    return out


def main(argv):
    parser = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n")[0])
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--alpha", type=float, default=ALPHA)
    parser.add_argument("--window", type=float, default=0.5)
    parser.add_argument("--upto", type=float, default=None)
    parser.add_argument("--width", type=float, default=2.0,
                        help="the structure's width [m] of a run without summary.json (default 2, a strip)")
    parser.add_argument("--markdown", action="store_true",
                        help="one table row per run instead of the blocks")
    args = parser.parse_args(argv)
    if not (args.alpha > 0 and args.window > 0):
        print(PROG + ": --alpha and --window must be > 0", file=sys.stderr)
        return 2
    if args.markdown:
        print("| run | L reached [m] | broken bonds | peak alpha F [N/m] | alpha F per %g m [N/m] |" % args.window)
        print("|---|---:|---:|---:|---|")
    for path in args.runs:
        try:
            record = read_run(path)
        except (OSError, KeyError, ValueError) as e:
            print("%s: cannot read: %s" % (path, e))
            continue
        summary, lengths, raw, greatest, last = record.summary, record.lengths, record.raw, record.greatest, record.last
        if args.upto is not None:
            kept = [k for k, l in enumerate(lengths) if l <= args.upto]
            lengths, raw, greatest = [lengths[k] for k in kept], [raw[k] for k in kept], [greatest[k] for k in kept]
        name = os.path.basename(os.path.normpath(path))
        width = summary[run_record.STRUCTURE_WIDTH] if summary else args.width
        per_metre = [run_record.calibrated(f, args.alpha) / width for f in raw]
        peak = run_record.calibrated(max(greatest), args.alpha) / width if greatest else float("nan")
        means = window_means(lengths, per_metre, args.window)
        if args.markdown:
            print("| %s | %.2f | %s | %.0f | %s |" % (name, lengths[-1] if lengths else 0.0,
                                                    last[run_record.BROKEN_BONDS], peak,
                                                    " ".join("%.0f" % m for _, m in means)))
            continue
        if summary is None:
            print("## %s (no summary.json: the rows of loads.csv.partial)" % name)
            print("means per %.2f m [N/m]: %s" % (args.window, " ".join("%.0f" % m for _, m in means)))
            print()
            continue
        series = (summary.get(run_record.EXPERIMENT) or {}).get("series", "?")  # null for a scenario of no series
        load = summary[run_record.LOAD]
        overrides = [o for o in summary[run_record.SCENARIO]["overrides"]
                     if not o.split("=")[0] in ("sheet.width", "structure.width", "channel.width",
                                                "structure.panels", "sheet.length", "structure.toe_x",
                                                "numerics.threads")]
        print("## %s (%s%s)" % (name, summary[run_record.SCENARIO]["name"],
                                (", " + ", ".join(overrides)) if overrides else ""))
        print("L %.2f m, %s; broken bonds %d of %d; peak alpha F %.0f N/m at %.2f m"
              % (lengths[-1] if lengths else 0.0, summary[run_record.STATUS], summary[run_record.BROKEN_BONDS],
                 summary[run_record.BROKEN_BONDS] + summary[run_record.INTACT_BONDS], peak,
                 lengths[per_metre.index(peak)] if per_metre else float("nan")))
        if series in EXPERIMENT_PER_METRE:
            mean_exp, peak_exp = EXPERIMENT_PER_METRE[series]
            print("experiment per metre: mean %.0f N/m, peak %.0f N/m (peak here %+.0f %%)"
                  % (mean_exp, peak_exp, 100.0 * (peak / peak_exp - 1.0)))
        if args.upto is not None and per_metre:
            print("mean alpha F over 0-%.2f m: %.0f N/m" % (lengths[-1], sum(per_metre) / len(per_metre)))
        print("means per %.1f m [N/m]: %s" % (args.window, " ".join("%.0f" % m for _, m in means)))
        print("steady: %s%s" % ("yes, " if load["steady_found"] else "no; ", load["steady_rule"]))
        if load["steady_found"]:
            w = load["steady_window_m"]
            steady_mean = run_record.at_alpha(load["steady_mean_N"], summary[run_record.CALIBRATION_FACTOR], args.alpha)
            print("steady window %.2f-%.2f m, mean alpha F %.0f N/m" % (w[0], w[1], steady_mean / width))
        fronts = front_distances(path, summary[run_record.STRUCTURE]["toe_x_m"])
        print("sheet front from the toe [m] at L: %s"
              % " ".join("%.2f@%.1f" % (d, l) for l, d in fronts))
        print()
    return 0
