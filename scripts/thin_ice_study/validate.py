"""Runs the validation matrix against the shallow-water experiments (paper Tables 4-6) and
regenerates docs/validation.md: on this machine (set-up and build as scripts/demo, then the runs,
a few at a time), or as one Slurm job array on a cluster.

  scripts/study validate [MATRIX OPTIONS] [--jobs N]                  run here, then collect
  scripts/study validate [MATRIX OPTIONS] --slurm [SBATCH OPTIONS...] submit one array task per run
  scripts/study validate --collect                                    copy the finished runs, report
  scripts/study validate --report-only                                only rebuild the report

MATRIX OPTIONS
  --series ID       a scenario of config/scenarios (default: the seven series W-1 W-2 W-3 M-1 M-2
                    S-1 S-2); may be repeated
  --seeds K,...     also run each series with these Voronoi seeds (sheet.seed), for the spread
                    that comes from the mesh alone
  --resolution      also run each series with 0.85 x the cell size (and 0.85 x its time step,
                    which the finer mesh's critical step needs) and with half the time step
  --until-length L  pushed length per run [m] or `end` (default: the experiment's L of Table 5,
                    or the pusher's travel where that is shorter: 24.05 m at full width; on the
                    CPU that is days per series, so give a length there)
  --set KEY=VALUE   a scenario override for every run of the matrix; may be repeated
  --tag NAME        name the runs ID-NAME (and ID-NAME-sK, ...) instead of ID, so that a
                    longer run (--tag long) sits beside the matrix's runs; a tagged run keeps
                    its checkpoint in the records, so that a later session can resume it
  --backend B       cpu, cuda or auto (default: the GPU when there is one)
  --wall-budget S   each run stops after S s of wall time with SIGTERM: `thin_ice run` finishes its
                    output interval and writes everything it has (status "interrupted"); under
                    Slurm the task then requeues itself and resumes (default there: 14400 s)
  --resume          go on with each run from its checkpoint in the records (RECORDS/RUN/
                    checkpoint.bin) to the new --until-length, instead of starting it again
  --accept-changed-scenario  with --resume: take the scenario file's values where they differ from a run's own
                    where the run's parameters did not (the flag of that name of `thin_ice run`)
  --keep-existing   skip a run whose RECORDS/RUN/summary.json says it completed to the same length
  --strips MATRIX   instead of --series, --seeds, --resolution and --tag: the runs of a strip matrix
                    (config/strips/*.matrix, the lines scripts/strip_matrix runs: NAME SCENARIO
                    [--width W] [--length L] [--set KEY=VALUE]... [--snapshots K]), each on its strip
                    (scripts/study strip), named NAME; records default to docs/validation/strips and
                    keep their checkpoints; --until-length defaults to the experiment's L of the
                    series the scenario file is named after. So the strips can go to the experiments'
                    lengths as one Slurm array: --strips config/strips/validation.matrix --resume --slurm
WHERE
  --bin DIR         the folder holding the thin_ice program (default: install and build the catkin
                    workspace, and use .ws/devel/lib/thin_ice_sim)
  --work DIR        the run directories (DIR/validation/RUN) and the sweep (DIR/sweep: the task
                    list, each task's log and end status) (default .ws)
  --records DIR     where each run's summary.json, load_bins.csv, loads.csv, load.png and profiles.csv are
                    copied (default docs/validation/full, with --strips docs/validation/strips); the report covers the folder above it
                    (docs/validation: the full-width runs and the strips)
  --report FILE     the report to write (default docs/validation.md)
RUNNING
  --jobs N          runs at a time on this machine (default 1); with N > 1 each run takes one
                    CPU thread (numerics.threads=1)
  --slurm ...       write DIR/sweep/array.sbatch (one task per run, --requeue), submit it with
                    sbatch and print the job id; every argument after --slurm goes to sbatch
                    (e.g. --partition=gpu --gres=gpu:1 --cpus-per-task=4 --time=06:00:00)
  --collect         copy the runs of the last sweep that wrote a record to RECORDS, report
                    each task that failed with its log's last line, and rebuild the report

Each task runs `thin_ice run` on its run directory: resumed when the directory holds a checkpoint
(a requeued or preempted task goes on where it stopped), started otherwise. Exit status: 0 all
runs went as asked; 1 a run failed, was refused or has not finished (--collect); 2 bad arguments.
"""
import functools
import json
import os
import shutil
import signal
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

import yaml

from . import ROOT, run_record, scenario_file, strip
from .phase2_table import EXPERIMENT_LENGTH, SERIES
from .refusal import refuse

PROG = "scripts/study validate"
SUMMARY = "runs the validation matrix (here, or as a Slurm job array) and regenerates docs/validation.md"
# The entry point, for the tasks this runs in processes of their own and for the report and plots.
STUDY = os.path.join(ROOT, "scripts", "study")

DEFAULT_SLURM_WALL_BUDGET = 14400  # [s] a task's slice of wall time under Slurm before it requeues
SLURM_TIME_MARGIN = 600  # [s] the array's --time beyond the wall budget: set-up and the last write
NOTHING_TO_REPORT = 3  # validation_report's exit status for a folder without a run of Table 5's series
RECORD_FILES = (run_record.SUMMARY_FILE, "load.png", run_record.LOAD_BINS_FILE, run_record.LOADS_FILE, "profiles.csv")


fail = functools.partial(refuse, PROG)  # bad input: one line, exit status 2


def say(message, stream=sys.stdout):
    print("[validate] " + message, file=stream, flush=True)


def positive_int(flag, text):
    if not text.isdigit() or int(text) < 1:
        fail(f"{flag} {text}; allowed: a whole number > 0")
    return int(text)


def parse_args(argv):
    o = {"series": [], "seeds": [], "resolution": False, "until": None, "sets": [], "tag": "",
         "backend": "auto", "wall_budget": None, "resume": False, "accept_changed": False,
         "keep_existing": False, "bin": None, "work": os.path.join(ROOT, ".ws"),
         "records": None, "report": os.path.join(ROOT, "docs/validation.md"),
         "jobs": 1, "slurm": None, "collect": False, "report_only": False, "task": None, "strips": None}
    valued = {"--series", "--seeds", "--until-length", "--set", "--tag", "--backend", "--wall-budget", "--bin",
              "--work", "--records", "--report", "--jobs", "--strips"}
    i = 0
    while i < len(argv):
        flag = argv[i]
        if flag in ("-h", "--help"):
            print(__doc__)
            sys.exit(0)
        if flag == "--slurm":
            o["slurm"] = argv[i + 1:]
            break
        if flag == "--task":
            if len(argv) != i + 3:
                fail("--task takes the sweep folder and the task's index, and nothing after them")
            o["task"] = (argv[i + 1], argv[i + 2])
            break
        flags = {"--resolution": "resolution", "--resume": "resume", "--accept-changed-scenario": "accept_changed",
                 "--keep-existing": "keep_existing", "--collect": "collect", "--report-only": "report_only"}
        if flag in flags:
            o[flags[flag]] = True
            i += 1
            continue
        if flag not in valued:
            fail(f"unknown argument '{flag}'; see {PROG} --help")
        if i + 1 >= len(argv):
            fail(flag + " needs a value")
        value = argv[i + 1]
        i += 2
        if flag == "--series":
            if not os.path.isfile(os.path.join(ROOT, "config/scenarios", value + ".yaml")):
                fail(f"--series {value}: no config/scenarios/{value}.yaml; allowed: {' '.join(SERIES)} or another "
                     "scenario there")
            o["series"].append(value)
        elif flag == "--seeds":
            parts = value.split(",")
            if not all(p.isdigit() for p in parts):
                fail(f"--seeds {value}; allowed: whole numbers >= 0 separated by commas (e.g. 2,3)")
            o["seeds"] = [int(p) for p in parts]
        elif flag == "--until-length":
            try:
                ok = value == "end" or float(value) > 0
            except ValueError:
                ok = False
            if not ok:
                fail(f"--until-length {value}; allowed: a length > 0 m, or end")
            o["until"] = value
        elif flag == "--set":
            if "=" not in value or " " in value:
                fail(f"--set '{value}'; allowed: section.key=value, without spaces")
            o["sets"].append(value)
        elif flag == "--tag":
            if not value.isalnum() or value.lower() != value:
                fail(f"--tag {value}; allowed: lower-case letters and digits")
            o["tag"] = value
        elif flag == "--backend":
            if value not in ("cpu", "cuda", "auto"):
                fail(f"--backend {value}; allowed: cpu, cuda, auto")
            o["backend"] = value
        elif flag == "--wall-budget":
            o["wall_budget"] = positive_int(flag, value)
        elif flag == "--jobs":
            o["jobs"] = positive_int(flag, value)
        elif flag == "--strips":
            if not os.path.isfile(value):
                fail(f"--strips {value}: no such file; allowed: a strip matrix such as config/strips/validation.matrix")
            o["strips"] = os.path.abspath(value)
        else:
            o[flag[2:]] = os.path.abspath(value)
    if o["accept_changed"] and not o["resume"]:
        fail("--accept-changed-scenario goes with --resume only")
    if o["slurm"] is not None and o["jobs"] != 1:
        fail("--jobs is for runs on this machine; under --slurm the cluster runs the tasks")
    if o["strips"] and (o["series"] or o["seeds"] or o["resolution"] or o["tag"]):
        fail("--strips names its runs itself; --series, --seeds, --resolution and --tag go without it")
    if o["records"] is None:
        o["records"] = os.path.join(ROOT, "docs/validation/strips" if o["strips"] else "docs/validation/full")
    if not o["series"]:
        o["series"] = list(SERIES)
    return o


# ---------------------------------------------------------------------------------------------
# The matrix: one task per run, each run directory prepared for its task.

def scenario_path(series):
    return os.path.join(ROOT, "config/scenarios", series + ".yaml")


def pusher_travel(scenario, overrides):
    """The pusher's travel [m] (structure.toe_x - sheet.x_min) of a parsed scenario file with the
    --set overrides given for the run."""
    values = {"structure.toe_x": scenario["structure"]["toe_x"], "sheet.x_min": scenario["sheet"].get("x_min", 0.0)}
    for o in overrides:
        key, _, value = o.partition("=")
        if key in values:
            values[key] = value
    return float(values["structure.toe_x"]) - float(values["sheet.x_min"])


def default_length(run):
    """The experiment's pushed length (Table 5), or the pusher's travel where that is shorter."""
    series, name = run["series"], run["name"]
    travel = pusher_travel(scenario_file.load(run["scenario"]), run["overrides"])
    if series not in EXPERIMENT_LENGTH:
        fail(f"{name}: {series} has no experiment's length (Table 5): give --until-length")
    length = EXPERIMENT_LENGTH[series]
    if length > travel:
        # The full-width sheets are 24 m long: the travel ends at 24.05 m, short of four
        # experiments' pushed lengths (24.6-25.9 m); `thin_ice run` refuses a target beyond it.
        say(f"{name}: the experiment's L = {length} m is beyond the pusher's travel ({travel!r} m, "
            f"structure.toe_x - sheet.x_min): run to {travel!r} m")
        length = travel
    return repr(length)


def strip_matrix(path):
    """The runs of a strip matrix (strip.read_matrix), each with its strip's overrides."""
    runs = []
    try:
        for name, scenario, args in strip.read_matrix(path):
            scenario = os.path.join(ROOT, scenario)
            overrides, snapshots, length = strip.matrix_run(scenario, args)
            series = os.path.splitext(os.path.basename(scenario))[0]
            runs.append({"name": name, "series": series, "scenario": scenario, "overrides": overrides,
                         "snapshots": snapshots, "sheet_length": length})
    except (OSError, ValueError, KeyError, TypeError, yaml.YAMLError) as e:
        fail(f"--strips {path}: {e}")
    return runs


def matrix(o):
    """Every run asked for: its name, series, scenario file, overrides, and the snapshots it takes
    over its sheet's length (sheet_length None: that many over every segment)."""
    if o["strips"]:
        return strip_matrix(o["strips"])
    runs = []

    def run(name, series, overrides):
        runs.append({"name": name, "series": series, "scenario": scenario_path(series), "overrides": overrides,
                     "snapshots": 5, "sheet_length": None})

    for series in o["series"]:
        base = series + ("-" + o["tag"] if o["tag"] else "")
        run(base, series, [])
        for k in o["seeds"]:
            run(f"{base}-s{k}", series, [f"sheet.seed={k}"])
        if o["resolution"]:
            scenario = scenario_file.load(scenario_path(series))
            cell, dt = float(scenario["sheet"]["cell_size"]), float(scenario["numerics"]["time_step"])
            # Critical steps scale with the cell size (bonds: sqrt(m/k) ~ cell size; the structure:
            # ~ its square root), so the finer mesh steps at 0.85 dt with the same sub-step count.
            # 0.85 is as fine as the paper's A/h^2 > 10 lets 0.2 m cells of 52 mm ice go (0.17 m: 10.7).
            run(base + "-fine", series, [f"sheet.cell_size={0.85 * cell!r}", f"numerics.time_step={0.85 * dt!r}"])
            run(base + "-halfdt", series, [f"numerics.time_step={0.5 * dt!r}"])
    return runs


def completed_to(run_dir, length):
    """True where the run's summary.json says it completed to the pushed length `length` [m, as the
    task gives it]; False where it says otherwise or has no summary (or one that cannot be read)."""
    try:
        s = run_record.require_summary(run_dir)
        return (s[run_record.STATUS] == "completed"
                and abs(s[run_record.TARGET].get("pushed_length_m", -1) - float(length)) < 1e-9)
    except (OSError, ValueError, KeyError, TypeError):
        return False


def plan(o):
    """Prepares each run's directory and returns (tasks, refused names)."""
    tasks, refused = [], []
    for run in matrix(o):
        name = run["name"]
        length = o["until"] or default_length(run)
        record, run_dir = os.path.join(o["records"], name), os.path.join(o["work"], "validation", name)
        if o["keep_existing"] and completed_to(record, length):
            say(f"{name}: kept ({record}/summary.json: completed to L = {length} m)")
            continue
        has_checkpoint = os.path.isfile(os.path.join(record, run_record.CHECKPOINT_FILE))
        if not o["resume"] and has_checkpoint:
            # A run with a checkpoint in the records may be the history of several sessions:
            # starting it again from L = 0 would replace that history with a short new one.
            say(f"{name}: refused: {record} holds a checkpoint (a run that can go on); give --resume to carry it on, "
                "or remove that directory to start it again", sys.stderr)
            refused.append(name)
            continue
        if o["resume"] and not has_checkpoint:
            # Never start a run again in place of one that was asked to go on: the history stays.
            say(f"{name}: skipped: --resume, but {record}/checkpoint.bin is missing (run it without --resume to start "
                "it again)", sys.stderr)
            continue
        shutil.rmtree(run_dir, ignore_errors=True)  # nothing of an earlier run may be taken for this one's
        os.makedirs(run_dir)
        if o["resume"]:
            # The kept record and the checkpoint go on; loads.csv too where this copy has it (a
            # clone keeps only the bins: the resumed run then writes the new rows alone).
            for f in (run_record.SUMMARY_FILE, run_record.LOAD_BINS_FILE, run_record.CHECKPOINT_FILE,
                      run_record.LOADS_FILE):
                if f != run_record.LOADS_FILE or os.path.isfile(os.path.join(record, f)):
                    shutil.copy(os.path.join(record, f), run_dir)
        tasks.append({"name": name, "series": run["series"], "scenario": run["scenario"], "length": length,
                      "overrides": o["sets"] + run["overrides"], "snapshots": run["snapshots"],
                      "sheet_length": run["sheet_length"],
                      "run_dir": run_dir, "record": record, "resumed": o["resume"],
                      "keep_checkpoint": bool(o["tag"] or o["strips"])})
    return tasks, refused


def write_sweep(o, tasks, thin_ice):
    sweep = os.path.join(o["work"], "sweep")
    shutil.rmtree(sweep, ignore_errors=True)
    os.makedirs(os.path.join(sweep, "logs"))
    os.makedirs(os.path.join(sweep, "status"))
    description = {"thin_ice": thin_ice, "backend": o["backend"], "wall_budget_s": o["wall_budget"],
                   "accept_changed_scenario": o["accept_changed"], "one_thread": o["jobs"] > 1,
                   "records": o["records"], "report": o["report"], "tasks": tasks}
    with open(os.path.join(sweep, "sweep.json.new"), "w") as f:
        json.dump(description, f, indent=1)
    os.replace(os.path.join(sweep, "sweep.json.new"), os.path.join(sweep, "sweep.json"))
    return sweep


def read_sweep(sweep):
    try:
        with open(os.path.join(sweep, "sweep.json")) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        fail(f"no sweep to read in {sweep} ({e}); run {PROG} or {PROG} --slurm first")


def sweep_runner(description):
    """The command line that runs a task's simulation, up to its arguments: `thin_ice run`. A sweep
    written before the one program (its sweep.json names "thin_ice_run", the separate runner of
    then) may still have tasks to requeue: they take the thin_ice beside that runner, where one
    was built, and the old runner as it was named otherwise."""
    if "thin_ice" in description:
        return [description["thin_ice"], "run"]
    old_runner = description["thin_ice_run"]
    beside = os.path.join(os.path.dirname(old_runner), "thin_ice")
    return [beside, "run"] if os.access(beside, os.X_OK) else [old_runner]


# ---------------------------------------------------------------------------------------------
# One task: `thin_ice run` on its run directory, resumed where it holds a checkpoint.

def run_task(sweep, index_text):
    description = read_sweep(sweep)
    tasks = description["tasks"]
    if not index_text.isdigit() or int(index_text) >= len(tasks):
        fail(f"--task {sweep} {index_text}: allowed: an index 0..{len(tasks) - 1}")
    task = tasks[int(index_text)]
    name, run_dir = task["name"], task["run_dir"]
    snapshots = task.get("snapshots", 5)  # over a fresh run; a strip's resumed segment takes its share below
    log_path = os.path.join(sweep, "logs", name + ".log")
    status_path = os.path.join(sweep, "status", name + ".json")
    if (os.path.isfile(os.path.join(run_dir, run_record.CHECKPOINT_FILE))
            and os.path.isfile(run_record.summary_path(run_dir))):
        if completed_to(run_dir, task["length"]) or (task["length"] == "end" and completed_status(run_dir)):
            write_status(status_path, 0, "completed before")
            return 0
        command = ["--resume", run_dir]
        if snapshots and task.get("sheet_length"):
            # A strip keeps the spacing of its line's K snapshots over its sheet (scripts/study strip)
            # on every segment, a requeued slice's too.
            reached = float(run_record.require_summary(run_dir)[run_record.PUSHED_LENGTH])
            snapshots = strip.segment_snapshots(snapshots, task["sheet_length"], reached, task["length"])
        if description["accept_changed_scenario"]:
            command.append("--accept-changed-scenario")
    else:
        shutil.rmtree(run_dir, ignore_errors=True)  # a start that left no checkpoint starts again
        os.makedirs(run_dir)
        # (a sweep written before tasks named their scenario file names only the series)
        command = ["--scenario", task.get("scenario") or scenario_path(task["series"])]
        for s in task["overrides"]:
            command += ["--set", s]
        threads = os.environ.get("SLURM_CPUS_PER_TASK") or ("1" if description["one_thread"] else None)
        if threads:
            command += ["--set", "numerics.threads=" + threads]
        command += ["--out", run_dir]
    command = sweep_runner(description) + command + [
        "--backend", description["backend"], "--until-length", task["length"], "--profiles"]
    if snapshots:
        command += ["--snapshots", str(snapshots)]
    budget = description["wall_budget_s"]
    if budget is None and "SLURM_JOB_ID" in os.environ:
        budget = DEFAULT_SLURM_WALL_BUDGET

    signalled = []
    with open(log_path, "a") as log:
        log.write(f"[validate] {time.strftime('%Y-%m-%d %H:%M:%S')} {' '.join(command)}\n")
        log.flush()
        child = subprocess.Popen(command, cwd=ROOT, stdout=log, stderr=subprocess.STDOUT)

        def forward(signum, _frame):
            # Slurm's preemption, requeue, cancel or time limit (or Ctrl-C here): `thin_ice run`
            # finishes its output interval and writes its record; this task must not requeue itself.
            signalled.append(signum)
            child.send_signal(signal.SIGTERM)

        signal.signal(signal.SIGTERM, forward)
        signal.signal(signal.SIGINT, forward)
        try:
            code = child.wait(timeout=budget)
        except subprocess.TimeoutExpired:
            child.send_signal(signal.SIGTERM)  # the wall budget: exit status 4, everything written
            try:
                code = child.wait(timeout=120)
            except subprocess.TimeoutExpired:
                child.kill()
                code = child.wait()
    requeue = code == 4 and not signalled and "SLURM_JOB_ID" in os.environ
    write_status(status_path, code, "requeued" if requeue else ("signalled" if signalled else "ended"))
    if requeue:
        # The wall budget's slice is over and the target not reached: back into the queue, to
        # resume from the checkpoint just written (Slurm delays a requeued job's start ~2 min).
        subprocess.run(["scontrol", "requeue", os.environ["SLURM_JOB_ID"]], check=False)
    return code


def completed_status(run_dir):
    """True where the run's summary.json says it completed; False where it says otherwise or has no
    summary (or one that cannot be read)."""
    try:
        return run_record.require_summary(run_dir)[run_record.STATUS] == "completed"
    except (OSError, ValueError, KeyError):
        return False


def write_status(path, code, how):
    with open(path + ".new", "w") as f:
        json.dump({"exit_status": code, "how": how, "at": time.strftime("%Y-%m-%dT%H:%M:%S")}, f)
    os.replace(path + ".new", path)


# ---------------------------------------------------------------------------------------------
# Running here, submitting to Slurm, collecting.

def run_here(sweep, jobs):
    tasks = read_sweep(sweep)["tasks"]

    def one(index):
        say(f"{tasks[index]['name']}: {tasks[index]['series']} to L = {tasks[index]['length']} m "
            f"(log: {os.path.join(sweep, 'logs', tasks[index]['name'] + '.log')})")
        code = subprocess.run([sys.executable, STUDY, "validate", "--task", sweep, str(index)]).returncode
        say(f"{tasks[index]['name']}: exit status {code}")

    with ThreadPoolExecutor(max_workers=jobs) as pool:
        list(pool.map(one, range(len(tasks))))


def submit(o, sweep, sbatch_options):
    tasks = read_sweep(sweep)["tasks"]
    budget = o["wall_budget"] or DEFAULT_SLURM_WALL_BUDGET
    minutes = -(-(budget + SLURM_TIME_MARGIN) // 60)
    script = os.path.join(sweep, "array.sbatch")
    with open(script, "w") as f:
        f.write("#!/bin/bash\n"
                f"# One task per run of the validation matrix (written by {PROG} --slurm).\n"
                "# Options given to sbatch on its command line win over these.\n"
                "#SBATCH --job-name=thin_ice_validate\n"
                f"#SBATCH --array=0-{len(tasks) - 1}\n"
                "#SBATCH --requeue\n"
                "#SBATCH --open-mode=append\n"
                f"#SBATCH --output={os.path.join(sweep, 'logs', 'slurm_%a.out')}\n"
                f"#SBATCH --time={minutes}\n"
                "#SBATCH --ntasks=1\n"
                "#SBATCH --cpus-per-task=1\n"
                f"exec /usr/bin/python3 {STUDY} validate --task {sweep} \"$SLURM_ARRAY_TASK_ID\"\n")
    with open(os.path.join(sweep, "sweep.json")) as f:
        description = json.load(f)
    description["wall_budget_s"] = budget
    with open(os.path.join(sweep, "sweep.json"), "w") as f:
        json.dump(description, f, indent=1)
    done = subprocess.run(["sbatch", "--parsable"] + sbatch_options + [script], stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        say(f"sbatch refused the array ({script}): {done.stderr.strip()}", sys.stderr)
        return 1
    job = done.stdout.strip().split(";")[0]
    say(f"submitted {len(tasks)} tasks as job array {job}; when it is done: {PROG} --collect"
        + ("" if o["work"] == os.path.join(ROOT, ".ws") else f" --work {o['work']}"), sys.stderr)
    print(job)
    return 0


def last_line(path):
    try:
        with open(path, errors="replace") as f:
            lines = [line.strip() for line in f if line.strip()]
        return lines[-1] if lines else "(empty log)"
    except OSError:
        return "(no log)"


def collect(sweep):
    """Copies each run that wrote a record, reports the tasks that failed; the names of the
    failed and unfinished tasks."""
    description = read_sweep(sweep)
    failed, unfinished = [], []
    for task in description["tasks"]:
        name, run_dir, record = task["name"], task["run_dir"], task["record"]
        log = os.path.join(sweep, "logs", name + ".log")
        try:
            with open(os.path.join(sweep, "status", name + ".json")) as f:
                status = json.load(f)
        except (OSError, ValueError):
            say(f"{name}: not finished (no end status yet: pending or running)")
            unfinished.append(name)
            continue
        code = status["exit_status"]
        if status["how"] == "requeued":
            say(f"{name}: in progress (stopped by its wall budget and requeued); copied as far as it got")
            unfinished.append(name)
        elif code not in (0, 4):
            say(f"{name}: failed, exit status {code}: {last_line(log)}", sys.stderr)
            failed.append(name)
            if task["resumed"]:
                say(f"{name}: {record} left as it was", sys.stderr)  # refused, or an unhealthy segment
                continue
        if not (os.path.isfile(os.path.join(run_dir, run_record.LOAD_BINS_FILE))
                and os.path.isfile(run_record.summary_path(run_dir))):
            say(f"{name}: no load_bins.csv and summary.json in {run_dir}: nothing copied", sys.stderr)
            continue
        subprocess.run([STUDY, "plot", run_dir], check=False)
        os.makedirs(record, exist_ok=True)
        # Each file copied beside its old one first and renamed over it: an interrupted copy leaves
        # the recorded file whole.
        for f in RECORD_FILES + ((run_record.CHECKPOINT_FILE,) if task["keep_checkpoint"] else ()):
            if os.path.isfile(os.path.join(run_dir, f)):
                shutil.copy(os.path.join(run_dir, f), os.path.join(record, f + ".new"))
                os.replace(os.path.join(record, f + ".new"), os.path.join(record, f))
            elif f == run_record.CHECKPOINT_FILE:
                if os.path.exists(os.path.join(record, f)):
                    os.remove(os.path.join(record, f))
    return failed, unfinished


def write_report(records, report):
    """The report over the folder that holds the records (docs/validation: its full/ and strips/).
    A folder without a run of Table 5's series (a matrix of the quick scenario) has nothing to
    report: the report is left as it was, and that is not a failure of the sweep."""
    runs = os.path.dirname(os.path.abspath(records))
    done = subprocess.run([sys.executable, STUDY, "validation_report", "--runs", runs, "--out", report])
    if done.returncode == 0:
        say("wrote " + report)
    elif done.returncode == NOTHING_TO_REPORT:
        say(f"{report} left as it was: {runs} holds no run of Table 5's series")
        return 0
    return done.returncode


def build():
    """Installs and builds as the README's commands do; the folder of the thin_ice program."""
    done = subprocess.run(["bash", "-c", 'source "$1/scripts/setup.sh" && thin_ice_install && thin_ice_build',
                           "validate", ROOT])
    if done.returncode != 0:
        say("the set-up or the build failed", sys.stderr)
        sys.exit(1)
    return os.path.join(ROOT, ".ws/devel/lib/thin_ice_sim")


def main(argv):
    o = parse_args(argv)
    if o["task"]:
        return run_task(*o["task"])
    if o["report_only"]:
        return 1 if write_report(o["records"], o["report"]) else 0
    sweep = os.path.join(o["work"], "sweep")
    if o["collect"]:
        description = read_sweep(sweep)
        failed, unfinished = collect(sweep)
        code = write_report(description["records"], description["report"])
        if failed or unfinished:
            say(f"failed: {' '.join(failed) or 'none'}; not finished: {' '.join(unfinished) or 'none'}", sys.stderr)
        return 1 if failed or unfinished or code else 0
    thin_ice = os.path.join(o["bin"] or build(), "thin_ice")
    if not os.access(thin_ice, os.X_OK):
        fail(f"--bin {o['bin']}: no thin_ice there")
    tasks, refused = plan(o)
    if not tasks:
        say("no run to do")
        return 1 if refused else 0
    sweep = write_sweep(o, tasks, thin_ice)
    if o["slurm"] is not None:
        return submit(o, sweep, o["slurm"]) or (1 if refused else 0)
    run_here(sweep, o["jobs"])
    failed, unfinished = collect(sweep)
    code = write_report(o["records"], o["report"])
    if failed or refused or unfinished:
        say(f"runs that ended early or were refused: {' '.join(refused + failed + unfinished)}", sys.stderr)
    return 1 if failed or refused or unfinished or code else 0
