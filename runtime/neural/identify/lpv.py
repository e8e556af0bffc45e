"""The linear-parameter-varying ARX baseline: the ARX regressor with coefficients affine in
scheduling signals, fitted by least squares (Bamieh and Giarré, Int. J. Robust Nonlinear
Control 12 (2002) 841-853).

The deviation dynamics of a clearance robot under its inner loop change with the arm's
configuration and speed and with the load the drives put on the joints; an ARX model of the
deviations alone is time-invariant. Here

    y(k+1) = carry y(k) + A phi(k) + sum_i s_i(k) B_i u_lags(k) + c0 + sum_i s_i(k) c_i

with phi(k) the ARX regressor (output and input lags), u_lags(k) its input lags, and s(k)
the scheduling signals known to the controller ahead of time: cos and sin of the ideal
robot's joint angles, its joint speeds and the drive torques of the motion (feedforward),
each normalised on the training runs. Only the input gain and the offset are scheduled: the
autoregressive part stays the ARX model's, so the free run is as stable as the twin's.
"better than linear" is judged against the better of ARX and LPV-ARX.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from jointplay.neural.identify.trajectories import Trajectory
from jointplay.neural.model.narx_model import Narx

Scheduled = tuple[np.ndarray, np.ndarray, np.ndarray]  # deviations, inputs, scheduling


def scheduling(trajectory: Trajectory, n_joints: int) -> np.ndarray:
    """Scheduling signals per sample: cos, sin of the ideal joint angles, ideal joint speeds,
    the motion's drive torques (jointplay.neural.model.scheduling, in its order)."""
    q = trajectory.r[:, :n_joints]
    dq = trajectory.r[:, n_joints: 2 * n_joints]
    return np.hstack([np.cos(q), np.sin(q), dq, trajectory.tau_base])


def scheduled_segments(trajectories: Sequence[Trajectory], skip: int,
                       n_joints: int) -> list[Scheduled]:
    return [(t.deviation[skip:], t.v[skip:], scheduling(t, n_joints)[skip:])
            for t in trajectories]


def _lagged(d: np.ndarray, u: np.ndarray, na: int, nb: int, k: np.ndarray) -> np.ndarray:
    return np.concatenate([d[k - i] for i in range(na)] + [u[k - i] for i in range(nb)], axis=1)


@dataclass(frozen=True)
class LpvArx:
    """A fitted LPV-ARX model (normalised regressor and scheduling, increments where carried)."""

    theta: np.ndarray  # ((1 + ns) (n_phi + 1), ny)
    phi_mean: np.ndarray
    phi_scale: np.ndarray
    s_mean: np.ndarray
    s_scale: np.ndarray
    carry: np.ndarray
    output_lags: int
    input_lags: int

    @property
    def history(self) -> int:
        return max(self.output_lags, self.input_lags) - 1

    def features(self, phi: np.ndarray, s: np.ndarray) -> np.ndarray:
        z = np.hstack([(phi - self.phi_mean) / self.phi_scale, np.ones((phi.shape[0], 1))])
        w = (s - self.s_mean) / self.s_scale
        # Scheduled: the input lags and the offset only. The autoregressive part stays that of
        # an ARX model, so the free run is as stable as the ARX twin's (scheduling the output
        # lags too made the one-step least-squares fit unstable in free run by 1e30 and more
        # on the paper scene's data, whatever the ridge from 1e-8 to 1e-4).
        v = z[:, self.n_output_regressors:]
        return np.hstack([z, *(v * w[:, i: i + 1] for i in range(w.shape[1]))])

    @property
    def n_output_regressors(self) -> int:
        return self.output_lags * self.carry.size

    def predict(self, phi: np.ndarray, s: np.ndarray, last: np.ndarray) -> np.ndarray:
        """The next outputs from regressors ``phi`` (rows), scheduling ``s`` and the current
        outputs ``last``."""
        return self.carry * last + self.features(phi, s) @ self.theta

    def as_narx(self, names: dict[str, Any], scheduling_names: Sequence[str], dt: float,
                output_scale: np.ndarray, context: dict[str, Any]) -> Narx:
        """The same model as a NARX model with one linear layer and a bilinear part, so that
        the controller step runs it (its regressor: the ARX regressor, then the scheduling
        signals)."""
        n_phi = self.phi_mean.size
        n_u = n_phi - self.n_output_regressors
        ns = self.s_mean.size
        theta = self.theta
        blocks = [theta[n_phi + 1 + i * (n_u + 1): n_phi + 1 + (i + 1) * (n_u + 1)]
                  for i in range(ns)]
        weight = np.hstack([theta[:n_phi].T, np.column_stack([b[-1] for b in blocks])])
        bilinear = np.hstack([b[:-1].T for b in blocks])
        ny = self.carry.size
        return Narx(weights=(weight,), biases=(theta[n_phi].copy(),),
                    regressor_mean=np.concatenate([self.phi_mean, self.s_mean]),
                    regressor_scale=np.concatenate([self.phi_scale, self.s_scale]),
                    increment_mean=np.zeros(ny), increment_scale=np.ones(ny),
                    output_scale=output_scale, output_lags=self.output_lags,
                    input_lags=self.input_lags, sample_time=dt, context=context,
                    increment=tuple(bool(c) for c in self.carry),
                    scheduling=tuple(scheduling_names), bilinear=bilinear, **names)

    def free_run(self, d: np.ndarray, u: np.ndarray, s: np.ndarray) -> np.ndarray:
        """Windows (B, m + h + 1, .) run on the model's own predictions from their measured
        history; returns the predictions (B, h, ny)."""
        m, na, nb = self.history, self.output_lags, self.input_lags
        hist = [d[:, m - i] for i in range(na)]
        out = []
        with np.errstate(all="ignore"):
            for j in range(d.shape[1] - m - 1):
                k = m + j
                phi = np.concatenate(hist + [u[:, k - i] for i in range(nb)], axis=1)
                nxt = self.predict(phi, s[:, k], hist[0])
                out.append(nxt)
                hist = [nxt, *hist[:-1]]
        return np.stack(out, axis=1)


def fit_lpv_arx(segments: Sequence[Scheduled], na: int, nb: int, carry: Sequence[bool],
                ridge: float = 1e-6) -> LpvArx:
    """Least squares (ridge ``ridge`` on normalised features) on every training sample."""
    m = max(na, nb) - 1
    c = np.asarray(carry, dtype=float)
    phis, ss, ts = [], [], []
    for d, u, s in segments:
        k = np.arange(m, d.shape[0] - 1)
        phis.append(_lagged(d, u, na, nb, k))
        ss.append(s[k])
        ts.append(d[k + 1] - c * d[k])
    phi, s, t = np.vstack(phis), np.vstack(ss), np.vstack(ts)
    scale = lambda a: np.where(a.std(0) > 1e-300, a.std(0), 1.0)  # noqa: E731
    model = LpvArx(np.zeros(0), phi.mean(0), scale(phi), s.mean(0), scale(s), c, na, nb)
    f = model.features(phi, s)
    theta = np.linalg.solve(f.T @ f + ridge * f.shape[0] * np.eye(f.shape[1]), f.T @ t)
    return LpvArx(theta, model.phi_mean, model.phi_scale, model.s_mean, model.s_scale, c, na,
                  nb)


def window_loss(model: LpvArx, segments: Sequence[Scheduled], length: int,
                scale: np.ndarray) -> float:
    """Mean squared free-run error over windows, each output divided by ``scale`` (the loss
    jointplay.neural.model.twin uses for the network and ARX)."""
    from jointplay.neural.model.twin import windows

    d, u, s = windows(segments, length, model.history)
    pred = model.free_run(d, u, s)
    with np.errstate(all="ignore"):
        loss = float(np.mean(((pred - d[:, model.history + 1:]) / scale) ** 2))
    return loss if np.isfinite(loss) else float("inf")


__all__ = ["LpvArx", "fit_lpv_arx", "scheduled_segments", "scheduling", "window_loss"]
