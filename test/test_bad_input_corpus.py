#!/usr/bin/python3
"""The project's corpus of bad input for `thin_ice run` (and `thin_ice resume`): the classes an
outside tester tried, written as cases generated from config/scenarios/quick.yaml and a
list by hand.
Each case asserts exit status 2, one error line (starting "thin_ice run:", followed at most by
the usage text) that names the key, file or argument at fault, and that nothing was written: the
--out directory of a refused run does not exist afterwards, and a directory it may not touch is
left byte for byte as it was.

Classes: every numeric key of quick.yaml set to a huge, a negative huge, a non-finite and a
non-numeric value, a list, and a map; the enumerations and flags set to values they do not take;
unknown, misspelt and retired keys; values each in range that together make no scenario (ice that
sinks, cells smaller than the thickness, a toe behind the front, an unstable time step); files
that are no scenario (missing, a folder, a device, too large, binary, empty, two YAML documents,
a list, a duplicate key, a required key missing, a quoted number); and command lines that ask for
nothing sensible.

    test_bad_input_corpus.py THIN_ICE SOURCE_DIR   (THIN_ICE: the thin_ice program)
"""
import hashlib
import os
import subprocess
import sys
import tempfile

import yaml

MIN_CASES = 100


def numeric_keys(scenario):
    """(section.key, value) of every number in the scenario, booleans left out."""
    keys = []
    for section, fields in scenario.items():
        if not isinstance(fields, dict):
            continue
        for key, value in fields.items():
            if isinstance(value, (int, float)) and not isinstance(value, bool):
                keys.append(f"{section}.{key}")
    return keys


def file_digest(folder):
    """Every file under `folder` with its SHA-256, to tell that nothing changed."""
    out = {}
    for root, _, files in os.walk(folder):
        for name in files:
            path = os.path.join(root, name)
            with open(path, "rb") as f:
                out[os.path.relpath(path, folder)] = hashlib.sha256(f.read()).hexdigest()
    return out


def check(command, args, needle, out_dir, untouched=None):
    """None when `command` (thin_ice run or thin_ice resume) refused `args` as the corpus asks;
    otherwise what went wrong."""
    before = file_digest(untouched) if untouched else None
    try:
        done = subprocess.run(command + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                              errors="replace", timeout=60)
    except subprocess.TimeoutExpired:
        return "did not end within 60 s"
    lines = done.stderr.strip().splitlines()
    errors = [line for line in lines if line.startswith("thin_ice run:")]
    usage = lines[1:] if len(lines) > 1 else []
    if done.returncode != 2:
        return f"exit status {done.returncode} (expected 2), stderr {done.stderr.strip()[-300:]!r}"
    if len(errors) != 1 or lines[0] != errors[0] or (usage and not usage[0].startswith("usage:")):
        return f"not one error line (then at most the usage): {done.stderr.strip()[:400]!r}"
    if needle not in errors[0]:
        return f"the line does not name {needle!r}: {errors[0]!r}"
    if any(ord(c) < 0x20 or ord(c) > 0x7e for c in errors[0]):
        return f"the line holds unprintable characters: {errors[0]!r}"
    if out_dir and os.path.exists(out_dir):
        return f"a refused run created {out_dir}"
    if untouched and file_digest(untouched) != before:
        return f"a refused run changed {untouched}"
    return None


def main():
    thin_ice, source = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    run = [thin_ice, "run"]
    quick = os.path.join(source, "config/scenarios/quick.yaml")
    with open(quick) as f:
        text = f.read()
    scenario = yaml.safe_load(text)
    failures, count = [], 0
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "out")
        base = ["--scenario", quick, "--until-time", "0.01", "--out", out]

        def case(args, needle, untouched=None, out_dir=out, command=run):
            nonlocal count
            count += 1
            problem = check(command, args, needle, out_dir, untouched)
            if problem:
                failures.append(f"{' '.join(a if len(a) < 60 else a[:57] + '...' for a in args)}: {problem}")

        # 1. Every numeric key: values no physical range holds, and values that are no number.
        for key in numeric_keys(scenario):
            for value in ("1e300", "-1e300", ".nan", ".inf", "-.inf", "abc", "[1, 2]", "{a: 1}"):
                case(base + ["--set", f"{key}={value}"], key)
        # 2. Enumerations and flags.
        for key, value in (("sheet.layout", "hexagonal"), ("sheet.layout", "'jittered_grid'"),
                           ("bottom.enabled", "2"), ("channel.enabled", "yes please"),
                           ("sheet.seed", "-1"), ("sheet.seed", "0x10")):
            case(base + ["--set", f"{key}={value}"], key)
        # 3. Keys that do not exist, or no longer do.
        for setting, needle in (("ice.thicknes=0.05", "thicknes"), ("icee.thickness=0.05", "icee"),
                                ("ice.contact_face=h", "ice.contact_face"),
                                ("ice.vertical_contact_depth=shallower", "ice.vertical_contact_depth"),
                                ("ice.failure_compression=strength", "ice.failure_compression"),
                                ("ice.bond_smoothing=strength", "ice.bond_smoothing"),
                                ("ice.plate_bending=true", "ice.plate_bending"),
                                ("ice.curvature_failure=true", "ice.curvature_failure"),
                                ("ice.vertical_stress=bending", "ice.vertical_stress"),
                                ("ice.vertical_slip_friction=edge_face", "ice.vertical_slip_friction"),
                                ("thickness=0.05", "thickness=0.05"), ("ice.=1", "ice.=1")):
            case(base + ["--set", setting], needle)
        # 4. Values in range that together make no scenario: the line names a key involved.
        for settings, needle in ((["water.density=910"], "does not float"),
                                 (["sheet.cell_size=0.12"], "sheet.cell_size"),
                                 (["structure.toe_x=2"], "structure.toe_x"),
                                 (["channel.width=0.5"], "channel.width"),
                                 (["numerics.time_step=1e-3"], "numerics.time_step"),
                                 (["numerics.structure_substeps=1"], "numerics.structure_substeps"),
                                 (["ice.youngs_modulus=2e10"], "numerics.time_step"),
                                 (["structure.panels=1000"], "structure.panels")):
            case(base + [a for s in settings for a in ("--set", s)], needle)
        # 5. Files that are no scenario.
        def scenario_file(name, content, binary=False):
            path = os.path.join(tmp, name)
            with open(path, "wb" if binary else "w") as f:
                f.write(content)
            return path

        rest = ["--until-time", "0.01", "--out", out]
        files = [
            (os.path.join(tmp, "missing.yaml"), "missing.yaml"),
            (tmp, tmp),
            ("/dev/zero", "/dev/zero"),
            (scenario_file("huge.yaml", text + "#" * (2 << 20)), "huge.yaml"),
            (scenario_file("binary.yaml", bytes(range(256)) * 4, binary=True), "binary.yaml"),
            (scenario_file("empty.yaml", ""), "empty.yaml"),
            (scenario_file("two.yaml", text + "\n---\n" + text), "two.yaml"),
            (scenario_file("list.yaml", "- 1\n- 2\n"), "list.yaml"),
            (scenario_file("duplicate.yaml", text.replace("ice:\n", "ice:\n  thickness: 0.05\n", 1)), "thickness"),
            (scenario_file("no_thickness.yaml", text.replace("  thickness: 0.051", "", 1)), "ice.thickness"),
            (scenario_file("quoted.yaml", text.replace("  thickness: 0.051", '  thickness: "0.051"', 1)),
             "ice.thickness"),
            (scenario_file("long_value.yaml", text.replace("  thickness: 0.051", "  thickness: " + "9" * 5000, 1)),
             "ice.thickness"),
        ]
        for path, needle in files:
            case(["--scenario", path] + rest, needle)
        # 6. Command lines.
        run_dir = os.path.join(tmp, "a_run")
        made = subprocess.run(run + ["--scenario", quick, "--until-time", "0.01", "--out", run_dir],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=120)
        if made.returncode != 0:
            failures.append(f"the run the command-line cases need: exit status {made.returncode}")
        for args, needle in (([], "--scenario"),
                             (["--scenario", quick, "--out", out], "--until-length"),
                             (["--scenario", quick, "--until-time", "1"], "--out"),
                             (["--scenario", quick, "--until-time", "1", "--until-length", "1", "--out", out],
                              "exactly one"),
                             (["--scenario", quick, "--until-length", "-1", "--out", out], "--until-length"),
                             (["--scenario", quick, "--until-length", "abc", "--out", out], "--until-length"),
                             (["--scenario", quick, "--until-length", "5", "--out", out], "travel"),
                             (["--scenario", quick, "--until-time", "0", "--out", out], "--until-time"),
                             (["--scenario", quick, "--until-time", "1e300", "--out", out], "time steps"),
                             (["--scenario", quick, "--until-time", "1", "--snapshots", "-1", "--out", out],
                              "--snapshots"),
                             (["--scenario", quick, "--until-time", "1", "--output-interval", "0", "--out", out],
                              "--output-interval"),
                             (["--scenario", quick, "--until-time", "1", "--backend", "gpu", "--out", out],
                              "--backend"),
                             (["--scenario", quick, "--until-time", "1", "--bogus", "1", "--out", out], "--bogus"),
                             (["--scenario", quick, "--until-time", "1", "--set", "ice.thickness", "--out", out],
                              "ice.thickness"),
                             (["--scenario", quick, "--until-time", "1", "--out", out, "--accept-changed-scenario"],
                              "--accept-changed-scenario"),
                             (["--resume", os.path.join(tmp, "nowhere"), "--until-time", "1"], "nowhere"),
                             (["--resume", run_dir, "--scenario", quick, "--until-time", "1"], "--resume")):
            case(args, needle)
        # A run directory that holds a run: neither overwritten nor resumed into nonsense.
        case(["--scenario", quick, "--until-time", "0.02", "--out", run_dir], "already holds a run",
             untouched=run_dir, out_dir=None)
        case(["--resume", run_dir, "--until-time", "0.005"], "already at", untouched=run_dir, out_dir=None)
        case(["--resume", run_dir, "--until-time", "1", "--set", "sheet.length=2"], "sheet.length",
             untouched=run_dir, out_dir=None)
        # `thin_ice resume DIR` is `thin_ice run --resume DIR`: the same refusals.
        resume = [thin_ice, "resume"]
        case([os.path.join(tmp, "nowhere"), "--until-time", "1"], "nowhere", command=resume)
        case([run_dir, "--scenario", quick, "--until-time", "1"], "--resume", command=resume)
        case([run_dir, "--until-time", "0.005"], "already at", untouched=run_dir, out_dir=None, command=resume)
        case([run_dir, "--until-time", "1", "--set", "sheet.length=2"], "sheet.length", untouched=run_dir,
             out_dir=None, command=resume)
    if count < MIN_CASES:
        failures.append(f"only {count} cases; the corpus is to hold at least {MIN_CASES}")
    if failures:
        print(f"{len(failures)} of {count} cases failed:")
        for f in failures:
            print("FAIL: " + f)
        sys.exit(1)
    print(f"OK: {count} bad inputs refused with exit status 2, one line naming what is wrong, nothing written")


if __name__ == "__main__":
    main()
