"""A mechanism at a fixed step: RK4 or Radau IIA (``run.integrator``), the serial arms' loop.

The steps are the generated ``rk4_step`` / ``radau_step`` of the mechanism's own library
(:mod:`jointplay.derive.fixed_step`, emitted beside its dynamics); blocks of them, the
contact onsets located by interpolating the penetration between step ends and the step
redone with the captured approach speed, are :mod:`jointplay.sim.fixed`'s. What a mechanism
adds is where the loop reads its model: the drive's power from the model's ``drive_power``
(the driver's torque times its rate, and the applied loads'), the eccentricity from its
``gaps``. The phases' peaks are not located at a fixed step: the impact table has the onset
columns only, as for the arms.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from jointplay.common.errors import SimulationError
from jointplay.mechanism.description import MechanismScene
from jointplay.mechanism.model import MechanismModel
from jointplay.results.records import Impacts
from jointplay.sim.assemble import _onsets
from jointplay.sim.fixed import _run_fixed
from jointplay.sim.problem import _Accumulated, _Trajectory


class MechanismFixedProblem:
    """What :func:`jointplay.sim.fixed._run_fixed` reads of a problem, for a mechanism."""

    adaptive_fallback = "bdf"

    def __init__(self, model: MechanismModel, scene: MechanismScene, p: np.ndarray,
                 scale: np.ndarray, loads: tuple[Any, ...]) -> None:
        self.model = model
        self.scene = scene
        self.p = p
        self.n = model.n_coordinates
        self.nx = model.n_state
        self.nc = len(model.clearance_joints)
        self.scale = scale
        self._loads = loads
        self._contact = model.function("contact") if self.nc else None
        self._gaps = model.function("gaps") if self.nc else None
        self._power = model.function("drive_power")

    def tau(self, t: np.ndarray | float) -> np.ndarray:
        """The applied loads at times t: shape (len(t), loads)."""
        from jointplay.mechanism.simulate import load_values

        return load_values(self._loads, np.atleast_1d(np.asarray(t, dtype=float)))

    def contact_at(self, x: np.ndarray, v_imp: np.ndarray) -> dict[str, np.ndarray]:
        assert self._contact is not None
        out = self._contact(x, self.p, v_imp)
        return dict(zip(self._contact.function.name_out(), out, strict=True))

    def eccentricity_at(self, x: np.ndarray, i: int) -> tuple[float, float]:
        assert self._gaps is not None
        _, _, ex, ey = self._gaps(x, self.p)
        return float(np.ravel(ex)[i]), float(np.ravel(ey)[i])

    def drive_power_casadi(self, x: Any, tau: Any, p: Any, v_imp: Any) -> Any:
        return self.model.casadi_function("drive_power")(x, tau, p, v_imp)

    def drive_power_at(self, x: np.ndarray, tau: np.ndarray, v_imp: np.ndarray) -> float:
        return float(np.ravel(self._power(x, tau, self.p, v_imp))[0])


class _Progress:
    """The fixed-step loop reports each output sample; a mechanism run shows no bar."""

    def update(self, count: int) -> None:
        del count


def run_fixed(model: MechanismModel, scene: MechanismScene, p: np.ndarray, x0: np.ndarray,
              scale: np.ndarray, loads: tuple[Any, ...]
              ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, Impacts, dict[str, int]]:
    """The states, captured impact speeds, drive work and dissipated energy at the output
    samples, the onsets and the loop's counts (SimulationError where a step fails)."""
    run = scene.run
    pr = MechanismFixedProblem(model, scene, p, scale, loads)
    rows = run.n_outputs + 1
    traj = _Trajectory(x=np.zeros((rows, model.n_state)), v_imp=np.zeros((rows, pr.nc)),
                       work=np.zeros(rows), dissipated=np.zeros(rows))
    stats = _Accumulated()
    try:
        _run_fixed(pr, x0, traj, stats, _Progress())  # type: ignore[arg-type]
    except SimulationError as err:
        if err.joint is None:
            raise
        # The loop numbers the clearance joints; a mechanism's reader knows them by name.
        name = model.cut_joint_names[model.clearance_joints.index(err.joint)]
        raise SimulationError(err.time, f"{err.cause} (the contact of {name})") from None
    impacts = _onsets(traj)
    return (traj.x, traj.v_imp, traj.work, traj.dissipated, impacts,
            {**stats.counts, "impacts": len(impacts)})


__all__ = ["MechanismFixedProblem", "run_fixed"]
