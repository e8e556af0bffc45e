"""Validation of a robot description: every field checked, each bad one named with what is
allowed (a :class:`~jointplay.common.errors.DescriptionError`, or
:class:`~jointplay.common.errors.DescriptionErrors` for several, all reported at once).

Every number is also checked against the physical range of its kind
(:data:`jointplay.common.limits.PHYSICAL_RANGES`). This runs when a :class:`Robot` is built,
so a TOML file, ``--set``, a sweep case and the Python API's overrides are checked alike."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from jointplay.common.errors import DescriptionError
from jointplay.common.limits import MIN_RADIAL_CLEARANCE, MIN_RESTITUTION
from jointplay.common.validation import Problems, finite, plausible, positive
from jointplay.robot.description import (
    CONTACT_LAWS,
    CONTACT_STIFFNESSES,
    FRICTION_LAWS,
    FRICTION_RAMPS,
    LUBRICATION_MODELS,
    MAX_LINKS,
    PEREIRA_CLEARANCE_RANGE,
    WEAR_MODELS,
)
from jointplay.robot.structure import JOINT_KINDS

if TYPE_CHECKING:
    from jointplay.robot.description import Joint, Robot


def _validate_effects(robot: Robot) -> None:
    """Lubrication, wear, and the joint length they need."""
    lub, wear = robot.lubrication, robot.wear
    if lub.model not in LUBRICATION_MODELS:
        raise DescriptionError("lubrication.model",
                               f"must be one of {', '.join(LUBRICATION_MODELS)}, got {lub.model!r}")
    positive("lubrication.viscosity", lub.viscosity)
    plausible("lubrication.viscosity", lub.viscosity, "lubrication.viscosity")
    finite("lubrication.transition", lub.transition)
    if not 0.0 < lub.transition < 1.0:
        raise DescriptionError("lubrication.transition",
                               f"must be an eccentricity ratio in (0, 1), got {lub.transition}")
    if wear.model not in WEAR_MODELS:
        raise DescriptionError("wear.model",
                               f"must be one of {', '.join(WEAR_MODELS)}, got {wear.model!r}")
    problems = Problems()
    for name in ("coefficient", "hardness"):
        with problems.check():
            positive(f"wear.{name}", getattr(wear, name))
            plausible(f"wear.{name}", getattr(wear, name), f"wear.{name}")
    problems.raise_any()


def check_robot_name(name: object) -> None:
    """A robot's name: it names generated folders and files, so letters, digits, '_', '-'."""
    if not isinstance(name, str) or not name.replace("_", "").replace("-", "").isalnum() \
            or not name.isascii():
        raise DescriptionError("name", f"must be letters, digits, '_' or '-', got {name!r}")


def validate(robot: Robot) -> None:
    """Raise :class:`DescriptionError` naming the invalid fields (all of them)."""
    problems = Problems()
    with problems.check():
        check_robot_name(robot.name)
    with problems.check():
        _validate_links(robot)
    with problems.check():
        positive("payload.mass", robot.payload_mass, allow_zero=True)
        plausible("payload.mass", robot.payload_mass, "payload.mass")
    with problems.check():
        _validate_joints(robot)
    with problems.check():
        _validate_effects(robot)
    with problems.check():
        if not robot.moving_joints and not robot.clearance_joints:
            raise DescriptionError("joints", "at least one joint must move or have play (not "
                                   "every joint locked)")
    with problems.check():
        _validate_gravity(robot)
    with problems.check():
        _validate_contact(robot)
    with problems.check():
        _validate_friction(robot)
    problems.raise_any()


def _validate_links(robot: Robot) -> None:
    """The link count, one joint per link, and each link's dimensions and mass."""
    k = len(robot.links)
    if k < 1 or k > MAX_LINKS:
        raise DescriptionError("links", f"the robot needs 1 to {MAX_LINKS} links, got {k}")
    if len(robot.joints) != k:
        raise DescriptionError(
            "joints", f"needs one joint per link ({k}), got {len(robot.joints)}")
    problems = Problems()
    for i, link in enumerate(robot.links, start=1):
        for name in ("length", "mass", "inertia"):
            with problems.check():
                positive(f"links[{i}].{name}", getattr(link, name))
                plausible(f"links[{i}].{name}", getattr(link, name), f"link.{name}")
        with problems.check():
            finite(f"links[{i}].com", link.com)
            # (a length that is not a number is reported by itself, not again here)
            if isinstance(link.length, (int, float)) and math.isfinite(link.length) \
                    and not 0.0 <= link.com <= link.length:
                raise DescriptionError(
                    f"links[{i}].com",
                    f"must lie on the link, 0 <= com <= length ({link.length}), got {link.com}")
    problems.raise_any()


def _validate_joints(robot: Robot) -> None:
    """Each joint's kind and angle, and the radii and materials of a joint with play."""
    problems = Problems()
    for i, joint in enumerate(robot.joints, start=1):
        with problems.check():
            _validate_joint(i, joint)
    problems.raise_any()


def _validate_joint(i: int, joint: Joint) -> None:
    if joint.kind not in JOINT_KINDS:
        raise DescriptionError(f"joints[{i}].kind",
                               f"must be one of {', '.join(JOINT_KINDS)}, got {joint.kind!r}")
    problems = Problems()
    with problems.check():
        plausible(f"joints[{i}].angle", joint.angle, "joint.angle")
    if joint.has_clearance:
        with problems.check():
            for part in ("bearing", "journal"):
                positive(f"joints[{i}].{part}_radius", getattr(joint, f"{part}_radius"))
                plausible(f"joints[{i}].{part}_radius", getattr(joint, f"{part}_radius"),
                          "joint.radius")
            if joint.journal_radius >= joint.bearing_radius:
                raise DescriptionError(
                    f"joints[{i}].journal_radius",
                    f"must be smaller than bearing_radius ({joint.bearing_radius}) to leave a "
                    f"clearance, got {joint.journal_radius}; use kind = \"ideal\" for no play")
            if joint.bearing_radius - joint.journal_radius < MIN_RADIAL_CLEARANCE:
                raise DescriptionError(
                    f"joints[{i}].journal_radius",
                    f"leaves a radial clearance of {joint.bearing_radius - joint.journal_radius:g}"
                    f" m, below the {MIN_RADIAL_CLEARANCE:g} m a real joint with play has; use "
                    "kind = \"ideal\" for no play")
        for part in ("bearing", "journal"):
            with problems.check():
                positive(f"joints[{i}].{part}_E", getattr(joint, f"{part}_E"))
                plausible(f"joints[{i}].{part}_E", getattr(joint, f"{part}_E"), "joint.E")
            with problems.check():
                nu = getattr(joint, f"{part}_nu")
                finite(f"joints[{i}].{part}_nu", nu)
                if not 0.0 < nu < 0.5:
                    raise DescriptionError(f"joints[{i}].{part}_nu",
                                           f"Poisson's ratio must be in (0, 0.5), got {nu}")
    problems.raise_any()


def _validate_gravity(robot: Robot) -> None:
    g = robot.gravity
    if len(g.vector) != 2:
        raise DescriptionError("gravity.vector", f"must have 2 components, got {len(g.vector)}")
    problems = Problems()
    for axis, v in zip("xy", g.vector, strict=True):
        with problems.check():
            plausible(f"gravity.vector.{axis}", v, "gravity")
    problems.raise_any()


def _validate_contact(robot: Robot) -> None:
    """The contact law and stiffness, the joint lengths they need, and their numbers."""
    c = robot.contact
    if c.law not in CONTACT_LAWS:
        raise DescriptionError("contact.law",
                               f"must be one of {', '.join(CONTACT_LAWS)}, got {c.law!r}")
    if c.stiffness not in CONTACT_STIFFNESSES:
        raise DescriptionError("contact.stiffness", f"must be one of "
                               f"{', '.join(CONTACT_STIFFNESSES)}, got {c.stiffness!r}")
    problems = Problems()
    with problems.check():
        _validate_lengths(robot)
    with problems.check():
        positive("contact.exponent", c.exponent)
        plausible("contact.exponent", c.exponent, "contact.exponent")
    with problems.check():
        finite("contact.restitution", c.restitution)
        if not MIN_RESTITUTION <= c.restitution <= 1.0:
            raise DescriptionError("contact.restitution",
                                   f"must be from {MIN_RESTITUTION:g} to 1, got "
                                   f"{c.restitution:g}")
    with problems.check():
        positive("contact.impact_speed_floor", c.impact_speed_floor)
        plausible("contact.impact_speed_floor", c.impact_speed_floor,
                  "contact.impact_speed_floor")
    problems.raise_any()


def _validate_friction(robot: Robot) -> None:
    f = robot.friction
    if f.law not in FRICTION_LAWS:
        raise DescriptionError("friction.law",
                               f"must be one of {', '.join(FRICTION_LAWS)}, got {f.law!r}")
    if f.ramp not in FRICTION_RAMPS:
        raise DescriptionError("friction.ramp",
                               f"must be one of {', '.join(FRICTION_RAMPS)}, got {f.ramp!r}")
    problems = Problems()
    with problems.check():
        positive("friction.mu", f.mu, allow_zero=True)
        plausible("friction.mu", f.mu, "friction.mu")
    # v0 = 0: the correction ramps from zero speed; the law's direction floor keeps it finite.
    with problems.check():
        positive("friction.v0", f.v0, allow_zero=True)
        plausible("friction.v0", f.v0, "friction.v0")
    with problems.check():
        positive("friction.v1", f.v1)
        plausible("friction.v1", f.v1, "friction.v1")
    problems.raise_any()
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
            positive(f"joints[{i}].length", joint.length)
            plausible(f"joints[{i}].length", joint.length, "joint.length")
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
                    f"contact law was fitted for ({low:g} m <= c < {high:g} m); choose radii "
                    "in that range or another contact.stiffness (johnson, liu)")


