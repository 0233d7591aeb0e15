"""Records the simulator's structure load from ROS as a run directory that scripts/study plot reads.

usage: scripts/study record_loads OUT_DIR [--every SECONDS]
Subscribes to structure/wrench and sim/status, prints a line every SECONDS of simulated time
(default 0.1), writes OUT_DIR/loads.csv and OUT_DIR/summary.json when the simulator goes away
(or on Ctrl-C). The wrench is the calibrated load (alpha of Eq. 18 applied by the node).
"""
import argparse
import json
import os
import sys
import time

import rospy
from geometry_msgs.msg import WrenchStamped

from . import run_record
from .run_summary import replace_files

try:  # the package's messages exist only in a built and sourced catkin workspace
    from thin_ice_sim.msg import PanelLoads, SimStatus
    MESSAGES_MISSING = None
except ImportError as error:
    MESSAGES_MISSING = error

PROG = "scripts/study record_loads"
SUMMARY = "records the simulator's structure load from ROS as a run directory (the demo's recorder)"


class Recorder:
    def __init__(self, out_dir, every):
        self.out_dir = out_dir
        self.every = every
        self.rows = []
        self.status = None
        self.next_print = 0.0
        self.last_status_wall = None
        self.written = False
        self.alpha = None  # calibration factor of Eq. (18), from structure/panel_loads
        rospy.Subscriber("structure/panel_loads", PanelLoads, self.on_panels, queue_size=10)
        rospy.Subscriber("structure/wrench", WrenchStamped, self.on_wrench, queue_size=1000)
        rospy.Subscriber("sim/status", SimStatus, self.on_status, queue_size=10)

    def on_panels(self, msg):
        self.alpha = msg.calibration_factor

    def on_status(self, msg):
        self.status = msg
        self.last_status_wall = time.time()

    def write_once(self):
        if not self.written:
            self.write()

    def on_wrench(self, msg):
        t = msg.header.stamp.to_sec()
        # The status comes at 10 Hz of wall time: carry its pushed length to this stamp with the
        # pusher velocity it reports.
        pushed = 0.0
        if self.status:
            pushed = self.status.pushed_length + self.status.pusher_velocity * (t - self.status.sim_time)
        broken = self.status.broken_bonds if self.status else 0
        self.rows.append((t, pushed, msg.wrench.force.x, msg.wrench.force.z, broken))
        if t >= self.next_print:
            print("t %6.2f s  L %6.3f m  F_cal %9.1f N  F_z %9.1f N  broken bonds %d"
                  % (t, pushed, msg.wrench.force.x, msg.wrench.force.z, broken), flush=True)
            self.next_print = t + self.every

    def write(self):
        self.written = True
        os.makedirs(self.out_dir, exist_ok=True)
        alpha = self.alpha or 1.0
        # loads.csv in the record's own columns (run_record.LOAD_COLUMNS, the mirror of run_record.hpp),
        # each row keyed by column; what ROS does not carry (pusher force, intact bonds, contacts) is 0.
        lines = [",".join(run_record.LOAD_COLUMNS) + "\n"]
        for t, pushed, fx, fz, broken in self.rows:
            row = {run_record.TIME: "%.6f" % t, run_record.PUSHED_LENGTH: "%.6f" % pushed,
                   run_record.HORIZONTAL_RAW: "%.6f" % run_record.raw_of(fx, alpha),
                   run_record.HORIZONTAL_CALIBRATED: "%.6f" % fx,
                   run_record.VERTICAL_RAW: "%.6f" % run_record.raw_of(fz, alpha),
                   run_record.PUSHER_FORCE: "0", run_record.INTACT_BONDS: "0", run_record.BROKEN_BONDS: "%d" % broken,
                   run_record.CONTACTS: "0"}
            lines.append(",".join(row[column] for column in run_record.LOAD_COLUMNS) + "\n")
        name = self.status.backend if self.status else "?"
        summary = {run_record.SCHEMA_VERSION: run_record.SUMMARY_SCHEMA_VERSION, run_record.STATUS: "completed",
                   run_record.SCENARIO: {"name": "recorded from ROS"}, run_record.BACKEND: name,
                   run_record.CALIBRATION_FACTOR: alpha}
        # Both files replaced together once both are written: an interrupted write leaves the old
        # pair (or none), never a truncated loads.csv.
        loads = os.path.join(self.out_dir, run_record.LOADS_FILE)
        replace_files({loads: "".join(lines),
                       os.path.join(self.out_dir, run_record.SUMMARY_FILE): json.dumps(summary, indent=2)})
        print("wrote %d rows to %s" % (len(self.rows), loads))


def positive_seconds(text):
    try:
        value = float(text)
    except ValueError:
        value = float("nan")
    if not (0.0 < value < float("inf")):
        raise argparse.ArgumentTypeError(f"'{text}' is invalid; allowed: a time > 0 [s]")
    return value


def main(argv):
    parser = argparse.ArgumentParser(prog=PROG,
                                     description="Records the structure load from ROS as a run directory.")
    parser.add_argument("out_dir", metavar="OUT_DIR", help="where loads.csv and summary.json go")
    parser.add_argument("--every", type=positive_seconds, default=0.1, metavar="SECONDS",
                        help="[s] of simulated time between printed lines (default 0.1)")
    args = parser.parse_args(rospy.myargv(argv))  # without ROS remappings (name:=value)
    if MESSAGES_MISSING is not None:
        print(f"{PROG}: the thin_ice_sim messages cannot be imported ({MESSAGES_MISSING}); allowed: a run "
              "with the catkin workspace built and sourced (source .ws/devel/setup.bash), as scripts/demo does",
              file=sys.stderr)
        return 2
    rospy.init_node("record_loads", anonymous=True)
    recorder = Recorder(args.out_dir, args.every)
    rospy.on_shutdown(recorder.write_once)
    # Stop when the simulator has gone: its status (10 Hz of wall time) stops arriving. The master
    # may go with it (roslaunch started one), so no master query is used.
    silence_limit = 3.0  # [s] wall
    while not rospy.is_shutdown():
        time.sleep(0.2)
        if recorder.last_status_wall is not None and time.time() - recorder.last_status_wall > silence_limit:
            break
    recorder.write()
