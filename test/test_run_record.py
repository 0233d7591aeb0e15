#!/usr/bin/python3
"""The scripts' mirror of the run record (scripts/thin_ice_study/run_record.py) against its owner
(include/thin_ice_sim/study/run_record.hpp) and against a record `thin_ice run` writes: the same file
names, columns and schema version, so that a column renamed on one side and not the other fails
here rather than in a plot. Each named constant of the mirror is the column of run_record.hpp of
the same name (PUSHED_LENGTH: load_column::kPushedLength, bin_column::kPushedLength ...) or a
field of the summary.json `thin_ice run` writes; one that is neither fails.

    test_run_record.py THIN_ICE SOURCE_DIR   (THIN_ICE: the thin_ice program)
"""
import csv
import json
import os
import re
import subprocess
import sys
import tempfile


def cpp_names(header_text):
    """The names run_record.hpp gives: its string constants (those inside a namespace block as
    "namespace::kName") and its three column arrays."""
    constant = re.compile(r'inline constexpr const char\* (k\w+) = "([^"]*)";')
    constants = {}
    for namespace, body in re.findall(r"namespace (\w+) \{(.*?)\}  // namespace \1", header_text, re.S):
        constants.update({f"{namespace}::{k}": v for k, v in constant.findall(body)})
    top_level = re.sub(r"namespace (\w+) \{.*?\}  // namespace \1", "", header_text, flags=re.S)
    constants.update(dict(constant.findall(top_level)))
    version = int(re.search(r"kSummarySchemaVersion = (\d+);", header_text).group(1))

    def array(name):
        body = re.search(r"inline constexpr const char\* " + name + r"\[\] = \{(.*?)\};", header_text, re.S).group(1)
        items = []
        for item in (x.strip() for x in body.split(",")):
            if item.startswith('"'):
                items.append(item.strip('"'))
            elif item:
                items.append(constants[item])
        return tuple(items)

    return (constants, version, array("kLoadColumns"), array("kSnapshotColumns"), array("kSnapshotIndexColumns"),
            array("kLoadBinColumns"))


def camel(name):
    """run_record.hpp's name of the mirror's constant `name`: PUSHED_LENGTH -> kPushedLength."""
    return "k" + "".join(part.capitalize() for part in name.split("_"))


COLUMN_NAMESPACES = ("load_column", "bin_column", "snapshot_column", "index_column")
FILE_NAMES = {"kSummaryFile": "SUMMARY_FILE", "kLoadsFile": "LOADS_FILE", "kLoadBinsFile": "LOAD_BINS_FILE",
              "kCheckpointFile": "CHECKPOINT_FILE", "kSnapshotDir": "SNAPSHOT_DIR",
              "kSnapshotIndexFile": "SNAPSHOT_INDEX_FILE", "kLoadsPartialFile": "LOADS_PARTIAL_FILE"}


def named_constants(run_record, constants):
    """Failures where an upper-case string constant of the mirror (but the file names) is neither
    the column of run_record.hpp of the same name, in every column namespace that has one, nor, where
    none has, a field listed in SUMMARY_FIELDS (which the written summary is checked for)."""
    failures = []
    column_names = {text for key, text in constants.items() if key.split("::")[0] in COLUMN_NAMESPACES}
    for name, value in vars(run_record).items():
        if not (name.isupper() and isinstance(value, str)) or name in FILE_NAMES.values():
            continue
        cpp = {f"{ns}::{camel(name)}": constants[f"{ns}::{camel(name)}"] for ns in COLUMN_NAMESPACES
               if f"{ns}::{camel(name)}" in constants}
        if cpp:
            failures += [f"{name} = {value!r}: {key} is {text!r}" for key, text in cpp.items() if text != value]
        elif value in column_names:
            failures.append(f"{name} = {value!r}: a column under a name run_record.hpp does not give it "
                            f"({camel(name)} in none of {', '.join(COLUMN_NAMESPACES)})")
        elif value not in run_record.SUMMARY_FIELDS:
            failures.append(f"{name} = {value!r} names no column of run_record.hpp ({camel(name)} in "
                            f"{', '.join(COLUMN_NAMESPACES)}) and is not in SUMMARY_FIELDS")
    return failures


def main():
    thin_ice, source = sys.argv[1], sys.argv[2]
    sys.path.insert(0, os.path.join(source, "scripts"))
    from thin_ice_study import run_record

    failures = []

    def expect(what, got, wanted):
        if got != wanted:
            failures.append(f"{what}: {got!r}, expected {wanted!r}")

    with open(os.path.join(source, "include/thin_ice_sim/study/run_record.hpp")) as f:
        constants, version, load_columns, snapshot_columns, index_columns, bin_columns = cpp_names(f.read())
    with open(os.path.join(source, "include/thin_ice_sim/study/load_bins.hpp")) as f:
        bin_length = float(re.search(r"kLoadBinLength = ([0-9.eE+-]+);", f.read()).group(1))
    expect("LOAD_BIN_LENGTH", run_record.LOAD_BIN_LENGTH, bin_length)
    expect("LOAD_BIN_COLUMNS", run_record.LOAD_BIN_COLUMNS, bin_columns)
    expect("schema version", run_record.SUMMARY_SCHEMA_VERSION, version)
    for cpp, py in FILE_NAMES.items():
        expect(py, getattr(run_record, py), constants[cpp])
    failures += named_constants(run_record, constants)
    expect("LOAD_COLUMNS", run_record.LOAD_COLUMNS, load_columns)
    expect("SNAPSHOT_COLUMNS", run_record.SNAPSHOT_COLUMNS, snapshot_columns)
    expect("SNAPSHOT_INDEX_COLUMNS", run_record.SNAPSHOT_INDEX_COLUMNS, index_columns)
    if len(load_columns) != 9:  # the parse found the array (nine columns before the panels)
        failures.append(f"parsed {len(load_columns)} load columns from run_record.hpp, expected 9")

    # alpha of Eq. (18): applied to a raw load, undone, and a load at one alpha brought to another.
    for what, got, wanted in (("calibrated(10, 0.63)", run_record.calibrated(10.0, 0.63), 6.3),
                              ("raw_of(6.3, 0.63)", run_record.raw_of(6.3, 0.63), 10.0),
                              ("at_alpha(6.3, 0.63, 1.7)", run_record.at_alpha(6.3, 0.63, 1.7), 17.0)):
        if abs(got - wanted) > 1e-12:
            failures.append(f"{what}: {got}, expected {wanted}")

    # mean_over weights each bin by the time it covers, over the bins ending in (begin, end]:
    # (10 * 0.7 + 20 * 0.7 + 40 * 0.35) / 1.75 = 20; without the first bin 28 / 1.05 = 26.67.
    bins = {"pushed_length_m": [0.035, 0.07, 0.1], "horizontal_calibrated_mean_N": [10.0, 20.0, 40.0],
            "duration_s": [0.7, 0.7, 0.35]}
    for begin, end, wanted in ((0.0, 0.1, 20.0), (0.035, 0.1, 28.0 / 1.05), (0.2, 0.3, None)):
        got = run_record.mean_over(bins, begin, end)
        if (got is None) != (wanted is None) or (wanted is not None and abs(got - wanted) > 1e-12):
            failures.append(f"mean_over({begin}, {end}): {got}, expected {wanted}")

    # The readers on files written here: a partial loads.csv read up to its half-written last line,
    # a header without a column asked for, and a run with no summary or no loads file.
    with tempfile.TemporaryDirectory() as run:
        with open(os.path.join(run, run_record.LOADS_FILE + ".partial"), "w") as f:
            f.write("time_s,pushed_length_m,horizontal_calibrated_N\n0.01,0.002,5\n0.02,0.004,7\n0.03,0.0")
        path, columns = run_record.read_load_columns(run, ("pushed_length_m", "horizontal_calibrated_N"))
        expect("read_load_columns file", path, os.path.join(run, run_record.LOADS_FILE + ".partial"))
        expect("read_load_columns rows", columns,
               {"pushed_length_m": [0.002, 0.004], "horizontal_calibrated_N": [5.0, 7.0]})
        try:
            run_record.read_load_columns(run, ("pushed_length_m", "horizontal_raw_N", "contacts"))
            failures.append("read_load_columns: a missing column was not refused")
        except ValueError as e:
            expect("read_load_columns message", str(e), f"{path}: missing column(s) contacts, horizontal_raw_N")
        expect("read_summary without one", run_record.read_summary(run), None)
        try:
            run_record.require_summary(run)
            failures.append("require_summary: a run without summary.json was not refused")
        except FileNotFoundError as e:
            expect("require_summary names the file", e.filename, run_record.summary_path(run))
        # A schema_version this mirror does not know is refused, as run_directory.cpp refuses it.
        for version in (run_record.SUMMARY_SCHEMA_VERSION + 1, 0, "1"):
            with open(run_record.summary_path(run), "w") as f:
                json.dump({run_record.SCHEMA_VERSION: version}, f)
            try:
                run_record.require_summary(run)
                failures.append(f"require_summary: schema_version {version!r} was not refused")
            except ValueError as e:
                if "schema_version" not in str(e) or "allowed: a whole number from 1 to" not in str(e):
                    failures.append(f"require_summary's refusal of {version!r} names no field and range: {e}")
        with open(run_record.summary_path(run), "w") as f:
            json.dump({run_record.SCHEMA_VERSION: run_record.SUMMARY_SCHEMA_VERSION}, f)
        expect("require_summary of a known version", run_record.require_summary(run),
               {run_record.SCHEMA_VERSION: run_record.SUMMARY_SCHEMA_VERSION})
        os.remove(run_record.summary_path(run))
        os.remove(path)
        try:
            run_record.read_load_columns(run, ("pushed_length_m",))
            failures.append("read_load_columns: a run without loads.csv was not refused")
        except FileNotFoundError:
            pass

    # A record as `thin_ice run` writes it: quick.yaml (2 panels), two snapshots.
    with tempfile.TemporaryDirectory() as out:
        cmd = [thin_ice, "run", "--scenario", os.path.join(source, "config/scenarios/quick.yaml"), "--until-time", "0.02",
               "--snapshots", "2", "--out", out]
        done = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=300)
        if done.returncode != 0:
            sys.exit(f"FAIL: exit status {done.returncode}: {done.stderr.strip()}")
        summary = run_record.read_summary(out)
        expect("summary schema_version", summary.get(run_record.SCHEMA_VERSION), run_record.SUMMARY_SCHEMA_VERSION)
        expect("SUMMARY_FIELDS missing from the summary `thin_ice run` writes",
               sorted(set(run_record.SUMMARY_FIELDS) - set(summary)), [])
        rows = run_record.read_load_rows(out)
        expect("loads.csv columns", tuple(rows[0].keys()),
               run_record.LOAD_COLUMNS + (run_record.panel_column(1), run_record.panel_column(2)))
        expect("loads.csv rows", len(rows), 2)  # 0.02 s at 0.01 s per row
        bins = run_record.read_load_bins(out)
        expect("load_bins.csv rows", sum(bins["samples"]), 2)  # both rows, in one bin (4 mm at 0.2 m/s)
        expect("load_bins.csv bins", bins["bin"], [0])
        expect("load_bins.csv end", bins["time_s"], [float(rows[-1]["time_s"])])
        snapshots = os.path.join(out, run_record.SNAPSHOT_DIR)
        with open(os.path.join(snapshots, run_record.SNAPSHOT_INDEX_FILE)) as f:
            index = list(csv.DictReader(f))
        expect("index.csv columns", tuple(index[0].keys()), run_record.SNAPSHOT_INDEX_COLUMNS)
        expect("snapshot files", [r["file"] for r in index], ["cells_000000.csv", "cells_000002.csv"])
        with open(os.path.join(snapshots, index[0]["file"])) as f:
            expect("snapshot columns", tuple(next(csv.reader(f))), run_record.SNAPSHOT_COLUMNS)
        expect("read_snapshot_index", run_record.read_snapshot_index(out), index)
        cells = run_record.read_snapshot_cells(out, index[0]["file"])
        expect("read_snapshot_cells columns", tuple(cells[0].keys()), run_record.SNAPSHOT_COLUMNS)
        expect("read_cells_file", run_record.read_cells_file(run_record.snapshot_path(out, index[0]["file"])), cells)
        _, columns = run_record.read_load_columns(out, ("time_s", "horizontal_raw_N"))
        expect("read_load_columns", columns["horizontal_raw_N"], [float(r["horizontal_raw_N"]) for r in rows])
        expect("require_summary", run_record.require_summary(out), summary)
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("run record: the mirror and a written record agree with run_record.hpp")


if __name__ == "__main__":
    main()
