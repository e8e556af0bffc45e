"""Sensitivities checked against central differences of whole runs (a gradient check).

:func:`compare_with_differences` runs a scene with sensitivities, then twice per parameter
with it moved by +-h and +-h/2, and states how far each output's sensitivity is from the
central difference (normwise: the largest difference over the largest central difference)
and how far the two differences are from each other (the reference's own uncertainty: noise
of the runs below h, truncation above). The state and the tip are compared between impacts:
at the samples outside every contact phase of every run (inside one, a difference straddles
the moved onset or separation, where the state is not smooth in the parameter).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from jointplay.common.errors import SimulationError
from jointplay.results.records import SimulationResult
from jointplay.scene.definition import Scene

# The outputs compared, and which of them are compared between impacts only.
OUTPUTS = ("state", "tip", "velocity", "times", "peaks")
BETWEEN_IMPACTS = ("state", "tip", "velocity")


def parameter_value(result: SimulationResult, name: str) -> float:
    """The value of a name ``simulate`` takes (``jointN.clearance`` included) in a run."""
    values = dict(zip(result.parameter_names, result.parameters.tolist(), strict=True))
    if name.endswith(".clearance"):
        joint = name.rsplit(".", 1)[0]
        return values[f"{joint}.bearing_radius"] - values[f"{joint}.journal_radius"]
    return float(values[name])


def _outputs(result: SimulationResult) -> dict[str, np.ndarray]:
    return {"state": np.hstack([result.q, result.u]), "tip": result.tip_position,
            "velocity": result.tip_velocity, "times": result.impacts.time,
            "peaks": result.impacts.peak_force}


def in_contact(result: SimulationResult) -> np.ndarray:
    """The samples of ``result`` inside some contact phase (onset to separation)."""
    impacts = result.impacts
    end = np.where(np.isfinite(impacts.separation_time), impacts.separation_time, np.inf)
    t = result.t[:, None]
    return np.asarray(np.any((t >= impacts.time[None, :]) & (t <= end[None, :]), axis=1))


def _central(scene: Scene, base: Mapping[str, float], name: str, value: float, h: float
             ) -> tuple[dict[str, np.ndarray], np.ndarray]:
    """Central differences of every output, and the samples in contact in either run."""
    from jointplay.sim import simulate

    plus = simulate(scene, parameters={**base, name: value + h})
    minus = simulate(scene, parameters={**base, name: value - h})
    if not np.array_equal(plus.impacts.joint, minus.impacts.joint):
        raise SimulationError(float(scene.run.t_end), f"moving {name} by +-{h:.3g} changes the "
                              "sequence of impacts: the outputs are not differentiable there; "
                              "shorten the run or take a smaller step")
    a, b = _outputs(plus), _outputs(minus)
    return {k: (a[k] - b[k]) / (2 * h) for k in a}, in_contact(plus) | in_contact(minus)


def _normwise(a: np.ndarray, b: np.ndarray) -> float:
    """max |a - b| / max |b|; where b is all zero (the parameter moves nothing): 0 if a is
    too, else inf; NaN when there is nothing to compare (no impacts, or every sample in
    contact)."""
    if not b.size:
        return float("nan")
    scale = float(np.max(np.abs(b)))
    if scale == 0:
        return 0.0 if not np.any(a) else float("inf")
    return float(np.max(np.abs(a - b)) / scale)


def compare_with_differences(scene: Scene, names: Sequence[str], *,
                             relative_step: float = 1e-3,
                             reference: Scene | None = None,
                             parameters: Mapping[str, float] | None = None,
                             error_control: bool = False) -> dict[str, dict[str, Any]]:
    """Per name: each output's normwise disagreement with central differences (``state``,
    ``tip``, ``velocity``, ``times``, ``peaks``), and beside each (``..._stability``) the
    differences' change from h to h / 2; h = ``relative_step`` times the parameter's value.
    The differences run ``reference`` (default ``scene``: give the same scene at tighter
    tolerances to check the sensitivities of a run at its own); ``parameters`` and
    ``error_control`` (``sensitivity_error_control``) as in ``simulate``. Raises
    SimulationError where a step changes the sequence of impacts."""
    from jointplay.sim import simulate

    base = dict(parameters or {})
    reference = reference or scene
    result = simulate(scene, parameters=base or None, sensitivities=names,
                      sensitivity_error_control=error_control)
    sens = result.sensitivities
    assert sens is not None
    analytic = {"state": sens.state, "tip": sens.tip_position, "velocity": sens.tip_velocity,
                "times": sens.impact_times, "peaks": sens.impact_peaks}
    report: dict[str, dict[str, Any]] = {}
    for k, name in enumerate(names):
        value = parameter_value(result, name)
        h = relative_step * abs(value)
        fd, contact = _central(reference, base, name, value, h)
        fd_half, contact_half = _central(reference, base, name, value, h / 2)
        free = ~(contact | contact_half | in_contact(result))
        row: dict[str, Any] = {"step": h, "impacts": len(result.impacts)}
        for key in OUTPUTS:
            rows = free if key in BETWEEN_IMPACTS else slice(None)
            if key in ("times", "peaks") and fd[key].shape != analytic[key].shape[:1]:
                raise SimulationError(float(scene.run.t_end), f"the run with sensitivities has "
                                      f"{analytic[key].shape[0]} impacts, the reference "
                                      f"{fd[key].shape[0]}: tighten the run's tolerances")
            row[key] = _normwise(analytic[key][rows, ..., k], fd[key][rows])
            row[f"{key}_stability"] = _normwise(fd_half[key][rows], fd[key][rows])
        report[name] = row
    return report
