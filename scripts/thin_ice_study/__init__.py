"""The Python study tools of thin_ice_sim: the scripts that run, read, tabulate and plot the runs of
`thin_ice run` (validation matrix, strip bench, reports, plots), and the libraries they share.

Each tool is a module with a main(argv) and a one-line SUMMARY, run through the one entry point
beside this folder: `scripts/study COMMAND [ARGS...]` (`scripts/study --help` lists the commands).
The modules without a main (run_record, run_summary, scenario_file, experiments, png_output,
strip_loads, phase2_table, depth_table, refusal) are libraries of the tools and of the tests.
Importing the package imports none of its modules, so that listing the commands needs neither matplotlib nor rospy.
"""
import os

# The repository root: scenario paths in summary.json, config/ and the builds under .ws start here.
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
