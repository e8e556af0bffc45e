"""One measurement in a fresh interpreter (so that sympy's caches and the compile cache start
cold), its JSON row read from the last line of its output; killed, with its children, when
it runs past its time."""

from __future__ import annotations

import json
import os
import signal
import subprocess
from collections.abc import Sequence
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
