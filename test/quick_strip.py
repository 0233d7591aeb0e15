"""The quick strip shared by the Python tests of thin_ice_run and its tools: config/scenarios/quick.yaml
cut to a 1 m strip 0.1 m from the structure, which meets the structure after about 0.27 s and
breaks bonds by 0.4 s, within seconds of wall time."""
import os
import subprocess
import sys

STRIP_OVERRIDES = ["--set", "sheet.length=1.0", "--set", "structure.toe_x=1.1",
                   "--set", "bottom.distance_from_structure=0.5"]


def strip_scenario(source):
    """thin_ice_run arguments that select the quick strip; source: the package's source folder."""
    return ["--scenario", os.path.join(source, "config/scenarios/quick.yaml")] + STRIP_OVERRIDES


def run_or_fail(cmd, what="thin_ice_run"):
    """Runs cmd; a non-zero exit ends the test with FAIL, the exit status and the tool's stderr."""
    done = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=300)
    if done.returncode != 0:
        sys.exit(f"FAIL: {what} exit status {done.returncode}: {done.stderr.strip()}")
    return done
