"""Contact flags and captured impact speeds for the methods whose events are located in Python
(``cvodes``, ``idas``, ``rk4``, ``radau``); ``bdf`` keeps the same state in C (driver.c).

Each clearance joint has a flag (in contact or free). An onset (penetration crossing zero
upwards while free) captures the approach speed d(delta)/dt, the model's ``v_imp`` input, and
records the impact; a separation clears the flag.
"""

from __future__ import annotations

import numpy as np

from jointplay.sim.problem import _Problem


class _EventState:
    """Contact flags and captured impact speeds of every clearance joint."""

    def __init__(self, pr: _Problem, x0: np.ndarray, t0: float,
                 impacts: list[tuple[float, int, float, float, float]]) -> None:
        self.pr = pr
        self.flags = np.zeros(pr.nc)
        self.v_imp = np.zeros(pr.nc)
        self.impacts = impacts
        if pr.nc:
            c = pr.contact_at(x0, self.v_imp)
            for i in np.flatnonzero(c["delta"] > 0):
                self.onset(int(i), t0, float(c["delta_dot"][i]), x0)

    def onset(self, i: int, t: float, speed: float, x: np.ndarray) -> None:
        """Joint i (index into the clearance joints) comes into contact at state x."""
        self.flags[i] = 1.0
        self.v_imp[i] = speed
        ex, ey = self.pr.eccentricity_at(x, i)
        self.impacts.append((t, int(self.pr.model.clearance_joints[i]), speed, ex, ey))

    def gap(self, x: np.ndarray) -> np.ndarray:
        """Per joint: > 0 where the penetration disagrees with the joint's flag."""
        delta = self.pr.contact_at(x, self.v_imp)["delta"]
        return np.where(self.flags > 0.5, -delta, delta)

    def switch(self, x: np.ndarray, t: float, joints: np.ndarray) -> None:
        """Flip the flags of ``joints`` (indices into the clearance joints) at state x."""
        c = self.pr.contact_at(x, self.v_imp)
        for i in joints:
            i = int(i)
            if self.flags[i] < 0.5:
                self.onset(i, t, float(c["delta_dot"][i]), x)
            else:
                self.flags[i] = 0.0
