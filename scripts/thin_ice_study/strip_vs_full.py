"""Does a strip stand for the full width? (issue #31, step 1): the load per metre of width of strip
runs (several seeds) against full-width runs of the same series, over the same span of pushed length.

usage: scripts/study strip_vs_full --span L --full RUN_DIR... --strips RUN_DIR... [--alpha A] [--window W]
                                   [--sections]

Prints one Markdown table: for each run, alpha F per metre of structure width [N/m] averaged over
0-L and per window; then the strips' mean and seed range (max - min), and whether the full-width
run's mean lies within the strips' range widened by the full-width seeds' own range where there
are several. A run shorter than the span is refused by name (a shorter record is not the same span).

--sections also cuts each full-width run into sections as wide as the strips' structure (adjacent
panels, one panel apart: panels 1-2, 2-3, ... of 1 m panels against 2 m strips) and prints each
section's alpha F per metre over 0-L: what a strip-sized slice of the full width carried, edges
included. It needs the run's rows (loads.csv with its panel columns, the whole run); a run that
has only its kept record (load_bins.csv holds no panel loads) is refused by name.
"""
import argparse
import os
import sys

from . import run_record
from .experiments import ALPHA
from .strip_loads import read_run, window_means, within_seed_spread

PROG = "scripts/study strip_vs_full"
SUMMARY = "does a strip stand for the full width: strip runs against full-width runs over the same span"


def per_metre(run, alpha, span):
    """(lengths, alpha F per metre of structure width) of one run directory over 0-span."""
    record = read_run(run)
    summary, lengths, raw = record.summary, record.lengths, record.raw
    if summary is None:
        raise ValueError("%s has no summary.json (a run still going, or killed)" % run)
    width = summary[run_record.STRUCTURE_WIDTH]
    kept = [k for k, length in enumerate(lengths) if length <= span + 1e-6]
    lengths, loads = [lengths[k] for k in kept], [run_record.calibrated(raw[k], alpha) / width for k in kept]
    # A record of bins reaches the span where its last whole bin before it ends.
    if not lengths or lengths[-1] < span - 1e-3 - record.resolution:
        raise ValueError("%s reaches L = %.3f m, short of the span %.3f m" % (run, lengths[-1] if lengths else 0.0, span))
    return lengths, loads


def section_means(run, alpha, span, section_width):
    """[(first panel, last panel, alpha F per metre [N/m])] over 0-span of every run of adjacent
    panels of the full-width `run` that together are `section_width` [m] wide: the rows' mean of
    the panels' summed raw loads [N] times alpha over the section's width, as per_metre averages
    the whole structure's."""
    summary = run_record.require_summary(run)
    if not run_record.rows_are_whole_run(run, summary):
        raise ValueError("%s has only part of its rows in loads.csv (or none): the kept record, load_bins.csv, "
                         "holds no panel loads, so --sections cannot cut it" % run)
    panels = summary[run_record.STRUCTURE]["panels"]
    panel_width = summary[run_record.STRUCTURE_WIDTH] / panels
    count = section_width / panel_width
    if abs(count - round(count)) > 1e-6 or not 1 <= round(count) <= panels:
        raise ValueError("%s: a section %.6g m wide is not a whole number of its %d panels of %.6g m"
                         % (run, section_width, panels, panel_width))
    count = int(round(count))
    sums, rows = [0.0] * (panels - count + 1), 0
    for row in run_record.read_load_rows(run):
        if float(row[run_record.PUSHED_LENGTH]) > span + 1e-6:
            break
        loads = [float(row[run_record.panel_column(k)]) for k in range(1, panels + 1)]
        for first in range(panels - count + 1):
            sums[first] += sum(loads[first:first + count])
        rows += 1
    if rows == 0:
        raise ValueError("%s has no row within 0-%.3f m" % (run, span))
    return [(first + 1, first + count, run_record.calibrated(total / rows, alpha) / section_width)
            for first, total in enumerate(sums)]


def main(argv):
    p = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n")[0])
    p.add_argument("--span", type=float, required=True)
    p.add_argument("--full", nargs="+", required=True)
    p.add_argument("--strips", nargs="+", required=True)
    p.add_argument("--alpha", type=float, default=ALPHA)
    p.add_argument("--window", type=float, default=0.5)
    p.add_argument("--sections", action="store_true")
    a = p.parse_args(argv)
    if not (a.span > 0 and a.window > 0 and a.alpha > 0):
        print(PROG + ": --span, --window and --alpha must be > 0", file=sys.stderr)
        return 2
    rows, sections = {}, {}
    try:
        for run in a.full + a.strips:
            lengths, loads = per_metre(run, a.alpha, a.span)
            means = [m for _, m in window_means(lengths, loads, a.window, int(round(a.span / a.window)))]
            rows[run] = (sum(loads) / len(loads), means)
        if a.sections:
            widths = {run_record.require_summary(r)[run_record.STRUCTURE_WIDTH] for r in a.strips}
            if len(widths) != 1:
                raise ValueError("--sections needs strips of one width; these are %s m wide"
                                 % ", ".join("%g" % w for w in sorted(widths)))
            section_width = widths.pop()
            for run in a.full:
                sections[run] = section_means(run, a.alpha, a.span, section_width)
    except (OSError, ValueError, KeyError) as e:
        print(PROG + ": %s" % e, file=sys.stderr)
        return 2
    windows = int(round(a.span / a.window))
    head = " | ".join("%.1f-%.1f m" % (k * a.window, (k + 1) * a.window) for k in range(windows))
    print("| run | width | mean 0-%.1f m [N/m] | %s |" % (a.span, head))
    print("|---|---|---:|%s" % ("---:|" * windows))
    for run in a.full + a.strips:
        mean, means = rows[run]
        print("| %s | %s | %.0f | %s |" % (os.path.basename(os.path.normpath(run)),
                                          "full" if run in a.full else "strip", mean,
                                          " | ".join("%.0f" % m for m in means)))
    strip_means = [rows[r][0] for r in a.strips]
    full_means = [rows[r][0] for r in a.full]
    low, high = min(strip_means), max(strip_means)
    centre, full, _, inside = within_seed_spread(strip_means, full_means)
    print()
    print("Strips: mean %.0f N/m, seed range %.0f-%.0f N/m (%.0f, %.1f %% of the mean); full width: %.0f N/m "
          "(%+.1f %% of the strips' mean): %s the seed spread."
          % (centre, low, high, high - low, 100.0 * (high - low) / centre, full, 100.0 * (full / centre - 1.0),
             "within" if inside else "outside"))
    for run, cut in sections.items():
        values = [mean for _, _, mean in cut]
        inside = sum(1 for v in values if low <= v <= high)
        print()
        print("%s in sections of %g m (panels %s): %s N/m over 0-%.1f m; %.0f-%.0f N/m, %d of %d within the "
              "strips' range." % (os.path.basename(os.path.normpath(run)), section_width,
                                  ", ".join("%d-%d" % (f, l) if f != l else "%d" % f for f, l, _ in cut),
                                  ", ".join("%.0f" % v for v in values), a.span, min(values), max(values),
                                  inside, len(values)))
    return 0
