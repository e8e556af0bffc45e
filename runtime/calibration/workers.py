"""Independent pieces of a calibration (the grid's runs, the tracks' fits over a window, the
lines' runs) on several cores.

The pieces share the compiled model, which cannot be pickled, so they run in processes
forked from this one (each inherits the model and the job) and send back only numbers. The
results do not depend on the number of workers: each piece is the same computation
wherever it runs. Where ``fork`` is unavailable, or one worker is asked for, the pieces run
here in turn.

A forked pool can hang (a child forked while another thread of this process held a lock it
then needs). Nothing waits on it without a bound: when no piece has come back for
:data:`STALL_S` seconds the pool is killed, one line on stderr says so, and the pieces not
yet back run here in turn, which gives the same numbers.
"""

from __future__ import annotations

import multiprocessing
import sys
from collections.abc import Callable, Sequence
from typing import Any

from jointplay.common import interrupts

_JOB: Callable[[int], Any] | None = None
# The longest a calibration waits for the next piece from its worker processes (s). A piece
# is one local fit over a window, or a chunk of short runs: seconds to a minute on a loaded
# 2-core machine; the bound leaves room for a machine many times busier.
STALL_S = 600.0


def _call(index: int) -> Any:
    assert _JOB is not None
    return _JOB(index)


def parallel_map(job: Callable[[int], Any], count: int, workers: int) -> list[Any]:
    """``[job(0), ..., job(count - 1)]``, on up to ``workers`` forked processes. ``job``
    must catch its own failures and return them as values. If the workers stall (nothing
    back for :data:`STALL_S` s), the rest run here."""
    global _JOB
    if workers <= 1 or count <= 1 or "fork" not in multiprocessing.get_all_start_methods():
        return [job(i) for i in range(count)]
    _JOB = job
    done: list[Any] = []
    try:
        with interrupts.started(
                lambda: multiprocessing.get_context("fork").Pool(min(workers, count))) as pool:
            pieces = pool.imap(_call, range(count), chunksize=1)
            try:
                for _ in range(count):
                    done.append(pieces.next(timeout=STALL_S))
            except multiprocessing.TimeoutError:
                pool.terminate()
                print(f"jointplay: calibration workers sent nothing for {STALL_S:g} s; "
                      f"running the {count - len(done)} remaining pieces in this process",
                      file=sys.stderr)
    finally:
        _JOB = None
    return done + [job(i) for i in range(len(done), count)]


def chunks(count: int, parts: int) -> list[Sequence[int]]:
    """``range(count)`` cut into at most ``parts`` contiguous pieces of near-equal size."""
    parts = max(1, min(parts, count))
    bounds = [round(k * count / parts) for k in range(parts + 1)]
    return [range(bounds[k], bounds[k + 1]) for k in range(parts)]
