#!/usr/bin/python3
"""scripts/thin_ice_study/run_summary.py's replace_files: the files are replaced together after all
of them were written, and a failure while writing leaves the old files as they were and no .new
file behind.

    test_replace_files.py SOURCE_DIR
"""
import os
import sys
import tempfile


def main():
    sys.path.insert(0, os.path.join(sys.argv[1], "scripts"))
    from thin_ice_study.run_summary import replace_files

    failures = []
    with tempfile.TemporaryDirectory() as d:
        first, second = os.path.join(d, "loads.csv"), os.path.join(d, "summary.json")
        for path in (first, second):
            with open(path, "w") as f:
                f.write("old " + os.path.basename(path))
        replace_files({first: "new loads", second: "new summary"})
        for path, text in ((first, "new loads"), (second, "new summary")):
            if open(path).read() != text:
                failures.append(f"after a good replace, {os.path.basename(path)} holds {open(path).read()!r}")

        # The second target's folder does not exist: its .new cannot be opened.
        missing = os.path.join(d, "no_such_folder", "summary.json")
        try:
            replace_files({first: "newer loads", missing: "newer summary"})
            failures.append("a write into a missing folder raised nothing")
        except OSError:
            pass
        if open(first).read() != "new loads":
            failures.append(f"a failed replace changed loads.csv to {open(first).read()!r}")
        left = sorted(n for n in os.listdir(d) if n.endswith(".new"))
        if left:
            failures.append(f"a failed replace left {left}")
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("OK: replace_files writes all, then renames; a failed write changes nothing and leaves no .new")


if __name__ == "__main__":
    main()
