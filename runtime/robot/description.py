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
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any, Literal

# The parameters by name live in their own module; their names stay importable from here.
from jointplay.robot.parameters import CLEARANCE_ALIAS as CLEARANCE_ALIAS
from jointplay.robot.parameters import _index
from jointplay.robot.parameters import clearance_aliases as clearance_aliases
from jointplay.robot.parameters import parameter_name as parameter_name
from jointplay.robot.parameters import resolve_aliases as resolve_aliases
from jointplay.robot.parameters import unknown_parameter as unknown_parameter
from jointplay.robot.parameters import with_parameters as with_parameters
from jointplay.robot.structure import (
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
    """One rigid link.

    Attributes
    ----------
    length : float
        Distance between its proximal and distal joints, m.
    mass : float
        kg.
    inertia : float
        Moment of inertia about the centre of mass, normal to the plane, kg m^2.
    com : float
        Distance of the centre of mass from the proximal joint, along the link, m.
    """

    length: float
    mass: float
    inertia: float
    com: float  # distance of the centre of mass from the proximal joint, along the link (m)


@dataclass(frozen=True)
class Joint:
    """Joint i joins link i-1 (or the ground for i = 1) to link i.

    For the clearance kinds the journal (on link i) of radius ``journal_radius`` sits in the
    bearing (on link i-1) of radius ``bearing_radius``; their difference is the radial
    clearance.

    Attributes
    ----------
    kind : {"ideal", "clearance", "locked", "locked_clearance"}
        ``ideal``: revolute, no play (one angle coordinate); ``clearance``: revolute with play
        (one angle plus the eccentricity (ex, ey)); ``locked``: no relative rotation (held at
        ``angle``), no coordinate; ``locked_clearance``: no relative rotation, but the journal
        floats in the bearing (ex, ey).
    angle : float
        The locked relative angle, rad; used by the locked kinds only.
    bearing_radius : float
        m.
    journal_radius : float
        m, less than ``bearing_radius``.
    bearing_E : float
        The bearing's Young's modulus, Pa.
    bearing_nu : float
        The bearing's Poisson's ratio.
    journal_E : float
        The journal's Young's modulus, Pa.
    journal_nu : float
        The journal's Poisson's ratio.
    length : float or None
        Axial length of the journal and bearing, m: needed only by the laws and effects that act
        along it (a cylindrical contact law, lubrication, wear), so None is valid until one is
        compiled.
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
    """Gravity in the plane of motion.

    Attributes
    ----------
    enabled : bool
        Whether the model has gravity (structure: compiled in or out).
    vector : tuple of float
        The acceleration of gravity (x, y), m/s^2.
    """

    enabled: bool = True
    vector: tuple[float, float] = (0.0, -9.81)  # m/s^2, in the plane of motion


@dataclass(frozen=True)
class Contact:
    """Continuous dissipative contact at clearance joints: F_n = F_e(d) (1 + x(ce) d'/d'-).

    Attributes
    ----------
    law : {"lankarani-nikravesh", "hunt-crossley", "gonthier", "flores"}
        The damping factor x(ce).
    stiffness : str
        The elastic force F_e(d): ``"hertz"`` (K d^n), or a conformal-cylinder law
        (``"johnson"``, ``"liu"``, ``"pereira"``) that needs each clearance joint's ``length``.
    exponent : float
        Hertz's exponent n.
    restitution : float
        The coefficient of restitution ce, 0 to 1.
    impact_speed_floor : float
        Floor of the captured impact speed d'-, m/s: grazing contact would otherwise give a
        damping coefficient x K / d'- that grows without bound.
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

    Attributes
    ----------
    law : {"coulomb", "none"}
        ``"none"`` compiles friction out.
    ramp : str
        The shape of c_d between ``v0`` and ``v1`` (``"linear"`` or a smooth ramp).
    mu : float
        The friction coefficient.
    v0 : float
        c_d = 0 below this sliding speed, m/s (>= 0; 0 ramps from zero speed).
    v1 : float
        c_d = 1 above this sliding speed, m/s (> v0).
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
    Above it the film is regularised, and what the run reports there (how far the journal
    squeezes the film) depends on the transition, not on the film: the default 0.99 is above
    every eccentricity ratio the lubricated paper arm reaches (0.985; at 0.95 it reported 0.9994,
    an artefact), and the run's summary says when a joint went above it.
    """

    model: str = "none"
    viscosity: float = 0.04
    transition: float = 0.99


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
    """A planar serial robot with optional clearance joints, validated on construction.

    Its structure (:meth:`structure`: link count, joint kinds, which effects exist) is what
    the compiled model depends on; every number is a run-time parameter (:meth:`parameters`).

    Attributes
    ----------
    links : tuple of Link
        The links, base first.
    joints : tuple of Joint
        One joint per link: joint i joins link i-1 (the ground for i = 1) to link i.
    name : str
        The robot's name (it names its model).
    payload_mass : float
        A point mass at the tip of the last link, kg.
    gravity : Gravity
        Gravity in the plane.
    contact : Contact
        The contact law of the clearance joints.
    friction : Friction
        Their friction.
    drive : bool
        Drive torques on the joints that move.
    lubrication : Lubrication
        A lubricant film in the clearance joints (none by default).
    wear : Wear
        Archard wear of the clearance joints (none by default).

    Raises
    ------
    DescriptionError
        On construction, naming the field and the fix.

    Examples
    --------
    >>> import jointplay
    >>> robot = jointplay.default_robot()
    >>> robot.n_links, robot.moving_joints, robot.clearance_joints
    (4, (2, 3), (2, 3))
    >>> round(robot.joints[1].bearing_radius - robot.joints[1].journal_radius, 9)  # m: play
    3e-05
    >>> robot.structure().joints
    ('locked', 'clearance', 'clearance', 'locked')
    """

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
        from jointplay.robot.validation import validate

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


def uniform_chain(n_links: int, kinds: Iterable[str] | None = None, **kwargs: Any) -> Robot:
    """A chain of identical 0.3 m, 1 kg uniform rods; handy for tests and benchmarks.

    Parameters
    ----------
    n_links : int
        The number of links.
    kinds : iterable of str, optional
        The kind of each joint (see :class:`Joint`); default all ``"ideal"``.
    **kwargs
        Any other field of :class:`Robot` (``name``, ``payload_mass``, ``friction``, ...).

    Returns
    -------
    Robot
        The chain, named ``chainN`` unless ``name`` is given.

    Examples
    --------
    >>> import jointplay
    >>> robot = jointplay.uniform_chain(3, ["ideal", "clearance", "ideal"], payload_mass=0.5)
    >>> robot.name, robot.moving_joints, robot.clearance_joints
    ('chain3', (1, 2, 3), (2,))
    >>> [p.name for p in robot.parameters()][:3]
    ['link1.length', 'link1.mass', 'link1.inertia']
    """
    kinds = list(kinds) if kinds is not None else ["ideal"] * n_links
    length = 0.3
    link = Link(length=length, mass=1.0, inertia=length**2 / 12, com=length / 2)
    return Robot(links=(link,) * n_links,
                 joints=tuple(Joint(kind=k) for k in kinds),  # type: ignore[arg-type]
                 name=kwargs.pop("name", f"chain{n_links}"), **kwargs)
