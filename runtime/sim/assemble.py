"""From integrated states to a SimulationResult: every derived quantity, mapped over samples."""

from __future__ import annotations

import functools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from jointplay.results.records import Impacts, SimulationResult
from jointplay.sim.native import map_function
from jointplay.sim.problem import _Problem, _Trajectory
from jointplay.store.model import Model


def _mapped(model: Model, name: str, columns: Sequence[np.ndarray]) -> list[np.ndarray]:
    """Evaluate a compiled function on many samples at once (inputs as columns, outputs as
    (size, samples) like CasADi's map), in one C loop over the samples."""
    count = max(c.shape[1] if c.ndim == 2 else 1 for c in columns)
    rows = [np.ascontiguousarray(c.T) if c.ndim == 2 and c.shape[1] == count and count > 1
            else np.ascontiguousarray(c[:, 0] if c.ndim == 2 else c) for c in columns]
    return [o.T for o in map_function(model, name, rows, count)]


def _assemble(pr: _Problem, traj: _Trajectory, t: np.ndarray, stats: dict[str, Any],
              wall: float, ideal: SimulationResult | None,
              phases: Impacts | None = None) -> SimulationResult:
    model, p, n = pr.model, pr.p, pr.n
    xs = traj.x.T
    tau = pr.tau(t)
    ps = np.repeat(p[:, None], t.size, axis=1)
    vs = traj.v_imp.T
    xdot = _mapped(model, "forward_dynamics", [xs, tau.T, ps, vs])[0]
    udot = xdot[n:].T
    tip = _mapped(model, "end_effector", [xs, udot.T, ps])
    contact = _contact_columns(pr, traj, t, xs, ps, vs)
    if phases is None:  # the Python event loops record onsets only
        phases = _onsets(traj)
    stats = {**stats, "impacts": len(phases), "wall_time_s": wall,
             "realtime_factor": wall / float(t[-1]) if t[-1] > 0 else math.nan}
    return SimulationResult(
        scene_name=pr.scene.name,
        integrator=pr.scene.run.integrator,
        t=t,
        coordinate_names=list(model.coordinates),
        q=traj.x[:, :n].copy(),
        u=traj.x[:, n:].copy(),
        udot=udot,
        tau=tau,
        torque_joints=list(model.torque_joints),
        tip_position=tip[0].T,
        tip_velocity=tip[1].T,
        tip_acceleration=tip[2].T,
        clearance_joints=list(model.clearance_joints),
        radial_clearance=contact.clearance,
        eccentricity=contact.eccentricity,
        penetration=contact.outputs["delta"],
        penetration_rate=contact.outputs["delta_dot"],
        normal_force=contact.outputs["f_n"],
        friction_force=contact.outputs["f_t"],
        contact_force=contact.force,
        sliding_speed=contact.outputs["v_t"],
        impacts=phases,
        energy=_energy(model, traj, xs, ps),
        parameter_names=list(model.parameters),
        parameters=p.copy(),
        stats=stats,
        metadata=_metadata(pr),
        ideal=ideal,
        wear=traj.wear,
    )


def _energy(model: Model, traj: _Trajectory, xs: np.ndarray, ps: np.ndarray
            ) -> dict[str, np.ndarray]:
    """Kinetic, gravity, contact and total energy per sample, the drive work and dissipated
    energy integrated during the run, and the balance that closes them (0 when exact)."""
    energy_parts = _mapped(model, "energy", [xs, ps])
    energy = {name: energy_parts[i].ravel()
              for i, name in enumerate(("kinetic", "gravity", "contact", "total"))}
    energy["drive_work"] = traj.work.copy()
    energy["dissipated"] = traj.dissipated.copy()
    energy["balance"] = energy["total"] - energy["total"][0] - traj.work + traj.dissipated
    return energy


@dataclass(frozen=True)
class _ContactColumns:
    """Per sample and clearance joint: the ``contact`` function's outputs by name, the
    eccentricity (ex, ey), the contact force (f_x, f_y); and each joint's radial clearance."""

    outputs: dict[str, np.ndarray]
    eccentricity: np.ndarray
    clearance: np.ndarray
    force: np.ndarray


def _contact_columns(pr: _Problem, traj: _Trajectory, t: np.ndarray, xs: np.ndarray,
                     ps: np.ndarray, vs: np.ndarray) -> _ContactColumns:
    model, p = pr.model, pr.p
    if not pr.nc:
        zeros = np.zeros((t.size, 0))
        return _ContactColumns(
            outputs={k: zeros for k in ("delta", "delta_dot", "f_n", "f_t", "v_t")},
            eccentricity=np.zeros((t.size, 0, 2)), clearance=np.zeros(0),
            force=np.zeros((t.size, 0, 2)))
    c = _mapped(model, "contact", [xs, ps, vs])
    names = model.casadi_function("contact").name_out()
    get = {name: c[i].T for i, name in enumerate(names)}
    ecc = np.stack([traj.x[:, [model.coordinates.index(f"ex{j}"),
                               model.coordinates.index(f"ey{j}")]]
                    for j in model.clearance_joints], axis=1)
    clearance = np.array([p[model.parameters.index(f"joint{j}.bearing_radius")]
                          - p[model.parameters.index(f"joint{j}.journal_radius")]
                          for j in model.clearance_joints])
    return _ContactColumns(outputs=get, eccentricity=ecc, clearance=clearance,
                           force=np.stack([get["f_x"], get["f_y"]], axis=2))


def _onsets(traj: _Trajectory) -> Impacts:
    """The impact table of a run whose event loop recorded onsets only."""
    rows = traj.impacts
    return Impacts(time=np.array([i[0] for i in rows], float),
                   joint=np.array([i[1] for i in rows], int),
                   speed=np.array([i[2] for i in rows], float),
                   eccentricity=np.array([i[3:] for i in rows], float).reshape(-1, 2))


@functools.cache
def _versions() -> dict[str, str]:
    from importlib.metadata import version

    return {pkg: version(pkg) for pkg in ("jointplay", "casadi", "numpy")}


def _metadata(pr: _Problem) -> dict[str, Any]:

    scene = pr.scene
    return {
        "scene": scene.text,
        "scene_source": scene.source or "",
        "torques": dict(scene.torque_text),
        "run": {k: getattr(scene.run, k) for k in ("t_end", "output_step", "integrator",
                                                    "rtol", "atol", "step", "max_steps",
                                                    "plausibility")},
        "model_input_hash": pr.model.layout.input_hash,
        "model_name": pr.model.name,
        "versions": _versions(),
    }


