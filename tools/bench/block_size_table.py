#!/usr/bin/env python3
"""Dependence of the result on the block cut: each scene is reconstructed with the automatic
block sizes, then with the arrangement blocks set to each given size (from about one building
per block to the whole scene; detection automatic), then with the detection blocks set to each
(arrangement automatic), and each result is measured. Writes
tools/bench/tables/NAME.json, which make_tables.py renders into docs/design/real_data.md.

Figures: the labels' energy (report `solver.objective`), its spread over the sizes (max / min - 1,
over the automatic run and one series), components and floating fragments; with ground truth,
precision and completeness at 5 cm; without, data fit and visibility consistency at a fixed 2 cm
(`evaluate --lines --epsilon 0.01`: the fit distance is 2 eps).

Usage: tools/bench/block_size_table.py --linesurf build/bin/linesurf --workdir /tmp/bt
           [--name block-size] [--machine TEXT] [--city-sizes 30,60,130]
           [--andalusian-sizes 6,20,80] [-- RECONSTRUCT_OPTIONS...]
Python 3 standard library only.
"""

import json
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_scenes import (arguments, command_line, evaluate, options_text,  # noqa: E402
                          reconstruct, run, scenes)
from table_file import write_table  # noqa: E402

ACCURACY_M = 0.05
FIT_HALF_M = 0.01  # evaluate --lines --epsilon: the data fit distance is twice this


def lines_figures(linesurf, mesh, lines):
    out = Path(str(mesh) + ".lines.json")
    run([linesurf, "-q", "evaluate", mesh, "--lines", lines, "--epsilon", FIT_HALF_M,
         "--json", out])
    q = json.load(open(out))["quality"]
    return 100.0 * q["data_fit"], 100.0 * q["visibility_consistency"]


# The series: label, flag of the size that is set.
SERIES = [("arrangement", "--block-size"), ("detection", "--detect-block-size")]


def measure_one(linesurf, extra, stem, name, scene, ground_truth, flags):
    report = reconstruct(linesurf, extra + flags, scene, stem)
    mesh = str(stem) + ".obj"
    q = report["quality"]
    return {
        "scene": name,
        "sizes": "%.3g / %.3g" % (report["block_size"], report["detection_block_size"]),
        "planes": report["counts"]["planes"],
        "energy": report["solver"]["objective"],
        "components": [q["num_components"], q["floating_fragments"]],
        "accuracy": list(evaluate(linesurf, mesh, ground_truth, ACCURACY_M))
                    if ground_truth else None,
        "fit": None if ground_truth else list(lines_figures(linesurf, mesh, scene)),
        "seconds": report["seconds"],
    }


def measure(linesurf, extra, work, key, name, scene, ground_truth, sizes):
    auto = measure_one(linesurf, extra, work / (key + ".auto"), name, scene, ground_truth, [])
    auto["varied"] = "none (automatic)"
    auto["spread"] = None
    rows = [auto]
    for label, flag in SERIES:
        series = [measure_one(linesurf, extra, work / ("%s.%s%g" % (key, label, size)), name,
                              scene, ground_truth, [flag, str(size)])
                  for size in sizes]
        energies = [auto["energy"]] + [r["energy"] for r in series]
        for r in series:
            r["varied"] = label
            r["spread"] = 100.0 * (max(energies) / min(energies) - 1.0)
        rows += series
    return rows


def main():
    parser = arguments(__doc__.splitlines()[0], "block-size")
    parser.add_argument("--city-sizes", default="30,60,130")
    parser.add_argument("--andalusian-sizes", default="6,20,80")
    args = parser.parse_args()
    work = Path(args.workdir)
    work.mkdir(parents=True, exist_ok=True)
    sizes = {"Andalusian": [float(s) for s in args.andalusian_sizes.split(",")]}
    rows = []
    for index, (name, scene, ground_truth) in enumerate(
            scenes(work, args.linesurf, include_example=False)):
        scene_sizes = sizes.get(name, [float(s) for s in args.city_sizes.split(",")])
        rows += measure(args.linesurf, args.extra, work, "scene%d" % index, name, scene,
                        ground_truth, scene_sizes)
    title = "The same scene cut into other blocks (reconstruct options: %s)" % options_text(args)
    command = command_line("block_size_table.py", args, " --city-sizes %s --andalusian-sizes %s"
                           % (args.city_sizes, args.andalusian_sizes))
    columns = [
        {"key": "scene", "header": "scene"},
        {"key": "varied", "header": "size set"},
        {"key": "sizes", "header": "block size / detection block size"},
        {"key": "planes", "header": "planes"},
        {"key": "energy", "header": "labels' energy", "format": "{:,.1f}"},
        {"key": "spread", "header": "energy max / min - 1 (automatic and the series)",
         "format": "{:.1f} %"},
        {"key": "components", "header": "components, floating fragments", "format": "{}, {}"},
        {"key": "accuracy", "header": "P / C at 5 cm", "format": "{:.1f} / {:.1f} %"},
        {"key": "fit", "header": "data fit / visibility at 2 cm", "format": "{:.1f} / {:.1f} %"},
        {"key": "seconds", "header": "s", "format": "{:.1f}"},
    ]
    write_table(args.name, "docs/design/real_data.md", title, command, columns, rows,
                args.machine)
    return 0


if __name__ == "__main__":
    sys.exit(main())
