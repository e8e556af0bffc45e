"""The scene's robot advanced one sample at a time (:class:`Stepper`), for closed-loop control
and identification: the same integrators and contact events as
:func:`jointplay.sim.simulate`."""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np

from jointplay.scene.definition import ADAPTIVE, Scene
from jointplay.sim.assemble import _mapped
from jointplay.sim.bdf import native_integrator, torque_fields
from jointplay.sim.casadi_methods import _AdaptiveIntegrator, _resolve_interval
from jointplay.sim.events import _EventState
from jointplay.sim.native import raise_for_status
from jointplay.sim.problem import (
    _Accumulated,
    _initial_state,
    _nearest_contact_joint,
    _parameter_vector,
    _Problem,
    _Trajectory,
    load_scene_model,
)
from jointplay.store.model import Model


class Stepper:
    """The scene's robot advanced one sample at a time, with torques added and held (ZOH).

    For closed-loop control and identification: :meth:`step` integrates one sample period with
    the scene's own torques plus ``u`` held constant, through contact events exactly as
    :func:`simulate` does (adaptive integrators only), and returns the new state. With the
    default ``bdf`` the integrator object lives in C across samples; a change of ``u`` restarts
    its history (the right-hand side jumps there).

    Parameters
    ----------
    scene : Scene
        The robot and its scene; its integrator must be adaptive (``bdf``, ``cvodes``, ``idas``
        or ``radau``).
    model : Model, optional
        The compiled model (default: :func:`load_scene_model` of ``scene``).
    parameters : mapping of str to float, or sequence of float, optional
        Numbers overridden by name, or the whole parameter vector, as for :func:`simulate`.
    sample_time : float, optional
        The period of one :meth:`step`, s (default: the scene's ``run.output_step``).
    substeps : int, default 1
        More than 1 (``bdf`` only) also records the state at that many evenly spaced points of
        every sample period (the integrator's own interpolant, the last one the sample itself),
        for quantities that must be known between samples: :meth:`dense_tip_acceleration`.

    Attributes
    ----------
    t : float
        The current time, s.
    x : numpy.ndarray
        The current state: the coordinates, then their rates.
    model : Model
        The compiled model being run.
    scene : Scene
        The scene.
    sample_time : float
        The period of one step, s.
    substeps : int
        The points recorded per sample period.
    stats : object
        The solver's statistics, accumulated over the steps.

    Raises
    ------
    ValueError
        When the integrator is a fixed-step one, or ``substeps`` > 1 without ``bdf``.

    Examples
    --------
    >>> import jointplay
    >>> stepper = jointplay.Stepper(jointplay.default_scene())
    >>> for _ in range(10):  # 10 ms with 0.1 N m added at joint 2, none at joint 3
    ...     x = stepper.step([0.1, 0.0])
    >>> round(stepper.t, 6), x.shape
    (0.01, (12,))
    """

    def __init__(self, scene: Scene, *, model: Model | None = None,
                 parameters: Mapping[str, float] | Sequence[float] | None = None,
                 sample_time: float | None = None, substeps: int = 1) -> None:
        from jointplay.sim import _refuse_mechanism

        _refuse_mechanism(scene, "Stepper")
        run = scene.run
        if run.integrator not in ADAPTIVE:
            raise ValueError(f"Stepper needs an adaptive integrator ({', '.join(ADAPTIVE)}), "
                             f"got {run.integrator!r}")
        if substeps < 1 or (substeps > 1 and run.integrator != "bdf"):
            raise ValueError(f"substeps must be 1, or more with the bdf integrator; got "
                             f"{substeps} with {run.integrator!r}")
        self.substeps = int(substeps)
        self.model = model or load_scene_model(scene)
        self.scene = scene
        self._pr = _Problem(self.model, scene, _parameter_vector(self.model, scene, parameters))
        self._native = run.integrator == "bdf"
        if self._native:
            self._bdf = native_integrator(self._pr)
        else:
            self._integ = _AdaptiveIntegrator(self._pr, run.integrator, run.rtol, run.atol,
                                              run.max_steps)
        self.sample_time = float(sample_time or run.output_step)
        self.stats = _Accumulated()
        self.reset()

    @property
    def parameters(self) -> np.ndarray:
        return self._pr.p

    def reset(self, x0: np.ndarray | None = None) -> None:
        """Back to t = 0 at ``x0`` (default: the scene's initial state)."""
        self.t = 0.0
        self.x = (np.asarray(x0, dtype=float).copy() if x0 is not None
                  else _initial_state(self.model, self.scene, self._pr.p))
        self.impacts: list[tuple[float, int, float, float, float]] = []
        self._dense: list[tuple[np.ndarray, ...]] = []  # (t, x, v_imp, tau) per sample
        self.work = 0.0
        self.dissipated = 0.0
        # (state, drive work, dissipated energy) at every sample, for energy_balance()
        self._samples: list[tuple[np.ndarray, float, float]] = [(self.x.copy(), 0.0, 0.0)]
        if self._native:
            self._bdf.reset(self.x)
            self._bdf.hold(np.full(len(self.model.torque_joints), np.nan))  # force a start
            self._seen_phases = 0
            self._v_imp = self._bdf.flags()[1]
        else:
            self._events = _EventState(self._pr, self.x, 0.0, self.impacts)

    def step(self, u: Sequence[float] | np.ndarray) -> np.ndarray:
        """Advance one sample with the added torques ``u`` (one per driven joint, N m)."""
        pr = self._pr
        pr.u_hold[:] = np.asarray(u, dtype=float)
        if self._native:
            x = self._step_native()
            self._samples.append((x.copy(), self.work, self.dissipated))
            return x
        traj = _Trajectory(x=np.zeros((2, pr.nx)), v_imp=np.zeros((2, pr.nc)),
                           work=np.array([self.work, 0.0]),
                           dissipated=np.array([self.dissipated, 0.0]), impacts=self.impacts)
        self.x = _resolve_interval(self._integ, pr, self.x, self.t, self.sample_time,
                                   self._events, traj, 0, self.stats)
        self.t += self.sample_time
        self.work, self.dissipated = float(traj.work[1]), float(traj.dissipated[1])
        self._samples.append((self.x.copy(), self.work, self.dissipated))
        return self.x

    def energy_balance(self) -> np.ndarray:
        """The energy balance at every sample so far, from t = 0 (J; 0 when exact): energy
        gained less the work of every torque applied (the scene's and the added ones) plus
        the energy dissipated, as ``result.energy["balance"]`` of :func:`simulate`."""
        xs = np.array([s[0] for s in self._samples]).T
        ps = np.repeat(self._pr.p[:, None], xs.shape[1], axis=1)
        total = _mapped(self.model, "energy", [xs, ps])[3].ravel()
        work = np.array([s[1] for s in self._samples])
        dissipated = np.array([s[2] for s in self._samples])
        return np.asarray(total - total[0] - work + dissipated)

    def _step_native(self) -> np.ndarray:
        pr, integ = self._pr, self._bdf
        integ.hold(pr.u_hold)
        t_next = self.t + self.sample_time
        times = self.t + self.sample_time * np.arange(1, self.substeps + 1) / self.substeps
        times[-1] = t_next
        values, speeds, status = integ.integrate(t_next, times)
        if status:
            raise_for_status(status, integ, torque_fields(pr),
                             lambda: _nearest_contact_joint(pr, self.x, self._v_imp))
        if self.substeps > 1:
            self._dense.append((times, values[:, :pr.nx].copy(), speeds.copy(),
                                pr.tau(times)))
        self.t = t_next
        self.x = values[-1, :pr.nx].copy()
        self._v_imp = speeds[-1]
        self.work = float(values[-1, pr.nx])
        if pr.nc:
            self.dissipated = float(values[-1, pr.nx + 1:].reshape(pr.nc, 3)[:, 1:].sum())
        rows = integ.phases()
        for row in rows[self._seen_phases:]:
            joint = int(self.model.clearance_joints[int(row[0])])
            self.impacts.append((float(row[1]), joint, float(row[2]), float(row[3]),
                                 float(row[4])))
        self._seen_phases = rows.shape[0]
        counts = integ.stats()
        self.stats.counts.update({k: counts[k] for k in ("steps", "rhs_evaluations",
                                                         "jacobian_evaluations", "events")})
        self.stats.counts["impacts"] = len(self.impacts)
        return self.x

    def dense_tip_acceleration(self) -> tuple[np.ndarray, np.ndarray]:
        """Times and end-effector accelerations (rows) at every recorded substep so far,
        from the model's dynamics at the interpolated states and the torque held there."""
        if not self._dense:
            return np.zeros(0), np.zeros((0, 2))
        pr = self._pr
        t, x, v, tau = (np.concatenate([d[i] for d in self._dense]) for i in range(4))
        ps = np.repeat(pr.p[:, None], t.size, axis=1)
        xdot = _mapped(self.model, "forward_dynamics", [x.T, tau.T, ps, v.T])[0]
        tip = _mapped(self.model, "end_effector", [x.T, xdot[pr.n:], ps])
        return t, tip[2].T

    def end_effector(self) -> dict[str, np.ndarray]:
        """Tip position, velocity and acceleration at the current state and held torque."""
        pr = self._pr
        v_imp = self._v_imp if self._native else self._events.v_imp
        xdot = self.model.forward_dynamics(self.x, pr.tau(self.t)[0], pr.p, v_imp)
        return self.model.end_effector(self.x, xdot[pr.n:], pr.p)
