"""linesurf.distributed: every executor gives the CLI's bytes; a worker killed mid-run and a
driver killed and run again still give them; a damaged unit input ends the run partial (exit 7)
naming the unit."""

import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest

import support
from linesurf import distributed

# The bundled house on small detection blocks with few planes each: 23 work units, then the
# children of those that reach the cap (a second round).
OPTIONS = ["--detect-block-size", "4", "--max-planes", "5"]


def have_module(name):
    try:
        __import__(name)
        return True
    except ImportError:
        return False


class Distributed(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        support.require_cli(cls)
        cls.tmp = tempfile.mkdtemp(prefix="linesurf_distributed_")
        cls.reference = os.path.join(cls.tmp, "reference.ply")
        support.run_cli("-q", "reconstruct", support.HOUSE, "-o", cls.reference, *OPTIONS)
        with open(cls.reference, "rb") as f:
            cls.reference_bytes = f.read()

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def paths(self, name):
        return os.path.join(self.tmp, name + ".ply"), os.path.join(self.tmp, name + ".work")

    def run_with(self, name, executor, log=None):
        output, work_dir = self.paths(name)
        code = distributed.run_distributed(support.CLI, support.HOUSE, output, work_dir, executor,
                                           OPTIONS, log=log)
        executor.close()
        return code, output

    def assert_reference_bytes(self, output):
        with open(output, "rb") as f:
            self.assertEqual(f.read(), self.reference_bytes, f"{output} differs from the CLI's")

    def test_sequential_and_process_pools_give_the_clis_bytes(self):
        for name, executor in [("sequential", distributed.SequentialExecutor()),
                               ("processes", distributed.ProcessExecutor(2))]:
            code, output = self.run_with(name, executor)
            self.assertEqual(code, 0, name)
            self.assert_reference_bytes(output)

    def test_a_process_pool_worker_killed_mid_run_is_replaced(self):
        class KilledOnce(distributed.ProcessExecutor):
            """Its first pool loses a worker to SIGKILL as the units go in."""
            killed = False

            def _pool(self):
                pool = super()._pool()
                if not self.killed:
                    self.killed = True
                    os.kill(pool.submit(os.getpid).result(), signal.SIGKILL)
                return pool

        lines = []
        code, output = self.run_with("killed-worker", KilledOnce(2), log=lines.append)
        self.assertEqual(code, 0, "\n".join(lines))
        self.assertTrue(any("running it again" in line for line in lines), "\n".join(lines))
        self.assert_reference_bytes(output)

    @unittest.skipUnless(have_module("distributed"), "python3-distributed is not installed")
    def test_a_dask_local_cluster_of_two_workers_gives_the_clis_bytes_when_one_is_killed(self):
        from distributed import Client, LocalCluster
        with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                          dashboard_address=None) as cluster, Client(cluster) as client:
            pids = list(client.run(os.getpid).values())
            self.assertEqual(len(pids), 2)
            done = []

            def kill_a_worker_once(message):
                done.append(message)
                if len(done) == 3:
                    os.kill(pids[0], signal.SIGKILL)

            code, output = self.run_with("dask", distributed.DaskExecutor(client),
                                         log=kill_a_worker_once)
        self.assertEqual(code, 0, "\n".join(done))
        self.assert_reference_bytes(output)

    @unittest.skipUnless(shutil.which("mpirun") and have_module("mpi4py"),
                         "mpirun or python3-mpi4py is not installed")
    def test_three_mpi_ranks_give_the_clis_bytes(self):
        output, work_dir = self.paths("mpi")
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        done = subprocess.run(
            ["mpirun", "-n", "3", "--oversubscribe", "-x", "PYTHONPATH", sys.executable, "-m",
             "mpi4py.futures", "-m", "linesurf.distributed", support.HOUSE, "-o", output,
             "--work-dir", work_dir, "--executor", "mpi", "--linesurf", support.CLI, *OPTIONS],
            capture_output=True, text=True, env=env, timeout=300, check=False)
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assert_reference_bytes(output)

    def test_a_killed_driver_run_again_resumes_and_gives_the_clis_bytes(self):
        output, work_dir = self.paths("resumed")
        command = [sys.executable, "-m", "linesurf.distributed", support.HOUSE, "-o", output,
                   "--work-dir", work_dir, "--executor", "sequential", "--linesurf", support.CLI,
                   *OPTIONS]
        driver = subprocess.Popen(command, stderr=subprocess.DEVNULL)
        units = os.path.join(work_dir, "units")
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline and driver.poll() is None:
            if os.path.isdir(units) and sum(n.endswith(".result.json")
                                            for n in os.listdir(units)) >= 3:
                break
            time.sleep(0.002)
        driver.kill()
        driver.wait()
        self.assertFalse(os.path.exists(output), "a killed run leaves no output")
        finished = sum(n.endswith(".result.json") for n in os.listdir(units))
        self.assertGreaterEqual(finished, 3)
        again = subprocess.run(command, capture_output=True, text=True, check=False)
        self.assertEqual(again.returncode, 0, again.stderr)
        first = next(line for line in again.stderr.splitlines() if "already done" in line)
        self.assertNotIn(" 0 already done", first)
        self.assert_reference_bytes(output)

    def test_a_damaged_unit_input_ends_the_run_partial_naming_the_unit(self):
        output, work_dir = self.paths("damaged")
        planned = support.cli_process("-q", "reconstruct", support.HOUSE, "-o", output,
                                      "--work-dir", work_dir, *OPTIONS)
        self.assertEqual(planned.returncode, 6, planned.stderr)
        unit = planned.stdout.split()[0]
        with open(os.path.join(work_dir, "units", unit + ".input.json"), "w") as f:
            f.write("not json")
        # The worker that meets the damaged file records the unit as failed (a step before it
        # would write the input again).
        failed = support.cli_process("work-unit", "--work-dir", work_dir, unit)
        self.assertEqual(failed.returncode, distributed.EXIT_PARTIAL, failed.stderr)
        self.assertIn(unit + ".input.json", failed.stderr)
        done = subprocess.run(
            [sys.executable, "-m", "linesurf.distributed", support.HOUSE, "-o", output,
             "--work-dir", work_dir, "--executor", "processes", "--pool-size", "2",
             "--linesurf", support.CLI, *OPTIONS], capture_output=True, text=True, check=False)
        self.assertEqual(done.returncode, distributed.EXIT_PARTIAL, done.stderr)
        self.assertIn(f"work unit {unit} failed", done.stderr)
        self.assertTrue(os.path.exists(output), "a partial result is still written")

if __name__ == "__main__":
    unittest.main()
