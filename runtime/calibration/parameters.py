"""The free parameters of a calibration: their names, start values and physical ranges.

A free name is any robot parameter ``--set`` accepts (``friction.mu``, ``link2.mass``, ...) or
``jointN.clearance`` (the radial clearance of clearance joint N, its bearing radius held). The
bounds are the ranges the validation accepts (:data:`jointplay.common.limits.PHYSICAL_RANGES`,
the robot validation's open intervals), so the fit never proposes a robot the simulator refuses.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.common.hints import did_you_mean
from jointplay.common.limits import MIN_RADIAL_CLEARANCE, PHYSICAL_RANGES
from jointplay.scene.definition import Scene
from jointplay.store.model import Model

_CLEARANCE = re.compile(r"joint(\d+)\.clearance")

# The range kind of each parameter name, by pattern (PHYSICAL_RANGES keys).
_KINDS = (
    (re.compile(r"link\d+\.(length|mass|inertia)"), lambda m: f"link.{m.group(1)}"),
    (re.compile(r"payload\.mass"), lambda m: "payload.mass"),
    (re.compile(r"joint\d+\.angle"), lambda m: "joint.angle"),
    (re.compile(r"joint\d+\.(bearing|journal)_radius"), lambda m: "joint.radius"),
    (re.compile(r"joint\d+\.(bearing|journal)_E"), lambda m: "joint.E"),
    (re.compile(r"joint\d+\.length"), lambda m: "joint.length"),
    (re.compile(r"gravity\.[xy]"), lambda m: "gravity"),
    (re.compile(r"(contact\.exponent|contact\.impact_speed_floor|friction\.mu|friction\.v0|"
                r"friction\.v1|lubrication\.viscosity|wear\.coefficient|wear\.hardness)"),
     lambda m: m.group(1)),
)
# Open intervals of the robot validation, kept a relative hair inside: the fit may reach a bound.
_OPEN = 1e-9
_INTERVALS = (
    (re.compile(r"joint\d+\.(bearing|journal)_nu"), (_OPEN, 0.5 - _OPEN)),
    (re.compile(r"contact\.restitution"), (_OPEN, 1.0)),
)


@dataclass(frozen=True)
class FreeParameters:
    """The parameters a calibration adjusts: names, start values and physical bounds."""

    names: tuple[str, ...]
    start: np.ndarray
    lower: np.ndarray
    upper: np.ndarray

    @property
    def size(self) -> int:
        return len(self.names)

    def as_overrides(self, values: Sequence[float] | np.ndarray) -> dict[str, float]:
        """``simulate(parameters=...)`` overrides giving the free parameters ``values``
        (``jointN.clearance`` among them: the simulator resolves it, bearing radius held)."""
        return {name: float(value) for name, value in zip(self.names, values, strict=True)}


def free_parameters(names: Sequence[str], scene: Scene, model: Model,
                    start: Mapping[str, float] | None = None,
                    flag: str = "free") -> FreeParameters:
    """Check ``names`` against the model and ``start`` against the physical ranges.

    Raises :class:`DescriptionError` naming the first bad name: unknown, repeated, absent
    from this model (friction in a frictionless robot), or a start outside its range.
    """
    return checked_free_parameters(
        names, start, "friction.mu or joint2.clearance",
        lambda name: _check_known(name, scene, model, flag),
        lambda name: physical_range(name, scene), lambda name: scene_value(name, scene), flag=flag)


def checked_free_parameters(names: Sequence[str], start: Mapping[str, float] | None,
                            example: str, check_known: Callable[[str], None],
                            value_range: Callable[[str], tuple[float, float]],
                            own_value: Callable[[str], float],
                            check_names: Callable[[Sequence[str]], None] | None = None,
                            flag: str = "free") -> FreeParameters:
    """The free parameters ``names`` starting at ``start`` (else ``own_value``), checked.

    ``example`` names two free parameters for the error when none is given; ``check_known``
    refuses a name the model lacks, ``check_names`` (if given) the names together; ``value_range``
    gives each name's bounds. The scene's and the mechanism's calibrations both check here.
    """
    if not names:
        raise DescriptionError(flag, f"no parameter names given; name at least one, e.g. {example}")
    seen: set[str] = set()
    for name in names:
        if name in seen:
            raise DescriptionError(f"{flag} {name}", "is named twice; name it once")
        seen.add(name)
        check_known(name)
    if check_names is not None:
        check_names(names)
    start = dict(start or {})
    for name in start:
        if name not in seen:
            raise DescriptionError(f"start {name}", "is not a free parameter; give start "
                                   f"values for the free ones only ({', '.join(names)})")
    rows = []
    for name in names:
        low, high = value_range(name)
        value = float(start[name]) if name in start else own_value(name)
        if not math.isfinite(value) or not low <= value <= high:
            raise DescriptionError(f"start {name}", f"{value!r} is outside its physical range "
                                   f"[{low:g}, {high:g}]; start inside it")
        rows.append((value, low, high))
    return FreeParameters(tuple(names), *(np.array(column) for column in zip(*rows, strict=True)))


def scene_value(name: str, scene: Scene) -> float:
    """The scene's own value of a free parameter."""
    if m := _CLEARANCE.fullmatch(name):
        joint = scene.robot.joints[int(m.group(1)) - 1]
        return float(joint.bearing_radius - joint.journal_radius)
    values = dict(zip([p.name for p in scene.robot.parameters()],
                      scene.robot.parameter_values(), strict=True))
    return float(values[name])


def physical_range(name: str, scene: Scene) -> tuple[float, float]:
    """The interval of values the project's validation accepts for ``name`` (closed)."""
    if m := _CLEARANCE.fullmatch(name):
        return _clearance_range(int(m.group(1)), scene)
    for pattern, interval in _INTERVALS:
        if pattern.fullmatch(name):
            return interval
    for pattern, kind in _KINDS:
        if found := pattern.fullmatch(name):
            low, high, _, _ = PHYSICAL_RANGES[kind(found)]
            return float(low), float(high)
    if m := re.fullmatch(r"link(\d+)\.com", name):
        return 0.0, float(scene.robot.links[int(m.group(1)) - 1].length)
    return -math.inf, math.inf


def _clearance_range(joint: int, scene: Scene) -> tuple[float, float]:
    """Radial clearance with the bearing held: at least a nanometre, a journal of at least
    the smallest plausible radius, and Pereira's fitted range where that law is compiled."""
    from jointplay.robot.description import PEREIRA_CLEARANCE_RANGE

    bearing = float(scene.robot.joints[joint - 1].bearing_radius)
    low, high = MIN_RADIAL_CLEARANCE, bearing - PHYSICAL_RANGES["joint.radius"][0]
    if scene.robot.contact.stiffness == "pereira":
        p_low, p_high = PEREIRA_CLEARANCE_RANGE
        low, high = max(low, p_low), min(high, p_high * (1 - _OPEN))
    return low, high


def _check_known(name: str, scene: Scene, model: Model, flag: str) -> None:
    if m := _CLEARANCE.fullmatch(name):
        joint = int(m.group(1))
        if joint not in model.clearance_joints:
            have = ", ".join(f"joint{j}.clearance" for j in model.clearance_joints) or "none"
            raise DescriptionError(f"{flag} {name}", f"joint {joint} has no clearance in this "
                                   f"model (clearance parameters: {have})")
    elif name not in model.parameters:
        from jointplay.robot.description import unknown_parameter

        known = [*model.parameters, *(f"joint{j}.clearance" for j in model.clearance_joints)]
        message = unknown_parameter(name, scene.robot).message
        if "is not a parameter" in message:
            message = "is not a parameter of this model" + did_you_mean(name, known)
        raise DescriptionError(f"{flag} {name}", message)
