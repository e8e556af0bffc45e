"""An independent simulator of planar serial arms with clearance joints, for the benchmark data.

It imports nothing of jointplay: it reads a robot table (the ``[robot]`` of a scene file, as
data) and writes its own equations of motion, so that the calibration benchmark judges the
calibration on motion made elsewhere, not on the model it fits.

Equations: Lagrange's, in the coordinates z = [angles of the moving joints, then (ex, ey) of
every joint with play], built as CasADi expressions and differentiated by CasADi's AD:

    M(z) z'' = Q(z, z', t) + dT/dz - (d/dz (M z')) z' - dV/dz,   M = d2T/dz'2,

with T the kinetic energy of the links (mass at the centre of mass, inertia about it) and the
payload (a point mass at the last link's end), V the potential of gravity. Conventions (the
ones of the robot description): link i's angle is the sum of the joint angles up to i
(moving joints: their coordinate q_i; locked ones: their ``angle``); joint i's bearing is the
end of link i-1 (the origin for i = 1), its journal, where link i starts, is the bearing plus
the eccentricity e = (ex, ey) in the inertial frame; the centre of mass lies ``com`` along the
link from the journal.

Clearance joint laws (Lankarani and Nikravesh, J. Mech. Des. 112 (1990) 369-376; Ambrosio's
modified Coulomb friction; Hertz's pin-in-hole stiffness):

    delta = |e| - c,   n = e/|e|,   t = z x n,   delta' = n.e',
    v_t = t.e' + omega_journal Rj - omega_bearing Rb          (contact-point sliding speed)
    F_n = max(0, K delta_+^n (1 + x(ce) delta' / max(v-, floor))),
    K = 4 / (3 (sigma_b + sigma_j)) sqrt(Rb Rj / (Rb - Rj)),   sigma = (1 - nu^2)/E,
    F_t = -mu c_d(|v_t|) F_n sign(v_t),   c_d: 0 below v0, 1 above v1, linear or C1 between,

the force -F_n n + F_t t acting on the journal (and its reaction on the bearing), and the
friction moments Rj F_t on the journal's link and -Rb F_t on the bearing's. v- is the
approach speed delta' captured where the penetration crosses zero upwards (an event located
by the integrator), held until the next onset. Drive torques act on link i with their
reaction on link i-1.

Integration: SciPy's Radau (order 5) with CasADi's exact Jacobian (emitted as C), at rtol 1e-8, atol
1e-9 on angles (rad) and 1e-9 c on eccentricities; each onset and separation ends a
segment, so the captured speed is the located one.
"""

from __future__ import annotations

import ctypes
import math
import os
import re
import subprocess
import tempfile
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import casadi as ca
import numpy as np
from scipy.integrate import solve_ivp

MOVING = ("ideal", "clearance")
WITH_PLAY = ("clearance", "locked_clearance")
DAMPING_FACTOR = {
    "lankarani-nikravesh": lambda ce: 0.75 * (1.0 - ce**2),
    "hunt-crossley": lambda ce: 1.5 * (1.0 - ce),
    "gonthier": lambda ce: (1.0 - ce**2) / ce,
    "flores": lambda ce: 1.6 * (1.0 - ce) / ce,
}
RTOL = 1e-8
ATOL = 1e-9


@dataclass(frozen=True)
class SineTerm:
    """One term amplitude * sin(2 pi frequency t + phase) of a drive torque (N m, Hz, rad)."""

    amplitude: float
    frequency: float
    phase: float = 0.0

    def expression(self) -> str:
        text = f"{self.amplitude!r}*sin(2*pi*{self.frequency!r}*t"
        return text + (f" + {self.phase!r})" if self.phase else ")")


def torque_expression(terms: Sequence[SineTerm]) -> str:
    """The scene-file expression of a sum of sine terms."""
    return " + ".join(term.expression() for term in terms) if terms else "0"


def torque_value(terms: Sequence[SineTerm], t: float) -> float:
    return sum(s.amplitude * math.sin(2.0 * math.pi * s.frequency * t + s.phase) for s in terms)


def resolved_robot(robot: Mapping[str, Any], values: Mapping[str, float]) -> dict[str, Any]:
    """A copy of the robot table with ``values`` applied: ``linkN.key``, ``jointN.key``,
    ``jointN.clearance`` (bearing radius held, journal radius follows), ``payload.mass``,
    ``friction.key``, ``contact.key``."""
    out: dict[str, Any] = {k: (dict(v) if isinstance(v, dict) else v) for k, v in robot.items()}
    out["links"] = [dict(link) for link in robot["links"]]
    out["joints"] = [dict(joint) for joint in robot["joints"]]
    for name, value in values.items():
        group, key = name.split(".", 1)
        indexed = re.fullmatch(r"(link|joint)(\d+)", group)
        if indexed:
            table = indexed.group(1) + "s"
            entry = out[table][int(indexed.group(2)) - 1]
            if key == "clearance":
                entry["journal_radius"] = entry["bearing_radius"] - float(value)
            else:
                if key not in entry:
                    raise KeyError(f"{name}: {group} has no {key!r}")
                entry[key] = float(value)
        elif group in ("payload", "friction", "contact"):
            if key not in out[group]:
                raise KeyError(f"{name}: [{group}] has no {key!r}")
            out[group][key] = float(value)
        else:
            raise KeyError(f"{name}: not a parameter this reference knows")
    return out


class Arm:
    """The equations of one robot table; :meth:`simulate` integrates them."""

    def __init__(self, robot: Mapping[str, Any]) -> None:
        links, joints = robot["links"], robot["joints"]
        if len(links) != len(joints):
            raise ValueError("one joint per link expected")
        kinds = [j.get("kind", "ideal") for j in joints]
        self.angle_names = [f"q{i}" for i, k in enumerate(kinds, 1) if k in MOVING]
        self.play_joints = [i for i, k in enumerate(kinds, 1) if k in WITH_PLAY]
        self.coordinates = self.angle_names + [f"{a}{i}" for i in self.play_joints
                                               for a in ("ex", "ey")]
        self.driven = [i for i, k in enumerate(kinds, 1) if k in MOVING] \
            if robot.get("drive", {}).get("enabled", False) else []
        n = len(self.coordinates)
        z, zd = ca.SX.sym("z", n), ca.SX.sym("zd", n)
        tau = ca.SX.sym("tau", len(self.driven))
        v_imp = ca.SX.sym("v_imp", len(self.play_joints))
        index = {name: k for k, name in enumerate(self.coordinates)}

        gravity = robot.get("gravity", {})
        g = ca.DM(gravity.get("vector", [0.0, -9.81])) if gravity.get("enabled", False) \
            else ca.DM([0.0, 0.0])
        kinetic, potential = ca.SX(0), ca.SX(0)
        theta, end = ca.SX(0), ca.SX.zeros(2)
        thetas, ends, journals = [ca.SX(0)], [end], []
        for i, (link, joint, kind) in enumerate(zip(links, joints, kinds, strict=True), 1):
            theta = theta + (z[index[f"q{i}"]] if kind in MOVING else float(joint["angle"]))
            journal = end + (ca.vertcat(z[index[f"ex{i}"]], z[index[f"ey{i}"]])
                             if kind in WITH_PLAY else 0)
            direction = ca.vertcat(ca.cos(theta), ca.sin(theta))
            com = journal + float(link["com"]) * direction
            end = journal + float(link["length"]) * direction
            m = float(link["mass"])
            v_com = ca.jtimes(com, z, zd)
            omega = ca.jtimes(theta, z, zd)
            kinetic += 0.5 * m * ca.dot(v_com, v_com) + 0.5 * float(link["inertia"]) * omega**2
            potential -= m * ca.dot(g, com)
            thetas.append(theta)
            ends.append(end)
            journals.append(journal)
        payload = float(robot.get("payload", {}).get("mass", 0.0))
        v_tip = ca.jtimes(end, z, zd)
        kinetic += 0.5 * payload * ca.dot(v_tip, v_tip)
        potential -= payload * ca.dot(g, end)

        force = ca.SX.zeros(n)
        for k, i in enumerate(self.driven):
            force[index[f"q{i}"]] += tau[k]
        deltas, rates = [], []
        for k, i in enumerate(self.play_joints):
            f = self._joint_force(robot, joints[i - 1], z, zd, index, i, thetas, v_imp[k])
            deltas.append(f["delta"])
            rates.append(f["rate"])
            force[index[f"ex{i}"]] += f["fx"]
            force[index[f"ey{i}"]] += f["fy"]
            force += ca.jacobian(thetas[i], z).T * (f["rj"] * f["ft"])
            if i > 1:
                force -= ca.jacobian(thetas[i - 1], z).T * (f["rb"] * f["ft"])

        mass = ca.hessian(kinetic, zd)[0]
        momentum = ca.gradient(kinetic, zd)
        rhs = force + ca.gradient(kinetic, z) - ca.jtimes(momentum, z, zd) \
            - ca.gradient(potential, z)
        x = ca.vertcat(z, zd)
        xdot = ca.vertcat(zd, ca.solve(mass, rhs))
        self.n = n
        functions = [ca.Function("arm_rhs", [x, tau, v_imp], [xdot]),
                     ca.Function("arm_jacobian", [x, tau, v_imp],
                                 [ca.densify(ca.jacobian(xdot, x))]),
                     ca.Function("arm_contact", [x], [ca.vertcat(*deltas, ca.SX(0)),
                                                      ca.vertcat(*rates, ca.SX(0))]),
                     ca.Function("arm_outputs", [x], [end, ca.vertcat(*thetas[1:])])]
        with tempfile.TemporaryDirectory() as folder:
            calls = Compiled(functions, Path(folder)).calls
        self.n = n
        self._rhs, self._jacobian = calls["arm_rhs"], calls["arm_jacobian"]
        self._contact, self._outputs = calls["arm_contact"], calls["arm_outputs"]
        contact = robot.get("contact", {})
        self.speed_floor = float(contact.get("impact_speed_floor", 0.0))
        self.clearances = [float(joints[i - 1]["bearing_radius"])
                           - float(joints[i - 1]["journal_radius"]) for i in self.play_joints]

    @staticmethod
    def _joint_force(robot: Mapping[str, Any], joint: Mapping[str, Any], z: ca.SX, zd: ca.SX,
                     index: Mapping[str, int], i: int, thetas: list[ca.SX],
                     v_imp: ca.SX) -> dict[str, Any]:
        rb, rj = float(joint["bearing_radius"]), float(joint["journal_radius"])
        c = rb - rj
        sigma_b = (1.0 - float(joint["bearing_nu"]) ** 2) / float(joint["bearing_E"])
        sigma_j = (1.0 - float(joint["journal_nu"]) ** 2) / float(joint["journal_E"])
        stiffness = 4.0 / (3.0 * (sigma_b + sigma_j)) * math.sqrt(rb * rj / c)
        contact = robot["contact"]
        if contact.get("stiffness", "hertz") != "hertz":
            raise ValueError("this reference models Hertz's pin-in-hole stiffness only")
        x_ce = DAMPING_FACTOR[contact["law"]](float(contact["restitution"]))
        exponent = float(contact["exponent"])
        floor = float(contact.get("impact_speed_floor", 0.0))
        ex, ey = z[index[f"ex{i}"]], z[index[f"ey{i}"]]
        vx, vy = zd[index[f"ex{i}"]], zd[index[f"ey{i}"]]
        # |e| floored far below c: the direction is used only in contact (|e| > c).
        ecc = ca.sqrt(ca.fmax(ex**2 + ey**2, (1e-9 * c) ** 2))
        nx, ny = ex / ecc, ey / ecc
        tx, ty = -ny, nx
        delta = ecc - c
        rate = nx * vx + ny * vy
        omega_j = ca.jtimes(thetas[i], z, zd)
        omega_b = ca.jtimes(thetas[i - 1], z, zd)
        sliding = tx * vx + ty * vy + omega_j * rj - omega_b * rb
        elastic = ca.if_else(delta > 0, stiffness * ca.fmax(delta, 1e-300) ** exponent, 0)
        normal = ca.fmax(elastic * (1 + x_ce * rate / ca.fmax(v_imp, floor)), 0)
        friction = robot.get("friction")
        ft: Any = ca.SX(0)
        if friction and friction.get("law", "coulomb") == "coulomb":
            v0, v1 = float(friction["v0"]), float(friction["v1"])
            s = ca.fmin(ca.fmax((ca.fabs(sliding) - v0) / (v1 - v0), 0), 1)
            ramp = friction.get("ramp", "linear")
            c_d = s if ramp == "linear" else s**2 * (3 - 2 * s)
            ft = -float(friction["mu"]) * c_d * normal * ca.sign(sliding)
        return {"delta": delta, "rate": rate, "fx": -normal * nx + ft * tx,
                "fy": -normal * ny + ft * ty, "ft": ft, "rb": rb, "rj": rj}

    def simulate(self, torques: Mapping[int, Sequence[SineTerm]], initial: Mapping[str, float],
                 t_end: float, output_step: float) -> dict[str, np.ndarray]:
        """The motion sampled every ``output_step`` from 0 to ``t_end``: ``t``, ``tip``
        (n x 2, the last link's end), ``angles`` (n x links, absolute), the coordinates and
        ``onsets`` (the number of contact onsets)."""
        n = self.n
        x0 = np.zeros(2 * n)
        for name, value in initial.items():
            if name.startswith("d") and name[1:] in self.coordinates:
                x0[n + self.coordinates.index(name[1:])] = value
            else:
                x0[self.coordinates.index(name)] = value
        samples = round(t_end / output_step)
        grid = np.arange(samples + 1) * output_step
        scale = np.ones(2 * n)
        for k, c in enumerate(self.clearances):
            pos = len(self.angle_names) + 2 * k
            scale[[pos, pos + 1, n + pos, n + pos + 1]] = c
        atol = ATOL * scale

        def tau(t: float) -> np.ndarray:
            return np.array([torque_value(torques.get(i, ()), t) for i in self.driven])

        nc = len(self.play_joints)
        flags, v_imp = np.zeros(nc, dtype=bool), np.zeros(nc)
        if nc:
            delta, rate = (a.ravel()[:nc] for a in self._contact(x0))
            flags[:] = delta > 0
            v_imp[flags] = rate[flags]
        onsets = int(flags.sum())
        t, x = 0.0, x0
        states = np.empty((samples + 1, 2 * n))
        filled = 0
        while t < t_end:
            def rhs(tt: float, xx: np.ndarray) -> np.ndarray:
                return self._rhs(xx, tau(tt), v_imp)[0].ravel()

            def jac(tt: float, xx: np.ndarray) -> np.ndarray:
                return self._jacobian(xx, tau(tt), v_imp)[0]

            events = []
            for k in range(nc):
                def event(tt: float, xx: np.ndarray, k: int = k) -> float:
                    d = float(self._contact(xx)[0][k, 0])
                    return -d if flags[k] else d
                event.terminal = True  # type: ignore[attr-defined]
                event.direction = 1.0  # type: ignore[attr-defined]
                events.append(event)
            t_eval = grid[filled:][grid[filled:] >= t]
            sol = solve_ivp(rhs, (t, t_end), x, method="Radau", jac=jac, rtol=RTOL, atol=atol,
                            t_eval=t_eval, events=events or None)
            if sol.status < 0:
                raise RuntimeError(f"reference integration failed at t = {sol.t[-1]:g} s: "
                                   f"{sol.message}")
            got = len(sol.t)
            if got:
                states[filled:filled + got] = np.asarray(sol.y).T
            filled += got
            if sol.status == 1:  # an onset or a separation
                hit = next(k for k in range(nc) if sol.t_events[k].size)
                t, x = float(sol.t_events[hit][0]), sol.y_events[hit][0]
                if flags[hit]:
                    flags[hit] = False
                else:
                    flags[hit] = True
                    v_imp[hit] = float(self._contact(x)[1][hit, 0])
                    onsets += 1
            else:
                t = t_end
        if filled != samples + 1:
            raise RuntimeError(f"reference filled {filled} of {samples + 1} samples")
        tips, angles = zip(*(self._outputs(s) for s in states), strict=True)
        return {"t": grid, "x": states,
                "tip": np.array([p.ravel() for p in tips]),
                "theta": np.array([a.ravel() for a in angles]),
                "onsets": np.array(onsets)}


class Compiled:
    """CasADi functions emitted as C, compiled with the system's C compiler and called through
    ctypes on preallocated buffers (a Python call into CasADi costs ~100x more)."""

    def __init__(self, functions: Sequence[ca.Function], folder: Path) -> None:
        generator = ca.CodeGenerator("reference_arm.c", {"casadi_int": "long long int"})
        for function in functions:
            generator.add(function)
        folder.mkdir(parents=True, exist_ok=True)
        source = folder / "reference_arm.c"
        generator.generate(str(folder) + os.sep)
        library = folder / "reference_arm.so"
        subprocess.run(["cc", "-O2", "-fPIC", "-shared", str(source), "-o", str(library),
                        "-lm"], check=True)
        self._library = ctypes.CDLL(str(library))
        self.calls: dict[str, Any] = {}
        for function in functions:
            self.calls[function.name()] = _Call(self._library, function)


class _Call:
    """One compiled function: inputs copied into and outputs read from fixed buffers."""

    def __init__(self, library: ctypes.CDLL, function: ca.Function) -> None:
        self.entry = getattr(library, function.name())
        self.entry.restype = ctypes.c_int
        real_p = ctypes.POINTER(ctypes.c_double)
        self.inputs = [np.zeros(function.nnz_in(k)) for k in range(function.n_in())]
        self.outputs = [np.zeros(function.nnz_out(k)) for k in range(function.n_out())]
        self.shapes = [function.size_out(k) for k in range(function.n_out())]
        self.arg = (real_p * max(function.sz_arg(), 1))(
            *[a.ctypes.data_as(real_p) for a in self.inputs])
        self.res = (real_p * max(function.sz_res(), 1))(
            *[r.ctypes.data_as(real_p) for r in self.outputs])
        self.iw = (ctypes.c_longlong * max(function.sz_iw(), 1))()
        self.w = (ctypes.c_double * max(function.sz_w(), 1))()

    def __call__(self, *values: Any) -> list[np.ndarray]:
        for buffer, value in zip(self.inputs, values, strict=True):
            buffer[:] = value
        if self.entry(self.arg, self.res, self.iw, self.w, 0):
            raise RuntimeError("compiled reference function failed")
        return [o.reshape(shape, order="F").copy() for o, shape in
                zip(self.outputs, self.shapes, strict=True)]
