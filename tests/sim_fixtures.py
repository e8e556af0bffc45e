"""Small robots and scenes for simulation tests, sized by parameters (not test files)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from jointplay.results.records import SimulationResult
from jointplay.scene.definition import Scene, scene_from_dict

STEEL_E = 207e9
STEEL_NU = 0.3


def hertz_stiffness(rb: float, rj: float, e: float = STEEL_E, nu: float = STEEL_NU) -> float:
    """K = 4 / (3 (sb + sj)) sqrt(Rb Rj / (Rb - Rj)) for two parts of the same material."""
    sigma = (1 - nu**2) / e
    return 4.0 / (3.0 * 2 * sigma) * math.sqrt(rb * rj / (rb - rj))


def clearance_joint(clearance: float = 30e-6, kind: str = "clearance",
                    bearing_radius: float = 10e-3) -> dict[str, Any]:
    return {"kind": kind, "bearing_radius": bearing_radius,
            "journal_radius": bearing_radius - clearance}


def robot_table(links: int, joints: list[dict[str, Any]], *, law: str = "lankarani-nikravesh",
                restitution: float = 0.9, mu: float = 0.0, ramp: str = "linear",
                gravity: bool = True, payload: float = 0.0, drive: bool = True,
                floor: float = 1e-3) -> dict[str, Any]:
    """A robot description table: uniform 0.3 m, 1 kg rods and the given joints."""
    return {
        "name": f"test_{links}link",
        "links": [{"length": 0.3, "mass": 1.0, "inertia": 0.0075, "com": 0.15}] * links,
        "joints": joints,
        "payload": {"mass": payload},
        "gravity": {"enabled": gravity, "vector": [0.0, -9.81]},
        "contact": {"law": law, "exponent": 1.5, "restitution": restitution,
                    "impact_speed_floor": floor},
        "friction": {"law": "coulomb" if mu > 0 else "none", "ramp": ramp, "mu": max(mu, 0.0),
                     "v0": 1e-4, "v1": 1e-2},
        "drive": {"enabled": drive},
    }


def make_scene(robot: dict[str, Any], *, torques: dict[str, str] | None = None,
               initial: dict[str, Any] | None = None, **run: Any) -> Scene:
    run = {"t_end": 0.2, "output_step": 1e-3, "rtol": 1e-8, "atol": 1e-8, **run}
    data = {"name": robot["name"], "robot": robot, "torques": torques or {},
            "initial": initial or {}, "run": run}
    return scene_from_dict(data, source="test")


def pin_in_bearing(*, law: str = "lankarani-nikravesh", restitution: float = 1.0,
                   clearance: float = 30e-6, mass: float = 2.0, mu: float = 0.0,
                   floor: float = 1e-3) -> dict[str, Any]:
    """A free body (no rotation) whose journal floats in a bearing on the ground: one link,
    joint 1 locked with play. No gravity, no drive."""
    table = robot_table(1, [clearance_joint(clearance, "locked_clearance") | {"angle": 0.0}],
                        law=law, restitution=restitution, mu=mu, gravity=False, drive=False,
                        floor=floor)
    table["links"] = [{"length": 0.1, "mass": mass, "inertia": 1e-3, "com": 0.05}]
    return table


def energy_scale(result: SimulationResult) -> float:
    """The energy that moved during a run: what a balance error is relative to."""
    e = result.energy
    return float(np.ptp(e["total"]) + np.max(np.abs(e["drive_work"])) + e["dissipated"][-1]
                 + np.max(e["kinetic"]))


def relative_balance(result: SimulationResult) -> float:
    return float(np.max(np.abs(result.energy["balance"])) / energy_scale(result))


def assert_finite(result: SimulationResult) -> None:
    for name in ("q", "u", "udot", "tip_position", "tip_velocity", "tip_acceleration",
                 "penetration", "normal_force", "friction_force", "sliding_speed"):
        value = getattr(result, name)
        assert np.all(np.isfinite(value)), f"{name} is not finite"
    for name, value in result.energy.items():
        assert np.all(np.isfinite(value)), f"energy {name} is not finite"


def restitution_closed_form(x: float) -> float:
    """The exact restitution of one impact under F = F_e(d) (1 + x d'/v-), any elastic law.

    With U the elastic potential (dU = F_e dd) and s = d'/v-, one impact obeys
    m v-^2 s ds/dU = -(1 + x s); U returns to 0 when s has gone from 1 to -e, so
    int_1^-e s / (1 + x s) ds = 0, i.e. x (1 + e) = ln((1 + x) / (1 - x e)) (x e < 1 keeps
    the force non-negative, so the clipping at 0 never acts). Solved for e by bracketing.
    """
    from scipy import optimize

    if x == 0:
        return 1.0

    def residual(e: float) -> float:
        return x * (1 + e) - math.log((1 + x) / (1 - x * e))

    upper = min(1.0, 1 / x) * (1 - 1e-15)
    return float(optimize.brentq(residual, 0.0, upper, xtol=1e-17, rtol=1e-15))
