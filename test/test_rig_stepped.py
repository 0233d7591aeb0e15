#!/usr/bin/python3
"""rostest: a rig steps the simulator with its controller in the loop (rig_stepped.test).

Paused from the start, the simulator is advanced by sim/step, lock-step: a first call of 0.05 s of
simulated time (5 load periods), then one call per load period (0.01 s, the controller's sample
period), each waiting for the example controller to answer every wrench with a pusher command. As
with Gazebo: /clock goes on while paused, the controller's command does not expire between the
calls however long the wall time between them (~cmd_timeout counts simulated time), every load
period of a step publishes its wrench, and the load settles near the set point as in the running
case (rig_example.test: the mean over each 0.5 s window after 2 s within +-50 % of it). Then
sim/unpause (std_srvs/Empty) runs it, and sim/reset takes it back to t = 0.
"""
import os
import sys
import threading
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import Twist, WrenchStamped
from rosgraph_msgs.msg import Clock
from std_srvs.srv import Empty

from thin_ice_sim.msg import SimStatus
from thin_ice_sim.srv import Step

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rig_band import END, assert_load_in_band  # noqa: E402

FIRST_STEP = 0.05   # [s] of simulated time of the first sim/step call: several load periods
LOAD_PERIOD = 0.01  # [s] of simulated time: 1 / ~load_rate (100 Hz), the controller's sample period


class RigSteppedTest(unittest.TestCase):
    def test_stepped_with_the_controller_in_the_loop(self):
        rospy.init_node("test_rig_stepped")
        set_point = rospy.get_param("~set_point")
        lock = threading.Lock()
        wrenches, clocks, commands, status = [], [], [], {}

        def keep(store, value):
            with lock:
                store.append(value)

        rospy.Subscriber("structure/wrench", WrenchStamped,
                         lambda m: keep(wrenches, (m.header.stamp.to_sec(), m.wrench.force.x)), queue_size=10000)
        rospy.Subscriber("/clock", Clock, lambda m: keep(clocks, m.clock.to_sec()), queue_size=1000)
        rospy.Subscriber("pusher/cmd_vel", Twist, lambda m: keep(commands, m.linear.x), queue_size=10000)
        rospy.Subscriber("sim/status", SimStatus, lambda m: status.update(last=m), queue_size=10)
        for name in ("sim/pause", "sim/unpause", "sim/reset", "sim/step"):
            rospy.wait_for_service(name, timeout=60.0)
        step = rospy.ServiceProxy("sim/step", Step)
        unpause = rospy.ServiceProxy("sim/unpause", Empty)
        reset = rospy.ServiceProxy("sim/reset", Empty)

        # Paused: the frozen clock goes on.
        time.sleep(1.0)
        with lock:
            frozen = list(clocks)
        self.assertGreaterEqual(len(frozen), 5, "no /clock while paused")
        self.assertEqual(set(frozen), {0.0})

        # Stepped with the controller in the loop; a pause of 1.5 s of wall time (more than
        # ~cmd_timeout, 1 s) halfway does not stop the pusher.
        # Lock-step, as a rig stack that steps a simulator does: before the next step the rig waits
        # until the controller has answered every wrench of this one. The first call spans
        # FIRST_STEP (several load periods, each of which must publish its wrench); the loop then
        # steps at the controller's own sample period, one load period, as a rig steps at its
        # control period. A hold of several periods between commands is a different loop: at 0.05
        # s per call the controller's command changes every fifth sample, and on quick.yaml the
        # first contact's overshoot turns into 1.5 s of pushing free floes at 17-25 N.
        durations = [FIRST_STEP] + [LOAD_PERIOD] * int(round((END - FIRST_STEP) / LOAD_PERIOD))
        for k, duration in enumerate(durations):
            with lock:
                wrenches_before = len(wrenches)
            answer = step(steps=0, duration=duration)
            self.assertTrue(answer.success, answer.message)
            expected = int(round(duration / LOAD_PERIOD))
            deadline = time.time() + 30.0
            while time.time() < deadline:
                with lock:
                    arrived = len(wrenches) - wrenches_before
                    answered = len(commands) >= len(wrenches)
                if arrived >= expected and answered:
                    break
                time.sleep(0.002)
            self.assertGreaterEqual(arrived, expected, "the wrenches of call %d did not arrive" % k)
            self.assertTrue(answered, "the controller did not answer the wrenches of call %d" % k)
            time.sleep(0.005)  # the answer reaches the node as it reached the test
            if k == len(durations) // 2:
                time.sleep(1.5)  # longer than ~cmd_timeout in wall time: the command must not expire
        time.sleep(0.5)
        with lock:
            data = list(wrenches)
            sent = list(commands)
        self.assertGreaterEqual(len(data), int(END * 100) - 1, "one wrench per load period of every step")
        self.assertGreaterEqual(len(sent), len(data), "the controller answered the wrenches")
        self.assertNotEqual(status["last"].pusher_velocity, 0.0, "the command expired between steps")
        assert_load_in_band(self, data, set_point)

        # sim/unpause (Empty) runs it; sim/reset takes it back to t = 0.
        unpause()
        time.sleep(1.0)
        self.assertFalse(status["last"].paused)
        self.assertGreater(status["last"].sim_time, END)
        reset()
        time.sleep(0.5)
        self.assertLess(status["last"].sim_time, 0.5)


if __name__ == "__main__":
    rostest.rosrun("thin_ice_sim", "rig_stepped", RigSteppedTest)
