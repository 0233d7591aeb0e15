#!/usr/bin/python3
"""scripts/study plot_side_view draws a run's last snapshot (or a named one), with the rubble profiles
that `thin_ice probe profiles` wrote of it over the cells when asked, and refuses bad input with
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
        # The same snapshot with its rubble profiles drawn over it (the file thin_ice probe profiles writes).
        profiles = os.path.join(tmp, "profiles.csv")
        run_or_fail([thin_ice, "probe", "profiles", run, "--out", profiles], "probe profiles")
        with_profiles = os.path.join(tmp, "side_profiles.png")
        run_or_fail(script + [run, with_profiles, "--profiles", profiles], "plot_side_view --profiles")
        if not os.path.getsize(with_profiles) > 10000:
            failures.append(f"{with_profiles} is {os.path.getsize(with_profiles)} bytes")
        not_profiles = os.path.join(tmp, "not_profiles.csv")
        with open(not_profiles, "w") as f:
            f.write("x,y\n1,2\n")
        bad_row = os.path.join(tmp, "bad_row.csv")
        with open(bad_row, "w") as f:
            f.write("profile,coordinate_m,value_m\nside,24.1,0.2\nfront,1,2\n")
        # A run folder without snapshots (docs/validation/ keeps none), and outputs that cannot be written.
        bare = os.path.join(tmp, "bare")
        os.makedirs(bare)
        with open(os.path.join(run, "summary.json")) as f, open(os.path.join(bare, "summary.json"), "w") as g:
            g.write(f.read())
        for args, needle in (([run, out, "--snapshot", "cells_999999.csv"], "cells_999999.csv"),
                             ([run, out, "--reach", "-1"], "--reach -1"),
                             ([run, out, "--profiles", not_profiles], "header"),
                             ([run, out, "--profiles", bad_row], "line 3"),
                             ([run, out, "--profiles", os.path.join(tmp, "none.csv")], "none.csv"),
                             ([bare, out], "no snapshots/index.csv"),
                             ([os.path.join(tmp, "none"), out], "cannot read summary.json"),
                             ([run, os.path.join(tmp, "no_folder", "side.png")], "no_folder"),
                             ([run, os.path.join(tmp, "side.pgn")], "ending in .png")):
            problem = refusal_problem(script + args, needle)
            if problem:
                failures.append(f"{args}: {problem}")
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("OK: plot_side_view draws the last snapshot, with and without its profiles, and names bad input in one line")


if __name__ == "__main__":
    main()
