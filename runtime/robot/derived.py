"""Parameters derived from the robot's own numbers: ``jointN.clearance``.

The parameter vector holds each clearance joint's two radii; what wear and calibration speak
of is the radial clearance c = Rb - Rj between them. ``jointN.clearance`` is that clearance
with the bearing radius held, so setting it moves the journal radius (Rj = Rb - c), and its
direction in the parameter vector is d(Rj)/dc = -1. Every name a run accepts by name (the
robot's parameters and these) resolves here, in one place: to values of the parameter
vector (:func:`expand_derived`) and to directions in it (:func:`parameter_directions`).
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.robot.description import Robot

_CLEARANCE = re.compile(r"joint(\d+)\.clearance")


def derived_names(parameter_names: Sequence[str]) -> list[str]:
    """The derived names a model with ``parameter_names`` has: ``jointN.clearance`` for each
    joint with both radii (a clearance joint)."""
    names = []
    for name in parameter_names:
        m = re.fullmatch(r"joint(\d+)\.bearing_radius", name)
        if m and f"joint{m.group(1)}.journal_radius" in parameter_names:
            names.append(f"joint{m.group(1)}.clearance")
    return names


def _unknown(name: str, parameter_names: Sequence[str], robot: Robot) -> DescriptionError:
    from jointplay.common.hints import did_you_mean
    from jointplay.robot.description import unknown_parameter

    m = _CLEARANCE.fullmatch(name)
    if m:
        return DescriptionError(name, f"joint {m.group(1)} has no radial clearance in this "
                                "model (not a clearance joint)"
                                + did_you_mean(name, derived_names(parameter_names)))
    err = unknown_parameter(name, robot)
    if "initial value" in err.message:
        return err
    return DescriptionError(name, "is not a parameter of this model"
                            + did_you_mean(name, [*parameter_names,
                                                  *derived_names(parameter_names)]))


def parameter_directions(names: Sequence[str], parameter_names: Sequence[str],
                         robot: Robot) -> np.ndarray:
    """d(parameter vector)/d(name) for each name, as rows (len(names), len(parameter_names)):
    a unit vector for a parameter, -1 on the journal radius for ``jointN.clearance``.
    Raises :class:`DescriptionError` naming a name the model does not have (and the nearest
    one it has)."""
    params = list(parameter_names)
    rows = np.zeros((len(names), len(params)))
    for k, name in enumerate(names):
        if name in params:
            rows[k, params.index(name)] = 1.0
            continue
        m = _CLEARANCE.fullmatch(name)
        journal = f"joint{m.group(1)}.journal_radius" if m else ""
        if not m or journal not in params or f"joint{m.group(1)}.bearing_radius" not in params:
            raise _unknown(name, params, robot)
        rows[k, params.index(journal)] = -1.0
    return rows


def expand_derived(values: Mapping[str, float], parameter_names: Sequence[str],
                   robot: Robot, current: Mapping[str, float]) -> dict[str, float]:
    """``values`` with every ``jointN.clearance`` replaced by the journal radius it gives
    (the bearing radius from ``values`` if set there, else from ``current``); other names
    pass through unchanged (checked by the caller). A clearance set beside its own journal
    radius is a contradiction and raises."""
    out: dict[str, float] = {}
    for name, value in values.items():
        m = _CLEARANCE.fullmatch(str(name))
        if not m or name in parameter_names:
            out[name] = value
            continue
        bearing = f"joint{m.group(1)}.bearing_radius"
        journal = f"joint{m.group(1)}.journal_radius"
        if journal not in parameter_names:
            raise _unknown(str(name), list(parameter_names), robot)
        if journal in values:
            raise DescriptionError(str(name), f"is set beside {journal}, which it determines "
                                   "(Rj = Rb - c); set one of them")
        if isinstance(value, bool) or not isinstance(value, (int, float, np.integer,
                                                              np.floating)):
            raise DescriptionError(str(name), f"must be a number, got {value!r}")
        rb = float(values.get(bearing, current[bearing]))
        if not 0 < float(value) < rb:
            raise DescriptionError(str(name), f"must be a radial clearance between 0 and the "
                                   f"bearing radius ({rb:g} m), got {value!r}; use kind = "
                                   "\"ideal\" for no play")
        out[journal] = rb - float(value)
    return out
