#!/usr/bin/python3
"""scripts/study, the one entry point of the Python tools: its list is every module of
scripts/thin_ice_study with a main() and no library module, each listed command runs (its own
--help, exit 0, naming itself as `scripts/study COMMAND`), and no command or an unknown one gets
the list or one line naming it, with exit status 2.

    test_study_entry.py SOURCE_DIR
"""
import ast
import os
import subprocess
import sys


def run(study, *args):
    return subprocess.run(["/usr/bin/python3", study, *args], capture_output=True, text=True, timeout=120)


def main():
    source = sys.argv[1]
    study = os.path.join(source, "scripts", "study")
    package = os.path.join(source, "scripts", "thin_ice_study")
    failures = []

    # What the list must hold, worked out here from the package's files independently of the
    # entry point's own reading: modules defining main() at their top level.
    expected = set()
    for name in os.listdir(package):
        stem, extension = os.path.splitext(name)
        if extension == ".py" and not stem.startswith("_"):
            with open(os.path.join(package, name)) as f:
                if any(isinstance(n, ast.FunctionDef) and n.name == "main" for n in ast.parse(f.read()).body):
                    expected.add(stem)
    for must in ("strip", "strip_table", "validate", "ice_layers", "plot"):
        if must not in expected:
            failures.append(f"{must} has no main() in the package")
    for library in ("run_record", "run_summary", "scenario_file", "png_output"):
        if library in expected:
            failures.append(f"the library module {library} has a main()")

    listing = run(study, "--help")
    listed = {line.split()[0] for line in listing.stdout.splitlines()[6:] if line.startswith("  ")}
    if listing.returncode != 0 or listed != expected:
        failures.append(f"--help: exit {listing.returncode}, listed {sorted(listed)}, expected {sorted(expected)}")
    bare = run(study)
    if bare.returncode != 2 or bare.stdout != listing.stdout:
        failures.append(f"no command: exit {bare.returncode} (expected 2 and the list)")
    unknown = run(study, "no_such_tool")
    if (unknown.returncode != 2 or len(unknown.stderr.strip().splitlines()) != 1
            or "'no_such_tool'" not in unknown.stderr or "strip_table" not in unknown.stderr):
        failures.append(f"unknown command: exit {unknown.returncode}, stderr {unknown.stderr!r}")
    library = run(study, "run_summary")
    if library.returncode != 2:
        failures.append(f"a library module run as a command: exit {library.returncode}")

    # Every command answers --help under its own name (record_loads needs a ROS master only to run).
    for command in sorted(expected):
        help_run = run(study, command, "--help")
        if command == "count_test_results":
            ok = help_run.returncode == 2 and f"scripts/study {command}" in help_run.stderr
        else:
            ok = help_run.returncode == 0 and f"scripts/study {command}" in help_run.stdout
        if not ok:
            failures.append(f"{command} --help: exit {help_run.returncode}, "
                            f"{(help_run.stdout + help_run.stderr).strip()[:200]!r}")

    for f in failures:
        print("FAIL:", f)
    if failures:
        return 1
    print(f"OK: scripts/study lists the {len(expected)} commands of the package and no library, each answers "
          "--help under its own name, and no command or an unknown one exits 2")
    return 0


if __name__ == "__main__":
    sys.exit(main())
