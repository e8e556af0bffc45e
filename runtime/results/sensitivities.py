"""Sensitivities of a run's outputs to named parameters (``simulate(..., sensitivities=...)``)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np


@dataclass(frozen=True)
class Sensitivities:
    """Derivatives of a run's outputs with respect to the parameters ``names``.

    The last axis of every array runs over ``names``. ``state`` is d x / d p at the output
    samples ``t`` (the same times as ``result.t``; x = (q, u) in ``result.coordinate_names``
    order); ``tip_position`` and ``tip_velocity`` those of the end effector.
    ``impact_times`` and ``impact_peaks`` are row for row those of ``result.impacts``: the
    derivative of each located contact onset time and of each phase's located peak normal
    force. Units: the output's unit over the parameter's.
    """

    names: tuple[str, ...]
    t: np.ndarray  # (n_t,) s
    state: np.ndarray  # (n_t, n_x, n_p)
    tip_position: np.ndarray  # (n_t, 2, n_p)
    tip_velocity: np.ndarray  # (n_t, 2, n_p)
    impact_times: np.ndarray  # (n_impacts, n_p)
    impact_peaks: np.ndarray  # (n_impacts, n_p)

    def __post_init__(self) -> None:
        for name in ("t", "state", "tip_position", "tip_velocity", "impact_times",
                     "impact_peaks"):
            value = np.array(getattr(self, name), dtype=float)
            value.setflags(write=False)
            object.__setattr__(self, name, value)
        object.__setattr__(self, "names", tuple(self.names))

    def column(self, name: str) -> int:
        """The index of ``name`` on the last axis."""
        if name not in self.names:
            raise KeyError(f"{name!r} is not among the sensitivities of this run "
                           f"({', '.join(self.names)})")
        return self.names.index(name)

    def to_dict(self) -> dict[str, Any]:
        """Plain lists (JSON-ready): every array and the names."""
        return {"names": list(self.names), "t": self.t.tolist(), "state": self.state.tolist(),
                "tip_position": self.tip_position.tolist(),
                "tip_velocity": self.tip_velocity.tolist(),
                "impact_times": self.impact_times.tolist(),
                "impact_peaks": self.impact_peaks.tolist()}
