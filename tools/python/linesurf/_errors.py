"""The linesurf.Error hierarchy: one class per facade ErrorCode (linesurf/error.h)."""


class Error(Exception):
    """A linesurf failure: ``code`` (e.g. "invalid_input"), ``stage`` and ``message``.

    str(error) is "stage: message", as Error::ToString in C++.
    """

    def __init__(self, message, code="internal", stage=""):
        super().__init__(f"{stage}: {message}" if stage else message)
        self.code = code
        self.stage = stage
        self.message = message


class InvalidOptions(Error, ValueError):
    """An option is out of its documented range (the message names the field)."""


class InvalidInput(Error, ValueError):
    """The input is malformed or holds nothing usable (the message names the index or line)."""


class Degenerate(Error):
    """The input is valid but geometrically degenerate for the task."""


class Cancelled(Error):
    """The run was cancelled (the progress callback returned True)."""


class SolverFailed(Error):
    """The optimisation did not reach an optimum (time or iteration limit)."""


class ResourceExhausted(Error, MemoryError):
    """Out of memory or over a size limit."""


class Internal(Error):
    """A broken invariant: a bug in linesurf."""


_BY_CODE = {
    "invalid_options": InvalidOptions,
    "invalid_input": InvalidInput,
    "degenerate": Degenerate,
    "cancelled": Cancelled,
    "solver_failed": SolverFailed,
    "resource_exhausted": ResourceExhausted,
    "internal": Internal,
}


def from_code(code, stage, message):
    """The exception for a facade error (called by the compiled module)."""
    return _BY_CODE.get(code, Error)(message, code=code, stage=stage)
