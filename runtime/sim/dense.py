"""Dense output of a finished run (``result.sol``), for the adaptive methods.

``bdf`` replays the run in the compiled driver with the asked times added to its outputs:
the driver interpolates outputs on its steps and never steps to them, so the replay takes
the run's own steps (same calls, same bounds) and returns its interpolating polynomials.
``cvodes`` and ``idas`` restart from the last sample before each time and integrate to it
through every contact transition, with the run's tolerances.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from jointplay.results.records import SimulationResult
from jointplay.results.solution import DenseSolution
from jointplay.sim.bdf import PROGRESS_CALLS, _joint_at_failure, native_integrator, torque_fields
from jointplay.sim.casadi_methods import _AdaptiveIntegrator, _resolve_interval
from jointplay.sim.events import _EventState
from jointplay.sim.native import raise_for_status
from jointplay.sim.problem import _Accumulated, _Problem, _Trajectory

Evaluate = Callable[[np.ndarray], np.ndarray]
# Most points read in one call by a restarted cvodes / idas (a power of two: few integrator
# objects are built).
_BLOCK = 256


def attach(result: SimulationResult, pr: _Problem, traj: _Trajectory, x0: np.ndarray
           ) -> SimulationResult:
    """Give ``result`` the dense output of the method that made it (adaptive methods)."""
    run = pr.scene.run
    t = result.t
    if run.integrator == "bdf":
        evaluate = _bdf_replay(pr, x0, t)
        accuracy = ("the compiled BDF's own interpolating polynomial on each of the run's "
                    f"steps: within the run's tolerances (rtol {run.rtol:g}, atol "
                    f"{run.atol:g}, scaled) between samples as at them, and equal to the "
                    "samples at the output times")
    elif run.integrator in ("cvodes", "idas"):
        evaluate = _adaptive_restart(pr, traj, t)
        accuracy = (f"{run.integrator} restarted from the last sample before each time, "
                    f"through every contact event, with the run's tolerances (rtol "
                    f"{run.rtol:g}, atol {run.atol:g}, scaled)")
    else:
        return result
    return result.with_dense_output(DenseSolution(
        float(t[0]), float(t[-1]), pr.nx, evaluate, method=run.integrator, accuracy=accuracy))


def _bdf_replay(pr: _Problem, x0: np.ndarray, t: np.ndarray) -> Evaluate:
    nx = pr.nx
    bounds = np.linspace(0.0, float(t[-1]), PROGRESS_CALLS + 1)[1:]

    def evaluate(times: np.ndarray) -> np.ndarray:
        # The run's own output times ride along: the driver's per-output step limit counts
        # from the last output, so the replay must see the outputs the run saw.
        grid, inverse = np.unique(np.concatenate([t[1:], times[times > t[0]]]),
                                  return_inverse=True)
        integ = native_integrator(pr)
        integ.reset(x0)
        values = np.empty((grid.size, nx))
        done = 0
        for bound in bounds:
            upto = int(np.searchsorted(grid, bound, side="right"))
            out, _, status = integ.integrate(float(bound), grid[done:upto])
            if status:
                raise_for_status(status, integ, torque_fields(pr),
                                 lambda: _joint_at_failure(pr, integ))
            values[done:upto] = out[:, :nx]
            done = upto
        result = np.empty((times.size, nx))
        later = times > t[0]
        result[~later] = x0
        result[later] = values[inverse[t.size - 1:]]
        return result

    return evaluate


def _adaptive_restart(pr: _Problem, traj: _Trajectory, t: np.ndarray) -> Evaluate:
    run = pr.scene.run
    states, speeds = traj.x.copy(), traj.v_imp.copy()
    made: list[_AdaptiveIntegrator] = []  # built on first use: most results never call sol

    def restart(k: int) -> _EventState:
        """The contact state at sample k: its captured speeds, flags from its penetration."""
        events = _EventState.__new__(_EventState)
        events.pr, events.impacts = pr, []
        events.v_imp = speeds[k].copy()
        events.flags = np.zeros(pr.nc)
        if pr.nc:
            events.flags[:] = pr.contact_at(states[k], events.v_imp)["delta"] > 0
        return events

    def evaluate(times: np.ndarray) -> np.ndarray:
        if not made:
            made.append(_AdaptiveIntegrator(pr, run.integrator, run.rtol, run.atol,
                                            run.max_steps))
        integ = made[0]
        out = np.empty((times.size, pr.nx))
        stats = _Accumulated()
        index = np.minimum(np.searchsorted(t, times, side="right") - 1, t.size - 1)
        for k in np.unique(index):
            rows = np.flatnonzero(index == k)
            at = times[rows]
            on_sample = at == t[k]
            out[rows[on_sample]] = states[k]
            rows, at = rows[~on_sample], at[~on_sample]
            if not rows.size:
                continue
            events = restart(int(k))
            x, t_cur = states[k], float(t[k])
            spacing = float(at[0] - t_cur)
            equal = bool(np.allclose(np.diff(at, prepend=t_cur), spacing, rtol=0.0,
                                     atol=1e-12 * max(float(t[-1]), 1.0)))
            i = 0
            while i < rows.size:
                if equal:
                    # Equally spaced: a block of points in one call, kept up to the first
                    # point whose stretch holds a contact change (as the run itself does).
                    # The whole interval at once (one integrator object for every interval
                    # of a grid), what is left after a contact change in powers of two.
                    left = rows.size - i
                    count = left if i == 0 and left <= _BLOCK else \
                        min(_BLOCK, 1 << int(np.log2(left)))
                    xs, qs = integ.run(x, t_cur, count * spacing, count, events.v_imp,
                                       events.flags, stats)
                    hits = (np.flatnonzero(np.any(qs[:, :pr.nc] > 0, axis=1)) if pr.nc
                            else np.zeros(0, int))
                    accept = int(hits[0]) if hits.size else count
                    if accept:
                        out[rows[i:i + accept]] = xs[:accept]
                        x, t_cur = xs[accept - 1], float(at[i + accept - 1])
                        i += accept
                    if accept == count:
                        continue
                # Through the contact change(s) to the next point, located as in the run.
                step = _Trajectory(x=np.zeros((2, pr.nx)), v_imp=np.zeros((2, pr.nc)),
                                   work=np.zeros(2), dissipated=np.zeros(2))
                x = _resolve_interval(integ, pr, x, t_cur, float(at[i]) - t_cur, events,
                                      step, 0, stats)
                t_cur = float(at[i])
                out[rows[i]] = x
                i += 1
        return out

    return evaluate


# Samples of a replay must match the file's to this fraction of each state's largest value.
REPLAY_MATCH = 1e-9


def replay(result: SimulationResult) -> tuple[DenseSolution | None, str]:
    """The dense output of a result read from a file, by running its scene again.

    The file keeps the scene text, the run settings, the parameter vector and the model's
    input hash. Before anything is compiled or run, the settings must pass the limits every
    run passes and give exactly the file's output times (a file claiming ``t_end = 1e5`` over
    50 ms of samples is not run for a day), and the scene's robot must hash to the model that
    made the file. The run is then repeated and used only if every sample matches the file's
    (to ``REPLAY_MATCH`` of each state's scale; a NaN anywhere is a mismatch). Returns the
    solution, or None and why not, in a few words.
    """
    import tomllib

    from jointplay.common.errors import DescriptionError, JointplayError
    from jointplay.scene.definition import ADAPTIVE, scene_from_dict
    from jointplay.sim import load_scene_model, simulate

    meta = result.metadata
    if result.integrator not in ADAPTIVE:
        return None, f"the fixed-step {result.integrator} method has no dense output"
    state = np.hstack([result.q, result.u])
    if state.size == 0 or not np.all(np.isfinite(state)):
        return None, "the file's samples hold NaN or infinite values"
    text = meta.get("scene")
    if not isinstance(text, str) or not text.strip():
        return None, "the file keeps no scene text to run again"
    source = str(meta.get("scene_source") or "") or None
    try:
        data = tomllib.loads(text)
        base = Path(source).parent if source else None
        scene = scene_from_dict(data, source=source or "the results file", base=base,
                                text=text)
        settings = meta.get("run")
        if isinstance(settings, dict):
            scene = scene.with_run(**settings)
    except (tomllib.TOMLDecodeError, DescriptionError, OSError, TypeError,
            ValueError) as err:
        return None, f"its scene cannot be read again ({' '.join(str(err).split())[:200]})"
    why = _settings_disagree(scene.run, result.t)
    if why:
        return None, why
    if _input_hash(scene) != meta.get("model_input_hash"):
        return None, "the model its scene builds now is not the one that made the file"
    model = load_scene_model(scene)
    if len(result.parameters) != len(model.parameters):
        return None, "the file's parameters do not fit the model"
    try:
        again = simulate(scene, model=model, parameters=result.parameters.tolist())
    except JointplayError as err:
        return None, f"running its scene again fails ({str(err).splitlines()[0][:200]})"
    replayed = np.hstack([again.q, again.u])
    if state.shape != replayed.shape:
        return None, "running its scene again gives other output times"
    scale = np.max(np.abs(state), axis=0) + np.finfo(float).tiny
    apart = float(np.max(np.abs(replayed - state) / scale))
    if not apart <= REPLAY_MATCH:  # NaN included
        return None, (f"running its scene again does not reproduce the file (apart by "
                      f"{apart:.2g} of the states' scale)")
    sol = again.sol
    sol.accuracy = (f"its scene run again, every sample matching the file's to {apart:.2g} "
                    f"of the states' scale: {sol.accuracy}")
    return sol, f"dense output of the {sol.method} run, its scene run again"


def _settings_disagree(run: Any, t: np.ndarray) -> str | None:
    """Why the run settings (already checked against the limits) cannot have made the
    output times ``t``, or None: a replay never runs longer than the file's own run."""
    expected = run.n_outputs + 1
    last = float(t[-1]) if t.size else float("nan")
    if t.size != expected or not np.isclose(last, run.t_end, rtol=1e-9, atol=0.0):
        return (f"its settings (t_end = {run.t_end:g} s, output_step = {run.output_step:g} s: "
                f"{expected} samples) do not give the file's {t.size} samples up to "
                f"{last:g} s; not run again")
    return None


def _input_hash(scene: Any) -> str:
    """The input hash of the model the scene's robot needs, found without compiling it."""
    from jointplay.store.formulation import formulation_for
    from jointplay.store.stamp import provenance

    structure = scene.robot.structure()
    return str(provenance(structure.as_dict(), formulation_for(structure))["input_hash"])
