"""The summary.json of a `thin_ice run` from Python: written again (scripts/study recalibrate,
scripts/study reanalyse; the load statistics from `thin_ice analyse`, the C++ code `thin_ice run` uses,
one layout, and files replaced only when whole), and the scenario it names read back with the run's
overrides (scripts/study validation_report, scripts/study ice_layers)."""
import json
import os
import subprocess
import sys

from . import ROOT, run_record

BUILDS = (".ws/devel/lib/thin_ice_sim", ".ws/build_core_only/bin")  # catkin's, then plain CMake's


def default_tool(caller):
    """The thin_ice program of the catkin build, else of the plain CMake build, under .ws (the
    scripts' --tool when none is given)."""
    for folder in BUILDS:
        path = os.path.join(ROOT, folder, "thin_ice")
        if os.access(path, os.X_OK):
            return path
    sys.exit(f"{caller}: no thin_ice under {' or '.join(BUILDS)}: build first, or give --tool")


def analyse(tool, run_dir):
    """The answer of `thin_ice analyse RUN_DIR` (tool: the thin_ice program): summary.json's "load"
    and "experiment" objects worked out from its loads.csv, and "scenario_calibration_factor", the
    alpha its scenario gives now (None, with "scenario_error", when the scenario cannot be loaded).
    Run from the repository root, where the runs' relative scenario paths start; raises
    RuntimeError with the command's message when it refuses the directory."""
    # The tool's path is the caller's (relative to where the script was started), not ROOT's.
    try:
        done = subprocess.run([os.path.abspath(tool), "analyse", os.path.abspath(run_dir)], cwd=ROOT,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=600)
    except OSError as e:
        raise RuntimeError(f"cannot start {tool}: {e.strerror}") from e
    if done.returncode != 0:
        raise RuntimeError(done.stderr.strip() or f"{tool} analyse: exit status {done.returncode}")
    try:
        return json.loads(done.stdout)
    except ValueError as e:
        raise RuntimeError(f"{tool} analyse did not answer in JSON ({e}): is {tool} the thin_ice program?") from e


def scenario_of_run(summary):
    """The scenario file a run was made from (summary.json's scenario.file, relative to the
    repository root unless absolute) as a dict, with the run's --set overrides applied: each
    "section.key=value" sets scenario[section][key], to a float where the value reads as one.
    Raises OSError, KeyError, TypeError or yaml.YAMLError where the file or a section is missing."""
    from . import scenario_file  # here, not at the top: the module's other users do without yaml
    path = summary[run_record.SCENARIO]["file"]
    path = path if os.path.isabs(path) else os.path.join(ROOT, path)
    scenario = scenario_file.load(path)
    for override in summary[run_record.SCENARIO].get("overrides", []):
        key, value = override.split("=", 1)
        section, name = key.split(".", 1)
        try:
            value = float(value)
        except ValueError:
            pass
        scenario.setdefault(section, {})[name] = value
    return scenario


def floating_level(summary):
    """(h [m], z_rest [m]) of a run's ice: z_rest = h/2 - (rho_i / rho_w) h is where a cell's centroid
    floats at rest (Archimedes; the model's cells do not tilt), from the run's scenario file and
    overrides. Raises ValueError naming the file and the keys when they are missing or unphysical."""
    import yaml
    file = summary[run_record.SCENARIO]["file"]
    try:
        scenario = scenario_of_run(summary)
        h, rho_i, rho_w = (float(scenario[s][k]) for s, k in (("ice", "thickness"), ("ice", "density"),
                                                              ("water", "density")))
    except (OSError, KeyError, TypeError, ValueError, yaml.YAMLError) as e:
        raise ValueError(f"cannot read ice.thickness, ice.density and water.density of {file}: {e}") from e
    if not (h > 0 and rho_w > 0 and 0 < rho_i < rho_w):
        raise ValueError(f"{file}: ice.thickness {h:g}, ice.density {rho_i:g}, water.density {rho_w:g}; "
                         "allowed: h > 0 and 0 < rho_i < rho_w")
    return h, 0.5 * h - rho_i / rho_w * h


def sheet_size(cells):
    """Cells in the pushed sheet, the largest piece held together by intact bonds, from a snapshot's
    rows (column piece_cells, which older snapshots lack); None for a snapshot without that column."""
    if not cells or run_record.PIECE_CELLS not in cells[0]:
        return None
    return max(int(c[run_record.PIECE_CELLS]) for c in cells)


def _json(value, indent):
    """value as JSON: objects one key per line, lists of plain values on one line."""
    pad, inner = " " * indent, " " * (indent + 2)
    if isinstance(value, dict) and value:
        items = (f"{inner}{json.dumps(k)}: {_json(v, indent + 2)}" for k, v in value.items())
        return "{\n" + ",\n".join(items) + "\n" + pad + "}"
    if isinstance(value, list) and any(isinstance(v, (dict, list)) for v in value):
        return "[\n" + ",\n".join(inner + _json(v, indent + 2) for v in value) + "\n" + pad + "]"
    return json.dumps(value, separators=(", ", ": "))


def summary_text(summary):
    """summary.json one key per line, with lists of numbers kept on one line as `thin_ice run` has them."""
    return _json(summary, 0) + "\n"


def replace_files(contents):
    """contents: {path: text}. Every file is written beside its old one first, flushed to disk,
    and only then are they renamed over the old ones, so that a failure while writing leaves the
    old files as they were and no .new file behind. (The renames themselves are not one atomic
    step: a crash between two of them leaves some files new and some old.)"""
    written = []
    try:
        for path, text in contents.items():
            written.append(path + ".new")
            with open(path + ".new", "w", newline="") as f:
                f.write(text)
                f.flush()
                os.fsync(f.fileno())
    except BaseException:
        for new_path in written:
            try:
                os.remove(new_path)
            except FileNotFoundError:
                pass
        raise
    for path in contents:
        os.replace(path + ".new", path)
