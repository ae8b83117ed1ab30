#!/usr/bin/env python3
"""Dependence of the result on the frame: each scene is reconstructed as given and moved by a
similarity (scaled by 37.1; turned 70 degrees about (1, 2, 3), so that its up axis is not z;
both); each moved result is moved back and compared with the first one and with the ground
truth. Writes tools/bench/tables/NAME.json, which make_tables.py renders into
docs/design/real_data.md.

Usage: tools/bench/frame_table.py --linesurf build/bin/linesurf --workdir /tmp/ft
           [--name frame-dependence] [--machine TEXT] [-- RECONSTRUCT_OPTIONS...]
Options after `--` go to every `linesurf reconstruct` (e.g. `-- --engine monolithic`).
Python 3 standard library only. Scenes: the README example (house), synthetic city-16
(seed 4016) and Andalusian when ../shared/data holds it (skipped with a message otherwise).
"""

import json
import math
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_scenes import (arguments, command_line, evaluate, options_text,  # noqa: E402
                          reconstruct, scenes)
from table_file import write_table  # noqa: E402
AXIS = (1.0, 2.0, 3.0)
# The moves: name, scale, degrees about AXIS.
MOVES = [("x37.1", 37.1, 0.0), ("70 deg", 1.0, 70.0), ("x37.1, 70 deg", 37.1, 70.0)]
# Agreement of the two results and accuracy against the ground truth, metres of the scene as
# given (the comparison is made after moving back).
AGREEMENT_M = 0.01
ACCURACY_M = 0.05


def rotation(axis, degrees):
    n = math.sqrt(sum(a * a for a in axis))
    x, y, z = (a / n for a in axis)
    t = math.radians(degrees)
    c, s, k = math.cos(t), math.sin(t), 1.0 - math.cos(t)
    return [[c + x * x * k, x * y * k - z * s, x * z * k + y * s],
            [y * x * k + z * s, c + y * y * k, y * z * k - x * s],
            [z * x * k - y * s, z * y * k + x * s, c + z * z * k]]


class Move:
    """x -> scale R x, R the rotation by `degrees` about AXIS."""

    def __init__(self, scale, degrees):
        self.scale = scale
        self.r = rotation(AXIS, degrees)

    def apply(self, p):
        return [self.scale * sum(self.r[i][j] * p[j] for j in range(3)) for i in range(3)]

    def turn(self, n):
        return [sum(self.r[i][j] * n[j] for j in range(3)) for i in range(3)]

    def back(self, p):  # R is orthogonal: the inverse is its transpose
        return [sum(self.r[j][i] * p[j] for j in range(3)) / self.scale for i in range(3)]


def moved_scene(m, src, dst):
    """The reference JSON `src` with every point moved and every normal turned."""
    scene = json.load(open(src))
    for line in scene["lines"]:
        line["pt1"] = m.apply(line["pt1"])
        line["pt2"] = m.apply(line["pt2"])
        line["pt_views"] = [m.apply(v) for v in line.get("pt_views", [])]
    for plane in scene.get("planes", []):
        for key in ("inlier", "point"):
            if key in plane:
                plane[key] = m.apply(plane[key])
        if "normal" in plane:
            plane["normal"] = m.turn(plane["normal"])
    with open(dst, "w") as out:
        json.dump(scene, out)


def obj_moved_back(m, src, dst):
    with open(src) as inp, open(dst, "w") as out:
        for line in inp:
            if line.startswith("v "):
                p = m.back([float(v) for v in line.split()[1:4]])
                out.write("v %r %r %r\n" % tuple(p))
            else:
                out.write(line)


def measure(linesurf, extra, work, key, name, scene, ground_truth):
    """One row per move of the scene."""
    base_obj = work / (key + ".base.obj")
    base = reconstruct(linesurf, extra, scene, work / (key + ".base"))
    base_accuracy = evaluate(linesurf, base_obj, ground_truth, ACCURACY_M) if ground_truth else None
    rows = []
    for index, (move_name, scale, degrees) in enumerate(MOVES):
        m = Move(scale, degrees)
        stem = work / ("%s.move%d" % (key, index))
        moved_scene(m, scene, str(stem) + ".lines.json")
        moved = reconstruct(linesurf, extra, str(stem) + ".lines.json", stem)
        back = Path(str(stem) + ".back.obj")
        obj_moved_back(m, str(stem) + ".obj", back)
        rows.append({
            "scene": name,
            "move": move_name,
            "planes": [base["counts"]["planes"], moved["counts"]["planes"]],
            "components": [base["quality"]["num_components"], moved["quality"]["num_components"]],
            "fragments": [base["quality"]["floating_fragments"],
                          moved["quality"]["floating_fragments"]],
            "volume": 100.0 * (moved["quality"]["enclosed_volume"] / scale ** 3 /
                               base["quality"]["enclosed_volume"] - 1.0),
            "epsilon": [base["epsilon"]["epsilon"], moved["epsilon"]["epsilon"] / scale],
            "agreement": list(evaluate(linesurf, back, base_obj, AGREEMENT_M)),
            "accuracy": (list(base_accuracy + evaluate(linesurf, back, ground_truth, ACCURACY_M))
                         if ground_truth else None),
        })
    return rows


def main():
    args = arguments(__doc__.splitlines()[0], "frame-dependence").parse_args()
    work = Path(args.workdir)
    work.mkdir(parents=True, exist_ok=True)
    rows = []
    for index, (name, scene, ground_truth) in enumerate(scenes(work, args.linesurf)):
        rows += measure(args.linesurf, args.extra, work, "scene%d" % index, name, scene,
                        ground_truth)
    title = "The same scene in another frame (reconstruct options: %s)" % options_text(args)
    command = command_line("frame_table.py", args)
    columns = [
        {"key": "scene", "header": "scene"},
        {"key": "move", "header": "moved by"},
        {"key": "planes", "header": "planes: given frame / moved", "format": "{} / {}"},
        {"key": "components", "header": "components", "format": "{} / {}"},
        {"key": "fragments", "header": "floating fragments", "format": "{} / {}"},
        {"key": "volume", "header": "volume moved back vs given", "format": "{:+.2f} %"},
        {"key": "epsilon", "header": "eps (scene units of the given frame)",
         "format": "{:.4g} / {:.4g}"},
        {"key": "agreement",
         "header": "moved-back result within 1 cm of the given frame's: precision / "
         "completeness", "format": "{:.1f} / {:.1f} %"},
        {"key": "accuracy",
         "header": "P / C at 5 cm against the ground truth: given frame; moved back",
         "format": "{:.1f} / {:.1f}; {:.1f} / {:.1f} %"},
    ]
    write_table(args.name, "docs/design/real_data.md", title, command, columns, rows,
                args.machine)
    return 0


if __name__ == "__main__":
    sys.exit(main())
