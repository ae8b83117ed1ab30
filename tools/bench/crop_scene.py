#!/usr/bin/env python3
"""Crop a reference JSON scene to a box, for quick experiments on a part of a large scene
(the Andalusian crop of docs/user/results.md, "Integral labelling").

Keeps the lines with both endpoints in the box (with their views), and the planes that the kept
lines refer to, renumbered in their original order; plane_index entries follow.

Usage: tools/bench/crop_scene.py INPUT.json OUTPUT.json XMIN XMAX YMIN YMAX ZMIN ZMAX
Exit status: 0, 2 on bad usage. Python 3 standard library only.
"""

import json
import sys


def main(argv):
    if len(argv) != 9:
        print(__doc__, file=sys.stderr)
        return 2
    source, target = argv[1], argv[2]
    x0, x1, y0, y1, z0, z1 = map(float, argv[3:9])

    def inside(p):
        return x0 <= p[0] <= x1 and y0 <= p[1] <= y1 and z0 <= p[2] <= z1

    with open(source) as f:
        scene = json.load(f)
    lines = [l for l in scene["lines"] if inside(l["pt1"]) and inside(l["pt2"])]
    used = sorted({i for l in lines for i in (l.get("plane_index") or [])})
    new_index = {old: new for new, old in enumerate(used)}
    for l in lines:
        l["plane_index"] = [new_index[i] for i in (l.get("plane_index") or [])]
    out = {"lines": lines, "planes": [scene["planes"][i] for i in used]}
    with open(target, "w") as f:
        json.dump(out, f)
    supported = sum(1 for l in lines if l["plane_index"])
    print(f"{len(lines)} lines ({supported} on planes), {len(used)} planes")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
