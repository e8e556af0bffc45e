"""A scene's ``[initial]`` table: the coordinates and speeds it may name, their values checked
(known names, finite, physically plausible, journals inside their bearings), and how the
journals start (``journals = "centred"`` or ``"resting"``, and what a resting start needs)."""

from __future__ import annotations

import functools
import math
from collections.abc import Mapping
from typing import Any

from jointplay.common import limits
from jointplay.common.errors import DescriptionError
from jointplay.common.hints import did_you_mean
from jointplay.common.validation import Problems, plausible
from jointplay.robot import Robot
from jointplay.robot.structure import Structure, coordinate_layout
from jointplay.scene.expressions import parse_expression


def _error(field_name: str, message: str, source: str | None) -> DescriptionError:
    return DescriptionError(field_name, message, source)


def finite_number(value: Any, where: str, source: str | None) -> float:
    try:  # an integer beyond float64 (10**400) is no finite float either
        number = float(value) if isinstance(value, (int, float)) else math.nan
    except OverflowError:
        number = math.inf
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(number):
        shown = repr(value)
        shown = shown if len(shown) <= 40 else f"{shown[:20]}... ({len(shown)} characters)"
        raise _error(where, f"must be a finite number in SI units, got {shown}", source)
    return number


def coordinate_names(robot: Robot) -> list[str]:
    """Generalised coordinates in model order: moving angles, then (ex, ey) per clearance."""
    return list(_coordinates_of(robot.structure()))


@functools.lru_cache(maxsize=64)
def _coordinates_of(structure: Structure) -> tuple[str, ...]:
    # Every scene built checks its initial state against these: computed once per structure.
    return tuple(c.name for c in coordinate_layout(structure))


def initial_numbers(raw: Any, constants: Mapping[str, float],
                     source: str | None) -> dict[str, Any]:
    """``[initial]`` as read: constant expressions (``"-pi/2"``) evaluated; the values are
    checked by :func:`validate_initial`."""
    if not isinstance(raw, Mapping):
        raise _error("initial", f"must be a table, got {type(raw).__name__}", source)
    problems = Problems()
    out: dict[str, Any] = {}
    for key, value in raw.items():
        with problems.check():
            if isinstance(value, str):
                expr = parse_expression(value, field=f"initial.{key}", constants=constants,
                                        source=source)
                if not expr.is_constant:
                    raise _error(f"initial.{key}", "must not depend on t", source)
                value = float(expr.numpy(0.0))
            out[key] = value
    problems.raise_any(source)
    return out


def _initial_kind(key: str) -> str:
    """The PHYSICAL_RANGES kind of an initial value (eccentricities: the clearance bound)."""
    if key.startswith("dq"):
        return "initial.speed"
    if key.startswith("de"):
        return "initial.eccentricity_rate"
    return "initial.angle"


def validate_initial(values: Any, robot: Robot) -> dict[str, float]:
    """The initial state's values, every one checked: a known coordinate or speed of the robot
    (did-you-mean otherwise), a finite number in its physical range, and each journal inside
    its bearing. All problems are reported together."""
    if not isinstance(values, Mapping):
        raise _error("initial", f"must be a mapping of names to numbers, got "
                     f"{type(values).__name__}", None)
    coords = coordinate_names(robot)
    allowed = (*coords, *[f"d{c}" for c in coords])
    problems = Problems()
    out: dict[str, float] = {}
    for key, value in values.items():
        with problems.check():
            if key not in allowed:
                raise _error(f"initial.{key}", f"unknown key (allowed: {', '.join(allowed)})"
                             f"{did_you_mean(str(key), allowed)}", None)
            number = finite_number(value, f"initial.{key}", None)
            if not key.startswith("e"):  # eccentricities: the clearance bound below
                plausible(f"initial.{key}", number, _initial_kind(key))
            out[key] = number
    for j, joint in enumerate(robot.joints, start=1):
        if joint.has_clearance:
            with problems.check():
                ex, ey = out.get(f"ex{j}", 0.0), out.get(f"ey{j}", 0.0)
                clearance = joint.bearing_radius - joint.journal_radius
                # Inside means |e| <= c, or pressed elastically into the wall as a loaded
                # journal at rest is (sub-micrometre on the built-in robot): at most
                # INITIAL_PENETRATION_FRACTION of c beyond it. Deeper, the journal would
                # start inside the wall.
                if math.hypot(ex, ey) > clearance * (1 + INITIAL_PENETRATION_FRACTION):
                    raise _error(f"initial.ex{j}", "the journal must start inside its bearing: "
                                 f"|e| = {math.hypot(ex, ey):g} m, at most the radial "
                                 f"clearance ({clearance:g} m) plus an elastic "
                                 f"{INITIAL_PENETRATION_FRACTION:.0%} of it", None)
    problems.raise_any()
    return out



INITIAL_PENETRATION_FRACTION = 0.1
"""How far, as a fraction of the radial clearance, an initial eccentricity may press the journal
into its bearing: an elastic start (a resting journal's penetration), never one inside the wall."""
JOURNAL_STARTS = ("centred", "resting")


def check_journals(journals: Any, initial: Mapping[str, float], source: str | None) -> None:
    if journals not in JOURNAL_STARTS:
        raise _error("initial.journals", f"must be one of {', '.join(JOURNAL_STARTS)}, got "
                     f"{journals!r}", source)
    if journals == "resting":
        given = sorted(k for k, v in initial.items()
                       if (k.startswith("d") or k.startswith(("ex", "ey"))) and v != 0)
        if given:
            raise _error("initial.journals", "\"resting\" starts at rest with the journals "
                         "where they rest: leave out the speeds and eccentricities "
                         f"({', '.join(given)})", source)


def check_resting(journals: str, robot: Robot) -> None:
    """"resting" is solved at run time (the static equilibrium: each journal carries the
    weight beyond it, the drives hold the arm): what it needs is checked now, before any
    model is compiled."""
    if journals != "resting" or not any(j.has_clearance for j in robot.joints):
        return
    if not robot.drive:
        raise _error("initial.journals", "\"resting\" holds the arm still with its drive "
                     "torques: enable [robot.drive], or start the journals \"centred\" or at "
                     "given eccentricities", None)
    if not robot.gravity.enabled or not any(robot.gravity.vector):
        raise _error("initial.journals", "\"resting\" rests each journal on its bearing "
                     "under gravity: enable [robot.gravity], or start the journals "
                     "\"centred\" or at given eccentricities", None)


def check_resting_depth(robot: Robot) -> None:
    """Refuse a resting start whose journals would rest deeper in their bearings than the
    penetration stop allows (a payload of 1e5 kg, say), before any model is compiled.

    At rest each clearance joint carries the weight of every link beyond it and the payload,
    along gravity (the drive torques are moments), so the static penetration follows from
    the Hertz law in closed form, delta = (W / K)^(1/n), with the pin-in-hole stiffness
    K = 4 / (3 (s_b + s_j)) sqrt(R_b R_j / (R_b - R_j)), s = (1 - nu^2) / E. Only the Hertz
    law of dry joints is estimated here; the others are checked at the run's first output."""
    if robot.contact.stiffness != "hertz" or robot.lubrication.model != "none":
        return
    g = math.hypot(*robot.gravity.vector)
    for j, joint in enumerate(robot.joints, start=1):
        if not joint.has_clearance:
            continue
        weight = g * (sum(link.mass for link in robot.links[j - 1:]) + robot.payload_mass)
        soft = ((1 - joint.bearing_nu ** 2) / joint.bearing_E
                + (1 - joint.journal_nu ** 2) / joint.journal_E)
        stiffness = 4.0 / (3.0 * soft) * math.sqrt(
            joint.bearing_radius * joint.journal_radius
            / (joint.bearing_radius - joint.journal_radius))
        depth = (weight / stiffness) ** (1.0 / robot.contact.exponent)
        bound = limits.MAX_PENETRATION_FRACTION * joint.journal_radius
        if depth > bound:
            raise _error("initial.journals", f"\"resting\": joint {j}'s journal would rest "
                         f"{depth * 1e6:.4g} um deep in its bearing under the {weight:.4g} N "
                         f"beyond it (Hertz), beyond the {bound * 1e6:.4g} um "
                         f"({100 * limits.MAX_PENETRATION_FRACTION:g} % of its radius) the "
                         "contact law describes: check the masses and the payload (or keep "
                         "such a run with [run] plausibility = \"warn\")", None)
