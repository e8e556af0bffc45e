"""A second process that draws a command's figures while the command goes on with its own work.

``jointplay simulate --plot`` spends most of its time in matplotlib: importing it and drawing
the figures. :class:`FigureProcess` starts a fresh interpreter (a plain subprocess, never a
fork) as soon as the command knows it will draw; that process imports matplotlib and loads
its fonts while the command simulates. :meth:`FigureProcess.submit` hands it the figure jobs
(pickled: module-level functions and their arguments) and returns at once, so the command
writes its results file meanwhile; :meth:`Pending.collect` waits for the PNG bytes, at most
:data:`TIMEOUT_S`, and the command writes every file itself (so an output transaction of
:func:`jointplay.common.files.all_or_nothing` sees them all).

The figures always get drawn: if the process cannot start, fails, sends something unreadable,
runs past the timeout or stays stopped (SIGSTOP) for :data:`STOPPED_S`, it is killed, one line
on stderr says why, and the jobs run in this process instead. Nothing waits without a bound.

The process imports only the modules the figures need, not the whole package
(``jointplay/__init__`` loads the simulator, CasADi and h5py: a second more before it could
draw): the bootstrap below registers the package by its folders without running its
``__init__``.
"""

from __future__ import annotations

import atexit
import contextlib
import gc
import importlib
import os
import pickle
import subprocess
import sys
import threading
import time
from collections.abc import Sequence
from pathlib import Path

from jointplay.common import figures, interrupts
from jointplay.common.files import atomic_write_bytes

# The longest a command waits for the figure process once it has the jobs (s); then the
# figures are drawn in the command's own process. The paper scene's eight figures take 1-3 s
# there; the bound leaves room for a machine many times busier.
TIMEOUT_S = 120.0
# The longest the figure process may stay stopped (SIGSTOP, a debugger, Ctrl-Z sent to it
# alone) while the command waits for it (s): then it is killed, one line says so, and the
# figures are drawn here, rather than waiting out TIMEOUT_S without a word.
STOPPED_S = 5.0
# How often the wait looks at the process's state (s).
_POLL_S = 0.25
# Loaded by the figure process while it waits for its jobs.
_PRELOAD = ("jointplay.results.plots", "jointplay.results.derived", "jointplay.results.contacts")
# False: never start a figure process; every figure is drawn in the calling process. The
# environment variable JOINTPLAY_FIGURE_PROCESS=0 does the same for a command (to compare).
ENABLED = True

# Run by ``python -c``: the package is registered by its folders (argv[1], os.pathsep
# separated) without running its __init__, then the worker serves.
_BOOTSTRAP = (
    "import os, sys, types; "
    "package = types.ModuleType('jointplay'); "
    "package.__path__ = sys.argv[1].split(os.pathsep); "
    "sys.modules['jointplay'] = package; "
    "from jointplay.common.figure_process import serve; "
    "sys.exit(serve())"
)


# The process started by start_early, until the command claims it.
_early: FigureProcess | None = None


def start_early() -> None:
    """In the ``jointplay`` program, when its command line asks for ``simulate ... --plot``:
    start the figure process now, before the packages import. ``import jointplay`` calls
    this first thing (as it does the interrupt guard), so that the figure process imports
    matplotlib while this one imports the simulator (about a second each), not after it. A
    process the command does not claim is killed when this one exits; if this one dies
    outright, the figure process reads the end of its input and ends."""
    global _early
    if _early is not None or not interrupts.is_program() or not _asks_for_figures(sys.argv[1:]):
        return
    if wanted():
        _early = FigureProcess()
        atexit.register(_discard_early)


def _asks_for_figures(argv: list[str]) -> bool:
    """Whether the command line reads as ``simulate`` with ``--plot`` (not asking for help).
    A guess from the words alone: a wrong one costs a process started in vain, or started
    later by the command itself."""
    words = [w for w in argv if not w.startswith("-")]
    return (bool(words) and words[0] == "simulate"
            and any(w == "--plot" or w.startswith("--plot=") for w in argv)
            and not any(w in ("-h", "--help") for w in argv))


def _discard_early() -> None:
    global _early
    process, _early = _early, None
    if process is not None:
        process.close()


def claim() -> FigureProcess:
    """The figure process started early for this command, else a new one."""
    global _early
    process, _early = _early, None
    return process if process is not None else FigureProcess()


def wanted() -> bool:
    """Whether a figure process can shorten the command: enabled, and a second CPU to run
    on (on one CPU it would only add its start-up)."""
    return (ENABLED and os.environ.get("JOINTPLAY_FIGURE_PROCESS", "1") != "0"
            and _cpus() >= 2)


class FigureProcess:
    """A started figure process; use as a context manager, which kills it on leaving (an
    error, an interrupt, or figures that were never submitted)."""

    def __init__(self) -> None:
        import jointplay

        self._proc: subprocess.Popen[bytes] | None = None
        self.failure = ""
        try:
            self._proc = subprocess.Popen(
                [sys.executable, "-c", _BOOTSTRAP, os.pathsep.join(jointplay.__path__)],
                stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        except OSError as err:
            self.failure = f"it could not start ({err})"

    def __enter__(self) -> FigureProcess:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def close(self) -> None:
        """Kill the process if it still runs, and reap it."""
        proc, self._proc = self._proc, None
        if proc is not None and proc.poll() is None:
            proc.kill()
        if proc is not None:
            proc.wait()
            for pipe in (proc.stdin, proc.stdout, proc.stderr):
                if pipe is not None:
                    pipe.close()

    def submit(self, jobs: Sequence[figures.FigureJob]) -> Pending:
        """Hand ``jobs`` (each draws and saves one figure) to the process; returns at once."""
        return Pending(self, list(jobs))

    def _exchange(self, payload: bytes, timeout: float) -> tuple[bytes, bytes, int]:
        """Send ``payload``, close its input, and read all it writes: (stdout, stderr, exit
        status). Raises subprocess.TimeoutExpired (the process is then killed)."""
        proc = self._proc
        assert proc is not None
        try:
            out, err = proc.communicate(payload, timeout=timeout)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.communicate()
            raise
        return out, err, proc.returncode


class Pending:
    """Figures being drawn by a :class:`FigureProcess`."""

    def __init__(self, process: FigureProcess, jobs: list[figures.FigureJob]) -> None:
        self._process = process
        self._jobs = jobs
        self._outcome: tuple[bytes, bytes, int] | str = process.failure
        self._thread: threading.Thread | None = None
        self._stopped = ""
        if process._proc is None:
            return
        try:
            payload = pickle.dumps(jobs, protocol=pickle.HIGHEST_PROTOCOL)
        except Exception as err:  # a job that cannot travel: drawn here
            self._outcome = f"its jobs could not be sent ({type(err).__name__}: {err})"
            return
        # The exchange runs beside the caller, which goes on with its own work; the thread
        # only writes and reads the pipes.
        self._thread = threading.Thread(target=self._run, args=(payload,),
                                        name="jointplay-figures", daemon=True)
        self._thread.start()

    def _run(self, payload: bytes) -> None:
        try:
            self._outcome = self._process._exchange(payload, TIMEOUT_S)
        except subprocess.TimeoutExpired:
            self._outcome = f"it did not finish within {TIMEOUT_S:g} s"
        except OSError as err:
            self._outcome = f"it could not be reached ({err})"

    def collect(self) -> list[Path]:
        """Wait for the figures, write every file here, and return the paths in job order;
        on any failure of the process, draw the figures in this process instead."""
        if self._thread is not None:
            self._wait(self._thread)
        self._process.close()
        drawn = self._stopped or self._decoded()
        if isinstance(drawn, str):
            print(f"jointplay: the figure process failed: {drawn}; drawing the figures here",
                  file=sys.stderr)
            return figures.draw_all(self._jobs)
        paths = []
        for path, data in drawn:
            atomic_write_bytes(path, data)
            paths.append(path)
        return paths

    def _wait(self, thread: threading.Thread) -> None:
        """Wait for the exchange; a process stopped for STOPPED_S is killed (which ends the
        exchange) and the reason kept."""
        proc = self._process._proc
        stopped_since: float | None = None
        while thread.is_alive():
            thread.join(_POLL_S)
            if not thread.is_alive() or proc is None:
                continue
            if not _is_stopped(proc.pid):
                stopped_since = None
                continue
            now = time.monotonic()
            stopped_since = now if stopped_since is None else stopped_since
            if now - stopped_since >= STOPPED_S:
                self._stopped = f"it was stopped (SIGSTOP) for {STOPPED_S:g} s"
                with contextlib.suppress(OSError):
                    proc.kill()  # SIGKILL ends a stopped process too
                thread.join()

    def _decoded(self) -> list[tuple[Path, bytes]] | str:
        """The (path, PNG bytes) the process sent, or why there are none."""
        outcome = self._outcome
        if isinstance(outcome, str):
            return outcome
        out, err, status = outcome
        if status != 0:
            last = err.decode(errors="replace").strip().splitlines()[-1:] or ["no message"]
            return f"exit status {status}: {last[0][:300]}"
        try:
            drawn = pickle.loads(out)
        except Exception as exc:
            return f"its answer could not be read ({type(exc).__name__})"
        if not (isinstance(drawn, list) and all(
                isinstance(p, Path) and isinstance(d, bytes) for p, d in drawn)):
            return "its answer was not a list of figures"
        return drawn


def serve() -> int:
    """The figure process: load matplotlib and its fonts, read the pickled jobs from stdin,
    draw them, write ``[(path, PNG bytes), ...]`` pickled to stdout. Ctrl-C (which reaches
    the command's whole process group) ends it at once and quietly: the command stops too,
    and says so."""
    import signal

    signal.signal(signal.SIGINT, _leave)
    figures.warm_up()
    # The modules of the default figures, loaded before the jobs arrive (the jobs' own
    # imports would otherwise come after).
    for name in _PRELOAD:
        importlib.import_module(name)
    # No cyclic garbage collection: a figure is a web of cycles, and a full collection over
    # all of matplotlib's objects took 0.15 s; this process ends when the figures are sent.
    gc.disable()
    payload = sys.stdin.buffer.read()
    if not payload:  # the command ended before it had figures to draw
        return 0
    jobs = pickle.loads(payload)
    drawn = drawn_on_two_cpus(jobs) if _cpus() >= 2 else figures.capture(jobs)
    sys.stdout.buffer.write(pickle.dumps(drawn, protocol=pickle.HIGHEST_PROTOCOL))
    sys.stdout.buffer.flush()
    # Done: leave without the interpreter's teardown of matplotlib's modules (0.1-0.2 s that
    # the command would wait for, since it reads until this process closes its output).
    os._exit(0)


def drawn_on_two_cpus(jobs: Sequence[figures.FigureJob]) -> list[tuple[Path, bytes]]:
    """``figures.capture(jobs)``, the jobs shared between this process and a copy of it
    forked now (matplotlib and its fonts already loaded: the copy starts drawing at once),
    in job order. Each process takes the next job not yet taken as it comes free (the jobs
    come costliest first, so the two finish close together whatever the figures cost). Where
    the copy fails, this process draws what the copy did not send: the figures are the same
    either way."""
    if len(jobs) < 2 or len(jobs) > 255:
        return figures.capture(jobs)
    # The queue: one byte per job index in a pipe, read one byte at a time by both processes
    # (a read of one byte from a pipe is atomic: no job is taken twice).
    queue_read, queue_write = os.pipe()
    os.write(queue_write, bytes(range(len(jobs))))
    os.close(queue_write)
    answer_read, answer_write = os.pipe()
    pid = interrupts.fork()
    if pid == 0:  # the copy: draw what it takes, send it, and leave without any teardown
        status = 1
        try:
            os.close(answer_read)
            data = pickle.dumps(_take_and_draw(jobs, queue_read),
                                protocol=pickle.HIGHEST_PROTOCOL)
            with os.fdopen(answer_write, "wb") as pipe:
                pipe.write(data)
            status = 0
        finally:
            os._exit(status)
    os.close(answer_write)
    drawn = _take_and_draw(jobs, queue_read)
    os.close(queue_read)
    with os.fdopen(answer_read, "rb") as pipe:
        data = pipe.read()
    _, status = os.waitpid(pid, 0)
    try:
        sent = pickle.loads(data) if status == 0 else {}
    except Exception:
        sent = {}
    if isinstance(sent, dict):
        drawn.update((i, figure) for i, figure in sent.items() if i not in drawn)
    for i in range(len(jobs)):  # what the copy took and did not send
        if i not in drawn:
            drawn[i] = figures.capture([jobs[i]])
    return [figure for i in range(len(jobs)) for figure in drawn[i]]


def _take_and_draw(jobs: Sequence[figures.FigureJob], queue: int
                   ) -> dict[int, list[tuple[Path, bytes]]]:
    """Draw the jobs whose indices this process reads from ``queue`` until it is empty."""
    drawn = {}
    while index := os.read(queue, 1):
        drawn[index[0]] = figures.capture([jobs[index[0]]])
    return drawn


def _cpus() -> int:
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def _is_stopped(pid: int) -> bool:
    """Whether the process is stopped (state T or t in /proc; False where there is no
    /proc: there the wait is bounded by TIMEOUT_S alone)."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as fh:
            state = fh.read().rsplit(b")", 1)[1].split()[0]
    except (OSError, IndexError):
        return False
    return state in (b"T", b"t")


def _leave(signum: int, frame: object) -> None:
    os._exit(128 + signum)


def draw(jobs: Sequence[figures.FigureJob], process: FigureProcess | None) -> list[Path]:
    """Draw ``jobs`` in ``process`` when given, else here; the paths in job order."""
    if process is None:
        return figures.draw_all(jobs)
    return process.submit(jobs).collect()


__all__ = ["ENABLED", "STOPPED_S", "TIMEOUT_S", "FigureProcess", "Pending", "claim", "draw",
           "serve", "start_early", "wanted"]


start_early()  # on the first import, which `import jointplay` makes right after the guard
