"""Brings run directories of `thin_ice run` made at one structural factor alpha (Eq. 18, F_cal =
alpha F) to another, without running them again: alpha multiplies the output only and enters no
equation of motion, so loads.csv's F_cal column is alpha times its raw column and the kept record's
(load_bins.csv) calibrated columns scale with alpha; the statistics are worked out again from the
bins by `thin_ice analyse`, with the code `thin_ice run` uses at the end of
a run. The result is what a run made at the new alpha writes (test/test_recalibrate.py compares
the two).

usage: scripts/study recalibrate RUN_DIR [RUN_DIR...] [--alpha A] [--tool PATH]

Without --alpha, the new alpha is structure.calibration_factor of the run's scenario file as it
stands now (summary.json's scenario.file, relative to the repository root, with the run's own
--set overrides), as `thin_ice analyse` loads it with the C++ scenario loader. In each run,
loads.csv's horizontal_calibrated_N becomes alpha times horizontal_raw_N (where the directory has
loads.csv), load_bins.csv's calibrated columns new/old alpha times theirs; summary.json gets the
statistics and errors against the experiment worked out again, calibration_factor, and a
"recalibrations" entry that records the change. --tool: the thin_ice program, whose `analyse`
command is used (default: under .ws). Both files are written beside the old ones and then renamed
over them. A run already at the new alpha is left alone. A run with a checkpoint can only be
brought to its scenario's alpha, the one a resumed run would write. Exit status 2 when a run
cannot be brought over; the others are still done.
"""
import argparse
import datetime
import io
import json
import math
import os
import sys
import tempfile

from . import run_record
from .run_summary import analyse, default_tool, replace_files, summary_text

PROG = "scripts/study recalibrate"
SUMMARY = "brings runs to another alpha of Eq. 18 (F_cal and its statistics) without running them again"


class RunError(Exception):
    pass


def alpha_of_scenario(tool, run_dir, remedy):
    """(alpha, where it comes from): structure.calibration_factor of the run's scenario file as it
    stands now, with the run's own --set applied, as the C++ scenario loader reads it. remedy: what
    the message tells the user to do when the scenario cannot be loaded."""
    try:
        answer = analyse(tool, run_dir)
    except RuntimeError as e:
        raise RunError(str(e))
    if answer.get("scenario_calibration_factor") is None:
        raise RunError(f"the run's scenario cannot be loaded ({answer.get('scenario_error')}); {remedy}")
    return answer["scenario_calibration_factor"], "the run's scenario with its overrides"


def check_alpha(value, where):
    if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0.0):
        raise RunError(f"calibration_factor = {value!r} from {where}: alpha must be a finite number > 0")
    return float(value)


def rewritten(path, targets, value):
    """The CSV file's text with the columns `targets(header)` (their indices) of every row set to
    value(row, column) [a number], written with the nine significant digits of `thin_ice run`, the
    other columns as they were. RunError names the file and the line where a row is not a record's."""
    rows = run_record.read_table(path)
    if not rows:
        raise RunError(f"{path} is empty")
    header = rows[0]
    columns = targets(header)
    out = io.StringIO()
    out.write(",".join(header) + "\n")
    for number, row in enumerate(rows[1:], start=2):
        if len(row) != len(header):
            raise RunError(f"{path}: line {number} has {len(row)} fields, the header {len(header)}")
        try:
            for k in columns:
                row[k] = f"{value(row, k):.9g}"
        except ValueError:
            raise RunError(f"{path}: line {number}: a load is not a number")
        out.write(",".join(row) + "\n")
    return out.getvalue()


def rescaled_loads(path, alpha):
    """loads.csv's text with horizontal_calibrated_N = alpha * horizontal_raw_N in every row."""
    found = {}

    def calibrated_column(header):
        if run_record.HORIZONTAL_RAW not in header or run_record.HORIZONTAL_CALIBRATED not in header:
            raise RunError(f"{path}: no {run_record.HORIZONTAL_RAW} and {run_record.HORIZONTAL_CALIBRATED} columns")
        found["raw"] = header.index(run_record.HORIZONTAL_RAW)
        return [header.index(run_record.HORIZONTAL_CALIBRATED)]
    return rewritten(path, calibrated_column, lambda row, _: run_record.calibrated(float(row[found["raw"]]), alpha))


# load_bins.csv's columns of alpha F: its mean, least and greatest per bin.
CALIBRATED_BIN_COLUMNS = (run_record.CALIBRATED_MEAN, run_record.CALIBRATED_LEAST, run_record.CALIBRATED_GREATEST)


def rescaled_bins(path, alpha_run, alpha_new):
    """load_bins.csv's text with its three calibrated columns (mean, least, greatest F_cal) brought
    from the run's alpha_run to alpha_new [-] (times alpha_new / alpha_run)."""
    def calibrated_columns(header):
        columns = [k for k, name in enumerate(header) if name in CALIBRATED_BIN_COLUMNS]
        if len(columns) != 3:
            raise RunError(f"{path}: not the header of a load_bins.csv of `thin_ice run` ({len(columns)} calibrated "
                           "columns)")
        return columns
    return rewritten(path, calibrated_columns, lambda row, k: run_record.at_alpha(float(row[k]), alpha_run, alpha_new))


def recalibrate(run_dir, tool, alpha_new=None):
    """Returns a line saying what was done; raises RunError, leaving the run as it was."""
    summary_path, loads_path = run_record.summary_path(run_dir), os.path.join(run_dir, run_record.LOADS_FILE)
    bins_path = os.path.join(run_dir, run_record.LOAD_BINS_FILE)
    if os.path.exists(os.path.join(run_dir, run_record.LOADS_PARTIAL_FILE)):
        raise RunError("a run is still writing here (loads.csv.partial)")
    if not (os.path.exists(summary_path) and os.path.exists(bins_path)):
        raise RunError("no summary.json and load_bins.csv: not a finished run directory of `thin_ice run` (a run made "
                       "before load_bins.csv: `thin_ice analyse RUN_DIR --write-bins` writes it)")
    try:
        summary = run_record.require_summary(run_dir)
    except (OSError, json.JSONDecodeError) as e:
        raise RunError(f"{summary_path}: {e}")
    except ValueError as e:  # a layout this mirror does not know: the reason names the file
        raise RunError(str(e))
    alpha_run = check_alpha(summary.get(run_record.CALIBRATION_FACTOR), summary_path)
    if alpha_new is None:
        value, where = alpha_of_scenario(tool, run_dir, "give --alpha")
        alpha_new = check_alpha(value, where)
    elif os.path.exists(os.path.join(run_dir, run_record.CHECKPOINT_FILE)):
        # A resumed run appends rows at its scenario's alpha: the record must already be at it.
        value, where = alpha_of_scenario(
            tool, run_dir, "a run with a checkpoint.bin is rescaled only to its scenario's alpha, so the "
            "scenario must load (mend it, or remove checkpoint.bin if the run will not be resumed)")
        if alpha_new != value:
            raise RunError(f"--alpha {alpha_new:g}: the run has a checkpoint, and a resumed run writes F_cal at "
                           f"alpha = {value:g} ({where}); only that alpha is allowed here")
    if alpha_new == alpha_run:
        return f"already at alpha = {alpha_run:g}, left alone"
    # loads.csv where this directory has it (a clone keeps only the bins): F_cal = alpha F per row.
    loads_text = rescaled_loads(loads_path, alpha_new) if os.path.exists(loads_path) else None
    bins_text = rescaled_bins(bins_path, alpha_run, alpha_new)
    summary[run_record.CALIBRATION_FACTOR] = alpha_new
    summary.setdefault("recalibrations", []).append(
        {"from_alpha": alpha_run, "to_alpha": alpha_new, "by": PROG,
         "date": datetime.date.today().isoformat()})
    # The statistics of the new column, from a copy of the two files: the run stays as it was
    # until both are ready.
    with tempfile.TemporaryDirectory() as scratch:
        with open(os.path.join(scratch, run_record.LOAD_BINS_FILE), "w", newline="") as f:
            f.write(bins_text)
        with open(run_record.summary_path(scratch), "w") as f:
            f.write(summary_text(summary))
        try:
            fresh = analyse(tool, scratch)
            for field in (run_record.LOAD, run_record.EXPERIMENT):
                summary[field] = fresh[field]
        except RuntimeError as e:
            raise RunError(str(e).replace(scratch, run_dir))
    files = {bins_path: bins_text, summary_path: summary_text(summary)}
    if loads_text is not None:
        files[loads_path] = loads_text
    replace_files(files)
    return f"alpha {alpha_run:g} -> {alpha_new:g}: F_cal and its statistics worked out again"


def main(argv):
    parser = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0])
    parser.add_argument("run_dirs", nargs="+", metavar="RUN_DIR")
    parser.add_argument("--alpha", type=float, help="the new alpha [-] (default: the scenario file's)")
    parser.add_argument("--tool", help="path of the thin_ice program")
    args = parser.parse_args(argv)
    tool = args.tool or default_tool(PROG)
    status = 0
    for run_dir in args.run_dirs:
        try:
            alpha = None if args.alpha is None else check_alpha(args.alpha, "--alpha")
            print(f"{run_dir}: {recalibrate(run_dir, tool, alpha)}")
        except RunError as e:
            print(f"{PROG}: {run_dir}: {e}", file=sys.stderr)
            status = 2
    return status
