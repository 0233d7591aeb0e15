#!/usr/bin/python3
"""The one program's dispatch: `thin_ice` alone prints its commands on stderr (exit status 2),
`thin_ice --help` (or `help`, `-h`) on stdout (0), and an unknown command or probe is one line
naming those allowed (2); every command and probe answers --help with its own usage (0), and
`thin_ice resume` without a run directory first is one line (2); `thin_ice parameters` prints a
scenario's resolved parameters as a scenario file that loads back to the same text, E_v by its rule or as stated (0), and a bad
argument or value is one line (2).

    test_command_line.py THIN_ICE   (THIN_ICE: the thin_ice program)
"""
import os
import subprocess
import sys
import tempfile

COMMANDS = ["run", "resume", "sheet", "analyse", "parameters", "probe"]
PROBES = ["edge-check", "edge-balance", "bond-offset", "profiles"]


def call(args):
    return subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=60)


def listed(text, names):
    """Whether each of `names` begins a line of the list in `text`."""
    starts = {line.split()[0] for line in text.splitlines() if line.startswith("  ") and line.split()}
    return all(name in starts for name in names)


def main():
    thin_ice = sys.argv[1]
    failures = []

    def expect(args, code, stdout_check=None, stderr_check=None, what=""):
        done = call([thin_ice] + args)
        problem = done.returncode != code
        problem = problem or (stdout_check is not None and not stdout_check(done.stdout))
        problem = problem or (stderr_check is not None and not stderr_check(done.stderr))
        if problem:
            failures.append(f"thin_ice {' '.join(args)} ({what}): exit status {done.returncode} (expected {code}), "
                            f"stdout {done.stdout[:300]!r}, stderr {done.stderr[:300]!r}")

    def one_line(expected):
        return lambda err: err.splitlines() == [expected]

    expect([], 2, lambda out: out == "", lambda err: listed(err, COMMANDS), "the list on stderr")
    for flag in ("--help", "-h", "help"):
        expect([flag], 0, lambda out: listed(out, COMMANDS), lambda err: err == "", "the list on stdout")
    expect(["bogus"], 2, lambda out: out == "",
           one_line("thin_ice: unknown command 'bogus'; allowed: " + " ".join(COMMANDS)), "an unknown command")
    # The old programs' names are no commands.
    expect(["thin_ice_run"], 2, None,
           one_line("thin_ice: unknown command 'thin_ice_run'; allowed: " + " ".join(COMMANDS)), "an old name")
    expect(["probe"], 2, lambda out: out == "", lambda err: listed(err, PROBES), "the probes on stderr")
    expect(["probe", "--help"], 0, lambda out: listed(out, PROBES), None, "the probes on stdout")
    expect(["probe", "bogus"], 2, lambda out: out == "",
           one_line("thin_ice probe: unknown probe 'bogus'; allowed: " + " ".join(PROBES)), "an unknown probe")
    expect(["resume"], 2, lambda out: out == "",
           lambda err: len(err.splitlines()) == 1 and err.startswith("thin_ice resume: "), "no run directory")
    expect(["resume", "--until-time", "1"], 2, None,
           lambda err: len(err.splitlines()) == 1 and err.startswith("thin_ice resume: "), "a flag first")
    # Each command's own usage names it as it is called now.
    for args, usage in ((["run"], "usage: thin_ice run "), (["resume"], "usage: thin_ice run "),
                        (["sheet"], "usage: thin_ice sheet "), (["analyse"], "usage: thin_ice analyse "),
                        (["parameters"], "usage: thin_ice parameters ")) + tuple(
                            (["probe", p], f"usage: thin_ice probe {p} ") for p in PROBES):
        expect(args + ["--help"], 0, lambda out, usage=usage: out.startswith(usage), None, "its usage")
    # thin_ice parameters: quick.yaml as resolved (M-2's ice on a strip), printed as a scenario file
    # that, loaded again, prints the same parameters; E_v worked out by its rule when asked.
    quick = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "config", "scenarios", "quick.yaml")
    printed = call([thin_ice, "parameters", "--scenario", quick, "--set", "sheet.seed=3"])
    lines = printed.stdout.splitlines()
    if printed.returncode != 0 or "  vertical_modulus_floating_plate_multiple: 4" not in lines or \
            "  seed: 3" not in lines or "  thickness: 0.051" not in lines or \
            not any(line.startswith("  vertical_modulus: 12749") for line in lines):
        failures.append(f"thin_ice parameters quick.yaml: exit status {printed.returncode}, stdout {printed.stdout[:300]!r}")
    else:
        with tempfile.TemporaryDirectory() as tmp:
            resolved = os.path.join(tmp, "resolved.yaml")
            with open(resolved, "w") as f:
                f.write(printed.stdout)
            again = call([thin_ice, "parameters", "--scenario", resolved])
            if again.returncode != 0 or again.stdout.splitlines()[1:] != lines[1:]:
                failures.append(f"the printed parameters loaded again: exit status {again.returncode}, "
                                f"{again.stdout[:200]!r}, differs: {again.stdout.splitlines()[1:] != lines[1:]}")
    stated = call([thin_ice, "parameters", "--scenario", quick, "--set", "ice.vertical_modulus=1.276e6"])
    if stated.returncode != 0 or "  vertical_modulus: 1276000" not in stated.stdout.splitlines() or \
            "vertical_modulus_floating_plate_multiple" in stated.stdout:
        failures.append(f"thin_ice parameters with E_v stated: exit status {stated.returncode}, {stated.stdout[:300]!r}")
    expect(["parameters", "--scenario", quick, "--set", "ice.thickness=-1"], 2, lambda out: out == "",
           lambda err: len(err.splitlines()) == 1 and "ice.thickness" in err, "a value out of range")
    expect(["parameters", "--scenario", quick, "--until-time", "1"], 2, lambda out: out == "",
           lambda err: err.startswith("thin_ice parameters: unexpected argument '--until-time'"), "a run's flag")
    expect(["parameters"], 2, lambda out: out == "",
           lambda err: err.startswith("thin_ice parameters: --scenario FILE is required"), "no scenario")
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("OK: the commands and probes listed and dispatched, unknown names refused in one line, each usage as called")


if __name__ == "__main__":
    main()
