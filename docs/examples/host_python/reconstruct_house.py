#!/usr/bin/env python3
"""reconstruct_house.py [LINES.json [MESH.ply]]: reconstructs a scene through the installed
linesurf Python module with the options of
`linesurf reconstruct LINES.json --scene exterior -o MESH.ply` (same mesh bytes).

    PYTHONPATH=<prefix>/lib/python3.11/site-packages /usr/bin/python3 reconstruct_house.py \
        docs/examples/house/lines.json house.ply
"""

import os
import sys

import linesurf


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    lines = argv[1] if len(argv) > 1 else os.path.join(here, "..", "house", "lines.json")
    mesh_path = argv[2] if len(argv) > 2 else "house.ply"
    try:
        scene = linesurf.read_scene(lines)
        result = linesurf.reconstruct(
            scene, scene_mode="exterior",
            progress=lambda stage, f: print(f"\r{stage:<10} {100 * f:3.0f} %", end="",
                                            file=sys.stderr))
        print(file=sys.stderr)
        for warning in result.warnings:
            print(f"reconstruct_house: warning: {warning}", file=sys.stderr)
        linesurf.write_mesh(mesh_path, result.mesh)
    except linesurf.InvalidInput as error:
        print(f"\nreconstruct_house: {error}", file=sys.stderr)
        return 3
    except linesurf.Error as error:
        print(f"\nreconstruct_house: {error} ({error.code})", file=sys.stderr)
        return 4
    r = result.report
    closed = "closed 2-manifold" if r["mesh"]["closed"] and r["mesh"]["manifold"] else "NOT closed"
    print(f"linesurf {linesurf.__version__}: {r['counts']['planes']} planes, "
          f"{r['counts']['cells']} cells, mesh "
          f"{len(result.mesh.vertices)} vertices / {result.mesh.num_faces} faces ({closed}), "
          f"{r['total_seconds']:.2f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
