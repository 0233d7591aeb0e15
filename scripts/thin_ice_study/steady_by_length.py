"""The steady-state rule's verdict on a run's record cut short at every STEP metres of pushed
length, with the code `thin_ice run` uses at the end of a run (`thin_ice analyse` on a copy of the
run holding only the bins of its kept record, load_bins.csv, up to the cut). It shows whether a run's verdict holds as the run goes on:
a window found at one length that the load leaves later was a pause of phase 1, not phase 2.

usage: scripts/study steady_by_length RUN_DIR [--step S] [--from L] [--tool PATH]
  --step  spacing of the cuts [m] (default 0.5); the run's own end is always the last bin
  --from  first cut [m] (default: one step)
  --tool  the thin_ice program (default: the catkin build's, else the plain CMake build's)
Prints a Markdown table on stdout: cut, steady window found or not, the window, its mean (or the
tail mean) and its error against the experiment, the peak and the phase-1 slope up to the cut.
Exit status 2 when RUN_DIR is not a finished run or an argument is bad.
"""
import functools
import argparse
import os
import shutil
import tempfile

from . import run_record
from .run_summary import analyse, default_tool
from .refusal import refuse

PROG = "scripts/study steady_by_length"
SUMMARY = "the steady-state rule's verdict on a run's record cut short at every STEP metres"


fail = functools.partial(refuse, PROG)  # bad input: one line, exit status 2


def number(value, fmt=".0f"):
    """value formatted, or "-" where the statistics have none (a record too short for it)."""
    return "-" if value is None else format(value, fmt)


def verdict_rows(tool, run, step, first):
    """[(cut [m], load object, experiment object)] for the cuts first, first + step, ... and the end."""
    bins_path = os.path.join(run, run_record.LOAD_BINS_FILE)
    try:
        header, *samples = run_record.read_table(bins_path)
        column = header.index(run_record.PUSHED_LENGTH)
        lengths = [float(row[column]) for row in samples]
    except (OSError, ValueError) as e:
        fail(f"{run} has no readable {run_record.LOAD_BINS_FILE} with a {run_record.PUSHED_LENGTH} column ({e}; "
             f"a run made before it: `thin_ice analyse {run} --write-bins` writes it)")
    if not lengths:
        fail(f"{bins_path} has no bins")
    end = lengths[-1]
    cuts, k = [], 0
    # A cut within a millimetre of the end is the end (a record stops a few steps past its target).
    while first + k * step < end - 1e-3:
        cuts.append(first + k * step)
        k += 1
    cuts.append(end)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for cut in cuts:
            shutil.copy(run_record.summary_path(run), tmp)
            with open(os.path.join(tmp, run_record.LOAD_BINS_FILE), "w") as f:
                f.write(",".join(header) + "\n")
                f.writelines(",".join(row) + "\n" for row, x in zip(samples, lengths) if x <= cut + 1e-9)
            try:
                answer = analyse(tool, tmp)
            except RuntimeError as e:
                fail(f"thin_ice analyse refused {run} cut at {cut:g} m: {e}")
            rows.append((cut, answer[run_record.LOAD], answer.get(run_record.EXPERIMENT) or {}))
    return rows


def main(argv):
    p = argparse.ArgumentParser(prog=PROG, description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("run", metavar="RUN_DIR")
    p.add_argument("--step", type=float, default=0.5)
    p.add_argument("--from", dest="first", type=float)
    p.add_argument("--tool")
    a = p.parse_args(argv)
    if not a.step > 0:
        fail(f"--step {a.step:g}; allowed: a length > 0 m")
    first = a.step if a.first is None else a.first
    if not first > 0:
        fail(f"--from {first:g}; allowed: a length > 0 m")
    if not os.path.isfile(run_record.summary_path(a.run)):
        fail(f"{a.run} is not a finished run directory of `thin_ice run` (no summary.json)")
    if os.path.exists(os.path.join(a.run, run_record.LOADS_PARTIAL_FILE)):
        fail(f"{a.run} is still being written (loads.csv.partial): its summary.json and loads.csv are of an "
             "earlier stop; allowed: a run that has stopped")
    tool = a.tool or default_tool(PROG)
    if not (os.path.isfile(tool) and os.access(tool, os.X_OK)):
        fail(f"--tool {tool} is not an executable file; allowed: the path of the thin_ice program")
    print(f"{os.path.basename(os.path.normpath(a.run))}: the steady-state rule on the record cut at each length")
    print("")
    print("| cut at L [m] | steady window | window [m] | mean [N] (tail mean where none) | error | peak [N] "
          "| phase-1 slope [N/m] |")
    print("|---:|---|---|---:|---:|---:|---:|")
    for cut, load, exp in verdict_rows(tool, a.run, a.step, first):
        window = load.get("steady_window_m") or [None, None]
        mean, reference = load.get("steady_mean_N"), exp.get("steady_mean_N")
        error = f"{100.0 * (mean / reference - 1.0):+.1f} %" if mean is not None and reference else "-"
        print(f"| {cut:.3f} | {'found' if load.get('steady_found') else 'none'} | {number(window[0], '.2f')}-"
              f"{number(window[1], '.2f')} | {number(mean)} | {error} | {number(load.get('peak_N'))} "
              f"| {number(load.get('phase1_slope_N_per_m'))} |")
