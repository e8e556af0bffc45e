"""The compile-time part of a mechanism and, from it alone, its coordinates and parameters.

A mechanism is a tree of rigid bodies rooted at the ground (revolute joints that are ideal or
locked, prismatic joints), closed into loops by *cut* joints, each a revolute joint with
clearance: cut there, a loop holds a force element between two body points (the journal's
centre minus the bearing's centre is the eccentricity), so the equations stay ODEs in the
tree's coordinates. A prescribed-motion driver fixes one revolute joint's angle as a function
of time; the model carries a clock coordinate (t itself, integrated exactly: t'' = 0 with
t' = 1) so that every compiled function, the contact laws' included, sees the driver's angle
without a time input.

Everything here is sympy-free: the derivation (:mod:`jointplay.derive.mechanism`) and the
runtime read the same lists, in the same order.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

# The name of the clock coordinate (s): always the last coordinate.
CLOCK = "t"


@dataclass(frozen=True)
class JointStructure:
    """One joint as the generated code sees it: which bodies, which kind, tree or cut."""

    name: str
    type: str  # "revolute" | "prismatic" | "floating" (a body held by clearance joints only)
    kind: str  # revolute: "ideal" | "clearance" | "locked"; prismatic: "ideal"; "free"
    parent: str  # a body's name or "ground"; the bearing's side of a clearance joint
    child: str  # the journal's side of a clearance joint
    cut: bool  # closes a loop (a clearance joint, a force element)
    driven: bool = False

    def as_dict(self) -> dict[str, Any]:
        return {"name": self.name, "type": self.type, "kind": self.kind,
                "parent": self.parent, "child": self.child, "cut": self.cut,
                "driven": self.driven}


@dataclass(frozen=True)
class MechanismStructure:
    """What changes the generated code: bodies, joints in tree order (a tree joint's parent
    is the ground or a body placed by an earlier joint), the driver's law, the effects.

    ``driver_angle`` is None for the constant-speed law (angle = driver.start + driver.speed
    t, both runtime parameters) or the text of an angle expression of t (compiled in)."""

    bodies: tuple[str, ...]
    joints: tuple[JointStructure, ...]
    gravity: bool
    contact_law: str | None
    friction_law: str
    friction_ramp: str | None
    driver_angle: str | None = None
    # Applied loads, their values expressions of t given at run time: torques on these
    # revolute joints (on the child, the reaction on the parent), then forces (name, body)
    # at a body's point, in the ground's axes: the model's input tau, in this order
    # (each torque, then each force's x and y).
    torque_joints: tuple[str, ...] = ()
    forces: tuple[tuple[str, str], ...] = ()

    # laws.contact_terms reads these of a structure; a mechanism has neither.
    contact_stiffness = None
    lubrication = None
    wear = None

    @property
    def driver(self) -> JointStructure | None:
        return next((j for j in self.joints if j.driven), None)

    @property
    def cut_joints(self) -> tuple[JointStructure, ...]:
        return tuple(j for j in self.joints if j.cut)

    @property
    def tree_joints(self) -> tuple[JointStructure, ...]:
        return tuple(j for j in self.joints if not j.cut)

    def as_dict(self) -> dict[str, Any]:
        """The canonical form: hashed into the model's stamp, written to its layout."""
        return {"kind": "mechanism", "bodies": list(self.bodies),
                "joints": [j.as_dict() for j in self.joints], "gravity": self.gravity,
                "contact_law": self.contact_law,
                "friction": (f"{self.friction_law}-{self.friction_ramp}"
                             if self.friction_ramp else "none"),
                "driver_angle": self.driver_angle,
                **({"torques": list(self.torque_joints)} if self.torque_joints else {}),
                **({"forces": [list(f) for f in self.forces]} if self.forces else {})}

    @property
    def load_inputs(self) -> list[str]:
        """The names of the entries of the input tau (N m, N)."""
        return [f"torques.{j}" for j in self.torque_joints] + [
            f"forces.{name}.{axis}" for name, _ in self.forces for axis in ("x", "y")]


@dataclass(frozen=True)
class MechanismCoordinate:
    name: str  # "<joint>.angle", "<joint>.position", or "t"
    unit: str
    joint: str | None


def coordinates(structure: MechanismStructure) -> list[MechanismCoordinate]:
    """The tree's free coordinates in joint order, then the clock."""
    out = []
    for joint in structure.tree_joints:
        if joint.driven or joint.kind == "locked":
            continue
        if joint.type == "floating":
            out += [MechanismCoordinate(f"{joint.name}.x", "m", joint.name),
                    MechanismCoordinate(f"{joint.name}.y", "m", joint.name),
                    MechanismCoordinate(f"{joint.name}.angle", "rad", joint.name)]
        elif joint.type == "revolute":
            out.append(MechanismCoordinate(f"{joint.name}.angle", "rad", joint.name))
        else:
            out.append(MechanismCoordinate(f"{joint.name}.position", "m", joint.name))
    out.append(MechanismCoordinate(CLOCK, "s", None))
    return out


def parameter_names(structure: MechanismStructure) -> list[str]:
    """Every number the model takes at run time, in slot order."""
    out: list[str] = []
    for body in structure.bodies:
        out += [f"{body}.mass", f"{body}.inertia", f"{body}.com_x", f"{body}.com_y"]
    if structure.gravity:
        out += ["gravity.x", "gravity.y"]
    for joint in structure.joints:
        j = joint.name
        if joint.type == "floating":
            continue
        out += [f"{j}.parent_x", f"{j}.parent_y", f"{j}.child_x", f"{j}.child_y"]
        if joint.type == "prismatic":
            out += [f"{j}.axis_x", f"{j}.axis_y", f"{j}.angle"]
        elif joint.kind == "locked":
            out.append(f"{j}.angle")
        elif joint.kind == "clearance":
            out += [f"{j}.{key}" for key in CLEARANCE_KEYS]
    for name, _ in structure.forces:
        out += [f"{name}.at_x", f"{name}.at_y"]
    if structure.driver is not None and structure.driver_angle is None:
        out += ["driver.start", "driver.speed"]
    if structure.contact_law is not None:
        out += ["contact.exponent", "contact.restitution", "contact.impact_speed_floor"]
    if structure.friction_ramp is not None:
        out += ["friction.mu", "friction.v0", "friction.v1"]
    return out


CLEARANCE_KEYS = ("bearing_radius", "journal_radius", "bearing_E", "bearing_nu", "journal_E",
                  "journal_nu")
