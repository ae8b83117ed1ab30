"""Ctrl-C (SIGINT) during a long reconstruction raises KeyboardInterrupt promptly: counted in
stages, not seconds (the latency is a benchmark's, tests/bench/api_bench.cpp)."""

import os
import signal
import subprocess
import tempfile
import threading
import unittest

import linesurf
import support

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
        stages = []  # the stage of each progress report
        stages_at_signal = []

        def interrupt():
            stages_at_signal.append(len(stages))
            os.kill(os.getpid(), signal.SIGINT)

        timer = threading.Timer(INTERRUPT_AFTER_SECONDS, interrupt)
        timer.start()
        try:
            with self.assertRaises(KeyboardInterrupt):
                linesurf.reconstruct(scene, num_threads=2,
                                     progress=lambda stage, fraction: stages.append(stage))
        finally:
            timer.cancel()
        self.assertTrue(stages_at_signal, "the run ended before the signal: the scene is too small")
        # The stage under way when the signal came may end and at most one more begin before the
        # engine polls the flag; a run that ignored the signal would report every later stage.
        running = stages[stages_at_signal[0] - 1:stages_at_signal[0]]
        later = set(stages[stages_at_signal[0]:]) - set(running)
        self.assertLessEqual(len(later), 1,
                             f"stages after SIGINT in {running}: {sorted(later)}")


if __name__ == "__main__":
    unittest.main()
