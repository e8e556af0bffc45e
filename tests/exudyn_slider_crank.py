"""Outside reference for the slider-crank with a revolute clearance joint, simulated with Exudyn.

The mechanism (Flores, Ambrosio, Claro and Lankarani's benchmark; values in ``SliderCrank``):
a crank of length r turns about the origin at constant speed from theta = 0 (pointing along +x
at the slider), a connecting rod of length l hangs on the crank pin by an ideal revolute joint,
and a slider moves on a horizontal guide along +x through the origin. The rod's far end and the
slider are joined by a revolute joint with clearance: the journal (radius Rj) on one of them
floats in the bearing (radius Rb = Rj + c) on the other.

Exudyn's side: one ``ObjectKinematicTree`` (minimal coordinates, Exudyn's own recursive mass
matrix, gravity and velocity terms) with three joints: the crank (RevoluteZ at the origin),
the rod (RevoluteZ at the crank pin, angle phi relative to the crank) and the slider
(PrismaticX on the ground). Cut at the clearance joint the loop is a tree, so the equations are
ODEs and Exudyn's error-controlled explicit DOPRI5 integrates them at tight tolerance.

- The driver: Exudyn's explicit solvers take no general constraints, so the crank carries a
  flywheel of inertia ``flywheel_inertia`` (1e8 kg m^2) and starts at the driving speed. The
  torque the driver would apply is tau = -I_fly theta'' (to a relative 1e-11: the rest of the
  crank row of the mass matrix is below 1e-3 kg m^2), and the crank departs from constant speed
  by |delta theta| <= int int |tau| / I_fly, reported as ``crank_angle_error`` (1.2e-11 rad
  over the first revolution).
- The clearance joint is a generalised force written here (``forceUserFunction`` of the tree),
  not taken from jointplay: with e = journal centre - bearing centre, penetration d = |e| - c,
  n = e/|e|, t = n rotated +90 deg, d' = e'.n and the sliding speed of the contact points
  v_t = t.e' + w_journal Rj - w_bearing Rb (docs/explanation/models.md),

      F_n = max(0, K d+^n (1 + x(ce) d'/v-)),  x(ce) = 3 (1 - ce^2) / 4 (Lankarani-Nikravesh),
      K = 4 / (3 (sigma_b + sigma_j)) sqrt(Rb Rj / c),  sigma = (1 - nu^2) / E,
      F_t = -mu c_d(|v_t|) F_n v_t / max(|v_t|, v0, v1/1000),  c_d the linear ramp v0 -> v1,

  acting on the journal at its contact point (force -F_n n + F_t t, moment Rj F_t) and the
  opposite on the bearing (moment -Rb F_t, which the slider's guide takes). v- = max(captured
  approach speed, ``impact_speed_floor``).
- The approach speed v- is d' at the onset of each impact, located, not sampled: a step that
  ends in contact (or whose cubic Hermite of d, d' rises above 0) is undone, the run restarts
  from the step's start to the crossing of d = 0 found by quintic Hermite interpolation of the
  coordinates (contact switched off on that stretch, which lies before the crossing), takes d'
  there and goes on with contact.
- Outputs between steps: coordinates and speeds from the quintic Hermite spline through the
  coordinates, speeds and accelerations at every step (scipy ``BPoly.from_derivatives``),
  accelerations and the driving torque from the equations of motion at that state. Each
  impact's peak normal force is located, never read off samples: in the step where dF_n/dt
  (from the accelerations) turns negative, the maximum of F_n along the spline (scipy's
  bounded ``minimize_scalar``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import exudyn as exu
import numpy as np
from exudyn.itemInterface import NodeGenericODE2, ObjectKinematicTree
from scipy.interpolate import BPoly, CubicHermiteSpline
from scipy.optimize import minimize_scalar


@dataclass(frozen=True)
class SliderCrank:
    """The benchmark's values (SI units); ``journal_on`` names the body that carries the journal."""

    crank_length: float = 0.05
    crank_mass: float = 0.30
    crank_inertia: float = 1.0e-4  # about the centre of mass, which is at mid-length
    rod_length: float = 0.12
    rod_mass: float = 0.21
    rod_inertia: float = 2.5e-4
    slider_mass: float = 0.14
    journal_radius: float = 10.0e-3
    bearing_radius: float = 10.5e-3
    journal_on: str = "rod"  # "rod" (bearing in the slider) or "slider" (bearing in the rod)
    crank_speed: float = 5000.0 * 2.0 * math.pi / 60.0  # rad/s
    gravity: tuple[float, float] = (0.0, -9.81)
    restitution: float = 0.9
    young: float = 207.0e9
    poisson: float = 0.3
    exponent: float = 1.5
    impact_speed_floor: float = 1.0e-3
    mu: float = 0.0
    v0: float = 1.0e-4
    v1: float = 1.0e-2
    flywheel_inertia: float = 1.0e8

    @property
    def clearance(self) -> float:
        return self.bearing_radius - self.journal_radius

    @property
    def stiffness(self) -> float:
        sigma = (1.0 - self.poisson**2) / self.young
        rb, rj = self.bearing_radius, self.journal_radius
        return 4.0 / (3.0 * 2.0 * sigma) * math.sqrt(rb * rj / (rb - rj))

    @property
    def damping_factor(self) -> float:
        return 0.75 * (1.0 - self.restitution**2)


def ideal_slider(theta: np.ndarray, r: float, rod: float) -> np.ndarray:
    """s(theta) = r cos theta + sqrt(l^2 - r^2 sin^2 theta), l = ``rod``: the ideal slider."""
    return r * np.cos(theta) + np.sqrt(rod * rod - (r * np.sin(theta)) ** 2)


def ideal_start(m: SliderCrank) -> tuple[np.ndarray, np.ndarray]:
    """Coordinates [theta, phi, x] and speeds of the ideal mechanism at theta = 0 (journal
    centred): the rod lies along +x and turns at -w r / l absolutely, the slider is at rest."""
    r, rl, w = m.crank_length, m.rod_length, m.crank_speed
    return np.array([0.0, 0.0, r + rl]), np.array([w, -w * (1.0 + r / rl), 0.0])


@dataclass
class _Contact:
    """The clearance joint's kinematics and forces at one state (see the module docstring)."""

    e: np.ndarray
    e_t: np.ndarray
    penetration: float
    rate: float
    normal_force: float
    friction_force: float
    generalized: np.ndarray
    rod_force: np.ndarray  # the contact force on the rod (N)


def _geometry(m: SliderCrank, q: np.ndarray, v: np.ndarray):
    r, rl = m.crank_length, m.rod_length
    theta, phi, x = q
    psi, psi_t = theta + phi, v[0] + v[1]
    c1, s1, c2, s2 = math.cos(theta), math.sin(theta), math.cos(psi), math.sin(psi)
    tip = np.array([r * c1 + rl * c2, r * s1 + rl * s2])  # rod end, journal or bearing centre
    d_theta = np.array([-r * s1 - rl * s2, r * c1 + rl * c2])  # d tip / d theta
    d_phi = np.array([-rl * s2, rl * c2])  # d tip / d phi
    tip_t = d_theta * v[0] + d_phi * v[1]
    slider, slider_t = np.array([x, 0.0]), np.array([v[2], 0.0])
    return tip, tip_t, d_theta, d_phi, slider, slider_t, psi_t


def contact(m: SliderCrank, q: np.ndarray, v: np.ndarray, approach: float | None) -> _Contact:
    """Forces of the clearance joint; ``approach`` None switches the contact force off."""
    tip, tip_t, d_theta, d_phi, slider, slider_t, psi_t = _geometry(m, q, v)
    on_rod = m.journal_on == "rod"
    sign = 1.0 if on_rod else -1.0  # e = journal - bearing
    e, e_t = sign * (tip - slider), sign * (tip_t - slider_t)
    ecc = math.hypot(e[0], e[1])
    c = m.clearance
    penetration = ecc - c
    generalized = np.zeros(3)
    if penetration <= 0.0 or approach is None:
        rate = float(e_t @ e / ecc) if ecc > 0.0 else 0.0
        return _Contact(e, e_t, penetration, rate, 0.0, 0.0, generalized, np.zeros(2))
    n = e / ecc
    t = np.array([-n[1], n[0]])
    rate = float(e_t @ n)
    w_journal, w_bearing = (psi_t, 0.0) if on_rod else (0.0, psi_t)
    sliding = float(t @ e_t) + w_journal * m.journal_radius - w_bearing * m.bearing_radius
    v_minus = max(approach, m.impact_speed_floor)
    fn = max(0.0, m.stiffness * penetration**m.exponent
             * (1.0 + m.damping_factor * rate / v_minus))
    ft = 0.0
    if m.mu > 0.0:
        speed = abs(sliding)
        ramp = min(max((speed - m.v0) / (m.v1 - m.v0), 0.0), 1.0)
        ft = -m.mu * ramp * fn * sliding / max(speed, m.v0, 1e-3 * m.v1)
    force = -fn * n + ft * t  # on the journal
    if on_rod:  # journal on the rod: force and moment Rj ft on the rod, -force on the slider
        generalized[0] = force @ d_theta + m.journal_radius * ft
        generalized[1] = force @ d_phi + m.journal_radius * ft
        generalized[2] = -force[0]
    else:  # journal on the slider: -force and moment -Rb ft on the rod
        generalized[0] = -force @ d_theta - m.bearing_radius * ft
        generalized[1] = -force @ d_phi - m.bearing_radius * ft
        generalized[2] = force[0]
    return _Contact(e, e_t, penetration, rate, fn, ft, generalized,
                    force if on_rod else -force)


def _penetration_and_rate(m: SliderCrank, q: np.ndarray, v: np.ndarray) -> tuple[float, float]:
    c = contact(m, q, v, None)
    return c.penetration, c.rate


@dataclass
class Impact:
    onset: float  # s, located
    approach_speed: float  # m/s, d' at the onset
    separation: float = math.nan  # s, located (nan while still in contact at the end)
    peak_force: float = 0.0  # N, located
    peak_time: float = math.nan


@dataclass
class SliderCrankRun:
    """Every accepted step of one Exudyn run: t, coordinates q = [theta, phi, x], speeds v,
    accelerations a; the located impacts, and what the run cost."""

    model: SliderCrank
    t: np.ndarray
    q: np.ndarray
    v: np.ndarray
    a: np.ndarray
    impacts: list[Impact]
    approach: np.ndarray  # the v- in force at the end of each step (nan out of contact)
    restarts: int = 0
    splines: list[BPoly] = field(init=False, repr=False)

    def __post_init__(self) -> None:
        self.splines = [BPoly.from_derivatives(self.t, np.stack([self.q[:, j], self.v[:, j],
                                                                 self.a[:, j]], axis=1))
                        for j in range(3)]

    def spline(self, times: np.ndarray, order: int = 0) -> np.ndarray:
        """Coordinates (order 0), speeds (1) or accelerations (2) at ``times``, one row each."""
        return np.stack([s(times, order) for s in self.splines], axis=-1)

    def at(self, times: np.ndarray) -> dict[str, np.ndarray]:
        """The slider's x, x', x'', the orbit e = journal - bearing, the driving torque, the
        crank's departure from constant speed and the contact's normal force at ``times``:
        coordinates and speeds from the spline, accelerations from the equations of motion at
        that state (``rod_and_slider_accelerations``), since second derivatives of a position
        spline lose digits to round-off on short steps."""
        times = np.asarray(times, dtype=float)
        q, v = self.spline(times), self.spline(times, 1)
        m = self.model
        out = {key: np.empty(times.size) for key in
               ("slider_acceleration", "normal_force", "driving_torque")}
        e = np.empty((times.size, 2))
        for k, tk in enumerate(times):
            i = min(max(int(np.searchsorted(self.t, tk, side="right")) - 1, 0), self.t.size - 2)
            v_minus = self.approach[i]  # the approach speed in force on this step
            cont = contact(m, q[k], v[k], None if math.isnan(v_minus) else v_minus)
            rod_tt, slider_tt = rod_and_slider_accelerations(m, q[k], v[k], cont)
            a = np.array([0.0, rod_tt, slider_tt])
            e[k] = cont.e
            out["normal_force"][k] = cont.normal_force
            out["slider_acceleration"][k] = slider_tt
            out["driving_torque"][k] = driving_torque(m, q[k], v[k], a, cont.rod_force)
        return {"slider_position": q[:, 2], "slider_velocity": v[:, 2], "orbit": e, **out,
                "crank_angle_error": q[:, 0] - m.crank_speed * times}


def rod_and_slider_accelerations(m: SliderCrank, q: np.ndarray, v: np.ndarray,
                                 cont: _Contact) -> tuple[float, float]:
    """psi'' of the rod and x'' of the slider with the crank at constant speed: the rod turns
    about the crank pin A, I_A psi'' = M_A(contact) + ((G - A) x m g)_z - m ((G - A) x a_A)_z,
    I_A = I_G + m (l/2)^2, a_A = -w^2 A; the slider feels only the contact along x."""
    r, rl, w = m.crank_length, m.rod_length, v[0]
    theta, psi = q[0], q[0] + q[1]
    arm = 0.5 * rl * np.array([math.cos(psi), math.sin(psi)])  # G - A
    pin_tt = -w * w * r * np.array([math.cos(theta), math.sin(theta)])
    g = np.asarray(m.gravity)
    moment = (cont.generalized[1] + m.rod_mass * (arm[0] * g[1] - arm[1] * g[0])
              - m.rod_mass * (arm[0] * pin_tt[1] - arm[1] * pin_tt[0]))
    inertia = m.rod_inertia + m.rod_mass * (0.5 * rl) ** 2
    return moment / inertia, cont.generalized[2] / m.slider_mass


def driving_torque(m: SliderCrank, q: np.ndarray, v: np.ndarray, a: np.ndarray,
                   rod_force: np.ndarray) -> float:
    """The torque that holds the crank at constant speed (Newton-Euler on crank and rod).

    The crank pin carries F = m_rod a_G - m_rod g - (contact force on the rod) to the rod, so
    the driver supplies tau = (A x F)_z - (G_crank x m_crank g)_z with A the crank pin and
    G_crank the crank's centre of mass (theta'' = 0). At the steps it equals Exudyn's
    -I_fly theta'' (tests/test_slider_crank_reference.py checks it).
    """
    r, rl = m.crank_length, m.rod_length
    theta, psi, w, psi_t, psi_tt = q[0], q[0] + q[1], v[0], v[0] + v[1], a[1]
    c1, s1, c2, s2 = math.cos(theta), math.sin(theta), math.cos(psi), math.sin(psi)
    pin = np.array([r * c1, r * s1])
    pin_tt = -w * w * pin  # constant crank speed
    rod_com_tt = pin_tt + 0.5 * rl * (psi_tt * np.array([-s2, c2])
                                      - psi_t**2 * np.array([c2, s2]))
    g = np.asarray(m.gravity)
    pin_force = m.rod_mass * (rod_com_tt - g) - rod_force
    crank_weight_moment = 0.5 * (pin[0] * g[1] - pin[1] * g[0]) * m.crank_mass
    return float(pin[0] * pin_force[1] - pin[1] * pin_force[0] - crank_weight_moment)


class _Runner:
    """The Exudyn system with the event bookkeeping of the module docstring."""

    def __init__(self, m: SliderCrank, rtol: float, atol: float) -> None:
        self.m = m
        self.approach: float | None = None  # None: out of contact (force off)
        self.contact_on = True
        self.records: list[tuple[float, np.ndarray, np.ndarray, np.ndarray, float]] = []
        self.stopped = False
        self.sc = exu.SystemContainer()
        mbs = self.mbs = self.sc.AddSystem()
        q0, v0 = ideal_start(m)
        self.node = mbs.AddNode(NodeGenericODE2(numberOfODE2Coordinates=3,
                                                referenceCoordinates=[0.0] * 3,
                                                initialCoordinates=q0.tolist(),
                                                initialCoordinates_t=v0.tolist()))
        r, rl = m.crank_length, m.rod_length
        # Exudyn's type stubs declare these list types without the list argument they take
        matrices: Any = exu.Matrix3DList
        vectors: Any = exu.Vector3DList
        # planar motion: only the z inertia acts; the slider does not turn (1e-6 unused)
        inertias = [m.crank_inertia + m.flywheel_inertia, m.rod_inertia, 1e-6]
        mbs.AddObject(ObjectKinematicTree(
            nodeNumber=self.node, gravity=[m.gravity[0], m.gravity[1], 0.0],
            jointTypes=[exu.JointType.RevoluteZ, exu.JointType.RevoluteZ,
                        exu.JointType.PrismaticX],
            linkParents=[-1, 0, -1],
            jointTransformations=matrices([np.eye(3)] * 3),
            jointOffsets=vectors([[0.0, 0.0, 0.0], [r, 0.0, 0.0], [0.0, 0.0, 0.0]]),
            linkInertiasCOM=matrices([np.eye(3) * j for j in inertias]),
            linkCOMs=vectors([[0.5 * r, 0.0, 0.0], [0.5 * rl, 0.0, 0.0], [0.0, 0.0, 0.0]]),
            linkMasses=[m.crank_mass, m.rod_mass, m.slider_mass],
            forceUserFunction=self._force))
        mbs.SetPostStepUserFunction(self._post_step)
        mbs.Assemble()
        self.settings = ss = exu.SimulationSettings()
        ti = ss.timeIntegration
        ti.verboseMode = 0
        ti.absoluteTolerance = atol
        ti.relativeTolerance = rtol
        ti.explicit.useLieGroupIntegration = False
        ti.explicit.computeEndOfStepAccelerations = True
        ti.numberOfSteps = 1000  # the first step's size; DOPRI5 adapts it
        ti.minimumStepSize = 1e-14
        ss.solution.file.write = False
        ss.solution.sensors.writePeriod = 1e30
        ss.show.computationTime = False
        ss.show.statistics = False

    def _force(self, mbs, t, item, q, q_t):
        if not self.contact_on:
            return [0.0, 0.0, 0.0]
        return contact(self.m, np.asarray(q), np.asarray(q_t), self.approach).generalized.tolist()

    def _state(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        sd = self.mbs.systemData
        return (np.array(sd.GetODE2Coordinates()), np.array(sd.GetODE2Coordinates_t()),
                np.array(sd.GetODE2Coordinates_tt()))

    def _post_step(self, mbs, t: float) -> bool:
        q, v, a = self._state()
        if self.records and t <= self.records[-1][0]:
            return True
        d, rate = _penetration_and_rate(self.m, q, v)
        if self.contact_on and self.approach is None and self.records:
            t0, q0, v0, _, _ = self.records[-1]
            d0, rate0 = _penetration_and_rate(self.m, q0, v0)
            grazed = CubicHermiteSpline([t0, t], [d0, d], [rate0, rate])
            if d > 0.0 or np.any(grazed(np.linspace(t0, t, 9)[1:-1]) > 0.0):
                self.stopped = True  # onset inside this step: undo it, locate the crossing
                return False
        if self.approach is not None and d <= 0.0:
            self.approach = None  # separated (the force has gone to 0 continuously)
        self.records.append((t, q, v, a, math.nan if self.approach is None else self.approach))
        return True

    def solve(self, start: float, end: float, q: np.ndarray, v: np.ndarray,
              step: float) -> None:
        sd = self.mbs.systemData
        sd.SetODE2Coordinates(q.tolist(), configuration=exu.ConfigurationType.Initial)
        sd.SetODE2Coordinates_t(v.tolist(), configuration=exu.ConfigurationType.Initial)
        ti = self.settings.timeIntegration
        ti.startTime, ti.endTime = start, end
        ti.initialStepSize = step
        self.stopped = False
        exu.SolveDynamic(self.mbs, self.settings, solverType=exu.DynamicSolverType.DOPRI5,
                         updateInitialValues=False)


def _onset_time(m: SliderCrank, a: tuple, b: tuple) -> float:
    """First crossing of d = 0 inside the step from record a to record b (quintic Hermite)."""
    ta, tb = a[0], b[0]
    splines = [BPoly.from_derivatives([ta, tb], [[a[1][j], a[2][j], a[3][j]],
                                                 [b[1][j], b[2][j], b[3][j]]]) for j in range(3)]

    def spline(x: np.ndarray | float, order: int = 0) -> np.ndarray:
        return np.stack([s(x, order) for s in splines], axis=-1)

    grid = np.linspace(ta, tb, 65)
    qs, vs = spline(grid), spline(grid, 1)
    d = np.array([_penetration_and_rate(m, qk, vk)[0] for qk, vk in zip(qs, vs, strict=True)])
    k = int(np.flatnonzero(d > 0.0)[0]) if np.any(d > 0.0) else int(np.argmax(d))
    lo, hi = grid[max(k - 1, 0)], grid[k]
    for _ in range(60):  # bisection on the spline to round-off
        mid = 0.5 * (lo + hi)
        if _penetration_and_rate(m, spline(mid), spline(mid, 1))[0] > 0.0:
            hi = mid
        else:
            lo = mid
    return lo


def simulate(m: SliderCrank, end_time: float, *, rtol: float = 1e-10,
             atol: float = 1e-12) -> SliderCrankRun:
    """Run the mechanism from the ideal start at theta = 0 to ``end_time`` seconds."""
    runner = _Runner(m, rtol, atol)
    q, v = ideal_start(m)
    t, step = 0.0, 1e-6
    runner.records.append((0.0, q, v, np.zeros(3), math.nan))
    restarts = 0
    impacts: list[Impact] = []
    while True:
        runner.solve(t, end_time, q, v, step)
        if not runner.stopped:
            break
        restarts += 1
        if restarts > 100000:
            raise RuntimeError(f"more than 100000 impacts before t = {t:.6g} s")
        # undo the step that reached contact; integrate contact-free to the crossing
        before = runner.records[-1]
        q_b, v_b, a_b = runner._state()
        after = (runner.mbs.systemData.GetTime(), q_b, v_b, a_b)
        onset = _onset_time(m, before, after)
        step = max(onset - before[0], 1e-14)
        if onset > before[0]:
            runner.contact_on = False
            runner.solve(before[0], onset, before[1], before[2], 0.5 * step)
            runner.contact_on = True
        t, q, v, _ = runner.records[-1][:4]
        _, rate = _penetration_and_rate(m, q, v)
        runner.approach = max(rate, 0.0)
        impacts.append(Impact(onset=t, approach_speed=rate))
        runner.records[-1] = (*runner.records[-1][:4], runner.approach)
        step = 1e-8
    # A restart can leave two steps ends a few 1e-11 s apart; a spline through both would lose
    # digits in its derivative to round-off, so the earlier one goes (out of contact only).
    rec = [r for k, r in enumerate(runner.records)
           if k + 1 == len(runner.records) or k == 0
           or runner.records[k + 1][0] - r[0] > 1e-9 or not math.isnan(r[4])]
    run = SliderCrankRun(
        model=m, t=np.array([r[0] for r in rec]), q=np.array([r[1] for r in rec]),
        v=np.array([r[2] for r in rec]), a=np.array([r[3] for r in rec]),
        impacts=impacts, approach=np.array([r[4] for r in rec]), restarts=restarts)
    _locate_impacts(run)
    return run


def _force_and_rate(m: SliderCrank, q: np.ndarray, v: np.ndarray, a: np.ndarray,
                    v_minus: float) -> tuple[float, float]:
    """F_n and dF_n/dt at one state (accelerations a), for the peak search."""
    cont = contact(m, q, v, v_minus)
    if cont.normal_force <= 0.0:
        return 0.0, 0.0
    h = 1e-7 * max(abs(v_minus), 1e-3) / max(np.max(np.abs(a)), 1.0)
    # d/dt along the motion: one central difference of the exact force along (v, a)
    fp = contact(m, q + h * v, v + h * a, v_minus).normal_force
    fm = contact(m, q - h * v, v - h * a, v_minus).normal_force
    return cont.normal_force, (fp - fm) / (2.0 * h)


def _locate_impacts(run: SliderCrankRun) -> None:
    m = run.model
    for imp in run.impacts:
        first = int(np.searchsorted(run.t, imp.onset))
        last = first
        while last + 1 < run.t.size and not math.isnan(run.approach[last + 1]):
            last += 1
        if last + 1 < run.t.size:  # separation: d crosses 0 downwards in the next step
            ta, tb = run.t[last], run.t[last + 1]
            pen = [_penetration_and_rate(m, run.q[k], run.v[k]) for k in (last, last + 1)]
            sep = CubicHermiteSpline([ta, tb], [pen[0][0], pen[1][0]], [pen[0][1], pen[1][1]])
            roots = [x for x in sep.roots(extrapolate=False) if ta <= x <= tb]
            imp.separation = float(roots[0]) if roots else float(tb)
        ks = range(first, last + 1)
        fr = np.array([_force_and_rate(m, run.q[k], run.v[k], run.a[k], imp.approach_speed)
                       for k in ks])
        if fr.size == 0:
            continue
        ts = run.t[first:last + 1]
        best_t, best_f = ts[int(np.argmax(fr[:, 0]))], float(np.max(fr[:, 0]))
        for j in range(len(ts) - 1):
            if fr[j, 1] > 0.0 >= fr[j + 1, 1]:  # dF/dt turns negative in this step
                def minus_force(x: float) -> float:
                    return -float(run.at(np.array([x]))["normal_force"][0])

                found = minimize_scalar(minus_force, bounds=(ts[j], ts[j + 1]),
                                        method="bounded", options={"xatol": 1e-16})
                if -found.fun > best_f:
                    best_t, best_f = float(found.x), float(-found.fun)
        imp.peak_force, imp.peak_time = best_f, best_t

