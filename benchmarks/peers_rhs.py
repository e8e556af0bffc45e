"""The peers' right-hand sides, all from the same sympy equations (see peers.py): PyDy's
Cython code, sympy.lambdify with numpy, and jointplay's compiled function in the same driver."""

from __future__ import annotations

import math
import time
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

# ---- the shared symbolic equations ---------------------------------------------------------------


@dataclass
class Equations:
    """M(q) du/dt = f(x, tau, p, v_imp) with the contact laws substituted, as sympy."""

    symbolic: Any
    mass_matrix: Any
    forcing: Any
    derive_s: float


def equations(robot: Any) -> Equations:
    from jointplay.derive import derive

    t0 = time.process_time()
    sm = derive(robot.structure())
    binding = {}
    for c in sm.clearance:  # what build_functions binds the placeholders to
        binding[c.force_x] = c.law.force_x
        binding[c.force_y] = c.law.force_y
        binding[c.force_t] = c.law.friction_force
    forcing = sm.forcing.xreplace(binding)
    return Equations(symbolic=sm, mass_matrix=sm.mass_matrix, forcing=forcing,
                     derive_s=time.process_time() - t0)


def parameter_values(eq: Equations, robot: Any) -> dict[Any, float]:
    values = dict(zip(eq.symbolic.parameter_symbols, robot.parameter_values(), strict=True))
    for c in eq.symbolic.clearance:
        values[c.impact_speed] = 0.0
    return values


class _KaneLike:
    """The attributes of a KanesMethod that ``pydy.system.System`` reads."""

    def __init__(self, eq: Equations, forcing: Any) -> None:
        import sympy as sp
        from sympy.physics.mechanics import dynamicsymbols

        t = dynamicsymbols._t
        sm = eq.symbolic
        n = len(sm.q)
        self.q = sp.Matrix(sm.q)
        self.u = sp.Matrix(sm.u)
        self.mass_matrix = eq.mass_matrix
        self.forcing = forcing
        self.mass_matrix_full = sp.diag(sp.eye(n), eq.mass_matrix)
        self.forcing_full = sp.Matrix.vstack(self.u, forcing)
        self._qdot = self.q.diff(t)
        self._udot = self.u.diff(t)
        self._uaux = sp.Matrix()

    def kindiffdict(self) -> dict[Any, Any]:
        from sympy.physics.mechanics import dynamicsymbols

        return {qi.diff(dynamicsymbols._t): ui for qi, ui in zip(self.q, self.u, strict=True)}


def fast_torques(scene: Any) -> Callable[[float], np.ndarray]:
    """The scene's drive torques as one cheap scalar function of t for the Python peers.

    A scene's expressions evaluate through NumPy (about 24 us each per scalar call, more than
    a compiled right-hand side); the same text goes through ``sympy.lambdify`` with the math
    module here, checked against the scene's own evaluation. Tables keep the scene's path.
    """
    import sympy as sp

    fns = scene.torques
    slow = lambda t: np.array([float(f.numpy(t)) for f in fns])  # noqa: E731
    if not fns or "table" in scene.torque_text:
        return slow
    t_sym = sp.Symbol("t", real=True)
    names = {k: sp.Float(v) for k, v in scene.constants.items()}
    try:
        exprs = [sp.sympify(scene.torque_text[k], locals={**names, "t": t_sym})
                 for k in scene.torque_text]
        fast = sp.lambdify([t_sym], exprs, "math")
    except (sp.SympifyError, SyntaxError, TypeError, ValueError):
        return slow
    for t in np.linspace(0.0, scene.run.t_end, 17):
        if not np.allclose(fast(float(t)), slow(float(t)), rtol=1e-12, atol=1e-12):
            return slow

    def torques(t: float) -> np.ndarray:
        return np.array(fast(t), dtype=float)

    return torques


@dataclass
class PeerRhs:
    name: str
    rhs: Callable[[float, np.ndarray, np.ndarray], np.ndarray]
    build_s: float
    per_call_us: float = math.nan
    note: str = ""


def pydy_rhs(eq: Equations, robot: Any, scene: Any, build_dir: Path) -> PeerRhs:
    """PyDy's System with the Cython generator; torques as specifieds, v_imp as constants."""
    from pydy.system import System
    from sympy.physics.mechanics import dynamicsymbols

    sm = eq.symbolic
    taus = [dynamicsymbols(s.name) for s in sm.torques]
    forcing = eq.forcing.xreplace(dict(zip(sm.torques, taus, strict=True)))
    kane = _KaneLike(eq, forcing)
    values = parameter_values(eq, robot)
    probe = System(kane)  # which symbols the equations actually use
    constants = {s: v for s, v in values.items() if s in probe.constants_symbols}
    torques = fast_torques(scene)

    def specified(_x: np.ndarray, t: float) -> np.ndarray:
        return torques(t)

    # PyDy's second specifieds format fixes the order of the torque symbols (a set otherwise).
    system = System(kane, constants=constants,
                    specifieds={"symbols": taus, "values": specified} if taus else None)
    c0 = time.process_time()
    w0 = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        f = system.generate_ode_function(generator="cython", tmp_dir=str(build_dir),
                                         constants_arg_type="array",
                                         specifieds_arg_type="function")
    build_s = time.perf_counter() - w0
    del c0
    order = list(system.constants_symbols)
    p = np.array([constants[s] for s in order])
    v_slots = [order.index(c.impact_speed) for c in sm.clearance]

    def rhs(t: float, x: np.ndarray, v_imp: np.ndarray) -> np.ndarray:
        p[v_slots] = v_imp
        return np.array(f(x, t, specified, p))

    return PeerRhs("PyDy (Cython) + LSODA", rhs, build_s)


def newcomer_rhs(eq: Equations, robot: Any, scene: Any) -> PeerRhs:
    """``sympy.lambdify`` (NumPy) of M and f, ``numpy.linalg.solve`` for the accelerations."""
    import sympy as sp

    sm = eq.symbolic
    n = len(sm.q)
    qs = sp.symbols(f"x0:{2 * n}", real=True)
    plain = dict(zip([*sm.q, *sm.u], qs, strict=True))
    values = parameter_values(eq, robot)
    params = list(values)
    args = [*qs, *sm.torques, *params]
    w0 = time.perf_counter()
    mass = sp.lambdify(args, eq.mass_matrix.xreplace(plain))
    force = sp.lambdify(args, eq.forcing.xreplace(plain))
    build_s = time.perf_counter() - w0
    p = np.array([values[s] for s in params])
    v_slots = [params.index(c.impact_speed) for c in sm.clearance]
    torques = fast_torques(scene)

    def rhs(t: float, x: np.ndarray, v_imp: np.ndarray) -> np.ndarray:
        p[v_slots] = v_imp
        a = [*x, *torques(t), *p]
        acc = np.linalg.solve(np.asarray(mass(*a), dtype=float),
                              np.asarray(force(*a), dtype=float).ravel())
        return np.concatenate([x[n:], acc])

    return PeerRhs("sympy.lambdify + LSODA", rhs, build_s)


def jointplay_lsoda_rhs(model: Any, scene: Any) -> PeerRhs:
    """jointplay's compiled forward dynamics in the peers' LSODA driver: the same integration
    as (a) and (b), so only the right-hand side differs."""
    fd = model.function("forward_dynamics")
    fd.inputs[2][:] = model.parameter_vector()
    torques = fast_torques(scene)

    def rhs(t: float, x: np.ndarray, v_imp: np.ndarray) -> np.ndarray:
        fd.inputs[0][:] = x
        fd.inputs[1][:] = torques(t)
        fd.inputs[3][:] = v_imp
        fd.trigger()
        return fd.outputs[0].copy()

    return PeerRhs("jointplay rhs + LSODA (same driver)", rhs, 0.0)
