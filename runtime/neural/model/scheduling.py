"""Scheduling signals: what the deviation dynamics of a clearance robot under its inner loop
depend on, known to the controller ahead of time.

The deviations from the ideal robot are micrometres and 1e-4 rad; how they respond to the
added torque changes with the arm's configuration (gravity's and the inertia's direction at
each joint), its speed (Coriolis and centrifugal loads, the journals' sliding) and the load
the drives put on the bearings. A model that sees only the deviations and the added torque
cannot tell these apart; these signals tell it. Per moving joint j:

- ``cos(qj_ref)``, ``sin(qj_ref)``: the ideal robot's joint angle;
- ``dqj_ref``: its joint speed;
- ``tauj_ff``: the drive torque of the motion (the scene's torque, the feedforward).

They are computed from the reference's outputs and the feedforward torque at the sample, in
identification (from the stored runs) and in the controller step (from its ``r`` and
``tau_ff`` inputs), by the same function; over the controller's horizon they are held.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import casadi as ca
import numpy as np


def scheduling_names(joints: Sequence[int]) -> tuple[str, ...]:
    """The scheduling signals' names for the moving joints ``joints``, in order."""
    return (*(f"cos(q{j}_ref)" for j in joints), *(f"sin(q{j}_ref)" for j in joints),
            *(f"dq{j}_ref" for j in joints), *(f"tau{j}_ff" for j in joints))


def _source(name: str, output_names: Sequence[str], input_names: Sequence[str]
            ) -> tuple[str, int]:
    """(what, index): "cos"/"sin"/"r" of the reference output, or "tau" of the feedforward."""
    for kind in ("cos", "sin"):
        if name.startswith(f"{kind}(") and name.endswith("_ref)"):
            return kind, list(output_names).index(name[len(kind) + 1: -len("_ref)")])
    if name.endswith("_ref"):
        return "r", list(output_names).index(name[: -len("_ref")])
    if name.startswith("tau") and name.endswith("_ff"):
        return "tau", list(input_names).index(f"v{name[3: -len('_ff')]}")
    raise ValueError(f"unknown scheduling signal {name!r}")


def scheduling_values(names: Sequence[str], output_names: Sequence[str],
                      input_names: Sequence[str], r: Any, tau_ff: Any) -> Any:
    """The signals ``names`` from the reference's outputs ``r`` and the feedforward
    ``tau_ff``: numpy rows (N, ny) and (N, nu) give (N, len(names)); CasADi columns give a
    column."""
    symbolic = isinstance(r, (ca.SX, ca.MX, ca.DM))
    cols = []
    for name in names:
        kind, i = _source(name, output_names, input_names)
        src = tau_ff if kind == "tau" else r
        x = src[i] if symbolic else np.asarray(src)[..., i]
        if kind == "cos":
            x = ca.cos(x) if symbolic else np.cos(x)
        elif kind == "sin":
            x = ca.sin(x) if symbolic else np.sin(x)
        cols.append(x)
    if symbolic:
        return ca.vertcat(*cols) if cols else ca.DM.zeros(0)
    return np.stack(cols, axis=-1) if cols else np.zeros((*np.shape(r)[:-1], 0))


def trajectory_scheduling(trajectory: Any, output_names: Sequence[str],
                          input_names: Sequence[str]) -> np.ndarray:
    """Every scheduling signal of the moving joints along a stored run (N, 4 nj)."""
    joints = [int(n[1:]) for n in input_names]
    return scheduling_values(scheduling_names(joints), output_names, input_names,
                             trajectory.r, trajectory.tau_base)


__all__ = ["scheduling_names", "scheduling_values", "trajectory_scheduling"]


def with_random_scheduling(model: Any, joints: Sequence[int], rng: np.random.Generator, *,
                           linear_sd: float, random_normalisation: bool = False) -> Any:
    """``model`` (a Narx) extended by the scheduling signals of ``joints`` as further
    regressors with random weights (first layer N(0, 0.3), linear path N(0, ``linear_sd``)):
    a network of the trained one's shape, to exercise and time the controller step with
    scheduling inputs. ``random_normalisation`` also draws their means and scales (else 0
    and 1), so that a check covers the normalisation too."""
    from dataclasses import replace

    names = scheduling_names(joints)
    ns = len(names)
    first = np.hstack([model.weights[0], rng.normal(0, 0.3, (model.weights[0].shape[0], ns))])
    linear = None if model.linear is None else np.hstack(
        [model.linear, rng.normal(0, linear_sd, (model.n_outputs, ns))])
    mean = rng.normal(0, 0.3, ns) if random_normalisation else np.zeros(ns)
    scale = rng.uniform(0.5, 2.0, ns) if random_normalisation else np.ones(ns)
    return replace(model, weights=(first, *model.weights[1:]), linear=linear,
                   regressor_mean=np.concatenate([model.regressor_mean, mean]),
                   regressor_scale=np.concatenate([model.regressor_scale, scale]),
                   scheduling=names)
