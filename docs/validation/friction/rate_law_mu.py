#!/usr/bin/python3
"""The ice-ice friction coefficient that a rate-dependent friction law gives at the slip speeds of
a run's touching contacts.

Input: the histograms written by a build with slip_histogram.patch (beside this file): the share of
touching contacts, and of their normal force F_n + |F_v|, in bins of slip speed (4 a decade).
The law: 0.7 at or below 1e-6 m/s, 0.1 at or above 1e-2 m/s, linear in log10 of the speed between
(the rate-dependent ice-ice friction Lishman and Polojarvi put into a 2-D DEM of rubble, POAC 2015).

    docs/validation/friction/rate_law_mu.py docs/validation/friction/slip_*.txt
"""
import math
import re
import sys

ROW = re.compile(r"slip +([\d.e+-]+)\.\.([\d.e+-]+) m/s +count +([\d.]+) cum +[\d.]+ +force +([\d.]+)")


def rate_law(speed):
    """Friction coefficient [-] at slip speed [m/s]."""
    decade = math.log10(speed)
    return 0.7 if decade <= -6 else (0.1 if decade >= -2 else 0.7 - 0.15 * (decade + 6))


def main(paths):
    print("| histogram | force-weighted median slip [m/s] | mu there | force-weighted mean mu | "
          "contact-weighted mean mu | force share below 1e-3 m/s |")
    print("|---|---:|---:|---:|---:|---:|")
    for path in paths:
        rows = []
        with open(path) as f:
            for line in f:
                m = ROW.match(line)
                if m:
                    low, high, count, force = map(float, m.groups())
                    rows.append((math.sqrt(low * high), count, force))
        if not rows:
            sys.exit(f"{path}: no histogram rows")
        force_sum = sum(r[2] for r in rows)
        count_sum = sum(r[1] for r in rows)
        cumulative, median = 0.0, None
        for speed, _, force in rows:
            cumulative += force / force_sum
            if median is None and cumulative >= 0.5:
                median = speed
        by_force = sum(rate_law(s) * f for s, _, f in rows) / force_sum
        by_count = sum(rate_law(s) * c for s, c, _ in rows) / count_sum
        slow = sum(f for s, _, f in rows if s < 1e-3) / force_sum
        print(f"| {path} | {median:.2g} | {rate_law(median):.2f} | {by_force:.2f} | {by_count:.2f} | {slow:.2f} |")


if __name__ == "__main__":
    main(sys.argv[1:])
