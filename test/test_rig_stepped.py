#!/usr/bin/python3
"""rostest: a rig steps the simulator with its controller in the loop (rig_stepped.test).

Paused from the start, the simulator is advanced by sim/step in calls of 0.05 s of simulated time
(5 load periods each) while the example controller answers every wrench with a pusher command. As
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

STEP = 0.05     # [s] of simulated time per sim/step call


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
        calls = int(round(END / STEP))
        for k in range(calls):
            answer = step(steps=0, duration=STEP)
            self.assertTrue(answer.success, answer.message)
            if k == calls // 2:
                time.sleep(1.5)
            time.sleep(0.02)  # the controller answers the last wrench
        time.sleep(0.5)
        with lock:
            data = list(wrenches)
            sent = list(commands)
        self.assertGreaterEqual(len(data), int(END * 100) - 1, "one wrench per load period of every step")
        self.assertGreater(len(sent), calls, "the controller answered the wrenches")
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
