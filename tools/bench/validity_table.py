#!/usr/bin/env python3
"""Validity of the outputs: runs `linesurf reconstruct` at defaults on the README example,
Andalusian (when ../shared/data holds it) and synthetic cities, writing PLY and CityJSON, and
records per scene the classes of the library's checker (the report's `validity`, on the PLY
mesh) and of the independent CityJSON checker of the tests (tests/support/cityjson_check.py,
with the official 2.0.2 schemas when ../shared/reference/cityjson-2.0.2 holds them) into
tools/bench/tables/validity.json, which make_tables.py renders into docs/user/formats.md.

Usage: tools/bench/validity_table.py --linesurf build/bin/linesurf --workdir /tmp/vt
           [--cities 100,1000] [--seed 4016] [--machine TEXT]
Python 3 standard library (and python3-jsonschema for the schemas).
"""

import argparse
import json
import os
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(Path(__file__).resolve().parent))
from table_file import write_table  # noqa: E402
SHARED = REPO.parent / "shared"
sys.path.insert(0, str(REPO / "tests" / "support"))
import cityjson_check  # noqa: E402  (the tests' independent checker)

LIBRARY_CLASSES = ["num_boundary_edges", "num_non_manifold_edges", "num_non_manifold_vertices",
                   "num_degenerate_faces", "num_zero_area_faces", "num_non_planar_faces",
                   "num_intersecting_triangle_pairs", "num_coincident_vertices",
                   "num_touching_triangle_pairs"]


def run(cmd):
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)


def scenes(args, work):
    yield "example", "README example (house)", REPO / "docs" / "examples" / "house" / "lines.json"
    andalusian = SHARED / "data" / "andalusian" / "input_lines_from_residuals.json"
    if andalusian.exists():
        yield "andalusian", "Andalusian", andalusian
    else:
        print("validity_table: Andalusian absent from %s, skipped" % andalusian, file=sys.stderr)
    for size in [int(s) for s in args.cities.split(",") if s]:
        out = work / ("city-%d" % size)
        if not (out / "lines.json").exists():
            run([args.linesurf, "synth", "city", "--size", str(size), "--seed", str(args.seed),
                 "-o", str(out)])
        yield "city-%d" % size, "synthetic city-%d (seed %d)" % (size, args.seed), out / "lines.json"


def measure(args, work, key, name, path):
    stem = work / key
    start = time.monotonic()
    run([args.linesurf, "reconstruct", str(path), "-o", str(stem) + ".ply",
         "--report", str(stem) + ".json"])
    seconds = time.monotonic() - start
    run([args.linesurf, "reconstruct", str(path), "-o", str(stem) + ".city.json"])
    report = json.load(open(str(stem) + ".json"))
    v = report["validity"]
    schemas = SHARED / "reference" / "cityjson-2.0.2"
    validators = cityjson_check.load_validators(str(schemas)) if schemas.exists() else None
    city = cityjson_check.check_file(str(stem) + ".city.json", validators)
    city_defects = sum(city[c] for c in cityjson_check.CLASSES)
    return {
        "scene": name,
        "faces": v["num_faces"],
        "library": {"valid": "yes" if v["valid"] else "no",
                    "defects": sum(v[c] for c in LIBRARY_CLASSES)},
        "coincident": v["num_coincident_vertices"],
        "touching": v["num_touching_triangle_pairs"],
        "zero_area": v["num_zero_area_faces"],
        "pinch_cells": report["mesh"]["pinch_cells_relabelled"],
        "cityjson": {"buildings": city["buildings"], "defects": city_defects,
                     "schema": "2.0.2" if city["schema_checked"] else "not checked"},
        "seconds": seconds,
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--linesurf", default=str(REPO / "build" / "bin" / "linesurf"))
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--cities", default="100,1000")
    parser.add_argument("--seed", type=int, default=4016)
    parser.add_argument("--machine", default="")
    args = parser.parse_args()
    work = Path(args.workdir)
    work.mkdir(parents=True, exist_ok=True)
    rows = [measure(args, work, key, name, path) for key, name, path in scenes(args, work)]
    title = "Validity of the outputs at defaults"
    command = ("python3 tools/bench/validity_table.py --linesurf %s --workdir %s "
               "--cities %s --seed %d" % (os.path.relpath(args.linesurf, REPO),
               args.workdir, args.cities, args.seed))
    columns = [
        {"key": "scene", "header": "scene"},
        {"key": "faces", "header": "PLY faces"},
        {"key": "library", "header": "library checker: valid (defects)",
         "format": "{valid} ({defects})"},
        {"key": "coincident", "header": "coincident vertices"},
        {"key": "touching", "header": "touching triangle pairs"},
        {"key": "zero_area", "header": "zero-area faces"},
        {"key": "pinch_cells", "header": "cells relabelled by the pinch repair"},
        {"key": "cityjson", "header": "CityJSON: buildings, defects (independent checker), schema",
         "format": "{buildings}, {defects}, {schema}"},
        {"key": "seconds", "header": "s (PLY run)", "format": "{:.1f}"},
    ]
    write_table("validity", "docs/user/formats.md", title, command, columns, rows, args.machine)
    return 0


if __name__ == "__main__":
    sys.exit(main())
