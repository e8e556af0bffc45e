"""The typed description of a mechanism scene, its topology check and its numbers.

:meth:`Mechanism.structure` decides the generated code (which joint is cut, which driven);
:meth:`Mechanism.parameter_values` gives the runtime parameters in slot order. Topology: the
joints that are not clearance joints must form a forest reaching every body from the ground
(a loop closed only by ideal or locked joints, or by a prismatic joint, is refused: it would
need constraint equations); each clearance joint then closes a loop and is cut, a force
element between its bearing (on the parent) and its journal (on the child).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Any, cast

from jointplay.common.errors import DescriptionError
from jointplay.common.hints import did_you_mean
from jointplay.common.limits import MAX_FIXED_STEPS
from jointplay.mechanism.structure import (
    CLEARANCE_KEYS,
    JointStructure,
    MechanismStructure,
    parameter_names,
)

GROUND = "ground"
# dataclasses.replace with field names chosen at run time (each checked before the call).
_replace = cast(Any, dataclasses.replace)
# run.output_step must divide run.t_end within this relative tolerance.
_DIVIDES = 1e-9


@dataclass(frozen=True)
class Body:
    name: str
    mass: float  # kg
    inertia: float  # kg m^2 about the centre of mass
    com: tuple[float, float]  # m, the centre of mass in the body's frame


@dataclass(frozen=True)
class Joint:
    name: str
    type: str  # revolute | prismatic
    kind: str  # ideal | clearance | locked
    parent: str
    child: str
    at_parent: tuple[float, float]  # m, in the parent's frame
    at_child: tuple[float, float]  # m, in the child's frame
    angle: float = 0.0  # rad: a locked joint's angle; a prismatic child's fixed angle
    axis: tuple[float, float] = (1.0, 0.0)  # unit sliding direction in the parent's frame
    clearance: dict[str, float] = field(default_factory=dict)

    @property
    def radial_clearance(self) -> float:
        return self.clearance["bearing_radius"] - self.clearance["journal_radius"]


@dataclass(frozen=True)
class Driver:
    joint: str
    angle: str | None  # an expression of t (rad), or None for start + speed t
    speed: float  # rad/s
    start: float  # rad


@dataclass(frozen=True)
class Force:
    """A force (N) at a body's point (m, in the body's frame), in the ground's axes; its
    components are expressions of t."""

    name: str
    body: str
    at: tuple[float, float]
    x: str
    y: str


INTEGRATORS = ("bdf", "rk4", "radau")
"""A mechanism's integrators: the compiled BDF with located events (the default), or RK4 or
Radau IIA at a fixed step with onsets located between step ends (the serial arms' methods)."""


@dataclass(frozen=True)
class RunSettings:
    t_end: float = 0.012
    output_step: float = 1.0e-5
    rtol: float = 1.0e-6
    atol: float = 1.0e-6  # scaled: rad, and fractions of the smallest radial clearance (m)
    max_steps: int = 200000
    integrator: str = "bdf"
    step: float = 1.0e-7  # s: the fixed step of rk4 and radau; it must divide output_step

    @property
    def n_outputs(self) -> int:
        return round(self.t_end / self.output_step)

    @property
    def steps_per_output(self) -> int:
        return max(1, round(self.output_step / self.step))

    def check(self) -> None:
        n = self.t_end / self.output_step
        if abs(n - round(n)) > _DIVIDES * n or round(n) < 1:
            raise DescriptionError("run.output_step", f"must divide run.t_end ({self.t_end:g} "
                                   f"s) a whole number of times, got {self.output_step:g}")
        if round(n) > 10_000_000:
            raise DescriptionError("run.output_step", "asks for more than 1e7 samples; make "
                                   "it larger")
        if self.integrator not in INTEGRATORS:
            hint = did_you_mean(str(self.integrator), INTEGRATORS)
            raise DescriptionError("run.integrator", f"must be one of {', '.join(INTEGRATORS)} "
                                   f"for a mechanism, got {self.integrator!r}{hint}")
        if self.integrator == "bdf":
            return
        if not (math.isfinite(self.step) and self.step > 0):
            raise DescriptionError("run.step", f"must be > 0, got {self.step!r}")
        if self.step > self.output_step or abs(self.steps_per_output * self.step
                                               - self.output_step) > _DIVIDES * self.output_step:
            raise DescriptionError("run.step", f"the fixed step must divide run.output_step "
                                   f"({self.output_step:g} s), got {self.step:g}")
        if self.t_end / self.step > MAX_FIXED_STEPS:
            raise DescriptionError("run.step", f"gives {self.t_end / self.step:.3g} fixed steps "
                                   f"over run.t_end = {self.t_end:g} s; at most "
                                   f"{MAX_FIXED_STEPS} are allowed")


@dataclass(frozen=True)
class Mechanism:
    name: str
    bodies: tuple[Body, ...]
    joints: tuple[Joint, ...]
    driver: Driver | None
    gravity: tuple[float, float] | None
    contact_law: str
    exponent: float
    restitution: float
    impact_speed_floor: float
    friction_law: str
    friction_ramp: str
    mu: float
    v0: float
    v1: float
    torques: tuple[tuple[str, str], ...] = ()  # (revolute joint, expression of t in N m)
    forces: tuple[Force, ...] = ()

    def check(self) -> None:
        """The topology (see the module docstring); raises naming the joint and the fix."""
        self.structure()

    def structure(self) -> MechanismStructure:
        order = _tree_order(self)
        cut = {j.name for j in self.joints if j.kind == "clearance"}
        driven = self.driver.joint if self.driver else None
        joints = tuple(JointStructure(name=j.name, type=j.type, kind=j.kind, parent=j.parent,
                                      child=j.child, cut=j.name in cut,
                                      driven=j.name == driven)
                       for j in order + [j for j in self.joints if j.name in cut])
        has_clearance = bool(cut)
        friction = has_clearance and self.friction_law != "none"
        return MechanismStructure(
            bodies=tuple(b.name for b in self.bodies), joints=joints,
            gravity=self.gravity is not None,
            contact_law=self.contact_law if has_clearance else None,
            friction_law=self.friction_law if friction else "none",
            friction_ramp=self.friction_ramp if friction else None,
            driver_angle=self.driver.angle if self.driver else None,
            torque_joints=tuple(j for j, _ in self.torques),
            forces=tuple((f.name, f.body) for f in self.forces))

    def load_expressions(self) -> tuple[str, ...]:
        """The applied loads' expressions, in the order of the model's input tau."""
        return tuple(text for _, text in self.torques) + tuple(
            text for f in self.forces for text in (f.x, f.y))

    def parameter_values(self) -> dict[str, float]:
        """Every runtime parameter by name (:func:`parameter_names`' names)."""
        values: dict[str, float] = {}
        for b in self.bodies:
            values |= {f"{b.name}.mass": b.mass, f"{b.name}.inertia": b.inertia,
                       f"{b.name}.com_x": b.com[0], f"{b.name}.com_y": b.com[1]}
        if self.gravity is not None:
            values |= {"gravity.x": self.gravity[0], "gravity.y": self.gravity[1]}
        for j in self.joints:
            values |= {f"{j.name}.parent_x": j.at_parent[0], f"{j.name}.parent_y": j.at_parent[1],
                       f"{j.name}.child_x": j.at_child[0], f"{j.name}.child_y": j.at_child[1],
                       f"{j.name}.axis_x": j.axis[0], f"{j.name}.axis_y": j.axis[1],
                       f"{j.name}.angle": j.angle}
            values |= {f"{j.name}.{k}": j.clearance[k] for k in CLEARANCE_KEYS
                       if k in j.clearance}
        if self.driver is not None:
            values |= {"driver.start": self.driver.start, "driver.speed": self.driver.speed}
        for f in self.forces:
            values |= {f"{f.name}.at_x": f.at[0], f"{f.name}.at_y": f.at[1]}
        values |= {"contact.exponent": self.exponent, "contact.restitution": self.restitution,
                   "contact.impact_speed_floor": self.impact_speed_floor,
                   "friction.mu": self.mu, "friction.v0": self.v0, "friction.v1": self.v1}
        names = parameter_names(self.structure())
        return {name: values[name] for name in names}

    def with_values(self, changes: dict[str, float]) -> Mechanism:
        """A copy with parameters changed by name (``crank.mass``, ``slider_pin.journal_radius``,
        ``friction.mu``...); structure never changes here."""
        names = parameter_names(self.structure())
        out = self
        for name, value in changes.items():
            if name not in names and not name.endswith(".angle") and name in _SWITCHED_OFF:
                raise DescriptionError(name, f"is not in this mechanism's model: "
                                       f"{_SWITCHED_OFF[name]}")
            out = _with_value(out, name, float(value))
        out.check()
        return out


# Parameters of effects a mechanism's file can switch off, and how to switch them on.
_SWITCHED_OFF = {
    **{f"friction.{k}": "its friction is off (mechanism.friction.law = \"none\"); set the "
       "law to \"coulomb\" in the file" for k in ("mu", "v0", "v1")},
    **{f"contact.{k}": "it has no clearance joint" for k in ("exponent", "restitution",
                                                            "impact_speed_floor")},
    **{f"driver.{k}": "its driver has no speed and start (it is an angle expression, or "
       "absent)" for k in ("speed", "start")},
}


def _with_value(m: Mechanism, name: str, value: float) -> Mechanism:
    owner, _, key = name.partition(".")
    if owner in ("contact", "friction"):
        attr = {"exponent": "exponent", "restitution": "restitution",
                "impact_speed_floor": "impact_speed_floor", "mu": "mu", "v0": "v0",
                "v1": "v1"}.get(key)
        if attr is None:
            raise DescriptionError(name, "is no parameter of the mechanism")
        return cast(Mechanism, _replace(m, **{attr: value}))
    if owner == "driver" and m.driver is not None and key in ("speed", "start"):
        return dataclasses.replace(m, driver=_replace(m.driver, **{key: value}))
    for i, b in enumerate(m.bodies):
        if b.name == owner and key in ("mass", "inertia", "com_x", "com_y"):
            if key.startswith("com"):
                com = (value, b.com[1]) if key == "com_x" else (b.com[0], value)
                new = dataclasses.replace(b, com=com)
            else:
                new = _replace(b, **{key: value})
            return dataclasses.replace(m, bodies=(*m.bodies[:i], new, *m.bodies[i + 1:]))
    points = {"parent_x": ("at_parent", 0), "parent_y": ("at_parent", 1),
              "child_x": ("at_child", 0), "child_y": ("at_child", 1)}
    for i, j in enumerate(m.joints):
        if j.name == owner and key in points:
            attr, k = points[key]
            point = list(getattr(j, attr))
            point[k] = value
            new_joint = _replace(j, **{attr: (point[0], point[1])})
            return dataclasses.replace(m, joints=(*m.joints[:i], new_joint, *m.joints[i + 1:]))
        if j.name == owner and key == "angle" and (j.type == "prismatic" or j.kind == "locked"):
            new_joint = dataclasses.replace(j, angle=value)
            return dataclasses.replace(m, joints=(*m.joints[:i], new_joint, *m.joints[i + 1:]))
        if j.name == owner and key in j.clearance:
            new_joint = dataclasses.replace(j, clearance={**j.clearance, key: value})
            return dataclasses.replace(m, joints=(*m.joints[:i], new_joint, *m.joints[i + 1:]))
    raise DescriptionError(name, "is no parameter of the mechanism (a body's mass, inertia, "
                           "com_x, com_y; a joint's parent_x, parent_y, child_x, child_y; a "
                           "clearance joint's radii, E, nu; contact.*, friction.*, "
                           "driver.speed; `jointplay inspect FILE` lists them)")


def _tree_order(m: Mechanism) -> list[Joint]:
    """The non-clearance joints, parents first, with a floating joint (from the ground: x, y
    and angle) for each body they leave unplaced: such a body is held by clearance joints
    only. Refuses loops of non-clearance joints and bodies joined to nothing."""
    placed = {GROUND}
    pending = [j for j in m.joints if j.kind != "clearance"]
    order: list[Joint] = []
    by_child: dict[str, Joint] = {}
    for j in pending:
        if j.child in by_child:
            other = by_child[j.child]
            raise DescriptionError(
                f"joint {j.name!r}", f"closes a loop through body {j.child!r} (also the child "
                f"of {other.name!r}) with no clearance joint in it; a loop closed only by "
                "ideal, locked or prismatic joints needs constraint equations, which "
                "mechanism files do not support: give one joint of the loop "
                "kind = \"clearance\"")
        by_child[j.child] = j
    floating: list[str] = []
    while pending:
        ready = [j for j in pending if j.parent in placed]
        if not ready:
            roots = [j.parent for j in pending if j.parent not in by_child]
            if not roots:
                j = pending[0]
                raise DescriptionError(f"joint {j.name!r}", "closes a loop of ideal joints; "
                                       "give one joint of the loop kind = \"clearance\"")
            order.append(_floating(roots[0]))
            floating.append(roots[0])
            placed.add(roots[0])
            continue
        for j in ready:
            placed.add(j.child)
            order.append(j)
            pending.remove(j)
    for body in m.bodies:
        if body.name not in placed:
            order.append(_floating(body.name))
            floating.append(body.name)
            placed.add(body.name)
    _check_floating(m, order, floating)
    for j in m.joints:
        if j.kind == "clearance" and j.parent == j.child:
            raise DescriptionError(f"joint {j.name!r}", "joins a body to itself")
    return order


def _floating(body: str) -> Joint:
    return Joint(name=body, type="floating", kind="free", parent=GROUND, child=body,
                 at_parent=(0.0, 0.0), at_child=(0.0, 0.0))


def _check_floating(m: Mechanism, order: list[Joint], floating: list[str]) -> None:
    """Each floating body, with the bodies its joints carry, must be held by a clearance
    joint; its coordinates' names must not be a joint's."""
    names = {j.name for j in m.joints}
    for body in floating:
        if body in names:
            raise DescriptionError(f"body {body!r}", "is held by clearance joints only, so it "
                                   "floats, with coordinates named after it; a joint has its "
                                   "name: rename the joint or the body")
        group = {body}
        for j in order:
            if j.parent in group:
                group.add(j.child)
        if not any(j.kind == "clearance" and (j.parent in group or j.child in group)
                   for j in m.joints):
            raise DescriptionError(f"body {body!r}", "is joined to nothing: no joint places "
                                   "it from the ground and no clearance joint holds it; add "
                                   "its joints")


@dataclass(frozen=True)
class MechanismScene:
    """A mechanism and what to run: the file's contents, validated.

    Attributes
    ----------
    name : str
        The scene's name.
    description : str
        One line on what it is.
    mechanism : Mechanism
        Bodies, joints, driver, loads, contact and friction.
    run : RunSettings
        Duration, output step, integrator and tolerances.
    source : str or None
        The file it was read from.
    initial : dict of str to float
        Starting values of coordinates for the assembly at t = 0.
    output : str or None
        The coordinate the run follows (the file's ``[output]``; None: the default rule).
    """

    name: str
    description: str
    mechanism: Mechanism
    run: RunSettings
    source: str | None = None
    # Starting values of coordinates for the assembly at t = 0 (see simulate.assembled_state)
    initial: dict[str, float] = field(default_factory=dict)
    # The coordinate the run follows ([output] coordinate); None: the rule of
    # jointplay.mechanism.output.default_output
    output: str | None = None

    @property
    def output_coordinate(self) -> str:
        """The coordinate the summary and the figures follow (the file's, or the rule's)."""
        from jointplay.mechanism.output import default_output

        return self.output or default_output(self.mechanism)

    def with_run(self, **changes: float | str) -> MechanismScene:
        run = cast(RunSettings, _replace(self.run, **changes))
        run.check()
        return dataclasses.replace(self, run=run)

    def with_mechanism(self, mechanism: Mechanism) -> MechanismScene:
        return dataclasses.replace(self, mechanism=mechanism)

    @property
    def smallest_clearance(self) -> float:
        gaps = [j.radial_clearance for j in self.mechanism.joints if j.kind == "clearance"]
        return min(gaps) if gaps else math.nan
