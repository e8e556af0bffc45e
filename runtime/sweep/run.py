"""Running a sweep: the cases not yet finished, on a Dask cluster (given, at an address, or a
new local one) or one by one in this process; each case recorded as it completes, then the
table and the figures."""

from __future__ import annotations

import contextlib
import logging
import os
import sys
import time
import uuid
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from jointplay.common import interrupts, limits
from jointplay.sweep.axes import _error
from jointplay.sweep.case import run_case, worker_failure
from jointplay.sweep.plots import plot_sweep
from jointplay.sweep.records import (
    CASES_DIR,
    PLOTS_DIR,
    SERIES_DIR,
    TABLE_NAME,
    is_finished,
    read_row,
    record,
    write_manifest,
)
from jointplay.sweep.spec import Case, Sweep, SweepError, load_sweep
from jointplay.sweep.table import build_table

# Dask reruns a task whose worker died (up to distributed.scheduler.allowed-failures times);
# ``retries`` reruns a task that raised outside the simulation (a model that failed to load).
RETRIES = 2
CONNECT_TIMEOUT = "20s"


# A new local Dask cluster's cost before its first case is done (wall s, 2 cores): the
# start of the scheduler and two workers (4.3 s at load average 6.6, docs/sweeps.md) plus
# the workers' first import of the simulator (2.2 s at load 15; docs/results/figure-cost.md).
# At load 15 the start alone took 26 s: the estimate is a lightly loaded machine's, which
# favours the cluster.
CLUSTER_START_S = 6.5


def engine_choice(first_case_s: float, remaining: int, workers: int) -> tuple[bool, str]:
    """Whether the ``remaining`` cases go to a new local cluster of ``workers`` processes,
    and why, in one line, from the wall time of the first case run in this process.

    In this process they take about ``remaining * first_case_s``; a cluster saves at most
    the share ``1 - 1/workers`` of that, and costs :data:`CLUSTER_START_S` first. The cluster
    is chosen only when the saving exceeds its start-up.
    """
    here = remaining * first_case_s
    saving = here * (1.0 - 1.0 / workers) if workers > 1 else 0.0
    first = f"the first case took {first_case_s:.2g} s here"
    if saving > CLUSTER_START_S:
        return True, (f"the other {remaining} cases run on a local Dask cluster of {workers} "
                      f"workers: {first}, so about {here:.3g} s in this process, of which "
                      f"the cluster saves about {saving:.3g} s for about {CLUSTER_START_S:g} s "
                      "of start-up (--workers 0 keeps them here)")
    why = (f"a cluster of {workers} workers would save at most {saving:.3g} s of that for "
           f"about {CLUSTER_START_S:g} s of start-up" if workers > 1 else
           "this machine has one core for them")
    return False, (f"the other {remaining} cases run in this process: {first}, so about "
                   f"{here:.3g} s, and {why} (--workers N starts one)")


@dataclass(frozen=True)
class SweepResult:
    """How a run of a sweep went; ``table`` is the ``pyarrow.Table`` written to ``path``."""

    table: Any
    path: Path
    cases: int
    ran: int
    reused: int
    failed: int
    wall_time_s: float
    plots: list[Path]
    engine: str = ""  # where the cases ran, and why when it was chosen


def default_workers() -> int:
    """min(usable cores, 4): more processes than cores only adds contention."""
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        cores = os.cpu_count() or 1
    return max(1, min(cores, 4))


def _check_out(out: Path, flag: str) -> Path:
    if out.exists() and not out.is_dir():
        raise _error(flag, f"{out} exists and is not a folder", None)
    target = out
    while not target.exists():
        target = target.parent
    if not os.access(target, os.W_OK | os.X_OK):
        raise _error(flag, f"cannot write to {target}: permission denied", None)
    return out



@contextlib.contextmanager
def _dask_client(client: Any, scheduler: str | None, workers: int | None) -> Iterator[Any]:
    """The given client, or one to the cluster at ``scheduler``, or to a new local cluster
    (closed again on the way out)."""
    if client is not None:
        yield client
        return
    from distributed import Client

    with contextlib.ExitStack() as stack:
        if scheduler:
            try:
                client = Client(scheduler, timeout=CONNECT_TIMEOUT)
            except (OSError, TimeoutError) as err:
                raise SweepError(f"cannot reach the Dask scheduler at {scheduler!r}: {err}") \
                    from None
        else:
            # Workers stopped mid-task by an interrupt leave semaphores that the resource
            # tracker (a process that takes its warning options from ours) cleans up, with a
            # warning that is no concern of the user's.
            option = "ignore:resource_tracker:UserWarning"
            if option not in sys.warnoptions:
                sys.warnoptions.append(option)
            cluster = stack.enter_context(_local_cluster(workers or default_workers()))
            client = Client(cluster)
        stack.callback(client.close)
        yield client


@contextlib.contextmanager
def _local_cluster(workers: int) -> Iterator[Any]:
    """A local cluster whose worker processes ignore SIGINT.

    Ctrl-C at a terminal reaches the whole process group; this process alone must stop the
    sweep, in order (a worker interrupted on its own prints tracebacks and loses its case).
    Workers are forked from a fork server started with SIGINT ignored, which they inherit;
    this process ignores SIGINT only while that server starts, a few milliseconds.
    """
    import multiprocessing

    import dask
    from distributed import LocalCluster

    settings = {}
    if "forkserver" in multiprocessing.get_all_start_methods():
        from multiprocessing import forkserver

        with interrupts.ignoring():
            forkserver.ensure_running()
        settings["distributed.worker.multiprocessing-method"] = "forkserver"
    # Started whole even when Ctrl-C comes meanwhile (then closed, and the interrupt raised).
    # Worker logs only at CRITICAL: a worker that loses its scheduler when a sweep is
    # interrupted logs errors that are no concern of the user's; failed cases come back as
    # rows and errors.
    cluster = None
    try:
        with interrupts.deferred(), dask.config.set(settings):
            # No dashboard; the scheduler's HTTP server (health, metrics) starts anyway, on
            # 8787 unless told otherwise: a free port, so that a cluster already running
            # there (another sweep, a user's) costs no warning.
            cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                   dashboard_address=None, silence_logs=logging.CRITICAL,
                                   scheduler_kwargs={"dashboard_address": ":0"})
        yield cluster
    finally:
        if cluster is not None:
            cluster.close()


def _run_dask(client: Any, pending: Sequence[Case], out: Path, *, series: bool,
              hook: Callable[[Case], None] | None, progress: Any,
              verify: bool = False) -> None:
    """Submit every pending case; record each as it completes, in completion order."""
    from distributed import as_completed

    token = uuid.uuid4().hex[:8]
    by_key = {f"jointplay-case-{c.key}-{token}": c for c in pending}
    futures = client.map(run_case, list(pending), key=list(by_key), series=series, hook=hook,
                         verify=verify, retries=RETRIES, pure=False)
    try:
        for future in as_completed(futures):
            case = by_key.pop(future.key)
            try:
                outcome = future.result()
            except Exception as err:  # KilledWorker, or a task that kept raising
                interrupts.raise_if_interrupted()
                if _is_interrupt(err):  # the worker was interrupted: the case is not done
                    future.release()
                    continue
                outcome = worker_failure(case, err)
            except KeyboardInterrupt:
                if interrupts.interrupted():  # ours, not the worker's
                    raise
                future.release()
                continue
            future.release()
            record(out, outcome)
            progress.update(1)
    finally:
        if by_key:  # interrupted: nothing left running on the cluster
            client.cancel([f for f in futures if f.key in by_key])


def _is_interrupt(err: BaseException) -> bool:
    """Whether a task's error is an interrupt of the worker (Dask may rebuild its type)."""
    return isinstance(err, KeyboardInterrupt) or type(err).__name__ == "KeyboardInterrupt"


def check_options(client: Any, workers: int | None, scheduler: str | None) -> None:
    if workers is not None and (isinstance(workers, bool) or not isinstance(workers, int)
                                or not 0 <= workers <= limits.MAX_WORKERS):
        raise _error("--workers", f"must be an integer from 0 to {limits.MAX_WORKERS}, got "
                     f"{workers!r}", None)
    if scheduler and (client is not None or workers is not None):
        raise _error("--scheduler", "uses the workers of an existing cluster: give no "
                     "--workers (and no client) with it", None)
    if client is not None and workers is not None:
        raise _error("--workers", "a client brings its own workers; give one or the other",
                     None)


def run_sweep(sweep: Sweep | str | Path, out: str | Path, *, client: Any = None,
              workers: int | None = None, scheduler: str | None = None, series: bool = False,
              retry_failed: bool = False, plots: bool = True, quiet: bool = True,
              hook: Callable[[Case], None] | None = None, verify: bool = False
              ) -> SweepResult:
    """Run every case of ``sweep`` not already finished in ``out``; write the table and plots.

    Cases run on ``client`` (a ``distributed.Client``) if given, else on the cluster at
    ``scheduler``, else on a new local cluster of ``workers`` processes; ``workers=0`` runs
    them one by one in this process, without Dask. Given none of these, this process runs
    the first case and :func:`engine_choice` sends the rest to a local cluster of
    :func:`default_workers` processes only when that saves more than the cluster's
    start-up; ``SweepResult.engine`` says which and why. ``series`` also keeps each case's
    full time series (``out/series/<key>.h5``).
    Failed simulations are kept as ``failed`` rows; ``retry_failed`` runs them again.
    ``hook(case)`` runs before each case, where the case runs. ``verify`` checks every case
    against the same case at tolerances 10x tighter (about doubling its cost) and adds the
    accuracy columns (:data:`jointplay.sweep.metrics.ACCURACY_METRICS`); a case finished
    without them runs again.
    """
    from tqdm import tqdm

    from jointplay.common.extras import require
    from jointplay.common.files import OutputPlan, all_or_nothing, make_folder, sweep_stale
    from jointplay.sim import load_scene_model

    require("sweep", "run_sweep()")  # Dask runs the cases, pyarrow writes the table
    started = time.perf_counter()
    if not isinstance(sweep, Sweep):
        sweep = load_sweep(sweep)
    out = _check_out(Path(out), "--out")
    check_options(client, workers, scheduler)
    # Compile once here, so that local workers (and any sharing the cache) only load.
    load_scene_model(sweep.scene)
    load_scene_model(sweep.scene, ideal=True)
    pending = [c for c in sweep.cases
               if not is_finished(read_row(out, c.key), out, series=series,
                                   retry_failed=retry_failed, verify=verify)]
    reused = len(sweep.cases) - len(pending)
    # Neither --workers nor a cluster given: this process runs the first case, whose cost
    # decides where the rest go (engine_choice).
    choose = workers is None and client is None and not scheduler
    serial = (workers == 0 and client is None and not scheduler) or (choose
                                                                       and len(pending) <= 1)
    engine = _engine(client, scheduler, workers, serial)
    with contextlib.ExitStack() as stack:
        cluster = None
        if pending and not serial and not choose:  # before anything is written: it may
            cluster = stack.enter_context(_dask_client(client, scheduler, workers))  # fail
        (out / CASES_DIR).mkdir(parents=True, exist_ok=True)
        for folder in (out, out / CASES_DIR, out / SERIES_DIR, out / PLOTS_DIR):
            sweep_stale(folder)  # temporaries of a run that was killed
        if series:
            (out / SERIES_DIR).mkdir(exist_ok=True)
        write_manifest(sweep, out)
        progress = stack.enter_context(tqdm(total=len(sweep.cases), initial=reused,
                                            disable=quiet, unit="case", desc=sweep.name,
                                            dynamic_ncols=True))
        rest = pending
        if choose and not serial:
            first = time.perf_counter()
            record(out, run_case(pending[0], series=series, hook=hook, verify=verify))
            progress.update(1)
            use_cluster, engine = engine_choice(time.perf_counter() - first,
                                                len(pending) - 1, default_workers())
            if not quiet:
                progress.write(f"sweep {sweep.name}: {engine}")
            rest = pending[1:]
            if use_cluster:
                cluster = stack.enter_context(_dask_client(None, None, None))
        if cluster is not None:
            _run_dask(cluster, rest, out, series=series, hook=hook, progress=progress,
                      verify=verify)
        else:
            for case in rest:
                record(out, run_case(case, series=series, hook=hook, verify=verify))
                progress.update(1)
    # The table and the figures are one output: both appear, or (a full disk) neither.
    final = OutputPlan()
    final.file("--out", out / TABLE_NAME, "the table")
    final.folder("--out", out / PLOTS_DIR, "the figures", pattern="*.png")
    with all_or_nothing(final):
        if plots:
            make_folder(out / PLOTS_DIR)
        table = build_table(sweep, out)
        figures = plot_sweep(sweep, table, out / PLOTS_DIR) if plots else []
    failed = sum(1 for s in table.column("status").to_pylist() if s != "ok")
    return SweepResult(table=table, path=out / TABLE_NAME, cases=len(sweep.cases),
                       ran=len(pending), reused=reused, failed=failed,
                       wall_time_s=time.perf_counter() - started, plots=figures,
                       engine=engine)


def _engine(client: Any, scheduler: str | None, workers: int | None, serial: bool) -> str:
    """Where the cases run when that is given (or there is at most one case to run)."""
    if client is not None:
        return "the cases run on the given Dask client's cluster"
    if scheduler:
        return f"the cases run on the Dask cluster at {scheduler}"
    if serial:
        return ("the cases run in this process" + (" (--workers 0)" if workers == 0 else
                                                   ": at most one case to run"))
    return f"the cases run on a local Dask cluster of {workers} workers (--workers)"
