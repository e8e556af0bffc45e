"""Section (c) of the peers benchmark (see peers.py): Pinocchio's ABA against jointplay's
ideal-joint right-hand side, per call and inside CVODES through Python callbacks."""

from __future__ import annotations

import functools
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import casadi as ca
import numpy as np
from peers_runs import (
    REFERENCE_RTOL,
    cpu_runs,
    errors,
    initial_state,
    jointplay_sweep,
    spread,
    trajectory_from_states,
)

from jointplay.bench import timed_runs
from jointplay.common.timing import per_call_seconds

# ---- (c): Pinocchio on the ideal-joint robot -------------------------------------------------


def pinocchio_model(robot: Any) -> Any:
    """The ideal robot as a planar RZ chain; locked joints removed by buildReducedModel."""
    import pinocchio as pin

    model = pin.Model()
    parent, offset = 0, 0.0
    for i, link in enumerate(robot.links, start=1):
        jid = model.addJoint(parent, pin.JointModelRZ(),
                             pin.SE3(np.eye(3), np.array([offset, 0.0, 0.0])), f"joint{i}")
        model.addJointFrame(jid)
        inertia = np.diag([link.inertia + 0.5, link.inertia + 0.7, link.inertia])
        model.appendBodyToJoint(jid, pin.Inertia(link.mass, np.array([link.com, 0.0, 0.0]),
                                                 inertia), pin.SE3.Identity())
        parent, offset = jid, link.length
    model.appendBodyToJoint(parent, pin.Inertia(robot.payload_mass,
                                                np.array([offset, 0.0, 0.0]),
                                                np.zeros((3, 3))), pin.SE3.Identity())
    model.gravity.linear = np.array([*robot.gravity.vector, 0.0]) if robot.gravity.enabled \
        else np.zeros(3)
    locked = [i for i, j in enumerate(robot.joints, start=1) if j.kind == "locked"]
    if locked:
        q_ref = np.array([j.angle if j.kind == "locked" else 0.0 for j in robot.joints])
        gravity = model.gravity.linear.copy()
        model = pin.buildReducedModel(model, locked, q_ref)
        model.gravity.linear = gravity
    return model


class _JacobianCallback(ca.Callback):
    """d(rhs)/d(x, tau), called back into Python; the third input (the output) is unused."""

    def __init__(self, name: str, jac: Callable[[np.ndarray, np.ndarray],
                                                tuple[np.ndarray, np.ndarray]],
                 nx: int, ntau: int, opts: Mapping[str, Any]) -> None:
        ca.Callback.__init__(self)
        self._jac_fn, self._nx, self._ntau = jac, nx, ntau
        self.construct(f"jac_{name}", dict(opts))

    def get_n_in(self) -> int:
        return 3

    def get_n_out(self) -> int:
        return 2

    def get_sparsity_in(self, i: int) -> Any:
        return ca.Sparsity.dense([self._nx, self._ntau][i], 1) if i < 2 \
            else ca.Sparsity(self._nx, 1)

    def get_sparsity_out(self, i: int) -> Any:
        return ca.Sparsity.dense(self._nx, [self._nx, self._ntau][i])

    def eval(self, arg: Sequence[Any]) -> list[Any]:
        jx, jt = self._jac_fn(np.asarray(arg[0]).ravel(), np.asarray(arg[1]).ravel())
        return [jx, jt]


class _RhsCallback(ca.Callback):
    """The right-hand side f(x, tau), called back into Python, with its Jacobian; counts its
    calls."""

    def __init__(self, name: str, fn: Callable[[np.ndarray, np.ndarray], np.ndarray],
                 jac: Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]],
                 nx: int, ntau: int) -> None:
        ca.Callback.__init__(self)
        self._name, self._fn, self._jac_fn = name, fn, jac
        self._nx, self._ntau = nx, ntau
        self.calls = 0
        self.construct(name, {})

    def get_n_in(self) -> int:
        return 2

    def get_n_out(self) -> int:
        return 1

    def get_sparsity_in(self, i: int) -> Any:
        return ca.Sparsity.dense([self._nx, self._ntau][i], 1)

    def get_sparsity_out(self, i: int) -> Any:
        return ca.Sparsity.dense(self._nx, 1)

    def eval(self, arg: Sequence[Any]) -> list[Any]:
        self.calls += 1
        return [self._fn(np.asarray(arg[0]).ravel(), np.asarray(arg[1]).ravel())]

    def has_jacobian(self) -> bool:
        return True

    def get_jacobian(self, _name: str, _inames: Any, _onames: Any,
                     opts: Mapping[str, Any]) -> Any:
        # Kept on self: CasADi holds no reference to a Python callback.
        self._jac_callback = _JacobianCallback(self._name, self._jac_fn, self._nx,
                                                self._ntau, opts)
        return self._jac_callback


def _cvodes_callback_run(name: str, fn: Callable[[np.ndarray, np.ndarray], np.ndarray],
                         jac: Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]],
                         scene: Any, x0: np.ndarray, rtol: float) -> tuple[np.ndarray, int]:
    """CVODES over the output grid with the rhs and its Jacobian called back into Python."""
    rhs = _RhsCallback(name, fn, jac, x0.size, len(scene.torques))
    x = ca.MX.sym("x", x0.size)
    t = ca.MX.sym("t")
    tau = ca.vertcat(*[f.casadi(t) for f in scene.torques])
    grid = np.arange(1, scene.run.n_outputs + 1) * scene.run.output_step
    integ = ca.integrator(f"cvodes_{name}", "cvodes", {"x": x, "t": t, "ode": rhs(x, tau)},
                          0.0, grid, {"reltol": rtol, "abstol": rtol,
                                      "max_num_steps": scene.run.max_steps})
    out = integ(x0=x0)
    xs = np.vstack([x0, np.asarray(out["xf"]).T])
    return xs, rhs.calls


@dataclass
class _IdealRhs:
    """The ideal-joint right-hand side and its Jacobian, from jointplay and from Pinocchio,
    each as f(x, tau) and J(x, tau) -> (d/dx, d/dtau)."""

    jp_fd: Callable[[np.ndarray, np.ndarray], np.ndarray]
    jp_jac: Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]]
    pin_fd: Callable[[np.ndarray, np.ndarray], np.ndarray]
    pin_jac: Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]]


def _ideal_rhs(model: Any, pm: Any, data: Any) -> _IdealRhs:
    import pinocchio as pin

    n = model.n_coordinates
    p = model.parameter_vector()
    fd = model.function("forward_dynamics")
    jac = model.function("jac_forward_dynamics")
    fd.inputs[2][:] = p

    def jp_fd(xx: np.ndarray, tt: np.ndarray) -> np.ndarray:
        fd.inputs[0][:] = xx
        fd.inputs[1][:] = tt
        fd.trigger()
        return fd.outputs[0].copy()

    def jp_jac(xx: np.ndarray, tt: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        blocks = jac(xx, tt, p, np.zeros(0), np.zeros(0))
        return blocks[0], blocks[1]

    def pin_fd(xx: np.ndarray, tt: np.ndarray) -> np.ndarray:
        return np.concatenate([xx[n:], pin.aba(pm, data, xx[:n], xx[n:], tt)])

    eye, zeros = np.eye(n), np.zeros((n, n))

    def pin_jac(xx: np.ndarray, tt: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        pin.computeABADerivatives(pm, data, xx[:n], xx[n:], tt)
        minv = np.triu(data.Minv) + np.triu(data.Minv, 1).T
        jx = np.block([[zeros, eye], [data.ddq_dq, data.ddq_dv]])
        return jx, np.vstack([np.zeros((n, n)), minv])

    return _IdealRhs(jp_fd=jp_fd, jp_jac=jp_jac, pin_fd=pin_fd, pin_jac=pin_jac)


def pinocchio_section(scene: Any, repeats: int, rtols: Sequence[float]
                      ) -> tuple[list[dict[str, Any]], dict[str, Any]]:
    from jointplay.scene.definition import ideal_counterpart
    from jointplay.sim import load_scene_model

    ideal_scene = scene.with_robot(ideal_counterpart(scene.robot))
    model = load_scene_model(scene, ideal=True)
    n = model.n_coordinates
    pm = pinocchio_model(ideal_scene.robot)
    data = pm.createData()
    if pm.nq != n:
        raise RuntimeError(f"Pinocchio model has {pm.nq} coordinates, jointplay's {n}")
    rhs = _ideal_rhs(model, pm, data)
    per_call = _ideal_per_call(model, pm, data, rhs)
    return _ideal_callback_rows(ideal_scene, model, rhs, repeats, rtols), per_call


def _ideal_per_call(model: Any, pm: Any, data: Any, rhs: _IdealRhs) -> dict[str, Any]:
    """Per call: pin.aba against jointplay's forward dynamics, and both Jacobians; how far
    they agree at a random state."""
    import pinocchio as pin

    n = model.n_coordinates
    p = model.parameter_vector()
    fd = model.function("forward_dynamics")
    jac = model.function("jac_forward_dynamics")
    rng = np.random.default_rng(7)
    x = rng.uniform(-1.0, 1.0, 2 * n)
    tau = rng.uniform(-2.0, 2.0, n)
    check = np.max(np.abs(model.forward_dynamics(x, tau, p)[n:]
                          - np.asarray(pin.aba(pm, data, x[:n], x[n:], tau))))
    jp_check = np.max(np.abs(rhs.jp_jac(x, tau)[0] - rhs.pin_jac(x, tau)[0]))

    q_arr, v_arr, t_arr = x[:n].copy(), x[n:].copy(), tau.copy()
    fd.inputs[0][:] = x
    fd.inputs[1][:] = tau
    fd.inputs[2][:] = p
    per_call = {
        "pin_aba_us": per_call_seconds(lambda: pin.aba(pm, data, q_arr, v_arr, t_arr)) * 1e6,
        "jp_trigger_us": per_call_seconds(fd.trigger) * 1e6,
        "jp_in_trigger_out_us": per_call_seconds(lambda: rhs.jp_fd(x, tau)) * 1e6,
        "jp_call_us": per_call_seconds(lambda: fd(x, tau, p, np.zeros(0))) * 1e6,
        "pin_aba_derivatives_us": per_call_seconds(
            lambda: pin.computeABADerivatives(pm, data, q_arr, v_arr, t_arr)) * 1e6,
        "jp_jacobian_us": per_call_seconds(jac.trigger) * 1e6,
        "max_abs_diff_aba": float(check),
        "max_abs_diff_jacobian": float(jp_check),
    }
    per_call["ratio"] = per_call["jp_in_trigger_out_us"] / per_call["pin_aba_us"]
    return per_call


def _ideal_callback_rows(ideal_scene: Any, model: Any, rhs: _IdealRhs, repeats: int,
                         rtols: Sequence[float]) -> list[dict[str, Any]]:
    """CVODES with each right-hand side called back into Python, and jointplay's simulate,
    at each tolerance, against the ideal scene's tight reference."""
    p = model.parameter_vector()
    tight = timed_runs(ideal_scene.with_run(integrator="cvodes", rtol=REFERENCE_RTOL,
                                            atol=REFERENCE_RTOL), model, 1)
    reference = tight.result
    assert reference is not None, tight.failure
    x0 = initial_state(model, ideal_scene)
    grid = reference.t
    rows = []
    for rtol in rtols:
        for label, fn, jfn in (("Pinocchio ABA, CVODES via Python callback", rhs.pin_fd,
                                rhs.pin_jac),
                               ("jointplay rhs, CVODES via Python callback", rhs.jp_fd,
                                rhs.jp_jac)):
            (xs, calls), cpu = cpu_runs(functools.partial(
                _cvodes_callback_run, label.split()[0].lower(), fn, jfn, ideal_scene, x0, rtol),
                repeats)
            taus = np.array([[float(f.numpy(t)) for f in ideal_scene.torques] for t in grid])
            xdots = np.array([fn(xs[i], taus[i]) for i in range(grid.size)])
            traj = trajectory_from_states(model, p, grid, xs, xdots, np.zeros(0))
            rows.append({"code": label, "rtol": rtol, "t_end": ideal_scene.run.t_end,
                         "status": "ok", **spread(cpu), **errors(traj, reference),
                         "rhs_evaluations": calls})
        rows += jointplay_sweep(ideal_scene, model, reference, [rtol], repeats,
                                label="jointplay simulate (compiled, no callback)")
    return rows
