"""linesurf.distributed: a reconstruction whose work units run on other processes or machines.

    python3 -m linesurf.distributed INPUT -o OUT [--workers N | --scheduler ADDRESS |
        --executor sequential|processes|mpi] [--work-dir DIR] [reconstruct options...]

The run goes through `linesurf reconstruct --work-dir DIR` (the C++ CLI): each call either
finishes the run or stops and names the work units it needs (per-block plane detection); the
driver runs them on an executor (run_work_unit, in this process, a process pool, a Dask cluster
or MPI ranks) and calls again. Data moves as files in the work directory, never as pickled C++
objects, so the output is the same bytes for any executor, worker count and completion order,
and a rerun over the same directory skips what is done. docs/user/distributed.md has the guide.
"""

from .driver import EXIT_FAILED, EXIT_OK, EXIT_PARTIAL, run_distributed
from .executors import (DaskExecutor, MpiExecutor, ProcessExecutor, SequentialExecutor,
                        UnitError, run_unit)

__all__ = ["DaskExecutor", "EXIT_FAILED", "EXIT_OK", "EXIT_PARTIAL", "MpiExecutor",
           "ProcessExecutor", "SequentialExecutor", "UnitError", "run_distributed", "run_unit"]
