"""The run record as the scripts read it: the mirror of include/thin_ice_sim/study/run_record.hpp,
which owns the layout (`thin_ice run` writes through it). test/test_run_record.py holds the two to
each other, so a column renamed there and not here fails the tests. Also here, the one place the
scripts apply or undo alpha of Eq. (18): calibrated, raw_of and at_alpha."""
import csv
import json
import os

SUMMARY_SCHEMA_VERSION = 1  # summary.json's "schema_version"; records before the field: the same layout

SUMMARY_FILE = "summary.json"
LOADS_FILE = "loads.csv"  # written through LOADS_PARTIAL_FILE, renamed when the run ends
LOADS_PARTIAL_FILE = "loads.csv.partial"  # loads.csv while its segment runs
LOAD_BINS_FILE = "load_bins.csv"  # the kept record: the whole run in bins of pushed length
CHECKPOINT_FILE = "checkpoint.bin"
SNAPSHOT_DIR = "snapshots"
SNAPSHOT_INDEX_FILE = "index.csv"

# The columns of the record's CSV files, each named as run_record.hpp names it (load_column::kTime:
# TIME, snapshot_column::kInIntactSheet: IN_INTACT_SHEET; test/test_run_record.py holds each to the
# constant of its name there); a name two files share (time_s, pushed_length_m, intact_bonds,
# broken_bonds) is one constant here. The scripts index rows with these, not with the names.
TIME = "time_s"                                # [s] simulated
PUSHED_LENGTH = "pushed_length_m"              # [m]
HORIZONTAL_RAW = "horizontal_raw_N"            # F of Eq. (17) [N]
HORIZONTAL_CALIBRATED = "horizontal_calibrated_N"  # alpha F of Eq. (18) [N]
VERTICAL_RAW = "vertical_raw_N"                # [N], +z
PUSHER_FORCE = "pusher_force_N"                # [N], +x
INTACT_BONDS = "intact_bonds"
BROKEN_BONDS = "broken_bonds"
CONTACTS = "contacts"
BIN = "bin"                                    # k: the bin (k b, (k + 1) b] of pushed length
DURATION = "duration_s"                        # [s] the bin's rows' intervals
SAMPLES = "samples"                            # rows of loads.csv in the bin
CALIBRATED_MEAN = "horizontal_calibrated_mean_N"        # [N]
CALIBRATED_LEAST = "horizontal_calibrated_least_N"      # [N]
CALIBRATED_GREATEST = "horizontal_calibrated_greatest_N"  # [N]
VERTICAL_MEAN = "vertical_raw_mean_N"          # [N], +z
PUSHER_MEAN = "pusher_force_mean_N"            # [N], +x
CELL = "cell"
X = "x_m"                                      # [m] the cell's centroid
Y = "y_m"                                      # [m]
Z = "z_m"                                      # [m]
YAW = "yaw_rad"                                # [rad]
IN_INTACT_SHEET = "in_intact_sheet"            # "1" while any of the cell's bonds holds
PIECE_CELLS = "piece_cells"                    # cells of its bonded piece (older snapshots lack it)
POLYGON = "polygon_xy_m"                       # "x0 y0 x1 y1 ..." [m], one field
FILE = "file"                                  # index.csv: the snapshot's cells file

# loads.csv: one row per output interval; these columns, then panel_1_N ... panel_P_N.
LOAD_COLUMNS = (TIME, PUSHED_LENGTH, HORIZONTAL_RAW, HORIZONTAL_CALIBRATED, VERTICAL_RAW, PUSHER_FORCE, INTACT_BONDS,
                BROKEN_BONDS, CONTACTS)
# load_bins.csv: one row per bin of LOAD_BIN_LENGTH of pushed ice (include/thin_ice_sim/study/load_bins.hpp).
LOAD_BIN_LENGTH = 0.035  # [m] the paper's output step; the C++ side's kLoadBinLength
LOAD_BIN_COLUMNS = (BIN, TIME, PUSHED_LENGTH, DURATION, SAMPLES, CALIBRATED_MEAN, CALIBRATED_LEAST, CALIBRATED_GREATEST,
                    VERTICAL_MEAN, PUSHER_MEAN, INTACT_BONDS, BROKEN_BONDS)
SNAPSHOT_COLUMNS = (CELL, X, Y, Z, YAW, IN_INTACT_SHEET, PIECE_CELLS, POLYGON)
SNAPSHOT_INDEX_COLUMNS = (FILE, TIME, PUSHED_LENGTH)

# summary.json's top-level fields that the scripts read or write, as `thin_ice run` writes them
# (run_record.hpp's SummaryRecord, through summaryJson; test/test_run_record.py finds each in a
# summary it writes). The run's last pushed_length_m, intact_bonds and broken_bonds are the columns'
# constants above; the objects' own fields ("load": steady_mean_N, peak_N ...) are named where they
# are read.
SCHEMA_VERSION = "schema_version"              # holds SUMMARY_SCHEMA_VERSION
STATUS = "status"                              # "completed", "interrupted" or "unhealthy"
SCENARIO = "scenario"                          # {"name", "file", "hash", "overrides"}
BACKEND = "backend"
TARGET = "target"                              # {"pushed_length_m" or "time_s": the run's target}
LOADS_CSV_FROM = "loads_csv_from_s"            # [s] where loads.csv starts (> 0: resumed from the kept record)
RESUMED_AT = "resumed_at_m"                    # [m] the pushed lengths at which it was resumed
OVERRIDES_FROM = "overrides_from_m"            # [{"set", "from_m"}]: overrides given on resumption
CALIBRATION_FACTOR = "calibration_factor"      # alpha [-] of Eq. (18) at which the run recorded alpha F
LOAD = "load"                                  # the load statistics of alpha F (at CALIBRATION_FACTOR)
STRUCTURE_WIDTH = "structure_width_m"          # [m]
STRUCTURE = "structure"                        # {"toe_x_m", "angle_deg", "width_m", "height_m", "panels"}
FALSE_BOTTOM = "false_bottom"                  # {"depth_m", "distance_from_structure_m"}, or null
EXPERIMENT = "experiment"                      # Table 6 for the run's series, or null
SUMMARY_FIELDS = (SCHEMA_VERSION, STATUS, SCENARIO, BACKEND, TARGET, LOADS_CSV_FROM, RESUMED_AT, OVERRIDES_FROM,
                  PUSHED_LENGTH, INTACT_BONDS, BROKEN_BONDS, CALIBRATION_FACTOR, LOAD, STRUCTURE_WIDTH, STRUCTURE,
                  FALSE_BOTTOM, EXPERIMENT)


# alpha of Eq. (18), F_cal = alpha F: the record holds F (horizontal_raw_N) and alpha F at the run's
# own alpha (summary.json's calibration_factor); these are the only places the scripts apply or undo it.
def calibrated(raw, alpha):
    """alpha F [N]: the raw load `raw` [N] (F of Eq. (17), or a quantity proportional to it: per
    metre of width [N/m], per metre of pushed ice [N/m]) times the calibration factor alpha [-]."""
    return alpha * raw


def raw_of(value, run_alpha):
    """The raw load F [N] (or per metre, as `value` is) under a calibrated load alpha F `value` [N]
    recorded at run_alpha [-] (a run's calibration_factor): value / run_alpha."""
    return value / run_alpha


def at_alpha(value, run_alpha, alpha):
    """A calibrated load `value` [N] (or per metre, as it is) recorded at the run's own run_alpha
    [-] (its calibration_factor), brought to alpha [-]: alpha / run_alpha * value."""
    return alpha / run_alpha * value


def panel_column(panel):
    """loads.csv's column of panel `panel` (1-based): its raw horizontal load [N]."""
    return f"panel_{panel}_N"


def loads_path(run_dir):
    """loads.csv of a run, or, where there is none, loads.csv.partial (a first segment killed before
    it finished: its rows are written one by one); None when there is neither. A resumed segment
    killed with SIGKILL leaves both: loads.csv, the record up to its resumption, is the one read."""
    path, partial = os.path.join(run_dir, LOADS_FILE), os.path.join(run_dir, LOADS_PARTIAL_FILE)
    if os.path.exists(path):
        return path
    return partial if os.path.exists(partial) else None


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
    return os.path.exists(os.path.join(run_dir, LOADS_FILE)) and not summary.get(LOADS_CSV_FROM)


def summary_path(run_dir):
    """RUN/summary.json."""
    return os.path.join(run_dir, SUMMARY_FILE)


def require_summary(run_dir):
    """summary.json as it was written (a dict in a record of `thin_ice run`), for a caller to whom
    the run must have one; raises FileNotFoundError naming the file where it has none (OSError
    where it cannot be read), and ValueError where it is not JSON or its schema_version is not one
    this mirror knows (1 to SUMMARY_SCHEMA_VERSION; a record without the field is layout 1), as the
    C++ reader refuses it."""
    path = summary_path(run_dir)
    with open(path) as f:
        summary = json.load(f)
    version = summary.get(SCHEMA_VERSION, 1) if isinstance(summary, dict) else 1
    if isinstance(version, bool) or not isinstance(version, int) or not 1 <= version <= SUMMARY_SCHEMA_VERSION:
        newer = isinstance(version, int) and not isinstance(version, bool) and version > SUMMARY_SCHEMA_VERSION
        raise ValueError(f"{path}: \"{SCHEMA_VERSION}\" is {json.dumps(version)}; allowed: a whole number from 1 to "
                         f"{SUMMARY_SCHEMA_VERSION}" + (" (a record of a newer thin_ice is read by that thin_ice)"
                                                         if newer else ""))
    return summary


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
    whole = (BIN, SAMPLES, INTACT_BONDS, BROKEN_BONDS)
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
    for length, mean, d in zip(bins[PUSHED_LENGTH], bins[CALIBRATED_MEAN], bins[DURATION]):
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
