#!/usr/bin/python3
"""rostest: the node refuses a bad scenario or a bad parameter with one fatal message and a non-zero
exit."""
import os
import subprocess
import tempfile
import unittest

import roslib.packages
import rospkg
import rospy
import rostest


class BadScenarioTest(unittest.TestCase):
    def run_node(self, *params, cwd=None):
        # The executable as roslaunch finds it (catkin's libexec directory first); rosrun's
        # 'find -L' would also walk the workspace .ws/ inside the repository.
        executable = roslib.packages.find_node("thin_ice_sim", "thin_ice_node")[0]
        # A node name of its own per test: private parameters stay on the parameter server.
        command = [executable, "__name:=" + self.id().split(".")[-1]] + list(params)
        return subprocess.run(command, capture_output=True, text=True, timeout=60, cwd=cwd)

    def private_parameter(self, name, value):
        """Sets ~name of the node that run_node starts (lists cannot be given on its command line)."""
        rospy.set_param("/" + self.id().split(".")[-1] + "/" + name, value)

    def test_bad_value_names_file_and_key(self):
        quick = os.path.join(rospkg.RosPack().get_path("thin_ice_sim"), "config", "scenarios", "quick.yaml")
        with open(quick) as f:
            text = f.read()
        bad = text.replace("  thickness: 0.051", "  thickness: -0.051", 1)
        self.assertNotEqual(bad, text)
        with tempfile.NamedTemporaryFile("w", suffix=".yaml", delete=False) as f:
            f.write(bad)
            path = f.name
        try:
            result = self.run_node("_scenario:=" + path)
        finally:
            os.unlink(path)
        output = result.stdout + result.stderr
        self.assertNotEqual(result.returncode, 0, output)
        self.assertIn(path, output)
        self.assertIn("ice.thickness", output)

    def test_missing_scenario_file(self):
        result = self.run_node("_scenario:=/nonexistent/none.yaml")
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("none.yaml", result.stdout + result.stderr)

    def test_bad_node_parameter(self):
        result = self.run_node("_scenario:=quick", "_load_rate:=-5.0")
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("load_rate", result.stdout + result.stderr)

    def test_relative_scenario_path_names_the_directory_it_was_looked_for_in(self):
        # Under roslaunch the working directory is ~/.ros: the message must say so.
        with tempfile.TemporaryDirectory() as directory:
            result = self.run_node("_scenario:=cases/none.yaml", cwd=directory)
            self.assertNotEqual(result.returncode, 0)
            self.assertIn(os.path.join(os.path.realpath(directory), "cases", "none.yaml"),
                          result.stdout + result.stderr)

    def test_parameter_of_the_wrong_type_is_refused(self):
        # ros::NodeHandle::param would silently keep the default for a value of another type.
        result = self.run_node("_scenario:=quick", "_paused:=maybe")
        output = result.stdout + result.stderr
        self.assertNotEqual(result.returncode, 0, output)
        self.assertIn("~paused = maybe", output)
        self.assertIn("true or false", output)
        result = self.run_node("_scenario:=quick", "_load_rate:=fast")
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("~load_rate = fast", result.stdout + result.stderr)

    def test_a_rate_that_would_block_the_node_is_refused(self):
        # 0.001 Hz of simulated time would simulate 1000 s in one uninterruptible call.
        result = self.run_node("_scenario:=quick", "_load_rate:=0.001")
        output = result.stdout + result.stderr
        self.assertNotEqual(result.returncode, 0, output)
        self.assertIn("~load_rate = 0.001", output)
        self.assertIn("allowed: 1 to", output)

    def test_a_negative_load_arrow_scale_is_refused(self):
        result = self.run_node("_scenario:=quick", "_load_arrow_scale:=-0.003")
        output = result.stdout + result.stderr
        self.assertNotEqual(result.returncode, 0, output)
        self.assertIn("~load_arrow_scale = -0.003 is invalid; allowed: 0 or 1e-06 to 1 m per N/m", output)

    def test_set_item_that_is_not_a_string_is_refused(self):
        # A colon typed for '=' makes a YAML dictionary: named, not a crash of the node.
        self.private_parameter("set", ["sheet.length=1.0", {"numerics.threads": 2}])
        result = self.run_node("_scenario:=quick")
        output = result.stdout + result.stderr
        self.assertEqual(result.returncode, 1, output)
        self.assertIn("~set item 1", output)
        self.assertIn("dictionary", output)

    def test_scenario_velocity_above_the_speed_limit_is_refused(self):
        # quick.yaml pushes at 0.2 m/s; the limit applies to it as to every command.
        result = self.run_node("_scenario:=quick", "_max_pusher_speed:=0.1")
        output = result.stdout + result.stderr
        self.assertNotEqual(result.returncode, 0, output)
        self.assertIn("pusher.velocity = 0.2", output)
        self.assertIn("~max_pusher_speed = 0.1", output)


if __name__ == "__main__":
    rostest.rosrun("thin_ice_sim", "node_bad_scenario", BadScenarioTest)
