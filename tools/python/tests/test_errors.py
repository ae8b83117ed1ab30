"""Bad input, bad options and cancels raise the linesurf.Error subclass that names the fault."""

import unittest

import numpy as np

import linesurf
import support


class Errors(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scene = linesurf.read_scene(support.HOUSE)

    def test_error_classes_follow_the_error_codes(self):
        self.assertTrue(issubclass(linesurf.InvalidInput, linesurf.Error))
        self.assertTrue(issubclass(linesurf.InvalidInput, ValueError))
        self.assertTrue(issubclass(linesurf.InvalidOptions, ValueError))
        self.assertTrue(issubclass(linesurf.Cancelled, linesurf.Error))

    def test_observation_out_of_range_names_the_index(self):
        s = self.scene
        observations = s.observations.copy()
        observations[7, 1] = len(s.viewpoints)
        with self.assertRaises(linesurf.InvalidInput) as caught:
            linesurf.reconstruct(s.segments, s.viewpoints, observations)
        self.assertEqual(caught.exception.code, "invalid_input")
        self.assertIn("observations[7].viewpoint", str(caught.exception))

    def test_negative_index_names_the_index(self):
        s = self.scene
        observations = s.observations.astype(np.int64)
        observations[3, 0] = -1
        with self.assertRaises(linesurf.InvalidInput) as caught:
            linesurf.reconstruct(s.segments, s.viewpoints, observations)
        self.assertIn("observations[3].segment", str(caught.exception))

    def test_wrong_shapes_and_dtypes_name_the_array(self):
        s = self.scene
        with self.assertRaisesRegex(ValueError, r"segments: expected an array of shape"):
            linesurf.reconstruct(np.zeros((4, 5)), s.viewpoints, s.observations)
        with self.assertRaisesRegex(ValueError, r"viewpoints: .*got \(2, 2\)"):
            linesurf.reconstruct(s.segments, np.zeros((2, 2)), s.observations)
        with self.assertRaisesRegex(TypeError, r"observations: expected an integer array"):
            linesurf.reconstruct(s.segments, s.viewpoints, s.observations.astype(float))

    def test_empty_scene_is_invalid_input(self):
        with self.assertRaises(linesurf.InvalidInput):
            linesurf.reconstruct(np.zeros((0, 6)), np.zeros((0, 3)), np.zeros((0, 2), int))

    def test_unknown_option_is_a_type_error_naming_it(self):
        with self.assertRaisesRegex(TypeError, r"unknown option 'visibilty'"):
            linesurf.reconstruct(self.scene, visibilty=0.5)
        with self.assertRaisesRegex(TypeError, r"unknown option 'weights.visibilty'"):
            linesurf.reconstruct(self.scene, weights={"visibilty": 0.5})
        with self.assertRaisesRegex(TypeError, r"option 'seed' cannot be 'x'"):
            linesurf.detect_planes(self.scene, seed="x")

    def test_out_of_range_option_is_a_value_error_with_the_facade_message(self):
        expected = linesurf.ReconstructOptions()
        expected.weights.visibility = -1.0
        with self.assertRaises(linesurf.InvalidOptions) as facade:
            expected.validate()
        with self.assertRaises(ValueError) as caught:
            linesurf.reconstruct(self.scene, weights={"visibility": -1.0})
        self.assertIsInstance(caught.exception, linesurf.InvalidOptions)
        self.assertEqual(caught.exception.message, facade.exception.message)
        self.assertIn("weights.visibility", str(caught.exception))

    def test_unknown_enum_name_is_invalid_options(self):
        with self.assertRaisesRegex(linesurf.InvalidOptions, r"solver.backend: unknown value"):
            linesurf.reconstruct(self.scene, solver={"backend": "simplex"})

    def test_missing_file_is_invalid_input_naming_it(self):
        with self.assertRaises(linesurf.InvalidInput) as caught:
            linesurf.read_scene("/nonexistent/lines.json")
        self.assertIn("/nonexistent/lines.json", str(caught.exception))

    def test_bad_mesh_extension_is_invalid_input(self):
        result = linesurf.Mesh.from_faces([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
        with self.assertRaises(linesurf.InvalidInput):
            linesurf.write_mesh("/tmp/linesurf_python_mesh.xyz", result)

    def test_cancel_from_the_progress_callback_raises_cancelled(self):
        calls = []

        def cancel_at_once(stage, fraction):
            calls.append(stage)
            return True

        with self.assertRaises(linesurf.Cancelled) as caught:
            linesurf.reconstruct(self.scene, scene_mode="exterior", progress=cancel_at_once)
        self.assertEqual(caught.exception.code, "cancelled")
        self.assertEqual(len(set(calls)), 1, f"stages after the cancel: {calls}")

    def test_exception_in_the_progress_callback_propagates(self):
        def fail(stage, fraction):
            raise RuntimeError(f"host failed in {stage}")

        with self.assertRaisesRegex(RuntimeError, r"host failed in"):
            linesurf.reconstruct(self.scene, progress=fail)


if __name__ == "__main__":
    unittest.main()
