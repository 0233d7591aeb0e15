#!/usr/bin/python3
"""rostest of the thin_ice_sim node's interface (test/node_interface.test).

The tests run in name order against one node: rate and stamps, markers, pusher commands (speed,
clamping, dropping, timeout), pause/step/reset, and finally the loads once the ice reaches the
structure.
"""
import math
import os
import re
import threading
import time
import unittest

import rospkg
import rospy
import rostest
import tf2_ros
import yaml
from geometry_msgs.msg import Twist, WrenchStamped
from rosgraph_msgs.msg import Clock
from std_srvs.srv import Empty, Trigger
from visualization_msgs.msg import Marker, MarkerArray

from thin_ice_sim.msg import PanelLoads, SimStatus
from thin_ice_sim.srv import Step

LOAD_PERIOD = 0.01  # [s] of simulated time: 1 / ~load_rate
# [s] quick.yaml's dt, read from the file so that a new step there does not break these tests
with open(os.path.join(rospkg.RosPack().get_path("thin_ice_sim"), "config", "scenarios", "quick.yaml")) as f:
    QUICK = yaml.safe_load(f)
TIME_STEP = float(QUICK["numerics"]["time_step"])
TOE_X = 2.0  # [m] structure.toe_x as node_interface.test sets it
LOAD_ARROW_SCALE = 0.003  # [m per N/m of structure width] ~load_arrow_scale's default


class NodeInterfaceTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_node_interface")
        cls.lock = threading.Lock()
        cls.wrenches = []
        cls.panels = []
        cls.clocks = []
        cls.status = None
        cls.markers = None
        rospy.Subscriber("structure/wrench", WrenchStamped, cls._on_wrench, queue_size=1000)
        rospy.Subscriber("structure/panel_loads", PanelLoads, cls._on_panels, queue_size=100)
        rospy.Subscriber("/clock", Clock, cls._on_clock, queue_size=1000)
        rospy.Subscriber("sim/status", SimStatus, cls._on_status, queue_size=10)
        rospy.Subscriber("ice/cells", MarkerArray, cls._on_markers, queue_size=2)
        cls.command = rospy.Publisher("pusher/cmd_vel", Twist, queue_size=10)
        for name in ("sim/pause", "sim/unpause", "sim/unpause_checked", "sim/reset", "sim/step"):
            rospy.wait_for_service(name, timeout=60.0)
        # pause, unpause and reset are std_srvs/Empty, as Gazebo's; unpause_checked is the Trigger
        # variant that answers why it refused.
        cls.pause = rospy.ServiceProxy("sim/pause", Empty)
        cls.unpause = rospy.ServiceProxy("sim/unpause", Empty)
        cls.unpause_checked = rospy.ServiceProxy("sim/unpause_checked", Trigger)
        cls.reset = rospy.ServiceProxy("sim/reset", Empty)
        cls.step = rospy.ServiceProxy("sim/step", Step)
        cls.tf_buffer = tf2_ros.Buffer()
        cls.tf_listener = tf2_ros.TransformListener(cls.tf_buffer)

    @classmethod
    def _on_wrench(cls, msg):
        with cls.lock:
            cls.wrenches.append(msg)

    @classmethod
    def _on_panels(cls, msg):
        with cls.lock:
            cls.panels.append(msg)

    @classmethod
    def _on_clock(cls, msg):
        with cls.lock:
            cls.clocks.append(msg.clock.to_sec())

    @classmethod
    def _on_status(cls, msg):
        with cls.lock:
            cls.status = msg

    @classmethod
    def _on_markers(cls, msg):
        with cls.lock:
            cls.markers = msg

    def wait_for(self, predicate, timeout, what):
        deadline = time.time() + timeout
        while time.time() < deadline:
            if predicate():
                return
            time.sleep(0.02)
        self.fail("timed out after %.0f s waiting for %s" % (timeout, what))

    def latest_status(self, after_wall=None):
        """A status message received after now (the node publishes it at 10 Hz of wall time)."""
        with self.lock:
            self.__class__.status = None
        self.wait_for(lambda: self.status is not None, 10.0, "sim/status")
        return self.status

    def pusher_x(self):
        t = self.tf_buffer.lookup_transform("world", "pusher", rospy.Time(0), rospy.Duration(5.0))
        return t.transform.translation.x, t.header.stamp.to_sec()

    def send(self, velocity, seconds):
        """Publishes a pusher command at 20 Hz for `seconds` of wall time."""
        end = time.time() + seconds
        while time.time() < end:
            self.command.publish(self._twist(velocity))
            time.sleep(0.05)

    @staticmethod
    def _twist(velocity):
        t = Twist()
        t.linear.x = velocity
        return t

    def test_01_wrench_rate_and_stamps_follow_the_clock(self):
        self.wait_for(lambda: len(self.wrenches) > 50, 60.0, "50 wrench messages")
        with self.lock:
            stamps = [w.header.stamp.to_sec() for w in self.wrenches[-50:]]
            frames = {w.header.frame_id for w in self.wrenches}
            clocks = list(self.clocks)
        gaps = [b - a for a, b in zip(stamps, stamps[1:])]
        self.assertTrue(all(g > 0 for g in gaps), "stamps must increase")
        gaps.sort()
        self.assertAlmostEqual(gaps[len(gaps) // 2], LOAD_PERIOD, delta=0.01 * LOAD_PERIOD)
        self.assertEqual(frames, {"structure"})
        self.assertTrue(clocks, "no /clock message")
        self.assertGreaterEqual(max(clocks) + 1e-9, stamps[0])
        self.assertTrue(all(b >= a for a, b in zip(clocks, clocks[1:])), "/clock went backwards")
        with self.lock:
            self.assertTrue(self.panels and len(self.panels[-1].panels) == 2, "two panel wrenches")

    def test_02_markers_arrive(self):
        self.wait_for(lambda: self.markers is not None, 30.0, "ice/cells markers")
        namespaces = {m.ns: m for m in self.markers.markers}
        for ns in ("cells", "outlines", "structure", "pusher", "bottom", "load", "readout", "legend"):
            self.assertIn(ns, namespaces)
        self.assertGreater(len(namespaces["cells"].points), 0)
        self.assertEqual(len(namespaces["cells"].points), len(namespaces["cells"].colors))

    def test_03_pusher_moves_at_the_commanded_speed(self):
        self.send(0.1, 1.0)  # the command is in effect
        x0, t0 = self.pusher_x()
        self.send(0.1, 2.0)
        x1, t1 = self.pusher_x()
        self.assertGreater(t1 - t0, 0.02, "simulated time did not advance")
        self.assertAlmostEqual((x1 - x0) / (t1 - t0), 0.1, delta=0.02 * 0.1)

    def test_04_bad_commands_are_clamped_or_dropped(self):
        self.send(5.0, 0.5)
        self.assertAlmostEqual(self.latest_status().pusher_velocity, 0.5, delta=1e-9)  # ~max_pusher_speed
        # Dropped commands do not feed the ~cmd_timeout watchdog (1 s here), so the check below
        # must come well inside 1 s of the last valid command: 0.1 + 0.2 + 0.2 + 0.1 s.
        self.send(float("nan"), 0.2)
        self.send(float("inf"), 0.2)
        self.assertAlmostEqual(self.latest_status().pusher_velocity, 0.5, delta=1e-9)  # dropped
        self.send(-5.0, 0.3)
        self.assertAlmostEqual(self.latest_status().pusher_velocity, -0.5, delta=1e-9)

    def test_05_pusher_stops_after_the_command_timeout(self):
        self.send(0.1, 0.5)
        # ~cmd_timeout is 1 s of simulated time. The node runs as fast as the CPU lets it, which on
        # a busy 2-core machine may be slower than real time: wait for the simulated second (and
        # a fifth more), not for a wall-time guess of it.
        last_command = self.latest_status().sim_time
        self.wait_for(lambda: self.latest_status().sim_time > last_command + 1.2, 120.0,
                      "1.2 s of simulated time after the last command")
        self.assertEqual(self.latest_status().pusher_velocity, 0.0)
        x0, t0 = self.pusher_x()
        time.sleep(0.5)
        x1, t1 = self.pusher_x()
        self.assertGreater(t1, t0)
        self.assertAlmostEqual(x1, x0, delta=1e-12)

    def test_06_pause_step_and_reset(self):
        self.pause()
        time.sleep(0.3)
        before = self.latest_status()
        time.sleep(0.5)
        after = self.latest_status()
        self.assertTrue(after.paused)
        self.assertEqual(after.sim_time, before.sim_time)
        answer = self.step(steps=0, duration=0.05)
        self.assertTrue(answer.success, answer.message)
        self.assertAlmostEqual(answer.sim_time - before.sim_time, 0.05, delta=TIME_STEP)
        answer = self.step(steps=100, duration=0.0)
        self.assertAlmostEqual(answer.sim_time - before.sim_time, 0.05 + 100 * TIME_STEP, delta=1e-9)
        # A duration rounds up to whole steps: the tiniest positive one is one step.
        tiny = self.step(steps=0, duration=1e-300)
        self.assertTrue(tiny.success, tiny.message)
        self.assertIn("stepped 1 steps", tiny.message)
        self.assertAlmostEqual(tiny.sim_time - answer.sim_time, TIME_STEP, delta=1e-12)
        answer = tiny
        # Requests beyond ~max_steps_per_call are refused, not run for days or cast into a
        # negative count: a huge duration, and 2^32 - 1 steps (what -1 becomes in the uint32).
        for steps, duration in ((0, 1e300), (2**32 - 1, 0.0)):
            refused = self.step(steps=steps, duration=duration)
            self.assertFalse(refused.success)
            self.assertIn("max_steps_per_call", refused.message)
            self.assertEqual(refused.sim_time, answer.sim_time)
        self.reset()
        status = self.latest_status()
        self.assertEqual(status.sim_time, 0.0)
        self.assertEqual(status.pushed_length, 0.0)
        self.assertEqual(status.broken_bonds, 0)
        self.assertTrue(self.unpause_checked().success)
        self.assertFalse(self.latest_status().paused)

    def test_07_loads_become_nonzero_when_the_ice_reaches_the_structure(self):
        # After the reset the scenario's 0.2 m/s holds again (no command since), and the strip
        # front reaches the structure after about 5 s of simulated time.
        def loaded():
            with self.lock:
                return any(w.wrench.force.x > 1.0 for w in self.wrenches[-200:])
        self.wait_for(loaded, 240.0, "a horizontal load above 1 N")
        self.wait_for(lambda: self.latest_status().broken_bonds > 0, 120.0, "broken bonds")
        self.assertEqual(self.latest_status().last_error, "")

        # The load arrow of ice/cells, worked out by hand: its head on the face at half the face's
        # height (z = h/2, x = toe + (h/2) cot(angle)), its length along x F_cal (the readout of the
        # same marker array, rounded to 1 N) x ~load_arrow_scale / the structure's width.
        def arrow_drawn():
            with self.lock:
                markers = self.markers
            return any(m.ns == "load" and m.action == Marker.ADD for m in markers.markers)
        self.wait_for(arrow_drawn, 120.0, "a load arrow (F_cal above 27 N)")
        with self.lock:
            namespaces = {m.ns: m for m in self.markers.markers}
        structure = QUICK["structure"]
        height, width = float(structure["height"]), float(structure["width"])
        tail, head = namespaces["load"].points
        self.assertAlmostEqual(head.z, 0.5 * height, places=9)
        self.assertAlmostEqual(head.x, TOE_X + 0.5 * height / math.tan(math.radians(float(structure["angle_deg"]))),
                               places=9)
        f_cal = float(re.search(r"F_cal (-?[0-9]+) N", namespaces["readout"].text).group(1))
        self.assertGreater(f_cal, 0.0)
        self.assertAlmostEqual(head.x - tail.x, f_cal * LOAD_ARROW_SCALE / width, delta=0.5 * LOAD_ARROW_SCALE / width)


    def test_08_paused_as_gazebo_clock_goes_on_commands_wait_and_step_publishes_every_period(self):
        # A rig stepping with its controller in the loop: while paused /clock goes on (frozen), a
        # command waits out any wall time (~cmd_timeout counts simulated time), and a step of
        # 0.2 s publishes the wrench of each of its 20 load periods (100 Hz), stamped in order.
        self.pause()
        time.sleep(0.3)
        with self.lock:
            first = len(self.clocks)
        time.sleep(1.0)
        with self.lock:
            frozen = self.clocks[first:]
        self.assertGreaterEqual(len(frozen), 5, "about 10 /clock messages a second while paused")
        self.assertEqual(len(set(frozen)), 1, "the clock is frozen while paused")
        self.command.publish(self._twist(0.05))
        time.sleep(1.6)  # more than ~cmd_timeout (1 s) of wall time, no simulated time
        with self.lock:
            before = len(self.wrenches)
        answer = self.step(steps=0, duration=0.2)
        self.assertTrue(answer.success, answer.message)
        self.assertAlmostEqual(self.latest_status().pusher_velocity, 0.05, delta=1e-9)
        time.sleep(0.5)
        with self.lock:
            stamps = [w.header.stamp.to_sec() for w in self.wrenches[before:]]
        self.assertGreaterEqual(len(stamps), 20, "one wrench per load period of the step")
        self.assertEqual(stamps, sorted(stamps))
        self.assertAlmostEqual(stamps[-1] - stamps[-20], 0.19, delta=TIME_STEP + 1e-9)
        self.unpause()
        self.assertFalse(self.latest_status().paused)


    def test_09_limits_and_pacing_change_at_run_time(self):
        # dynamic_reconfigure: a lower speed limit clamps the next command; a real-time factor
        # outside the start-up range (1e-4: between 0 and 1e-3) is refused and nothing changes.
        import dynamic_reconfigure.client
        client = dynamic_reconfigure.client.Client("thin_ice_sim", timeout=30)
        self.assertAlmostEqual(client.update_configuration({"max_pusher_speed": 0.1})["max_pusher_speed"], 0.1)
        self.send(0.3, 0.3)
        self.assertAlmostEqual(self.latest_status().pusher_velocity, 0.1, delta=1e-9)
        answered = client.update_configuration({"real_time_factor": 1e-4})
        self.assertEqual(answered["real_time_factor"], 0.0, "a refused value is answered with the one kept")
        client.update_configuration({"max_pusher_speed": 0.5})
        self.send(0.3, 0.3)
        self.assertAlmostEqual(self.latest_status().pusher_velocity, 0.3, delta=1e-9)


if __name__ == "__main__":
    rostest.rosrun("thin_ice_sim", "node_interface", NodeInterfaceTest)
