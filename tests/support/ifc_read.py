"""A minimal reader of the IFC4 STEP files linesurf writes, independent of linesurf's code:
entities by id, the site placement, every IfcFacetedBrep / IfcShellBasedSurfaceModel face with
its loops, and from them the face count and the signed volume (divergence theorem)."""

import re

ENTITY = re.compile(r"^#(\d+)=(\w+)\((.*)\);$")


def _refs(text):
    return [int(x) for x in re.findall(r"#(\d+)", text)]


def _numbers(text):
    return [float(x) for x in re.findall(r"[-+]?\d+\.\d*(?:E[-+]?\d+)?", text)]


def read_ifc(path):
    entities = {}
    schema = None
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.strip()
            if line.startswith("FILE_SCHEMA"):
                schema = re.findall(r"'([^']*)'", line)[0]
            m = ENTITY.match(line)
            if m:
                entities[int(m.group(1))] = (m.group(2), m.group(3))

    def point(i):
        kind, args = entities[i]
        assert kind == "IFCCARTESIANPOINT", kind
        return _numbers(args)

    site = next(args for kind, args in entities.values() if kind == "IFCSITE")
    placement = _refs(site)[0]
    axes = _refs(entities[placement][1])[-1]
    origin = point(_refs(entities[axes][1])[0])
    faces = 0
    six_volume = 0.0
    lowest = [float("inf")] * 3
    for kind, args in entities.values():
        if kind != "IFCFACE":
            continue
        faces += 1
        for bound in _refs(args):
            loop = _refs(entities[bound][1])[0]
            same = entities[bound][1].endswith(".T.")
            ring = [point(i) for i in _refs(entities[loop][1])]
            if not same:
                ring.reverse()
            ring = [[p[k] + origin[k] for k in range(3)] for p in ring]
            for p in ring:
                lowest = [min(lowest[k], p[k]) for k in range(3)]
            a = ring[0]
            for k in range(1, len(ring) - 1):
                b, c = ring[k], ring[k + 1]
                six_volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                               + a[2] * (b[0] * c[1] - b[1] * c[0]))
    crs = [re.findall(r"'([^']*)'", args)[0] for kind, args in entities.values()
           if kind == "IFCPROJECTEDCRS"]
    return {"schema": schema, "faces": faces, "volume": six_volume / 6.0,
            "buildings": sum(1 for kind, _ in entities.values() if kind == "IFCBUILDING"),
            "crs": crs[0] if crs else None, "min_corner": lowest}
