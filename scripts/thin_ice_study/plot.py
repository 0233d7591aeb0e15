"""Draws the horizontal ice load against pushed ice length of `thin_ice run` results, as the
paper's Figures 10-12: the simulated calibrated load F_cal (blue), the experimental steady-state
mean (green dashed) and peak (orange dashed) of Table 6 when the scenario has them, the
model's steady-state window (shaded) with its mean (blue dotted), and the lengths at which the
run was resumed from its checkpoint (grey dash-dotted; summary.json's resumed_at_m).

usage: scripts/study plot RUN_DIR [RUN_DIR...] [--out PNG]

Reads RUN_DIR/loads.csv (or loads.csv.partial of a run still going) and RUN_DIR/summary.json; where
loads.csv is absent or holds only the last segments (a clone keeps only the kept record), the
means of load_bins.csv's 35 mm bins.
Without --out each run is drawn to RUN_DIR/load.png; with --out all runs go into one picture,
one panel per run. Snapshots (RUN_DIR/snapshots) are not drawn.
"""
import argparse
import os
import sys
import textwrap

from . import run_record
from .png_output import check_png_path, save_png

PROG = "scripts/study plot"
SUMMARY = "draws F_cal against pushed length of runs, with Table 6's lines and the steady window"

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit(f"{PROG} needs matplotlib (Debian: apt-get install python3-matplotlib)")

BLUE, GREEN, ORANGE, GREY = "#1f77b4", "#2ca02c", "#ff7f0e", "0.45"


def read_run(run_dir):
    """Returns (L [m], F_cal [N], summary dict or None, note about the data)."""
    path = run_record.loads_path(run_dir)
    summary = run_record.read_summary(run_dir)
    if not run_record.rows_are_whole_run(run_dir, summary) and os.path.exists(os.path.join(run_dir, run_record.LOAD_BINS_FILE)):
        # A clone's copy of a run (loads.csv is not kept) or a run resumed there: the kept record.
        try:
            bins = run_record.read_load_bins(run_dir)
        except ValueError as e:
            sys.exit(f"{PROG}: {e}")
        return (bins[run_record.PUSHED_LENGTH], bins[run_record.CALIBRATED_MEAN], summary,
                f"means of {1000 * run_record.LOAD_BIN_LENGTH:.0f} mm bins")
    if path is None:
        sys.exit(f"{PROG}: {run_dir}: no loads.csv nor load_bins.csv (is it the --out directory of a `thin_ice run`?)")
    try:
        path, columns = run_record.read_load_columns(run_dir,
                                                     (run_record.PUSHED_LENGTH, run_record.HORIZONTAL_CALIBRATED))
    except ValueError as e:
        sys.exit(f"{PROG}: {e}")
    note = "partial" if os.path.basename(path) == run_record.LOADS_PARTIAL_FILE else ""
    lengths, loads = columns[run_record.PUSHED_LENGTH], columns[run_record.HORIZONTAL_CALIBRATED]
    if summary is None:
        note = ", ".join(n for n in (note, "no summary.json") if n)
    return lengths, loads, summary, note


def finite(*values):
    return all(isinstance(v, (int, float)) for v in values)


def resumptions(summary):
    """The pushed lengths [m] at which the run was resumed from its checkpoint."""
    return [v for v in (summary or {}).get(run_record.RESUMED_AT) or [] if finite(v)]


def draw(ax, run_dir, lengths, loads, summary, note):
    ax.plot(lengths, loads, color=BLUE, linewidth=1.0, label="TIM simulation $F_{cal}$")
    summary = summary or {}
    load = summary.get(run_record.LOAD) or {}
    experiment = summary.get(run_record.EXPERIMENT)
    if experiment:
        series = experiment.get("series", "")
        scale = experiment.get("width_scale", 1.0)
        if abs(scale - 1.0) > 1e-9:  # a slice of the 10 m structure: Table 6 per metre of width
            series = f"{series} x {scale:g} (width)"

        ax.axhline(experiment["steady_mean_N"], color=GREEN, linestyle="--", linewidth=1.5,
                   label=f"experiment {series} steady state {experiment['steady_mean_N']:.0f} N")
        ax.axhline(experiment["peak_N"], color=ORANGE, linestyle="--", linewidth=1.5,
                   label=f"experiment {series} peak {experiment['peak_N']:.0f} N")
    window = load.get("steady_window_m") or [None, None]
    mean = load.get("steady_mean_N")
    if finite(window[0], window[1], mean):
        found = load.get("steady_found", False)
        what = "steady window" if found else "not steady: tail window"
        ax.axvspan(window[0], window[1], color=BLUE, alpha=0.08,
                   label=f"model {what} {window[0]:.2f}-{window[1]:.2f} m")
        error = (experiment or {}).get("steady_mean_error_percent")
        versus = f" ({error:+.1f} %)" if finite(error) else ""
        ax.hlines(mean, window[0], window[1], colors=BLUE, linestyles=":", linewidth=2.0,
                  label=f"model mean {mean:.0f} N{versus}")
    peak, peak_at = load.get("peak_N"), load.get("peak_at_m")
    if finite(peak, peak_at):
        error = (experiment or {}).get("peak_error_percent")
        versus = f" ({error:+.1f} %)" if finite(error) else ""
        ax.plot([peak_at], [peak], "o", color=BLUE, markersize=5,
                label=f"model peak {peak:.0f} N{versus}")
    resumed = resumptions(summary)
    for k, length in enumerate(resumed):
        ax.axvline(length, color=GREY, linestyle="-.", linewidth=0.8,
                   label=("resumed from its checkpoint at L = " + ", ".join(f"{v:g}" for v in resumed) + " m")
                   if k == 0 else None)

    scenario = (summary.get(run_record.SCENARIO) or {}).get("name") or os.path.basename(
        os.path.normpath(run_dir))
    # The overrides that change the model (not the thread count), so that variants of one series
    # (seeds, readings, resolution) can be told apart.
    overrides = (summary.get(run_record.SCENARIO) or {}).get("overrides", [])
    # Overrides given when the run was resumed come last, in order, and hold from that length on.
    switched = [s.get("from_m") if isinstance(s, dict) else None for s in summary.get(run_record.OVERRIDES_FROM) or []]
    first_switched = len(overrides) - len(switched)
    changes = [o + (f" (from L = {switched[k - first_switched]:g} m)"
                    if k >= first_switched and finite(switched[k - first_switched]) else "")
               for k, o in enumerate(overrides) if not o.replace(" ", "").startswith("numerics.threads=")]
    if changes:
        scenario += " with " + ", ".join(changes)
    title = f"{scenario}, backend {summary.get(run_record.BACKEND, '?')}"
    if summary.get(run_record.STATUS) not in (None, "completed"):
        note = ", ".join(n for n in (note, f"run {summary[run_record.STATUS]}") if n)
    if note:
        title += f" ({note})"
    ax.set_title("\n".join(textwrap.wrap(title, 110)))  # a long list of overrides wraps, not widens
    ax.set_xlabel("pushed ice length $L$ [m]")
    ax.set_ylabel("horizontal load $F_{cal}$ [N]")
    ax.set_xlim(left=0.0)
    ax.set_ylim(bottom=min(0.0, min(loads, default=0.0)))
    ax.grid(True, alpha=0.3)
    # Below the axes: inside, it would hide the horizontal reference lines or the record.
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=3, fontsize=8, frameon=False)


def main(argv):
    parser = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0])
    parser.add_argument("run_dirs", nargs="+", metavar="RUN_DIR")
    parser.add_argument("--out", metavar="PNG", help="one picture for all runs")
    args = parser.parse_args(argv)
    if args.out:
        check_png_path(PROG, "--out", args.out)
    runs = [(d, *read_run(d)) for d in args.run_dirs]
    if args.out:
        groups = [(args.out, runs)]
    else:
        groups = [(os.path.join(run[0], "load.png"), [run]) for run in runs]
    for out, group in groups:
        fig, axes = plt.subplots(len(group), 1, figsize=(10, 5.5 * len(group)), squeeze=False)
        for ax, run in zip(axes[:, 0], group):
            draw(ax, *run)
        fig.tight_layout()
        save_png(fig, out, dpi=120, bbox_inches="tight")
        plt.close(fig)
        resumed = [f"{run[0]} resumed at L = " + ", ".join(f"{v:g}" for v in resumptions(run[3])) + " m"
                   for run in group if resumptions(run[3])]
        print(f"wrote {out}" + (f" ({'; '.join(resumed)})" if resumed else ""))
