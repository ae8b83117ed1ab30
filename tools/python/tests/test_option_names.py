"""Every option is declared once (linesurf/option_schema.h): the CLI's flags, the --config keys,
the C API's names, the Python fields and docs/user/cli_reference.md are exactly its set."""

import ctypes
import json
import os
import re
import tempfile
import unittest

import linesurf
import support

# The CLI's own options beside the library's (paths, report, output format, CRS, help).
CLI_OWN_FLAGS = {
    "reconstruct": {"--help", "--output", "--report", "--config", "--nvm", "--colmap", "--ascii",
                    "--cityjson", "--crs", "--work-dir"},
    "detect": {"--help", "--output", "--report", "--config", "--nvm", "--colmap", "--vg"},
}
# DetectOptions: the detection group, the seed and the thread count.
DETECT_PATHS = {"seed", "num_threads"}


def schema():
    """The options as `linesurf options --json` lists them (the schema, visited)."""
    return json.loads(support.run_cli("options", "--json").stdout)


def python_paths(options, prefix=""):
    """The option paths an options object exposes, nested groups walked."""
    paths = set()
    for name in type(options)._fields:
        value = getattr(options, name)
        if hasattr(type(value), "_fields"):
            paths |= python_paths(value, prefix + name + ".")
        else:
            paths.add(prefix + name)
    return paths


def help_flags(command):
    """The long flags `linesurf COMMAND --help` lists."""
    text = support.run_cli(command, "--help").stdout
    return set(re.findall(r"(?:^|[ ,])(--[a-z][a-z0-9-]*)", text))


class OptionNames(unittest.TestCase):
    def setUp(self):
        support.require_cli(self)
        self.rows = schema()
        self.paths = {r["path"] for r in self.rows}

    def test_the_schema_lists_every_option_once(self):
        self.assertEqual(len(self.paths), len(self.rows))
        flags = [r["flag"] for r in self.rows]
        self.assertEqual(len(set(flags)), len(flags))
        self.assertEqual(set(linesurf._linesurf._option_paths()), self.paths)

    def test_python_fields_are_the_paths(self):
        self.assertEqual(python_paths(linesurf.ReconstructOptions()), self.paths)
        detect = {p for p in self.paths if p.startswith("detection.")} | DETECT_PATHS
        self.assertEqual(python_paths(linesurf.DetectOptions()), detect)

    def test_cli_flags_are_the_flags(self):
        flags = {r["flag"] for r in self.rows if r["path"] != "num_threads"}
        self.assertEqual(help_flags("reconstruct") - CLI_OWN_FLAGS["reconstruct"], flags)
        detect = {r["flag"] for r in self.rows
                  if r["path"].startswith("detection.") and r["path"] != "plane_source"}
        detect.add("--seed")
        self.assertEqual(help_flags("detect") - CLI_OWN_FLAGS["detect"], detect)
        # num_threads is the global -j/--threads, given before the subcommand.
        self.assertIn("-j,--threads", support.run_cli("--help").stdout)

    def test_config_keys_are_the_paths(self):
        # A config holding every path at its default runs; the report's options are the same
        # paths, nested at the dots.
        defaults = linesurf.ReconstructOptions()
        config = {}
        for path in self.paths - {"num_threads"}:
            owner, name = defaults, path
            for group in path.split(".")[:-1]:
                owner = getattr(owner, group)
            name = path.split(".")[-1]
            config[path] = getattr(owner, name)
        config["scene_mode"] = "exterior"
        with tempfile.TemporaryDirectory() as tmp:
            config_path = os.path.join(tmp, "config.json")
            with open(config_path, "w", encoding="utf-8") as f:
                json.dump(config, f)
            report_path = os.path.join(tmp, "report.json")
            support.run_cli("reconstruct", support.HOUSE, "--config", config_path, "-o",
                            os.path.join(tmp, "m.ply"), "--report", report_path)
            with open(report_path, encoding="utf-8") as f:
                report = json.load(f)
            bad_path = os.path.join(tmp, "bad.json")
            with open(bad_path, "w", encoding="utf-8") as f:
                json.dump({"weights.visibilty": 1.0}, f)
            done = support.cli_process("reconstruct", support.HOUSE, "--config", bad_path, "-o",
                                       os.path.join(tmp, "n.ply"))
            self.assertEqual(done.returncode, 2, done.stderr)
            self.assertIn("'weights.visibilty' is not an option", done.stderr)

        def flatten(node, prefix=""):
            out = set()
            for key, value in node.items():
                out |= flatten(value, prefix + key + ".") if isinstance(value, dict) else {
                    prefix + key}
            return out
        self.assertEqual(flatten(report["options"]), self.paths)

    def test_c_names_are_the_paths(self):
        library = os.environ.get("LINESURF_LIBRARY", "")
        if not library:
            self.skipTest("LINESURF_LIBRARY is not set")
        c = ctypes.CDLL(library)
        c.linesurf_options_create.restype = ctypes.c_void_p
        c.linesurf_options_set_number.argtypes = [ctypes.c_void_p, ctypes.c_char_p,
                                                  ctypes.c_double, ctypes.c_void_p]
        c.linesurf_options_set_string.argtypes = [ctypes.c_void_p, ctypes.c_char_p,
                                                  ctypes.c_char_p, ctypes.c_void_p]
        c.linesurf_options_free.argtypes = [ctypes.c_void_p]
        options = c.linesurf_options_create()
        try:
            for row in self.rows:
                name = row["path"].encode()
                if row["type"].startswith("one of"):
                    status = c.linesurf_options_set_string(options, name,
                                                           row["default"].encode(), None)
                else:
                    value = {"true": 1.0, "false": 0.0, "unset": 1.0}.get(row["default"])
                    status = c.linesurf_options_set_number(
                        options, name, float(row["default"]) if value is None else value, None)
                self.assertEqual(status, 0, row["path"])
            self.assertNotEqual(c.linesurf_options_set_number(options, b"weights.visibilty",
                                                              1.0, None), 0)
        finally:
            c.linesurf_options_free(options)

    def test_the_reference_doc_lists_every_option(self):
        with open(os.path.join(support.SOURCE_DIR, "docs", "user", "cli_reference.md"),
                  encoding="utf-8") as f:
            doc = f.read()
        listed = set(re.findall(r"^\| `([a-z_.]+)` \|", doc, flags=re.M))
        self.assertEqual(listed, self.paths)


if __name__ == "__main__":
    unittest.main()
