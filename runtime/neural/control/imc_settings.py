"""The internal-model controller's tuning: the settings, the outputs it tracks by default, and
the settings resolved against a model (defaults filled from it, every value checked, errors
naming the flag)."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from jointplay.common.errors import DescriptionError
from jointplay.neural.model.narx import Narx


@dataclass(frozen=True)
class ControllerSettings:
    """The controller's tuning; every field has a command-line flag of the same name."""

    horizon: int = 5  # d: samples ahead the prediction is matched (5: the horizon every
    # study case was measured with; on the default scene the network tracks a little better
    # at 1, 3 and 4 over 10 seeds and worse at 10, but at 1 it rings at 10 µm clearance:
    # docs/control.md)
    regularisation: float = 1e-3  # lam, in units of the scaled outputs per (N m)^2
    setpoint_filter: float = 0.9  # a: the target leaves the deviation measured at
    # engagement over about 10 samples instead of at once (median RMS |Δa| over 10 seeds,
    # offset case 1.31e-3 -> 1.23e-3, scene 9.97e-4 -> 9.61e-4; docs/control.md)
    mismatch_filter: float = 0.9  # b
    tracked: tuple[str, ...] = ()  # outputs in C; default: see default_tracked
    scales: tuple[float, ...] = ()  # error of each tracked output that counts as 1
    torque_limit: tuple[float, ...] = ()  # |feedforward + PD + v| per joint, N m
    rate_limit: tuple[float, ...] = ()  # |dv/dt| per joint, N m/s
    iterations: int = 1  # Gauss-Newton steps on the linearisation (1: the AIMNC law)
    guard: bool = True  # trust region and fallback (off only to show what it prevents)
    trust_input: float = 2.0  # |v| <= this x the largest |v| in training
    trust_range: float = 0.5  # regressor within the training range widened by this x its width
    trust_mismatch: float = 10.0  # |C e| (scaled tracked mismatch) at most this
    fallback_hold: int = 100  # samples on the fallback after a first intervention
    # s the outer loop waits at the start (v = 0, the inner PD alone) before it starts its
    # models from the measured history; None: twice the start-up the model's training runs
    # left out (the journals falling from the centred start and bouncing, which no joint
    # torque prevents; engaging at its end, the IMC meets the decaying bounce: offset case,
    # median RMS |Δa| 2.11e-3 against 1.23e-3; engaging at 0 the worst of 10 seeds is 4.4x
    # worse on the scene; docs/control.md).
    engage: float | None = None
    # The sensors' noise, (output name, standard deviation in its unit) per noisy output;
    # when given, the horizon is chosen for it (jointplay.neural.control.noise_tuning): the shortest
    # whose predicted RMS tip acceleration from the noise is within 1 + noise_budget of the
    # inner loop's alone.
    measurement_noise: tuple[tuple[str, float], ...] = ()
    # 0.07: over 10 seeds under the study's noise (pairwise mismatch filter, horizon found to
    # the sample) the worst seed was within 10 % of PD on all three goal metrics: 1.06x its
    # position, 1.08x its velocity and 1.095x its RMS acceleration error. 0.075 gave 1.00x,
    # 1.00x and 1.098x; 0.08 let the acceleration reach 1.108x, 0.06 the position 1.20x;
    # docs/control.md, "Measurement noise".
    noise_budget: float = 0.07


def default_tracked(narx: Narx, horizon: int) -> tuple[str, ...]:
    """The end effector's position and velocity along the axis the torques move it most, and
    the angle and speed of the last nu - 1 moving joints.

    Near a stretched configuration (the paper's arm hangs almost straight) the other axis runs
    along the arm, where the joints have next to no authority: asking for it makes the inverse
    ill-conditioned. Velocities are tracked with the positions because they give the loop its
    damping; the joint rows pin the configuration the end-effector rows leave free.
    """
    joints = narx.context.get("plant", {}).get("inner_loop", {}).get("joints", [])
    names = narx.output_names
    if not joints or not {"tip_x", "tip_y", "tip_vx", "tip_vy"} <= set(names):
        return tuple(n for n in names if n.startswith("q"))[: narx.n_inputs] \
            or names[: narx.n_inputs]
    # The axis along which the tip moved most in the training data (driven by the same
    # torques). Choosing it from the network's own d-step gain, as before, picked the axis
    # along the arm for two of ten seeds at d = 5, and those loops failed (docs/control.md).
    del horizon
    axis = max("xy", key=lambda a: float(narx.output_scale[narx.output_index(f"tip_{a}")]))
    out = [f"tip_{axis}", f"tip_v{axis}"]
    for j in joints[len(joints) - (narx.n_inputs - 1):] if narx.n_inputs > 1 else []:
        out += [f"q{j}", f"dq{j}"]
    return tuple(out)


def resolve_settings(narx: Narx, settings: ControllerSettings) -> ControllerSettings:
    """Fill defaults from the model and check every value against it (errors name the flag)."""
    plant = narx.context.get("plant", {})
    nu = narx.n_inputs
    for flag, value, ok, allowed in (
            ("--horizon", settings.horizon, isinstance(settings.horizon, int)
             and 1 <= settings.horizon <= 500, "an integer from 1 to 500"),
            ("--lambda", settings.regularisation, math.isfinite(settings.regularisation)
             and settings.regularisation >= 0, "a finite number >= 0"),
            ("--setpoint-filter", settings.setpoint_filter,
             0 <= settings.setpoint_filter < 1, "a number in [0, 1)"),
            ("--mismatch-filter", settings.mismatch_filter,
             0 <= settings.mismatch_filter < 1, "a number in [0, 1)"),
            ("--iterations", settings.iterations, isinstance(settings.iterations, int)
             and 1 <= settings.iterations <= 20, "an integer from 1 to 20"),
            ("--trust-input", settings.trust_input, math.isfinite(settings.trust_input)
             and settings.trust_input > 0, "a positive number"),
            ("--trust-range", settings.trust_range, math.isfinite(settings.trust_range)
             and settings.trust_range >= 0, "a number >= 0"),
            ("--trust-mismatch", settings.trust_mismatch,
             math.isfinite(settings.trust_mismatch) and settings.trust_mismatch > 0,
             "a positive number"),
            ("--fallback-hold", settings.fallback_hold, isinstance(settings.fallback_hold, int)
             and settings.fallback_hold >= 1, "an integer >= 1"),
            ("--engage", settings.engage, settings.engage is None
             or (math.isfinite(settings.engage) and settings.engage >= 0), "a number >= 0"),
            ("--noise-budget", settings.noise_budget, math.isfinite(settings.noise_budget)
             and settings.noise_budget > 0, "a positive number")):
        if not ok:
            raise DescriptionError(flag, f"must be {allowed}, got {value!r}")
    _check_noise(narx, settings.measurement_noise)
    tracked = settings.tracked or default_tracked(narx, max(1, settings.horizon))
    for name in tracked:
        if name not in narx.output_names:
            raise DescriptionError("--track", f"{name!r} is not an output of the model "
                                   f"(outputs: {', '.join(narx.output_names)})")
    if len(set(tracked)) != len(tracked):
        raise DescriptionError("--track", "names an output twice")
    scales = settings.scales or tuple(float(narx.output_scale[narx.output_index(n)])
                                      for n in tracked)
    if len(scales) != len(tracked) or not all(s > 0 and math.isfinite(s) for s in scales):
        raise DescriptionError("--scales", f"needs one positive number per tracked output "
                               f"({len(tracked)}), got {list(scales)}")
    limits = settings.torque_limit or tuple(plant.get("torque_limit", ())) or (math.inf,) * nu
    if len(limits) != nu or not all(v > 0 for v in limits):
        raise DescriptionError("--torque-limit", f"needs {nu} positive values, got "
                               f"{list(limits)}")
    rates = settings.rate_limit or tuple(10.0 * v if math.isfinite(v) else math.inf
                                         for v in limits)
    if len(rates) != nu or not all(v > 0 for v in rates):
        raise DescriptionError("--rate-limit", f"needs {nu} positive values, got {list(rates)}")
    engage = settings.engage if settings.engage is not None else 2.0 * float(
        plant.get("transient", 0.0))
    return replace(settings, tracked=tuple(tracked), scales=tuple(float(s) for s in scales),
                   torque_limit=tuple(float(v) for v in limits),
                   rate_limit=tuple(float(v) for v in rates), engage=engage)


def _check_noise(narx: Narx, noise: tuple[tuple[str, float], ...]) -> None:
    names = [name for name, _ in noise]
    for name, std in noise:
        if name not in narx.output_names:
            raise DescriptionError("--measurement-noise", f"{name!r} is not an output of the "
                                   f"model (outputs: {', '.join(narx.output_names)})")
        if not (math.isfinite(std) and std >= 0):
            raise DescriptionError("--measurement-noise", f"{name}: the standard deviation "
                                   f"must be a finite number >= 0, got {std!r}")
    if len(set(names)) != len(names):
        raise DescriptionError("--measurement-noise", "names an output twice")


__all__ = ["ControllerSettings", "default_tracked", "resolve_settings"]
