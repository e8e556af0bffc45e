"""Independent pieces of work (a calibration's runs and fits, identification trajectories, a
study's runs) on several cores, or on a Dask cluster: the one worker pool of jointplay.

Locally the pieces share compiled models, which cannot be pickled, so they run in a
:class:`concurrent.futures.ProcessPoolExecutor` whose processes are forked from this one (each
inherits the models and the job) and send back only numbers. On a cluster
(:func:`on_cluster`, the calibration's ``--scheduler``) each piece travels pickled, a
calibration's predictor reloading its model there
(:meth:`jointplay.calibration.predict.Predictor.__setstate__`). The results do not depend on
where the pieces run: each is the same computation. Where ``fork`` is unavailable, or one
worker is asked for, the pieces run here in turn.

Nothing waits without a bound. A worker that dies (killed, out of memory) breaks the pool
(``BrokenProcessPool``); one that sends nothing back for :data:`STALL_S` seconds is taken as
stuck and the pool killed. Either way one line on stderr says so and the pieces not yet back
run here in turn, which gives the same numbers. The workers ignore Ctrl-C from the moment
they are forked: this process alone stops them (SIGKILL: they hold nothing to clean up), so an
interrupt prints only the command's own line.
"""

from __future__ import annotations

import contextlib
import multiprocessing
import os
import sys
import time
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from typing import Any

from jointplay.common import interrupts

_JOB: Callable[[int], Any] | None = None
_CLIENT: list[Any] = []  # the Dask client of :func:`on_cluster`, while inside it
# Set while this process forks pool workers: the copies ignore Ctrl-C from their first
# instruction on (see _quiet_in_copy).
_FORKING = [False]
STALL_S = 600.0
"""The longest a map waits for the next piece from its workers (s). A piece (a calibration's
local fit over a window or chunk of short runs, a trajectory, a study's run) takes seconds
to a minute on a loaded 2-core machine; the bound leaves room for a machine many times
busier."""
CONNECT_TIMEOUT_S = 20.0
"""How long ``--scheduler`` waits for the cluster to answer."""


def _call(index: int) -> Any:
    assert _JOB is not None
    return _JOB(index)


def _quiet_in_copy() -> None:
    # Registered after jointplay.common.interrupts' own hook, so it runs after it in the copy
    # and overrides the handler that hook restores.
    if _FORKING[0]:
        interrupts.ignore_in_child()


if hasattr(os, "register_at_fork"):
    os.register_at_fork(after_in_child=_quiet_in_copy)


@contextlib.contextmanager
def on_cluster(address: str | None) -> Iterator[None]:
    """Within: the pieces run on the Dask cluster whose scheduler is at ``address`` (None:
    locally). An address that does not answer is a :class:`DescriptionError` naming
    ``--scheduler``."""
    if not address:
        yield
        return
    from distributed import Client

    from jointplay.common.errors import DescriptionError

    try:
        with interrupts.deferred():
            client = Client(address, timeout=CONNECT_TIMEOUT_S)
    except (OSError, TimeoutError) as err:
        raise DescriptionError("--scheduler", f"cannot reach the Dask scheduler at "
                               f"{address!r} ({err}); start it, or leave --scheduler out to "
                               "run on this machine's cores") from None
    _CLIENT.append(client)
    try:
        yield
    finally:
        _CLIENT.remove(client)
        client.close()


def parallel_map(job: Callable[[int], Any], count: int, workers: int, *,
                 label: str = "calibration",
                 on_result: Callable[[Any], None] | None = None) -> list[Any]:
    """``[job(0), ..., job(count - 1)]``, on up to ``workers`` forked processes (or on the
    cluster of :func:`on_cluster`). An exception ``job`` raises in a worker is raised here
    (the workers stopped). If a worker dies or the workers stall (nothing back for
    :data:`STALL_S` s), one line on stderr names the ``label``'s workers and the rest run
    here. ``on_result`` is called with each piece as it comes back (a progress bar)."""
    def here(index: int) -> Any:
        value = job(index)
        if on_result is not None:
            on_result(value)
        return value

    if _CLIENT and count > 1:
        values = _on_dask(_CLIENT[-1], job, count)
        if on_result is not None:
            for value in values:
                on_result(value)
        return values
    if workers <= 1 or count <= 1 or "fork" not in multiprocessing.get_all_start_methods():
        return [here(i) for i in range(count)]
    done = _forked(job, count, min(workers, count), label, on_result)
    return [done[i] if i in done else here(i) for i in range(count)]


def _forked(job: Callable[[int], Any], count: int, workers: int, label: str,
            on_result: Callable[[Any], None] | None) -> dict[int, Any]:
    """The pieces that came back from a pool of ``workers`` forked processes, by index; the
    pool is killed once every piece is back, a worker died, the workers stalled, a piece
    raised, or this process is interrupted."""
    global _JOB
    _JOB = job
    pool = ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context("fork"))
    done: dict[int, Any] = {}
    try:
        with interrupts.deferred():  # the first submission forks every worker
            _FORKING[0] = True
            try:
                pending: dict[Future[Any], int] = {pool.submit(_call, i): i
                                                   for i in range(count)}
            finally:
                _FORKING[0] = False
        problem = None
        while pending and problem is None:
            finished, _ = wait(pending, timeout=STALL_S, return_when=FIRST_COMPLETED)
            if not finished:
                problem = f"sent nothing back for {STALL_S:g} s"
            for future in finished:
                index = pending.pop(future)
                try:
                    done[index] = future.result()
                except BrokenProcessPool:
                    problem = "lost a worker process (killed, or out of memory)"
                    continue
                if on_result is not None:
                    on_result(done[index])
        if problem is not None:
            print(f"jointplay: the {label}'s worker processes {problem}; running the "
                  f"{count - len(done)} remaining pieces in this process", file=sys.stderr)
    finally:
        _stop(pool)
        _JOB = None
    return done


def _stop(pool: ProcessPoolExecutor) -> None:
    """Kill the pool's workers and let the pool go, waiting on nothing they might hold."""
    # The executor keeps its processes by pid; a worker killed mid-piece cannot leave a
    # lock held that this process waits on, since nothing here joins the pool's queues.
    processes = list((getattr(pool, "_processes", None) or {}).values())
    manager = getattr(pool, "_executor_manager_thread", None)
    for process in processes:
        with contextlib.suppress(OSError):
            process.kill()
    pool.shutdown(wait=False, cancel_futures=True)
    # The pool's own thread reaps the killed workers too; a join here racing it can find the
    # child already reaped but its exit not yet recorded (the process would still read as
    # running), so that thread is let finish first, within the same bound.
    deadline = time.monotonic() + 5.0
    if manager is not None:
        manager.join(max(0.0, deadline - time.monotonic()))
    for process in processes:  # reaped (a killed process exits at once)
        process.join(max(0.0, deadline - time.monotonic()))


def _on_dask(client: Any, job: Callable[[int], Any], count: int) -> list[Any]:
    """The pieces on the cluster (which reruns a piece whose worker died); a piece not back
    for :data:`STALL_S` s stops the run with one error line."""
    from distributed import TimeoutError as DaskTimeout
    from distributed import wait as dask_wait

    from jointplay.common.errors import SimulationError

    futures = client.map(job, list(range(count)), pure=False)
    try:
        dask_wait(futures, timeout=STALL_S)
        return list(client.gather(futures))
    except (DaskTimeout, TimeoutError):
        raise SimulationError(float("nan"), f"the Dask cluster sent no result for {STALL_S:g} "
                              "s; check its workers, or leave --scheduler out") from None
    finally:
        client.cancel(futures)


def chunks(count: int, parts: int) -> list[Sequence[int]]:
    """``range(count)`` cut into at most ``parts`` contiguous pieces of near-equal size."""
    parts = max(1, min(parts, count))
    bounds = [round(k * count / parts) for k in range(parts + 1)]
    return [range(bounds[k], bounds[k + 1]) for k in range(parts)]
