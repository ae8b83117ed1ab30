"""An independent checker of CityJSON and CityJSONSeq files: the official JSON schemas (when the
folder holding them is given) and the validity classes of ISO 19107 / val3dity that a Solid
must pass, computed here from the file alone (no linesurf code).

Run as a script: `python3 cityjson_check.py [--schemas DIR] FILE...` prints one JSON line per
file with the count of each defect class and exits 1 when a file has any.
"""

import argparse
import json
import math
import os
import sys
from collections import defaultdict

# Defect classes, in the order they are reported (val3dity's numbering in brackets).
CLASSES = (
    "schema",                 # the official schema rejects the document or a line
    "duplicate_vertices",     # two vertices at one position [102]
    "too_few_points",         # a ring of fewer than three distinct points [101]
    "repeated_ring_points",   # a ring passes a point twice [102, 104]
    "non_planar",             # a polygon's point off its best-fit plane by more than the tolerance [203]
    "zero_area",              # a polygon of (near) zero area [203, 204]
    "hole_outside",           # an inner ring not inside its outer ring, or oriented as it [201, 205, 208]
    "open_shell",             # an edge not used exactly once in each direction [302, 303]
    "non_manifold_vertex",    # the polygons around a vertex are not one fan [303]
    "inward_shell",           # a Solid whose shell encloses a non-positive volume [307]
)

PLANARITY_TOLERANCE_M = 0.001   # metres, whatever the scene's tolerance
MIN_AREA_M2 = 1e-8              # square metres


def load_validators(schema_dir):
    """Draft 7 validators of the CityJSON document and of a CityJSONFeature, from the official
    schema files in `schema_dir` (the merged *.min.schema.json files, or the split ones, which
    refer to each other by $id); None when the folder does not hold them."""
    import jsonschema  # Debian python3-jsonschema

    if not schema_dir or not os.path.isdir(schema_dir):
        return None
    schemas = {}
    for name in os.listdir(schema_dir):
        if name.endswith(".json"):
            with open(os.path.join(schema_dir, name), encoding="utf-8") as f:
                schemas[name] = json.load(f)
    store = {s["$id"]: s for s in schemas.values() if isinstance(s, dict) and "$id" in s}

    def validator(stem):
        for name in (stem + ".min.schema.json", stem + ".schema.json"):
            if name in schemas:
                schema = schemas[name]
                resolver = jsonschema.RefResolver(schema.get("$id", ""), schema, store=store)
                return jsonschema.Draft7Validator(schema, resolver=resolver)
        return None

    city, feature = validator("cityjson"), validator("cityjsonfeature")
    return (city, feature) if city and feature else None


def _sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _newell(points):
    """Twice the vector area of a ring (about its first point)."""
    n = [0.0, 0.0, 0.0]
    o = points[0]
    for k in range(1, len(points) - 1):
        c = _cross(_sub(points[k], o), _sub(points[k + 1], o))
        n = [n[0] + c[0], n[1] + c[1], n[2] + c[2]]
    return tuple(n)


def _project(points, normal, origin):
    """2D coordinates in the plane of `normal`, counter-clockwise about it."""
    length = math.sqrt(_dot(normal, normal))
    n = tuple(c / length for c in normal)
    helper = (1.0, 0.0, 0.0) if abs(n[0]) < 0.6 else (0.0, 1.0, 0.0)
    u = _cross(helper, n)
    ul = math.sqrt(_dot(u, u))
    u = tuple(c / ul for c in u)
    v = _cross(n, u)
    return [(_dot(_sub(p, origin), u), _dot(_sub(p, origin), v)) for p in points]


def _inside(p, ring):
    inside = False
    j = len(ring) - 1
    for i in range(len(ring)):
        a, b = ring[i], ring[j]
        if (a[1] > p[1]) != (b[1] > p[1]) and \
                p[0] < (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) + a[0]:
            inside = not inside
        j = i
    return inside


def _check_polygon(polygon, points_of, counts):
    """Ring and polygon classes of one polygon (a list of rings of vertex indices)."""
    for ring in polygon:
        if len(set(ring)) < 3:
            counts["too_few_points"] += 1
        if len(set(ring)) != len(ring):
            counts["repeated_ring_points"] += 1
    outer = [points_of(i) for i in polygon[0]]
    if len(outer) < 3:
        return
    normal = _newell(outer)
    area = 0.5 * math.sqrt(_dot(normal, normal))
    if area <= MIN_AREA_M2:
        counts["zero_area"] += 1
        return
    unit = tuple(c / (2.0 * area) for c in normal)
    # Planarity against the plane of the outer ring through the rings' centroid.
    every = [points_of(i) for ring in polygon for i in ring]
    centroid = tuple(sum(p[k] for p in every) / len(every) for k in range(3))
    if max(abs(_dot(_sub(p, centroid), unit)) for p in every) > PLANARITY_TOLERANCE_M:
        counts["non_planar"] += 1
    outer_2d = _project(outer, normal, outer[0])
    for hole in polygon[1:]:
        points = [points_of(i) for i in hole]
        if len(points) < 3:
            continue
        hole_normal = _newell(points)
        hole_2d = _project(points, normal, outer[0])
        probe = ((hole_2d[0][0] + hole_2d[1][0]) / 2, (hole_2d[0][1] + hole_2d[1][1]) / 2)
        if _dot(hole_normal, normal) >= 0.0 or not _inside(probe, outer_2d):
            counts["hole_outside"] += 1


def _check_shell(shell, points_of, counts, solid):
    """Closure, vertex fans and orientation of one shell (a list of polygons)."""
    directed = defaultdict(int)
    around = defaultdict(list)  # vertex -> (previous, next) of each ring passing it
    for polygon in shell:
        for ring in polygon:
            for k, v in enumerate(ring):
                w = ring[(k + 1) % len(ring)]
                directed[(v, w)] += 1
                around[v].append((ring[k - 1], w))
    for (v, w), n in directed.items():
        if n != 1 or directed.get((w, v), 0) != 1:
            counts["open_shell"] += 1
    for v, passes in around.items():
        # One fan: the passes chained by shared edges (next of one is the previous of another)
        # form a single cycle.
        seen, stack = {0}, [0]
        index_of_previous = defaultdict(list)
        for i, (previous, _) in enumerate(passes):
            index_of_previous[previous].append(i)
        while stack:
            i = stack.pop()
            for j in index_of_previous.get(passes[i][1], []):
                if j not in seen:
                    seen.add(j)
                    stack.append(j)
        if len(seen) != len(passes):
            counts["non_manifold_vertex"] += 1
    if solid:
        six_volume = 0.0
        origin = points_of(shell[0][0][0])
        for polygon in shell:
            for ring in polygon:
                a = _sub(points_of(ring[0]), origin)
                for k in range(1, len(ring) - 1):
                    b = _sub(points_of(ring[k]), origin)
                    c = _sub(points_of(ring[k + 1]), origin)
                    six_volume += _dot(a, _cross(b, c))
        if six_volume <= 0.0:
            counts["inward_shell"] += 1


def _check_objects(city_objects, vertices, transform, counts):
    scale, translate = transform["scale"], transform["translate"]

    def points_of(i):
        return tuple(vertices[i][k] * scale[k] + translate[k] for k in range(3))

    if len({tuple(v) for v in vertices}) != len(vertices):
        counts["duplicate_vertices"] += len(vertices) - len({tuple(v) for v in vertices})
    for obj in city_objects.values():
        for geometry in obj.get("geometry", []):
            kind = geometry["type"]
            if kind == "Solid":
                shells = geometry["boundaries"]
            elif kind == "CompositeSolid" or kind == "MultiSolid":
                shells = [shell for solid in geometry["boundaries"] for shell in solid]
            else:
                shells = [geometry["boundaries"]]
            for shell in shells:
                for polygon in shell:
                    _check_polygon(polygon, points_of, counts)
                _check_shell(shell, points_of, counts, solid=kind != "CompositeSurface"
                             and kind != "MultiSurface")


def check_file(path, validators=None):
    """Defect counts of a CityJSON (.city.json) or CityJSONSeq (.jsonl) file, plus the number
    of buildings and polygons it holds."""
    counts = {name: 0 for name in CLASSES}
    buildings = polygons = 0
    with open(path, encoding="utf-8") as f:
        if path.endswith(".jsonl"):
            documents = [json.loads(line) for line in f if line.strip()]
        else:
            documents = [json.load(f)]
    header = documents[0]
    for i, document in enumerate(documents):
        if validators:
            validator = validators[0] if i == 0 else validators[1]
            counts["schema"] += sum(1 for _ in validator.iter_errors(document))
        _check_objects(document["CityObjects"], document["vertices"], header["transform"], counts)
        for obj in document["CityObjects"].values():
            buildings += obj["type"] == "Building"
            for geometry in obj.get("geometry", []):
                boundaries = geometry["boundaries"]
                polygons += len(boundaries[0]) if geometry["type"] == "Solid" else len(boundaries)
    return {"file": path, "version": header.get("version"), "buildings": buildings,
            "polygons": polygons, "schema_checked": bool(validators), **counts}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--schemas", help="folder of the official CityJSON schemas")
    parser.add_argument("files", nargs="+")
    args = parser.parse_args()
    validators = load_validators(args.schemas) if args.schemas else None
    if args.schemas and not validators:
        print(f"cityjson_check: no CityJSON schemas in {args.schemas}", file=sys.stderr)
        return 2
    bad = False
    for path in args.files:
        result = check_file(path, validators)
        bad = bad or any(result[name] for name in CLASSES)
        print(json.dumps(result))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
