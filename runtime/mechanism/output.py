"""The output a mechanism run follows: the coordinate its summary and its first figures show.

A slider-crank's reader looks at the slider, a four-bar's at the rocker: the output link, the
one the driver moves the mechanism for. A file names it (``[output] coordinate = "..."``);
without one, :func:`default_output` picks it by a rule that needs only the structure:

1. the first prismatic joint's travel (a slider: ``guide.position``);
2. otherwise the last body, in the file's order, pivoted on the ground by a revolute joint
   that is not driven (a rocker): its angle from the ground, the pivot's coordinate when the
   pivot is an ideal joint (``rocker_pivot.angle``), the body's own when the body floats
   (``rocker.angle``, a clearance pivot);
3. otherwise the last angle among the coordinates (the link placed last);
4. otherwise the first coordinate.

The clock ``t`` is never an output.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from jointplay.mechanism.structure import CLOCK, coordinates

if TYPE_CHECKING:
    from jointplay.mechanism.description import Mechanism


def default_output(mechanism: Mechanism) -> str:
    """The coordinate a run follows when its file names none (the rule above)."""
    structure = mechanism.structure()
    names = [c.name for c in coordinates(structure) if c.name != CLOCK]
    for joint in mechanism.joints:
        if joint.type == "prismatic":
            return f"{joint.name}.position"
    floating = {j.child for j in structure.tree_joints if j.type == "floating"}
    driven = mechanism.driver.joint if mechanism.driver else None
    pivots = [j for j in mechanism.joints
              if j.type == "revolute" and j.parent == "ground" and j.name != driven]
    for joint in reversed(pivots):
        if joint.kind == "clearance" and joint.child in floating:
            return f"{joint.child}.angle"
        if joint.kind == "ideal":
            return f"{joint.name}.angle"
    angles = [name for name in names if name.endswith(".angle")]
    if angles:
        return angles[-1]
    return names[0] if names else CLOCK


def figure_stem(name: str, unit: str) -> tuple[str, str]:
    """The figures' file-name stem and the axis's word for an output coordinate: "slider"
    for a prismatic joint's travel, else the coordinate's name (``rocker_angle``)."""
    if unit == "m" and name.endswith(".position"):
        return "slider", "slider"
    return name.replace(".", "_"), name


def followed(output: str, names: list[str]) -> str:
    """The coordinate a result follows: its recorded ``output``; for a result that records
    none, the first slider, else the last angle, else the first coordinate (rules 1, 3, 4
    on the names alone)."""
    if output in names:
        return output
    free = [name for name in names if name != CLOCK]
    sliders = [name for name in free if name.endswith(".position")]
    angles = [name for name in free if name.endswith(".angle")]
    return (sliders[:1] or angles[-1:] or free[:1] or names[:1])[0]
