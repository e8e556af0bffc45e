"""One timer for "what does one call cost": medians of calibrated batches, the GC off."""

from __future__ import annotations

import gc
import statistics
import time
from collections.abc import Callable
from typing import Any


def per_call_seconds(fn: Callable[[], Any], repeats: int = 7, batch_s: float = 0.05,
                     clock: Callable[[], float] = time.perf_counter) -> float:
    """Median seconds per call over ``repeats`` batches sized to take about ``batch_s``.

    ``clock`` reads the time: wall by default, ``time.process_time`` for CPU seconds.

    The batch size is calibrated first (so a 1 us call and a 10 ms call are both timed over
    enough calls for the clock's resolution not to matter), and the garbage collector is off
    while timing, so one collection does not land in one batch.
    """
    fn()
    number = 1
    while True:
        t0 = clock()
        for _ in range(number):
            fn()
        elapsed = clock() - t0
        if elapsed >= batch_s / 4 or number >= 1 << 22:
            break
        number *= 4
    number = max(1, int(number * batch_s / max(elapsed, 1e-9)))
    samples = []
    enabled = gc.isenabled()
    gc.disable()
    try:
        for _ in range(repeats):
            t0 = clock()
            for _ in range(number):
                fn()
            samples.append((clock() - t0) / number)
    finally:
        if enabled:
            gc.enable()
    return statistics.median(samples)
