"""A run's load record per metre of structure width, for the strip tools (scripts/study strip_table,
scripts/study strip_vs_full): one reader and one set of window means."""
import math

from . import run_record


def read_run(path):
    """(summary or None, lengths [m], raw horizontal loads [N], last row). A run killed before it
    wrote its summary still has its rows in loads.csv.partial (written row by row): those are read,
    and the summary is None. Where loads.csv is absent or holds only the last segments (a clone
    keeps only the kept record), the bins of load_bins.csv stand for the rows: their end lengths,
    their mean loads, and the last bin's bond counts."""
    summary = run_record.read_summary(path)
    if summary is not None and (summary.get("loads_csv_from_s") or run_record.loads_path(path) is None):
        bins = run_record.read_load_bins(path)
        alpha = summary["calibration_factor"]
        raw = [f / alpha for f in bins["horizontal_calibrated_mean_N"]]
        last = {"broken_bonds": bins["broken_bonds"][-1], "intact_bonds": bins["intact_bonds"][-1]} if raw else None
        return summary, bins["pushed_length_m"], raw, last
    rows = run_record.read_load_rows(path)
    lengths = [float(row["pushed_length_m"]) for row in rows]
    raw = [float(row["horizontal_raw_N"]) for row in rows]
    return summary, lengths, raw, rows[-1] if rows else None


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
