"""reconstruct() on the bundled house gives the CLI's mesh bytes; results and options."""

import json
import os
import tempfile
import unittest

import numpy as np

import linesurf
import support


class ReconstructHouse(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scene = linesurf.read_scene(support.HOUSE)
        cls.result = linesurf.reconstruct(cls.scene, scene_mode="exterior")

    def test_scene_arrays_have_the_documented_shapes(self):
        s = self.scene
        self.assertEqual(s.segments.shape[1:], (2, 3))
        self.assertEqual(s.segments.dtype, np.float64)
        self.assertEqual(s.viewpoints.shape[1:], (3,))
        self.assertEqual(s.observations.shape[1:], (2,))
        self.assertGreater(len(s.segments), 0)
        self.assertLess(int(s.observations[:, 1].max()), len(s.viewpoints))

    def test_mesh_bytes_equal_the_cli(self):
        support.require_cli(self)
        with tempfile.TemporaryDirectory() as tmp:
            cli_mesh = os.path.join(tmp, "cli.ply")
            py_mesh = os.path.join(tmp, "python.ply")
            support.run_cli("reconstruct", support.HOUSE, "--scene", "exterior", "-o", cli_mesh)
            linesurf.write_mesh(py_mesh, self.result.mesh)
            with open(cli_mesh, "rb") as a, open(py_mesh, "rb") as b:
                self.assertEqual(a.read(), b.read())

    def test_report_is_the_clis_json(self):
        # One layout: the CLI's report is the library's plus the paths and the CLI's own output
        # options; only the timings and the peak memory of the two runs differ.
        support.require_cli(self)
        with tempfile.TemporaryDirectory() as tmp:
            report_path = os.path.join(tmp, "report.json")
            support.run_cli("reconstruct", support.HOUSE, "--scene", "exterior", "-o",
                            os.path.join(tmp, "cli.ply"), "--report", report_path)
            with open(report_path, encoding="utf-8") as f:
                cli = json.load(f)
        for key in ("input", "output", "output_options"):
            self.assertIn(key, cli)
            del cli[key]
        report = dict(self.result.report)
        for run in (cli, report):
            for key in ("stage_seconds", "total_seconds", "peak_memory_bytes"):
                self.assertIn(key, run)
                del run[key]
        # The CLI's thread count is its -j (0 = automatic), as the default of num_threads.
        self.assertEqual(report, cli)
        self.assertTrue(report["validity"]["valid"])

    def test_mesh_arrays_are_consistent_with_the_report(self):
        mesh, report = self.result.mesh, self.result.report
        self.assertEqual(mesh.vertices.shape, (report["mesh"]["vertices"], 3))
        self.assertEqual(mesh.num_faces, report["mesh"]["faces"])
        self.assertEqual(int(mesh.face_offsets[0]), 0)
        self.assertEqual(int(mesh.face_offsets[-1]), len(mesh.face_indices))
        self.assertLess(int(mesh.face_indices.max()), len(mesh.vertices))
        self.assertTrue(report["mesh"]["closed"] and report["mesh"]["manifold"])
        self.assertGreater(report["mesh"]["volume"], 0.0)
        self.assertEqual(report["scene_mode"], "exterior")
        self.assertEqual(len(mesh.faces()), mesh.num_faces)

    def test_planes_and_memberships_index_each_other(self):
        r = self.result
        self.assertEqual(r.planes.shape, (r.report["counts"]["planes"], 2, 3))
        np.testing.assert_allclose(np.linalg.norm(r.planes[:, 1], axis=1), 1.0, atol=1e-9)
        self.assertEqual(r.memberships.shape[1], 2)
        self.assertLess(int(r.memberships[:, 0].max()), len(self.scene.segments))
        self.assertLess(int(r.memberships[:, 1].max()), len(r.planes))

    def test_flat_segments_and_lists_give_the_same_mesh(self):
        s = self.scene
        flat = linesurf.reconstruct(s.segments.reshape(-1, 6).tolist(), s.viewpoints.tolist(),
                                    s.observations.astype(np.int64), scene_mode="exterior")
        np.testing.assert_array_equal(flat.mesh.vertices, self.result.mesh.vertices)
        np.testing.assert_array_equal(flat.mesh.face_indices, self.result.mesh.face_indices)

    def test_triangulate_gives_triangles(self):
        tri = linesurf.reconstruct(self.scene, scene_mode="exterior", triangulate=True)
        triangles = tri.mesh.triangles()
        self.assertEqual(triangles.shape[1], 3)
        self.assertGreater(len(triangles), self.result.mesh.num_faces)
        with self.assertRaises(ValueError):
            self.result.mesh.triangles()

    def test_merge_coplanar_gives_fewer_faces_of_the_same_solid(self):
        blocks = linesurf.reconstruct(self.scene, scene_mode="exterior", block_size=3.0)
        merged = linesurf.reconstruct(self.scene, scene_mode="exterior", block_size=3.0,
                                      merge_coplanar=True)
        self.assertLess(merged.mesh.num_faces, blocks.mesh.num_faces)
        self.assertAlmostEqual(merged.report["mesh"]["volume"], blocks.report["mesh"]["volume"],
                               delta=1e-9 * abs(blocks.report["mesh"]["volume"]))
        with self.assertRaisesRegex(linesurf.InvalidOptions, "merge_coplanar"):
            linesurf.reconstruct(self.scene, scene_mode="exterior", merge_coplanar=True,
                                 triangulate=True)

    def test_options_reach_the_run(self):
        r = linesurf.reconstruct(self.scene, scene_mode="exterior", sigma=0.25,
                                 solver={"backend": "clp"},
                                 weights={"visibility": 0.2, "crease": 0.3})
        self.assertEqual(r.report["sigma"], 0.25)
        self.assertEqual(r.report["crease_weight"], 0.3)
        self.assertEqual(r.report["solver"]["backend"], "clp")
        self.assertEqual(r.report["options"]["weights"]["visibility"], 0.2)

    def test_given_planes_reproduce_the_mesh(self):
        r = self.result
        again = linesurf.reconstruct(self.scene, planes=r.planes, memberships=r.memberships,
                                     scene_mode="exterior")
        self.assertEqual(again.report["counts"]["planes"], r.report["counts"]["planes"])
        self.assertEqual(again.report["options"]["plane_source"], "given")
        self.assertEqual(again.mesh.num_faces, r.mesh.num_faces)
        # The planes go through the engine's (normal, offset) form and back: last-bit changes.
        np.testing.assert_allclose(again.mesh.vertices, r.mesh.vertices, rtol=0, atol=1e-12)

    def test_prepared_solves_equal_fresh_reconstructions(self):
        prepared = linesurf.Reconstruction(self.scene, scene_mode="exterior")
        same = prepared.solve()
        np.testing.assert_array_equal(same.mesh.vertices, self.result.mesh.vertices)
        np.testing.assert_array_equal(same.mesh.face_indices, self.result.mesh.face_indices)
        other = prepared.solve(visibility=0.5, edge=0.05)
        fresh = linesurf.reconstruct(self.scene, scene_mode="exterior",
                                     weights={"visibility": 0.5, "edge": 0.05})
        np.testing.assert_array_equal(other.mesh.vertices, fresh.mesh.vertices)
        np.testing.assert_array_equal(other.mesh.face_indices, fresh.mesh.face_indices)
        self.assertEqual(prepared.options.weights.visibility,
                         linesurf.ReconstructOptions().weights.visibility)
        with self.assertRaisesRegex(TypeError, r"unknown option 'weights.sigma'"):
            prepared.solve(sigma=1.0)

    def test_detect_planes_matches_the_reconstruction_planes(self):
        d = linesurf.detect_planes(self.scene)
        np.testing.assert_array_equal(d.planes, self.result.planes)
        self.assertEqual(len(d.inlier_count), len(d.planes))
        self.assertEqual(d.report["stats"]["planes"], len(d.planes))
        self.assertEqual([p["inlier_count"] for p in d.report["planes"]], list(d.inlier_count))

    def test_progress_is_monotonic_per_stage(self):
        # Each stage runs once and its fraction never goes backwards (eps auto's probe
        # detections report as their own stage, estimate_epsilon, before detect_planes).
        calls = []
        linesurf.reconstruct(self.scene, scene_mode="exterior",
                             progress=lambda stage, f: calls.append((stage, f)))
        self.assertTrue(calls)
        stages = []
        for stage, fraction in calls:
            self.assertGreaterEqual(fraction, 0.0)
            self.assertLessEqual(fraction, 1.0)
            if not stages or stages[-1][0] != stage:
                self.assertNotIn(stage, [s for s, _ in stages], f"stage {stage} came back")
                stages.append([stage, fraction])
            else:
                self.assertGreaterEqual(fraction, stages[-1][1], f"{stage} went backwards")
                stages[-1][1] = fraction
        self.assertIn("estimate_epsilon", [s for s, _ in stages])
        self.assertGreaterEqual(len(stages), 4, f"stages reported: {stages}")

    def test_write_mesh_from_faces(self):
        mesh = linesurf.Mesh.from_faces([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
                                        [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "tet.obj")
            linesurf.write_mesh(path, mesh)
            with open(path, encoding="ascii") as f:
                text = f.read()
        self.assertEqual(text.count("\nv ") + text.startswith("v "), 4)
        self.assertEqual(text.count("f "), 4)


if __name__ == "__main__":
    unittest.main()
