#!/usr/bin/python3
"""The summary.json of `thin_ice run` records the structure and false-bottom geometry the run used,
with the run's --set overrides applied, so that readers of a run need not re-read the scenario
file, and the host instruction set the build was compiled for.

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
        if failures:
            sys.exit("FAIL: " + "; ".join(failures))
        print(f"OK: structure and false bottom recorded with the overrides applied; built for {level}")


if __name__ == "__main__":
    main()
