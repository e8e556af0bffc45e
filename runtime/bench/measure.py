"""Measuring a run: error measures against a reference, timed repeated runs, the reference
solution and how far a second method agrees with it (see the package docstring)."""

from __future__ import annotations

import math
import statistics
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from jointplay.common.errors import SimulationError
from jointplay.scene.definition import ADAPTIVE

if TYPE_CHECKING:
    from jointplay.results.records import SimulationResult
    from jointplay.scene.definition import Scene
    from jointplay.store.model import Model

QUICK_T_END = 0.01
REFERENCE_RTOL = 1e-10
CHECK_METHODS: tuple[str, ...] = ("idas", "radau")
DEFAULT_CHECK_STEP = 1e-6
# (key, Markdown header, format) of the tip error measures.
TIP_ERRORS: tuple[tuple[str, str, str], ...] = (
    ("position", "tip_position", "m"),
    ("velocity", "tip_velocity", "m/s"),
    ("acceleration", "tip_acceleration", "m/s^2"),
)
ERROR_KEYS: tuple[str, ...] = ("err_position", "err_velocity", "err_acceleration",
                               "err_final_state")
ERROR_LABELS: dict[str, str] = {
    "err_position": "end-effector position error [m]",
    "err_velocity": "end-effector velocity error [m/s]",
    "err_acceleration": "end-effector acceleration error [m/s²]",
    "err_final_state": "final-state error [scaled: rad, clearances]",
}



def tip_errors(result: SimulationResult, reference: SimulationResult) -> dict[str, float]:
    """Max over the output samples of the end-effector error norms, against ``reference``."""
    _check_same_grid(result, reference)
    return {f"err_{key}": float(np.max(np.linalg.norm(
        getattr(result, attr) - getattr(reference, attr), axis=1)))
        for key, attr, _ in TIP_ERRORS}


def state_scale(result: SimulationResult) -> np.ndarray:
    """Scale of each state entry: 1 for angles, c for eccentricities, c / 1 ms for their rates."""
    from jointplay.results.records import eccentricity_columns
    from jointplay.sim.problem import RATE_SCALE_TIME

    n = len(result.coordinate_names)
    scale = np.ones(2 * n)
    columns_of = eccentricity_columns(result.coordinate_names, result.clearance_joints)
    for k, columns in enumerate(columns_of.values()):
        c = float(result.radial_clearance[k])
        for i in columns:
            scale[i], scale[n + i] = c, c / RATE_SCALE_TIME
    return scale


def final_state_error(result: SimulationResult, reference: SimulationResult) -> float:
    """max |x(T) - x_ref(T)| in scaled units (see the module docstring)."""
    if result.coordinate_names != reference.coordinate_names:
        return math.nan  # a different model (e.g. ideal joints): states do not compare
    x = np.r_[result.q[-1], result.u[-1]]
    x_ref = np.r_[reference.q[-1], reference.u[-1]]
    return float(np.max(np.abs(x - x_ref) / state_scale(reference)))


def all_errors(result: SimulationResult, reference: SimulationResult) -> dict[str, float]:
    return {**tip_errors(result, reference),
            "err_final_state": final_state_error(result, reference)}


def _check_same_grid(result: SimulationResult, reference: SimulationResult) -> None:
    if result.t.shape != reference.t.shape or not np.allclose(result.t, reference.t,
                                                              rtol=0, atol=1e-12):
        raise ValueError("the result and the reference have different output times "
                         f"({result.t.size} vs {reference.t.size} samples)")


@dataclass
class Timed:
    """Repeated runs of one configuration: the first result, and every run's times."""

    result: SimulationResult | None
    cpu_s: list[float] = field(default_factory=list)
    wall_s: list[float] = field(default_factory=list)
    failure: str | None = None

    def spread(self, key: str = "cpu") -> dict[str, float]:
        values = self.cpu_s if key == "cpu" else self.wall_s
        if not values:
            return {f"{key}_median_s": math.nan, f"{key}_min_s": math.nan,
                    f"{key}_max_s": math.nan}
        return {f"{key}_median_s": statistics.median(values), f"{key}_min_s": min(values),
                f"{key}_max_s": max(values)}


def timed_runs(scene: Scene, model: Model, repeats: int,
               parameters: dict[str, float] | None = None) -> Timed:
    """Simulate ``repeats`` times; a :class:`SimulationError` ends it and is recorded."""
    from jointplay.sim import simulate

    timed = Timed(result=None)
    for _ in range(max(1, repeats)):
        c0 = time.process_time()
        try:
            result = simulate(scene, model=model, parameters=parameters, quiet=True)
        except SimulationError as err:
            return Timed(result=None, failure=str(err))
        timed.cpu_s.append(time.process_time() - c0)
        timed.wall_s.append(float(result.stats["wall_time_s"]))
        if timed.result is None:
            timed.result = result
    return timed


def run_counts(result: SimulationResult | None) -> dict[str, Any]:
    if result is None:
        return dict.fromkeys(COUNT_KEYS)
    return {k: int(result.stats.get(k, 0)) for k in COUNT_KEYS}


# What :func:`timing_columns` and the error measures give every timed row: their CSV keys and
# (key, Markdown header, format) table columns.
COUNT_KEYS: tuple[str, ...] = ("steps", "rhs_evaluations", "jacobian_evaluations", "events",
                               "impacts")
TIMING_KEYS: tuple[str, ...] = ("cpu_median_s", "cpu_min_s", "cpu_max_s", "wall_median_s",
                                "wall_min_s", "wall_max_s", "realtime_factor")
CPU_COLUMNS: tuple[tuple[str, str, str], ...] = (
    ("cpu_median_s", "CPU s (median)", "{:.3f}"),
    ("cpu_min_s", "min", "{:.3f}"),
    ("cpu_max_s", "max", "{:.3f}"),
    ("realtime_factor", "CPU s / sim s", "{:.3f}"),
)
TIP_ERROR_COLUMNS: tuple[tuple[str, str, str], ...] = (
    ("err_position", "pos err m", "{:.2e}"),
    ("err_velocity", "vel err m/s", "{:.2e}"),
    ("err_acceleration", "acc err m/s²", "{:.2e}"),
)


def timing_columns(timed: Timed, t_end: float) -> dict[str, Any]:
    """The columns every timed row has: repeats, CPU and wall spread, counts, CPU per sim s."""
    cpu = timed.spread("cpu")
    return {"repeats": len(timed.cpu_s), **cpu, **timed.spread("wall"),
            **run_counts(timed.result), "realtime_factor": cpu["cpu_median_s"] / t_end}


def run_label(scene: Scene) -> str:
    run = scene.run
    if run.integrator in ADAPTIVE:
        return f"{run.integrator} rtol={run.rtol:g} atol={run.atol:g}"
    return f"{run.integrator} step={run.step:g}"


def cold_compile_seconds(model: Model) -> float:
    """gcc time of the model's C into an empty cache (the cached library costs nothing)."""
    from jointplay.store.build import DEFAULT_CFLAGS, compile_source

    source = (model.folder / "model.c").read_text(encoding="utf-8")
    with tempfile.TemporaryDirectory(prefix="jointplay-bench-") as tmp:
        _, seconds = compile_source(source, DEFAULT_CFLAGS, cache=Path(tmp))
    return seconds


@dataclass
class Reference:
    """The reference solution and how far a second method agrees with it."""

    result: SimulationResult
    label: str
    cpu_s: float
    check_label: str
    check_cpu_s: float
    agreement: dict[str, float]


def reference_solution(scene: Scene, model: Model, *, rtol: float = REFERENCE_RTOL,
                       check: str = "idas", check_step: float = DEFAULT_CHECK_STEP
                       ) -> Reference:
    """CVODES at ``rtol`` (atol tied to it), checked against IDAS at the same tolerance or
    Radau IIA at ``check_step``. Raises :class:`SimulationError` if either run fails."""
    ref_scene = scene.with_run(integrator="cvodes", rtol=rtol, atol=rtol)
    if check == "idas":
        check_scene = scene.with_run(integrator="idas", rtol=rtol, atol=rtol)
    else:
        check_scene = scene.with_run(integrator="radau", step=check_step)
    ref = timed_runs(ref_scene, model, 1)
    if ref.result is None:
        raise SimulationError(0.0, f"the reference run ({run_label(ref_scene)}) failed: "
                                   f"{ref.failure}")
    second = timed_runs(check_scene, model, 1)
    if second.result is None:
        raise SimulationError(0.0, f"the reference check ({run_label(check_scene)}) failed: "
                                   f"{second.failure}")
    return Reference(result=ref.result, label=run_label(ref_scene), cpu_s=ref.cpu_s[0],
                     check_label=run_label(check_scene), check_cpu_s=second.cpu_s[0],
                     agreement=all_errors(second.result, ref.result))
