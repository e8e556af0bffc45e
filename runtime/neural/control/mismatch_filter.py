"""The mismatch filter when the sensors' noise is declared: a steady-state Kalman filter per
tracked position-velocity pair.

The first-order filter e_f(k) = b e_f(k-1) + (1 - b) e(k) treats every output alone. A
velocity's mismatch is also the slope of its position's, and the positions are measured far
more finely than their speeds (a 21-bit encoder's 3 µrad against 4 mrad/s for its 1 ms
difference): a slope fitted over ten samples of the position carries a third of the noise
that b = 0.9 leaves on the speed. With the noise declared, each pair whose position and
velocity both have a declared deviation is estimated together: the mismatch modelled as a
position integrating a velocity that drifts as a random walk, both measured, the gain the
steady-state Kalman gain. The random walk's variance q is set so that, with the position
left out, the velocity's gain would be the first-order filter's 1 - b (q = σ_v² (1 - b)² / b):
the filter keeps the bandwidth it had, and the position adds what it knows.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from jointplay.neural.control.imc_settings import ControllerSettings
from jointplay.neural.model.narx import Narx


def position_of(name: str) -> str | None:
    """The position output whose slope the velocity output ``name`` is (dqN -> qN,
    tip_vA -> tip_A), or None when ``name`` is no velocity."""
    if name.startswith("dq"):
        return name[1:]
    if name.startswith("tip_v"):
        return "tip_" + name.removeprefix("tip_v")
    return None


@dataclass(frozen=True)
class PairGain:
    """One position-velocity pair: the rows of the outputs and the 2 x 2 Kalman gain."""

    position: int
    velocity: int
    gain: np.ndarray  # rows (position, velocity), columns (position, velocity) residuals


def pair_gains(model: Narx, settings: ControllerSettings) -> list[PairGain]:
    """The pairs estimated together (none without declared noise on both members)."""
    from scipy.linalg import solve_discrete_are

    std = dict(settings.measurement_noise)
    names = list(model.output_names)
    b = settings.mismatch_filter
    t = model.sample_time
    out = []
    for vname in names:
        pname = position_of(vname)
        if pname is None or pname not in names:
            continue
        sp, sv = std.get(pname, 0.0), std.get(vname, 0.0)
        if not (sp > 0 and sv > 0 and b > 0):
            continue
        a = np.array([[1.0, t], [0.0, 1.0]])
        # A tiny process variance on the position keeps the Riccati equation's solution
        # positive definite; the position follows its velocity.
        q = np.diag([1e-12 * sp ** 2, sv ** 2 * (1 - b) ** 2 / b])
        r = np.diag([sp ** 2, sv ** 2])
        p = solve_discrete_are(a.T, np.eye(2), q, r)
        out.append(PairGain(names.index(pname), names.index(vname),
                            p @ np.linalg.inv(p + r)))
    return out


__all__ = ["PairGain", "pair_gains", "position_of"]
