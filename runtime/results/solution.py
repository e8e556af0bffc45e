"""``result.sol``: a run's state at any time between its samples, as a callable.

Like SciPy's ``OdeSolution`` (``solve_ivp(..., dense_output=True).sol``): ``sol(t)`` takes a
scalar or a 1-D array of times inside the run and returns the state x = (q, u), shape (n,)
or (n, m), in the order of ``coordinate_names`` (coordinates, then their rates).

Where it comes from depends on the integrator (``sol.method``, ``sol.accuracy`` say which):

* ``bdf``: the compiled BDF's own dense output (the interpolating polynomial of each step),
  read by replaying the run: the driver's steps never depend on the output times, so the
  replay takes the very steps of the run and ``sol(result.t)`` equals the samples.
* ``cvodes`` / ``idas``: the same method restarted from the last sample before each time,
  through every contact event in between, at the run's tolerances.
* fixed-step methods (``rk4``, ``radau``) and results read from a file: cubic Hermite
  between the output samples, from the states and their derivatives (u, and the model's
  accelerations), whose error is stated in ``accuracy``.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from jointplay.results.records import SimulationResult

# Times this close (relative to the run's span) outside [t_min, t_max] are taken as the end.
_END_SLACK = 1e-12


class DenseSolution:
    """The state of a run as a function of time: ``sol(t)`` -> (n,) or (n, m).

    ``result.sol`` of a :class:`SimulationResult`; like SciPy's ``OdeSolution``, it takes a
    time or a 1-D array of times inside the run.

    Parameters
    ----------
    t_min : float
        The start of the run, s.
    t_max : float
        Its end, s.
    n_state : int
        The length of the state.
    evaluate : callable
        Sorted unique times inside the run -> (m, n_state) states.
    method : str
        Where the states come from: the integrator's dense output (its name) or ``"hermite"``
        (cubic Hermite between samples).
    accuracy : str
        What that source's accuracy is, in words.

    Attributes
    ----------
    t_min : float
        The start of the run, s.
    t_max : float
        Its end, s.
    n_state : int
        The length of the state.
    method : str
        The source of the states.
    accuracy : str
        Its accuracy, in words.
    """

    def __init__(self, t_min: float, t_max: float, n_state: int,
                 evaluate: Callable[[np.ndarray], np.ndarray], *, method: str,
                 accuracy: str) -> None:
        self.t_min = float(t_min)
        self.t_max = float(t_max)
        self.n_state = int(n_state)
        self._evaluate = evaluate  # sorted unique times inside the run -> (m, n_state)
        self.method = method
        self.accuracy = accuracy

    def __repr__(self) -> str:
        return (f"DenseSolution(t in [{self.t_min:g}, {self.t_max:g}] s, {self.n_state} states, "
                f"{self.method})")

    def __call__(self, t: float | np.ndarray) -> np.ndarray:
        times = np.asarray(t, dtype=float)
        if times.ndim > 1:
            raise ValueError(f"sol(t): t must be a number or a 1-D array, got shape "
                             f"{times.shape}")
        flat = times.reshape(-1)
        slack = _END_SLACK * max(self.t_max - self.t_min, 1.0)
        outside = ~np.isfinite(flat) | (flat < self.t_min - slack) | (flat > self.t_max + slack)
        if np.any(outside):
            bad = float(flat[np.argmax(outside)])
            raise ValueError(f"sol(t): t = {bad!r} s is outside the run, [{self.t_min:g}, "
                             f"{self.t_max:g}] s")
        unique, inverse = np.unique(np.clip(flat, self.t_min, self.t_max), return_inverse=True)
        values = np.asarray(self._evaluate(unique), dtype=float)
        out = values[inverse].T
        return out[:, 0].copy() if times.ndim == 0 else out


def hermite(t: np.ndarray, x: np.ndarray, xdot: np.ndarray
            ) -> Callable[[np.ndarray], np.ndarray]:
    """Piecewise cubic Hermite interpolant through (t, x) with slopes xdot (rows per sample)."""

    def evaluate(times: np.ndarray) -> np.ndarray:
        k = np.clip(np.searchsorted(t, times, side="right") - 1, 0, max(t.size - 2, 0))
        if t.size < 2:
            return np.repeat(x[:1], times.size, axis=0)
        h = (t[k + 1] - t[k])[:, None]
        s = ((times - t[k]) / (t[k + 1] - t[k]))[:, None]
        h00 = (1 + 2 * s) * (1 - s) ** 2
        h10 = s * (1 - s) ** 2
        h01 = s**2 * (3 - 2 * s)
        h11 = s**2 * (s - 1)
        return h00 * x[k] + h10 * h * xdot[k] + h01 * x[k + 1] + h11 * h * xdot[k + 1]

    return evaluate


def hermite_accuracy(result: SimulationResult, why: str) -> str:
    step = float(np.median(np.diff(result.t))) if result.n_samples > 1 else 0.0
    return (f"cubic Hermite between the output samples ({why}): from q, u and the model's "
            f"accelerations at each sample; its error grows as h^4 with the output step "
            f"h = {step:.3g} s while the motion is smooth, but only as h across a contact "
            "onset or separation inside an interval, and no tolerance controls it. For "
            "values accurate between samples, run with a finer run.output_step or an adaptive "
            "integrator (bdf, cvodes, idas).")


def sample_solution(result: SimulationResult, why: str) -> DenseSolution:
    """The cubic Hermite interpolant of a result's samples (see :func:`hermite_accuracy`)."""
    x = np.hstack([result.q, result.u])
    xdot = np.hstack([result.u, result.udot])
    return DenseSolution(float(result.t[0]), float(result.t[-1]), x.shape[1],
                         hermite(result.t, x, xdot), method="hermite",
                         accuracy=hermite_accuracy(result, why))
