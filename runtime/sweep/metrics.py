"""A case's summary numbers: the tip's error against the ideal-joint run, the located contact
peaks, energy and integrator work (the columns of the sweep table)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from jointplay.results.records import SimulationResult

# Contact columns from the contact-phase table (located, never sampled), overall and per
CONTACT_METRICS: tuple[tuple[str, str], ...] = (
    ("peak_normal_force", "float"), ("max_penetration", "float"), ("impacts", "int"),
    ("max_approach_speed", "float"))


# Columns of a case checked at 10x tighter tolerances (sweeps run with verify): the accuracy
# statement's estimated tip error (m), agreement horizon (s) and energy residual (J).
ACCURACY_METRICS: tuple[tuple[str, str], ...] = (
    ("tip_error_estimate", "float"), ("agreement_horizon", "float"),
    ("accuracy_energy_residual", "float"))


def accuracy_metrics(result: SimulationResult) -> dict[str, Any]:
    """The accuracy columns of a verified case (empty without a statement)."""
    acc = result.accuracy
    if acc is None:
        return {}
    return {"tip_error_estimate": acc.tip_error_estimate,
            "agreement_horizon": acc.agreement_horizon,
            "accuracy_energy_residual": acc.energy_residual}


def metric_columns(clearance_joints: Sequence[int], wear: bool = False
                   ) -> list[tuple[str, str]]:
    """(column, type) of the summary metrics, type one of float, int, str (with ``wear``,
    the Archard wear columns of :func:`jointplay.results.wear.wear_metrics` too)."""
    cols = [("max_position_error", "float"), ("max_velocity_error", "float"),
            ("max_acceleration_error", "float"), ("rms_position_error", "float")]
    for name, kind in CONTACT_METRICS:
        cols += [(name, kind)] + [(f"{name}_joint{j}", kind) for j in clearance_joints]
    cols += [("peak_note", "str"), ("implausible", "str"), ("energy_dissipated", "float"),
             ("energy_balance_error", "float")]
    cols += [(name, "int") for name in ("steps", "rhs_evaluations", "jacobian_evaluations",
                                        "error_test_failures", "integrator_calls", "events")]
    cols += [("simulation_time_s", "float"), ("wall_time_s", "float"), ("cpu_time_s", "float")]
    if wear:
        from jointplay.results.wear import WEAR_METRICS

        for name in WEAR_METRICS:
            cols += [(name, "float")] + [(f"{name}_joint{j}", "float") for j in clearance_joints]
    return cols


def case_metrics(result: SimulationResult, ideal: SimulationResult) -> dict[str, Any]:
    def worst(a: np.ndarray, b: np.ndarray) -> float:
        return float(np.max(np.linalg.norm(a - b, axis=1)))

    pos = np.linalg.norm(result.tip_position - ideal.tip_position, axis=1)
    out: dict[str, Any] = {
        "max_position_error": float(np.max(pos)),
        "max_velocity_error": worst(result.tip_velocity, ideal.tip_velocity),
        "max_acceleration_error": worst(result.tip_acceleration, ideal.tip_acceleration),
        "rms_position_error": float(np.sqrt(np.mean(pos**2))),
        "energy_dissipated": float(result.energy["dissipated"][-1]),
        "energy_balance_error": float(np.max(np.abs(result.energy["balance"]))),
        "simulation_time_s": float(result.stats["wall_time_s"]),
    }
    out.update(contact_metrics(result))
    out.update(accuracy_metrics(result))
    if result.wear is not None:
        from jointplay.results.wear import wear_metrics

        out.update(wear_metrics(result.wear))
    for name in ("steps", "rhs_evaluations", "jacobian_evaluations", "error_test_failures",
                 "integrator_calls", "events"):
        out[name] = int(result.stats.get(name, 0))
    # a case kept with run.plausibility = "warn" though it left the physical domain: why
    out["implausible"] = result.implausible
    return out


def _number_or_none(value: float) -> float | None:
    return None if math.isnan(value) else float(value)


def contact_metrics(result: SimulationResult) -> dict[str, Any]:
    """Peak force, max penetration, impact count and largest approach speed, overall and per
    clearance joint, from the contact-phase table; ``peak_note`` says why peaks are None."""
    from jointplay.results.contacts import joint_contacts, overall

    joints = joint_contacts(result)
    out: dict[str, Any] = {"impacts": len(result.impacts)}
    for c in joints:
        out[f"peak_normal_force_joint{c.joint}"] = _number_or_none(c.peak_force)
        out[f"max_penetration_joint{c.joint}"] = _number_or_none(c.max_penetration)
        out[f"impacts_joint{c.joint}"] = c.impacts
        out[f"max_approach_speed_joint{c.joint}"] = _number_or_none(c.max_approach_speed)
    out["peak_normal_force"] = _number_or_none(overall([c.peak_force for c in joints]))
    out["max_penetration"] = _number_or_none(overall([c.max_penetration for c in joints]))
    speeds = [c.max_approach_speed for c in joints if c.impacts]
    out["max_approach_speed"] = max(speeds) if speeds else None
    notes = sorted({f"joint {c.joint}: {c.note}" for c in joints if c.note is not None})
    out["peak_note"] = "; ".join(notes) if notes else None
    return out


