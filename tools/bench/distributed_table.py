#!/usr/bin/env python3
"""linesurf.distributed against one process: runs `linesurf reconstruct` on synthetic cities,
then the same run through `python3 -m linesurf.distributed` on local process pools, Dask
LocalClusters and mpirun, and records per run the wall time, whether the mesh is the one
process's bytes, the units and the peak memory of the largest step process (the CLI calls, which
hold the scene) and of the largest worker (the units' own reports) into
tools/bench/tables/distributed.json, which make_tables.py renders into docs/user/distributed.md.

Usage: tools/bench/distributed_table.py --linesurf build/bin/linesurf --workdir /tmp/dt
           [--cities 100,1000] [--seed 4016] [--workers 1,2,4] [--machine TEXT]
Needs PYTHONPATH=build/python, python3-distributed, python3-mpi4py and openmpi-bin.
"""

import argparse
import hashlib
import json
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(Path(__file__).resolve().parent))
from table_file import write_table  # noqa: E402


def digest(path):
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


# Runs its arguments and prints the largest peak RSS (KiB) of its process tree: a fresh
# RUSAGE_CHILDREN per measured run.
PEAK_OF_TREE = ("import resource, subprocess, sys\n"
                "code = subprocess.run(sys.argv[1:]).returncode\n"
                "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss, file=sys.stderr)\n"
                "sys.exit(code)\n")


def timed(cmd, env=None):
    """Runs `cmd` (failing on a non-zero exit); returns its wall seconds and the largest peak RSS
    of any process of its tree, in MB."""
    start = time.monotonic()
    done = subprocess.run([sys.executable, "-c", PEAK_OF_TREE] + cmd, env=env,
                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                          check=False)
    if done.returncode != 0:
        raise SystemExit("distributed_table: %s exited %d:\n%s"
                         % (" ".join(cmd), done.returncode, done.stderr[-3000:]))
    return time.monotonic() - start, int(done.stderr.split()[-1]) / 1024


def worker_peak_mb(work_dir):
    peak = 0
    for name in os.listdir(os.path.join(work_dir, "units")):
        if name.endswith(".result.json"):
            with open(os.path.join(work_dir, "units", name)) as f:
                peak = max(peak, json.load(f).get("peak_rss_bytes", 0))
    return peak / 2**20


def runs(args):
    """(label, command prefix before the driver's own arguments, extra driver arguments)."""
    driver = [sys.executable, "-m", "linesurf.distributed"]
    for n in [int(w) for w in args.workers.split(",") if w]:
        yield "local processes", n, driver, ["--executor", "processes", "--pool-size", str(n)]
        yield "Dask LocalCluster", n, driver, ["--workers", str(n)]
    mpi = ["mpirun", "-n", "3", "--oversubscribe", "-x", "PYTHONPATH", sys.executable, "-m",
           "mpi4py.futures", "-m", "linesurf.distributed"]
    yield "mpirun (2 worker ranks)", 2, mpi, ["--executor", "mpi"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--linesurf", default=str(REPO / "build" / "bin" / "linesurf"))
    parser.add_argument("--workdir", required=True)
    parser.add_argument("--cities", default="100,1000")
    parser.add_argument("--seed", type=int, default=4016)
    parser.add_argument("--workers", default="1,2,4")
    parser.add_argument("--machine", default="")
    args = parser.parse_args()
    work = Path(args.workdir)
    work.mkdir(parents=True, exist_ok=True)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    rows = []
    for size in [int(s) for s in args.cities.split(",") if s]:
        scene = work / ("city-%d" % size)
        if not (scene / "lines.json").exists():
            subprocess.run([args.linesurf, "synth", "city", "--size", str(size), "--seed",
                            str(args.seed), "-o", str(scene)], check=True,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        lines = str(scene / "lines.json")
        one = str(work / ("city-%d-one.ply" % size))
        seconds, one_mb = timed([args.linesurf, "reconstruct", lines, "-o", one])
        reference = digest(one)
        rows.append({"scene": "city-%d" % size, "executor": "one process (`linesurf reconstruct`)",
                     "workers": None, "seconds": seconds, "same": "-", "units": None,
                     "step_mb": one_mb, "worker_mb": None})
        for label, workers, prefix, extra in runs(args):
            key = "city-%d-%s-%d" % (size, label.split()[0].lower(), workers)
            out, work_dir = str(work / (key + ".ply")), str(work / (key + ".work"))
            shutil.rmtree(work_dir, ignore_errors=True)
            if os.path.exists(out):
                os.remove(out)
            seconds, step_mb = timed(prefix + [lines, "-o", out, "--work-dir", work_dir,
                                               "--linesurf", args.linesurf] + extra, env)
            with open(os.path.join(work_dir, "manifest.json")) as f:
                units = len(json.load(f)["units"])
            rows.append({"scene": "city-%d" % size, "executor": label, "workers": workers,
                         "seconds": seconds, "same": "yes" if digest(out) == reference else "NO",
                         "units": units, "step_mb": step_mb,
                         "worker_mb": worker_peak_mb(work_dir)})
            print(rows[-1], file=sys.stderr)
    title = "linesurf.distributed against one process"
    command = ("PYTHONPATH=build/python python3 tools/bench/distributed_table.py "
               "--linesurf %s --workdir %s --cities %s --seed %d --workers %s"
               % (os.path.relpath(args.linesurf, REPO), args.workdir, args.cities,
               args.seed, args.workers))
    columns = [
        {"key": "scene", "header": "scene"},
        {"key": "executor", "header": "executor"},
        {"key": "workers", "header": "workers"},
        {"key": "seconds", "header": "wall s", "format": "{:.1f}"},
        {"key": "same", "header": "same bytes as one process"},
        {"key": "units", "header": "work units"},
        {"key": "step_mb", "header": "peak RSS MB, largest process",
         "format": "{:,.0f}"},
        {"key": "worker_mb", "header": "peak RSS MB, largest worker", "format": "{:,.0f}"},
    ]
    write_table("distributed", "docs/user/distributed.md", title, command, columns, rows,
                args.machine)
    return 0


if __name__ == "__main__":
    sys.exit(main())
