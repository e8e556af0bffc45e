"""A robot's parameters by name: the parameter-vector names of its fields, the
``jointN.clearance`` aliases, the error for an unknown name, and copies of a robot with named
parameters changed (:func:`with_parameters`)."""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import replace
from typing import TYPE_CHECKING, Any

from jointplay.common.errors import DescriptionError, combined
from jointplay.common.hints import did_you_mean
from jointplay.robot.structure import Parameter

if TYPE_CHECKING:
    from jointplay.robot.description import Robot


def _index(parameter: Parameter) -> int:
    if parameter.index is None:
        raise ValueError(f"parameter {parameter.name} names no link or joint")
    return parameter.index


def parameter_name(field_name: str) -> str:
    """The parameter-vector name of a robot field: ``links[2].mass`` -> ``link2.mass``,
    ``gravity.vector.y`` -> ``gravity.y`` (other names are the same in both)."""
    m = re.fullmatch(r"(links|joints)\[(\d+)\]\.(\w+)", field_name)
    if m:
        return f"{m.group(1)[:-1]}{m.group(2)}.{m.group(3)}"
    if field_name.startswith("gravity.vector."):
        return f"gravity.{field_name.rsplit('.', 1)[1]}"
    return field_name


def unknown_parameter(name: str, robot: Robot) -> DescriptionError:
    """The error for a name that is no parameter of ``robot``: the nearest parameter, or, for
    an initial coordinate or speed (``q2``, ``dex3``), where those are set."""
    from jointplay.robot.structure import coordinate_layout

    coords = [c.name for c in coordinate_layout(robot.structure())]
    if name in coords or (name.startswith("d") and name[1:] in coords):
        return DescriptionError(name, "is an initial value, not a robot parameter: set it in "
                                "the scene's [initial] table (in Python: "
                                f"scene.with_initial({name}=...))")
    known = [p.name for p in robot.parameters()] + clearance_aliases(robot)
    match = CLEARANCE_ALIAS.fullmatch(name)
    if match:
        joints = ", ".join(map(str, robot.clearance_joints)) or "none"
        return DescriptionError(name, f"joint {match.group(1)} has no clearance (joints with "
                                f"clearance: {joints})" + did_you_mean(name, known))
    return DescriptionError(name, "is not a parameter of this model"
                            + did_you_mean(name, known))


CLEARANCE_ALIAS = re.compile(r"joint(\d+)\.clearance")
"""``jointN.clearance``: the radial clearance of joint N (bearing_radius - journal_radius),
a name accepted wherever parameters are set by name; setting it moves the journal radius and
holds the bearing radius (or the bearing radius given beside it)."""


def clearance_aliases(robot: Robot) -> list[str]:
    """The ``jointN.clearance`` names of ``robot``'s joints with play."""
    return [f"joint{j}.clearance" for j in robot.clearance_joints]


def resolve_aliases(robot: Robot, values: Mapping[str, Any]) -> dict[str, Any]:
    """``values`` with every ``jointN.clearance`` replaced by the journal radius it means
    (``bearing_radius - clearance``, the bearing radius given beside it or ``robot``'s).
    Raises :class:`DescriptionError` for an alias beside its own journal radius."""
    out = {k: v for k, v in values.items() if not CLEARANCE_ALIAS.fullmatch(str(k))}
    for name, value in values.items():
        match = CLEARANCE_ALIAS.fullmatch(str(name))
        if not match or name not in clearance_aliases(robot):
            if match:
                out[name] = value  # refused below as unknown, with the joints that have play
            continue
        j = int(match.group(1))
        if f"joint{j}.journal_radius" in values:
            raise DescriptionError(name, f"sets joint{j}.journal_radius, which is also given: "
                                   "give one of them")
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise DescriptionError(name, f"must be a number, got {value!r}")
        bearing = values.get(f"joint{j}.bearing_radius", robot.joints[j - 1].bearing_radius)
        if not 0 < float(value) < float(bearing):
            raise DescriptionError(name, f"must be a radial clearance between 0 and the bearing "
                                   f"radius ({float(bearing):g} m), got {value!r}; use kind = "
                                   "\"ideal\" for no play")
        out[f"joint{j}.journal_radius"] = float(bearing) - float(value)
    return out


def with_parameters(robot: Robot, values: Mapping[str, float]) -> Robot:
    """A copy of ``robot`` with named parameters changed (structure unchanged).

    Parameters
    ----------
    robot : Robot
        The robot.
    values : mapping of str to float
        New values by parameter name (``"link2.mass"``, ``"friction.mu"``; the names of
        :meth:`~jointplay.robot.description.Robot.parameters`); the ``jointN.clearance``
        aliases are accepted (the radial clearance, bearing radius held;
        :data:`CLEARANCE_ALIAS`).

    Returns
    -------
    Robot
        The changed, validated copy.

    Raises
    ------
    DescriptionError
        For an unknown name or a value out of range.
    """
    derived = {f"joint{m.group(1)}.journal_radius": str(name) for name in values
               if (m := CLEARANCE_ALIAS.fullmatch(str(name)))}
    values = resolve_aliases(robot, values)
    try:
        return _with_parameters(robot, values)
    except DescriptionError as err:
        if not derived:
            raise
        problems = [DescriptionError(derived[parameter_name(e.field)], "leaves "
                                     f"{parameter_name(e.field)} (bearing_radius - clearance)"
                                     f" that {e.message}", e.source)
                    if parameter_name(e.field) in derived else e for e in err.problems]
        raise combined(problems) from None


def _with_parameters(robot: Robot, values: Mapping[str, float]) -> Robot:
    known = {p.name: p for p in robot.parameters()}
    links = [vars(link).copy() for link in robot.links]
    joints = [vars(j).copy() for j in robot.joints]
    effects = {"contact": vars(robot.contact).copy(), "friction": vars(robot.friction).copy(),
               "lubrication": vars(robot.lubrication).copy(), "wear": vars(robot.wear).copy()}
    gravity = list(robot.gravity.vector)
    payload = robot.payload_mass
    unknown = [unknown_parameter(name, robot) for name in values if name not in known]
    for name, value in values.items():
        if name not in known:
            continue
        prm = known[name]
        if prm.owner == "link":
            links[_index(prm) - 1][prm.attribute] = value
        elif prm.owner == "joint":
            joints[_index(prm) - 1][prm.attribute] = value
        elif prm.owner == "payload":
            payload = value
        elif prm.owner == "gravity":
            gravity["xy".index(prm.attribute)] = value
        else:
            effects[prm.owner][prm.attribute] = value
    try:
        changed = _rebuilt(robot, links, joints, effects, gravity, payload)
    except DescriptionError as err:
        raise combined([*unknown, err]) from None
    if unknown:
        raise combined(unknown)
    return changed


def _rebuilt(robot: Robot, links: list[dict[str, Any]], joints: list[dict[str, Any]],
             effects: dict[str, dict[str, Any]], gravity: list[float], payload: float) -> Robot:
    # Imported here: the description module imports this one for its parameter vector.
    from jointplay.robot.description import (
        Contact,
        Friction,
        Gravity,
        Joint,
        Link,
        Lubrication,
        Wear,
    )

    return replace(
        robot,
        links=tuple(Link(**d) for d in links),
        joints=tuple(Joint(**d) for d in joints),
        gravity=Gravity(robot.gravity.enabled, (gravity[0], gravity[1])),
        contact=Contact(**effects["contact"]),
        friction=Friction(**effects["friction"]),
        lubrication=Lubrication(**effects["lubrication"]),
        wear=Wear(**effects["wear"]),
        payload_mass=payload,
    )
