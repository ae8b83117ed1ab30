"""The executors of linesurf.distributed: one interface, `run(work_dir, units, threads, log)`,
over this process, a local process pool, a Dask cluster and MPI ranks (mpi4py.futures).

Each runs every unit to a result file in the work directory: a unit whose worker died (killed,
out of memory) is submitted again, up to `attempts` times; a unit that fails on its own input
gets a failed result from the unit itself (status "failed"), which is final. UnitError is raised
when a unit cannot be run at all (its worker died `attempts` times, or the work directory is not
the run's).
"""

import concurrent.futures


class UnitError(RuntimeError):
    """A work unit that could not be run: its id and why."""

    def __init__(self, unit, reason):
        super().__init__(f"work unit {unit}: {reason}")
        self.unit = unit
        self.reason = reason


def run_unit(work_dir, unit, threads):
    """Runs one work unit in this process (the GIL is released while it runs); returns its
    result's summary {id, status, reason, seconds}. Importable by workers: it takes and returns
    plain values."""
    from linesurf import _linesurf
    return _linesurf.run_work_unit(work_dir, unit, threads)


def _is_unit_error(error):
    """A linesurf.Error from the unit itself (no manifest, no such unit): not a worker's death,
    so running it again would not help."""
    from linesurf import Error
    return isinstance(error, Error)


class _FuturesExecutor:
    """Runs units on a concurrent.futures-style pool; subclasses make and remake the pool."""

    attempts = 3

    def _pool(self):
        raise NotImplementedError

    def _reset(self):
        """Called when the pool broke (a worker died); the next _pool() must work again."""

    def _completed(self, futures):
        """The futures in the order they finish."""
        return concurrent.futures.as_completed(futures)

    def _check_retry(self, unit, error, tries, log):
        """Raises UnitError when `unit`, whose worker failed with `error`, is not run again."""
        if _is_unit_error(error):
            raise UnitError(unit, str(error)) from error
        if tries >= self.attempts:
            raise UnitError(unit, f"its worker failed {tries} times, last: "
                                  f"{type(error).__name__}: {error}") from error
        log(f"work unit {unit}: its worker failed ({type(error).__name__}), running it again")

    def run(self, work_dir, units, threads, log):
        tries = {unit: 0 for unit in units}
        waiting = list(units)
        results = {}
        while waiting:
            pool = self._pool()
            futures = {}
            again = []
            for unit in waiting:
                tries[unit] += 1
                try:
                    futures[pool.submit(run_unit, work_dir, unit, threads)] = unit
                except Exception as error:  # a pool broken by a dead worker refuses work
                    self._check_retry(unit, error, tries[unit], log)
                    again.append(unit)
            for future in self._completed(futures):
                unit = futures[future]
                try:
                    info = future.result()
                except Exception as error:  # the worker died, or the unit could not start
                    self._check_retry(unit, error, tries[unit], log)
                    again.append(unit)
                    continue
                results[unit] = info
                log(f"work unit {unit} {info['status']} in {info['seconds']:.2f} s "
                    f"({len(results)}/{len(units)})"
                    + (f": {info['reason']}" if info["status"] == "failed" else ""))
            waiting = again
            if waiting:
                self._reset()
        return results

    def close(self):
        """Releases the pool."""


class SequentialExecutor(_FuturesExecutor):
    """Every unit in this process, one after the other."""

    attempts = 1

    class _Here:
        def submit(self, fn, *args):
            future = concurrent.futures.Future()
            try:
                future.set_result(fn(*args))
            except Exception as error:
                future.set_exception(error)
            return future

    def _pool(self):
        return self._Here()


class ProcessExecutor(_FuturesExecutor):
    """A pool of `workers` local processes (concurrent.futures); a pool broken by a dead worker
    is replaced."""

    def __init__(self, workers):
        self.workers = workers
        self._executor = None

    def _pool(self):
        if self._executor is None:
            self._executor = concurrent.futures.ProcessPoolExecutor(max_workers=self.workers)
        return self._executor

    def _reset(self):
        if self._executor is not None:
            self._executor.shutdown(wait=True, cancel_futures=True)
        self._executor = None

    def close(self):
        self._reset()


class DaskExecutor(_FuturesExecutor):
    """A dask.distributed cluster: `client` a distributed.Client. Dask itself runs again a task
    whose worker died (up to its allowed-failures setting); this executor submits again what
    still failed."""

    def __init__(self, client):
        self.client = client
        self._attempt = 0

    def _pool(self):
        self._attempt += 1
        client, attempt = self.client, self._attempt

        class _Submit:
            def submit(self, fn, work_dir, unit, threads):
                # A key of its own per attempt: a resubmitted unit is a new task.
                return client.submit(fn, work_dir, unit, threads, key=f"{unit}-{attempt}",
                                     pure=False)

        return _Submit()

    def _completed(self, futures):
        from distributed import as_completed
        return as_completed(list(futures))


class MpiExecutor(_FuturesExecutor):
    """MPI ranks through mpi4py.futures (run the driver under
    `mpirun -n N python3 -m mpi4py.futures -m linesurf.distributed ...`: rank 0 drives, the
    others run units)."""

    attempts = 1  # a dead rank ends the MPI job: nothing to submit to again

    def __init__(self):
        from mpi4py.futures import MPIPoolExecutor
        self._executor = MPIPoolExecutor()

    def _pool(self):
        return self._executor

    def close(self):
        self._executor.shutdown(wait=True)
