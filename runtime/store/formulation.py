"""Which formulation of the dynamics a model is emitted with: decided without sympy.

* ``closed``: Kane's mass matrix and forcing as expressions, solved by a sparse LDL^T; the
  Jacobian by AD of M a - f. The smallest code for short chains (the paper robot).
* ``recursive``: the articulated-body algorithm over the chain, and the Jacobian as
  -M^-1 dID/dx through the articulated inertias (:mod:`jointplay.derive.recursive`), or,
  for long chains of clearance joints, by the chain rule through each link's pose and
  twist (:mod:`jointplay.derive.recursive_chain_rule`). Its derivation time does not grow
  with the chain, and its cost grows linearly (forward dynamics) and quadratically (state
  Jacobian) in the coordinates, where the closed form's grow faster.

``auto`` (the default) takes the recursion from :data:`RECURSIVE_FROM_COORDINATES`
coordinates on. The latest measurement (docs/results/build-times.md, "Which formulation a model is
emitted with")
has the recursion as cheap or cheaper from 2 coordinates on in most cases, the paper robot
included; the threshold stays above the paper robot until its checked-in model and the
figures measured on it are regenerated with the recursion;
``$JOINTPLAY_FORMULATION`` or an explicit argument overrides it. The formulation is part of a
model's input hash, so both can sit in the cache side by side.
"""

from __future__ import annotations

import os

from jointplay.common.errors import DescriptionError
from jointplay.robot.structure import Structure

FORMULATIONS = ("closed", "recursive")
CHOICES = ("auto", *FORMULATIONS)
ENVIRONMENT = "JOINTPLAY_FORMULATION"
# From this many coordinates on, ``auto`` emits the recursion (see the module docstring).
RECURSIVE_FROM_COORDINATES = 7


def coordinate_count(structure: Structure) -> int:
    return len(structure.moving_joints) + 2 * len(structure.clearance_joints)


def formulation_for(structure: Structure, requested: str | None = None) -> str:
    """``closed`` or ``recursive`` for ``structure``: ``requested`` if given, else
    ``$JOINTPLAY_FORMULATION``, else ``auto`` (chosen by the number of coordinates)."""
    source = "the formulation"
    if requested is None:
        requested = os.environ.get(ENVIRONMENT) or "auto"
        source = f"${ENVIRONMENT}"
    if requested not in CHOICES:
        raise DescriptionError(source, f"{requested!r} is not a formulation; use one of "
                               f"{', '.join(CHOICES)} (auto: chosen by the number of "
                               "coordinates)")
    if requested != "auto":
        return requested
    return ("recursive" if coordinate_count(structure) >= RECURSIVE_FROM_COORDINATES
            else "closed")
