"""The simulator: a scene's robot integrated through its contact events.

Rooms: ``problem`` (model, parameters, torques, scaling, contact flags), ``bdf`` with
``native`` and ``driver.c`` (the default method: a whole run in compiled code, events
included), ``casadi_methods`` (CVODES and IDAS through CasADi, the independent reference),
``fixed`` (compiled RK4 and Radau IIA steps at a fixed step) and ``assemble`` (every derived
output). :func:`simulate` runs a scene; :class:`Stepper` (``stepper``) advances it one sample at a
time for closed loops.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Mapping, Sequence
from typing import Any

import numpy as np

from jointplay.common.errors import SimulationError
from jointplay.results.records import Impacts, SimulationResult
from jointplay.scene.definition import ADAPTIVE, Plausibility, Scene, ideal_counterpart
from jointplay.sim.assemble import _assemble
from jointplay.sim.bdf import run_bdf
from jointplay.sim.casadi_methods import _run_adaptive
from jointplay.sim.fixed import _run_fixed
from jointplay.sim.native import NEWTON_MATRICES
from jointplay.sim.plausibility import (
    PenetrationWatch,
    PlausibilityWarning,
    check_result,
    implausible,
    singular_torque,
)
from jointplay.sim.problem import (
    _Accumulated,
    _initial_state,
    _parameter_vector,
    _Problem,
    _Trajectory,
    load_scene_model,
)
from jointplay.sim.stepper import Stepper
from jointplay.store.model import Model

__all__ = ["METHODS", "Stepper", "can_check_accuracy", "load_scene_model", "simulate",
           "tighter_note",
           "tighter_settings",
           "with_accuracy"]

# One interface for every integration method: (problem, x0, trajectory to fill, statistics,
# progress bar) -> the contact-phase table, or None where the method records onsets only
# (then assembled from the trajectory's impact list).
Method = Callable[[_Problem, np.ndarray, _Trajectory, _Accumulated, Any], "Impacts | None"]
METHODS: dict[str, Method] = {"bdf": run_bdf, "cvodes": _run_adaptive, "idas": _run_adaptive,
                              "rk4": _run_fixed, "radau": _run_fixed}


def _refuse_mechanism(scene: object, what: str) -> None:
    """A mechanism's scene has its own entry point: say which, not fail on a missing robot."""
    from jointplay.mechanism.description import MechanismScene

    if isinstance(scene, MechanismScene):
        from jointplay.common.errors import DescriptionError

        raise DescriptionError("scene", f"is a mechanism ({scene.name}); {what} takes a serial "
                               "arm's scene: simulate a mechanism with "
                               "jointplay.simulate_mechanism(scene)", scene.source)


def simulate(scene: Scene, *, model: Model | None = None,
             parameters: Mapping[str, float] | Sequence[float] | None = None,
             compare_ideal: bool = False, quiet: bool = True,
             verify: bool = False, plausibility: Plausibility | None = None,
             sensitivities: Sequence[str] | None = None,
             sensitivity_error_control: bool = False, peaks: bool = True,
             newton: str = "auto") -> SimulationResult:
    """Simulate ``scene`` and return every output as numpy arrays.

    The compiled model of the scene's robot is loaded (derived and compiled once, then
    cached); changing numbers never recompiles.

    Parameters
    ----------
    scene : Scene
        The robot, its drive torques, initial state and run settings.
    model : Model, optional
        The compiled model to run (default: :func:`load_scene_model` of ``scene``).
    parameters : mapping of str to float, or sequence of float, optional
        Numbers of the scene's robot overridden by name (``{"friction.mu": 0.1}``; the names of
        ``Model.parameters``, plus ``jointN.clearance``), or the whole parameter vector.
    compare_ideal : bool, default False
        Also simulate the same scene with ideal joints, into ``result.ideal``.
    quiet : bool, default True
        No progress bar.
    verify : bool, default False
        Also run the scene at tolerances 10x tighter (fixed-step methods: a 10x smaller step)
        and state the first run's accuracy in ``result.accuracy`` (:class:`Accuracy`: estimated
        tip error, energy residuals, the agreement horizon of the impact sequence and which
        impacts are tolerance-sensitive); it costs that second run.
    plausibility : {"stop", "warn", "off"}, optional
        What a run that leaves the physical domain does (a journal driven through its bearing,
        at an output sample or at a located deepest point of a contact phase; an energy balance
        that no longer closes): ``"stop"`` raises :class:`SimulationError`; ``"warn"`` issues one
        :class:`~jointplay.sim.plausibility.PlausibilityWarning` and returns the result with
        ``result.implausible`` saying why; ``"off"`` checks neither. Default: the scene's
        ``run.plausibility``, itself ``"stop"`` unless set.
    sensitivities : sequence of str, optional
        Parameter names (any name ``parameters`` takes, and ``jointN.clearance``, the radial
        clearance of joint N with its bearing radius held): ``result.sensitivities``
        (:class:`jointplay.results.sensitivities.Sensitivities`) then holds the derivatives of
        the state, the tip, the impact times and peak forces with respect to each, integrated
        beside the state and carried through every contact onset (``bdf`` only).
    sensitivity_error_control : bool, default False
        Put the sensitivities in the integrator's error test (their error then follows the run's
        tolerances, at the price of more steps, and the state changes within those tolerances).
        By default they stay out of it, and the state is the same as without them.
    peaks : bool, default True
        Locate each contact phase's peak normal force (``bdf``: Brent's method on the dense
        output over the force sampled at every step in contact; with ``sensitivities``, its
        derivatives too). ``False`` skips that, for runs that need the motion only (a
        calibration's trial runs): ``result.impacts.peak_force`` and ``peak_force_time`` (and
        ``result.sensitivities.impact_peaks``) are NaN, everything else is the same to the bit,
        and a run costs up to a tenth less CPU (``benchmarks/run_options_cost.py``: 7-10 % without
        sensitivities, within the machine's scatter with them).
    newton : {"auto", "full", "reduced"}, default "auto"
        The Newton matrix of ``bdf``'s steps for a second-order system: ``"full"`` factors
        I - c J (2n rows), ``"reduced"`` the n x n matrix it reduces to (the same solution up
        to round-off; ``benchmarks/run_options_cost.py --option newton``: 15-20 % less CPU
        on the three-link arm's 7 coordinates without sensitivities, 1-6 % on the paper arm's
        8), ``"auto"`` the reduced one from 12 coordinates on. Round-off in an impact burst
        changes the steps taken, so the two runs differ within the tolerances.

    Returns
    -------
    SimulationResult
        The trajectory at every output sample, the located impacts, the energy balance, the
        solver's statistics and the dense output ``result.sol``.

    Raises
    ------
    SimulationError
        With the time, the joint and the cause, when the integration cannot go on.
    DescriptionError
        When an option or a parameter name is invalid (it names the field and the fix).

    Examples
    --------
    >>> import numpy as np
    >>> import jointplay
    >>> scene = jointplay.default_scene().with_run(t_end=0.02)
    >>> result = jointplay.simulate(scene, compare_ideal=True)
    >>> result.t.shape, result.coordinate_names
    ((21,), ['q2', 'q3', 'ex2', 'ey2', 'ex3', 'ey3'])
    >>> round(float(result.impacts.peak_force.max()))  # N, located, not sampled
    1657
    >>> error = np.linalg.norm(result.tip_position - result.ideal.tip_position, axis=1)
    >>> bool(error.max() < 1e-3)  # m: the clearance's tip error over 20 ms
    True
    """
    from tqdm import tqdm

    _refuse_mechanism(scene, "simulate")
    if plausibility is not None:
        scene = scene.with_run(plausibility=plausibility)
    if verify and not can_check_accuracy(scene):
        from jointplay.common.errors import DescriptionError

        raise DescriptionError("verify", "the run's settings are at their limits (run.rtol, "
                               "run.atol or run.step): no tighter run can check its "
                               "accuracy; use verify=False")

    if newton not in NEWTON_MATRICES:  # before any work, the ideal arm's run included
        from jointplay.common.errors import DescriptionError

        raise DescriptionError("newton", f"must be one of {', '.join(NEWTON_MATRICES)}, got "
                               f"{newton!r}")
    names = _sensitivity_names(sensitivities, scene.run.integrator)
    model = model or load_scene_model(scene)
    p = _parameter_vector(model, scene, parameters)
    if names:  # every name checked before any work
        from jointplay.robot.derived import parameter_directions

        parameter_directions(names, model.parameters, scene.robot)
    ideal_result = None
    if compare_ideal:
        ideal_scene = scene.with_robot(ideal_counterpart(scene.robot))
        ideal_model = load_scene_model(scene, ideal=True)
        ideal_params = None
        if isinstance(parameters, Mapping):
            ideal_params = {k: v for k, v in parameters.items()
                            if k in ideal_model.parameters}
        ideal_result = simulate(ideal_scene, model=ideal_model,
                                parameters=ideal_params, quiet=quiet,
                                plausibility=plausibility, newton=newton)
    pr = _Problem(model, scene, p)
    pr.peaks = bool(peaks)
    pr.newton = newton
    run = scene.run
    if model.structure.wear is not None and run.integrator != "bdf":
        from jointplay.common.errors import DescriptionError

        raise DescriptionError("run.integrator", "wear is integrated by the compiled loop: "
                               f"use integrator = \"bdf\" with [robot.wear] (got "
                               f"{run.integrator!r})", scene.source)
    n_out = run.n_outputs
    t = np.arange(n_out + 1) * run.output_step
    traj = _Trajectory(x=np.zeros((n_out + 1, model.n_state)),
                       v_imp=np.zeros((n_out + 1, pr.nc)),
                       work=np.zeros(n_out + 1), dissipated=np.zeros(n_out + 1))
    x0 = _initial_state(model, scene, p)
    if names:
        from jointplay.sim.sensitivity import sensitivity_inputs

        pr.sensitivity = sensitivity_inputs(pr, names, x0, sensitivity_error_control)
    stats = _Accumulated()
    if run.integrator == "bdf":  # compiled now if the cache lacks it: said before the bar
        from jointplay.sim.native import driver_library

        driver_library()
    start = time.perf_counter()
    with tqdm(total=n_out, disable=quiet, delay=2.0, unit="out", leave=False,
              desc=f"{scene.name} ({run.integrator})") as progress:
        # The watch checks each batch of new samples for a journal driven through its bearing.
        watch = PenetrationWatch(progress, pr, traj)
        try:
            phases = METHODS[run.integrator](pr, x0, traj, stats, watch)
        except SimulationError as err:
            # A torque singular between output times makes every integrator fail in its own
            # way (a collapsed step, too much work, a non-finite state): name the torque.
            cause = singular_torque(pr, err.time)
            if cause is None:
                raise
            raise SimulationError(err.time, cause) from None
    wall = time.perf_counter() - start
    counts: dict[str, Any] = dict(stats.counts)
    result = _assemble(pr, traj, t, counts, wall, ideal_result, phases)
    watch.check_impacts(result.impacts)  # every located deepest point, whatever the outputs
    result = implausible(watch.findings + check_result(result, pr), pr, result)
    if names:
        result = _with_sensitivities(result, pr, names, traj)
    if verify:
        result = with_accuracy(result, scene, model=model, parameters=parameters, quiet=quiet)
    # Last: the dense output is attached to this very object (a dataclass replace drops it).
    from jointplay.sim.dense import attach

    return attach(result, pr, traj, x0)


def _sensitivity_names(names: Sequence[str] | None, integrator: str) -> tuple[str, ...]:
    """The names asked for, checked for form (the model checks them by name later)."""
    from jointplay.common.errors import DescriptionError

    if names is None:
        return ()
    if isinstance(names, str):
        names = (names,)
    names = tuple(names)
    for name in names:
        if not isinstance(name, str):
            raise DescriptionError("sensitivities", f"names parameters by name (strings), "
                                   f"got {name!r}")
    if names and integrator != "bdf":
        raise DescriptionError("run.integrator", f"sensitivities are integrated by the bdf "
                               f"integrator only; use integrator = \"bdf\" (got "
                               f"{integrator!r})")
    return names


def _with_sensitivities(result: SimulationResult, pr: _Problem, names: tuple[str, ...],
                        traj: _Trajectory) -> SimulationResult:
    """``result`` with its sensitivities; the problem stops carrying them (a dense output
    run later integrates the state alone)."""
    from dataclasses import replace

    from jointplay.sim.sensitivity import assemble_sensitivities

    inputs, pr.sensitivity = pr.sensitivity, None
    impacts = result.impacts
    joints = np.array([pr.model.clearance_joints.index(int(j)) for j in impacts.joint],
                      dtype=int)
    sens = assemble_sensitivities(pr, names, inputs, result.t, traj.x, traj.sensitivity,
                                  traj.phase_sensitivity, joints,
                                  np.asarray(impacts.max_penetration, dtype=float))
    return replace(result, sensitivities=sens)


def tighter_settings(scene: Scene) -> dict[str, float]:
    """The run settings of the accuracy check: tolerances (or the fixed step) 10x tighter,
    clamped to the limits a run may have (:data:`~jointplay.common.limits.MIN_RTOL`,
    ``MIN_ATOL``, ``MIN_STEP``, ``MAX_FIXED_STEPS``; :func:`tighter_note` says when), so the
    check of any valid run is itself a valid run."""
    from jointplay.common import limits
    from jointplay.results.accuracy import TIGHTER

    run = scene.run
    if run.integrator in ADAPTIVE:
        return {"rtol": max(run.rtol / TIGHTER, limits.MIN_RTOL),
                "atol": max(run.atol / TIGHTER, limits.MIN_ATOL)}
    # A step that still divides the output step: the most steps per output up to 10x the
    # run's, within the smallest step and the most steps a run may take.
    per_output = run.steps_per_output
    smallest = max(limits.MIN_STEP, run.t_end / limits.MAX_FIXED_STEPS)
    most = max(per_output, math.floor(run.output_step / smallest * (1 + 1e-12)))
    return {"step": run.output_step / min(per_output * round(TIGHTER), most)}


def can_check_accuracy(scene: Scene) -> bool:
    """Whether the accuracy check's settings differ from the run's: not where every one is
    at its limit already (rk4 at the smallest step, say), where the check would repeat the
    run and estimate nothing."""
    run = scene.run
    return any(value != getattr(run, name) for name, value in tighter_settings(scene).items())


def tighter_note(scene: Scene) -> str | None:
    """Why the accuracy check's settings are less than 10x tighter (a limit), or None."""
    from jointplay.results.accuracy import TIGHTER

    run = scene.run
    tighter = tighter_settings(scene)
    names = ("rtol", "atol") if run.integrator in ADAPTIVE else ("step",)
    clamped = [f"run.{name} {tighter[name]:g} (not {getattr(run, name) / TIGHTER:g})"
               for name in names
               if not math.isclose(tighter[name] * TIGHTER, getattr(run, name), rel_tol=1e-9)]
    if not clamped:
        return None
    return (f"the check's {', '.join(clamped)} is clamped to the limits a run may have, so "
            "it is less than 10x tighter and its error estimates are less certain")


def with_accuracy(result: SimulationResult, scene: Scene, *, model: Model | None = None,
                  parameters: Mapping[str, float] | Sequence[float] | None = None,
                  quiet: bool = True) -> SimulationResult:
    """``result`` (a run of ``scene`` with ``parameters``) with its accuracy statement, from
    a second run at tolerances 10x tighter: what ``simulate(..., verify=True)`` does, for a
    run already made (the CLI decides after the first run whether the check is affordable)."""
    import warnings

    from jointplay.results.accuracy import compare_runs

    tighter = tighter_settings(scene)
    model = model or load_scene_model(scene)
    with warnings.catch_warnings():  # the run itself has said whether it is plausible
        warnings.simplefilter("ignore", PlausibilityWarning)
        check = simulate(scene.with_run(**tighter), model=model, parameters=parameters,
                         quiet=quiet)
    run = scene.run
    adaptive = run.integrator in ADAPTIVE
    accuracy = compare_runs(result, check,
                            rtol=run.rtol if adaptive else math.nan,
                            atol=run.atol if adaptive else math.nan,
                            check_rtol=tighter.get("rtol", math.nan),
                            check_atol=tighter.get("atol", math.nan))
    return result.with_accuracy(accuracy)
