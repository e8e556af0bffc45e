"""The outer loop's bandwidth chosen for the sensors' noise.

The internal-model law corrects the filtered mismatch within ``horizon`` samples: at the
default horizon (5 ms) it acts on a velocity mismatch like a velocity loop tens of times
stiffer than the inner PD, and white noise on the measured velocities passes into v and, since
torque reaches acceleration directly, into the end effector's acceleration. A longer horizon
asks for the same correction over more samples and so with a smaller torque.

With the sensors' noise declared (``ControllerSettings.measurement_noise``), the horizon is
chosen before the controller is built: the linear twin stands in for the plant (its input is
the torque added to the inner loop's, so the inner PD's own response to the noise,
-Kp n_q - Kd n_dq, enters it the same way as v), the ARX-IMC step runs on it with
white noise on every measured output, and the stationary RMS of the model's acceleration outputs
is compared with that of the inner loop alone under the same noise. The shortest candidate
horizon whose ratio is within ``1 + noise_budget`` is taken, to the sample (the coarse
candidate list, then the samples between the last candidate outside and the first inside).
With a perfect internal model the mismatch is the noise alone, so this is what the outer loop
adds to the noise, not to the clearance's effect. The step predicted is the one that will
run, with the pairwise mismatch filter of declared noise (jointplay.neural.control.mismatch_filter).

How far to trust the prediction (docs/control.md, "Measurement noise"): at horizon 20, over
the study's 10 seed models, the predicted ratio ranges 1.066-1.092 and the measured one
(closed loop on the clearance robot, the study's noise case) 1.081-1.094; the measurement
depends little on the seed, the prediction more, through each twin's fit. It ranks horizons
correctly for every model, which is what the choice uses.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import casadi as ca
import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.neural.control.imc_settings import ControllerSettings, resolve_settings
from jointplay.neural.control.imc_step import build_step
from jointplay.neural.control.internal_model import _inner_gains
from jointplay.neural.model.narx import Narx

# Candidate horizons, tried from the settings' own upward (then refined to the sample inside
# the first gap that crosses the budget); the work per controller step grows
# linearly with the horizon (about 0.85 µs per sample of it for the default network).
HORIZONS = (5, 8, 10, 15, 20, 25, 30, 40, 50, 60, 80, 100)
IMPULSE = 2000  # samples of the impulse response summed (2 s at 1 ms; on the study's models
# 8000 changed the predicted ratios by less than 1e-5)


@dataclass(frozen=True)
class NoiseTuning:
    """The horizon chosen for the declared noise and the predictions behind it."""

    horizon: int
    budget: float
    ratios: tuple[tuple[int, float], ...]  # (horizon, predicted RMS acceleration ratio) tried
    inner_only_rms: float  # predicted RMS acceleration from the noise, inner loop alone
    met: bool  # a candidate's ratio was within the budget

    @property
    def ratio(self) -> float:
        return dict(self.ratios)[self.horizon]

    def describe(self) -> str:
        tried = ", ".join(f"{h}: {r:.3f}x" for h, r in self.ratios)
        head = (f"measurement noise declared: horizon {self.horizon} (predicted RMS tip "
                f"acceleration from the noise {self.ratio:.3f}x the inner loop's alone, "
                f"budget {1 + self.budget:.3f}x; tried {tried})")
        if self.met:
            return head
        return (head + f"; NO horizon up to {HORIZONS[-1]} meets the budget: the outer loop "
                "adds more noise than asked at every horizon; raise --noise-budget, lower "
                "the sensors' noise, or run the inner loop alone")


def noise_vector(model: Narx, settings: ControllerSettings) -> np.ndarray:
    """The declared standard deviation of every model output (0 where none was declared)."""
    out = np.zeros(model.n_outputs)
    for name, std in settings.measurement_noise:
        out[model.output_index(name)] = std
    return out


def tune_to_noise(model: Narx, twin: Narx | None,
                  settings: ControllerSettings) -> tuple[ControllerSettings, NoiseTuning]:
    """``settings`` with the horizon chosen for its declared noise (see the module's text).

    ``twin``: the linear model to predict with (the network itself when there is none)."""
    settings = resolve_settings(model, settings)
    plant = twin if twin is not None else model
    noise = noise_vector(plant, settings)
    accel = [i for i, c in enumerate(plant.carry) if c == 0.0]
    if not accel:
        raise DescriptionError("--measurement-noise", "the model predicts no acceleration "
                               "(value) outputs to judge the noise by; identify with the "
                               "default outputs")
    inner = _predicted_rms(plant, settings, None, noise, accel)
    if not inner > 0:
        q_idx, dq_idx, _, _ = _inner_gains(plant)
        joints = [plant.output_names[i] for i in (*q_idx, *dq_idx)]
        raise DescriptionError("--measurement-noise", "the budget is relative to the inner "
                               "loop's own response to the noise, and none is declared on "
                               f"what it measures: declare the noise of {', '.join(joints)}")
    def within(h: int) -> bool:
        ratios[h] = _predicted_rms(plant, settings, h, noise, accel) / inner
        return ratios[h] <= 1.0 + settings.noise_budget

    ratios: dict[int, float] = {}
    chosen = None
    tried = settings.horizon - 1
    for h in sorted({settings.horizon, *(h for h in HORIZONS if h > settings.horizon)}):
        if within(h):
            # The first candidate within the budget; the shortest horizon between it and the
            # last one outside is found sample by sample (the ratio falls as the horizon grows:
            # a coarse list alone lands up to a whole gap beyond the budget's horizon).
            chosen = next((g for g in range(tried + 1, h) if within(g)), h)
            break
        tried = h
    met = chosen is not None
    if chosen is None:
        chosen = min(ratios, key=ratios.__getitem__)
    tuning = NoiseTuning(chosen, settings.noise_budget, tuple(sorted(ratios.items())), inner,
                         met)
    return replace(settings, horizon=chosen), tuning


def _predicted_rms(plant: Narx, settings: ControllerSettings, horizon: int | None,
                   std: np.ndarray, accel: list[int]) -> float:
    """Stationary RMS of the norm of ``plant``'s acceleration outputs under white measurement
    noise of standard deviation ``std`` (see :func:`linear_noise_loop`): the sum over the
    loop's impulse response, IMPULSE samples long."""
    a, b, c, d = linear_noise_loop(plant, settings, horizon, accel)
    state = b * std
    variance = float(np.sum((d * std) ** 2))
    for _ in range(IMPULSE):
        variance += float(np.sum((c @ state) ** 2))
        state = a @ state
    return float(np.sqrt(variance))


def linear_noise_loop(plant: Narx, settings: ControllerSettings, horizon: int | None,
                      outputs: list[int]) -> tuple[np.ndarray, ...]:
    """(A, B, C, D) of x(k+1) = A x(k) + B n(k), z(k) = C x(k) + D n(k): ``plant``'s
    ``outputs`` one sample ahead, driven by the inner PD's response to the measurement noise
    n and (``horizon`` given) by the ARX-IMC step's v computed from the noisy measurements,
    linearised at rest (exact for the linear twin while no limit acts). x holds the
    controller's state (with a horizon) and the plant's output and input histories."""
    ny, nu, na, nb = plant.n_outputs, plant.n_inputs, plant.output_lags, plant.input_lags
    q_idx, dq_idx, kp, kd = _inner_gains(plant)
    n = ca.SX.sym("n", ny)
    xp = ca.SX.sym("xp", na * ny + nb * nu)
    hist, upast = xp[: na * ny], xp[na * ny:]
    pd_noise = (-ca.DM(kp) * n[q_idx] - ca.DM(kd) * n[dq_idx]) if q_idx else ca.DM.zeros(nu)
    parts: list[ca.SX] = []
    if horizon is None:
        x = xp
        u = pd_noise
    else:
        step, layout = build_step(plant, replace(settings, horizon=horizon, guard=False))
        xc = ca.SX.sym("xc", len(layout["state"]))
        x = ca.vertcat(xc, xp)
        _, xc_next, v, _, _ = step(hist[:ny] + n, ca.DM.zeros(ny), ca.DM.zeros(nu), xc)
        u = v + pd_noise
        parts.append(xc_next)
    y_next = plant.casadi_function("net_next")(ca.vertcat(hist, u, upast[: (nb - 1) * nu]))
    x_next = ca.vertcat(*parts, y_next, hist[: (na - 1) * ny], u, upast[: (nb - 1) * nu])
    z = y_next[outputs]
    jac = ca.Function("loop", [x, n], [ca.jacobian(x_next, x), ca.jacobian(x_next, n),
                                       ca.jacobian(z, x), ca.jacobian(z, n)])
    return tuple(np.asarray(m) for m in jac(np.zeros(x.numel()), np.zeros(ny)))


__all__ = ["HORIZONS", "NoiseTuning", "linear_noise_loop", "noise_vector", "tune_to_noise"]
