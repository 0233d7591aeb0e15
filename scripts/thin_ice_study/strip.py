"""Runs a scenario on a narrow strip: the fast bench for the physics (issue #31).

A full-width run (10 m sheet, structure and channel) advances 0.3-0.8 m of pushed ice per hour on
one thread once its pile has grown. A strip cuts the width (sheet, structure, channel alike) and
the sheet's length, keeping everything else: the ice, the laws, the gap between the ice front and
the toe, the false bottom's distance from the toe, the panels' width; the channel's walls become
frictionless (a symmetry boundary: the strip is a slice of a wider sheet). The loads are then compared
per metre of width (`thin_ice run` scales the experiment's figures to the structure's width).

usage: scripts/study strip SCENARIO --out DIR [--width W] [--length L] [--bin THIN_ICE]
                           [--set section.key=value]... (--until-length L | --until-time T) [other
                           `thin_ice run` arguments]
  --width   strip width [m] (default 2): sheet.width, structure.width, channel.width
  --length  sheet length [m] (default 10); structure.toe_x moves with the ice front
  --bin     the thin_ice program to use, whose `run` runs the strip (default: the catkin build's,
            else build/core's, else the device bundle's)
scripts/study strip --print-runner prints the thin_ice program it would use (for `thin_ice resume`).
scripts/study strip --resume-snapshots DIR UNTIL [the run's strip arguments] prints the --snapshots a
resumption of DIR to UNTIL (a length [m] or `end`) takes to keep the spacing of the run's own
--snapshots K over its --length: K x segment / length, at least 1; nothing without --snapshots.
Every other argument goes to `thin_ice run` unchanged. The overrides are printed before the run
and stored by `thin_ice run` in DIR/summary.json, so `thin_ice resume DIR` goes on with them.
"""
import functools
import math
import os
import re

import yaml

from . import ROOT, run_record, scenario_file
from .refusal import refuse

PROG = "scripts/study strip"
SUMMARY = "runs a scenario on a narrow strip (sheet, structure and channel cut in width): the fast bench"

RUNNER_CANDIDATES = [  # the thin_ice program of each build, in order of preference
    os.path.join(ROOT, ".ws/devel/lib/thin_ice_sim/thin_ice"),
    os.path.join(ROOT, "build/core/bin/thin_ice"),
    os.path.join(ROOT, ".ws/build_core_only/bin/thin_ice"),
    os.path.join(ROOT, ".ws/device_bundle/bin/thin_ice"),
]


fail = functools.partial(refuse, PROG)  # bad input: one line, exit status 2


def length_value(flag, text):
    """The length [m] > 0 that `text` gives for `flag`; ValueError naming both otherwise."""
    try:
        value = float(text)
    except ValueError:
        value = float("nan")
    if not (math.isfinite(value) and value > 0.0):
        raise ValueError("%s %s; allowed: a length > 0 m" % (flag, text))
    return value


def positive_number(flag, text):
    try:
        return length_value(flag, text)
    except ValueError as e:
        fail(str(e))


def strip_overrides(scenario, width, length):
    """The --set overrides that turn `scenario` (a parsed scenario file) into a strip."""
    sheet, structure = scenario["sheet"], scenario["structure"]
    x_min = float(sheet.get("x_min", 0.0))
    gap = float(structure["toe_x"]) - (x_min + float(sheet["length"]))  # ice front to toe [m]
    panel_width = float(structure["width"]) / int(structure["panels"])  # [m]
    panels = max(1, int(round(width / panel_width)))
    overrides = [
        "sheet.width=%g" % width,
        "sheet.length=%g" % length,
        "structure.width=%g" % width,
        "structure.panels=%d" % panels,
        "structure.toe_x=%.6g" % (x_min + length + gap),
    ]
    if scenario.get("channel", {}).get("enabled", False):
        # Frictionless walls: a symmetry boundary, as the strip is a slice of a wider sheet. With
        # the scenario's wall friction (0.1) the pile of a 2 m M-2 strip held 11 % more load per
        # metre over 0-2 m than at full width; without it 7 %, about the full-width seed's own
        # offset (docs/journal/phase2-campaign.md). A --set given to the strip still wins.
        overrides.append("channel.width=%g" % width)
        overrides.append("channel.friction=0")
    return overrides


def read_matrix(path):
    """The runs of a strip matrix file (config/strips/*.matrix, as scripts/strip_matrix reads it): one
    (name, scenario, arguments) per line NAME SCENARIO [ARGUMENTS...], '#' starting a comment."""
    runs = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            words = line.split("#", 1)[0].split()
            if not words:
                continue
            if len(words) < 2 or not re.fullmatch(r"[A-Za-z0-9._-]+", words[0]):
                raise ValueError("%s line %d: '%s'; allowed: NAME SCENARIO [ARGUMENTS...], NAME in letters, digits, "
                                 "'.', '_' and '-'" % (path, number, line.strip()))
            runs.append((words[0], words[1], words[2:]))
    return runs


def matrix_arguments(args):
    """A strip matrix line's arguments: (width [m], sheet length [m], --set values, snapshots K over
    the sheet's length, 0: none). A line takes --width, --length, --set and --snapshots; anything
    else raises ValueError naming it."""
    width, length, snapshots, sets = 2.0, 10.0, 0, []
    if len(args) % 2:
        raise ValueError("arguments '%s'; allowed: pairs of --width W, --length L, --set KEY=VALUE, "
                         "--snapshots K" % " ".join(args))
    for flag, value in zip(args[::2], args[1::2]):
        if flag == "--width":
            width = length_value(flag, value)
        elif flag == "--length":
            length = length_value(flag, value)
        elif flag == "--set":
            sets.append(value)
        elif flag == "--snapshots":
            if not value.isdigit():
                raise ValueError("--snapshots %s; allowed: a whole number >= 0" % value)
            snapshots = int(value)
        else:
            raise ValueError("argument %s; allowed in a matrix line: --width, --length, --set, --snapshots" % flag)
    return width, length, sets, snapshots


def matrix_run(scenario_path, args):
    """What one line of a strip matrix asks for: (overrides, snapshots K, sheet length [m]). The
    overrides are the strip's (strip_overrides) followed by the line's own --set values, which win."""
    width, length, sets, snapshots = matrix_arguments(args)
    return strip_overrides(scenario_file.load(scenario_path), width, length) + sets, snapshots, length


def default_runner():
    runner = next((c for c in RUNNER_CANDIDATES if os.access(c, os.X_OK)), None)
    if runner is None:
        fail("no thin_ice built (looked in: %s); build first or give --bin" % ", ".join(RUNNER_CANDIDATES))
    return runner


def resume_snapshots(run_dir, until, args):
    """The --snapshots argument for resuming `run_dir` to `until` (see the usage), or ""."""
    _, length, _, snapshots = matrix_arguments(args)
    if not snapshots:
        return ""
    reached = float(run_record.require_summary(run_dir)[run_record.PUSHED_LENGTH])
    return "--snapshots %d" % segment_snapshots(snapshots, length, reached, until)


def segment_snapshots(snapshots, length, reached, until):
    """Snapshots of a resumption from `reached` to `until` (a length [m] or `end`) of a run that asked
    for `snapshots` over its sheet `length` [m]: the same spacing, at least one."""
    target = length if until == "end" else float(until)  # "end": the pusher's travel, about --length
    segment = max(0.0, target - reached)
    return max(1, int(round(snapshots * segment / length)))


def main(argv):
    if len(argv) < 1 or argv[0] in ("-h", "--help"):
        print(__doc__)
        return 0 if argv else 2
    if argv == ["--print-runner"]:
        print(default_runner())
        return 0
    if argv[0] == "--resume-snapshots":
        if len(argv) < 3:
            fail("--resume-snapshots needs DIR and UNTIL")
        try:
            print(resume_snapshots(argv[1], argv[2], argv[3:]))
        except ValueError as e:
            fail(str(e))
        return 0
    scenario_path, rest = argv[0], argv[1:]
    width, length, runner, passed = 2.0, 10.0, None, []
    i = 0
    while i < len(rest):
        arg = rest[i]
        if arg in ("--width", "--length", "--bin"):
            if i + 1 >= len(rest):
                fail(arg + " needs a value")
            value = rest[i + 1]
            if arg == "--width":
                width = positive_number(arg, value)
            elif arg == "--length":
                length = positive_number(arg, value)
            else:
                runner = value
            i += 2
            continue
        passed.append(arg)
        i += 1
    try:
        scenario = scenario_file.load(scenario_path)
        overrides = strip_overrides(scenario, width, length)
    except (OSError, yaml.YAMLError, KeyError, TypeError, ValueError) as e:
        fail("cannot read the strip's geometry from %s: %s" % (scenario_path, e))
    if runner is None:
        runner = default_runner()
    command = [runner, "run", "--scenario", scenario_path]
    for o in overrides:
        command += ["--set", o]
    # The caller's own overrides come last, so that they win over the strip's.
    command += passed
    print("[strip] " + " ".join(command), flush=True)
    # The runner takes this process's place, so that a signal (a wall budget's SIGTERM) reaches it
    # and it writes what it reached.
    os.execv(runner, command)
