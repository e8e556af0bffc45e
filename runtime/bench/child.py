"""One measurement in a fresh interpreter (so that sympy's caches and the compile cache start
cold), its JSON row read from the last line of its output; killed, with its children, when
it runs past its time.

:func:`watch_child` also watches the child's resident memory (its whole process group, gcc
included) and the stages it reports (:func:`report_stage`), with a time limit per clock (a
clock spans several stages: the build, say), so a case killed for time or memory is a
result that says where it was and keeps what it had measured."""

from __future__ import annotations

import contextlib
import json
import os
import signal
import subprocess
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any


class ChildFailed(RuntimeError):
    """The child timed out or exited non-zero; the message says which (and its last words)."""


def json_from_child(argv: Sequence[str], timeout: float) -> dict[str, Any]:
    """Run ``argv`` in a new session; the JSON object on the last line of its stdout.

    Raises :class:`ChildFailed` with "timed out after N s" (its whole process group killed)
    or "exit N: <last line of stderr>".
    """
    proc = subprocess.Popen(list(argv), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, start_new_session=True)
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        raise ChildFailed(f"timed out after {timeout:.0f} s") from None
    if proc.returncode != 0:
        tail = (err.strip().splitlines() or ["?"])[-1]
        raise ChildFailed(f"exit {proc.returncode}: {tail}")
    return dict(json.loads(out.strip().splitlines()[-1]))


# ---- a child watched stage by stage, with time and memory limits ------------------------------

STAGE_MARK = "@stage "  # a line on the child's stderr: the mark, then a JSON object


def report_stage(stage: str, clock: str = "", **measured: Any) -> None:
    """In the child: say that ``stage`` starts (on ``clock``, whose limit the parent enforces
    from the first stage on it), with what has been measured so far (kept if it is killed)."""
    import sys

    print(STAGE_MARK + json.dumps({"stage": stage, "clock": clock, "measured": measured}),
          file=sys.stderr, flush=True)


@dataclass(frozen=True)
class ChildLimits:
    """What a watched child may use: wall seconds in all, wall seconds per clock (a clock spans
    the stages reported on it), and MiB of resident memory for its whole process group."""

    timeout_s: float
    clock_s: Mapping[str, float] = field(default_factory=dict)
    memory_mib: float | None = None
    poll_s: float = 0.1


@dataclass(frozen=True)
class ChildProgress:
    stage: str
    elapsed_s: float
    rss_mib: float


@dataclass(frozen=True)
class ChildOutcome:
    """The JSON row of a child that finished, or ``failure`` saying why it did not; either way
    what its stages reported (``measured``), the stage it was in, and the largest resident
    memory of its process group seen in the samples (MiB)."""

    row: dict[str, Any] | None
    measured: dict[str, Any]
    failure: str | None
    stage: str
    elapsed_s: float
    peak_rss_mib: float


def group_rss_mib(group: int) -> float:
    """Resident memory (MiB) of every process in process group ``group``, from /proc."""
    page = os.sysconf("SC_PAGE_SIZE")
    total = 0
    for entry in os.scandir("/proc"):
        if not entry.name.isdigit():
            continue
        try:
            with open(f"/proc/{entry.name}/stat", "rb") as fh:
                fields = fh.read().rsplit(b")", 1)[1].split()
        except OSError:  # the process ended between the listing and the read
            continue
        if int(fields[2]) == group:  # fields from the state on: state ppid pgrp ...
            total += int(fields[21]) * page
    return total / (1 << 20)


def watch_child(argv: Sequence[str], limits: ChildLimits,
                on_progress: Callable[[ChildProgress], None] | None = None) -> ChildOutcome:
    """Run ``argv`` in a new session; kill its process group when it runs past
    ``limits.timeout_s``, past a clock's limit, or holds more than ``limits.memory_mib``.

    The child reports its stages with :func:`report_stage` on stderr and prints its JSON row
    as the last line of stdout. Never raises for the child's failures: the outcome says.
    """
    import threading

    proc = subprocess.Popen(list(argv), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, start_new_session=True)
    out_lines: list[str] = []
    err_tail: list[str] = []
    state: dict[str, Any] = {"stage": "start", "clock": "", "measured": {}}
    clock_start: dict[str, float] = {}
    started = time.monotonic()
    lock = threading.Lock()

    def read_stdout() -> None:
        assert proc.stdout is not None
        out_lines.extend(proc.stdout)

    def read_stderr() -> None:
        assert proc.stderr is not None
        for line in proc.stderr:
            if line.startswith(STAGE_MARK):
                note = json.loads(line[len(STAGE_MARK):])
                with lock:
                    state["stage"], state["clock"] = note["stage"], note["clock"]
                    state["measured"].update(note["measured"])
                    if note["clock"]:
                        clock_start.setdefault(note["clock"], time.monotonic())
            elif line.strip():
                err_tail[:] = [*err_tail[-19:], line.rstrip()]

    readers = [threading.Thread(target=read_stdout, daemon=True),
               threading.Thread(target=read_stderr, daemon=True)]
    for reader in readers:
        reader.start()
    peak, failure = 0.0, None
    while proc.poll() is None:
        now = time.monotonic()
        rss = group_rss_mib(proc.pid)
        peak = max(peak, rss)
        with lock:
            stage, clock = state["stage"], state["clock"]
            on_clock = now - clock_start[clock] if clock in clock_start else 0.0
        if now - started > limits.timeout_s:
            failure = f"timed out after {limits.timeout_s:g} s (in stage {stage})"
        elif clock in limits.clock_s and on_clock > limits.clock_s[clock]:
            failure = (f"{clock} exceeded its limit of {limits.clock_s[clock]:g} s "
                       f"(in stage {stage})")
        elif limits.memory_mib is not None and rss > limits.memory_mib:
            failure = (f"memory {rss:.0f} MiB exceeded the limit of {limits.memory_mib:g} MiB "
                       f"(in stage {stage})")
        if failure:
            with contextlib.suppress(ProcessLookupError):
                os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
            break
        if on_progress is not None:
            on_progress(ChildProgress(stage, now - started, rss))
        with contextlib.suppress(subprocess.TimeoutExpired):
            proc.wait(timeout=limits.poll_s)
    # A grandchild (gcc) may outlive a child that crashed: end the group either way.
    with contextlib.suppress(ProcessLookupError):
        os.killpg(proc.pid, signal.SIGKILL)
    for reader in readers:
        reader.join(timeout=10)
    elapsed = time.monotonic() - started
    row = None
    if failure is None and proc.returncode != 0:
        failure = f"exit {proc.returncode} (in stage {state['stage']}): " + (
            err_tail[-1] if err_tail else "no message")
    elif failure is None:
        try:
            row = dict(json.loads(out_lines[-1]))
        except (IndexError, ValueError):
            failure = "finished without a JSON row on its last line of output"
    return ChildOutcome(row=row, measured=dict(state["measured"]), failure=failure,
                        stage=state["stage"], elapsed_s=elapsed, peak_rss_mib=peak)
