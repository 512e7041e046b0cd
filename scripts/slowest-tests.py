#!/usr/bin/env python3
"""Prints the N slowest tests of a ctest run from its JUnit file (ctest --output-junit),
with each one's share of the summed test time: the test budget at a glance."""
import sys
import xml.etree.ElementTree as ET


def main() -> int:
    if len(sys.argv) != 3:
        print("usage: slowest-tests.py CTEST_JUNIT.xml N", file=sys.stderr)
        return 2
    path, count = sys.argv[1], int(sys.argv[2])
    try:
        cases = ET.parse(path).getroot().iter("testcase")
    except (OSError, ET.ParseError) as e:
        print(f"slowest-tests: cannot read {path}: {e}", file=sys.stderr)
        return 2
    times = sorted(((float(c.get("time", 0)), c.get("name", "?")) for c in cases), reverse=True)
    total = sum(t for t, _ in times)
    print(f"slowest {min(count, len(times))} of {len(times)} tests (summed test time {total:.0f} s):")
    for t, name in times[:count]:
        print(f"  {t:7.1f} s  {100 * t / total if total else 0:4.1f} %  {name}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
