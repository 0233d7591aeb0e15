"""Writes docs/validation.md from the validation runs that scripts/study validate copied to
docs/validation/RUN/ (summary.json and load.png of each `thin_ice run`): a table in the layout of
the paper's Table 6 with this project's numbers beside the experiment's, the seed spread, the
resolution checks and the load plots. Only what the runs measured is reported; a series without
a run is listed as not run. Three hand-written files in the runs folder are taken in as they are:
misses.md (why each missed target is missed, and what was tried) under the targets' table,
phase2.md (the strip bench and the paper's readings tried against those misses) after it, and
procedure.md (the calibration procedure: where each value comes from, which series were only
predicted) after it. calibration.md, the dated notes (a journal, newest first), is linked at the
end, after the load histories, not copied in.

  scripts/study validation_report --runs docs/validation --out docs/validation.md
"""
import argparse
import csv
import glob
import json
import math
import os
import re
import sys

from .experiments import ICE_TYPE, PAPER_TIM, PHASE1_SLOPE, PUSHED_LENGTH, STEADY_MEAN
from . import run_record
from .phase2_table import phase2_table
from .png_output import save_png

PROG = "scripts/study validation_report"
SUMMARY = "writes docs/validation.md from the validation runs in docs/validation/"

SERIES = ["W-1", "W-2", "W-3", "M-1", "M-2", "S-1", "S-2"]
EXPERIMENT_LENGTH = PUSHED_LENGTH  # [m] Table 5, per series (config/experiments.yaml)
TARGETS = ("steady-state mean within +-10 %, peak within +-25 %, phase-1 slope within +-25 % of "
           f"{PHASE1_SLOPE:.0f} N/m")


def fail(message):
    """Bad input: one message, exit status 2, and the old report left as it was."""
    print(f"{PROG}: {message}", file=sys.stderr)
    sys.exit(2)


def load_runs(root):
    runs = {}
    for path in sorted(glob.glob(os.path.join(root, "*", "summary.json"))):
        try:
            with open(path) as f:
                summary = json.load(f)
        except ValueError as e:
            fail(f"{path} is not JSON ({e}); allowed: a summary.json of `thin_ice run`")
        if not isinstance(summary, dict) or not isinstance(summary.get("load"), dict):
            fail(f"{path} has no \"load\" object; allowed: a summary.json of `thin_ice run`")
        runs[os.path.basename(os.path.dirname(path))] = summary
    return runs


def record(root, name, summary):
    """What a run's kept record (load_bins.csv) says beyond its summary: the mean F_cal over the whole
    record [N], the broken bonds at the end, and the history itself (L, F_cal per bin) for the
    comparison plots; with the pushed length at the first broken bond [m] (None if none broke) as
    the summary of `thin_ice run` gives it. None for a run without the record."""
    try:
        bins = run_record.read_load_bins(os.path.join(root, name))
    except FileNotFoundError:
        return None
    except ValueError as e:
        fail(str(e))
    if not bins["bin"]:
        return None
    first_failure = (summary.get("load") or {}).get("first_failure_m")
    return {"first_failure_m": first_failure,
            "record_mean_N": run_record.mean_over(bins, -math.inf, math.inf),
            "broken_end": bins["broken_bonds"][-1],
            "lengths": bins["pushed_length_m"], "loads": bins["horizontal_calibrated_mean_N"]}


def spread_text(values, fmt="{:.0f}"):
    """mean +- sample standard deviation (relative) of two or more values."""
    m = sum(values) / len(values)
    sd = math.sqrt(sum((x - m) ** 2 for x in values) / (len(values) - 1))
    return f"{fmt.format(m)} +- {fmt.format(sd)} ({100 * sd / m:.1f} %)" if m else f"{fmt.format(m)} +- {fmt.format(sd)}"


def pyplot():
    """matplotlib.pyplot drawing to files (Agg), or None when matplotlib is missing."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        return plt
    except ImportError:
        return None


def compare_plot(root, sid, names, histories):
    """docs/validation/SID/variants.png: F_cal against L of the base run, its seeds and its
    resolution variants, on one set of axes."""
    plt = pyplot()
    if plt is None:
        print(f"{PROG}: no comparison plot for {sid}: matplotlib is missing")
        return None
    fig, ax = plt.subplots(figsize=(9, 4.5))
    for name in names:
        h = histories[name]
        if name == sid:  # the base run under the others, so that a variant that follows it shows
            ax.plot(h["lengths"], h["loads"], color="black", lw=2.2, alpha=0.45, label=name, zorder=1)
        else:
            ax.plot(h["lengths"], h["loads"], lw=0.9, label=name, zorder=2)
    ax.set_xlabel("pushed ice length L [m]")
    ax.set_ylabel("F_cal [N]")
    ax.set_title(f"{sid}: base run, Voronoi seeds and resolution variants")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, ncol=2)
    fig.tight_layout()
    out = os.path.join(root, sid, "variants.png")
    save_png(fig, out, dpi=110)
    plt.close(fig)
    return out


EXPERIMENT_MEAN = STEADY_MEAN  # [N] Table 6 / Figs. 10-12, per ice type, 10 m structure
WINDOW_M = 0.5  # width of the windows in which the long runs' loads are averaged [m]
READING = "edge_face"  # the contact friction of the engine (once ice.vertical_slip_friction, removed by issue #31)
ARCHIVE = "level_only"  # docs/validation/level_only/: the runs of the reading every run had until 2026-12-02


def window_means(history, width):
    """Mean F_cal in consecutive windows [k width, (k + 1) width) of pushed length, from L = 0;
    the last window is kept only when the record covers at least half of it. Returns a dict
    k -> (begin, end reached, mean); a window without samples is left out."""
    out, k = {}, 0
    last = history["lengths"][-1]
    while k * width < last:
        begin, end = k * width, (k + 1) * width
        inside = [f for x, f in zip(history["lengths"], history["loads"]) if begin <= x < end]
        reached = min(end, last)
        if inside and reached - begin >= 0.5 * width:
            out[k] = (begin, reached, sum(inside) / len(inside))
        k += 1
    return out


LONG_RUN = re.compile(r"[WMS]-\d(-[a-z]\w*)?-long")  # group 1: a variant of the reading ("-plate"), or None


def long_run_entries(runs, histories, reading):
    """The runs past the matrix's length (named ID-long, or ID-VARIANT-long) among `runs`, each with
    its history and the model it ran: the contact friction's reading (edge_face or level_only) and the variant."""
    return [{"name": n, "label": n if reading == READING else f"{n} ({reading})", "summary": runs[n],
             "history": histories[n], "model": (reading, LONG_RUN.fullmatch(n).group(1))}
            for n in sorted(runs)
            if LONG_RUN.fullmatch(n) and histories.get(n) and window_means(histories[n], WINDOW_M)]


def long_runs_section(root, entries, rel):
    """The long runs of long_run_entries: their mean load per 0.5 m of pushed length, the
    weak-above-medium comparison window by window at equal L (between runs of the same model), and
    one plot (runs of another model than the scenarios' dotted)."""
    if not entries:
        return ["## Long runs", "", "None yet (`scripts/study validate --series ID --tag long --until-length L`).", ""]
    means = {e["label"]: window_means(e["history"], WINDOW_M) for e in entries}
    count = max(max(m) for m in means.values()) + 1
    header = " | ".join(f"{k * WINDOW_M:.1f}-{(k + 1) * WINDOW_M:.1f} m" for k in range(count))
    lines = ["## Long runs: mean load per 0.5 m of pushed ice", "",
             f"Mean F_cal [N] in each {WINDOW_M} m window of pushed length L (a last window is shown when the run "
             "covers at least half of it, with the length reached in brackets). Experiment: the steady-state mean "
             "of Table 6, scaled to the run's width. Runs marked (level_only) ran before the scenarios took "
             "edge_face friction (docs/validation/level_only/).", "",
             f"| run | L reached [m] | {header} | experiment's steady mean [N] |",
             "|---|---:|" + "---:|" * count + "---:|"]
    for e in entries:
        n, s = e["label"], e["summary"]
        cells = []
        for k in range(count):
            w = means[n].get(k)
            cells.append("-" if w is None else
                         f"{w[2]:.0f}" + ("" if w[1] - w[0] > WINDOW_M - 1e-9 else f" (to {w[1]:.2f})"))
        scale = (s.get("experiment") or {}).get("width_scale", 1.0) or 1.0
        lines.append(f"| {n} | {s.get('pushed_length_m', 0):.3f} | " + " | ".join(cells) +
                     f" | {EXPERIMENT_MEAN[n[0]] * scale:.0f} |")
    lines.append("")
    # Weak above medium, as the experiment has it: compared window by window at equal L.
    for w in (e for e in entries if e["name"][0] == "W"):
        for m in (e for e in entries if e["name"][0] == "M"):
            if w["model"] != m["model"]:
                continue  # another reading or variant: not the same model
            mw, mm = means[w["label"]], means[m["label"]]
            pairs = [(mw[k], mm[k]) for k in sorted(set(mw) & set(mm))
                     if mw[k][1] - mw[k][0] > WINDOW_M - 1e-9
                     and mm[k][1] - mm[k][0] > WINDOW_M - 1e-9 and mm[k][2] != 0.0]
            if not pairs:
                continue
            above = sum(1 for a, b in pairs if a[2] > b[2])
            ratios = ", ".join(f"{a[0]:.1f}-{a[1]:.1f} m: {a[2] / b[2]:.2f}" for a, b in pairs)
            lines += [f"Weak above medium ({w['label']} against {m['label']}, whole windows at equal L): weak is "
                      f"higher in {above} of {len(pairs)} windows; ratio weak / medium by window: {ratios}. The "
                      f"experiment's steady states give {EXPERIMENT_MEAN['W'] / EXPERIMENT_MEAN['M']:.2f}.", ""]
    plt = pyplot()
    if plt is not None:
        fig, ax = plt.subplots(figsize=(10, 4.8))
        colours = {"W": "#1f77b4", "M": "#ff7f0e", "S": "#2ca02c"}
        drawn_experiment = set()
        for e in entries:
            n, h, c = e["label"], e["history"], colours[e["name"][0]]
            other = e["model"] != (READING, None)
            ax.plot(h["lengths"], h["loads"], color=c, lw=0.5, alpha=0.2 if other else 0.35)
            windows = [means[n][k] for k in sorted(means[n])]
            ax.step([a for a, _, _ in windows] + [windows[-1][1]], [v for _, _, v in windows] + [windows[-1][2]],
                    where="post", color=c, lw=2, ls=":" if other else "-", label=f"{n}: mean per {WINDOW_M} m")
            scale = (e["summary"].get("experiment") or {}).get("width_scale", 1.0) or 1.0
            if (n[0], scale) not in drawn_experiment:
                drawn_experiment.add((n[0], scale))
                ax.axhline(EXPERIMENT_MEAN[n[0]] * scale, color=c, ls="--", lw=1,
                           label=f"experiment, {ICE_TYPE[n[0]]} ice: steady mean")
        ax.set_xlabel("pushed ice length L [m]")
        ax.set_ylabel("F_cal [N]")
        ax.set_title("Long runs: F_cal (thin) and its mean per 0.5 m of pushed ice (steps)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        save_png(fig, os.path.join(root, "long_runs.png"), dpi=110)
        plt.close(fig)
        lines += [f"![Long runs]({rel}/long_runs.png)", ""]
    return lines


def structure_of(summary):
    """The run's structure geometry (toe_x, angle_deg, width, height) and the false bottom's depth,
    as summary.json records them; None, with the reason, when they cannot be had."""
    st = summary.get("structure")
    if isinstance(st, dict) and all(k in st for k in ("toe_x_m", "angle_deg", "width_m", "height_m")):
        bottom = summary.get("false_bottom") or {}
        return {"toe_x": st["toe_x_m"], "angle_deg": st["angle_deg"], "width": st["width_m"],
                "height": st["height_m"], "bottom_depth": float(bottom.get("depth_m", 0.0))}, None
    return structure_from_scenario_file(summary)


def structure_from_scenario_file(summary):
    """For runs whose summary.json predates its "structure" section: the scenario file (relative to
    the repository root as scripts/study validate gives it) with the run's overrides applied
    (run_summary.scenario_of_run); None, with the reason, when the file cannot be read."""
    try:
        from .run_summary import scenario_of_run
        scenario = scenario_of_run(summary)
        st = dict(scenario["structure"])
        st["bottom_depth"] = float((scenario.get("bottom") or {}).get("depth", 0.25))
        return st, None
    except (ImportError, OSError, KeyError, TypeError, ValueError) as e:
        return None, f"{summary['scenario']['file']}: {e}"


def profile_plot(root, name, summary):
    """docs/validation/RUN/profiles.png from RUN/profiles.csv: the rubble pile above water seen
    from the side (highest cell top per 0.1 m bin along x) and from above (farthest cell from the
    toe per 0.1 m bin along y), drawn beside the structure, as the paper's Figs. 13 and 15."""
    path = os.path.join(root, name, "profiles.csv")
    if not os.path.exists(path):
        return None
    st, why = structure_of(summary)
    if st is None:
        print(f"{PROG}: no profile plot for {name}: {why}")
        return None
    plt = pyplot()
    if plt is None:
        print(f"{PROG}: no profile plot for {name}: matplotlib is missing")
        return None
    side, top = [], []
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            (side if r["profile"] == "side" else top).append((float(r["coordinate_m"]), float(r["value_m"])))
    toe, angle = float(st["toe_x"]), math.radians(float(st["angle_deg"]))
    height, width, depth = float(st["height"]), float(st["width"]), st["bottom_depth"]
    fig, (ax_side, ax_top) = plt.subplots(1, 2, figsize=(11, 4.2))
    # Side view: x towards the structure, z up; the face from the false bottom to its top.
    xs = [x for x, _ in side]
    ax_side.bar(xs, [z for _, z in side], width=0.1, color="#9ecae1", edgecolor="#3182bd", lw=0.5,
                label="highest ice top above water, per 0.1 m")
    ax_side.plot([toe - depth / math.tan(angle), toe + height / math.tan(angle)], [-depth, height], color="black",
                 lw=2, label=f"structure face ({math.degrees(angle):.0f} deg)")
    ax_side.axhline(0.0, color="#2ca02c", lw=0.8, ls="--", label="waterline")
    ax_side.set_xlim(min(xs) - 0.1, toe + height / math.tan(angle) + 0.1)
    ax_side.set_ylim(-depth, max(height, max((z for _, z in side), default=0.0)) * 1.05)
    ax_side.set_xlabel("x [m]")
    ax_side.set_ylabel("z [m]")
    ax_side.set_title("side profile")
    ax_side.set_aspect("equal")
    ax_side.legend(fontsize=7, loc="upper left")
    # Top view: y across, x towards the structure; the pile's reach from the toe per bin.
    ys = [y for y, _ in top]
    ax_top.barh(ys, [e for _, e in top], left=[toe - e for _, e in top], height=0.1, color="#9ecae1",
                edgecolor="#3182bd", lw=0.5, label="ice above water, reach from the toe per 0.1 m")
    ax_top.plot([toe, toe], [-0.5 * width, 0.5 * width], color="black", lw=2, label="structure toe (waterline)")
    ax_top.set_xlabel("x [m]")
    ax_top.set_ylabel("y [m]")
    ax_top.set_title("top profile")
    reach = max((e for _, e in top), default=0.0)
    ax_top.set_xlim(toe - max(1.0, 1.2 * reach), toe + 0.3)
    ax_top.legend(fontsize=7, loc="upper left")
    fig.suptitle(f"{name}: rubble pile at L = {summary.get('pushed_length_m', float('nan')):.2f} m "
                 f"(model only: the experiment's profiles, Fig. 13, are drawings without data)")
    fig.tight_layout()
    out = os.path.join(root, name, "profiles.png")
    save_png(fig, out, dpi=110)
    plt.close(fig)
    return out


def pct(model, reference):
    if model is None or reference in (None, 0) or (isinstance(model, float) and math.isnan(model)):
        return "-"
    change = 100.0 * (model - reference) / reference
    return f"{0.0 if abs(change) < 0.05 else change:+.1f} %"  # no "-0.0 %"


def num(value, fmt="{:.0f}"):
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "-"
    return fmt.format(value)


def row(name, s):
    load, exp = s.get("load") or {}, s.get("experiment") or {}
    scale = exp.get("width_scale", 1.0) or 1.0
    slope_ref = PHASE1_SLOPE * scale
    reached = s.get("pushed_length_m")
    series = re.match(r"[WMS]-\d", name)
    full = EXPERIMENT_LENGTH.get(series.group(0)) if series else None
    steady = "steady" if load.get("steady_found") else "tail mean, not steady"
    # The phase-1 slope is fitted up to the steady-state window; without one it spans whatever the
    # record holds (saw teeth of a short run) and is not the experiment's phase 1.
    slope = load.get("phase1_slope_N_per_m")
    slope_text = num(slope) if load.get("steady_found") else f"{num(slope)} (no steady state: not phase 1)"
    slope_error = pct(slope, slope_ref) if load.get("steady_found") else "-"
    step = f"{num(s.get('time_step_s'), '{:.2g}')} / {s.get('structure_substeps', 1)}"
    return (f"| {name} | {s.get('cells', '-')} | {s.get('structure_width_m', '-')} | {s.get('backend', '-')} | {step} | "
            f"{num(reached, '{:.2f}')} of {num(full, '{:.1f}')} | "
            f"{num(load.get('peak_N'))} | {num(exp.get('peak_N'))} | {pct(load.get('peak_N'), exp.get('peak_N'))} | "
            f"{num(load.get('steady_mean_N'))} ({steady}) | {num(exp.get('steady_mean_N'))} | "
            f"{pct(load.get('steady_mean_N'), exp.get('steady_mean_N'))} | "
            f"{slope_text} | {num(slope_ref)} | {slope_error} |")


# Issue #6's tolerances: steady-state mean, peak and phase-1 slope, as fractions of the experiment's.
TOLERANCE = {"steady": 0.10, "peak": 0.25, "slope": 0.25}
SERIES_RUN = re.compile(r"([WMS])-\d(-long)?")  # a series as its scenario stands, to 0.5 m or longer


def verdict(model, reference, tolerance):
    """'met' or 'missed' for model against reference within +-tolerance (a fraction)."""
    return "met" if abs(model - reference) <= tolerance * abs(reference) else "missed"


def hand_written(path):
    """The lines of a hand-written Markdown file kept beside the runs, as it is ([] when there is none)."""
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [f.read().rstrip(), ""]


def targets_at_a_glance(runs):
    """Per ice type, the targets of issue #6 judged on the longest run of that type (the others of
    the type are shorter: their loads are of an earlier phase), and weak against medium from those
    runs' steady means."""
    longest, others = {}, {}
    for name, s in runs.items():
        m = SERIES_RUN.fullmatch(name)
        if not m or not s.get("load"):
            continue
        kind = m.group(1)
        others.setdefault(kind, []).append(name)
        best = longest.get(kind)
        if best is None or s.get("pushed_length_m", 0.0) > runs[best].get("pushed_length_m", 0.0):
            longest[kind] = name
    if not longest:
        return []
    lines = ["## Targets at a glance", "",
             "Each ice type judged on its longest run (the runs to 0.5 m end in the first failures, before",
             "any pile: their numbers are in the tables below). Steady mean and phase-1 slope count only where",
             "the rule in the code found a steady window; otherwise the tail mean is shown, not judged.", "",
             "| ice | run | L reached [m] | steady mean [N] (exp.) | error | +-10 % | peak [N] (exp.) | error | +-25 % |"
             " phase-1 slope [N/m] (exp.) | error | +-25 % |",
             "|---|---|---:|---:|---:|---|---:|---:|---|---:|---:|---|"]
    steady_means = {}
    for kind in ("W", "M", "S"):
        if kind not in longest:
            lines.append(f"| {ICE_TYPE[kind]} | none | - | - | - | - | - | - | - | - | - | - |")
            continue
        name = longest[kind]
        s = runs[name]
        load, exp = s["load"], s.get("experiment") or {}
        scale = exp.get("width_scale", 1.0) or 1.0
        mean, peak, slope = load.get("steady_mean_N"), load.get("peak_N"), load.get("phase1_slope_N_per_m")
        exp_mean, exp_peak, exp_slope = exp.get("steady_mean_N"), exp.get("peak_N"), PHASE1_SLOPE * scale
        if load.get("steady_found"):
            steady_means[kind] = mean / scale
            mean_cells = (f"{num(mean)} ({num(exp_mean)})", pct(mean, exp_mean), verdict(mean, exp_mean, TOLERANCE["steady"]))
            slope_cells = (f"{num(slope)} ({num(exp_slope)})", pct(slope, exp_slope),
                           verdict(slope, exp_slope, TOLERANCE["slope"]))
        else:
            mean_cells = (f"tail mean {num(mean)} ({num(exp_mean)})", pct(mean, exp_mean), "no steady window")
            slope_cells = (f"{num(slope)} ({num(exp_slope)})", "-", "no steady window")
        peak_cells = (f"{num(peak)} ({num(exp_peak)})", pct(peak, exp_peak), verdict(peak, exp_peak, TOLERANCE["peak"]))
        lines.append(f"| {ICE_TYPE[kind]} | {name} | {num(s.get('pushed_length_m'), '{:.2f}')} | "
                     + " | ".join(mean_cells + peak_cells + slope_cells) + " |")
    lines.append("")
    if "W" in steady_means and "M" in steady_means:
        ratio = steady_means["W"] / steady_means["M"]
        lines.append(f"Weak above medium in steady state: {longest['W']} / {longest['M']} = {ratio:.2f} "
                     f"({'met' if ratio > 1.0 else 'missed'}; the experiment: "
                     f"{EXPERIMENT_MEAN['W'] / EXPERIMENT_MEAN['M']:.2f}).")
    else:
        lines.append("Weak above medium in steady state: not judged (the longest weak and medium runs do not both "
                     "have a steady window).")
    shorter = []
    for kind in ("W", "M", "S"):
        for name in sorted(others.get(kind, [])):
            if name != longest.get(kind):
                s = runs[name]
                shorter.append(f"{name} ({num(s.get('pushed_length_m'), '{:.2f}')} m, peak "
                               f"{pct(s['load'].get('peak_N'), (s.get('experiment') or {}).get('peak_N'))})")
    if shorter:
        lines.append("")
        lines.append("Not judged above, shorter runs of the same types: " + ", ".join(shorter) + ".")
    return lines + [""]


def alpha_text(runs):
    """The structural factor alpha of Eq. (18) that the runs' F_cal carries, as summary.json records it."""
    alphas = sorted({s.get("calibration_factor") for s in runs.values() if s.get("calibration_factor") is not None})
    if not alphas:
        return "alpha as each run's scenario gives it"
    if len(alphas) == 1:
        return f"alpha = {alphas[0]:g} in every run"
    return "alpha = " + ", ".join(f"{a:g}" for a in alphas) + " (differs between runs; see each run's summary.json)"


def table6(runs):
    """The Table 6 layout: one row per run."""
    return (["| run | cells | width [m] | backend | dt [s] / structure sub-steps | L reached of experiment [m] |"
             " F_p model [N] | F_p exp. [N] | error |"
             " F_avg model [N] | F_avg exp. [N] | error | phase-1 slope model [N/m] | exp. [N/m] | error |",
             "|---|---:|---:|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|"]
            + [row(name, runs[name]) for name in sorted(runs)])


def seeds_and_resolution(root, runs, histories, rel, level="##"):
    """The spread over Voronoi seeds (ID, ID-seedK), the resolution checks (ID-fine, ID-halfdt,
    ID-singlerate against ID) and one plot per series of its base run and variants."""
    spread, tail_spreads = [], []
    for sid in SERIES:
        names = [n for n in runs if re.fullmatch(re.escape(sid) + r"(-seed\d+)?", n)]
        if len(names) >= 2:
            seeds = [runs[n] for n in names]
            # A record too short for statistics has none (null): it cannot count in the spread.
            seeds = [s for s in seeds if s["load"].get("steady_mean_N") is not None and s["load"].get("peak_N") is not None]
            if len(seeds) < 2:
                continue
            means = [s["load"]["steady_mean_N"] for s in seeds]
            peaks = [s["load"]["peak_N"] for s in seeds]
            recs = [histories[n] for n in names if histories[n]]
            record_means = [r["record_mean_N"] for r in recs]
            failures = [r["first_failure_m"] for r in recs if r["first_failure_m"] is not None]
            m = sum(means) / len(means)
            if m:
                tail_spreads.append(100 * math.sqrt(sum((x - m) ** 2 for x in means) / (len(means) - 1)) / m)
            spread.append(f"| {sid} | {len(seeds)} | {spread_text(peaks)} | "
                          f"{spread_text(record_means) if len(record_means) >= 2 else '-'} | {spread_text(means)} | "
                          + (f"{min(failures):.4f} - {max(failures):.4f}" if failures else "-") + " |")
    lines = [f"{level} Spread from the Voronoi mesh alone (seeds)", ""]
    lines += (["| series | runs | F_p mean +- std [N] | mean F_cal over the record [N] | F_avg (tail mean where not steady) [N] "
               "| first broken bond at L [m] |", "|---|---:|---:|---:|---:|---:|"] + spread
              if spread else ["Not run yet (`scripts/study validate --series ID --seeds 2,3`)."])
    unsteady = [n for n in runs if re.fullmatch(r"[WMS]-\d(-seed\d+)?", n) and not runs[n]["load"].get("steady_found")]
    if spread and unsteady:
        lines += ["", "Where a run has no steady state (" + ", ".join(sorted(unsteady)) + "), its F_avg above is the "
                  "tail mean of its last quarter, not a steady-state load."]
    lines.append("")
    res = []
    for sid in SERIES:
        for variant, what in (("fine", "0.85 x cell size and time step"), ("halfdt", "half time step"),
                              ("singlerate", "one rate: every cell at the structure's step")):
            name = f"{sid}-{variant}"
            if sid in runs and name in runs:
                v_run = runs[name]
                what = (f"{what} (dt {v_run.get('time_step_s', 0):.2g} s, "
                        f"{v_run.get('structure_substeps', 1)} sub-step(s); base: dt "
                        f"{runs[sid].get('time_step_s', 0):.2g} s, {runs[sid].get('structure_substeps', 1)})")
                b, v = runs[sid]["load"], runs[name]["load"]
                hb, hv = histories.get(sid), histories.get(name)
                failure = (f"{num(hb['first_failure_m'], '{:.4f}')} / {num(hv['first_failure_m'], '{:.4f}')}"
                           if hb and hv else "-")
                record_mean = pct(hv["record_mean_N"], hb["record_mean_N"]) if hb and hv else "-"
                broken = f"{hb['broken_end']} / {hv['broken_end']}" if hb and hv else "-"
                res.append(f"| {sid} | {what} | {pct(v['peak_N'], b['peak_N'])} | "
                           f"{num(b.get('peak_at_m'), '{:.4f}')} / {num(v.get('peak_at_m'), '{:.4f}')} | {failure} | "
                           f"{record_mean} | {pct(v['steady_mean_N'], b['steady_mean_N'])} | {broken} |")
    lines += [f"{level} Resolution checks (change against the base run of the series)", ""]
    lines += (["Base / variant where two values are given. A change counts as a resolution effect only where it is",
               "larger than the spread of the same series over Voronoi seeds (above): F_p, its position and the",
               "first failure are sharp; the tail mean's standard deviation over seeds is "
               + (" and ".join(f"{t:.0f} %" for t in tail_spreads) if tail_spreads else "not measured yet") + ".", "",
               "| series | variant | F_p | F_p at L [m] | first broken bond at L [m] | mean F_cal over the record "
               "| F_avg (tail mean where not steady) | broken bonds at the end |",
               "|---|---|---:|---:|---:|---:|---:|---:|"] + res
              if res else ["Not run yet (`scripts/study validate --series ID --resolution`)."])
    lines.append("")
    for sid in SERIES:
        names = sorted(n for n in runs if histories.get(n) and
                       re.fullmatch(re.escape(sid) + r"(-seed\d+|-fine|-halfdt|-singlerate)?", n))
        if sid in names and len(names) >= 2 and compare_plot(root, sid, names, histories):
            lines += [f"![{sid} and its variants]({rel}/{sid}/variants.png)", ""]
    return lines


def profile_runs(runs, strong_first):
    """The runs whose rubble profiles are shown: strong ice's base runs first where asked (the
    paper's Fig. 15), then the longest run (ID or ID-long) of each ice type."""
    longest = {}
    for name, summary in runs.items():
        if re.fullmatch(r"[WMS]-\d(-long)?", name) and summary.get("pushed_length_m", 0) > longest.get(name[0], ("", 0))[1]:
            longest[name[0]] = (name, summary.get("pushed_length_m", 0))
    first = [n for n in ("S-1", "S-2") if n in runs] if strong_first else []
    return first + [v[0] for _, v in sorted(longest.items()) if v[0] not in first]


def pile_lines(root, runs, names, rel, label=""):
    lines = []
    for name in names:
        if profile_plot(root, name, runs[name]):
            lines += [f"### {name}{label}", "", f"![{name} rubble profiles]({rel}/{name}/profiles.png)", ""]
            # The ice under the water too, where a side view was drawn (scripts/study plot_side_view).
            if os.path.exists(os.path.join(root, name, "side_view.png")):
                lines += [f"![{name} cells near the structure, from the side and from above]({rel}/{name}/side_view.png)", ""]
    return lines


def main(argv):
    p = argparse.ArgumentParser(prog=PROG, description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--runs", required=True)
    p.add_argument("--out", required=True)
    a = p.parse_args(argv)
    if not os.path.isdir(a.runs):
        fail(f"--runs {a.runs}: no such folder; allowed: the folder of run folders (docs/validation)")
    if not a.out.endswith(".md") or not os.path.isdir(os.path.dirname(os.path.abspath(a.out))):
        fail(f"--out {a.out}: allowed: a .md file in an existing folder")
    runs = load_runs(a.runs)
    if not runs:
        fail(f"--runs {a.runs} holds no run (no {a.runs}/RUN/summary.json): the report would say nothing was run; "
             f"{a.out} is left as it was")
    rel = os.path.relpath(a.runs, os.path.dirname(os.path.abspath(a.out)))
    # The runs of the earlier reading, kept apart so that every run above them is of the scenarios as
    # they stand: docs/validation/level_only/RUN.
    archive, archive_rel = os.path.join(a.runs, ARCHIVE), f"{rel}/{ARCHIVE}"
    archived = load_runs(archive) if os.path.isdir(archive) else {}
    lines = ["# Validation against the shallow-water experiments", "",
             "Regenerated by `scripts/study validate` from the runs in docs/validation/ (each run's summary.json",
             "and load plot). Experiment: Lemström and Polojärvi's model-scale tests, paper Tables 4-6. Loads",
             f"are the calibrated horizontal load F_cal = alpha F (Eq. 18; alpha = 0.63 in the first table; in the tables of the earlier reading, "
             f"{alpha_text(runs)}); a run on a structure",
             "narrower than the experiment's 10 m is compared per metre of width (the experiment's loads are",
             "scaled by width / 10 m). The steady state is found by the rule written in",
             "`include/thin_ice_sim/study/load_statistics.hpp`; where the rule finds none, the mean of the last",
             "quarter of the record is shown and marked \"tail mean, not steady\": that is not a steady-state",
             "load. The phase-1 slope is the least-squares slope of F_cal against L from the first failure",
             "(from the end of that failure's collapse: the pile begins there) to the start of the steady window;",
             "its error is given only where there is a steady window.",
             f"Targets (issue #6): {TARGETS}.", "",
             "The first table is of the scenarios as they stand (the phase-2 reading: E_v four times the "
             "floating-plate value, alpha = 0.63; \"Phase 2\" below says how it was chosen). The tables after it are "
             "of the reading before phase 2 (E_v from the floating-plate length, alpha = 1), kept until the runs at "
             "the new reading reach their lengths. "
             f"Within the tables the contact friction is the engine's ({READING}: the edge face of offset cells "
             "resists their vertical slip). "
             f"The runs made without it ({ARCHIVE}, until 2026-12-02) are in docs/validation/{ARCHIVE}/ "
             "and in their own section further down." if archived else "", "",
             ]
    # The scenarios' reading first (issue #31): every series from the validation strips and the
    # full-width runs at that reading, as far as they have got.
    lines += ["## Every series at the scenarios' reading (E_v x 4, alpha = 0.63)", "",
              "The runs of the scenarios as they stand: 2 m strips (sheet, structure, panels and channel 2 m wide,",
              "walls frictionless; config/strips/validation.matrix, a 31 m sheet so that the experiments' lengths fit,",
              "and the two W-3 strips of a 14 m sheet) and full-width runs, in docs/validation/strips/ and",
              "docs/validation/full/. alpha F per metre of structure width against Table 6 per metre; the raw",
              "load beside it. Runs in progress are shown as far as they got, with the experiment's pushed length",
              "in brackets: a window the rule finds in the first metres (before any pile) is reported, not",
              "trusted. The tables after this one are of the reading before phase 2.", ""]
    lines += phase2_table(a.runs)
    lines.append("")
    # Why the table's loads miss, as far as the runs have shown it: written by hand beside them.
    lines += hand_written(os.path.join(a.runs, "phase2_why.md"))
    lines += targets_at_a_glance(runs)
    # Why each target missed above is missed, and what was tried: written by hand beside the runs.
    lines += hand_written(os.path.join(a.runs, "misses.md"))
    # Phase 2 (issue #31): the strip bench and the paper's readings, the work on the misses above.
    lines += hand_written(os.path.join(a.runs, "phase2.md"))
    # Where each value of the scenarios comes from, and which series were only predicted.
    lines += hand_written(os.path.join(a.runs, "procedure.md"))
    lines += ["## Table 6 layout: model against experiment", ""]
    lines += table6(runs)
    missing = [sid for sid in SERIES if sid not in runs]
    lines += ["", f"Series without a run yet: {', '.join(missing) if missing else 'none'}.", "",
              "The paper's own TIM runs (Table 6) for comparison: "
              + "; ".join(f"{k}: F_p {v[0]} N, F_avg {v[1]} N" for k, v in PAPER_TIM.items()) + ".", ""]

    histories = {n: record(a.runs, n, runs[n]) for n in runs}
    archived_histories = {n: record(archive, n, archived[n]) for n in archived}
    lines += seeds_and_resolution(a.runs, runs, histories, rel)
    lines += long_runs_section(a.runs, long_run_entries(runs, histories, READING) +
                               long_run_entries(archived, archived_histories, ARCHIVE), rel)

    pile = pile_lines(a.runs, runs, profile_runs(runs, strong_first=True), rel)
    pile += pile_lines(archive, archived, profile_runs(archived, strong_first=False), archive_rel, f" ({ARCHIVE})")
    lines += ["## Rubble pile profiles", ""]
    lines += (["The ice above the waterline at the end of each run: strong ice (S-1, S-2), as the paper's",
               "Fig. 15 asks, and the longest run of each ice type (of the earlier reading too, marked level_only).",
               "Heights are cell tops (z + h/2; cells do not tilt in this 2.5-D model); the top view bins by cell",
               "centroid, so it is good to about a cell radius. Where a run has a side view (scripts/study plot_side_view,",
               "from its last snapshot), it shows every cell near the structure, under the waterline as well.",
               ""] + pile if pile else ["No run with profiles.csv yet."])
    lines.append("")

    # Where the broken ice went, counted per snapshot (scripts/study ice_layers --plot / --csv).
    layer_sections = []
    for root, root_rel, label in ((a.runs, rel, ""), (archive, archive_rel, f" ({ARCHIVE})")):
        if not os.path.isdir(root):
            continue
        layer_plots = sorted(n for n in os.listdir(root) if re.fullmatch(r"layers_[\w-]+\.png", n))
        if layer_plots:
            numbers = (f"; the numbers are in [layers.csv]({root_rel}/layers.csv)"
                       if os.path.exists(os.path.join(root, "layers.csv")) else "")
            layer_sections += [f"Runs{label}{numbers}:", ""] + [f"![{n[:-4]}{label}]({root_rel}/{n})" for n in layer_plots] + [""]
    if layer_sections:
        lines += ["## Where the broken ice goes: under or over the sheet", "",
                  "Per snapshot, the broken ice more than h/2 under and over the sheet's floating level and the",
                  "sheet's own cells pressed down (the sheet: the largest piece held together by intact bonds),",
                  "drawn by scripts/study ice_layers. The runs and what they show: the calibration notes (linked at the end).", ""]
        lines += layer_sections

    if archived:
        lines += [f"## The runs of the earlier reading (no friction on the edge face: {ARCHIVE})", "",
                  "Until 2026-12-02 every run let two cells at different heights slide past each other vertically",
                  "without friction (docs/model.md, \"DEM contacts\"). These runs, their seeds, resolution checks and",
                  f"experiments are kept in docs/validation/{ARCHIVE}/ under the names the calibration notes (at the end)",
                  "give them; their scenario files have since changed, so they are history, not the model.", ""]
        lines += table6(archived) + [""]
        lines += seeds_and_resolution(archive, archived, archived_histories, archive_rel, level="###")

    lines += ["## Load histories", ""]
    for root, root_rel, group, label in ((a.runs, rel, runs, ""), (archive, archive_rel, archived, f" ({ARCHIVE})")):
        for name in sorted(group):
            if os.path.exists(os.path.join(root, name, "load.png")):
                lines += [f"### {name}{label}", "", f"![{name}{label}]({root_rel}/{name}/load.png)", ""]

    # The dated notes come last: the evidence, read after the results they led to. They are a
    # journal kept beside the runs, so the report links them instead of copying them in.
    if os.path.exists(os.path.join(a.runs, "calibration.md")):
        lines += ["## Calibration notes", "",
                  f"What was run, why, and what it showed, in the order it was done, newest first: "
                  f"[calibration.md]({rel}/calibration.md), a dated journal. Where an early note and a later "
                  "one disagree, the later one stands; the sections above say how things stand now.", ""]
    path = a.out
    with open(path + ".partial", "w") as f:
        f.write("\n".join(lines))
    os.replace(path + ".partial", path)
