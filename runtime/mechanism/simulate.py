"""Simulate a mechanism: the compiled BDF with located impacts, outputs, the ideal mechanism.

The run is the serial arms' integrator (:mod:`jointplay.sim.native`, driver.c) on the
mechanism's model: the gaps of the cut clearance joints and the driver's power come from the
model's own functions, every contact onset and separation is located on the dense output and
each contact phase's peak force and deepest penetration are located too. The start is the
ideal mechanism's state at t = 0 (loops closed with every journal centred, velocities
consistent), found by Newton's method on the loop-closure equations.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from types import SimpleNamespace
from typing import Any, cast

import numpy as np

from jointplay.common.errors import DescriptionError, SimulationError
from jointplay.mechanism.description import MechanismScene
from jointplay.mechanism.model import MechanismModel, model_for
from jointplay.results.records import Impacts
from jointplay.sim.bdf import phase_table
from jointplay.sim.native import NativeIntegrator, raise_for_status

# The state's scale (driver.c integrates x / scale): lengths in radial clearances, their rates
# in clearances per RATE_SCALE_TIME, angles and their rates as they are.
RATE_SCALE_TIME = 1e-3
MAX_EVENTS = 100000
_NEWTON_STEPS = 50


@dataclass
class MechanismResult:
    """A mechanism run's samples and what was located (SI units).

    Attributes
    ----------
    name : str
        The scene's name.
    t : numpy.ndarray
        Output times (s), shape (samples,).
    coordinates : list of str
        The tree coordinates' names, the clock ``t`` last.
    units : list of str
        Each coordinate's unit (m or rad).
    x : numpy.ndarray
        Coordinates then rates, shape (samples, 2 n).
    acceleration : numpy.ndarray
        The coordinates' second derivatives, shape (samples, n).
    cut_joints : list of str
        The cut clearance joints, in the order of the per-joint columns below.
    clearance : numpy.ndarray
        Each cut joint's radial clearance (m).
    eccentricity : numpy.ndarray
        Journal centre minus bearing centre (m), shape (samples, joints, 2).
    normal_force : numpy.ndarray
        Contact normal force (N), shape (samples, joints).
    penetration : numpy.ndarray
        Contact penetration (m), shape (samples, joints).
    driving_torque : numpy.ndarray
        The torque the driver applies to hold its prescribed motion (N m).
    kinetic : numpy.ndarray
        Kinetic energy (J).
    potential : numpy.ndarray
        Gravity's potential energy (J).
    contact_potential : numpy.ndarray
        Energy stored in the contacts' deformation (J).
    drive_work : numpy.ndarray
        The driver's and the applied loads' work since t = 0 (J), integrated in the loop.
    dissipated : numpy.ndarray
        Energy lost to contact damping and friction since t = 0 (J).
    impacts : Impacts
        The located contact phases (onset, peak force, penetration).
    stats : dict
        The integrator's statistics (steps, events, wall time).
    rtol : float
        The relative tolerance the run used.
    atol : float
        The absolute tolerance the run used.
    ideal : dict or None
        The ideal mechanism's coordinates, rates and accelerations at ``t`` (with
        ``compare_ideal``).
    accuracy : object or None
        The accuracy statement (with ``verify``).
    notes : list of str
        What the run says about itself (skipped checks, ...).
    output : str
        The coordinate the summary and the figures follow.
    integrator : str
        ``bdf`` (events and peaks located), or ``rk4`` / ``radau`` at a fixed step (the impact
        table has the onset columns only).
    step : float or None
        The fixed step (s) of ``rk4`` and ``radau``; None for ``bdf``.

    Examples
    --------
    >>> from importlib.resources import files
    >>> import jointplay
    >>> path = files("jointplay.scenes") / "slider_crank.toml"
    >>> scene = jointplay.load_mechanism_scene(path).with_run(t_end=0.004)
    >>> result = jointplay.simulate_mechanism(scene)
    >>> result.output, result.coordinate(result.output).shape == result.t.shape
    ('guide.position', True)
    """

    name: str
    t: np.ndarray
    coordinates: list[str]
    units: list[str]
    x: np.ndarray
    acceleration: np.ndarray
    cut_joints: list[str]
    clearance: np.ndarray
    eccentricity: np.ndarray
    normal_force: np.ndarray
    penetration: np.ndarray
    driving_torque: np.ndarray
    kinetic: np.ndarray
    potential: np.ndarray
    contact_potential: np.ndarray
    drive_work: np.ndarray
    dissipated: np.ndarray
    impacts: Impacts
    stats: dict[str, Any]
    rtol: float
    atol: float
    ideal: dict[str, np.ndarray] | None = None
    accuracy: Any = None
    notes: list[str] = field(default_factory=list)
    # The coordinate the summary and the figures follow (the file's [output], or the rule of
    # jointplay.mechanism.output)
    output: str = ""
    # The integration method and, for rk4 and radau, the fixed step (s)
    integrator: str = "bdf"
    step: float | None = None

    def coordinate(self, name: str) -> np.ndarray:
        return self.x[:, self.coordinates.index(name)]

    def rate(self, name: str) -> np.ndarray:
        return self.x[:, len(self.coordinates) + self.coordinates.index(name)]

    def coordinate_acceleration(self, name: str) -> np.ndarray:
        return self.acceleration[:, self.coordinates.index(name)]

    def contact_statistics(self, since: float = 0.0) -> dict[str, float]:
        """What a run's contact does from ``since`` (s) to its end, every cut joint together:
        the impact count and rate (1/s), the fraction of the time in contact (averaged over
        the clearance joints), the located peak forces' median and largest (N) and the
        approach speeds' median (m/s); NaN where there is no impact. These are what two runs
        past their agreement horizon can be compared by."""
        t_end = float(self.t[-1])
        rows = self.impacts.time >= since
        ends = np.where(np.isfinite(self.impacts.separation_time),
                        self.impacts.separation_time, t_end)
        span = max(t_end - since, np.finfo(float).tiny)
        contact = np.clip(ends, since, t_end) - np.clip(self.impacts.time, since, t_end)
        peaks, speeds = self.impacts.peak_force[rows], self.impacts.speed[rows]
        return {"impacts": float(rows.sum()), "impact_rate": float(rows.sum()) / span,
                "contact_fraction": float(contact.sum()) / span / max(1, len(self.cut_joints)),
                "median_peak_force": float(np.median(peaks)) if peaks.size else np.nan,
                "largest_peak_force": float(np.max(peaks)) if peaks.size else np.nan,
                "median_approach_speed": float(np.median(speeds)) if speeds.size else np.nan}

    def largest_contact_force(self, joint: int) -> tuple[float, float, bool]:
        """Cut joint ``joint``'s (1-based) largest contact force (N), when (s), and whether it
        was located (bdf: the phases' located peaks) or read off the samples (a fixed step
        locates no peaks); (0, NaN, False) without contact."""
        rows = (self.impacts.joint == joint) & np.isfinite(self.impacts.peak_force)
        if rows.any():
            k = int(np.argmax(np.where(rows, self.impacts.peak_force, -np.inf)))
            return float(self.impacts.peak_force[k]), float(self.impacts.peak_force_time[k]), True
        force = self.normal_force[:, joint - 1]
        if not np.any(force > 0):
            return 0.0, float("nan"), False
        k = int(np.argmax(force))
        return float(force[k]), float(self.t[k]), False

    @property
    def energy_residual(self) -> np.ndarray:
        """Total energy change - drive work + dissipated (J): zero up to integration error."""
        total = self.kinetic + self.potential + self.contact_potential
        return total - total[0] - self.drive_work + self.dissipated


def _scale(model: MechanismModel, scene: MechanismScene) -> np.ndarray:
    n = model.n_coordinates
    scale = np.ones(model.n_state)
    clearance = scene.smallest_clearance
    if np.isfinite(clearance):
        for i, unit in enumerate(model.units):
            if unit == "m":
                scale[i] = clearance
                scale[n + i] = clearance / RATE_SCALE_TIME
    return scale


def assembled_state(model: MechanismModel, p: np.ndarray, t0: float = 0.0,
                    start: dict[str, float] | None = None) -> np.ndarray:
    """The ideal mechanism's state at t0: every cut joint's eccentricity and its rate zero.

    Damped Newton on the closure equations from the free coordinates at ``start`` (the
    scene's ``[initial]`` table: which assembly, where a loop has two; 0 for the others),
    least squares where the loops leave freedom (the smallest change)."""
    n = model.n_coordinates
    x = np.zeros(2 * n)
    x[n - 1], x[2 * n - 1] = t0, 1.0
    for name, value in (start or {}).items():
        x[model.coordinates.index(name)] = value
    if not model.clearance_joints:
        return x
    closure = model.function("closure")
    free = slice(0, n - 1)
    residual = np.linalg.norm(closure(x, p)[0])
    for _ in range(_NEWTON_STEPS):
        e, e_q, _, _ = closure(x, p)
        step = np.linalg.lstsq(e_q, -e, rcond=None)[0]
        base = x[free].copy()
        for fraction in (1.0, 0.5, 0.25, 0.125, 0.0625):  # a step that does not lower |e|
            x[free] = base + fraction * step                  # is shortened
            trial = np.linalg.norm(closure(x, p)[0])
            if trial < residual or fraction == 0.0625:
                break
        residual = trial
        if np.max(np.abs(step)) < 1e-15 * (1.0 + np.max(np.abs(x[free]))):
            break
    e, e_q, e_theta, _ = closure(x, p)
    if np.max(np.abs(e)) > 1e-12:
        raise DescriptionError("mechanism.joints", f"the loops do not close at t = {t0:g}: "
                               f"a journal stays {np.max(np.abs(e)):.3g} m from its bearing's "
                               "centre after Newton's method from "
                               + (", ".join(f"{k} = {v:g}" for k, v in start.items())
                                  if start else "every coordinate at 0")
                               + "; check the joints' points and the bodies' lengths, or "
                               "give the coordinates' starting values in an [initial] table "
                               "(e.g. a rocker's angle near its assembled value)")
    rate = model.function("outputs")(x, np.zeros(model.n_loads), p,
                                     np.zeros(len(model.clearance_joints)))[1][0]
    x[n:2 * n - 1] = np.linalg.lstsq(e_q, -e_theta * rate, rcond=None)[0]
    return x


def simulate_mechanism(scene: MechanismScene, *, model: MechanismModel | None = None,
                       compare_ideal: bool = False) -> MechanismResult:
    """Run a mechanism scene (see :class:`MechanismResult`)."""
    model = model or model_for(scene.mechanism)
    p = model.parameter_vector(scene.mechanism)
    run = scene.run
    x0 = assembled_state(model, p, start=scene.initial)
    loads = load_functions(scene)
    clearance = np.array([next(j.radial_clearance for j in scene.mechanism.joints
                               if j.name == name) for name in model.cut_joint_names])
    t = np.arange(run.n_outputs + 1) * run.output_step
    started = time.perf_counter()
    if run.integrator == "bdf":
        x, v_imp, work, dissipated, impacts, counts = _run_bdf(model, scene, p, x0, loads,
                                                               clearance, t)
    else:
        from jointplay.mechanism.fixed import run_fixed

        x, v_imp, work, dissipated, impacts, counts = run_fixed(
            model, scene, p, x0, _scale(model, scene), loads)
    wall = time.perf_counter() - started
    tau = load_values(loads, t)
    samples = _samples(model, p, x, v_imp, tau)
    _check_penetration(scene, model, impacts, t, samples["penetration"])
    fixed = run.integrator != "bdf"
    result = MechanismResult(
        name=scene.name, t=t, coordinates=list(model.coordinates), units=list(model.units),
        x=x, cut_joints=list(model.cut_joint_names), clearance=clearance, drive_work=work,
        dissipated=dissipated, impacts=impacts, stats={"wall_time_s": wall, **counts},
        rtol=run.rtol, atol=run.atol, output=scene.output_coordinate,
        integrator=run.integrator, step=run.step if fixed else None,
        **cast(dict[str, Any], samples))
    if compare_ideal:
        result.ideal = ideal_motion(model, p, t, scene.initial, tau, guess=x)
    return result


def _run_bdf(model: MechanismModel, scene: MechanismScene, p: np.ndarray, x0: np.ndarray,
             loads: tuple[Any, ...], clearance: np.ndarray, t: np.ndarray
             ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, Impacts, dict[str, int]]:
    """The compiled BDF (driver.c) with every onset, separation and peak located."""
    run = scene.run
    nc = len(model.clearance_joints)
    integ = NativeIntegrator(model, p, _scale(model, scene), np.zeros((nc, 2), np.int32),
                             clearance, np.zeros(0, np.int32), loads, rtol=run.rtol,
                             atol=run.atol, max_steps=run.max_steps, max_events=MAX_EVENTS,
                             model_gaps=True)
    integ.reset(x0)
    _, v_first = integ.flags()
    values, v_out, status = integ.integrate(float(t[-1]), t[1:])
    if status:
        raise_for_status(status, integ, list(model.structure.load_inputs), lambda: None)
    nx = model.n_state
    x = np.vstack([x0, values[:, :nx]])
    v_imp = np.vstack([v_first, v_out]) if nc else np.zeros((len(t), 0))
    work = np.concatenate([[0.0], values[:, nx]])
    per_joint = values[:, nx + 1:nx + 1 + 3 * nc].reshape(len(t) - 1, nc, 3)
    dissipated = np.concatenate([[0.0], per_joint[:, :, 1:].sum(axis=(1, 2))])
    rows = integ.phases()
    final = integ.current()
    for r in np.flatnonzero(~np.isfinite(rows[:, 9])):  # phases open at the end
        rows[r, 11:14] += final[nx + 1 + 3 * int(rows[r, 0]):nx + 4 + 3 * int(rows[r, 0])]
    impacts = phase_table(cast(Any, SimpleNamespace(model=model)), rows, float(t[-1]))
    return x, v_imp, work, dissipated, impacts, integ.stats()


def _check_penetration(scene: MechanismScene, model: MechanismModel, impacts: Impacts,
                       t: np.ndarray, penetration: np.ndarray) -> None:
    """Stop (SimulationError) where a journal went further into its bearing than the contact
    laws describe (:data:`jointplay.common.limits.MAX_PENETRATION_FRACTION` of its radius),
    by each contact phase's located deepest point (the samples' ``penetration`` at a fixed
    step, which locates no peaks): a state no metal joint survives, reached only from an
    impossible input."""
    from jointplay.common.limits import MAX_PENETRATION_FRACTION

    joints = {j.name: j for j in scene.mechanism.joints}
    for k, name in enumerate(model.cut_joint_names):
        limit = MAX_PENETRATION_FRACTION * joints[name].clearance["journal_radius"]
        deep = np.flatnonzero(penetration[:, k] > limit)
        if deep.size and not np.any(impacts.max_penetration[impacts.joint == k + 1] > limit):
            raise SimulationError(float(t[deep[0]]), f"the journal of {name} is "
                                  f"{penetration[deep[0], k]:.3g} m into its bearing here, "
                                  f"beyond {MAX_PENETRATION_FRACTION:g} of its radius that "
                                  "the contact laws describe; check the masses, speeds and "
                                  "materials, or shorten run.step")
        rows = np.flatnonzero((impacts.joint == k + 1) & (impacts.max_penetration > limit))
        if rows.size:
            first = rows[np.argmin(impacts.time[rows])]
            at = float(impacts.time[first])
            raise SimulationError(at, f"in the contact of {name} that begins here, its journal "
                                  f"goes {impacts.max_penetration[first]:.3g} m into its "
                                  f"bearing (deepest at t = "
                                  f"{impacts.max_penetration_time[first]:.6g} s), beyond "
                                  f"{MAX_PENETRATION_FRACTION:g} of its radius that the "
                                  "contact laws describe; check the masses, speeds and "
                                  "materials")


def load_functions(scene: MechanismScene) -> tuple[Any, ...]:
    """The applied loads' expressions of t, parsed, in the order of the model's input."""
    from jointplay.scene.expressions import parse_expression

    return tuple(parse_expression(text, field="mechanism loads")
                 for text in scene.mechanism.load_expressions())


def load_values(loads: tuple[Any, ...], t: np.ndarray) -> np.ndarray:
    """The loads at times t: (len(t), loads)."""
    if not loads:
        return np.zeros((len(t), 0))
    return np.stack([np.asarray(f.numpy(t), dtype=float) for f in loads], axis=1)


def _samples(model: MechanismModel, p: np.ndarray, x: np.ndarray, v_imp: np.ndarray,
             tau: np.ndarray) -> dict[str, np.ndarray]:
    """The outputs at every sample, each function evaluated over all samples in one C loop."""
    from jointplay.sim.native import map_function

    rows = len(x)
    nc = len(model.clearance_joints)
    torque, _, kinetic, potential, contact_pot, acc, _ = map_function(
        model, "outputs", [x, tau, p, v_imp], rows)
    out = {"acceleration": acc, "driving_torque": torque[:, 0], "kinetic": kinetic[:, 0],
           "potential": potential[:, 0], "contact_potential": contact_pot[:, 0],
           "eccentricity": np.zeros((rows, nc, 2)), "normal_force": np.zeros((rows, nc)),
           "penetration": np.zeros((rows, nc))}
    if nc:
        contact = map_function(model, "contact", [x, p, v_imp], rows)
        gaps = map_function(model, "gaps", [x, p], rows)
        out["penetration"], out["normal_force"] = contact[0], contact[3]
        out["eccentricity"] = np.stack([gaps[2], gaps[3]], axis=2)
    return out


def ideal_motion(model: MechanismModel, p: np.ndarray, t: np.ndarray,
                 start: dict[str, float] | None = None, tau: np.ndarray | None = None,
                 guess: np.ndarray | None = None) -> dict[str, np.ndarray]:
    """The ideal mechanism (every clearance joint ideal) at times t, where the driver moves it
    completely: positions by Newton's method on the loop closure, velocities and accelerations
    from its first and second derivatives, the driving torque from the principle with the
    joints' constraint forces. Refuses (DescriptionError) a mechanism that keeps freedom.

    With ``guess`` (states at t: the clearance run's, within its clearances of the ideal
    motion, on its assembly), every sample is solved at once from it; else, or where that does
    not converge, sample by sample, each from the last."""
    n = model.n_coordinates
    ncons = 2 * len(model.clearance_joints)
    if ncons != n - 1:
        raise DescriptionError("--compare-ideal", f"the ideal mechanism keeps {n - 1 - ncons} "
                               "degrees of freedom the driver does not fix (or its loops "
                               "over-constrain it); --compare-ideal supports mechanisms the "
                               "driver moves completely once their clearance joints are "
                               "ideal")
    if guess is not None:
        found = _ideal_from_guess(model, p, t, guess, tau)
        if found is not None:
            return found
    closure, residual = model.function("closure"), model.function("ideal_residual")
    outputs = model.function("outputs")
    zeros = np.zeros(len(model.clearance_joints))
    x = np.zeros((len(t), 2 * n))
    acc = np.zeros((len(t), n))
    torque = np.zeros(len(t))
    state = assembled_state(model, p, float(t[0]), start)
    for k, tk in enumerate(t):
        state[n - 1] = tk
        for _ in range(_NEWTON_STEPS):  # from the last sample's positions
            e, e_q, _, _ = closure(state, p)
            step = np.linalg.solve(e_q, -e)
            state[:n - 1] += step
            if np.max(np.abs(step)) < 1e-14 * (1.0 + np.max(np.abs(state[:n - 1]))):
                break
        e, e_q, e_theta, _ = closure(state, p)
        if np.max(np.abs(e)) > 1e-10:
            raise SimulationError(float(tk), "the ideal mechanism cannot be assembled here (a "
                                  "loop that cannot close, or a dead point of the loop)")
        loads = tau[k] if tau is not None else np.zeros(model.n_loads)
        rate = outputs(state, loads, p, zeros)[1][0]
        state[n:2 * n - 1] = np.linalg.solve(e_q, -e_theta * rate)
        _, _, _, gamma = closure(state, p)
        a = np.zeros(n)
        a[:n - 1] = np.linalg.solve(e_q, -gamma)
        r = residual(state, a, loads, p)[0]
        # Constraint forces lam (on the journals) balance the tree's rows: R_q = e_q^T lam;
        # the driver supplies the rest of its row: tau = R_theta - e_theta . lam.
        lam = np.linalg.solve(e_q.T, r[:n - 1])
        torque[k] = r[n - 1] - e_theta @ lam
        x[k], acc[k] = state, a
    return {"x": x, "acceleration": acc, "driving_torque": torque}


def _dense_rows(function: Any, index: int, values: np.ndarray) -> np.ndarray:
    """Rows of a mapped output's nonzeros as dense (rows, n_rows, n_cols) arrays."""
    sparsity = function.sparsity_out(index)
    rows, cols = sparsity.get_triplet()
    out = np.zeros((values.shape[0], sparsity.size1(), sparsity.size2()))
    out[:, np.asarray(rows, int), np.asarray(cols, int)] = values
    return out


def _ideal_from_guess(model: MechanismModel, p: np.ndarray, t: np.ndarray, guess: np.ndarray,
                      tau: np.ndarray | None) -> dict[str, np.ndarray] | None:
    """:func:`ideal_motion` for every sample at once (Newton from ``guess``, each function
    mapped over the samples in one C loop); None where a sample does not converge."""
    from jointplay.sim.native import map_function

    count, n = len(t), model.n_coordinates
    m = n - 1
    closure = model.function("closure").function
    loads = tau if tau is not None else np.zeros((count, model.n_loads))
    x = np.zeros((count, 2 * n))
    x[:, :m], x[:, n - 1], x[:, 2 * n - 1] = guess[:, :m], t, 1.0

    def closure_at(x: np.ndarray) -> tuple[np.ndarray, ...]:
        values = map_function(model, "closure", [x, p], count)
        return tuple(_dense_rows(closure, i, v) for i, v in enumerate(values))

    for _ in range(_NEWTON_STEPS):
        e, e_q, _, _ = closure_at(x)
        step = np.linalg.solve(e_q, -e)[..., 0]
        x[:, :m] += step
        if np.max(np.abs(step)) < 1e-14 * (1.0 + np.max(np.abs(x[:, :m]))):
            break
    e, e_q, e_theta, _ = closure_at(x)
    if not np.all(np.isfinite(e)) or np.max(np.abs(e)) > 1e-10:
        return None
    zeros = np.zeros(len(model.clearance_joints))
    rate = map_function(model, "outputs", [x, loads, p, zeros], count)[1][:, 0]
    x[:, n:2 * n - 1] = np.linalg.solve(e_q, -e_theta * rate[:, None, None])[..., 0]
    gamma = closure_at(x)[3]
    acc = np.zeros((count, n))
    acc[:, :m] = np.linalg.solve(e_q, -gamma)[..., 0]
    residual = map_function(model, "ideal_residual", [x, acc, loads, p], count)[0]
    lam = np.linalg.solve(np.transpose(e_q, (0, 2, 1)), residual[:, :m, None])
    torque = residual[:, m] - np.sum(e_theta * lam, axis=(1, 2))
    return {"x": x, "acceleration": acc, "driving_torque": torque}
