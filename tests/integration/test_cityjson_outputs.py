"""CityJSON 2.0, CityJSONSeq and IFC4 written by `linesurf reconstruct`: CityJSON checked by an
independent checker (tests/support/cityjson_check.py) and, when ../shared holds them, by the
official CityJSON 2.0.2 schemas (the checker itself is shown to catch every defect class on
hand-made files); IFC read back by a STEP reader of its own (tests/support/ifc_read.py) with the
volume and face count of the reconstruction."""

import copy
import json
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "support"))
import cityjson_check  # noqa: E402
import ifc_read  # noqa: E402

CLI = os.environ.get("LINESURF_CLI", "")
SOURCE_DIR = os.environ.get("LINESURF_SOURCE_DIR", os.path.join(HERE, "..", ".."))
SHARED_DIR = os.environ.get("LINESURF_SHARED_DIR", os.path.join(SOURCE_DIR, "..", "shared"))
SCHEMA_DIR = os.path.join(SHARED_DIR, "reference", "cityjson-2.0.2")
HOUSE = os.path.join(SOURCE_DIR, "docs", "examples", "house", "lines.json")


def run_cli(*args):
    env = {k: v for k, v in os.environ.items() if k != "LD_PRELOAD"}
    done = subprocess.run([CLI, "--quiet", *args], capture_output=True, text=True, check=False,
                          env=env)
    if done.returncode != 0:
        raise AssertionError(f"linesurf {' '.join(args)} exited {done.returncode}: {done.stderr}")
    return done


def defects(result):
    return {name: result[name] for name in cityjson_check.CLASSES if result[name]}


class WrittenFiles(unittest.TestCase):
    """The example house and a georeferenced synthetic city, as CityJSON and CityJSONSeq."""

    @classmethod
    def setUpClass(cls):
        if not CLI or not os.path.exists(CLI):
            raise unittest.SkipTest("LINESURF_CLI is not set: the CLI is not built")
        cls.dir = tempfile.TemporaryDirectory()
        cls.validators = cityjson_check.load_validators(SCHEMA_DIR)
        out = cls.dir.name
        city = os.path.join(out, "city")
        run_cli("synth", "city", "--size", "4", "--seed", "3", "--offset", "1000000", "-o", city)
        cls.files = {}
        for name, scene, extra in (("house", HOUSE, ["--scene", "exterior"]),
                                   ("city", os.path.join(city, "lines.json"),
                                    ["--crs", "EPSG:7415"])):
            for ext in (".city.json", ".city.jsonl", ".ifc"):
                path = os.path.join(out, name + ext)
                report = os.path.join(out, name + ext + ".report.json")
                run_cli("reconstruct", scene, "-o", path, "--report", report, *extra)
                cls.files[name + ext] = path
                cls.files[name + ext + ".report"] = report

    @classmethod
    def tearDownClass(cls):
        cls.dir.cleanup()

    def test_ifc_reads_back_with_the_volume_and_faces(self):
        for name in ("house", "city"):
            model = ifc_read.read_ifc(self.files[name + ".ifc"])
            with open(self.files[name + ".ifc.report"], encoding="utf-8") as f:
                volume = json.load(f)["validity"]["signed_volume"]
            city = cityjson_check.check_file(self.files[name + ".city.json"])
            self.assertEqual(model["schema"], "IFC4", name)
            self.assertEqual(model["buildings"], city["buildings"], name)
            self.assertEqual(model["faces"], city["polygons"], name)
            self.assertAlmostEqual(model["volume"], volume, delta=1e-6 * abs(volume), msg=name)
        crs = ifc_read.read_ifc(self.files["city.ifc"])
        self.assertEqual(crs["crs"], "EPSG:7415")
        self.assertGreater(crs["min_corner"][0], 999000.0)  # the 1e6 m offset kept

    def test_every_file_is_valid(self):
        for name, path in self.files.items():
            if not name.endswith((".city.json", ".city.jsonl")):
                continue
            result = cityjson_check.check_file(path, self.validators)
            self.assertEqual(result["version"], "2.0", name)
            self.assertEqual(defects(result), {}, name)
            self.assertGreater(result["buildings"], 0, name)

    def test_against_the_official_schemas(self):
        if self.validators is None:
            self.skipTest(f"no CityJSON 2.0.2 schemas in {SCHEMA_DIR} (../shared/reference)")
        for name, path in self.files.items():
            if name.endswith((".city.json", ".city.jsonl")):
                self.assertTrue(cityjson_check.check_file(path, self.validators)["schema_checked"])

    def test_sequence_holds_the_document_buildings(self):
        for name in ("house", "city"):
            with open(self.files[name + ".city.json"], encoding="utf-8") as f:
                document = json.load(f)
            with open(self.files[name + ".city.jsonl"], encoding="utf-8") as f:
                lines = [json.loads(line) for line in f]
            self.assertEqual(lines[0]["type"], "CityJSON")
            self.assertEqual(lines[0]["transform"], document["transform"])
            features = lines[1:]
            self.assertEqual([f["id"] for f in features], list(document["CityObjects"]))
            for feature in features:
                self.assertEqual(feature["type"], "CityJSONFeature")
                self.assertEqual(feature["CityObjects"][feature["id"]]["geometry"][0]["lod"], "2.2")

    def test_house_is_one_building_of_merged_planar_polygons(self):
        result = cityjson_check.check_file(self.files["house.city.json"])
        self.assertEqual(result["buildings"], 1)
        # Four walls, two roof planes and the ground: one polygon per plane.
        self.assertEqual(result["polygons"], 7)
        with open(self.files["house.city.json"], encoding="utf-8") as f:
            geometry = json.load(f)["CityObjects"]["building_0"]["geometry"][0]
        types = sorted(geometry["semantics"]["surfaces"][v]["type"]
                       for v in geometry["semantics"]["values"][0])
        self.assertEqual(types, ["GroundSurface"] + ["RoofSurface"] * 2 + ["WallSurface"] * 4)

    def test_georeferenced_city_keeps_its_frame(self):
        with open(self.files["city.city.json"], encoding="utf-8") as f:
            document = json.load(f)
        self.assertEqual(document["metadata"]["referenceSystem"],
                         "https://www.opengis.net/def/crs/EPSG/0/7415")
        extent = document["metadata"]["geographicalExtent"]
        self.assertGreater(extent[0], 999000.0)  # x and y offset by 1e6 m
        self.assertGreater(extent[1], 999000.0)
        self.assertLessEqual(document["transform"]["scale"][0], 1e-3)  # millimetres or finer

    def test_bad_crs_is_refused_before_the_run(self):
        env = {k: v for k, v in os.environ.items() if k != "LD_PRELOAD"}
        out = os.path.join(self.dir.name, "bad.city.json")
        done = subprocess.run([CLI, "reconstruct", HOUSE, "-o", out, "--crs", "WGS84"],
                              capture_output=True, text=True, check=False, env=env)
        self.assertNotEqual(done.returncode, 0)
        self.assertIn("crs", done.stderr)
        self.assertFalse(os.path.exists(out))


def unit_cube():
    """A valid CityJSON 2.0 document: one Building, a unit cube Solid (millimetre integers)."""
    vertices = [[x * 1000, y * 1000, z * 1000] for z in (0, 1) for y in (0, 1) for x in (0, 1)]
    faces = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    return {"type": "CityJSON", "version": "2.0",
            "transform": {"scale": [0.001, 0.001, 0.001], "translate": [0.0, 0.0, 0.0]},
            "CityObjects": {"b": {"type": "Building", "geometry": [
                {"type": "Solid", "lod": "2.2", "boundaries": [[[f] for f in faces]]}]}},
            "vertices": vertices}


class CheckerCatchesEveryClass(unittest.TestCase):
    """Hand-made invalid files: each breaks one class and the checker counts it."""

    def check(self, document):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "m.city.json")
            with open(path, "w", encoding="utf-8") as f:
                json.dump(document, f)
            return defects(cityjson_check.check_file(path))

    def shell(self, document):
        return document["CityObjects"]["b"]["geometry"][0]["boundaries"][0]

    def test_valid_cube_has_no_defect(self):
        self.assertEqual(self.check(unit_cube()), {})

    def test_duplicate_vertex(self):
        d = unit_cube()
        d["vertices"].append([0, 0, 0])
        self.assertIn("duplicate_vertices", self.check(d))

    def test_ring_of_two_points(self):
        d = unit_cube()
        self.shell(d)[0] = [[0, 2, 0]]
        self.assertIn("too_few_points", self.check(d))

    def test_repeated_ring_point(self):
        d = unit_cube()
        self.shell(d)[0] = [[0, 2, 3, 2, 1]]
        self.assertIn("repeated_ring_points", self.check(d))

    def test_non_planar_polygon(self):
        d = unit_cube()
        d["vertices"][3] = [1000, 1000, 50]  # 5 cm off the ground plane
        self.assertIn("non_planar", self.check(d))

    def test_zero_area_polygon(self):
        d = unit_cube()
        d["vertices"].append([500, 0, 0])
        self.shell(d).append([[0, 8, 1]])  # collinear: no area
        self.assertIn("zero_area", self.check(d))

    def test_hole_outside_or_same_orientation(self):
        d = unit_cube()
        d["vertices"] += [[200, 200, 0], [400, 200, 0], [400, 400, 0], [200, 400, 0]]
        # Same orientation as the ground's outer ring (clockwise seen from above).
        self.shell(d)[0].append([8, 11, 10, 9])
        self.assertIn("hole_outside", self.check(d))

    def test_open_shell(self):
        d = unit_cube()
        del self.shell(d)[1]
        self.assertIn("open_shell", self.check(d))

    def test_non_manifold_vertex(self):
        # Two cubes in one Solid touching at vertex (1, 1, 1) only.
        d = unit_cube()
        base = len(d["vertices"])
        d["vertices"] += [[x * 1000 + 1000, y * 1000 + 1000, z * 1000 + 1000]
                          for z in (0, 1) for y in (0, 1) for x in (0, 1)][1:]
        index = [7] + list(range(base, base + 7))  # the shared corner is cube 1's vertex 7
        for face in copy.deepcopy(unit_cube()["CityObjects"]["b"]["geometry"][0]["boundaries"][0]):
            self.shell(d).append([[index[v] for v in face[0]]])
        self.assertIn("non_manifold_vertex", self.check(d))

    def test_inward_shell(self):
        d = unit_cube()
        for polygon in self.shell(d):
            polygon[0].reverse()
        self.assertIn("inward_shell", self.check(d))


if __name__ == "__main__":
    unittest.main()
