"""Shared paths and scenes of the Python tests."""

import os
import subprocess
import unittest

SOURCE_DIR = os.environ.get("LINESURF_SOURCE_DIR",
                            os.path.join(os.path.dirname(__file__), "..", "..", ".."))
HOUSE = os.path.join(SOURCE_DIR, "docs", "examples", "house", "lines.json")
CLI = os.environ.get("LINESURF_CLI", "")
SHARED_DIR = os.environ.get("LINESURF_SHARED_DIR", "")


def require_cli(test):
    if not CLI or not os.path.exists(CLI):
        raise unittest.SkipTest("LINESURF_CLI is not set: the CLI is not built")
    del test


def cli_process(*args):
    """Runs `linesurf ARGS` and returns the completed process, whatever its exit."""
    # A sanitized build preloads the shared ASan runtime into python (CMakeLists.txt); the CLI
    # links its own, and two runtimes in one process abort.
    env = {k: v for k, v in os.environ.items() if k != "LD_PRELOAD"}
    return subprocess.run([CLI, *args], capture_output=True, text=True, check=False, env=env)


def run_cli(*args):
    """Runs `linesurf ARGS` and fails with its stderr when it exits non-zero."""
    done = cli_process(*args)
    if done.returncode != 0:
        raise AssertionError(f"linesurf {' '.join(args)} exited {done.returncode}: "
                             f"{done.stderr}")
    return done
