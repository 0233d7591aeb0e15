"""A run's load record per metre of structure width, for the strip tools (scripts/study strip_table,
scripts/study strip_vs_full): one reader and one set of window means."""
import collections
import math

from . import run_record


Record = collections.namedtuple("Record", "summary lengths raw greatest last resolution")
Record.__doc__ = """A run's load record: summary (None for a first segment still being written),
lengths [m], raw horizontal loads [N] and the greatest raw load of each sample [N], the last
sample's bond counts (a dict with "broken_bonds"), and the record's resolution [m] of pushed ice
(0 for rows; a bin's width for the kept record)."""


def read_run(path):
    """The run's Record. Rows of loads.csv where it holds the whole run; a run killed before it
    wrote its summary still has its rows in loads.csv.partial (written row by row): those are read,
    and the summary is None. Where loads.csv is absent or holds only the last segments (a clone
    keeps only the kept record, a run resumed from it writes its own segment), the bins of
    load_bins.csv stand for the rows: their end lengths, mean and greatest loads, and the last
    bin's bond counts."""
    summary = run_record.read_summary(path)
    if summary is not None and not run_record.rows_are_whole_run(path, summary):
        bins = run_record.read_load_bins(path)
        run_alpha = summary[run_record.CALIBRATION_FACTOR]
        last = ({run_record.BROKEN_BONDS: bins[run_record.BROKEN_BONDS][-1],
                 run_record.INTACT_BONDS: bins[run_record.INTACT_BONDS][-1]} if bins[run_record.BIN] else None)
        return Record(summary, bins[run_record.PUSHED_LENGTH],
                      [run_record.raw_of(f, run_alpha) for f in bins[run_record.CALIBRATED_MEAN]],
                      [run_record.raw_of(f, run_alpha) for f in bins[run_record.CALIBRATED_GREATEST]], last,
                      run_record.LOAD_BIN_LENGTH)
    rows = run_record.read_load_rows(path)
    lengths = [float(row[run_record.PUSHED_LENGTH]) for row in rows]
    raw = [float(row[run_record.HORIZONTAL_RAW]) for row in rows]
    return Record(summary, lengths, raw, raw, rows[-1] if rows else None, 0.0)


def window_means(lengths, values, window, windows=None):
    """[(begin, mean)] of `values` over [k window, (k + 1) window) of pushed length: the whole
    windows the record covers, or the first `windows` of them (the last one taking a final row at
    its end)."""
    count = windows if windows is not None else (int(math.floor(lengths[-1] / window)) if lengths else 0)
    sums, counts = [0.0] * count, [0] * count
    for length, value in zip(lengths, values):
        k = int(math.floor(length / window))
        if windows is not None:
            k = min(k, count - 1)
        if 0 <= k < count:
            sums[k] += value
            counts[k] += 1
    return [(k * window, sums[k] / counts[k] if counts[k] else float("nan")) for k in range(count)]


def within_seed_spread(strip_means, full_means):
    """Issue #31's check of a strip against the full width: the full-width mean lies within the seed
    spread of the strips' mean, the spread being the larger of the strips' range and the full-width
    seeds' own range. Returns (strips' mean, full-width mean, spread, verdict)."""
    centre = sum(strip_means) / len(strip_means)
    full = sum(full_means) / len(full_means)
    spread = max(max(strip_means) - min(strip_means), max(full_means) - min(full_means))
    return centre, full, spread, abs(full - centre) <= spread
