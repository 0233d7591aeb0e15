"""The table of docs/validation.md on the water depth over the false bottom (not in the paper; the
scenarios' base/tank.yaml sets it): every strip run at another depth (docs/validation/strips/
ID-sK-bottomD, config/strips/bottom-depth.matrix) beside the strips of the same series at the
scenarios' depth (ID-sK), with the load per metre of structure width averaged over fixed spans of
pushed ice and the steady window the rule in the code found at the end of the run.

Loads are alpha F per metre of width at the paper's alpha (a run recorded at another alpha is
rescaled), averaged over the kept record (load_bins.csv) weighted by time. A span is shown only
where the run has pushed past its end, so that every figure of a column covers the same ice.
"""
import os
import re

from .experiments import ALPHA
from . import run_record
from .phase2_table import span_mean

SPANS = ((2.0, 5.0), (5.0, 8.0), (8.0, 10.0))  # [m] of pushed ice: from after the first failures to where the depth runs reach
DEPTH_RUN = re.compile(r"(?P<series>[WMS]-\d)-s(?P<seed>\d+)-bottom(?P<depth>\d+(?:\.\d+)?)")
SCENARIO_RUN = re.compile(r"(?P<series>[WMS]-\d)-s(?P<seed>\d+)")


def depth_runs(root):
    """[(series, seed, depth [m], path)] of the strips at another depth and, for each series among
    them, its strips at the scenarios' depth (the depth each run recorded), sorted by series,
    depth and seed."""
    base = os.path.join(root, "strips")
    if not os.path.isdir(base):
        return []
    names = sorted(os.listdir(base))
    other = [m for m in (DEPTH_RUN.fullmatch(n) for n in names) if m]
    series = {m["series"] for m in other}
    found = []
    for name in names:
        path = os.path.join(base, name)
        summary = run_record.read_summary(path)
        if summary is None:
            continue
        m = DEPTH_RUN.fullmatch(name) or SCENARIO_RUN.fullmatch(name)
        if not m or m["series"] not in series:
            continue
        bottom = summary.get(run_record.FALSE_BOTTOM) or {}
        if "depth_m" not in bottom:
            continue  # a run without the false bottom, or one recorded before its geometry was
        found.append((m["series"], int(m["seed"]), float(bottom["depth_m"]), path))
    return sorted(found, key=lambda r: (r[0], r[2], r[1]))


def span_means(path, spans=SPANS):
    """alpha F per metre of width [N/m] over each span the run pushed past (None for the others)."""
    reached = run_record.require_summary(path)[run_record.PUSHED_LENGTH]
    return [span_mean(path, end, begin) if reached >= end else None for begin, end in spans]


def window_text(summary):
    """The steady window the rule found at the run's end, with its mean per metre, or "none"."""
    load = summary.get(run_record.LOAD) or {}
    if not load.get("steady_found"):
        return "none"
    begin, end = load["steady_window_m"]
    mean = run_record.at_alpha(load["steady_mean_N"], summary[run_record.CALIBRATION_FACTOR], ALPHA)
    return f"{begin:.2f}-{end:.2f} m, {mean / summary[run_record.STRUCTURE_WIDTH]:.0f} N/m"


def depth_table(root):
    """Markdown lines: the table, or nothing where no strip ran at another depth."""
    runs = depth_runs(root)
    if not runs:
        return []
    spans = " | ".join(f"alpha F {a:g}-{b:g} m [N/m]" for a, b in SPANS)
    lines = [f"| series | seed | depth [m] | L [m] | {spans} | steady window at the end |",
             "|---|---:|---:|---:|" + "---:|" * len(SPANS) + "---|"]
    for series, seed, depth, path in runs:
        summary = run_record.require_summary(path)
        means = " | ".join("-" if m is None else f"{m:.0f}" for m in span_means(path))
        lines.append(f"| {series} | {seed} | {depth:.2f} | {summary[run_record.PUSHED_LENGTH]:.2f} | {means} | "
                     f"{window_text(summary)} |")
    return lines
