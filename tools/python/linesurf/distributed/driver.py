"""The driver of linesurf.distributed: calls `linesurf reconstruct --work-dir` until it finishes,
running the work units each call names on an executor in between."""

import os
import subprocess
import sys

# Exit codes of `linesurf reconstruct` (docs/user/cli.md) the driver acts on or returns.
EXIT_OK = 0
EXIT_FAILED = 4
EXIT_UNITS_PENDING = 6
EXIT_PARTIAL = 7


def run_distributed(cli, input_path, output, work_dir, executor, reconstruct_args=(), threads=1,
                    log=None, step_threads=0):
    """Runs the reconstruction of `input_path` into `output` over `work_dir`, the work units on
    `executor` (executors.py), each with `threads` threads, the steps with `step_threads` (0 =
    every core: they run the stages that are not units). Returns the exit code of the last
    `linesurf reconstruct` call (0 done, 7 done without the planes of failed units, other codes
    its errors) or EXIT_FAILED when a unit could not be run (UnitError, logged)."""
    from .executors import UnitError
    log = log or (lambda message: print(f"linesurf.distributed: {message}", file=sys.stderr,
                                        flush=True))
    work_dir = os.path.abspath(work_dir)
    command = [cli, "-j", str(step_threads), "reconstruct", input_path, "-o", output,
               "--work-dir", work_dir, *reconstruct_args]
    step = 0
    while True:
        step += 1
        log(f"step {step}: linesurf reconstruct --work-dir {work_dir}")
        # stderr (progress, warnings, errors) goes straight to ours; stdout lists pending units.
        done = subprocess.run(command, stdout=subprocess.PIPE, text=True)
        if done.returncode != EXIT_UNITS_PENDING:
            log(f"step {step}: exit {done.returncode}")
            return done.returncode
        units = done.stdout.split()
        log(f"step {step}: running {len(units)} work units")
        try:
            executor.run(work_dir, units, threads, log)
        except UnitError as error:
            log(f"error: {error}")
            return EXIT_FAILED
