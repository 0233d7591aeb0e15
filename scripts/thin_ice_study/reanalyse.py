"""Works out the load statistics of finished run directories of `thin_ice run` again, after a change
to the statistics (load_statistics.hpp) or to the summary's "load" and "experiment" objects,
without running the simulation again. `thin_ice analyse` computes them from the run's kept record (load_bins.csv)
with the code `thin_ice run` uses at the end of a run; this script puts them into the run's
summary.json in place of the old ones and adds the date and the reason to its "reanalyses" list.
Nothing else in the run changes.

usage: scripts/study reanalyse --reason TEXT RUN_DIR [RUN_DIR...] [--tool PATH]

--tool: the thin_ice program, whose `analyse` command is used (default: the catkin build's, else
the plain CMake build's, under .ws). summary.json is written beside the old one and renamed over it. Exit status 2 when a
run cannot be analysed; the others are still done.
"""
import argparse
import datetime
import sys

from . import run_record
from .run_summary import analyse, default_tool, replace_files, summary_text

PROG = "scripts/study reanalyse"
SUMMARY = "works a finished run's load statistics out again (thin_ice analyse) after a change to them"


def reanalyse(tool, run_dir, reason):
    """Returns a line saying what changed; raises RuntimeError, leaving the run as it was."""
    fresh = analyse(tool, run_dir)
    load, experiment = fresh[run_record.LOAD], fresh[run_record.EXPERIMENT]
    summary = run_record.require_summary(run_dir)
    old = summary.get(run_record.LOAD) or {}
    summary[run_record.LOAD], summary[run_record.EXPERIMENT] = load, experiment
    summary.setdefault("reanalyses", []).append({"date": datetime.date.today().isoformat(), "why": reason})
    replace_files({run_record.summary_path(run_dir): summary_text(summary)})
    changed = [k for k in load if old.get(k) != load[k]]
    return "statistics worked out again; changed: " + (", ".join(changed) if changed else "nothing")


def main(argv):
    parser = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0])
    parser.add_argument("run_dirs", nargs="+", metavar="RUN_DIR")
    parser.add_argument("--tool", help="path of the thin_ice program")
    parser.add_argument("--reason", required=True, help="what changed in the statistics, for the run's record")
    args = parser.parse_args(argv)
    tool = args.tool or default_tool(PROG)
    status = 0
    for run_dir in args.run_dirs:
        try:
            print(f"{run_dir}: {reanalyse(tool, run_dir, args.reason)}")
        except (RuntimeError, OSError, ValueError, KeyError) as e:
            print(f"{PROG}: {run_dir}: {e}", file=sys.stderr)
            status = 2
    return status
