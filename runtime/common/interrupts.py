"""Ctrl-C means interrupt: remember that one arrived, whoever catches what it raises.

Compiled code (CasADi's integrators, h5py) may turn the ``KeyboardInterrupt`` raised by
Python's handler into an error of its own, or drop it. The command line installs
:func:`installed`, whose handler records the interrupt before raising; any layer that catches
an error can then ask :func:`interrupted` and re-raise it as the interrupt it was
(:func:`raise_if_interrupted`). Library callers that never enter it see Python's default.

Ctrl-C is honoured once: after the first, further presses are only recorded, so that the
cleanup it started (temporary files removed, workers stopped) runs to its end and the command
still ends with one line, exit 130. Before the command line takes over, while the packages
import, :func:`guard_imports` (run first thing by ``import jointplay`` in the ``jointplay``
program only) turns Ctrl-C into that same line and exit status at once: nothing has been
written yet.

A process started with SIGINT ignored (a shell script's background job, ``nohup``) keeps
ignoring it from start to end, as Python itself does: these handlers are installed only where
SIGINT is not ignored. SIGTERM still stops it in order.
"""

from __future__ import annotations

import contextlib
import os
import signal
import sys
import threading
from collections.abc import Callable, Iterator
from types import FrameType
from typing import Any, NoReturn, TypeVar

EXIT_INTERRUPTED = 130  # 128 + SIGINT, what a shell reports for Ctrl-C
EXIT_TERMINATED = 143  # 128 + SIGTERM

_state: dict[str, int] = {"interrupted": 0, "status": EXIT_INTERRUPTED, "installed": 0}
# The Ctrl-C handlers that deferred() and fork() have put aside, outermost first.
_replaced: list[Any] = []
T = TypeVar("T")


def _on_sigint(signum: int, frame: FrameType | None) -> None:
    interrupt()


def interrupt() -> NoReturn:
    """Record an interrupt and raise KeyboardInterrupt (also for compiled loops that saw the
    signal themselves). Within :func:`installed`, later Ctrl-C presses are only recorded."""
    if _state["installed"]:  # a library caller's process remembers nothing
        _state["interrupted"] = 1
        if threading.current_thread() is threading.main_thread() \
                and signal.getsignal(signal.SIGINT) is _on_sigint:
            signal.signal(signal.SIGINT, _record_only)
    raise KeyboardInterrupt


def _on_sigterm(signum: int, frame: FrameType | None) -> None:
    # Unwinding (not dying on the spot) lets every atomic write remove its temporary file.
    _state["interrupted"] = 1
    _state["status"] = EXIT_TERMINATED
    raise SystemExit(EXIT_TERMINATED)


@contextlib.contextmanager
def installed() -> Iterator[None]:
    """Within: record SIGINT (then raise KeyboardInterrupt) and turn SIGTERM into an orderly
    exit. The previous handlers are restored on the way out."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    _state["interrupted"] = 0
    _state["status"] = EXIT_INTERRUPTED
    ignored = signal.getsignal(signal.SIGINT) is signal.SIG_IGN  # inherited: kept
    previous = (signal.SIG_IGN if ignored else signal.signal(signal.SIGINT, _on_sigint),
                signal.signal(signal.SIGTERM, _on_sigterm))
    _state["installed"] = 1
    try:
        yield
    finally:
        # First of all, a press from here on is only recorded: were the handler still ours
        # once "installed" is dropped, a press as the command finishes would raise a
        # KeyboardInterrupt out of the command line, a traceback.
        if not ignored:
            signal.signal(signal.SIGINT, _record_only)
        unreported = sys.exc_info()[0] is KeyboardInterrupt  # raised past the command
        _state["installed"] = 0
        if _state["interrupted"] and _is_program():
            if unreported:
                os.write(2, b"jointplay: interrupted\n")
            # The command is over and cleaned up: a press while the interpreter shuts down
            # must not end it otherwise (Python resets its own handlers to the default then,
            # which would report death by SIGINT; "ignore" it keeps). Even so, a sweep's
            # stopped worker processes were seen to end it by SIGINT during the libraries'
            # exit hooks (about 1 run in 10): with nothing left to clean up, leave at once
            # with the status the command reports.
            signal.signal(signal.SIGINT, signal.SIG_IGN)
            signal.signal(signal.SIGTERM, previous[1])
            with contextlib.suppress(Exception):
                sys.stdout.flush()
                sys.stderr.flush()
            os._exit(_state["status"])
        elif _is_program():
            # The command has finished: a press from now on (the interpreter shutting down,
            # which resets Python-level handlers to the default and so would die by SIGINT)
            # is ignored, and the command's own status stands.
            signal.signal(signal.SIGINT, signal.SIG_IGN)
        else:
            signal.signal(signal.SIGINT, previous[0])
            # A program that ran a command (and heard it end with 130) goes on: the
            # interrupt is reported, and a later call must not raise it again.
            _state["interrupted"] = 0
        signal.signal(signal.SIGTERM, previous[1])


def interrupted() -> bool:
    """True once SIGINT (or SIGTERM) arrived since :func:`installed` was entered."""
    return bool(_state["interrupted"])


def exit_status() -> int:
    """130 after Ctrl-C (SIGINT), 143 after SIGTERM."""
    return int(_state["status"])


def raise_if_interrupted() -> None:
    """Raise KeyboardInterrupt if an interrupt arrived (call where an error is caught)."""
    if _state["interrupted"]:
        raise KeyboardInterrupt


def _record_only(signum: int, frame: FrameType | None) -> None:
    _state["interrupted"] = 1


def is_program() -> bool:
    """Whether this process is the ``jointplay`` command, not a program that imports
    jointplay."""
    return _is_program()


def _is_program() -> bool:
    """Whether this process is the ``jointplay`` command (its script, or ``python -m
    jointplay.cli``), not a program that imports jointplay."""
    if os.path.basename(sys.argv[0]) == "jointplay":
        return True
    argv = list(getattr(sys, "orig_argv", ()))
    return "-m" in argv[:-1] and argv[argv.index("-m") + 1] in ("jointplay.cli", "jointplay")


def _exit_at_once(signum: int, frame: FrameType | None) -> None:
    if not _state["interrupted"]:
        _state["interrupted"] = 1
        os.write(2, b"jointplay: interrupted\n")
    os._exit(EXIT_INTERRUPTED)


def guard_imports() -> None:
    """In the ``jointplay`` program only, and only where Ctrl-C still has Python's default
    handler: Ctrl-C before the command line installs its own handlers (while the packages
    import) prints one line and exits 130 at once, instead of a traceback. Nothing is written
    before then, so there is nothing to clean up. The command line restores this handler when
    it returns, which covers the interpreter's shutdown too."""
    if threading.current_thread() is not threading.main_thread() or not _is_program():
        return
    if signal.getsignal(signal.SIGINT) is signal.default_int_handler:
        signal.signal(signal.SIGINT, _exit_at_once)
        # NumPy's BLAS starts its threads as it imports. Started with SIGINT blocked, they
        # leave it to this thread: one delivered to them would not wake this thread from a
        # sleep or a wait, and the handler would wait with it. One that arrives meanwhile
        # is delivered on the way out.
        blocked = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
        try:
            import numpy  # noqa: F401
        finally:
            signal.pthread_sigmask(signal.SIG_SETMASK, blocked)


@contextlib.contextmanager
def deferred() -> Iterator[None]:
    """Within: a SIGINT is recorded but raised only on the way out, so that work which must
    not be cut in the middle (starting a cluster, whose half-made state nothing could close;
    a pool forking its workers, see :func:`fork` and :func:`started`) finishes first.
    Processes forked within keep the handler from before."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    with _recording() as before:
        yield
    _raise_recorded(before)


def fork() -> int:
    """``os.fork()``, with a Ctrl-C that arrives meanwhile raised here once it has returned
    (the copy, which has done nothing yet, killed and reaped first); the copy gets 0, and the
    handler this process had.

    Python runs the libraries' fork hooks (logging's lock) around a fork, and an error raised
    inside one is printed as "Exception ignored", with a traceback, and dropped: a Ctrl-C
    handled there would show a traceback and be lost. So every fork from the main thread goes
    through here, or, for a pool, happens inside :func:`deferred` (see :func:`started`)."""
    if threading.current_thread() is not threading.main_thread():
        return os.fork()
    with _recording() as before:
        pid = os.fork()
    if pid != 0 and _state["interrupted"] and not before:
        os.kill(pid, signal.SIGKILL)
        os.waitpid(pid, 0)
        _raise_recorded(before)
    return pid


@contextlib.contextmanager
def started(start: Callable[[], contextlib.AbstractContextManager[T]]) -> Iterator[T]:
    """``with start() as it``, with ``start`` (a pool that forks its workers) inside
    :func:`deferred`: a Ctrl-C meanwhile is raised once it has started, and leaving closes
    it (a pool is terminated)."""
    with contextlib.ExitStack() as stack:
        with deferred():
            it = stack.enter_context(start())
        yield it


@contextlib.contextmanager
def _recording() -> Iterator[int]:
    """Within (main thread only): SIGINT only recorded, the handler put aside (see
    :func:`_restore_in_copy`); yields whether an interrupt was recorded before."""
    before = _state["interrupted"]
    if signal.getsignal(signal.SIGINT) is signal.SIG_IGN:  # ignored stays ignored
        yield before
        return
    previous = signal.signal(signal.SIGINT, _record_only)
    _replaced.append(previous)
    try:
        yield before
    finally:
        if _replaced:  # (a copy's fork hook has emptied it)
            _replaced.pop()
        signal.signal(signal.SIGINT, previous)


def _raise_recorded(before: int) -> None:
    """Raise the interrupt recorded since ``before`` was read, if one was."""
    if _state["interrupted"] and not before:
        if not _state["installed"]:  # a library caller: raise it once, remember nothing
            _state["interrupted"] = 0
        interrupt()


def _restore_in_copy() -> None:
    """After a fork, in the copy: the Ctrl-C handler :func:`deferred` or :func:`fork` had put
    aside is the copy's again (a pool's workers keep to what they would have had)."""
    if _replaced and threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGINT, _replaced[0])
    _replaced.clear()


if hasattr(os, "register_at_fork"):
    os.register_at_fork(after_in_child=_restore_in_copy)


@contextlib.contextmanager
def held() -> Iterator[Callable[[], bool]]:
    """Within (main thread only): SIGINT and SIGTERM are only recorded, so that a short
    sequence of file operations (an output transaction's renames) is never cut between
    two steps; the caller may ask whether one arrived (to undo what it started). On the way
    out the first one is handed to the handler it would have met. In other threads, which
    signals never reach, nothing changes."""
    if threading.current_thread() is not threading.main_thread():
        yield lambda: False
        return
    arrived: list[int] = []

    def record(signum: int, frame: FrameType | None) -> None:
        arrived.append(signum)

    previous = signal.getsignal(signal.SIGINT), signal.getsignal(signal.SIGTERM)
    try:
        for signum, handler in zip((signal.SIGINT, signal.SIGTERM), previous, strict=True):
            # An ignored signal stays ignored; one handled outside Python (None) is left.
            if handler not in (signal.SIG_IGN, None):
                signal.signal(signum, record)
        yield lambda: bool(arrived)
    finally:
        for signum, handler in zip((signal.SIGINT, signal.SIGTERM), previous, strict=True):
            if handler is not None:
                signal.signal(signum, handler)
    if arrived:
        handler = previous[0] if arrived[0] == signal.SIGINT else previous[1]
        if callable(handler):
            handler(arrived[0], None)
        elif handler == signal.SIG_DFL:
            os.kill(os.getpid(), arrived[0])  # what it would have done: end the process


@contextlib.contextmanager
def ignoring() -> Iterator[None]:
    """Ignore SIGINT while a process is started, which keeps it ignored (dispositions set to
    "ignore" survive exec). Keep it brief: a Ctrl-C meanwhile is lost."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)


def ignore_in_child() -> None:
    """For worker processes: leave Ctrl-C to the parent, which stops them in order (with
    SIGTERM, which ends a worker at once: it has nothing of its own to clean up)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


guard_imports()  # on the first import, which `import jointplay` makes before any other

__all__ = ["EXIT_INTERRUPTED", "EXIT_TERMINATED", "deferred", "exit_status", "fork",
           "guard_imports", "held", "ignore_in_child", "ignoring", "installed", "interrupt",
           "interrupted", "raise_if_interrupted", "started"]
