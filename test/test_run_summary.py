#!/usr/bin/python3
"""The summary.json of `thin_ice run` records the structure and false-bottom geometry the run used,
with the run's --set overrides applied, so that readers of a run need not re-read the scenario
file, and the host instruction set the build was compiled for; a summary of a layout newer than
this thin_ice's (schema_version) is refused by analyse and resume.

    test_run_summary.py THIN_ICE SOURCE_DIR   (THIN_ICE: the thin_ice program)
"""
import json
import os
import subprocess
import sys
import tempfile


def main():
    thin_ice, source = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as out:
        # quick.yaml has toe_x 3.3 m, 60 deg, 1 m wide, 1 m high, 2 panels, bottom 0.25 m deep; three
        # of them overridden here, two left as the file gives them.
        cmd = [thin_ice, "run", "--scenario", os.path.join(source, "config/scenarios/quick.yaml"), "--until-time", "0.02",
               "--set", "structure.angle_deg=45", "--set", "structure.toe_x=3.4", "--set", "bottom.depth=0.3",
               "--out", out]
        done = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=300)
        if done.returncode != 0:
            sys.exit(f"FAIL: exit status {done.returncode}: {done.stderr.strip()}")
        summary = json.load(open(os.path.join(out, "summary.json")))
        expected = {("structure", "toe_x_m"): 3.4, ("structure", "angle_deg"): 45.0,
                    ("structure", "width_m"): 1.0, ("structure", "height_m"): 1.0, ("structure", "panels"): 2,
                    ("false_bottom", "depth_m"): 0.3, ("false_bottom", "distance_from_structure_m"): 1.0}
        failures = []
        for (section, key), value in expected.items():
            got = (summary.get(section) or {}).get(key)
            if got is None or abs(got - value) > 1e-12:
                failures.append(f"{section}.{key} = {got}, expected {value}")
        # The host instruction set of the build (CMake's THIN_ICE_CPU_LEVEL): "baseline" or a -march name.
        level = summary.get("cpu_instruction_set")
        if not isinstance(level, str) or not level or " " in level:
            failures.append(f"cpu_instruction_set = {level!r}, expected 'baseline' or a -march name")
        # A summary of a layout this thin_ice does not know (schema_version above its own) is refused
        # by its readers, analyse and resume alike, in one line naming the field: exit status 2.
        if summary.get("schema_version") != 1:
            failures.append(f"schema_version = {summary.get('schema_version')!r}, expected 1")
        summary["schema_version"] = 2
        with open(os.path.join(out, "summary.json"), "w") as f:
            json.dump(summary, f)
        for args in (["analyse", out], ["resume", out, "--until-time", "0.04"]):
            done = subprocess.run([thin_ice] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                  timeout=300)
            lines = done.stderr.strip().splitlines()
            if done.returncode != 2 or len(lines) != 1 or '"schema_version" is 2; allowed: a whole number from 1 to 1 (a record of a newer' not in lines[0]:
                failures.append(f"thin_ice {args[0]} of schema_version 2: exit status {done.returncode}, "
                                f"stderr {done.stderr.strip()!r}")
        if failures:
            sys.exit("FAIL: " + "; ".join(failures))
        print(f"OK: structure and false bottom recorded with the overrides applied; built for {level}; "
              "a summary of an unknown layout refused")


if __name__ == "__main__":
    main()
