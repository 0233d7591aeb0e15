"""Counts the test cases in a directory of JUnit XML files (gtest and rostest write these).

usage: scripts/study count_test_results DIR
Prints "PASSED FAILED SKIPPED" (one test case counts once, whatever the XML nesting) and lists
each failed case on stderr.
"""
import os
import sys
import xml.etree.ElementTree as ElementTree

SUMMARY = "counts passed, failed and skipped test cases in a directory of JUnit XML files"


PROG = "scripts/study count_test_results"


def main(argv):
    if len(argv) != 1 or not os.path.isdir(argv[0]):
        given = " ".join(argv) if argv else "nothing"
        print(f"{PROG}: DIR {given}; allowed: one directory of JUnit XML files", file=sys.stderr)
        return 2
    passed = failed = skipped = 0
    for root, _, files in os.walk(argv[0]):
        for name in sorted(files):
            if not name.endswith(".xml"):
                continue
            path = os.path.join(root, name)
            try:
                tree = ElementTree.parse(path)
            except ElementTree.ParseError as error:
                print(f"unreadable result file {path}: {error}", file=sys.stderr)
                failed += 1
                continue
            for case in tree.iter("testcase"):
                if case.find("failure") is not None or case.find("error") is not None:
                    failed += 1
                    print(f"FAILED: {case.get('classname')}.{case.get('name')} ({path})", file=sys.stderr)
                elif case.find("skipped") is not None or case.get("status") == "notrun" \
                        or case.get("result") == "skipped":
                    skipped += 1
                else:
                    passed += 1
    print(passed, failed, skipped)
