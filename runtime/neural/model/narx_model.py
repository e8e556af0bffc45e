"""NARX models: the next output from a window of past outputs and inputs, through a small network.

A model predicts

    y(k+1) = c * y(k) + m + s * (net(z) + L z + sum_i w_i B_i z_u),   z = (phi(k) - mu) / sigma
    phi(k) = [y(k), y(k-1), ..., y(k-na+1), u(k), u(k-1), ..., u(k-nb+1), w(k)]

with ``net`` a fully connected tanh network (linear last layer), ``L`` an optional linear direct
path, ``mu``/``sigma`` the regressor's normalisation and ``m``/``s`` that of the target.
``c`` is 1 for outputs predicted as increments y(k+1) - y(k) and 0 for outputs predicted as
values. Increments keep the network's job at the scale of what changes in one sample (a network
asked for the next angle itself would spend its precision on the angle, and lose to
persistence); outputs that follow the input without integrating it (accelerations) are
predicted as values, so that the model does not turn them into integrators.

``w(k)`` are optional scheduling signals (jointplay.neural.model.scheduling): what the deviation
dynamics depend on and the controller knows ahead of time (the ideal robot's configuration
and speed, the drive torque of the motion). ``B_i`` is an optional bilinear part, the input
lags' gain affine in the normalised scheduling signals ``w_i`` (``z_u`` the normalised input
lags): with a single linear layer it makes the model a linear-parameter-varying ARX model
(jointplay.neural.identify.lpv).

This module needs numpy and CasADi only: a saved model (jointplay.neural.model.narx reads and writes
it) runs without the training code (and without torch); the checksum over the content catches
edits and corruption.
"""

from __future__ import annotations

import hashlib
import json
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import casadi as ca
import numpy as np

FORMAT = "jointplay-narx"
FORMAT_VERSION = 1
ACTIVATIONS = ("tanh",)


@dataclass(frozen=True, eq=False)
class Narx:
    """A trained NARX network with its normalisation and the context it was trained in.

    ``weights[i]`` has shape (n_out, n_in) of layer i and ``biases[i]`` (n_out,); hidden layers
    apply ``activation``, the last one is linear. ``context`` holds what the model means:
    the robot it was identified on (hashes), the plant around it (inner loop), the reference,
    and training facts; it is carried along, checked by the users of the model, and saved.
    """

    output_names: tuple[str, ...]
    output_units: tuple[str, ...]
    input_names: tuple[str, ...]
    input_units: tuple[str, ...]
    output_lags: int
    input_lags: int
    weights: tuple[np.ndarray, ...]
    biases: tuple[np.ndarray, ...]
    regressor_mean: np.ndarray
    regressor_scale: np.ndarray
    increment_mean: np.ndarray
    increment_scale: np.ndarray
    output_scale: np.ndarray  # typical size of each output (std in the training data)
    sample_time: float
    activation: str = "tanh"
    context: dict[str, Any] = field(default_factory=dict)
    increment: tuple[bool, ...] = ()  # per output; empty: every output is an increment
    linear: np.ndarray | None = None  # (ny, n_regressor) direct path, or None
    scheduling: tuple[str, ...] = ()  # scheduling signals at the regressor's end
    bilinear: np.ndarray | None = None  # (ny, n_scheduling * n_input_regressors), or None

    @property
    def carry(self) -> np.ndarray:
        """c of the prediction: 1.0 for increment outputs, 0.0 for value outputs."""
        if not self.increment:
            return np.ones(self.n_outputs)
        return np.asarray(self.increment, dtype=float)

    def __post_init__(self) -> None:
        problems = _shape_problems(self)
        if problems:
            raise ValueError("inconsistent NARX model: " + "; ".join(problems))

    # ---- sizes ---------------------------------------------------------------------------
    @property
    def n_outputs(self) -> int:
        return len(self.output_names)

    @property
    def n_inputs(self) -> int:
        return len(self.input_names)

    @property
    def n_scheduling(self) -> int:
        return len(self.scheduling)

    @property
    def n_input_regressors(self) -> int:
        return self.input_lags * self.n_inputs

    @property
    def n_regressor(self) -> int:
        return self.output_lags * self.n_outputs + self.n_input_regressors + self.n_scheduling

    @property
    def hidden(self) -> tuple[int, ...]:
        return tuple(int(w.shape[0]) for w in self.weights[:-1])

    @property
    def history(self) -> int:
        """Samples of the past a prediction needs beyond the current one."""
        return max(self.output_lags, self.input_lags) - 1

    def output_index(self, name: str) -> int:
        try:
            return self.output_names.index(name)
        except ValueError:
            raise KeyError(f"{name!r} is not an output of this model (outputs: "
                           f"{', '.join(self.output_names)})") from None

    # ---- numpy evaluation ----------------------------------------------------------------
    def regressor(self, y_hist: np.ndarray, u_hist: np.ndarray,
                  w: np.ndarray | None = None) -> np.ndarray:
        """phi from the newest-first windows ``y_hist`` (na, ny) and ``u_hist`` (nb, nu) and
        the scheduling signals ``w`` at the current sample (their first n_scheduling)."""
        return np.concatenate([np.ravel(y_hist[: self.output_lags]),
                               np.ravel(u_hist[: self.input_lags]),
                               self._own(w)])

    def _own(self, w: np.ndarray | None) -> np.ndarray:
        """The model's scheduling columns of ``w`` (rows or one row; none without them)."""
        if not self.n_scheduling:
            return np.zeros(0) if w is None or np.ndim(w) == 1 else np.zeros((len(w), 0))
        if w is None:
            raise ValueError("this model needs its scheduling signals: "
                             + ", ".join(self.scheduling))
        return np.asarray(w)[..., : self.n_scheduling]

    def _bilinear(self, z: Any, lib: Any) -> Any:
        """sum_i w_i B_i z_u on normalised regressors (numpy rows, or a CasADi column)."""
        ny, nw = self.n_outputs, self.n_scheduling
        start = self.output_lags * ny
        nz = self.n_input_regressors
        bilinear = self.bilinear
        assert bilinear is not None, "called only for a model with a bilinear part"
        blocks = [bilinear[:, i * nz: (i + 1) * nz] for i in range(nw)]
        if lib is np:
            zu, w = z[..., start: start + nz], z[..., -nw:]
            return sum(w[..., i: i + 1] * (zu @ b.T) for i, b in enumerate(blocks))
        zu, w = z[start: start + nz], z[z.numel() - nw:]
        return sum(w[i] * ca.mtimes(ca.DM(b), zu) for i, b in enumerate(blocks))

    def network(self, z: np.ndarray) -> np.ndarray:
        """The bare network on normalised regressors ``z`` (..., n_regressor)."""
        z = np.asarray(z, dtype=float)
        h = z
        last = len(self.weights) - 1
        for i, (w, b) in enumerate(zip(self.weights, self.biases, strict=True)):
            h = h @ w.T + b
            if i < last:
                h = np.tanh(h)
        if self.bilinear is not None:
            h = h + self._bilinear(z, np)
        return h + z @ self.linear.T if self.linear is not None else h

    def predict(self, phi: np.ndarray) -> np.ndarray:
        """y(k+1) for regressors ``phi`` (..., n_regressor); batched over leading axes."""
        phi = np.asarray(phi, dtype=float)
        z = (phi - self.regressor_mean) / self.regressor_scale
        return self.carry * phi[..., : self.n_outputs] + self.increment_mean \
            + self.increment_scale * self.network(z)

    def regressors(self, y: np.ndarray, u: np.ndarray, w: np.ndarray | None = None
                   ) -> np.ndarray:
        """Every regressor of a trajectory: row j is phi(k) for k = history + j.

        ``y`` (N, ny) are outputs at the samples and ``u`` (N, nu) the inputs applied from
        each sample to the next.
        """
        m = self.history
        n = y.shape[0]
        rows = [y[m - i: n - 1 - i] for i in range(self.output_lags)]
        rows += [u[m - i: n - 1 - i] for i in range(self.input_lags)]
        if self.n_scheduling:
            rows.append(self._own(w)[m: n - 1])
        return np.concatenate(rows, axis=1)

    def one_step(self, y: np.ndarray, u: np.ndarray, w: np.ndarray | None = None
                 ) -> np.ndarray:
        """One-step-ahead predictions of y(k+1) for k = history .. N-2 (measured past)."""
        return self.predict(self.regressors(y, u, w))

    def free_run(self, y: np.ndarray, u: np.ndarray, w: np.ndarray | None = None
                 ) -> np.ndarray:
        """Simulation: from the first ``history + 1`` measured outputs on, the model feeds back
        its own predictions; returns y(k) for k = history + 1 .. N-1."""
        m = self.history
        n = y.shape[0]
        y_hist = np.array(y[m::-1][: self.output_lags], dtype=float)
        if y_hist.shape[0] < self.output_lags:  # pad a short start with the oldest value
            y_hist = np.vstack([y_hist] + [y_hist[-1:]] * (self.output_lags - y_hist.shape[0]))
        out = np.empty((n - 1 - m, self.n_outputs))
        for j, k in enumerate(range(m, n - 1)):
            u_hist = u[k - self.input_lags + 1: k + 1][::-1]
            nxt = self.predict(self.regressor(y_hist, u_hist, None if w is None else w[k]))
            out[j] = nxt
            y_hist = np.vstack([nxt[None, :], y_hist[:-1]])
        return out

    # ---- CasADi --------------------------------------------------------------------------
    def casadi_function(self, name: str = "narx") -> ca.Function:
        """phi -> y(k+1) as a CasADi SX function, the weights as constants (float64)."""
        phi = ca.SX.sym("phi", self.n_regressor)
        z = (phi - ca.DM(self.regressor_mean)) / ca.DM(self.regressor_scale)
        h = z
        last = len(self.weights) - 1
        for i, (w, b) in enumerate(zip(self.weights, self.biases, strict=True)):
            h = ca.mtimes(ca.DM(w), h) + ca.DM(b)
            if i < last:
                h = ca.tanh(h)
        if self.linear is not None:
            h = h + ca.mtimes(ca.DM(self.linear), z)
        if self.bilinear is not None:
            h = h + self._bilinear(z, ca)
        y_next = ca.DM(self.carry) * phi[: self.n_outputs] + ca.DM(self.increment_mean) \
            + ca.DM(self.increment_scale) * h
        return ca.Function(name, [phi], [y_next], ["phi"], ["y_next"])

    # ---- persistence ---------------------------------------------------------------------
    def content(self) -> dict[str, Any]:
        """Everything that defines the predictions, as plain JSON data (the scheduling entries
        only where there are some: models without them keep their checksum)."""
        extra: dict[str, Any] = {}
        if self.scheduling:
            extra["scheduling"] = list(self.scheduling)
        if self.bilinear is not None:
            extra["bilinear"] = self.bilinear.tolist()
        return {
            "outputs": [{"name": n, "unit": u, "increment": bool(c)}
                        for n, u, c in zip(self.output_names, self.output_units, self.carry,
                                           strict=True)],
            "inputs": [{"name": n, "unit": u}
                       for n, u in zip(self.input_names, self.input_units, strict=True)],
            "output_lags": self.output_lags,
            "input_lags": self.input_lags,
            "sample_time": self.sample_time,
            "activation": self.activation,
            "layers": [{"weight": w.tolist(), "bias": b.tolist()}
                       for w, b in zip(self.weights, self.biases, strict=True)],
            "linear": None if self.linear is None else self.linear.tolist(),
            "normalisation": {
                "regressor_mean": self.regressor_mean.tolist(),
                "regressor_scale": self.regressor_scale.tolist(),
                "increment_mean": self.increment_mean.tolist(),
                "increment_scale": self.increment_scale.tolist(),
                "output_scale": self.output_scale.tolist(),
            },
            **extra,
        }

    def checksum(self) -> str:
        return _checksum(self.content(), self.context)

    def to_dict(self) -> dict[str, Any]:
        return {"format": FORMAT, "format_version": FORMAT_VERSION, **self.content(),
                "context": self.context, "checksum": self.checksum()}


def _checksum(content: Mapping[str, Any], context: Mapping[str, Any]) -> str:
    text = json.dumps({"content": content, "context": context}, sort_keys=True,
                      separators=(",", ":"), allow_nan=False)
    return hashlib.sha256(text.encode()).hexdigest()


def _shape_problems(m: Narx) -> list[str]:
    out: list[str] = []
    ny, nu = len(m.output_names), len(m.input_names)
    if ny == 0 or nu == 0:
        out.append("needs at least one output and one input")
    if len(m.output_units) != ny or len(m.input_units) != nu:
        out.append("units must match the names one to one")
    if len(set(m.output_names)) != ny or len(set(m.input_names)) != nu:
        out.append("names must be unique")
    for name in ("output_lags", "input_lags"):
        value = getattr(m, name)
        if isinstance(value, bool) or not isinstance(value, int) or value < 1:
            out.append(f"{name} must be an integer >= 1, got {value!r}")
    if m.activation not in ACTIVATIONS:
        out.append(f"activation must be one of {', '.join(ACTIVATIONS)}, got {m.activation!r}")
    if not (isinstance(m.sample_time, float) and math.isfinite(m.sample_time)
            and m.sample_time > 0):
        out.append(f"sample_time must be a positive number, got {m.sample_time!r}")
    if out:
        return out
    n_phi = m.n_regressor
    if len(m.weights) != len(m.biases) or not m.weights:
        return ["needs one bias per weight matrix and at least one layer"]
    width = n_phi
    for i, (w, b) in enumerate(zip(m.weights, m.biases, strict=True)):
        if w.ndim != 2 or w.shape[1] != width:
            out.append(f"layer {i} weight has shape {w.shape}, expected (*, {width})")
            return out
        if b.shape != (w.shape[0],):
            out.append(f"layer {i} bias has shape {b.shape}, expected ({w.shape[0]},)")
        width = w.shape[0]
    if width != ny:
        out.append(f"the last layer gives {width} values for {ny} outputs")
    if m.increment and len(m.increment) != ny:
        out.append(f"increment has {len(m.increment)} flags for {ny} outputs")
    if m.linear is not None and m.linear.shape != (ny, n_phi):
        out.append(f"linear has shape {m.linear.shape}, expected ({ny}, {n_phi})")
    n_bi = m.n_scheduling * m.n_input_regressors
    if m.bilinear is not None and (not n_bi or m.bilinear.shape != (ny, n_bi)):
        out.append(f"bilinear has shape {m.bilinear.shape}, expected ({ny}, {n_bi}) (and "
                   "needs scheduling signals)")
    for name, vec, size in (("regressor_mean", m.regressor_mean, n_phi),
                            ("regressor_scale", m.regressor_scale, n_phi),
                            ("increment_mean", m.increment_mean, ny),
                            ("increment_scale", m.increment_scale, ny),
                            ("output_scale", m.output_scale, ny)):
        if vec.shape != (size,):
            out.append(f"{name} has shape {vec.shape}, expected ({size},)")
    arrays = [*m.weights, *m.biases, m.regressor_mean, m.regressor_scale, m.increment_mean,
              m.increment_scale, m.output_scale, *([] if m.linear is None else [m.linear]),
              *([] if m.bilinear is None else [m.bilinear])]
    if not all(np.all(np.isfinite(a)) for a in arrays):
        out.append("weights and normalisation must be finite")
    elif not all(np.all(s > 0) for s in (m.regressor_scale, m.increment_scale,
                                         m.output_scale)):
        out.append("normalisation scales must be > 0")
    return out


def nrmse(predicted: np.ndarray, measured: np.ndarray) -> np.ndarray:
    """Per column: RMS of the error over the standard deviation of the measurement."""
    err = np.sqrt(np.mean((predicted - measured) ** 2, axis=0))
    spread = np.std(measured, axis=0)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(spread > 0, err / np.where(spread > 0, spread, 1.0), np.inf)


def fit_percent(predicted: np.ndarray, measured: np.ndarray) -> np.ndarray:
    """100 (1 - |e| / |y - mean y|), per column (MATLAB's ``compare`` fit)."""
    return 100.0 * (1.0 - nrmse(predicted, measured))


__all__ = ["ACTIVATIONS", "FORMAT", "FORMAT_VERSION", "Narx", "fit_percent", "nrmse"]
