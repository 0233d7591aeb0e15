"""The run record as the scripts read it: the mirror of include/thin_ice_sim/study/run_record.hpp,
which owns the layout (`thin_ice run` writes through it). test/test_run_record.py holds the two to
each other, so a column renamed there and not here fails the tests."""
import csv
import json
import os

SUMMARY_SCHEMA_VERSION = 1  # summary.json's "schema_version"; records before the field: the same layout

SUMMARY_FILE = "summary.json"
LOADS_FILE = "loads.csv"  # written through loads.csv.partial, renamed when the run ends
LOAD_BINS_FILE = "load_bins.csv"  # the kept record: the whole run in bins of pushed length
CHECKPOINT_FILE = "checkpoint.bin"
SNAPSHOT_DIR = "snapshots"
SNAPSHOT_INDEX_FILE = "index.csv"

# loads.csv: one row per output interval; these columns, then panel_1_N ... panel_P_N.
LOAD_COLUMNS = ("time_s", "pushed_length_m", "horizontal_raw_N", "horizontal_calibrated_N", "vertical_raw_N",
                "pusher_force_N", "intact_bonds", "broken_bonds", "contacts")
# load_bins.csv: one row per bin of LOAD_BIN_LENGTH of pushed ice (include/thin_ice_sim/study/load_bins.hpp).
LOAD_BIN_LENGTH = 0.035  # [m] the paper's output step; the C++ side's kLoadBinLength
LOAD_BIN_COLUMNS = ("bin", "time_s", "pushed_length_m", "duration_s", "samples", "horizontal_calibrated_mean_N",
                    "horizontal_calibrated_least_N", "horizontal_calibrated_greatest_N", "vertical_raw_mean_N",
                    "pusher_force_mean_N", "intact_bonds", "broken_bonds")
SNAPSHOT_COLUMNS = ("cell", "x_m", "y_m", "z_m", "yaw_rad", "in_intact_sheet", "piece_cells", "polygon_xy_m")
SNAPSHOT_INDEX_COLUMNS = ("file", "time_s", "pushed_length_m")


def panel_column(panel):
    """loads.csv's column of panel `panel` (1-based): its raw horizontal load [N]."""
    return f"panel_{panel}_N"


def loads_path(run_dir):
    """loads.csv of a run, or, where there is none, loads.csv.partial (a first segment killed before
    it finished: its rows are written one by one); None when there is neither. A resumed segment
    killed with SIGKILL leaves both: loads.csv, the record up to its resumption, is the one read."""
    path = os.path.join(run_dir, LOADS_FILE)
    if os.path.exists(path):
        return path
    return path + ".partial" if os.path.exists(path + ".partial") else None


def existing_loads_path(run_dir):
    """loads_path, for a reader to whom the run must have rows: raises FileNotFoundError naming the
    run where there is neither loads.csv nor loads.csv.partial."""
    path = loads_path(run_dir)
    if path is None:
        raise FileNotFoundError(f"{run_dir}: no {LOADS_FILE} (nor {LOADS_FILE}.partial)")
    return path


def rows_are_whole_run(run_dir, summary):
    """True where the run's loads.csv holds every row of the run (not only the segments after a
    resumption from the kept record, summary.json's loads_csv_from_s > 0), or where a first segment
    is still being written (loads.csv.partial and no summary yet): the readers take its rows then,
    and load_bins.csv otherwise."""
    if summary is None:
        return loads_path(run_dir) is not None
    return os.path.exists(os.path.join(run_dir, LOADS_FILE)) and not summary.get("loads_csv_from_s")


def summary_path(run_dir):
    """RUN/summary.json."""
    return os.path.join(run_dir, SUMMARY_FILE)


def require_summary(run_dir):
    """summary.json as it was written (a dict in a record of `thin_ice run`), for a caller to whom
    the run must have one; raises FileNotFoundError naming the file where it has none (OSError
    where it cannot be read) and ValueError where it is not JSON."""
    with open(summary_path(run_dir)) as f:
        return json.load(f)


def read_summary(run_dir):
    """summary.json as a dict, or None where the run has none yet; raises OSError where it cannot
    be read and ValueError where it is not JSON."""
    if not os.path.exists(summary_path(run_dir)):
        return None
    return require_summary(run_dir)


def read_load_rows(run_dir):
    """loads.csv's rows as dicts of strings keyed by column (the partial file where there is no
    other); raises FileNotFoundError naming the run where there is neither."""
    with open(existing_loads_path(run_dir)) as f:
        return list(csv.DictReader(f))


def read_load_columns(run_dir, columns):
    """(path, {column: [values]}) of loads.csv's `columns` as floats (each in the unit its name
    ends with: m, s or N), from the partial file where there is no other; path is the file read.
    The rows are read up to the first that is not whole (a half-written last line of
    loads.csv.partial, its run still writing) and no further. Raises FileNotFoundError naming the
    run where there is neither file, OSError where it cannot be read, and ValueError naming the
    file and the missing columns where its header lacks one of `columns`."""
    path = existing_loads_path(run_dir)
    values = {name: [] for name in columns}
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        missing = set(columns) - set(reader.fieldnames or [])
        if missing:
            raise ValueError(f"{path}: missing column(s) {', '.join(sorted(missing))}")
        for row in reader:
            try:
                row_values = [float(row[name]) for name in columns]
            except (TypeError, ValueError):
                break  # a half-written last line of a partial file
            for name, value in zip(columns, row_values):
                values[name].append(value)
    return path, values


def read_table(path):
    """A CSV file of the record (loads.csv, load_bins.csv) as it was written: one list of strings
    per line, the header first, for the scripts that write it again (recalibrate) or a copy of it
    cut short (steady_by_length); raises OSError where it cannot be read."""
    with open(path, newline="") as f:
        return list(csv.reader(f))


def read_load_bins(run_dir):
    """load_bins.csv as a dict of columns: "pushed_length_m", "time_s", "duration_s" and the loads
    [N] as lists of floats, "samples", "intact_bonds" and "broken_bonds" as lists of ints. Raises
    FileNotFoundError naming the run where it has none (a run made before the file: `thin_ice
    analyse RUN_DIR --write-bins` writes it from loads.csv) and ValueError naming the file and the
    row where a row is not one of `thin_ice run`."""
    path = os.path.join(run_dir, LOAD_BINS_FILE)
    if not os.path.exists(path):
        raise FileNotFoundError(f"{run_dir}: no {LOAD_BINS_FILE} (a run made before it: `thin_ice analyse {run_dir} "
                                f"--write-bins` writes it from its {LOADS_FILE})")
    whole = ("bin", "samples", "intact_bonds", "broken_bonds")
    columns = {name: [] for name in LOAD_BIN_COLUMNS}
    with open(path, newline="") as f:
        for number, row in enumerate(csv.DictReader(f), 2):
            try:
                for name in LOAD_BIN_COLUMNS:
                    columns[name].append(int(row[name]) if name in whole else float(row[name]))
            except (KeyError, TypeError, ValueError):
                raise ValueError(f"{path}, line {number}: not a row of the {LOAD_BINS_FILE} of `thin_ice run` "
                                 "(a missing column or a row cut short)") from None
    return columns


def mean_over(bins, begin, end):
    """Time-weighted mean calibrated horizontal load [N] of the bins whose end length lies in
    (begin, end] [m], or None where there is none."""
    weighted = duration = 0.0
    for length, mean, d in zip(bins["pushed_length_m"], bins["horizontal_calibrated_mean_N"], bins["duration_s"]):
        if begin < length <= end:
            weighted += mean * d
            duration += d
    return weighted / duration if duration > 0 else None


def snapshot_index_path(run_dir):
    """RUN/snapshots/index.csv."""
    return os.path.join(run_dir, SNAPSHOT_DIR, SNAPSHOT_INDEX_FILE)


def read_snapshot_index(run_dir):
    """snapshots/index.csv's rows as dicts of strings ("file", "time_s", "pushed_length_m"), in the
    order written; raises OSError where the run has none (it was run without --snapshots N, or it
    is a copy that keeps none)."""
    with open(snapshot_index_path(run_dir), newline="") as f:
        return list(csv.DictReader(f))


def snapshot_path(run_dir, name):
    """The cells file `name` of the run's snapshot index."""
    return os.path.join(run_dir, SNAPSHOT_DIR, name)


def read_cells_file(path):
    """A snapshot's cells file, by its path: its rows (one per cell) as dicts of strings keyed by
    SNAPSHOT_COLUMNS (lengths in m, yaw in rad; older snapshots lack piece_cells); raises OSError
    where it cannot be read."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def read_snapshot_cells(run_dir, name):
    """The cells file `name` of the run's snapshot index (a "file" of read_snapshot_index) as
    read_cells_file gives it; raises OSError where the run has no such file."""
    return read_cells_file(snapshot_path(run_dir, name))
