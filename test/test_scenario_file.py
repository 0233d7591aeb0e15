#!/usr/bin/python3
"""scripts/thin_ice_study/scenario_file.py reads a scenario's base chain as the C++ loader does: a
file's keys over its base's, a cycle, an empty base or a file that is not a map refused, and every
shipped series merged to the full set of sections with its own ice.

    test_scenario_file.py SOURCE_DIR
"""
import os
import sys
import tempfile


def main():
    source = sys.argv[1]
    sys.path.insert(0, os.path.join(source, "scripts"))
    from thin_ice_study import scenario_file

    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        def write(name, text):
            with open(os.path.join(tmp, name), "w") as f:
                f.write(text)
            return os.path.join(tmp, name)

        write("a.yaml", "ice:\n  thickness: 0.05\n  density: 900\nsheet:\n  seed: 1\n")
        write("b.yaml", "base: a.yaml\nice:\n  density: 910\n")
        merged = scenario_file.load(write("c.yaml", "base: b.yaml\nsheet:\n  seed: 3\n"))
        if merged.get("ice") != {"thickness": 0.05, "density": 910} or merged.get("sheet") != {"seed": 3}:
            failures.append(f"chain a <- b <- c merged to {merged}")
        write("x.yaml", "base: y.yaml\n")
        write("y.yaml", "base: x.yaml\n")
        for name, text, needle in (("x.yaml", None, "cycle"), ("empty.yaml", "base: ''\n", "base"),
                                   ("list.yaml", "- 1\n- 2\n", "map of sections")):
            path = os.path.join(tmp, name) if text is None else write(name, text)
            try:
                scenario_file.load(path)
                failures.append(f"{name}: no error")
            except ValueError as e:
                if needle not in str(e):
                    failures.append(f"{name}: {e} (expected '{needle}')")
    for series in ("W-1", "W-2", "W-3", "M-1", "M-2", "S-1", "S-2"):
        s = scenario_file.load(os.path.join(source, "config/scenarios", series + ".yaml"))
        for section in ("ice", "sheet", "water", "bottom", "structure", "pusher", "channel", "numerics"):
            if section not in s:
                failures.append(f"{series}: no section {section} after its bases")
        if "thickness" not in s.get("ice", {}) or "time_step" not in s.get("numerics", {}):
            failures.append(f"{series}: its ice or its type's time step is missing")
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("scenario_file: chains, refusals and the seven series as expected")


if __name__ == "__main__":
    main()
