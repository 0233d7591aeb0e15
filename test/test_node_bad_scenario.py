#!/usr/bin/python3
"""rostest: the node refuses a bad scenario with one fatal message and a non-zero exit."""
import os
import subprocess
import tempfile
import unittest

import roslib.packages
import rospkg
import rostest


class BadScenarioTest(unittest.TestCase):
    def run_node(self, *params):
        # The executable as roslaunch finds it (catkin's libexec directory first); rosrun's
        # 'find -L' would also walk the workspace .ws/ inside the repository.
        executable = roslib.packages.find_node("thin_ice_sim", "thin_ice_node")[0]
        # A node name of its own per test: private parameters stay on the parameter server.
        command = [executable, "__name:=" + self.id().split(".")[-1]] + list(params)
        return subprocess.run(command, capture_output=True, text=True, timeout=60)

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


if __name__ == "__main__":
    rostest.rosrun("thin_ice_sim", "node_bad_scenario", BadScenarioTest)
