"""Writes docs/validation.md from the runs of the scenarios as they stand (docs/validation/strips/
and docs/validation/full/, each run's summary.json and kept record load_bins.csv): the table of
every series of Table 5 against Table 6 (phase2_table), the seed spread and the strip-against-
full-width check, issue #31's targets judged over those runs, the runs at another water depth over
the false bottom beside their series' (depth_table), one figure of every run's load, and,
taken in as they are, two hand-written files in the runs folder: phase2_why.md (why the loads
miss, as far as the runs show it) under the table, and bench.md (how the runs are made and how far
a strip stands for the full width) after the figure. Only what the runs measured is reported; a
series without a run is listed as not run. The runs' history is in docs/journal/:
phase2-campaign.md (the readings and every run since) and validation-before-phase2.md.

  scripts/study validation_report --runs docs/validation --out docs/validation.md
Exit status: 0 written; 2 bad input (the old report left as it was); 3 no run of Table 5's series
in the folder (nothing to report, the old report left as it was).
"""
import functools
import argparse
import datetime
import json
import os
import subprocess

from .experiments import ALPHA, PEAK, STEADY_MEAN, STRUCTURE_WIDTH
from .phase2_plot import SMOOTHING, draw
from .depth_table import depth_table
from .phase2_table import SERIES, phase2_table, runs_of, targets
from . import run_record
from .run_record import LOAD_BIN_LENGTH
from .refusal import refuse

PROG = "scripts/study validation_report"
SUMMARY = "writes docs/validation.md from the runs of the scenarios as they stand in docs/validation/"
FIGURE = "phase2_loads.png"  # in the runs folder
NOTHING_TO_REPORT = 3  # exit status where the runs folder holds no run of Table 5's series


fail = functools.partial(refuse, PROG)  # bad input: one line, exit status 2


def runs_date(root):
    """The date (YYYY-MM-DD) the table stands for: the day of the last commit that changed the runs
    under `root` (strips/, full/), or today where some of them are not committed yet (validate
    writes the report before the runs it copied are committed); None outside a git checkout (a
    folder of runs made elsewhere)."""
    def git(*args):
        try:
            done = subprocess.run(["git", "-C", root] + list(args), stdout=subprocess.PIPE,
                                  stderr=subprocess.DEVNULL, text=True, timeout=60)
        except (OSError, subprocess.SubprocessError):
            return None
        return done.stdout.strip() if done.returncode == 0 else None
    changed = git("status", "--porcelain", "--", "strips", "full")
    if changed is None:
        return None
    if changed:
        return datetime.date.today().isoformat()
    return git("log", "-1", "--format=%cs", "--", "strips", "full") or None


def hand_written(path):
    """The lines of a hand-written Markdown file kept beside the runs, as it is ([] when there is none)."""
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [f.read().rstrip(), ""]


def check_runs(root):
    """Ends the script (exit status 2) where the runs folder holds no run, or a summary that is not one
    of `thin_ice run`: the report would say what was not measured."""
    found = 0
    for series in SERIES:
        for _, path in runs_of(root, series):
            summary_path = run_record.summary_path(path)
            try:
                summary = run_record.require_summary(path)
            except json.JSONDecodeError as e:
                fail(f"{summary_path} is not JSON ({e}); allowed: a summary.json of `thin_ice run`")
            except ValueError as e:  # a layout this mirror does not know: the reason names the file
                fail(str(e))
            if not isinstance(summary, dict) or not isinstance(summary.get(run_record.LOAD), dict):
                fail(f"{summary_path} has no \"load\" object; allowed: a summary.json of `thin_ice run`")
            if not os.path.exists(os.path.join(path, run_record.LOAD_BINS_FILE)):
                fail(f"{path} has no load_bins.csv (a run made before it: `thin_ice analyse {path} --write-bins` "
                     "writes it from its loads.csv)")
            found += 1
    if not found:
        refuse(PROG, f"--runs {root} holds no run of Table 5's series (no {root}/strips/ID-sK or {root}/full/ID with "
               "a summary.json): nothing to report; the report is left as it was", NOTHING_TO_REPORT)


def main(argv):
    p = argparse.ArgumentParser(prog=PROG, description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--runs", required=True)
    p.add_argument("--out", required=True)
    a = p.parse_args(argv)
    if not os.path.isdir(a.runs):
        fail(f"--runs {a.runs}: no such folder; allowed: the folder of run folders (docs/validation)")
    if not a.out.endswith(".md") or not os.path.isdir(os.path.dirname(os.path.abspath(a.out))):
        fail(f"--out {a.out}: allowed: a .md file in an existing folder")
    check_runs(a.runs)
    rel = os.path.relpath(a.runs, os.path.dirname(os.path.abspath(a.out)))
    date = runs_date(a.runs)
    lines = ["# Validation against the shallow-water experiments", "",
             "Regenerated by `scripts/study validate` from the runs in docs/validation/strips/ and",
             "docs/validation/full/ (each run's summary.json and its kept record, load_bins.csv). Experiment:",
             "Lemström and Polojärvi's model-scale tests, paper Tables 4-6. Loads are the calibrated horizontal",
             f"load alpha F (Eq. 18) with the paper's alpha = {ALPHA:g}, per metre of structure width, so that a 2 m",
             "strip and the 10 m structure compare directly; the raw load is beside it. A run's statistics are",
             f"worked out on its record in bins of {1000 * LOAD_BIN_LENGTH:.0f} mm of pushed ice (the paper's output "
             "step), the peak from the", "greatest 0.01 s row. The steady state is found by the rule written in",
             "`include/thin_ice_sim/study/load_statistics.hpp`; where the rule finds none, the mean of the last",
             "quarter of the record is shown and marked \"tail mean, not steady\": that is not a steady-state",
             "load, and nothing is judged on it. The phase-1 slope is the least-squares slope of alpha F against L",
             "from the end of the first failure's collapse to the start of the steady window.", "",
             "## Every series at the scenarios' reading" + (f" (the runs as they stood on {date})" if date else ""), "",
             "2 m strips (sheet, structure, panels and channel 2 m wide, walls frictionless;",
             "config/strips/validation.matrix and seeds.matrix, a 31 m sheet so that the experiments' lengths",
             "fit, and two W-3 strips of a 14 m sheet) and full-width runs. Runs in progress are shown as far",
             "as they got, with the experiment's pushed length in brackets.", ""]
    lines += phase2_table(a.runs)
    lines.append("")
    lines += targets(a.runs)
    lines += hand_written(os.path.join(a.runs, "phase2_why.md"))
    depth = depth_table(a.runs)
    if depth:
        lines += ["## The water depth over the false bottom", "",
                  "Not in the paper; the scenarios set it (config/scenarios/base/tank.yaml). The strips run at",
                  "another depth (config/strips/bottom-depth.matrix) beside those of the same series at the",
                  "scenarios' depth, alpha F per metre of width over the same spans of pushed ice (a span where",
                  "the run has pushed past its end), and the window the steady-state rule found at the run's end:", ""]
        lines += depth + [""]
    experiment = {sid: (STEADY_MEAN[sid[0]] / STRUCTURE_WIDTH, PEAK[sid[0]] / STRUCTURE_WIDTH) for sid in SERIES}
    if draw(a.runs, os.path.join(a.runs, FIGURE), experiment):
        lines += ["## The loads", "",
                  f"Every run above, alpha F per metre of width averaged over {SMOOTHING:g} m of pushed ice, with the",
                  "experiment's steady mean (dashed) and peak (dotted):", "",
                  f"![Every run at the scenarios' reading]({rel}/{FIGURE})", ""]
    else:
        lines += ["(No figure: matplotlib is missing.)", ""]
    lines += hand_written(os.path.join(a.runs, "bench.md"))
    lines += ["## Records and history", "",
              f"Which files of each run the repository keeps, and why: [records.md]({rel}/records.md). How",
              "the reading was chosen and every run since, as written run by run: docs/journal/phase2-campaign.md.",
              "The validation of the reading before phase 2, its tables and the dated calibration notes:",
              "docs/journal/validation-before-phase2.md and docs/journal/calibration.md.", ""]
    path = a.out
    with open(path + ".partial", "w") as f:
        f.write("\n".join(lines))
    os.replace(path + ".partial", path)

