#!/usr/bin/python3
"""scripts/study plot_side_view draws a run's last snapshot (or a named one) and refuses bad input with
one message naming it.

    test_plot_side_view.py THIN_ICE SOURCE_DIR   (THIN_ICE: the thin_ice program)
"""
import os
import sys
import tempfile

from quick_strip import refusal_problem, run_or_fail, strip_scenario


def main():
    thin_ice, source = sys.argv[1], sys.argv[2]
    script = [os.path.join(source, "scripts", "study"), "plot_side_view"]
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        run = os.path.join(tmp, "run")
        run_or_fail([thin_ice, "run"] + strip_scenario(source) + ["--until-time", "0.4", "--snapshots", "2", "--out", run])
        out = os.path.join(tmp, "side.png")
        done = run_or_fail(script + [run, out], "plot_side_view")
        # The strip has 1 m x 1 m of 0.2 m cells in quick.yaml; its last snapshot is at t = 0.4 s.
        if not os.path.getsize(out) > 10000:
            failures.append(f"{out} is {os.path.getsize(out)} bytes")
        if "L = " not in done.stdout or "cells drawn" not in done.stdout:
            failures.append(f"unexpected report: {done.stdout.strip()!r}")
        # A run folder without snapshots (docs/validation/ keeps none), and outputs that cannot be written.
        bare = os.path.join(tmp, "bare")
        os.makedirs(bare)
        with open(os.path.join(run, "summary.json")) as f, open(os.path.join(bare, "summary.json"), "w") as g:
            g.write(f.read())
        for args, needle in (([run, out, "--snapshot", "cells_999999.csv"], "cells_999999.csv"),
                             ([run, out, "--reach", "-1"], "--reach -1"),
                             ([bare, out], "no snapshots/index.csv"),
                             ([os.path.join(tmp, "none"), out], "cannot read summary.json"),
                             ([run, os.path.join(tmp, "no_folder", "side.png")], "no_folder"),
                             ([run, os.path.join(tmp, "side.pgn")], "ending in .png")):
            problem = refusal_problem(script + args, needle)
            if problem:
                failures.append(f"{args}: {problem}")
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("OK: plot_side_view draws the last snapshot and names bad input in one line")


if __name__ == "__main__":
    main()
