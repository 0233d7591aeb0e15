"""The figure docs/validation.md shows under its lead table: every run at the scenarios' reading
(the validation strips and full-width runs of phase2_table), one panel per series of Table 5, alpha F
per metre of structure width against pushed length from each run's kept record (load_bins.csv,
averaged over 0.5 m so that the runs can be told apart), with the experiment's steady mean and peak
per metre (Table 6)."""
import os

from . import run_record
from .experiments import ALPHA
from .phase2_table import SERIES, runs_of
from .png_output import save_png

SMOOTHING = 0.5  # [m] of pushed ice each drawn point averages


def per_metre_windows(path):
    """([window ends, m], [alpha F per metre of width, N/m]) of a run over windows SMOOTHING long."""
    summary = run_record.read_summary(path)
    bins = run_record.read_load_bins(path)
    run_alpha, width = summary[run_record.CALIBRATION_FACTOR], summary[run_record.STRUCTURE_WIDTH]
    end = bins[run_record.PUSHED_LENGTH][-1] if bins[run_record.BIN] else 0.0
    xs, ys, k = [], [], 0
    while (k + 1) * SMOOTHING <= end + 1e-9:
        mean = run_record.mean_over(bins, k * SMOOTHING, (k + 1) * SMOOTHING)
        if mean is not None:
            xs.append((k + 1) * SMOOTHING)
            ys.append(run_record.at_alpha(mean, run_alpha, ALPHA) / width)
        k += 1
    return xs, ys


def draw(root, out, experiment_per_metre):
    """Writes the figure to `out`; returns False (nothing written) where matplotlib is missing or no
    series has a run. experiment_per_metre: {series: (steady mean, peak)} [N/m]."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return False
    series = [s for s in SERIES if runs_of(root, s)]
    if not series:
        return False
    columns = 4
    rows = (len(series) + columns - 1) // columns
    fig, axes = plt.subplots(rows, columns, figsize=(4.2 * columns, 3.2 * rows), squeeze=False, sharey=True)
    for ax in axes.flat[len(series):]:
        ax.set_visible(False)
    for ax, sid in zip(axes.flat, series):
        for label, path in runs_of(root, sid):
            xs, ys = per_metre_windows(path)
            ax.plot(xs, ys, lw=1.2, marker=".", ms=3, label=f"{label} ({os.path.basename(path)})")
        mean, peak = experiment_per_metre[sid]
        ax.axhline(mean, color="#2ca02c", ls="--", lw=1.0, label="experiment, steady mean")
        ax.axhline(peak, color="#ff7f0e", ls=":", lw=1.0, label="experiment, peak")
        ax.set_title(sid, fontsize=10)
        ax.set_xlabel("pushed ice length L [m]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=6, loc="upper left")
    for ax in axes[:, 0]:
        ax.set_ylabel("alpha F per metre of width [N/m]")
    fig.suptitle(f"Every run at the scenarios' reading: alpha = {ALPHA:g}, means over {SMOOTHING:g} m of pushed ice",
                 fontsize=11)
    fig.tight_layout()
    save_png(fig, out, dpi=90)
    plt.close(fig)
    return True
