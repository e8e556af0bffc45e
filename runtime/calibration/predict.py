"""The model's prediction of the measured columns, and its Jacobian in the free parameters.

The Jacobian comes from the compiled sensitivities (one run gives the outputs and their
derivatives through every impact); a name they do not cover takes central differences (two
runs). Samples come off the run's output grid where the measured times lie on it, else from
its dense output (the sensitivities interpolated linearly).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from jointplay.calibration.measured import TIP_COLUMNS, Measured, grid_indices
from jointplay.calibration.parameters import FreeParameters
from jointplay.common.errors import DescriptionError
from jointplay.common.pool import chunks, parallel_map
from jointplay.scene.definition import Scene
from jointplay.store.model import Model

# Central-difference step, relative to the parameter's magnitude: near the optimum of the error
# (cube root of the runs' relative accuracy) and far above the jitter of adaptive steps.
FD_RELATIVE_STEP = 1e-2


PIECES_PER_WORKER = 4
"""Pieces a list of points is cut into per worker (:func:`chi2_at_points`)."""


class TrialFailed(Exception):
    """A run at trial parameters stopped (a SimulationError): the message says where."""


@dataclass
class Counter:
    """Runs made so far (a run with sensitivities counts as one)."""

    simulations: int = 0
    by_kind: dict[str, int] = field(default_factory=lambda: {"plain": 0, "sensitivities": 0})

    def add(self, kind: str) -> None:
        self.simulations += 1
        self.by_kind[kind] += 1


class Predictor:
    """``outputs(x)`` (n_t, n_columns) and ``jacobian(x)`` (n_t, n_columns, n_free) of the
    measured columns at free-parameter values ``x``; caches the last point."""

    def __init__(self, scene: Scene, model: Model, free: FreeParameters,
                 measured: Measured, compiled: tuple[str, ...] | None = None) -> None:
        self.scene, self.model, self.free, self.measured = scene, model, free, measured
        self.counter = Counter()
        self._grid = grid_indices(measured.t, scene.run.output_step)
        # ``compiled``: the names another predictor of the same model already tried
        self.compiled = self._compiled_names() if compiled is None else compiled
        self._cache: dict[bytes, tuple[np.ndarray, np.ndarray | None]] = {}

    def for_free(self, free: FreeParameters) -> Predictor:
        """This predictor for ``free`` (the same names, other bounds: some held), sharing its
        last run (a fit from that point takes no run there again) but not its count."""
        other = Predictor(self.scene, self.model, free, self.measured, compiled=self.compiled)
        other._cache = self._cache
        return other

    def over(self, scene: Scene, measured: Measured | None = None) -> Predictor:
        """This predictor's model and free parameters on ``scene`` (a window's, or other
        tolerances) and ``measured`` (default: its own), with its own count and cache."""
        return Predictor(scene, self.model, self.free,
                         self.measured if measured is None else measured, compiled=self.compiled)

    def __getstate__(self) -> dict[str, Any]:
        # For a piece sent to a Dask worker: the compiled model does not pickle; the worker
        # loads it again from the scene (the hash-keyed cache, or derived once there).
        return {**self.__dict__, "model": None, "_cache": {}}

    def __setstate__(self, state: dict[str, Any]) -> None:
        from jointplay.sim import load_scene_model

        self.__dict__.update(state)
        self.model = load_scene_model(self.scene)

    def outputs(self, x: np.ndarray, *, with_jacobian: bool = True) -> np.ndarray:
        """The measured columns at ``x``; ``with_jacobian=False`` (a scan, a profile) runs
        without sensitivities, at a fraction of the cost, when no Jacobian is wanted next."""
        return self._evaluate(x, with_jacobian)[0]

    def jacobian(self, x: np.ndarray) -> np.ndarray:
        y, sens = self._evaluate(x)
        jac = np.zeros((*y.shape, self.free.size))
        for k, name in enumerate(self.free.names):
            if name not in self.compiled:
                jac[:, :, k] = self._central_difference(x, k)
            elif sens is not None:
                jac[:, :, k] = sens[:, :, self.compiled.index(name)]
        return jac

    def _evaluate(self, x: np.ndarray, with_jacobian: bool = True
                  ) -> tuple[np.ndarray, np.ndarray | None]:
        key = np.asarray(x, dtype=float).tobytes()
        cached = self._cache.get(key)
        wanted = self.compiled if with_jacobian else ()
        if cached is None or (wanted and cached[1] is None):
            self._cache.clear()  # a fit asks for one point at a time
            self._cache[key] = self._run(np.asarray(x, dtype=float), wanted)
        return self._cache[key]

    def _run(self, x: np.ndarray, names: tuple[str, ...]
             ) -> tuple[np.ndarray, np.ndarray | None]:
        from jointplay.common.errors import SimulationError
        from jointplay.sim import simulate

        overrides = self.free.as_overrides(x)
        # the motion alone: no peak force located (the same trajectory, up to 10 % less CPU)
        kwargs: dict[str, Any] = {"peaks": False, **({"sensitivities": names} if names else {})}
        try:
            result = simulate(self.scene, model=self.model, parameters=overrides, **kwargs)
        except SimulationError as err:
            raise TrialFailed(f"the run at {_describe(self.free.names, x)} stopped: {err}") \
                from None
        self.counter.add("sensitivities" if names else "plain")
        return self._sampled(result), (self._sampled_sensitivities(result) if names else None)

    def _columns(self, tip: np.ndarray, q: np.ndarray) -> list[np.ndarray]:
        """The measured columns, picked along axis 1 of the tip's position and coordinates."""
        return [tip[:, TIP_COLUMNS.index(name)] if name in TIP_COLUMNS
                else q[:, self.model.coordinates.index(name)] for name in self.measured.columns]

    def _sampled(self, result: Any) -> np.ndarray:
        tip, q = ((result.tip_position[self._grid], result.q[self._grid])
                  if self._grid is not None else self._dense(result))
        return np.column_stack(self._columns(tip, q))

    def _dense(self, result: Any) -> tuple[np.ndarray, np.ndarray]:
        from jointplay.sim.assemble import _mapped

        t = self.measured.t
        xs = result.sol(t)  # (n_state, m)
        n = len(self.model.coordinates)
        ps = np.repeat(np.asarray(result.parameters, float)[:, None], t.size, axis=1)
        tip = _mapped(self.model, "end_effector", [xs, np.zeros((n, t.size)), ps])[0]
        return tip.T, xs[:n].T

    def _sampled_sensitivities(self, result: Any) -> np.ndarray:
        sens = result.sensitivities
        columns = self._columns(np.asarray(sens.tip_position), np.asarray(sens.state))
        stacked = np.stack(columns, axis=1)  # (n_grid, n_columns, n_compiled)
        if self._grid is not None:
            return stacked[self._grid]
        t_grid = np.asarray(sens.t, float)
        return np.apply_along_axis(lambda y: np.interp(self.measured.t, t_grid, y), 0, stacked)

    def _central_difference(self, x: np.ndarray, k: int) -> np.ndarray:
        h = FD_RELATIVE_STEP * (abs(x[k]) if x[k] != 0 else 1e-2)
        up, down = x.copy(), x.copy()
        up[k], down[k] = min(x[k] + h, self.free.upper[k]), max(x[k] - h, self.free.lower[k])
        return (self._run(up, ())[0] - self._run(down, ())[0]) / (up[k] - down[k])

    def _compiled_names(self) -> tuple[str, ...]:
        """The free names the compiled sensitivities cover (each tried once on one step)."""
        from jointplay.sim import simulate

        short, names = self.scene.with_run(t_end=self.scene.run.output_step), []
        for name in self.free.names:
            try:
                simulate(short, model=self.model, parameters=None, sensitivities=(name,))
                names.append(name)
            except DescriptionError:
                pass
        return tuple(names)


def chi2_at(probe: Predictor, weights: np.ndarray, points: list[np.ndarray]
            ) -> tuple[list[float], int]:
    """chi² of ``probe``'s window at each point (inf where the run stops), and the runs."""
    before = probe.counter.simulations
    out = []
    for x in points:
        try:
            residual = whitened(probe.outputs(x, with_jacobian=False)
                                - probe.measured.values, weights)
        except TrialFailed:
            out.append(math.inf)
            continue
        out.append(float(np.sum(residual**2)))
    return out, probe.counter.simulations - before


def chi2_at_points(probe: Predictor, weights: np.ndarray, points: list[np.ndarray],
                   workers: int) -> tuple[list[float], int]:
    """:func:`chi2_at` of every point, in order, in pieces on up to ``workers`` processes
    (PIECES_PER_WORKER each: runs differ in cost); and the runs."""
    pieces = chunks(len(points), PIECES_PER_WORKER * workers)
    done = parallel_map(lambda i: chi2_at(probe, weights, [points[j] for j in pieces[i]]),
                        len(pieces), workers)
    return [value for values, _ in done for value in values], sum(runs for _, runs in done)


def line_minima(chi2: np.ndarray) -> list[int]:
    """The indices of the finite values along a line no higher than either neighbour, the
    lowest first."""
    padded = np.concatenate([[np.inf], chi2, [np.inf]])
    minima = [i for i in range(len(chi2))
              if np.isfinite(chi2[i]) and chi2[i] <= padded[i] and chi2[i] <= padded[i + 2]]
    return sorted(minima, key=lambda i: chi2[i])


def _describe(names: tuple[str, ...], x: np.ndarray) -> str:
    return ", ".join(f"{n} = {v:.6g}" for n, v in zip(names, x, strict=True))


def whitened(values: np.ndarray, sigma: np.ndarray) -> np.ndarray:
    """(n_t, n_columns[, n_p]) divided by each column's standard deviation, flattened to rows."""
    scaled = values / (sigma[None, :, None] if values.ndim == 3 else sigma[None, :])
    return scaled.reshape(values.shape[0] * values.shape[1], *values.shape[2:])
