"""The linear models on the network's regressor: the ARX twin and the LPV-ARX base.

The regressor (output and input lags of each run's deviations and added torques, and the
scheduling signals where the model has them) is the network's; the fits are ridge least
squares on it, normalised as the network normalises it, so that an ARX model is a network
with no hidden layer and runs through the same code (:class:`jointplay.neural.model.narx.Narx`).
Network training (:mod:`jointplay.neural.identify.training`) starts its linear part from these
fits."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from jointplay.neural.identify.trajectories import Trajectory
from jointplay.neural.model.inner_loop import output_increments
from jointplay.neural.model.narx import Narx
from jointplay.neural.model.scheduling import scheduling_names, trajectory_scheduling

# (deviations, added torques, scheduling signals) of one trajectory; the scheduling signals
# have no columns for a model without them.
Segment = tuple[np.ndarray, np.ndarray, np.ndarray]


def segments(trajectories: Sequence[Trajectory], skip: int,
              names: dict[str, Any] | None = None) -> list[Segment]:
    """Each run after ``skip`` samples; with the signal ``names``, its scheduling signals
    too (jointplay.neural.model.scheduling), else none."""
    out = []
    for tr in trajectories:
        if names is not None:
            w = trajectory_scheduling(tr, names["output_names"], names["input_names"])
        else:
            w = np.zeros((tr.v.shape[0], 0))
        out.append((tr.deviation[skip:], tr.v[skip:], w[skip:]))
    return out


def model_scheduling(names: dict[str, Any]) -> tuple[str, ...]:
    """The scheduling signals' names of the plant with these signal names."""
    return scheduling_names([int(n[1:]) for n in names["input_names"]])


def regress(segments: Sequence[Segment], na: int, nb: int,
             carry: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Regressors and targets (increments where ``carry`` is 1, values where 0)."""
    m = max(na, nb) - 1
    xs, ts = [], []
    for d, u, *w in segments:
        n = d.shape[0]
        rows = [d[m - i: n - 1 - i] for i in range(na)] + [u[m - i: n - 1 - i] for i in range(nb)]
        rows += [w[0][m: n - 1]] if w else []
        xs.append(np.concatenate(rows, axis=1))
        ts.append(d[m + 1:] - carry * d[m: n - 1])
    return np.vstack(xs), np.vstack(ts)


def least_squares(z: np.ndarray, t: np.ndarray, ridge: float) -> np.ndarray:
    a = np.hstack([z, np.ones((z.shape[0], 1))])
    return np.linalg.solve(a.T @ a + ridge * np.eye(a.shape[1]), a.T @ t)


def scale_floor(std: np.ndarray) -> np.ndarray:
    """Standard deviations floored so that constant columns normalise to themselves."""
    return np.where(std > 1e-300, std, 1.0)


def bilinear_features(z: np.ndarray, start: int, n_inputs: int, n_scheduling: int
                      ) -> np.ndarray:
    """The products w_i z_u of the normalised input lags and the normalised scheduling
    signals (the regressor's last columns), block i for signal i: the columns that the
    bilinear part of jointplay.neural.model.narx_model multiplies."""
    zu, w = z[:, start: start + n_inputs], z[:, z.shape[1] - n_scheduling:]
    return np.hstack([zu * w[:, i: i + 1] for i in range(n_scheduling)])


def linear_fit(z: np.ndarray, t: np.ndarray, ridge: float, bilinear: tuple[int, int, int] | None
                ) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    """(weight, bias, bilinear part) of the least-squares fit on normalised regressors ``z``;
    ``bilinear`` = (start, n_inputs, n_scheduling) adds the input lags' gain affine in the
    scheduling signals (LPV-ARX; ridge ``ridge`` x samples, as jointplay.neural.identify.lpv)."""
    if bilinear is None:
        theta = least_squares(z, t, ridge)
        return theta[:-1].T.copy(), theta[-1].copy(), None
    products = bilinear_features(z, *bilinear)
    theta = least_squares(np.hstack([z, products]), t, ridge * z.shape[0])
    n = z.shape[1]
    return theta[:n].T.copy(), theta[-1].copy(), theta[n:-1].T.copy()


def fit_arx(segments: Sequence[Segment], names: dict[str, Any],
            na: int, nb: int, dt: float, ridge: float = 1e-9,
            scheduling: Sequence[str] = (), lpv: bool = False) -> Narx:
    """The linear ARX baseline on the same regressor, by least squares (a network with no
    hidden layer, so it runs through the same code). Segments with scheduling signals give
    an ARX model with them as further regressors (``scheduling``: their names); with ``lpv``
    its input gain is affine in them too (an LPV-ARX model in the network's normalisation,
    the base of a network trained with ``lpv_base``; ridge :data:`LPV_RIDGE`)."""
    carry = np.asarray(output_increments(names["output_names"]), dtype=float)
    x, t = regress(segments, na, nb, carry)
    mu, sigma = x.mean(0), scale_floor(x.std(0))
    tm, ts = t.mean(0), scale_floor(t.std(0))
    ny = t.shape[1]
    shape = (na * ny, x.shape[1] - na * ny - len(scheduling), len(scheduling)) if lpv else None
    weight, bias, bilinear = linear_fit((x - mu) / sigma, (t - tm) / ts,
                                         LPV_RIDGE if lpv else ridge, shape)
    return Narx(weights=(weight,), biases=(bias,), regressor_mean=mu,
                regressor_scale=sigma, increment_mean=tm, increment_scale=ts,
                output_scale=scale_floor(np.vstack([seg[0] for seg in segments]).std(0)),
                output_lags=na, input_lags=nb, sample_time=dt,
                increment=tuple(bool(c) for c in carry), scheduling=tuple(scheduling),
                bilinear=bilinear, **names)


# Ridge of the LPV-ARX fit per sample on normalised features (jointplay.neural.identify.lpv's).
LPV_RIDGE = 1e-6
