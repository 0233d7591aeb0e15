#!/usr/bin/python3
"""rostest: with the example controller in the loop, the structure load settles in a band around
the set point.

Band: after 2 s of simulated time, the mean calibrated horizontal load over each further 0.5 s
window lies within +-50 % of the set point. The load of a breaking, riding-up ice sheet swings by
more than that from one 10 ms sample to the next, so the band is on window means, which is what a
load-controlled rig holds.
"""
import threading
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import WrenchStamped

SETTLE = 2.0   # [s] of simulated time before the band applies
WINDOW = 0.5   # [s] of simulated time per mean
END = 4.0      # [s] of simulated time observed
BAND = 0.5     # relative half-width of the band


class RigControllerTest(unittest.TestCase):
    def test_load_held_in_band(self):
        rospy.init_node("test_rig_controller")
        set_point = rospy.get_param("~set_point")
        samples = []
        lock = threading.Lock()

        def on_wrench(msg):
            with lock:
                samples.append((msg.header.stamp.to_sec(), msg.wrench.force.x))

        rospy.Subscriber("structure/wrench", WrenchStamped, on_wrench, queue_size=1000)
        deadline = time.time() + 360.0
        while time.time() < deadline:
            with lock:
                if samples and samples[-1][0] >= END:
                    break
            time.sleep(0.1)
        with lock:
            data = list(samples)
        self.assertTrue(data and data[-1][0] >= END, "the simulation did not reach %.1f s" % END)
        means = []
        t0 = 0.0
        while t0 + WINDOW <= END + 1e-9:
            w = [f for t, f in data if t0 <= t < t0 + WINDOW]
            means.append("%.1f-%.1f s: %.0f N" % (t0, t0 + WINDOW, sum(w) / len(w) if w else float("nan")))
            t0 += WINDOW
        print("window means: " + ", ".join(means))
        print("samples: %d, max %.1f N, first stamps %s" % (len(data), max(f for _, f in data), [round(t, 3) for t, _ in data[:5]]))
        start = SETTLE
        while start + WINDOW <= END + 1e-9:
            window = [f for t, f in data if start <= t < start + WINDOW]
            self.assertTrue(window, "no samples in [%.2f, %.2f) s" % (start, start + WINDOW))
            mean = sum(window) / len(window)
            self.assertLess(abs(mean - set_point), BAND * set_point,
                            "mean load %.1f N in [%.2f, %.2f) s is outside %.0f N +- %.0f %%"
                            % (mean, start, start + WINDOW, set_point, 100 * BAND))
            start += WINDOW


if __name__ == "__main__":
    rostest.rosrun("thin_ice_sim", "rig_controller", RigControllerTest)
