"""Independent pieces of a calibration (the grid's runs, the tracks' fits over a window, the
lines' runs) on several cores.

The pieces share the compiled model, which cannot be pickled, so they run in processes
forked from this one (each inherits the model and the job) and send back only numbers. The
results do not depend on the number of workers: each piece is the same computation
wherever it runs. Where ``fork`` is unavailable, or one worker is asked for, the pieces run
here in turn.
"""

from __future__ import annotations

import multiprocessing
from collections.abc import Callable, Sequence
from typing import Any

_JOB: Callable[[int], Any] | None = None


def _call(index: int) -> Any:
    assert _JOB is not None
    return _JOB(index)


def parallel_map(job: Callable[[int], Any], count: int, workers: int) -> list[Any]:
    """``[job(0), ..., job(count - 1)]``, on up to ``workers`` forked processes. ``job``
    must catch its own failures and return them as values."""
    global _JOB
    if workers <= 1 or count <= 1 or "fork" not in multiprocessing.get_all_start_methods():
        return [job(i) for i in range(count)]
    _JOB = job
    try:
        with multiprocessing.get_context("fork").Pool(min(workers, count)) as pool:
            return pool.map(_call, range(count), chunksize=1)
    finally:
        _JOB = None


def chunks(count: int, parts: int) -> list[Sequence[int]]:
    """``range(count)`` cut into at most ``parts`` contiguous pieces of near-equal size."""
    parts = max(1, min(parts, count))
    bounds = [round(k * count / parts) for k in range(parts + 1)]
    return [range(bounds[k], bounds[k + 1]) for k in range(parts)]
