"""Choosing a contact stiffness law for a robot from outside its file (benches, scripts).

The elastic law is part of the robot description (``[contact] stiffness``, with each clearance
joint's ``length`` for the cylindrical laws). Comparisons of the laws on one scene need the
same robot under each law; :func:`with_stiffness` makes that copy, giving clearance joints
without a length :data:`DEFAULT_LENGTH`.
"""

from __future__ import annotations

from dataclasses import replace

from jointplay.common.errors import DescriptionError
from jointplay.robot.description import CONTACT_STIFFNESSES, Robot

# Axial length given to clearance joints that have none, when a comparison switches a robot
# to a cylindrical law: 20 mm, a journal as long as its diameter at the default 10 mm radius.
DEFAULT_LENGTH = 0.02


def with_stiffness(robot: Robot, stiffness: str, length: float = DEFAULT_LENGTH) -> Robot:
    """``robot`` with ``contact.stiffness`` set; clearance joints without a length get
    ``length`` (m). Validated like any description."""
    joints = tuple(replace(j, length=length) if j.has_clearance and j.length is None else j
                   for j in robot.joints)
    suffix = "" if stiffness == "hertz" else f"_{stiffness}"
    return replace(robot, joints=joints, name=f"{robot.name}{suffix}",
                   contact=replace(robot.contact, stiffness=stiffness))  # type: ignore[arg-type]


def parse_stiffnesses(text: str, flag: str) -> list[str]:
    """``"hertz,johnson"`` -> ``["hertz", "johnson"]``, each a known law, none twice."""
    out: list[str] = []
    for part in (p.strip() for p in text.split(",")):
        if not part:
            continue
        if part not in CONTACT_STIFFNESSES:
            raise DescriptionError(flag, f"unknown contact stiffness {part!r}; choose from "
                                         f"{', '.join(CONTACT_STIFFNESSES)}")
        if part in out:
            raise DescriptionError(flag, f"{part!r} is given twice")
        out.append(part)
    if not out:
        raise DescriptionError(flag, "no contact stiffness given")
    return out
