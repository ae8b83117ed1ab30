"""Ctrl-C (SIGINT) during a long reconstruction raises KeyboardInterrupt promptly."""

import os
import signal
import subprocess
import tempfile
import threading
import time
import unittest

import linesurf
import support

# Generous against a loaded 2-core CI machine; the engine polls the cancel flag per chunk.
PROMPT_SECONDS = 5.0
INTERRUPT_AFTER_SECONDS = 0.5


def large_scene(tmp):
    """Andalusian from LINESURF_SHARED_DIR, else a synthetic city from the CLI, else None."""
    andalusian = os.path.join(support.SHARED_DIR, "data", "andalusian",
                              "input_lines_from_residuals.json")
    if support.SHARED_DIR and os.path.exists(andalusian):
        return linesurf.read_scene(andalusian)
    if support.CLI and os.path.exists(support.CLI):
        support.run_cli("synth", "city", "-o", tmp)
        return linesurf.read_scene(os.path.join(tmp, "lines.json"))
    return None


class Interrupt(unittest.TestCase):
    def test_sigint_raises_keyboard_interrupt_promptly(self):
        with tempfile.TemporaryDirectory() as tmp:
            scene = large_scene(tmp)
        if scene is None:
            self.skipTest("no large scene: neither Andalusian in LINESURF_SHARED_DIR nor the CLI")
        sent = []

        def interrupt():
            sent.append(time.monotonic())
            os.kill(os.getpid(), signal.SIGINT)

        timer = threading.Timer(INTERRUPT_AFTER_SECONDS, interrupt)
        timer.start()
        try:
            with self.assertRaises(KeyboardInterrupt):
                linesurf.reconstruct(scene, num_threads=2)
        finally:
            timer.cancel()
        self.assertTrue(sent, "the run ended before the signal: the scene is too small")
        self.assertLess(time.monotonic() - sent[0], PROMPT_SECONDS)


if __name__ == "__main__":
    unittest.main()
