"""Robot descriptions: typed, validated, and split into compile-time structure and parameters.

A description says how many links the planar chain has, what kind each joint is, which
effects are modelled, and every number. The *structure* (link count, joint kinds, effects and
laws) decides what code is generated; the *parameters* (every number) are a runtime vector, so
changing a number never re-derives or recompiles. Joints and links are numbered from 1.

This module is plain data: it imports neither sympy nor CasADi, so both the derivation and the
runtime share the one definition of the parameter vector below.
"""

from __future__ import annotations

import difflib
import hashlib
import json
import math
import tomllib
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Literal

from jointplay.errors import DescriptionError

JointKind = Literal["ideal", "clearance", "locked", "locked_clearance"]
ContactLaw = Literal["lankarani-nikravesh", "hunt-crossley", "gonthier", "flores"]
ContactStiffness = Literal["hertz", "johnson", "liu", "pereira"]
FrictionLaw = Literal["none", "coulomb"]
FrictionRamp = Literal["linear", "smooth"]

JOINT_KINDS: tuple[str, ...] = ("ideal", "clearance", "locked", "locked_clearance")
CONTACT_LAWS: tuple[str, ...] = ("lankarani-nikravesh", "hunt-crossley", "gonthier", "flores")
# The elastic part of the normal force: Hertz's K d^n, or a law for conformal cylinders of
# axial length joint{j}.length (see jointplay.derive.cylindrical).
CONTACT_STIFFNESSES: tuple[str, ...] = ("hertz", "johnson", "liu", "pereira")
# The clearance range (m) over which the Pereira-Ramalho-Ambrosio law was fitted.
PEREIRA_CLEARANCE_RANGE: tuple[float, float] = (5.0e-6, 10.0e-3)
FRICTION_LAWS: tuple[str, ...] = ("none", "coulomb")
FRICTION_RAMPS: tuple[str, ...] = ("linear", "smooth")
MAX_LINKS = 32

STEEL_E = 207e9
STEEL_NU = 0.3


@dataclass(frozen=True)
class Link:
    """One rigid link. Lengths in m, mass in kg, inertia in kg m^2 about the centre of mass."""

    length: float
    mass: float
    inertia: float
    com: float  # distance of the centre of mass from the proximal joint, along the link (m)


@dataclass(frozen=True)
class Joint:
    """Joint i joins link i-1 (or the ground for i = 1) to link i.

    kind:
      ``ideal``            revolute, no play: one angle coordinate.
      ``clearance``        revolute with play: one angle plus the eccentricity (ex, ey).
      ``locked``           no relative rotation (held at ``angle``), no coordinate.
      ``locked_clearance`` no relative rotation, but the journal floats in the bearing: (ex, ey).
    For clearance kinds the journal (on link i) of radius ``journal_radius`` sits in the bearing
    (on link i-1) of radius ``bearing_radius``; E (Pa) and nu are each part's elastic constants.
    """

    kind: JointKind = "ideal"
    angle: float = 0.0  # locked relative angle (rad); used by locked kinds only
    bearing_radius: float = 10.0e-3
    journal_radius: float = 9.97e-3
    bearing_E: float = STEEL_E
    bearing_nu: float = STEEL_NU
    journal_E: float = STEEL_E
    journal_nu: float = STEEL_NU
    # Axial length of the journal and bearing (m): needed only by laws that use it.
    length: float | None = None

    @property
    def moves(self) -> bool:
        return self.kind in ("ideal", "clearance")

    @property
    def has_clearance(self) -> bool:
        return self.kind in ("clearance", "locked_clearance")


@dataclass(frozen=True)
class Gravity:
    enabled: bool = True
    vector: tuple[float, float] = (0.0, -9.81)  # m/s^2, in the plane of motion


@dataclass(frozen=True)
class Contact:
    """Continuous dissipative contact at clearance joints: F_n = F_e(d) (1 + x(ce) d'/d'-).

    ``law`` chooses the damping factor x(ce); ``stiffness`` the elastic force F_e(d): Hertz's
    K d^n (``exponent`` n), or a conformal-cylinder law that needs each clearance joint's
    ``length``.
    """

    law: ContactLaw = "lankarani-nikravesh"
    stiffness: ContactStiffness = "hertz"
    exponent: float = 1.5
    restitution: float = 0.9
    # Floor of the captured impact speed d'- (m/s): grazing contact would otherwise give a
    # damping coefficient x K / d'- that grows without bound.
    impact_speed_floor: float = 1.0e-3


@dataclass(frozen=True)
class Friction:
    """Modified Coulomb friction (Ambrosio): F_t = -mu c_d(|v_t|) F_n v_t/|v_t|.

    c_d = 0 below v0 (>= 0; v0 = 0 ramps from zero speed), 1 above v1 (> v0).
    """

    law: FrictionLaw = "coulomb"
    ramp: FrictionRamp = "linear"
    mu: float = 0.05
    v0: float = 1.0e-4
    v1: float = 1.0e-2


@dataclass(frozen=True)
class Robot:
    """A planar serial robot with optional clearance joints, validated on construction."""

    links: tuple[Link, ...]
    joints: tuple[Joint, ...]
    name: str = "robot"
    payload_mass: float = 0.0  # point mass at the tip of the last link (kg)
    gravity: Gravity = field(default_factory=Gravity)
    contact: Contact = field(default_factory=Contact)
    friction: Friction = field(default_factory=Friction)
    drive: bool = True  # drive torques on the joints that move

    def __post_init__(self) -> None:
        validate(self)

    @property
    def n_links(self) -> int:
        return len(self.links)

    @property
    def moving_joints(self) -> tuple[int, ...]:
        """1-based indices of joints with an angle coordinate."""
        return tuple(i + 1 for i, j in enumerate(self.joints) if j.moves)

    @property
    def clearance_joints(self) -> tuple[int, ...]:
        """1-based indices of joints with eccentricity coordinates."""
        return tuple(i + 1 for i, j in enumerate(self.joints) if j.has_clearance)

    def structure(self) -> dict[str, Any]:
        """The compile-time part: what changes the generated code. Numbers are absent."""
        has_clearance = bool(self.clearance_joints)
        return {
            "links": self.n_links,
            "joints": [j.kind for j in self.joints],
            "gravity": self.gravity.enabled,
            "contact_law": self.contact.law if has_clearance else None,
            # Present only for a cylindrical law, so a Hertz model's structure (and its code)
            # is what it was before these laws existed.
            **({"contact_stiffness": self.contact.stiffness}
               if has_clearance and self.contact.stiffness != "hertz" else {}),
            "friction": (
                f"{self.friction.law}-{self.friction.ramp}"
                if has_clearance and self.friction.law != "none"
                else "none"
            ),
            "drive": self.drive,
        }

    def structure_hash(self) -> str:
        return hashlib.sha256(canonical_json(self.structure()).encode()).hexdigest()

    def parameters(self) -> list[Parameter]:
        return parameter_layout(self.structure())

    def parameter_values(self) -> list[float]:
        """The parameter vector, in the order of :meth:`parameters`."""
        return [float(self._value_of(p.name)) for p in self.parameters()]

    def _value_of(self, name: str) -> float:
        head, _, attr = name.partition(".")
        if head.startswith("link"):
            return getattr(self.links[int(head[4:]) - 1], attr)
        if head.startswith("joint"):
            value = getattr(self.joints[int(head[5:]) - 1], attr)
            if value is None:  # validation requires it wherever the layout has it
                raise KeyError(name)
            return value
        if head == "payload":
            return self.payload_mass
        if head == "gravity":
            return self.gravity.vector[0 if attr == "x" else 1]
        if head == "contact":
            return getattr(self.contact, attr)
        if head == "friction":
            return getattr(self.friction, attr)
        raise KeyError(name)

    def to_dict(self) -> dict[str, Any]:
        """A TOML-ready dictionary that :func:`robot_from_dict` reads back unchanged."""
        d: dict[str, Any] = {
            "name": self.name,
            "links": [vars(link).copy() for link in self.links],
            "joints": [_joint_dict(j) for j in self.joints],
            "payload": {"mass": self.payload_mass},
            "gravity": {"enabled": self.gravity.enabled, "vector": list(self.gravity.vector)},
            "contact": _contact_dict(self.contact),
            "friction": vars(self.friction).copy(),
            "drive": {"enabled": self.drive},
        }
        return d


def _joint_dict(j: Joint) -> dict[str, Any]:
    d: dict[str, Any] = {"kind": j.kind}
    if j.kind in ("locked", "locked_clearance"):
        d["angle"] = j.angle
    if j.has_clearance:
        for name in ("bearing_radius", "journal_radius", "bearing_E", "bearing_nu",
                     "journal_E", "journal_nu"):
            d[name] = getattr(j, name)
        if j.length is not None:
            d["length"] = j.length
    return d


def _contact_dict(c: Contact) -> dict[str, Any]:
    """The [contact] table; ``stiffness`` is written only when it is not the default, so a
    Hertz robot's TOML (and the checked-in generated/ folders) read as before."""
    d = vars(c).copy()
    if c.stiffness == "hertz":
        del d["stiffness"]
    return d


def canonical_json(obj: Any) -> str:
    return json.dumps(obj, sort_keys=True, separators=(",", ":"))


# --------------------------------------------------------------------------------------------
# The parameter vector
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Parameter:
    name: str  # dotted name, e.g. "link2.mass", "joint3.bearing_radius", "friction.mu"
    symbol: str  # LaTeX-friendly symbol used in the derived equations
    unit: str
    doc: str


def parameter_layout(structure: Mapping[str, Any]) -> list[Parameter]:
    """Every number the model takes at run time, in slot order, for a given structure.

    Only the parameters of effects the structure compiles are present.
    """
    out: list[Parameter] = []
    k = int(structure["links"])
    for i in range(1, k + 1):
        out += [
            Parameter(f"link{i}.length", f"L_{{{i}}}", "m", f"length of link {i}"),
            Parameter(f"link{i}.mass", f"m_{{{i}}}", "kg", f"mass of link {i}"),
            Parameter(f"link{i}.inertia", f"I_{{{i}}}", "kg m^2",
                      f"moment of inertia of link {i} about its centre of mass"),
            Parameter(f"link{i}.com", f"c_{{{i}}}", "m",
                      f"distance of link {i}'s centre of mass from joint {i}, along the link"),
        ]
    out.append(Parameter("payload.mass", "m_{p}", "kg",
                         "point payload at the tip of the last link"))
    if structure["gravity"]:
        out += [
            Parameter("gravity.x", "g_{x}", "m/s^2", "gravity, x component"),
            Parameter("gravity.y", "g_{y}", "m/s^2", "gravity, y component"),
        ]
    for i, kind in enumerate(structure["joints"], start=1):
        if kind in ("locked", "locked_clearance"):
            out.append(Parameter(f"joint{i}.angle", f"\\phi_{{{i}}}", "rad",
                                 f"fixed relative angle of locked joint {i}"))
        if kind in ("clearance", "locked_clearance"):
            out += [
                Parameter(f"joint{i}.bearing_radius", f"R_{{b{i}}}", "m",
                          f"bearing (hole) radius of joint {i}, on link {i - 1}"),
                Parameter(f"joint{i}.journal_radius", f"R_{{j{i}}}", "m",
                          f"journal (pin) radius of joint {i}, on link {i}"),
                Parameter(f"joint{i}.bearing_E", f"E_{{b{i}}}", "Pa",
                          f"Young's modulus of joint {i}'s bearing"),
                Parameter(f"joint{i}.bearing_nu", f"\\nu_{{b{i}}}", "1",
                          f"Poisson's ratio of joint {i}'s bearing"),
                Parameter(f"joint{i}.journal_E", f"E_{{j{i}}}", "Pa",
                          f"Young's modulus of joint {i}'s journal"),
                Parameter(f"joint{i}.journal_nu", f"\\nu_{{j{i}}}", "1",
                          f"Poisson's ratio of joint {i}'s journal"),
            ]
            if structure.get("contact_stiffness", "hertz") != "hertz":
                out.append(Parameter(f"joint{i}.length", f"\\ell_{{{i}}}", "m",
                                     "axial length of the journal and bearing"))
    if structure["contact_law"] is not None:
        if structure.get("contact_stiffness", "hertz") == "hertz":
            out.append(Parameter("contact.exponent", "n", "1",
                                 "Hertz exponent n of F_n = K d^n"))
        out += [
            Parameter("contact.restitution", "c_{e}", "1", "coefficient of restitution"),
            Parameter("contact.impact_speed_floor", "v_{min}", "m/s",
                      "floor of the captured impact speed (grazing contact)"),
        ]
    if structure["friction"] != "none":
        out += [
            Parameter("friction.mu", "\\mu", "1", "Coulomb friction coefficient"),
            Parameter("friction.v0", "v_{0}", "m/s", "sliding speed below which friction is 0"),
            Parameter("friction.v1", "v_{1}", "m/s", "sliding speed above which friction is full"),
        ]
    return out


# --------------------------------------------------------------------------------------------
# Validation
# --------------------------------------------------------------------------------------------


def _positive(field_name: str, value: float, *, allow_zero: bool = False) -> None:
    if not isinstance(value, (int, float)) or isinstance(value, bool) or math.isnan(value) \
            or math.isinf(value):
        raise DescriptionError(field_name, f"must be a finite number, got {value!r}")
    if value < 0 or (value == 0 and not allow_zero):
        bound = ">= 0" if allow_zero else "> 0"
        raise DescriptionError(field_name, f"must be {bound}, got {value!r}")


def _finite(field_name: str, value: float) -> None:
    if not isinstance(value, (int, float)) or isinstance(value, bool) or not math.isfinite(value):
        raise DescriptionError(field_name, f"must be a finite number, got {value!r}")


def validate(robot: Robot) -> None:
    """Raise :class:`DescriptionError` naming the first invalid field."""
    k = len(robot.links)
    if k < 1 or k > MAX_LINKS:
        raise DescriptionError("links", f"the robot needs 1 to {MAX_LINKS} links, got {k}")
    if len(robot.joints) != k:
        raise DescriptionError(
            "joints", f"needs one joint per link ({k}), got {len(robot.joints)}")
    for i, link in enumerate(robot.links, start=1):
        _positive(f"links[{i}].length", link.length)
        _positive(f"links[{i}].mass", link.mass)
        _positive(f"links[{i}].inertia", link.inertia)
        _finite(f"links[{i}].com", link.com)
        if not 0.0 <= link.com <= link.length:
            raise DescriptionError(
                f"links[{i}].com",
                f"must lie on the link, 0 <= com <= length ({link.length}), got {link.com}")
    _positive("payload.mass", robot.payload_mass, allow_zero=True)
    for i, joint in enumerate(robot.joints, start=1):
        if joint.kind not in JOINT_KINDS:
            raise DescriptionError(f"joints[{i}].kind",
                                   f"must be one of {', '.join(JOINT_KINDS)}, got {joint.kind!r}")
        _finite(f"joints[{i}].angle", joint.angle)
        if joint.has_clearance:
            _positive(f"joints[{i}].bearing_radius", joint.bearing_radius)
            _positive(f"joints[{i}].journal_radius", joint.journal_radius)
            if joint.journal_radius >= joint.bearing_radius:
                raise DescriptionError(
                    f"joints[{i}].journal_radius",
                    f"must be smaller than bearing_radius ({joint.bearing_radius}) to leave a "
                    f"clearance, got {joint.journal_radius}; use kind = \"ideal\" for no play")
            for part in ("bearing", "journal"):
                _positive(f"joints[{i}].{part}_E", getattr(joint, f"{part}_E"))
                nu = getattr(joint, f"{part}_nu")
                _finite(f"joints[{i}].{part}_nu", nu)
                if not 0.0 < nu < 0.5:
                    raise DescriptionError(f"joints[{i}].{part}_nu",
                                           f"Poisson's ratio must be in (0, 0.5), got {nu}")
    if not robot.moving_joints and not robot.clearance_joints:
        raise DescriptionError("joints", "at least one joint must move or have play (not every "
                               "joint locked)")
    g = robot.gravity
    if len(g.vector) != 2:
        raise DescriptionError("gravity.vector", f"must have 2 components, got {len(g.vector)}")
    for axis, v in zip("xy", g.vector, strict=True):
        _finite(f"gravity.vector.{axis}", v)
    c = robot.contact
    if c.law not in CONTACT_LAWS:
        raise DescriptionError("contact.law",
                               f"must be one of {', '.join(CONTACT_LAWS)}, got {c.law!r}")
    if c.stiffness not in CONTACT_STIFFNESSES:
        raise DescriptionError("contact.stiffness", f"must be one of "
                               f"{', '.join(CONTACT_STIFFNESSES)}, got {c.stiffness!r}")
    _validate_lengths(robot)
    _positive("contact.exponent", c.exponent)
    _finite("contact.restitution", c.restitution)
    if not 0.0 < c.restitution <= 1.0:
        raise DescriptionError("contact.restitution", f"must be in (0, 1], got {c.restitution}")
    _positive("contact.impact_speed_floor", c.impact_speed_floor)
    f = robot.friction
    if f.law not in FRICTION_LAWS:
        raise DescriptionError("friction.law",
                               f"must be one of {', '.join(FRICTION_LAWS)}, got {f.law!r}")
    if f.ramp not in FRICTION_RAMPS:
        raise DescriptionError("friction.ramp",
                               f"must be one of {', '.join(FRICTION_RAMPS)}, got {f.ramp!r}")
    _positive("friction.mu", f.mu, allow_zero=True)
    # v0 = 0: the correction ramps from zero speed; the law's direction floor keeps it finite.
    _positive("friction.v0", f.v0, allow_zero=True)
    _positive("friction.v1", f.v1)
    if f.v1 <= f.v0:
        raise DescriptionError("friction.v1", f"must exceed friction.v0 ({f.v0}), got {f.v1}")


def _validate_lengths(robot: Robot) -> None:
    """joint{j}.length: positive wherever given; required where a compiled law uses it."""
    stiffness = robot.contact.stiffness
    for i, joint in enumerate(robot.joints, start=1):
        if joint.length is not None:
            _positive(f"joints[{i}].length", joint.length)
        if not joint.has_clearance or stiffness == "hertz":
            continue
        if joint.length is None:
            raise DescriptionError(
                f"joints[{i}].length",
                f"is required by contact.stiffness = {stiffness!r}: the axial length of the "
                "journal and bearing in m; add e.g. length = 0.02 to this [[joints]] entry, "
                "or use stiffness = \"hertz\", which needs no length")
        if stiffness == "pereira":
            low, high = PEREIRA_CLEARANCE_RANGE
            c = joint.bearing_radius - joint.journal_radius
            if not low <= c < high:
                raise DescriptionError(
                    f"joints[{i}].journal_radius",
                    f"gives a radial clearance of {c:.6g} m, outside the range the Pereira "
                    f"law was fitted for ({low:g} m <= c < {high:g} m); choose radii in that "
                    "range or another contact.stiffness (johnson, liu)")


# --------------------------------------------------------------------------------------------
# Reading descriptions from TOML / dictionaries / flags
# --------------------------------------------------------------------------------------------

_TOP_KEYS = ("name", "links", "joints", "payload", "gravity", "contact", "friction", "drive")
_LINK_KEYS = ("length", "mass", "inertia", "com")
_JOINT_KEYS = ("kind", "angle", "bearing_radius", "journal_radius", "bearing_E", "bearing_nu",
               "journal_E", "journal_nu", "length")
_FLOAT_FIELDS = {"length", "mass", "inertia", "com", "angle", "bearing_radius", "journal_radius",
                 "bearing_E", "bearing_nu", "journal_E", "journal_nu", "exponent", "restitution",
                 "impact_speed_floor", "mu", "v0", "v1"}


def check_keys(table: Any, allowed: Sequence[str], where: str,
               source: str | None = None) -> None:
    """Refuse a non-table or an unknown key, naming the nearest allowed key."""
    if not isinstance(table, Mapping):
        raise DescriptionError(where or "(top level)",
                               f"must be a table, got {type(table).__name__}", source)
    for key in table:
        if key not in allowed:
            close = difflib.get_close_matches(key, allowed, n=1)
            hint = f"; did you mean {close[0]!r}?" if close else ""
            prefix = f"{where}." if where else ""
            raise DescriptionError(f"{prefix}{key}",
                                   f"unknown key (allowed: {', '.join(allowed)}){hint}", source)


def _number(value: Any, where: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise DescriptionError(where, f"must be a number in SI units, got {value!r}")
    return float(value)


def _numbers(table: Mapping[str, Any], where: str) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for key, value in table.items():
        out[key] = _number(value, f"{where}.{key}") if key in _FLOAT_FIELDS else value
    return out


def robot_from_dict(data: Mapping[str, Any], source: str | None = None) -> Robot:
    """Build a validated :class:`Robot` from a parsed TOML document."""
    try:
        return _robot_from_dict(data)
    except DescriptionError as err:
        err.source = source
        raise DescriptionError(err.field, err.message, source) from None


def _robot_from_dict(data: Mapping[str, Any]) -> Robot:
    if "robot" in data and isinstance(data["robot"], Mapping):
        data = data["robot"]
    check_keys(data, _TOP_KEYS, "")
    raw_links = data.get("links")
    if not isinstance(raw_links, list) or not raw_links:
        raise DescriptionError("links", "must be a non-empty array of [[links]] tables "
                                        f"(1 to {MAX_LINKS} links)")
    links = []
    for i, raw in enumerate(raw_links, start=1):
        check_keys(raw, _LINK_KEYS, f"links[{i}]")
        missing = [key for key in _LINK_KEYS if key not in raw]
        if missing:
            raise DescriptionError(f"links[{i}].{missing[0]}", "is required")
        links.append(Link(**_numbers(raw, f"links[{i}]")))
    raw_joints = data.get("joints", [{"kind": "ideal"}] * len(links))
    if not isinstance(raw_joints, list):
        raise DescriptionError("joints", "must be an array of [[joints]] tables")
    joints = []
    for i, raw in enumerate(raw_joints, start=1):
        check_keys(raw, _JOINT_KEYS, f"joints[{i}]")
        kind = raw.get("kind", "ideal")
        if isinstance(kind, list):
            raise DescriptionError(f"joints[{i}].kind",
                                   f"a joint has one kind, got {kind}; a locked joint with play "
                                   "is kind = \"locked_clearance\"")
        if kind not in JOINT_KINDS:
            close = difflib.get_close_matches(str(kind), JOINT_KINDS, n=1)
            hint = f"; did you mean {close[0]!r}?" if close else ""
            raise DescriptionError(f"joints[{i}].kind",
                                   f"must be one of {', '.join(JOINT_KINDS)}, got {kind!r}{hint}")
        joints.append(Joint(**_numbers(raw, f"joints[{i}]")))
    payload = data.get("payload", {})
    check_keys(payload, ("mass",), "payload")
    gravity_raw = data.get("gravity", {})
    check_keys(gravity_raw, ("enabled", "vector"), "gravity")
    vector = gravity_raw.get("vector", Gravity().vector)
    if not isinstance(vector, list | tuple) or len(vector) != 2:
        raise DescriptionError("gravity.vector", f"must be [gx, gy] in m/s^2, got {vector!r}")
    gravity = Gravity(enabled=_bool(gravity_raw.get("enabled", True), "gravity.enabled"),
                      vector=(_number(vector[0], "gravity.vector"),
                              _number(vector[1], "gravity.vector")))
    contact_raw = data.get("contact", {})
    check_keys(contact_raw, tuple(vars(Contact())), "contact")
    friction_raw = data.get("friction", {})
    check_keys(friction_raw, tuple(vars(Friction())), "friction")
    drive_raw = data.get("drive", {})
    check_keys(drive_raw, ("enabled",), "drive")
    name = data.get("name", "robot")
    if not isinstance(name, str) or not name.replace("_", "").replace("-", "").isalnum():
        raise DescriptionError("name", f"must be letters, digits, '_' or '-', got {name!r}")
    return Robot(
        links=tuple(links),
        joints=tuple(joints),
        name=name,
        payload_mass=_number(payload.get("mass", 0.0), "payload.mass"),
        gravity=gravity,
        contact=Contact(**_numbers(contact_raw, "contact")),
        friction=Friction(**_numbers(friction_raw, "friction")),
        drive=_bool(drive_raw.get("enabled", True), "drive.enabled"),
    )


def _bool(value: Any, where: str) -> bool:
    if not isinstance(value, bool):
        raise DescriptionError(where, f"must be true or false, got {value!r}")
    return value


def read_toml(path: str | Path, what: str) -> tuple[dict[str, Any], str]:
    """The parsed document and its text; errors name the file (``what``: "robot", "scene"...).

    Only a regular file of at most ``MAX_TOML_BYTES`` is read: a device or FIFO is refused at
    once instead of blocking or filling memory.
    """
    from jointplay.files import read_input
    from jointplay.limits import MAX_TOML_BYTES

    path = Path(path)
    data = read_input(path, "(file)", f"{what} TOML file", MAX_TOML_BYTES)
    try:
        # Newlines translated as by a text-mode read.
        text = data.decode("utf-8").replace("\r\n", "\n").replace("\r", "\n")
    except UnicodeDecodeError as err:
        raise DescriptionError("(file)", f"cannot be read ({err})", str(path)) from None
    try:
        return tomllib.loads(text), text
    except tomllib.TOMLDecodeError as err:
        raise DescriptionError("(toml)", f"malformed TOML: {err}", str(path)) from None


def load_robot(path: str | Path) -> Robot:
    """Read and validate a robot description TOML file (never executed: data only)."""
    data, _ = read_toml(path, "robot")
    return robot_from_dict(data, source=str(path))


def parse_index_list(text: str, flag: str, n_links: int) -> list[int]:
    """Parse ``"2,5"`` into ``[2, 5]``, checking each index names a joint 1..n_links."""
    out = []
    for part in (p.strip() for p in text.split(",")):
        if not part:
            continue
        if not part.isdigit():
            raise DescriptionError(flag, f"must be comma-separated joint numbers, got {part!r}")
        idx = int(part)
        if not 1 <= idx <= n_links:
            raise DescriptionError(flag, f"joint {idx} is out of range: joints are 1..{n_links}")
        out.append(idx)
    return out


def robot_from_flags(
    links: Any,
    clearance: str = "",
    locked: str = "",
    locked_clearance: str = "",
    friction: str = "coulomb",
    contact_law: str = "lankarani-nikravesh",
    gravity: bool = True,
) -> Robot:
    """The common case from command-line flags: k uniform links, chosen joint kinds.

    Links are 0.3 m, 1 kg, uniform rods; clearance joints are 10 mm steel bearings with
    0.03 mm radial clearance. Edit a TOML description for anything else.
    """
    if isinstance(links, bool) or not isinstance(links, int):
        try:
            links = int(str(links), 10)
        except ValueError:
            raise DescriptionError("--links", f"must be an integer from 1 to {MAX_LINKS}, "
                                              f"got {links!r}") from None
    if not 1 <= links <= MAX_LINKS:
        raise DescriptionError("--links", f"must be from 1 to {MAX_LINKS}, got {links}")
    kinds: dict[int, str] = {}
    for flag, kind, text in (("--clearance", "clearance", clearance),
                             ("--locked", "locked", locked),
                             ("--locked-clearance", "locked_clearance", locked_clearance)):
        for idx in parse_index_list(text, flag, links):
            if idx in kinds and kinds[idx] != kind:
                raise DescriptionError(
                    flag, f"joint {idx} is given two kinds ({kinds[idx]} and {kind}); a locked "
                          "joint with play is --locked-clearance")
            kinds[idx] = kind
    return uniform_chain(
        links,
        kinds=[kinds.get(i, "ideal") for i in range(1, links + 1)],
        gravity=Gravity(enabled=gravity),
        contact=Contact(law=contact_law),  # type: ignore[arg-type]
        friction=Friction(law=friction),  # type: ignore[arg-type]
    )


def with_parameters(robot: Robot, values: Mapping[str, float]) -> Robot:
    """A copy of ``robot`` with named parameters changed (structure unchanged)."""
    known = {p.name for p in robot.parameters()}
    links = [vars(link).copy() for link in robot.links]
    joints = [vars(j).copy() for j in robot.joints]
    top: dict[str, Any] = {}
    contact = vars(robot.contact).copy()
    friction = vars(robot.friction).copy()
    gravity = list(robot.gravity.vector)
    for name, value in values.items():
        if name not in known:
            close = difflib.get_close_matches(name, sorted(known), n=1)
            hint = f"; did you mean {close[0]!r}?" if close else ""
            raise DescriptionError(name, f"is not a parameter of this model{hint}")
        head, _, attr = name.partition(".")
        if head.startswith("link"):
            links[int(head[4:]) - 1][attr] = value
        elif head.startswith("joint"):
            joints[int(head[5:]) - 1][attr] = value
        elif head == "payload":
            top["payload_mass"] = value
        elif head == "gravity":
            gravity["xy".index(attr)] = value
        elif head == "contact":
            contact[attr] = value
        else:
            friction[attr] = value
    return replace(
        robot,
        links=tuple(Link(**d) for d in links),
        joints=tuple(Joint(**d) for d in joints),
        gravity=Gravity(robot.gravity.enabled, (gravity[0], gravity[1])),
        contact=Contact(**contact),
        friction=Friction(**friction),
        **top,
    )


def uniform_chain(n_links: int, kinds: Iterable[str] | None = None, **kwargs: Any) -> Robot:
    """A chain of identical 0.3 m, 1 kg rods; handy for tests and benchmarks."""
    kinds = list(kinds) if kinds is not None else ["ideal"] * n_links
    length = 0.3
    link = Link(length=length, mass=1.0, inertia=length**2 / 12, com=length / 2)
    return Robot(links=(link,) * n_links,
                 joints=tuple(Joint(kind=k) for k in kinds),  # type: ignore[arg-type]
                 name=kwargs.pop("name", f"chain{n_links}"), **kwargs)
