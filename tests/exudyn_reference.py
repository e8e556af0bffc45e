"""Outside reference for one pin-in-hole impact, simulated with Exudyn.

A free planar rigid body (``NodeRigidBody2D`` + ``ObjectRigidBody2D``, no gravity, no friction)
carries a journal of radius Rj whose centre starts at the centre of a hole of radius
Rb = Rj + c on the ground and moves along +x at the impact speed, so it hits the wall once.

Contact law: ``ObjectContactSphereSphere`` with ``isHollowSphere1=True`` (marker 0: journal,
marker 1: ground hole). Its gap is g = Rb - Rj - |e|, so the penetration is d = |e| - c, and with
``impactModel`` 1 or 2 its normal force is (theDoc, ObjectContactSphereSphere; source
``CObjectContactSphereSphere::ComputeContactForces``)

    F_n = k_c d^n + lambda d^n v_n,   v_n = -d',   lambda = -(k_c / v-) X(e_res),
    v- = max(minimumImpactVelocity, captured approach speed),

with X(e) = 3 (1 - e) / 2 for impactModel 1 (Hunt-Crossley) and, for impactModel 2 (mixed
Carvalho-Martins / Gonthier), X(e) = 3 (1 - e) (11 - e) / (2 (1 + 9 e)) for e > 1/3 and
X(e) = (1 - e^2) / e for 0 < e <= 1/3. That is exactly F_n = K d^n (1 + x d'/v-) of
shared/reference/clearance-physics.md once

    contactStiffness = K, contactStiffnessExponent = n, contactDamping = 0,
    impactModel = 2, restitutionCoefficient = e* with X(e*) = x(ce)  (closed-form inverse below),
    minimumImpactVelocity = impact_speed  (so v- is the impact speed, not Exudyn's value
    captured one step into the contact; that one is never larger),

for every law and every ce in (0, 1]: X is continuous and decreasing from +inf to 0 on (0, 1],
so e* exists and is unique (Exudyn requires e_res > 0). The mapping is exact, not a fit; only the
Hunt-Crossley law with impactModel 1 and e_res = ce (and Gonthier with ce <= 1/3 and
impactModel 2) would need no conversion. F_n is not clipped at zero (by either), which does not
matter: d' = -v-/x is an invariant line of m d'' = -F_n, so 1 + x d'/v- stays >= 0.

Integration: explicit RK44 with the constant step ``step``; with 1e-7 s (over 1000 steps per
impact for steel pins) results agree with closed forms and a Radau solve to ~1e-9 at 0.1 m/s and
<= 2e-6 at 1 m/s (tests/test_exudyn_reference.py); 1e-6 s would still give ~2e-4. The force-free
approach is integrated with a few long RK44 steps (exact for free flight) up to 20 steps before
the wall, so a call takes ~0.01-0.05 s whatever the clearance. Exudyn's discontinuous iteration is
switched off (its error measure |gap| * contactStiffness only shrinks explicit steps); the force
depends on the current gap alone.
"""

from __future__ import annotations

import math

import exudyn as exu
import numpy as np
from exudyn.itemInterface import (
    MarkerBodyRigid,
    NodeGenericData,
    NodeRigidBody2D,
    ObjectContactSphereSphere,
    ObjectGround,
    ObjectRigidBody2D,
    SensorNode,
    SensorObject,
)
from scipy.interpolate import CubicHermiteSpline
from scipy.special import beta

HYSTERESIS_FACTOR = {
    "lankarani-nikravesh": lambda ce: 3.0 * (1.0 - ce**2) / 4.0,
    "hunt-crossley": lambda ce: 3.0 * (1.0 - ce) / 2.0,
    "gonthier": lambda ce: (1.0 - ce**2) / ce,
    "flores": lambda ce: 8.0 * (1.0 - ce) / (5.0 * ce),
}


def exudyn_damping_factor(e_res: float) -> float:
    """X(e_res) of Exudyn's impactModel 2: lambda = -(k_c / v-) X(e_res)."""
    if e_res > 1.0 / 3.0:
        return 1.5 * (1.0 - e_res) * (11.0 - e_res) / (1.0 + 9.0 * e_res)
    return (1.0 - e_res**2) / e_res


def exudyn_restitution(x: float) -> float:
    """The restitutionCoefficient e* in (0, 1] with exudyn_damping_factor(e*) = x >= 0."""
    if x < 0.0 or not math.isfinite(x):
        raise ValueError(f"hysteresis factor must be finite and >= 0, got {x}")
    if x >= 8.0 / 3.0:  # Gonthier branch, e* <= 1/3: e^2 + x e - 1 = 0
        return 2.0 / (x + math.sqrt(x * x + 4.0))
    # 1.5 e^2 - (18 + 9x) e + (16.5 - x) = 0, smaller root, cancellation-free form
    b, c = 18.0 + 9.0 * x, 16.5 - x
    return 2.0 * c / (b + math.sqrt(b * b - 6.0 * c))


def hertz_duration(*, mass: float, stiffness: float, exponent: float, speed: float) -> float:
    """Duration of an undamped impact on K d^n: 2 dmax / (v p) B(1/p, 1/2), p = n + 1."""
    p = exponent + 1.0
    dmax = (p * mass * speed**2 / (2.0 * stiffness)) ** (1.0 / p)
    return 2.0 * dmax / (speed * p) * float(beta(1.0 / p, 0.5))


def _peak(y: np.ndarray) -> float:
    """Maximum of sampled y, refined by a parabola through the largest sample and its neighbours."""
    k = int(np.argmax(y))
    if k == 0 or k == len(y) - 1:
        return float(y[k])
    y0, y1, y2 = y[k - 1], y[k], y[k + 1]
    curv = y0 - 2.0 * y1 + y2
    return float(y1 - 0.125 * (y2 - y0) ** 2 / curv) if curv < 0.0 else float(y1)


def _crossing(t: np.ndarray, d: np.ndarray, dd: np.ndarray, k: int) -> float:
    """Time where d changes sign between samples k and k+1 (cubic Hermite on d and d')."""
    spline = CubicHermiteSpline(t[k:k + 2], d[k:k + 2], dd[k:k + 2])
    roots = [r for r in spline.roots(extrapolate=False) if t[k] <= r <= t[k + 1]]
    if roots:
        return float(roots[0])
    return float(t[k] - d[k] * (t[k + 1] - t[k]) / (d[k + 1] - d[k]))  # linear fallback


def _simulate(*, mass: float, stiffness: float, exponent: float, e_res: float,
              clearance: float, journal_radius: float, impact_speed: float, step: float,
              end_time: float) -> dict[str, np.ndarray]:
    """One Exudyn run; returns the sampled time, penetration, its rate, force and velocity."""
    sc = exu.SystemContainer()
    mbs = sc.AddSystem()
    ground = mbs.AddObject(ObjectGround())
    node = mbs.AddNode(NodeRigidBody2D(referenceCoordinates=[0.0, 0.0, 0.0],
                                       initialVelocities=[impact_speed, 0.0, 0.0]))
    body = mbs.AddObject(ObjectRigidBody2D(nodeNumber=node, mass=mass,
                                           inertia=0.5 * mass * journal_radius**2))
    m_journal = mbs.AddMarker(MarkerBodyRigid(bodyNumber=body))
    m_hole = mbs.AddMarker(MarkerBodyRigid(bodyNumber=ground))
    data = mbs.AddNode(NodeGenericData(initialCoordinates=[clearance, 0.0, 0.0, 0.0],
                                       numberOfDataCoordinates=4))
    contact = mbs.AddObject(ObjectContactSphereSphere(
        markerNumbers=[m_journal, m_hole], nodeNumber=data,
        spheresRadii=[journal_radius, journal_radius + clearance], isHollowSphere1=True,
        dynamicFriction=0.0, contactStiffness=stiffness, contactDamping=0.0,
        contactStiffnessExponent=exponent, restitutionCoefficient=e_res,
        minimumImpactVelocity=impact_speed, impactModel=2))
    out = exu.OutputVariableType
    s_force = mbs.AddSensor(SensorObject(objectNumber=contact, outputVariableType=out.Force,
                                         storeInternal=True))
    s_pos = mbs.AddSensor(SensorNode(nodeNumber=node, outputVariableType=out.Position,
                                     storeInternal=True))
    s_vel = mbs.AddSensor(SensorNode(nodeNumber=node, outputVariableType=out.Velocity,
                                     storeInternal=True))
    mbs.Assemble()

    ss = exu.SimulationSettings()
    ti = ss.timeIntegration
    ti.verboseMode = 0
    ti.automaticStepSize = False
    ti.adaptiveStep = False
    ti.explicit.useLieGroupIntegration = False
    ti.explicit.computeEndOfStepAccelerations = False
    ti.discontinuous.iterationTolerance = 1e100
    ss.solution.file.write = False
    ss.show.computationTime = False
    ss.show.statistics = False
    # Force-free approach up to 20 fine steps before the wall: RK44 is exact there for any
    # step, so 10 coarse steps replace up to millions of fine ones.
    t_approach = clearance / impact_speed - 20.0 * step
    if t_approach > 100.0 * step:
        ti.numberOfSteps = 10
        ti.endTime = t_approach
        ss.solution.sensors.writePeriod = t_approach
        exu.SolveDynamic(mbs, ss, solverType=exu.DynamicSolverType.RK44,
                         updateInitialValues=True)
        ti.startTime = t_approach
    else:
        t_approach = 0.0
    ti.numberOfSteps = max(1, math.ceil((end_time - t_approach) / step))
    ti.endTime = t_approach + ti.numberOfSteps * step
    ss.solution.sensors.writePeriod = step
    exu.SolveDynamic(mbs, ss, solverType=exu.DynamicSolverType.RK44)

    force = np.asarray(mbs.GetSensorStoredData(s_force), dtype=float)
    pos = np.asarray(mbs.GetSensorStoredData(s_pos), dtype=float)
    vel = np.asarray(mbs.GetSensorStoredData(s_vel), dtype=float)
    e = pos[:, 1:3]
    ecc = np.linalg.norm(e, axis=1)
    normal = e / np.where(ecc > 0.0, ecc, 1.0)[:, None]
    return {
        "t": pos[:, 0],
        "d": ecc - clearance,
        "dd": np.einsum("ij,ij->i", vel[:, 1:3], normal),
        # Exudyn's Force output is the force the wall exerts on the journal (along -n while
        # compressive): F_n = -Force . n
        "force": -np.einsum("ij,ij->i", force[:, 1:3], normal),
        "speed": np.linalg.norm(vel[:, 1:3], axis=1),
    }


def exudyn_pin_impact(*, mass: float, stiffness: float, exponent: float, restitution: float,
                      law: str, clearance: float, journal_radius: float, impact_speed: float,
                      step: float = 1e-7) -> dict[str, float]:
    """Simulate one pin-in-hole impact in Exudyn (see the module docstring for the mapping).

    Returns ``rebound_speed`` (m/s, after separation), ``peak_force`` (N), ``contact_duration``
    (s, from first d > 0 to separation, both located by Hermite interpolation between steps)
    and ``peak_penetration`` (m).
    """
    if law not in HYSTERESIS_FACTOR:
        raise ValueError(f"unknown law {law!r}; expected one of {sorted(HYSTERESIS_FACTOR)}")
    if not 0.0 < restitution <= 1.0:
        raise ValueError(f"restitution must be in (0, 1], got {restitution}")
    if min(mass, stiffness, exponent, clearance, journal_radius, impact_speed, step) <= 0.0:
        raise ValueError("all physical parameters and the step must be positive")
    x = HYSTERESIS_FACTOR[law](restitution)
    e_res = exudyn_restitution(x)
    assert math.isclose(exudyn_damping_factor(e_res), x, rel_tol=1e-12, abs_tol=1e-15)

    t_flight = clearance / impact_speed
    t_contact = hertz_duration(mass=mass, stiffness=stiffness, exponent=exponent,
                               speed=impact_speed)
    span = 2.0 * t_contact
    for _ in range(8):  # damped impacts can outlast the elastic one: extend until separation
        r = _simulate(mass=mass, stiffness=stiffness, exponent=exponent, e_res=e_res,
                      clearance=clearance, journal_radius=journal_radius,
                      impact_speed=impact_speed, step=step, end_time=t_flight + span)
        t, d, dd = r["t"], r["d"], r["dd"]
        inside = np.flatnonzero(d > 0.0)
        if inside.size:
            k_on = int(inside[0]) - 1  # last sample before the first contact
            gaps = np.flatnonzero(d[k_on + 1:] <= 0.0)
            # separated, with a free-flight sample recorded after it
            if gaps.size:
                k_off = k_on + int(gaps[0])  # last sample inside the first contact
                break
        span *= 2.0
    else:
        raise RuntimeError("no separation found; the impact does not end")

    first = slice(k_on, k_off + 2)  # the first contact with one sample either side
    return {
        "rebound_speed": float(r["speed"][k_off + 1]),  # free flight: constant until next hit
        "peak_force": _peak(r["force"][first]),
        "contact_duration": _crossing(t, d, dd, k_off) - _crossing(t, d, dd, k_on),
        "peak_penetration": _peak(d[first]),
    }
