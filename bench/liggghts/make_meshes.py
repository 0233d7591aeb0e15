#!/usr/bin/python3
"""Writes the two walls of the LIGGGHTS comparison as ASCII STL files (metres), from the same
numbers as the project's scenario: the inclined structure face and the pushing plate.

  make_meshes.py --out DIR --toe-x X --angle-deg A --width W --height H --depth D --pusher-x P
                 --waterline Z

structure.stl: the face through (toe_x, y, Z) inclined at A degrees from horizontal, rising away
  from the ice (towards +x), from D below to H above the waterline, across y in [-W/2, W/2].
pusher.stl: a vertical plate at x = P across y in [-W/2, W/2], from D below to H above Z.
"""
import argparse
import math
import os


def quad(a, b, c, d):
    """Two triangles of the quadrilateral a-b-c-d (corners in order)."""
    return [(a, b, c), (a, c, d)]


def write_stl(path, name, triangles):
    with open(path + ".partial", "w") as f:
        f.write(f"solid {name}\n")
        for t in triangles:
            f.write("  facet normal 0 0 0\n    outer loop\n")
            for v in t:
                f.write(f"      vertex {v[0]:.9g} {v[1]:.9g} {v[2]:.9g}\n")
            f.write("    endloop\n  endfacet\n")
        f.write(f"endsolid {name}\n")
    os.replace(path + ".partial", path)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    for key in ("toe-x", "angle-deg", "width", "height", "depth", "pusher-x", "waterline"):
        p.add_argument("--" + key, type=float, required=True)
    p.add_argument("--out", required=True)
    a = p.parse_args()
    if not (0.0 < a.angle_deg < 90.0) or a.width <= 0.0 or a.height <= 0.0 or a.depth <= 0.0:
        p.error(f"need 0 < angle-deg < 90 (got {a.angle_deg}), width, height, depth > 0")
    run = 1.0 / math.tan(math.radians(a.angle_deg))  # horizontal run per metre of rise
    y0, y1 = -0.5 * a.width, 0.5 * a.width
    z = a.waterline
    low = (a.toe_x - a.depth * run, z - a.depth)
    high = (a.toe_x + a.height * run, z + a.height)
    face = quad((low[0], y0, low[1]), (low[0], y1, low[1]), (high[0], y1, high[1]), (high[0], y0, high[1]))
    plate = quad((a.pusher_x, y0, z - a.depth), (a.pusher_x, y1, z - a.depth), (a.pusher_x, y1, z + a.height),
                 (a.pusher_x, y0, z + a.height))
    os.makedirs(a.out, exist_ok=True)
    write_stl(os.path.join(a.out, "structure.stl"), "structure", face)
    write_stl(os.path.join(a.out, "pusher.stl"), "pusher", plate)


if __name__ == "__main__":
    main()
