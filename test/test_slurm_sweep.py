#!/usr/bin/python3
"""scripts/study validate --slurm on a real one-node Slurm cluster brought up here (Debian's slurm-wlm
and munge; a private configuration, state and socket folder under .ws/slurm_test; the daemons
started by this test and stopped whatever happens):

  1. a matrix of three quick runs goes in as one job array; one task is requeued halfway (as a
     preemption would: Slurm sends SIGTERM, `thin_ice run` writes its record and checkpoint) and
     resumes from its checkpoint; --collect copies the three records and rebuilds the report;
  2. the same matrix run here (--jobs 2) gives the same loads.csv, byte for byte: the requeued
     run lost nothing and repeated nothing;
  3. a task given a wall budget shorter than its run stops, requeues itself and goes on, slice by
     slice, to the end; its record is the first rows of the longer run of step 1;
  4. a task that fails is reported by --collect with its log's last line, and --collect exits 1.

Slurm holds a requeued job back ~2 minutes before it may start again; the test lifts that hold
(scontrol update StartTime=now), as an administrator could.

    test_slurm_sweep.py THIN_ICE_DIR SOURCE_DIR   (THIN_ICE_DIR: the folder of the thin_ice program)
Exit status 77 (skipped) where the daemons are not installed or this is not root.
"""
import json
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time

DAEMONS = ("munged", "slurmctld", "slurmd", "sbatch", "squeue", "scontrol", "sinfo")


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Cluster:
    """One controller and one compute node on 127.0.0.1, and their munge daemon."""

    def __init__(self, folder):
        self.folder = folder
        # A Unix socket's path holds at most 107 bytes: a deep checkout puts munge's in /tmp.
        self.munge = os.path.join(folder, "munge")
        if len(os.path.join(self.munge, "munge.socket")) > 100:
            self.munge = tempfile.mkdtemp(prefix="thin_ice_munge_")
        self.conf = os.path.join(folder, "slurm.conf")
        self.env = dict(os.environ, SLURM_CONF=self.conf)
        self.pids = {}

    def write(self):
        for d in ("state", "spool", "log"):
            os.makedirs(os.path.join(self.folder, d), exist_ok=True)
        os.makedirs(self.munge, exist_ok=True)
        os.chmod(self.munge, 0o711)
        key = os.path.join(self.munge, "munge.key")
        with open(key, "wb") as f:
            f.write(os.urandom(1024))
        os.chmod(key, 0o400)
        host = socket.gethostname().split(".")[0]
        f = self.folder
        with open(self.conf, "w") as c:
            c.write(f"""ClusterName=thinicetest
SlurmctldHost={host}(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket={self.munge}/munge.socket
SlurmctldPort={free_port()}
SlurmdPort={free_port()}
StateSaveLocation={f}/state
SlurmdSpoolDir={f}/spool
SlurmctldPidFile={f}/slurmctld.pid
SlurmdPidFile={f}/slurmd.pid
SlurmctldLogFile={f}/log/slurmctld.log
SlurmdLogFile={f}/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
ReturnToService=2
KillWait=30
MinJobAge=600
NodeName=sweeptest NodeAddr=127.0.0.1 CPUs={os.cpu_count()} State=UNKNOWN
PartitionName=sweep Nodes=sweeptest Default=YES MaxTime=INFINITE State=UP
""")

    def start(self):
        self.write()
        m = self.munge
        subprocess.run(["munged", "--force", f"--key-file={m}/munge.key", f"--socket={m}/munge.socket",
                        f"--pid-file={m}/munged.pid", f"--log-file={m}/munged.log", f"--seed-file={m}/munged.seed"],
                       check=True)
        self.pids["munged"] = f"{m}/munged.pid"
        subprocess.run(["slurmctld", "-f", self.conf], check=True, env=self.env)
        self.pids["slurmctld"] = f"{self.folder}/slurmctld.pid"
        subprocess.run(["slurmd", "-f", self.conf, "-N", "sweeptest"], check=True, env=self.env)
        self.pids["slurmd"] = f"{self.folder}/slurmd.pid"
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline:
            state = subprocess.run(["sinfo", "-h", "-o", "%t"], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                                   text=True, env=self.env).stdout.strip()
            if state == "idle":
                return
            time.sleep(0.2)
        raise RuntimeError(f"the node did not come up (sinfo: {state!r}); logs in {self.folder}/log")

    def run(self, *args):
        return subprocess.run(list(args), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=self.env)

    def stop(self):
        """Cancels every job and stops the three daemons, waiting for each to be gone."""
        self.run("scancel", "--full", "--user=root")
        for name in ("slurmd", "slurmctld", "munged"):
            pid = self.read_pid(name)
            if pid is None:
                continue
            try:
                os.kill(pid, 15)
            except ProcessLookupError:
                continue
            for _ in range(100):
                if not os.path.exists(f"/proc/{pid}"):
                    break
                time.sleep(0.1)
            else:
                os.kill(pid, 9)

    def read_pid(self, name):
        try:
            with open(self.pids[name]) as f:
                return int(f.read().strip())
        except (KeyError, OSError, ValueError):
            return None

    def leftovers(self):
        """Processes still running from this cluster's configuration or munge folder."""
        # (a zombie, state Z, is gone but for its parent's wait: in a container whose first
        # process does not reap, a daemon's exit leaves one)
        out = subprocess.run(["ps", "-eo", "pid,stat,args"], stdout=subprocess.PIPE, text=True).stdout.splitlines()[1:]
        return [line for line in out if (self.conf in line or self.munge in line or "slurmstepd" in line)
                and line.split()[1][0] != "Z" and "ps -eo" not in line]

    def wait_for(self, job, timeout):
        """Waits until the job array has left the queue, lifting Slurm's hold on requeued tasks."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            queue = self.run("squeue", "-h", "-j", job, "-o", "%i %T %r").stdout.split("\n")
            queue = [line.split() for line in queue if line.strip()]
            if not queue:
                return True
            for task, state, reason in queue:
                if state == "PENDING" and reason == "BeginTime":
                    self.run("scontrol", "update", f"JobId={task}", "StartTime=now")
            time.sleep(0.3)
        return False


def validate(source, *args, env):
    return subprocess.run(["/usr/bin/python3", os.path.join(source, "scripts/study"), "validate"] + list(args),
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env, timeout=600)


def rows(path):
    with open(path) as f:
        return f.read().splitlines()


def main():
    bin_dir, source = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    if os.geteuid() != 0 or any(shutil.which(d) is None for d in DAEMONS):
        print("skipped: needs root and Debian's slurm-wlm and munge (scripts/setup.sh installs them)")
        sys.exit(77)
    folder = os.path.join(source, ".ws/slurm_test")
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    cluster = Cluster(os.path.join(folder, "cluster"))
    failures = []
    started = time.monotonic()

    def where(name):
        w = os.path.join(folder, name)
        return ["--bin", bin_dir, "--work", w, "--records", os.path.join(w, "records"),
                "--report", os.path.join(w, "report.md")]

    matrix = ["--series", "quick", "--seeds", "2,3", "--until-length", "1.0"]
    names = ("quick", "quick-s2", "quick-s3")
    try:
        cluster.start()
        print(f"cluster up in {time.monotonic() - started:.1f} s")
        # 1. The array, one task requeued halfway.
        sub = validate(source, *matrix, *where("array"), "--slurm", env=cluster.env)
        job = sub.stdout.strip()
        if sub.returncode != 0 or not job.isdigit():
            raise RuntimeError(f"--slurm: exit status {sub.returncode}, stdout {sub.stdout!r}, stderr {sub.stderr!r}")
        partial = os.path.join(folder, "array/validation/quick-s2/loads.csv.partial")
        deadline = time.monotonic() + 90
        while time.monotonic() < deadline and not (os.path.exists(partial) and len(rows(partial)) > 200):
            time.sleep(0.05)  # past t = 2 s of the run's 5 s
        requeue = cluster.run("scontrol", "requeue", f"{job}_1")
        if requeue.returncode != 0:
            failures.append(f"scontrol requeue {job}_1: {requeue.stderr.strip()}")
        if not cluster.wait_for(job, 120):
            raise RuntimeError(f"job array {job} still in the queue after 120 s")
        got = validate(source, "--collect", "--work", os.path.join(folder, "array"), env=cluster.env)
        if got.returncode != 0:
            failures.append(f"--collect: exit status {got.returncode}: {got.stderr.strip()[-500:]}")
        for name in names:
            with open(os.path.join(folder, "array/records", name, "summary.json")) as f:
                s = json.load(f)
            resumed = len(s["resumed_at_m"])
            if s["status"] != "completed" or s["pushed_length_m"] != 1.0 or (resumed > 0) != (name == "quick-s2"):
                failures.append(f"{name}: status {s['status']}, L {s['pushed_length_m']}, resumed at {s['resumed_at_m']}; "
                                f"expected completed to 1 m, resumed {'once' if name == 'quick-s2' else 'never'}")
        # quick is not a series of Table 5: the report has nothing to say and is not written, and
        # that does not fail the sweep.
        if os.path.exists(os.path.join(folder, "array/report.md")) or "holds no run of Table 5" not in got.stdout + got.stderr:
            failures.append("--collect of a quick matrix wrote a report, or did not say why it wrote none")
        print(f"array with a requeued task done at {time.monotonic() - started:.1f} s")

        # 2. The same matrix here, two at a time: the same records, byte for byte.
        here = validate(source, *matrix, *where("here"), "--jobs", "2", env=cluster.env)
        if here.returncode != 0:
            failures.append(f"the matrix here: exit status {here.returncode}: {here.stderr.strip()[-500:]}")
        for name in names:
            a, b = (os.path.join(folder, w, "records", name, "loads.csv") for w in ("array", "here"))
            if not (os.path.isfile(b) and rows(a) == rows(b)):
                failures.append(f"{name}: loads.csv from the array differs from the run made here")
        print(f"the matrix here done at {time.monotonic() - started:.1f} s")

        # 3. A wall budget of 1 s: the task requeues itself slice by slice to L = 0.6 m.
        sub = validate(source, "--series", "quick", "--until-length", "0.6", "--wall-budget", "1", *where("slices"),
                       "--slurm", env=cluster.env)
        job = sub.stdout.strip()
        if sub.returncode != 0 or not job.isdigit() or not cluster.wait_for(job, 120):
            raise RuntimeError(f"the sliced task: exit status {sub.returncode}, {sub.stderr.strip()[-300:]}")
        got = validate(source, "--collect", "--work", os.path.join(folder, "slices"), env=cluster.env)
        with open(os.path.join(folder, "slices/records/quick/summary.json")) as f:
            s = json.load(f)
        sliced = rows(os.path.join(folder, "slices/records/quick/loads.csv"))
        whole = rows(os.path.join(folder, "array/records/quick/loads.csv"))
        if got.returncode != 0 or s["status"] != "completed" or len(s["resumed_at_m"]) < 1:
            failures.append(f"the sliced task: --collect {got.returncode}, status {s['status']}, resumed at "
                            f"{s['resumed_at_m']}; expected 0, completed, resumed at least once")
        if len(sliced) < 2 or sliced != whole[:len(sliced)]:
            failures.append(f"the sliced task's {len(sliced)} rows are not the first rows of the whole run's")
        print(f"sliced task ({len(s['resumed_at_m'])} requeues) done at {time.monotonic() - started:.1f} s")

        # 4. A task that fails: reported with its log's last line.
        sub = validate(source, "--series", "quick", "--until-length", "0.2", "--set", "numerics.time_step=1",
                       *where("failing"), "--slurm", env=cluster.env)
        job = sub.stdout.strip()
        if sub.returncode != 0 or not job.isdigit() or not cluster.wait_for(job, 60):
            raise RuntimeError(f"the failing task: exit status {sub.returncode}, {sub.stderr.strip()[-300:]}")
        got = validate(source, "--collect", "--work", os.path.join(folder, "failing"), env=cluster.env)
        expected = "quick: failed, exit status 2: thin_ice run: "
        if got.returncode != 1 or expected not in got.stderr or "numerics.time_step" not in got.stderr:
            failures.append(f"the failing task's --collect: exit status {got.returncode}, stderr {got.stderr.strip()!r}; "
                            f"expected 1 and {expected!r} naming numerics.time_step")
    except (RuntimeError, OSError, subprocess.SubprocessError, ValueError, KeyError) as e:
        failures.append(f"{type(e).__name__}: {e}")
    finally:
        cluster.stop()
    left = cluster.leftovers()
    if left:
        failures.append("processes left behind: " + "; ".join(left))
    if failures:
        print(f"logs: {cluster.folder}/log")
        for f in failures:
            print("FAIL: " + f)
        sys.exit(1)
    if cluster.munge != os.path.join(cluster.folder, "munge"):
        shutil.rmtree(cluster.munge, ignore_errors=True)
    shutil.rmtree(folder, ignore_errors=True)
    print(f"ok: Slurm sweep test in {time.monotonic() - started:.1f} s, no process left behind")


if __name__ == "__main__":
    main()
