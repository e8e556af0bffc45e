"""Robot descriptions: typed, validated, and split into compile-time structure and parameters.

A description says how many links the planar chain has, what kind each joint is, which
effects are modelled, and every number. The *structure* (link count, joint kinds, effects and
laws) decides what code is generated; the *parameters* (every number) are a runtime vector, so
changing a number never re-derives or recompiles. Joints and links are numbered from 1.

This module is plain data: it imports neither sympy nor CasADi, so both the derivation and the
runtime share the one definition of the parameter vector below.
"""

from __future__ import annotations

import hashlib
import json
import math
import tomllib
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Literal

from jointplay.common.errors import DescriptionError
from jointplay.common.hints import did_you_mean
from jointplay.robot.structure import (
    JOINT_KINDS,
    JointKind,
    Parameter,
    Structure,
    parameter_layout,
)

ContactLaw = Literal["lankarani-nikravesh", "hunt-crossley", "gonthier", "flores"]
ContactStiffness = Literal["hertz", "johnson", "liu", "pereira"]
FrictionLaw = Literal["none", "coulomb"]
FrictionRamp = Literal["linear", "smooth"]

CONTACT_LAWS: tuple[str, ...] = ("lankarani-nikravesh", "hunt-crossley", "gonthier", "flores")
# The elastic part of the normal force: Hertz's K d^n, or a law for conformal cylinders of
# axial length joint{j}.length (see jointplay.derive.cylindrical).
CONTACT_STIFFNESSES: tuple[str, ...] = ("hertz", "johnson", "liu", "pereira")
# The clearance range (m) over which the Pereira-Ramalho-Ambrosio law was fitted.
PEREIRA_CLEARANCE_RANGE: tuple[float, float] = (5.0e-6, 10.0e-3)
FRICTION_LAWS: tuple[str, ...] = ("none", "coulomb")
FRICTION_RAMPS: tuple[str, ...] = ("linear", "smooth")
LUBRICATION_MODELS: tuple[str, ...] = ("none", "short-bearing", "long-bearing")
WEAR_MODELS: tuple[str, ...] = ("none", "archard")
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
    # Axial length of the journal and bearing (m): needed only by the laws and effects that
    # act along it (lubrication, wear), so None (absent) is valid until one is compiled.
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
class Lubrication:
    """Hydrodynamic film in every clearance joint (see jointplay.derive.lubrication).

    ``model``: ``none`` (dry joints), ``short-bearing`` or ``long-bearing`` (Pinkus and
    Sternlicht's closed forms); ``viscosity`` in Pa s; ``transition``: the eccentricity ratio
    from which the film force is smoothly frozen as the film closes (0 < transition < 1).
    """

    model: str = "none"
    viscosity: float = 0.04
    transition: float = 0.95


@dataclass(frozen=True)
class Wear:
    """Archard wear of every clearance joint, integrated during the run (jointplay.results.wear).

    ``coefficient``: the dimensionless wear coefficient k; ``hardness``: of the softer
    surface, Pa. Wear volume rate k F_n |v_t| / H.
    """

    model: str = "none"
    coefficient: float = 1.0e-4
    hardness: float = 2.0e9


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
    lubrication: Lubrication = field(default_factory=Lubrication)
    wear: Wear = field(default_factory=Wear)

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

    def structure(self) -> Structure:
        """The compile-time part: what changes the generated code. Numbers are absent."""
        has_clearance = bool(self.clearance_joints)
        friction = has_clearance and self.friction.law != "none"
        return Structure(
            links=self.n_links,
            joints=tuple(j.kind for j in self.joints),
            gravity=self.gravity.enabled,
            contact_law=self.contact.law if has_clearance else None,
            contact_stiffness=(self.contact.stiffness
                               if has_clearance and self.contact.stiffness != "hertz" else None),
            friction_law=self.friction.law if friction else "none",
            friction_ramp=self.friction.ramp if friction else None,
            drive=self.drive,
            # Effects enter the structure only when asked for: a scene without them keeps the
            # structure (and so the generated model) it always had.
            lubrication=(self.lubrication.model
                         if has_clearance and self.lubrication.model != "none" else None),
            wear=self.wear.model if has_clearance and self.wear.model != "none" else None,
        )

    def structure_hash(self) -> str:
        return hashlib.sha256(canonical_json(self.structure().as_dict()).encode()).hexdigest()

    def parameters(self) -> list[Parameter]:
        return parameter_layout(self.structure())

    def parameter_values(self) -> list[float]:
        """The parameter vector, in the order of :meth:`parameters`: the one source of every
        default a model or a simulation starts from."""
        return [float(self.value_of(p)) for p in self.parameters()]

    def value_of(self, parameter: Parameter) -> float:
        """The number this description gives for one slot of the parameter vector."""
        if parameter.owner == "link":
            return float(getattr(self.links[_index(parameter) - 1], parameter.attribute))
        if parameter.owner == "joint":
            value = getattr(self.joints[_index(parameter) - 1], parameter.attribute)
            if value is None:  # validation requires it wherever the layout has it
                raise KeyError(parameter.name)
            return float(value)
        if parameter.owner == "payload":
            return self.payload_mass
        if parameter.owner == "gravity":
            return self.gravity.vector["xy".index(parameter.attribute)]
        return float(getattr(getattr(self, parameter.owner), parameter.attribute))

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
        for key, default in (("lubrication", Lubrication()), ("wear", Wear())):
            if getattr(self, key) != default:
                d[key] = vars(getattr(self, key)).copy()
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


def _index(parameter: Parameter) -> int:
    if parameter.index is None:
        raise ValueError(f"parameter {parameter.name} names no link or joint")
    return parameter.index


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


def _validate_effects(robot: Robot) -> None:
    """Lubrication, wear, and the joint length they need."""
    lub, wear = robot.lubrication, robot.wear
    if lub.model not in LUBRICATION_MODELS:
        raise DescriptionError("lubrication.model",
                               f"must be one of {', '.join(LUBRICATION_MODELS)}, got {lub.model!r}")
    _positive("lubrication.viscosity", lub.viscosity)
    _finite("lubrication.transition", lub.transition)
    if not 0.0 < lub.transition < 1.0:
        raise DescriptionError("lubrication.transition",
                               f"must be an eccentricity ratio in (0, 1), got {lub.transition}")
    if wear.model not in WEAR_MODELS:
        raise DescriptionError("wear.model",
                               f"must be one of {', '.join(WEAR_MODELS)}, got {wear.model!r}")
    _positive("wear.coefficient", wear.coefficient)
    _positive("wear.hardness", wear.hardness)


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
    _validate_effects(robot)
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
    """joint{j}.length: positive wherever given; required where a compiled law or effect uses
    it (a cylindrical contact stiffness, lubrication, wear)."""
    stiffness = robot.contact.stiffness
    users = ([f"contact.stiffness = {stiffness!r}"] if stiffness != "hertz" else []) + [
        name for name in ("lubrication", "wear") if getattr(robot, name).model != "none"]
    for i, joint in enumerate(robot.joints, start=1):
        if joint.length is not None:
            _positive(f"joints[{i}].length", joint.length)
        if not joint.has_clearance or not users:
            continue
        if joint.length is None:
            raise DescriptionError(
                f"joints[{i}].length",
                f"is required by {' and '.join(users)}: the axial length of the journal and "
                "bearing in m; add e.g. length = 0.02 to this [[joints]] entry")
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

_TOP_KEYS = ("name", "links", "joints", "payload", "gravity", "contact", "friction", "drive",
             "lubrication", "wear")
_LINK_KEYS = ("length", "mass", "inertia", "com")
_JOINT_KEYS = ("kind", "angle", "bearing_radius", "journal_radius", "bearing_E", "bearing_nu",
               "journal_E", "journal_nu", "length")
_FLOAT_FIELDS = {"length", "mass", "inertia", "com", "angle", "bearing_radius", "journal_radius",
                 "bearing_E", "bearing_nu", "journal_E", "journal_nu", "exponent", "restitution",
                 "impact_speed_floor", "mu", "v0", "v1", "viscosity", "transition",
                 "coefficient", "hardness"}


def check_keys(table: Any, allowed: Sequence[str], where: str,
               source: str | None = None) -> None:
    """Refuse a non-table or an unknown key, naming the nearest allowed key."""
    if not isinstance(table, Mapping):
        raise DescriptionError(where or "(top level)",
                               f"must be a table, got {type(table).__name__}", source)
    for key in table:
        if key not in allowed:
            hint = did_you_mean(key, allowed)
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
            hint = did_you_mean(str(kind), JOINT_KINDS)
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
    lubrication_raw = data.get("lubrication", {})
    check_keys(lubrication_raw, tuple(vars(Lubrication())), "lubrication")
    wear_raw = data.get("wear", {})
    check_keys(wear_raw, tuple(vars(Wear())), "wear")
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
        lubrication=Lubrication(**_numbers(lubrication_raw, "lubrication")),
        wear=Wear(**_numbers(wear_raw, "wear")),
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
    from jointplay.common.files import read_input
    from jointplay.common.limits import MAX_TOML_BYTES

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
    known = {p.name: p for p in robot.parameters()}
    links = [vars(link).copy() for link in robot.links]
    joints = [vars(j).copy() for j in robot.joints]
    effects = {"contact": vars(robot.contact).copy(), "friction": vars(robot.friction).copy(),
               "lubrication": vars(robot.lubrication).copy(), "wear": vars(robot.wear).copy()}
    gravity = list(robot.gravity.vector)
    payload = robot.payload_mass
    for name, value in values.items():
        if name not in known:
            raise DescriptionError(name, "is not a parameter of this model"
                                   + did_you_mean(name, sorted(known)))
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


def uniform_chain(n_links: int, kinds: Iterable[str] | None = None, **kwargs: Any) -> Robot:
    """A chain of identical 0.3 m, 1 kg rods; handy for tests and benchmarks."""
    kinds = list(kinds) if kinds is not None else ["ideal"] * n_links
    length = 0.3
    link = Link(length=length, mass=1.0, inertia=length**2 / 12, com=length / 2)
    return Robot(links=(link,) * n_links,
                 joints=tuple(Joint(kind=k) for k in kinds),  # type: ignore[arg-type]
                 name=kwargs.pop("name", f"chain{n_links}"), **kwargs)
