"""The typed contract between the derivation and the runtime: structure, coordinates, parameters.

A :class:`Structure` is the compile-time part of a robot (link count, joint kinds, effects and
laws): it alone decides the generated code, and its canonical dictionary (:meth:`as_dict`) is
hashed into the stamp that finds a model. From it follow, in slot order, the model's
coordinates (:func:`coordinate_layout`) and the parameter vector (:func:`parameter_layout`):
the derivation names its symbols from these lists, the generator writes them into layout.json,
and the runtime reads them back typed, so no code anywhere parses a name such as "ex2" or
"joint3.bearing_radius" to find out what it refers to.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any, Literal

JointKind = Literal["ideal", "clearance", "locked", "locked_clearance"]
JOINT_KINDS: tuple[str, ...] = ("ideal", "clearance", "locked", "locked_clearance")
MOVING_KINDS = ("ideal", "clearance")
CLEARANCE_KINDS = ("clearance", "locked_clearance")
LOCKED_KINDS = ("locked", "locked_clearance")

ParameterOwner = Literal["link", "joint", "payload", "gravity", "contact", "friction",
                         "lubrication", "wear"]
CoordinateKind = Literal["angle", "ex", "ey"]


@dataclass(frozen=True)
class Structure:
    """What changes the generated code; numbers are absent.

    Two robots with equal structures share one compiled model (:meth:`Robot.structure`).

    Attributes
    ----------
    links : int
        The number of links.
    joints : tuple of str
        The kind of each joint.
    gravity : bool
        Gravity compiled in.
    contact_law : str or None
        The contact law's damping factor; None when no joint has clearance.
    friction_law : str
        ``"coulomb"`` or ``"none"`` (always ``"none"`` without clearance).
    friction_ramp : str or None
        The friction ramp; None when friction is off.
    drive : bool
        Drive torques on the moving joints.
    contact_stiffness : str or None
        ``"johnson"``, ``"liu"`` or ``"pereira"`` for a cylindrical law; None is Hertz's K d^n.
    lubrication : str or None
        ``"short-bearing"`` or ``"long-bearing"`` when a film is modelled.
    wear : str or None
        ``"archard"`` when wear is integrated during the run.
    """

    links: int
    joints: tuple[str, ...]
    gravity: bool
    contact_law: str | None
    friction_law: str
    friction_ramp: str | None
    drive: bool
    # "johnson" | "liu" | "pereira" for a cylindrical law; None is Hertz's K d^n
    contact_stiffness: str | None = None
    lubrication: str | None = None  # "short-bearing" | "long-bearing" when a film is modelled
    wear: str | None = None  # "archard" when wear is integrated during the run

    @property
    def moving_joints(self) -> tuple[int, ...]:
        """1-based indices of joints with an angle coordinate."""
        return tuple(i for i, k in enumerate(self.joints, start=1) if k in MOVING_KINDS)

    @property
    def clearance_joints(self) -> tuple[int, ...]:
        """1-based indices of joints with eccentricity coordinates."""
        return tuple(i for i, k in enumerate(self.joints, start=1) if k in CLEARANCE_KINDS)

    @property
    def uses_length(self) -> bool:
        """Whether a compiled law or effect needs the joints' axial length ``joint{j}.length``."""
        return bool(self.contact_stiffness or self.lubrication or self.wear)

    @property
    def has_friction(self) -> bool:
        return self.friction_law != "none"

    @property
    def friction(self) -> str:
        """The friction model as one word: "none", "coulomb-linear" or "coulomb-smooth"."""
        return f"{self.friction_law}-{self.friction_ramp}" if self.has_friction else "none"

    def as_dict(self) -> dict[str, Any]:
        """The canonical form: hashed into the model's stamp and written to layout.json."""
        out: dict[str, Any] = {
            "links": self.links, "joints": list(self.joints), "gravity": self.gravity,
            "contact_law": self.contact_law, "friction": self.friction, "drive": self.drive}
        # Present only when compiled, so that a structure without them hashes as it always did.
        for key in _OPTIONAL:
            if getattr(self, key) is not None:
                out[key] = getattr(self, key)
        return out

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> Structure:
        """Read :meth:`as_dict`'s form back (ValueError naming the key if it is not that)."""
        keys = {"links", "joints", "gravity", "contact_law", "friction", "drive"}
        if not isinstance(data, Mapping) or not keys <= set(data) <= keys | set(_OPTIONAL):
            raise ValueError(f"a structure has the keys {sorted(keys)}, and optionally "
                             f"{', '.join(_OPTIONAL)}")
        joints = data["joints"]
        if not isinstance(joints, list) or not all(k in JOINT_KINDS for k in joints):
            raise ValueError(f"'joints' must list kinds among {', '.join(JOINT_KINDS)}")
        friction = data["friction"]
        law, _, ramp = str(friction).partition("-")
        if friction != "none" and not ramp:
            raise ValueError(f"'friction' must be 'none' or 'LAW-RAMP', got {friction!r}")
        return cls(links=int(data["links"]), joints=tuple(joints),
                   gravity=bool(data["gravity"]), contact_law=data["contact_law"],
                   friction_law=law, friction_ramp=ramp or None, drive=bool(data["drive"]),
                   **{key: data.get(key) for key in _OPTIONAL})


_OPTIONAL = ("contact_stiffness", "lubrication", "wear")


@dataclass(frozen=True)
class Coordinate:
    """One generalised coordinate: the angle of a moving joint or an eccentricity component.

    Attributes
    ----------
    name : str
        ``"q2"``, ``"ex3"``, ...
    unit : str
        ``"rad"`` or ``"m"``.
    doc : str
        What it is, in words.
    kind : {"angle", "ex", "ey"}
        Which kind of coordinate.
    joint : int
        The 1-based joint it belongs to.
    """

    name: str  # e.g. "q2", "ex3"
    unit: str
    doc: str
    kind: CoordinateKind
    joint: int  # 1-based joint it belongs to

    def as_dict(self) -> dict[str, str]:
        return {"name": self.name, "unit": self.unit, "doc": self.doc}


@dataclass(frozen=True)
class Parameter:
    """One slot of the run-time parameter vector, and the description field it comes from.

    Attributes
    ----------
    name : str
        The dotted name ``simulate(parameters=...)`` takes: ``"link2.mass"``,
        ``"joint3.bearing_radius"``, ``"friction.mu"``, ...
    symbol : str
        The symbol used in the derived equations (LaTeX-friendly).
    unit : str
        Its SI unit.
    doc : str
        What it is, in words.
    owner : str
        The part of the description it belongs to (``"link"``, ``"joint"``, ``"payload"``,
        ``"gravity"``, ``"contact"``, ``"friction"``, ...).
    index : int or None
        The 1-based link or joint, for owners ``"link"`` and ``"joint"``.
    attribute : str
        The field of the owner (``"x"``/``"y"`` for gravity).
    """

    name: str  # dotted name, e.g. "link2.mass", "joint3.bearing_radius", "friction.mu"
    symbol: str  # LaTeX-friendly symbol used in the derived equations
    unit: str
    doc: str
    owner: ParameterOwner = "payload"
    index: int | None = None  # 1-based link or joint for owners "link" and "joint"
    attribute: str = "mass"  # the field of the owner; "x"/"y" for gravity

    def as_dict(self) -> dict[str, str]:
        return {"name": self.name, "symbol": self.symbol, "unit": self.unit, "doc": self.doc}


def coordinate_layout(structure: Structure) -> list[Coordinate]:
    """The generalised coordinates in slot order: the angles, then (ex, ey) joint by joint."""
    angles = [Coordinate(f"q{i}", "rad", f"angle of link {i} relative to "
                         f"{f'link {i - 1}' if i > 1 else 'the ground'}", "angle", i)
              for i in structure.moving_joints]
    axes: tuple[tuple[str, CoordinateKind], ...] = (("x", "ex"), ("y", "ey"))
    eccentricities = [
        Coordinate(f"e{axis}{i}", "m",
                   f"joint {i}: journal centre minus bearing centre, {axis}", kind, i)
        for i in structure.clearance_joints for axis, kind in axes]
    return angles + eccentricities


def _link(i: int, attribute: str, symbol: str, unit: str, doc: str) -> Parameter:
    return Parameter(f"link{i}.{attribute}", symbol, unit, doc, "link", i, attribute)


def _joint(i: int, attribute: str, symbol: str, unit: str, doc: str) -> Parameter:
    return Parameter(f"joint{i}.{attribute}", symbol, unit, doc, "joint", i, attribute)


def _effect(owner: ParameterOwner, attribute: str, symbol: str, unit: str, doc: str
            ) -> Parameter:
    return Parameter(f"{owner}.{attribute}", symbol, unit, doc, owner, None, attribute)


def parameter_layout(structure: Structure) -> list[Parameter]:
    """Every number the model takes at run time, in slot order, for a given structure.

    Only the parameters of effects the structure compiles are present.
    """
    out: list[Parameter] = []
    for i in range(1, structure.links + 1):
        out += [
            _link(i, "length", f"L_{{{i}}}", "m", f"length of link {i}"),
            _link(i, "mass", f"m_{{{i}}}", "kg", f"mass of link {i}"),
            _link(i, "inertia", f"I_{{{i}}}", "kg m^2",
                  f"moment of inertia of link {i} about its centre of mass"),
            _link(i, "com", f"c_{{{i}}}", "m",
                  f"distance of link {i}'s centre of mass from joint {i}, along the link"),
        ]
    out.append(_effect("payload", "mass", "m_{p}", "kg",
                       "point payload at the tip of the last link"))
    if structure.gravity:
        out += [_effect("gravity", "x", "g_{x}", "m/s^2", "gravity, x component"),
                _effect("gravity", "y", "g_{y}", "m/s^2", "gravity, y component")]
    for i, kind in enumerate(structure.joints, start=1):
        if kind in LOCKED_KINDS:
            out.append(_joint(i, "angle", f"\\phi_{{{i}}}", "rad",
                              f"fixed relative angle of locked joint {i}"))
        if kind in CLEARANCE_KINDS:
            out += _clearance_joint_parameters(i)
            if structure.uses_length:
                out.append(_joint(i, "length", f"\\ell_{{{i}}}", "m",
                                  "axial length of the journal and bearing"))
    if structure.contact_law is not None:
        if structure.contact_stiffness is None:  # the cylindrical laws set their own exponent
            out.append(_effect("contact", "exponent", "n", "1", "Hertz exponent n of F_n = K d^n"))
        out += [
            _effect("contact", "restitution", "c_{e}", "1", "coefficient of restitution"),
            _effect("contact", "impact_speed_floor", "v_{min}", "m/s",
                    "floor of the captured impact speed (grazing contact)"),
        ]
    if structure.lubrication:
        out += [
            _effect("lubrication", "viscosity", "\\mu_{l}", "Pa s",
                    "dynamic viscosity of the lubricant"),
            _effect("lubrication", "transition", "\\epsilon_{t}", "1",
                    "eccentricity ratio where the film force starts to freeze (film closing)"),
        ]
    if structure.wear:
        out += [
            _effect("wear", "coefficient", "k_{w}", "1", "Archard wear coefficient"),
            _effect("wear", "hardness", "H_{w}", "Pa", "hardness of the worn surface"),
        ]
    if structure.has_friction:
        out += [
            _effect("friction", "mu", "\\mu", "1", "Coulomb friction coefficient"),
            _effect("friction", "v0", "v_{0}", "m/s", "sliding speed below which friction is 0"),
            _effect("friction", "v1", "v_{1}", "m/s",
                    "sliding speed above which friction is full"),
        ]
    return out


def _clearance_joint_parameters(i: int) -> list[Parameter]:
    return [
        _joint(i, "bearing_radius", f"R_{{b{i}}}", "m",
               f"bearing (hole) radius of joint {i}, on link {i - 1}"),
        _joint(i, "journal_radius", f"R_{{j{i}}}", "m",
               f"journal (pin) radius of joint {i}, on link {i}"),
        _joint(i, "bearing_E", f"E_{{b{i}}}", "Pa", f"Young's modulus of joint {i}'s bearing"),
        _joint(i, "bearing_nu", f"\\nu_{{b{i}}}", "1", f"Poisson's ratio of joint {i}'s bearing"),
        _joint(i, "journal_E", f"E_{{j{i}}}", "Pa", f"Young's modulus of joint {i}'s journal"),
        _joint(i, "journal_nu", f"\\nu_{{j{i}}}", "1", f"Poisson's ratio of joint {i}'s journal"),
    ]
