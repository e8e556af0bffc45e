"""A scene's run settings (``[run]``): how it is integrated, each value checked on
construction and the settings checked against one another."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any, Literal

from jointplay.common import limits
from jointplay.common.errors import DescriptionError
from jointplay.common.hints import did_you_mean
from jointplay.common.validation import Problems, check_keys
from jointplay.scene.initial import finite_number as _finite_number

INTEGRATORS: tuple[str, ...] = ("bdf", "cvodes", "idas", "rk4", "radau")
ADAPTIVE: tuple[str, ...] = ("bdf", "cvodes", "idas")
PLAUSIBILITY: tuple[str, ...] = ("stop", "warn", "off")
"""What a run does when it leaves the physical domain (a journal driven through its bearing,
an energy balance that no longer closes): stop with an error (the default), warn and return
the result marked as implausible, or check nothing (:mod:`jointplay.sim.plausibility`)."""
Plausibility = Literal["stop", "warn", "off"]

_RUN_KEYS = ("t_end", "output_step", "integrator", "rtol", "atol", "step", "max_steps",
             "plausibility")


@dataclass(frozen=True)
class RunSettings:
    """How a scene is integrated.

    The defaults are the cheapest setting measured to meet the project's working accuracy on
    the default scene (tip error <= 1e-5 m, energy balance residual <= 0.1 % of the dissipated
    energy; see docs/results/accuracy.md). Validated on construction.

    Attributes
    ----------
    t_end : float
        Duration of the run, s.
    output_step : float
        Time between output samples, s.
    integrator : str
        ``bdf`` (the compiled BDF, the default), ``cvodes``, ``idas`` (CasADi's SUNDIALS),
        ``radau`` or ``rk4`` (fixed step).
    rtol : float
        The adaptive integrators' relative local error tolerance.
    atol : float
        Their absolute tolerance, in scaled units (radians and rad/s for angles; fractions of
        the joint's radial clearance for eccentricities, and of the clearance per millisecond
        for their rates), so one number serves both.
    step : float
        The fixed step of ``rk4`` and ``radau``, s; it must divide ``output_step``.
    max_steps : int
        Bound on the work between two outputs.
    plausibility : {"stop", "warn", "off"}
        What a run that leaves the physical domain does: ``"stop"`` (raise
        :class:`~jointplay.SimulationError`), ``"warn"`` (one warning; the result is returned,
        marked in ``result.implausible``) or ``"off"`` (see :data:`PLAUSIBILITY`).
    """

    t_end: float = 2.0
    output_step: float = 1e-3
    integrator: str = "bdf"
    rtol: float = 2e-6
    atol: float = 3e-7
    step: float = 1e-5
    max_steps: int = 200_000
    plausibility: Plausibility = "stop"

    def __post_init__(self) -> None:
        # Built from a file, flags or the API alike, the settings are checked here, once.
        _validate_run(self, None)

    @property
    def n_outputs(self) -> int:
        return round(self.t_end / self.output_step)

    @property
    def steps_per_output(self) -> int:
        return max(1, round(self.output_step / self.step))

def _error(field_name: str, message: str, source: str | None) -> DescriptionError:
    return DescriptionError(field_name, message, source)


def _positive_number(value: Any, where: str, source: str | None) -> float:
    number = _finite_number(value, where, source)
    if number <= 0:
        raise _error(where, f"must be > 0, got {value!r}", source)
    return number


def _validate_run(run: RunSettings, source: str | None) -> None:
    # Each setting by itself (all reported together), then how they fit one another.
    problems = Problems()
    for name, low, high in (("t_end", 0.0, limits.MAX_T_END),
                            ("output_step", limits.MIN_OUTPUT_STEP, math.inf),
                            ("step", limits.MIN_STEP, math.inf),
                            ("rtol", limits.MIN_RTOL, math.inf),
                            ("atol", limits.MIN_ATOL, math.inf)):
        with problems.check():
            value = _positive_number(getattr(run, name), f"run.{name}", source)
            if value > high:
                raise _error(f"run.{name}", f"must be at most {high:g}, got {value:g}", source)
            if value < low:
                raise _error(f"run.{name}", f"must be at least {low:g}, got {value:g}", source)
    with problems.check():
        if not isinstance(run.plausibility, str) or run.plausibility not in PLAUSIBILITY:
            hint = did_you_mean(str(run.plausibility), PLAUSIBILITY)
            raise _error("run.plausibility", f"must be one of {', '.join(PLAUSIBILITY)}, got "
                         f"{run.plausibility!r}{hint}", source)
    with problems.check():
        if not isinstance(run.integrator, str) or run.integrator not in INTEGRATORS:
            hint = did_you_mean(str(run.integrator), INTEGRATORS)
            raise _error("run.integrator", f"must be one of {', '.join(INTEGRATORS)}, got "
                         f"{run.integrator!r}{hint}", source)
    with problems.check():
        if isinstance(run.max_steps, bool) or not isinstance(run.max_steps, int) \
                or not 1 <= run.max_steps <= limits.MAX_MAX_STEPS:
            raise _error("run.max_steps", f"must be an integer from 1 to "
                         f"{limits.MAX_MAX_STEPS}, got {run.max_steps!r}", source)
    with problems.check():
        if isinstance(run.rtol, (int, float)) and run.rtol >= 1:
            raise _error("run.rtol", f"must be < 1, got {run.rtol}", source)
    problems.raise_any()
    if run.t_end / run.output_step > limits.MAX_OUTPUTS + 0.5:
        raise _error("run.output_step", f"gives {run.t_end / run.output_step:.3g} output "
                     f"samples over run.t_end = {run.t_end:g} s; at most "
                     f"{limits.MAX_OUTPUTS} are allowed (raise output_step or shorten t_end)",
                     source)
    if run.integrator not in ADAPTIVE and run.t_end / run.step > limits.MAX_FIXED_STEPS:
        raise _error("run.step", f"gives {run.t_end / run.step:.3g} fixed steps over "
                     f"run.t_end = {run.t_end:g} s; at most {limits.MAX_FIXED_STEPS} are "
                     "allowed", source)
    if run.output_step > run.t_end:
        raise _error("run.output_step", f"must not exceed run.t_end ({run.t_end}), got "
                     f"{run.output_step}", source)
    if abs(run.n_outputs * run.output_step - run.t_end) > 1e-9 * run.t_end:
        raise _error("run.output_step", f"must divide run.t_end ({run.t_end}) into whole "
                     f"samples, got {run.output_step}", source)
    if run.integrator not in ADAPTIVE and (run.step > run.output_step or abs(
            run.steps_per_output * run.step - run.output_step) > 1e-9 * run.output_step):
        raise _error("run.step", f"the fixed step must divide run.output_step "
                     f"({run.output_step}), got {run.step}", source)


def run_settings_from_table(raw: Any, source: str | None) -> RunSettings:
    """The run settings of a scene file's ``[run]`` table: the same checks as run settings
    built in Python (RunSettings checks its own values), unknown keys refused."""
    problems = Problems()
    if not isinstance(raw, Mapping):
        check_keys(raw, _RUN_KEYS, "run", source)
    with problems.check():
        check_keys(raw, _RUN_KEYS, "run", source)
    try:
        run = RunSettings(**{k: v for k, v in raw.items() if k in _RUN_KEYS})
    except DescriptionError as err:
        problems.found.extend(err.problems)
    problems.raise_any(source)
    return run
