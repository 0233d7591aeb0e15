#!/usr/bin/python3
"""rostest: after a numerical blow-up the node pauses, reports, and still answers every call."""
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import Twist
from std_srvs.srv import Empty, Trigger
from thin_ice_sim.msg import SimStatus
from thin_ice_sim.srv import Step


class NodeFaultTest(unittest.TestCase):
    def setUp(self):
        rospy.init_node("test_node_fault", anonymous=True)
        self.status = None
        rospy.Subscriber("sim/status", SimStatus, self.on_status, queue_size=10)
        for name in ("sim/pause", "sim/unpause", "sim/unpause_checked", "sim/reset", "sim/step"):
            rospy.wait_for_service(name, timeout=60.0)

    def on_status(self, msg):
        self.status = msg

    def wait_status(self, predicate, timeout, what):
        deadline = time.time() + timeout
        while time.time() < deadline:
            if self.status is not None and predicate(self.status):
                return self.status
            time.sleep(0.05)
        self.fail("timed out waiting for " + what)

    def test_blow_up_pauses_reports_and_keeps_serving(self):
        status = self.wait_status(lambda s: s.last_error != "", 60.0, "the blow-up to be reported")
        self.assertIn("blow-up", status.last_error)
        status = self.wait_status(lambda s: s.paused, 5.0, "the simulation to pause")
        frozen = status.sim_time
        time.sleep(0.5)
        self.assertEqual(self.status.sim_time, frozen)
        # Every call is still answered, none crashes the node.
        self.assertFalse(rospy.ServiceProxy("sim/step", Step)(steps=10, duration=0.0).success)
        self.assertFalse(rospy.ServiceProxy("sim/step", Step)(steps=0, duration=float("nan")).success)
        self.assertFalse(rospy.ServiceProxy("sim/step", Step)(steps=0, duration=-1.0).success)
        # sim/unpause_checked (Trigger): refused until a reset, with the reason.
        refused = rospy.ServiceProxy("sim/unpause_checked", Trigger)()
        self.assertFalse(refused.success)
        self.assertIn(status.last_error, refused.message)  # the error itself, and what to do
        self.assertIn("sim/reset", refused.message)
        # sim/unpause (Empty, as Gazebo's): answered, and the simulation stays paused with its error.
        rospy.ServiceProxy("sim/unpause", Empty)()
        time.sleep(0.5)
        self.assertTrue(self.status.paused)
        self.assertEqual(self.status.last_error, status.last_error)
        self.assertEqual(self.status.sim_time, frozen)
        publisher = rospy.Publisher("pusher/cmd_vel", Twist, queue_size=10)
        time.sleep(0.5)
        bad = Twist()
        bad.linear.x = float("nan")
        publisher.publish(bad)
        rospy.ServiceProxy("sim/reset", Empty)()
        status = self.wait_status(lambda s: s.last_error == "" and s.sim_time == 0.0, 10.0, "the reset")
        self.assertEqual(status.broken_bonds, 0)
        self.assertTrue(rospy.ServiceProxy("sim/unpause_checked", Trigger)().success)  # and then it runs again


if __name__ == "__main__":
    rostest.rosrun("thin_ice_sim", "node_fault", NodeFaultTest)
