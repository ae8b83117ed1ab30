#!/usr/bin/env python3
"""Where a synthetic reconstruction goes wrong: which detected planes and which faces.

  plane_audit.py planes SYNTH_DIR DETECTED.json
      every plane of DETECTED.json (`linesurf detect` output for SYNTH_DIR/lines.json): normal,
      offset, its segments, its distinct lines (collinear parts of one line count once) and the
      true planes of its segments (from SYNTH_DIR/meta.json, "out" = outliers), most frequent first.
  plane_audit.py far RESULT.ply GROUND_TRUTH.ply [THRESHOLD]
      the faces of RESULT with samples farther than THRESHOLD (default 0.05) from the ground
      truth, by far area: the plane each lies on, its area, the largest distance and a vertex.

Binary little-endian PLY (as linesurf writes it). Python 3 standard library only; slow (pure
Python point-to-triangle distances), meant for scenes of a few thousand faces.
"""

import collections
import json
import math
import random
import struct
import sys

PLY_TYPES = {"double": "d", "float64": "d", "float": "f", "float32": "f", "uchar": "B",
             "uint8": "B", "uint": "I", "uint32": "I", "int": "i", "int32": "i"}


def read_ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    counts, vertex_types, list_types, element = {}, [], None, None
    for line in data[:end].decode().splitlines():
        words = line.split()
        if words[0] == "format" and words[1] != "binary_little_endian":
            sys.exit(f"{path}: only binary_little_endian PLY is read")
        if words[0] == "element":
            element = words[1]
            counts[element] = int(words[2])
        elif words[0] == "property" and element == "vertex":
            vertex_types.append(PLY_TYPES[words[1]])
        elif words[0] == "property" and element == "face":
            list_types = (PLY_TYPES[words[2]], PLY_TYPES[words[3]])
    vertex_format = "<" + "".join(vertex_types)
    offset, vertices, faces = end, [], []
    for _ in range(counts.get("vertex", 0)):
        vertices.append(struct.unpack_from(vertex_format, data, offset)[:3])
        offset += struct.calcsize(vertex_format)
    for _ in range(counts.get("face", 0)):
        (n,) = struct.unpack_from("<" + list_types[0], data, offset)
        offset += struct.calcsize("<" + list_types[0])
        faces.append(struct.unpack_from("<" + list_types[1] * n, data, offset))
        offset += n * struct.calcsize("<" + list_types[1])
    return vertices, faces


def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def along(a, d, t): return (a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2])
def norm(a): return math.sqrt(dot(a, a))


def triangle_distance(p, a, b, c):
    """Distance from p to triangle abc (closest-feature regions, Ericson 5.1.5)."""
    ab, ac, ap = sub(b, a), sub(c, a), sub(p, a)
    d1, d2 = dot(ab, ap), dot(ac, ap)
    if d1 <= 0 and d2 <= 0:
        return norm(ap)
    bp = sub(p, b)
    d3, d4 = dot(ab, bp), dot(ac, bp)
    if d3 >= 0 and d4 <= d3:
        return norm(bp)
    vc = d1 * d4 - d3 * d2
    if vc <= 0 and d1 >= 0 and d3 <= 0:
        return norm(sub(p, along(a, ab, d1 / (d1 - d3))))
    cp = sub(p, c)
    d5, d6 = dot(ab, cp), dot(ac, cp)
    if d6 >= 0 and d5 <= d6:
        return norm(cp)
    vb = d5 * d2 - d1 * d6
    if vb <= 0 and d2 >= 0 and d6 <= 0:
        return norm(sub(p, along(a, ac, d2 / (d2 - d6))))
    va = d3 * d6 - d5 * d4
    if va <= 0 and d4 - d3 >= 0 and d5 - d6 >= 0:
        return norm(sub(p, along(b, sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6)))))
    v, w = vb / (va + vb + vc), vc / (va + vb + vc)
    return norm(sub(p, along(along(a, ab, v), ac, w)))


def triangles(vertices, face):
    for k in range(1, len(face) - 1):
        yield vertices[face[0]], vertices[face[k]], vertices[face[k + 1]]


def far_faces(result_path, truth_path, threshold):
    vertices, faces = read_ply(result_path)
    truth_vertices, truth_faces = read_ply(truth_path)
    truth = [t for f in truth_faces for t in triangles(truth_vertices, f)]
    rng = random.Random(1)
    rows, total_area, total_far = [], 0.0, 0.0
    for index, face in enumerate(faces):
        area, normal, samples = 0.0, (0.0, 0.0, 0.0), []
        for a, b, c in triangles(vertices, face):
            n = cross(sub(b, a), sub(c, a))
            normal = (normal[0] + n[0], normal[1] + n[1], normal[2] + n[2])
            area += 0.5 * norm(n)
            for _ in range(max(1, int(4 * 0.5 * norm(n)))):  # ~4 samples per unit area
                u, v = rng.random(), rng.random()
                if u + v > 1:
                    u, v = 1 - u, 1 - v
                samples.append(along(along(a, sub(b, a), u), sub(c, a), v))
        distances = [min(triangle_distance(p, *t) for t in truth) for p in samples]
        far = area * sum(d > threshold for d in distances) / len(distances)
        total_area += area
        total_far += far
        if far > 0:
            unit = tuple(x / max(norm(normal), 1e-300) for x in normal)
            rows.append((far, index, area, unit, dot(unit, vertices[face[0]]), max(distances),
                         vertices[face[0]]))
    print(f"{result_path}: area {total_area:.1f}, of it farther than {threshold} from the ground "
          f"truth {total_far:.1f} ({100 * total_far / max(total_area, 1e-300):.1f} %)")
    for far, index, area, n, offset, worst, vertex in sorted(rows, reverse=True)[:40]:
        print(f"far {far:8.2f} of face {index:5d} (area {area:8.2f}) on n=({n[0]:+.3f},{n[1]:+.3f},"
              f"{n[2]:+.3f}) d={offset:+9.3f}, max distance {worst:.2f}, vertex "
              f"({vertex[0]:.1f}, {vertex[1]:.1f}, {vertex[2]:.1f})")


def line_key(segment):
    """The infinite line of a segment, rounded: collinear parts of one line share it."""
    a, b = segment["pt1"], segment["pt2"]
    d = sub(b, a)
    d = tuple(x / norm(d) for x in d)
    if d[max(range(3), key=lambda k: abs(d[k]))] < 0:
        d = tuple(-x for x in d)
    t = dot(a, d)
    return tuple(round(x, 5) for x in d + tuple(a[k] - t * d[k] for k in range(3)))


def planes(synth_dir, detected_path):
    meta = json.load(open(f"{synth_dir}/meta.json"))
    detected = json.load(open(detected_path))
    keys = [line_key(s) for s in detected["lines"]]
    members = collections.defaultdict(list)
    for i, segment in enumerate(detected["lines"]):
        for p in segment.get("plane_index", []):
            members[p].append(i)
    print(f"{len(detected['lines'])} segments, {len(set(keys))} distinct lines, "
          f"{len(detected['planes'])} planes; true planes: "
          + ", ".join(f"{i} n={tuple(round(x, 3) for x in p['normal'])} "
                      f"d={dot(p['normal'], p['point']):.3f}" for i, p in enumerate(meta["planes"])))
    for p, plane in enumerate(detected["planes"]):
        n, segments = plane["normal"], members[p]
        truth = collections.Counter()
        for s in segments:
            info = meta["segments"][s]
            truth.update(info["planes"] if info["kind"] != "outlier" else ["out"])
        print(f"{p:4d} n=({n[0]:+.3f},{n[1]:+.3f},{n[2]:+.3f}) d={dot(n, plane['inlier']):+9.3f} "
              f"segments {len(segments):5d} lines {len({keys[s] for s in segments}):4d} "
              f"true planes {truth.most_common(4)}")


if __name__ == "__main__":
    if len(sys.argv) >= 4 and sys.argv[1] == "planes":
        planes(sys.argv[2], sys.argv[3])
    elif len(sys.argv) in (4, 5) and sys.argv[1] == "far":
        far_faces(sys.argv[2], sys.argv[3], float(sys.argv[4]) if len(sys.argv) == 5 else 0.05)
    else:
        sys.exit(__doc__)
