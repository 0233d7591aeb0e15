"""Shared by the Python tests of `thin_ice run` and the other commands: the quick strip
(config/scenarios/quick.yaml cut to a 1 m strip 0.1 m from the structure, which meets the structure
after about 0.27 s and breaks bonds by 0.4 s, within seconds of wall time), running a command, and
the check that a command refuses bad input with one message naming it."""
import os
import subprocess
import sys

STRIP_OVERRIDES = ["--set", "sheet.length=1.0", "--set", "structure.toe_x=1.1",
                   "--set", "bottom.distance_from_structure=0.5"]


def strip_scenario(source):
    """`thin_ice run` arguments that select the quick strip; source: the package's source folder."""
    return ["--scenario", os.path.join(source, "config/scenarios/quick.yaml")] + STRIP_OVERRIDES


def run_or_fail(cmd, what="thin_ice run"):
    """Runs cmd; a non-zero exit ends the test with FAIL, the exit status and the tool's stderr."""
    done = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=300)
    if done.returncode != 0:
        sys.exit(f"FAIL: {what} exit status {done.returncode}: {done.stderr.strip()}")
    return done


def refusal_problem(cmd, needle):
    """None when cmd fails with exactly one line on stderr that names `needle` (the project's rule
    for bad input); otherwise what it did instead."""
    done = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=120)
    lines = done.stderr.strip().splitlines()
    if done.returncode != 0 and len(lines) == 1 and needle in lines[0]:
        return None
    return f"exit status {done.returncode}, stderr {done.stderr.strip()!r}"
