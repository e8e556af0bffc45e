"""What a mechanism's calibration takes: its free parameters and its measured outputs.

A free name is any runtime parameter of the mechanism's model (``jointplay inspect FILE``
lists them: ``friction.mu``, ``rod.mass``, ``slider_pin.journal_radius``...) or
``JOINT.clearance``, the radial clearance of a clearance joint with its bearing radius held
(the journal's radius follows). The bounds are the ranges the mechanism file's validation
accepts for each kind of number, so the fit never proposes a mechanism the file would refuse.

The measured outputs are the columns ``jointplay simulate MECHANISM.toml --csv`` writes,
named the same: ``time`` and any of the coordinates (``guide.position``,
``crank_pin.angle``), their rates (``d/dt guide.position``) and accelerations
(``d2/dt2 guide.position``), ``driving_torque``, each clearance joint's eccentricity and
normal force (``slider_pin.ex``, ``slider_pin.ey``, ``slider_pin.normal_force``) and the
energies; the clock ``t`` is time itself, not a measurement. A results file (.h5 of
``jointplay simulate --out``) gives the coordinates and the eccentricities. Every cell is
checked before any run; the times must lie on the run's output grid.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np

from jointplay.calibration.measured import (
    Measured,
    checked_header,
    checked_times,
    grid_indices,
    read_csv_table,
)
from jointplay.calibration.parameters import FreeParameters, checked_free_parameters
from jointplay.common.errors import DescriptionError
from jointplay.common.hints import did_you_mean
from jointplay.common.limits import MIN_RADIAL_CLEARANCE, PHYSICAL_RANGES
from jointplay.mechanism.description import MechanismScene
from jointplay.mechanism.model import MechanismModel

CLEARANCE = ".clearance"
CLOCK = "t"
ENERGIES = ("driving_torque", "kinetic", "potential", "contact_potential", "drive_work",
            "dissipated")
RATE, ACCELERATION = "d/dt ", "d2/dt2 "
JOINT_OUTPUTS = ("ex", "ey", "normal_force")
_OPEN = 1e-9  # a relative hair inside an open end of a range (nu < 0.5)

# The range kind of each parameter name, by pattern (PHYSICAL_RANGES keys, or an interval).
_RANGES: tuple[tuple[re.Pattern[str], tuple[float, float] | str], ...] = (
    (re.compile(r"[^.]+\.mass"), "link.mass"),
    (re.compile(r"[^.]+\.inertia"), "link.inertia"),
    (re.compile(r"[^.]+\.angle"), "joint.angle"),
    (re.compile(r"[^.]+\.(bearing|journal)_radius"), "joint.radius"),
    (re.compile(r"[^.]+\.(bearing|journal)_E"), "joint.E"),
    (re.compile(r"[^.]+\.(bearing|journal)_nu"), (0.0, 0.5 - _OPEN)),
    (re.compile(r"gravity\.[xy]"), "gravity"),
    (re.compile(r"contact\.restitution"), (1e-3, 1.0)),
    (re.compile(r"contact\.exponent"), "contact.exponent"),
    (re.compile(r"contact\.impact_speed_floor"), "contact.impact_speed_floor"),
    (re.compile(r"friction\.(mu|v0|v1)"), ""),
)


def output_columns(model: MechanismModel) -> list[str]:
    """Every column a mechanism's measurement may hold, in ``simulate --csv``'s order."""
    coordinates = [c for c in model.coordinates if c != CLOCK]
    return [*coordinates, *(RATE + c for c in coordinates),
            *(ACCELERATION + c for c in coordinates), *ENERGIES,
            *(f"{j}.{k}" for j in model.cut_joint_names for k in JOINT_OUTPUTS)]


def clearance_joint(name: str, scene: MechanismScene) -> str | None:
    """The clearance joint a ``JOINT.clearance`` name refers to (None: not such a name)."""
    if not name.endswith(CLEARANCE):
        return None
    joint = name.removesuffix(CLEARANCE)
    return joint if any(j.name == joint and j.kind == "clearance"
                        for j in scene.mechanism.joints) else None


def mechanism_free_parameters(names: Sequence[str], scene: MechanismScene,
                              model: MechanismModel, start: Mapping[str, float] | None = None
                              ) -> FreeParameters:
    """Check ``names`` against the mechanism and ``start`` against the physical ranges;
    raises :class:`DescriptionError` naming the first bad name (``free NAME``, ``start
    NAME``)."""
    return checked_free_parameters(
        names, start, "friction.mu or slider_pin.clearance",
        lambda name: _check_known(name, scene, model),
        lambda name: parameter_range(name, scene), lambda name: scene_value(name, scene),
        check_names=lambda given: _check_radii(given, scene))


def scene_value(name: str, scene: MechanismScene) -> float:
    joint = clearance_joint(name, scene)
    if joint is not None:
        return float(next(j.radial_clearance for j in scene.mechanism.joints
                          if j.name == joint))
    return float(scene.mechanism.parameter_values()[name])


def parameter_range(name: str, scene: MechanismScene) -> tuple[float, float]:
    """The closed interval of values the mechanism file accepts for ``name`` (a radius kept
    at least a nanometre of play from its partner)."""
    joints = {j.name: j for j in scene.mechanism.joints}
    joint = clearance_joint(name, scene)
    if joint is not None:
        bearing = joints[joint].clearance["bearing_radius"]
        return MIN_RADIAL_CLEARANCE, bearing - PHYSICAL_RANGES["joint.radius"][0]
    owner, _, key = name.partition(".")
    for pattern, kind in _RANGES:
        if pattern.fullmatch(name):
            if isinstance(kind, tuple):
                return kind
            low, high, _, _ = PHYSICAL_RANGES[kind or name]
            if key == "journal_radius":
                high = min(high, joints[owner].clearance["bearing_radius"]
                           - MIN_RADIAL_CLEARANCE)
            elif key == "bearing_radius":
                low = max(low, joints[owner].clearance["journal_radius"] + MIN_RADIAL_CLEARANCE)
            return float(low), float(high)
    return -math.inf, math.inf


def _check_known(name: str, scene: MechanismScene, model: MechanismModel) -> None:
    if clearance_joint(name, scene) is not None or name in model.parameters:
        return
    clearances = [f"{j}{CLEARANCE}" for j in model.cut_joint_names]
    if name.endswith(CLEARANCE):
        raise DescriptionError(f"free {name}", f"{name.removesuffix(CLEARANCE)!r} is no "
                               "clearance joint of this mechanism (clearance parameters: "
                               f"{', '.join(clearances) or 'none'})")
    try:  # the mechanism's own words for a name it knows but has switched off
        scene.mechanism.with_values({name: 0.0})
        message = "is not a parameter of this mechanism's model"
    except DescriptionError as err:
        message = err.message
    raise DescriptionError(f"free {name}", message + did_you_mean(
        name, [*model.parameters, *clearances]))


def _check_radii(names: Sequence[str], scene: MechanismScene) -> None:
    """One number per clearance joint's play: its clearance, or one of its radii."""
    for j in scene.mechanism.joints:
        if j.kind != "clearance":
            continue
        given = [n for n in (f"{j.name}{CLEARANCE}", f"{j.name}.bearing_radius",
                             f"{j.name}.journal_radius") if n in names]
        if len(given) > 1:
            raise DescriptionError(f"free {given[1]}", f"frees the play of {j.name!r} twice "
                                   f"(with {given[0]}); free one of {j.name}.clearance, "
                                   "its bearing_radius or its journal_radius")


def read_mechanism_measured(path: str | Path, model: MechanismModel) -> Measured:
    """The measured samples in ``path`` (CSV, or a mechanism results file)."""
    path = Path(path)
    if not path.is_file():
        raise DescriptionError("measured", f"{path} does not exist or is not a file; give a "
                               "CSV table or a mechanism results file (.h5)")
    if path.suffix.lower() in (".h5", ".hdf5"):
        return _from_results(path, model)
    return _from_csv(path, model)


def on_output_grid(measured: Measured, scene: MechanismScene) -> Measured:
    """``measured`` if every time lies on the run's output grid; else the error naming the
    first time off it."""
    step = scene.run.output_step
    if grid_indices(measured.t, step) is None:
        k = np.rint(measured.t / step)
        first = int(np.argmax(np.abs(measured.t - k * step) > 1e-9 * step))
        raise DescriptionError("time", f"{measured.t[first]:.17g} s (sample {first + 1}) is "
                               f"not on the run's output grid (multiples of run.output_step "
                               f"= {step:g} s); a mechanism is compared at its samples: set "
                               "run.output_step in the scene file to the sampling interval "
                               "(or a divisor of it)", measured.source)
    return measured


def _from_csv(path: Path, model: MechanismModel) -> Measured:
    clock = "is the model's clock (time itself), not a measurement; drop the column"
    refused = {name: clock for name in (CLOCK, RATE + CLOCK, ACCELERATION + CLOCK)}
    return read_csv_table(path, "time, guide.position, ...",
                          lambda header, source: checked_header(
                              header, output_columns(model), source,
                              "is not an output of this mechanism", refused))


def _from_results(path: Path, model: MechanismModel) -> Measured:
    from jointplay.mechanism.results import is_mechanism_result, read_mechanism_result

    if not is_mechanism_result(path):
        raise DescriptionError("measured", "is not a mechanism results file (jointplay "
                               "simulate MECHANISM.toml --out); give one, or a CSV", str(path))
    result = read_mechanism_result(path, "measured")
    coordinates = [c for c in model.coordinates if c != CLOCK]
    if result.coordinates != model.coordinates or result.cut_joints != model.cut_joint_names:
        raise DescriptionError("measured", f"is a run of another mechanism (coordinates "
                               f"{', '.join(result.coordinates)}); measure this scene's",
                               str(path))
    columns = [*coordinates, *(f"{j}.{k}" for j in model.cut_joint_names for k in ("ex", "ey"))]
    values = np.column_stack([*(result.coordinate(c) for c in coordinates),
                              *(result.eccentricity[:, j, k]
                                for j in range(len(model.cut_joint_names)) for k in (0, 1))])
    if not np.all(np.isfinite(values)):
        raise DescriptionError("measured", "holds values that are not finite", str(path))
    return checked_times(Measured(str(path), np.asarray(result.t, float), tuple(columns),
                                   values))
