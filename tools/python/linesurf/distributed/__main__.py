"""python3 -m linesurf.distributed INPUT -o OUT [--workers N | --scheduler ADDRESS |
--executor sequential|processes|mpi] [--work-dir DIR] [--threads-per-worker T]
[--step-threads T] [--linesurf CLI]
[options of `linesurf reconstruct`]"""

import argparse
import os
import shutil
import sys

from .driver import run_distributed
from .executors import DaskExecutor, MpiExecutor, ProcessExecutor, SequentialExecutor


def _parser():
    p = argparse.ArgumentParser(
        prog="python3 -m linesurf.distributed",
        description="Reconstruct with the work units (per-block plane detection) run on local "
                    "processes, a Dask cluster or MPI ranks; every other argument goes to "
                    "`linesurf reconstruct` (docs/user/distributed.md).")
    p.add_argument("input", help="the scene, as `linesurf reconstruct` reads it")
    p.add_argument("-o", "--output", required=True, help="the mesh, as `linesurf reconstruct`")
    p.add_argument("--work-dir", help="the run's work directory, on a file system every worker "
                   "shares (default: OUTPUT.work); a rerun over it resumes")
    where = p.add_mutually_exclusive_group()
    where.add_argument("--workers", type=int,
                       help="start a Dask LocalCluster of N worker processes on 127.0.0.1")
    where.add_argument("--scheduler", help="join the Dask cluster of this scheduler address")
    where.add_argument("--executor", choices=["sequential", "processes", "mpi"],
                       help="sequential: this process; processes: a local pool of --pool-size "
                       "processes; mpi: the ranks of mpirun (under python3 -m mpi4py.futures)")
    p.add_argument("--pool-size", type=int, default=os.cpu_count() or 1,
                   help="--executor processes: the pool's processes (default: the cores)")
    p.add_argument("--threads-per-worker", type=int, default=1,
                   help="threads of each unit (oneTBB's pool is not limited by Dask's "
                   "OMP_NUM_THREADS; default 1)")
    p.add_argument("--step-threads", type=int, default=0,
                   help="threads of the steps (the `linesurf reconstruct --work-dir` calls, which "
                   "run every stage but the units; default 0: every core)")
    p.add_argument("--linesurf", default=os.environ.get("LINESURF_CLI") or shutil.which("linesurf"),
                   help="the linesurf executable (default: $LINESURF_CLI, then PATH)")
    return p


def _executor(args):
    if args.workers is not None or args.scheduler is not None:
        from distributed import Client, LocalCluster
        if args.scheduler is not None:
            return DaskExecutor(Client(args.scheduler)), None
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                               host="127.0.0.1", dashboard_address=None)
        return DaskExecutor(Client(cluster)), cluster
    if args.executor == "processes":
        return ProcessExecutor(args.pool_size), None
    if args.executor == "mpi":
        return MpiExecutor(), None
    return SequentialExecutor(), None


def main(argv=None):
    args, reconstruct_args = _parser().parse_known_args(argv)
    if not args.linesurf:
        print("linesurf.distributed: error: no linesurf executable (give --linesurf or put it "
              "on PATH)", file=sys.stderr)
        return 2
    if args.workers is not None and args.workers < 1:
        print("linesurf.distributed: error: --workers must be >= 1", file=sys.stderr)
        return 2
    executor, cluster = _executor(args)
    try:
        return run_distributed(args.linesurf, args.input, args.output,
                               args.work_dir or args.output + ".work", executor,
                               reconstruct_args, args.threads_per_worker,
                               step_threads=args.step_threads)
    finally:
        executor.close()
        if isinstance(executor, DaskExecutor):
            executor.client.close()
        if cluster is not None:
            cluster.close()


if __name__ == "__main__":
    sys.exit(main())
