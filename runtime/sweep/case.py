"""One case of a sweep, where it runs (a worker, or this process): the case's robot and its
ideal-joint counterpart simulated, and the row that summarises them."""

from __future__ import annotations

import math
import os
import socket
import threading
import time
import warnings
from collections import OrderedDict
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

from jointplay.common import interrupts
from jointplay.common.errors import SimulationError
from jointplay.scene.definition import Scene, ideal_counterpart
from jointplay.sweep.metrics import case_metrics
from jointplay.sweep.spec import Case

if TYPE_CHECKING:
    from jointplay.results.records import SimulationResult
    from jointplay.store.model import Model

# Failures of these stages are deterministic; a restart keeps them (unless retry_failed).
STAGE_SIMULATION = "simulation"
STAGE_WORKER = "worker"
_IDEAL_CACHE_SIZE = 16

_LOCAL = threading.local()
_IDEAL_LOCK = threading.Lock()
_IDEAL_CACHE: OrderedDict[str, SimulationResult | BaseException] = OrderedDict()


def _model(scene: Scene, ideal: bool) -> Model:
    """This thread's loaded model of the scene's structure (a compiled library is not shared
    between threads, whose calls would race on its buffers)."""
    from jointplay.sim import load_scene_model

    models: dict[tuple[str, bool], Model] = _LOCAL.__dict__.setdefault("models", {})
    key = (scene.robot.structure_hash(), ideal)
    if key not in models:
        models[key] = load_scene_model(scene, ideal=ideal)
    return models[key]


def _ideal_result(case: Case, model: Model) -> tuple[SimulationResult, bool]:
    """The ideal-joint run of the case, shared by every case with the same ideal robot.

    The ideal robot has no clearance, contact or friction parameters, so cases that vary only
    those share one ideal run (deterministic: reusing it gives the very same numbers).
    Returns the result and whether it was reused.
    """
    from jointplay.sim import simulate

    with _IDEAL_LOCK:
        hit = _IDEAL_CACHE.get(case.ideal_key)
        if hit is not None:
            _IDEAL_CACHE.move_to_end(case.ideal_key)
    if hit is None:
        scene = case.scene.with_robot(ideal_counterpart(case.scene.robot))
        try:
            hit = simulate(scene, model=model, quiet=True)
        except Exception as err:  # deterministic: remembered like a result
            interrupts.raise_if_interrupted()  # not an interrupt, which is no result at all
            hit = err
        with _IDEAL_LOCK:
            _IDEAL_CACHE[case.ideal_key] = hit
            while len(_IDEAL_CACHE) > _IDEAL_CACHE_SIZE:
                _IDEAL_CACHE.popitem(last=False)
        reused = False
    else:
        reused = True
    if isinstance(hit, BaseException):
        raise hit
    return hit, reused


@dataclass(frozen=True)
class CaseOutcome:
    """What a case sends back: its row, and the full result when series are kept."""

    key: str
    row: dict[str, Any]
    result: SimulationResult | None = None


# Contact columns from the contact-phase table (located, never sampled), overall and per


def _blank_row(case: Case) -> dict[str, Any]:
    return {"key": case.key, "status": "ok", "error": None, "error_type": None,
            "error_stage": None, "error_time": None, "error_joint": None,
            "parameters": {**case.swept, **case.parameters}, "ideal_reused": None,
            "worker": f"{socket.gethostname()}:{os.getpid()}", "series": None}


def run_case(case: Case, *, series: bool = False,
             hook: Callable[[Case], None] | None = None, verify: bool = False) -> CaseOutcome:
    """Simulate one case and summarise it; a simulation that fails gives a ``failed`` row.
    ``verify`` adds the case's accuracy statement (``simulate(..., verify=True)``).

    Runs on a worker (or in this process): the model is loaded from the compile cache once
    per worker thread. ``hook(case)`` is called first (instrumentation and fault injection).
    """
    from jointplay.sim import simulate
    from jointplay.sim.plausibility import PlausibilityWarning

    if hook is not None:
        hook(case)
    start, cpu = time.perf_counter(), time.process_time()
    row = _blank_row(case)
    model = _model(case.scene, ideal=False)
    ideal_model = _model(case.scene, ideal=True)
    full: SimulationResult | None = None
    stage = "ideal robot"
    try:
        ideal, reused = _ideal_result(case, ideal_model)
        row["ideal_reused"] = reused
        stage = "robot"
        with warnings.catch_warnings():  # a kept implausible case is marked in its row
            warnings.simplefilter("ignore", PlausibilityWarning)
            result = simulate(case.scene, model=model, quiet=True, verify=verify)
    except Exception as err:
        # An interrupt that compiled code turned into an error is no outcome: the case is
        # simply not done, and the next run picks it up.
        interrupts.raise_if_interrupted()
        message = err.cause if isinstance(err, SimulationError) else str(err)
        row.update(status="failed", error=f"{stage}: {message or type(err).__name__}",
                   error_type=type(err).__name__, error_stage=STAGE_SIMULATION,
                   error_time=getattr(err, "time", None), error_joint=getattr(err, "joint",
                                                                              None))
    else:
        metrics = case_metrics(result, ideal)
        # None marks a peak the integrator does not locate (see peak_note); anything else
        # must be finite: never an "ok" row with NaN in it.
        bad = [name for name, value in metrics.items()
               if isinstance(value, float) and not math.isfinite(value)]
        if bad:
            row.update(status="failed", error=f"robot: non-finite {', '.join(bad)}",
                       error_type="SimulationError", error_stage=STAGE_SIMULATION)
        else:
            row.update(metrics)
            if series:
                full = replace(result, ideal=ideal)
    row["wall_time_s"] = time.perf_counter() - start
    # CPU seconds of the process: well below wall time when other work shares the cores.
    row["cpu_time_s"] = time.process_time() - cpu
    return CaseOutcome(case.key, row, full)


def worker_failure(case: Case, err: BaseException) -> CaseOutcome:
    """A row for a case whose task could not finish (its worker kept dying, or it raised)."""
    row = _blank_row(case)
    row.update(status="failed", error=f"worker: {err}" if str(err) else "worker: "
               f"{type(err).__name__}", error_type=type(err).__name__, error_stage=STAGE_WORKER,
               worker=None)
    return CaseOutcome(case.key, row, None)


