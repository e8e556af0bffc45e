"""What ``jointplay identify``, ``control`` and ``control-study`` share: their scene and
settings (a scene file's tables or a settings file, over a preset, ``--set`` on top), and the
flags that override the settings, each declared once in a table with the key it sets and
checked as that key (jointplay.neural.study.settings_schema).
"""

from __future__ import annotations

import argparse
import math
from dataclasses import replace
from typing import TYPE_CHECKING, Any

from jointplay.common import limits as size_limits
from jointplay.common.errors import DescriptionError
from jointplay.neural.identify.config import BASE_MOTIONS, RESIDUAL_CRITERIA, IdentifyConfig
from jointplay.neural.study.settings_schema import SCHEMA

if TYPE_CHECKING:
    from jointplay.scene.definition import Scene


# ---- the scene ----------------------------------------------------------------------------------

def neural_scene_argument(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("scene", nargs="?",
                        help="scene file (TOML; its [identify], [control] and [study] tables "
                             "are the settings), or a settings file naming its scene; "
                             "default: the paper scene")


def load_control_scene(path: str | None, quiet: bool = False) -> Scene:
    """The scene of a command; closed loops step with an adaptive integrator."""
    from jointplay.scene.definition import ADAPTIVE, default_scene, load_scene

    scene = load_scene(path) if path else default_scene()
    if not scene.robot.drive or not scene.robot.moving_joints:
        raise DescriptionError("scene", "the robot has no driven joints to control")
    if scene.run.integrator not in ADAPTIVE:
        if not quiet:
            print(f"note: run.integrator {scene.run.integrator!r} cannot be stepped sample by "
                  "sample with added torques; using bdf")
        scene = scene.with_run(integrator="bdf")
    return scene


# ---- number lists ---------------------------------------------------------------------------

def float_list(text: str | None, flag: str, count: int | None = None,
               positive: bool = True) -> tuple[float, ...]:
    """``"1,2"`` to finite numbers (> 0, or >= 0 when not ``positive``); with ``count``, one
    value stands for every driven joint. ``None`` (flag not given) is the empty tuple."""
    if text is None:
        return ()
    try:
        values = tuple(float(v) for v in text.split(",") if v.strip())
    except ValueError:
        raise DescriptionError(flag, f"expects comma-separated numbers, got {text!r}") from None
    if not values or not all(math.isfinite(v) for v in values):
        raise DescriptionError(flag, f"expects finite numbers, got {text!r}")
    if positive and not all(v > 0 for v in values):
        raise DescriptionError(flag, f"every value must be > 0, got {text!r}")
    if not positive and not all(v >= 0 for v in values):
        raise DescriptionError(flag, f"every value must be >= 0, got {text!r}")
    return per_joint(values, flag, count) if count is not None else values


def per_joint(values: tuple[float, ...], name: str, count: int) -> tuple[float, ...]:
    """One value per driven joint; one value stands for every joint; empty stays empty."""
    if values and len(values) not in (1, count):
        raise DescriptionError(name, f"give one value, or one per driven joint ({count}), got "
                               f"{len(values)}")
    return values * count if len(values) == 1 else values


# ---- identification: data and training ------------------------------------------------------

COUNTS_FLAG = "--train/--validation/--test"
# Each command's flags by dest, and the settings key each sets (a tuple: the flag gives them
# comma-separated; "!": the flag is the key's negation).
FlagKeys = dict[str, str | tuple[str, ...]]
# identify's flags: (name, the settings key(s) it sets, help, type: int, float, str, bool
# or the choices, whether control-study has it too and how: "" as is, "identify-" prefixed,
# None not at all). A tuple of keys: the flag gives them comma-separated; "!": the negation.
_IDENTIFY_TABLE: tuple[tuple[str, str | tuple[str, ...], str, Any, str | None], ...] = (
    ("train", "identify.n_train", "training trajectories", int, ""),
    ("validation", "identify.n_validation", "validation trajectories (early stopping, the "
     "residual weight)", int, ""),
    ("test", "identify.n_test", "test trajectories", int, ""),
    ("duration", "identify.duration", "seconds per trajectory", float, ""),
    ("lags", ("identify.output_lags", "identify.input_lags"), "output lags,input lags", str,
     "identify-"),
    ("hidden", "identify.hidden", "hidden layer widths, e.g. 24,24", str, "identify-"),
    ("iterations", ("identify.one_step_iterations", "identify.multi_step_iterations"),
     "L-BFGS iterations: one-step phase, free-run phase (early stopping may end either "
     "sooner)", str, "identify-"),
    ("window", "identify.window", "samples per free-run window, for training and for "
     "weighing the residual", int, "identify-"),
    ("scheduling", "identify.scheduling", "the network also sees the scheduling signals: the "
     "ideal robot's joint angles (cos, sin) and speeds and the drive torques of the motion "
     "(the LPV-ARX baseline always does)", bool, ""),
    ("lpv-base", "identify.lpv_base", "with --scheduling: the network's linear part is an "
     "LPV-ARX model (input gain affine in the scheduling signals), started at its "
     "least-squares fit, and its residual is weighed against it", bool, ""),
    ("contact-outputs", "identify.contact_outputs", "the journals' eccentricities (ex, ey) at "
     "every clearance joint are measured outputs too (bearing displacement sensors): every "
     "model and controller sees the contact state", bool, "identify-"),
    ("linear-input-gain", "identify.linear_input_gain", "the network's hidden layers do not "
     "see the added torque: the model's input gain (what the controller inverts) is its "
     "linear part's, and the network corrects only the rest of the response", bool,
     "identify-"),
    ("residual-by", "identify.residual_by", "how the network's residual weight is chosen on "
     "validation: free-run (its free-run loss over windows), closed-loop (each candidate "
     "runs as the internal-model controller on the validation runs' motions; the lowest RMS "
     "acceleration error after settling wins; needs --validation 2 or more) or "
     "closed-loop-scene (the same on motions of the scene's own family: its torques at other "
     "amplitudes, rates and time shifts, seeded)", RESIDUAL_CRITERIA, "identify-"),
    ("base-fraction", "identify.base_fraction", "peak of the excitation runs' base torques "
     "(multisines, steps, chirps), as a fraction of the torque limit", float, "identify-"),
    ("base-motions", "identify.base_motions", "what drives the training and validation runs' "
     "reference motions: mixed (the scene's torques, random multisines and steps in turn) or "
     "scene-family (the scene's torques at other amplitudes, rates and time shifts, seeded: "
     "the motions the controller is judged on); the test runs keep their families",
     BASE_MOTIONS, "identify-"),
    ("scene-motions", "identify.scene_motions", "with closed-loop-scene: how many motions of "
     "the scene's family each candidate runs on", int, "identify-"),
    ("clearances", "identify.clearances", "radial clearances, m, the training and validation "
     "runs span (each run on one, cycling with the payloads; e.g. 30e-6,100e-6; default: "
     "the scene's)", str, "identify-"),
    ("payloads", "identify.payloads", "payload masses, kg, the training and validation runs "
     "span (e.g. 0,2,3; default: the scene's)", str, "identify-"),
    ("no-linear-path", "!identify.linear_path", "no linear direct path beside the hidden "
     "layers (the bare network)", bool, None),
    ("kp", "identify.kp", "inner-loop PD stiffness per driven joint, N m/rad (empty: the "
     "inner loop's default)", str, None),
    ("kd", "identify.kd", "inner-loop PD damping per driven joint, N m s/rad (empty: the "
     "inner loop's default)", str, None),
    ("torque-limit", "identify.torque_limit", "actuator limits per driven joint, N m (empty: "
     "3 x the scene's peak torque)", str, None),
    ("seed", "identify.seed", "seed of everything random", int, None),
    ("workers", "identify.workers", "processes simulating trajectories (0: one per core, at "
     "most 4)", int, None),
)


def add_identify_arguments(parser: argparse.ArgumentParser, *, study: bool = False
                           ) -> FlagKeys:
    """identify's flags (``study``: the ones control-study has, most prefixed with
    ``identify-``); the settings key each sets, by its dest."""
    keys: FlagKeys = {}
    for name, key, text, kind, in_study in _IDENTIFY_TABLE:
        if study and in_study is None:
            continue
        flag = f"--{in_study if study else ''}{name}"
        dest = "identify_" + name.replace("-", "_")
        if kind is bool:
            parser.add_argument(flag, dest=dest, action="store_true", help=text)
        elif isinstance(kind, tuple):
            parser.add_argument(flag, dest=dest, choices=kind, help=text)
        else:
            parser.add_argument(flag, dest=dest, type=kind, help=text)
        keys[dest] = key
    return keys


def check_identify_for(config: IdentifyConfig, scene: Scene,
                       given: dict[str, str]) -> IdentifyConfig:
    """What depends on the scene, checked before any work (each named by its flag when one
    gave it, else by its key): per-joint values, the contact state measured, the trajectories'
    number and duration; the per-joint values with one for every joint."""
    def name(key: str) -> str:
        return given.get(f"identify.{key}", f"identify.{key}")

    n = len(scene.robot.moving_joints)
    joints: dict[str, Any] = {key: per_joint(getattr(config, key), name(key), n)
                              for key in ("kp", "kd", "torque_limit")}
    if config.contact_outputs and not scene.robot.clearance_joints:
        raise DescriptionError(name("contact_outputs"), "the scene's robot has no clearance "
                               "joint, so there is no journal eccentricity to measure")
    counts = (config.n_train, config.n_validation, config.n_test)
    if sum(counts) > size_limits.MAX_TRAJECTORIES:
        raise DescriptionError(COUNTS_FLAG, f"{sum(counts)} trajectories in all; at most "
                               f"{size_limits.MAX_TRAJECTORIES} are allowed")
    lags = (config.output_lags, config.input_lags)
    dt = scene.run.output_step
    if round((config.duration - config.transient) / dt) < max(lags) + 2:
        raise DescriptionError(name("transient"), f"{config.transient:g} s of trajectories of "
                               f"{config.duration:g} s leaves too few samples for lags {lags} "
                               f"at {dt:g} s per sample (at least {max(lags) + 2}); shorten "
                               f"it or lengthen {name('duration')}")
    check_duration(config.duration, counts, lags, dt, name("duration"))
    return replace(config, **joints)


def check_tracked_for(tracked: tuple[str, ...], scene: Scene, contact_outputs: bool,
                      given: dict[str, str]) -> None:
    """The tracked outputs named in the settings, checked before any work against the
    outputs every model identified on ``scene`` will have (the moving joints' angles and
    speeds, the tip's signals, the journals' eccentricities when measured)."""
    from jointplay.common.hints import did_you_mean
    from jointplay.neural.model.inner_loop import output_names

    field = given.get("control.tracked", "control.tracked")
    contact = scene.robot.clearance_joints if contact_outputs else ()
    names, _ = output_names(scene.robot.moving_joints, contact)
    for name in tracked:
        if name not in names:
            raise DescriptionError(field, f"{name!r} is not an output of the models this scene "
                                   f"gives (outputs: {', '.join(names)})"
                                   + did_you_mean(name, names))
    if len(set(tracked)) != len(tracked):
        twice = next(n for n in tracked if tracked.count(n) > 1)
        raise DescriptionError(field, f"names {twice!r} twice; name each output once")


def check_duration(duration: float, counts: tuple[int, ...], lags: tuple[int, ...],
                   dt: float, name: str = "--duration") -> None:
    """Seconds per trajectory: within the samples allowed, long enough for the lags."""
    samples = sum(counts) * duration / dt
    if samples > size_limits.MAX_IDENTIFY_SAMPLES:
        raise DescriptionError(name, f"{sum(counts)} trajectories of {duration:g} s "
                               f"at {dt:g} s per sample are {samples:.3g} "
                               f"samples; at most {size_limits.MAX_IDENTIFY_SAMPLES} are allowed")
    if round(duration / dt) < max(lags) + 2 + round(0.05 / dt):
        raise DescriptionError(name, f"{duration:g} s is too short for lags "
                               f"{lags} at {dt:g} s per sample after the 0.05 s transient")


# ---- the controller's tuning ----------------------------------------------------------------

# The controller's flags (``control`` and ``control-study``): (flag, dest, the settings key,
# help, type).
_CONTROL_TABLE: tuple[tuple[str, str, str, str, Any], ...] = (
    ("--horizon", "horizon", "control.horizon", "samples ahead the prediction is matched",
     int),
    ("--lambda", "lambda_", "control.regularisation", "regularisation of the inverse", float),
    ("--setpoint-filter", "setpoint_filter", "control.setpoint_filter",
     "a in y_d(k+1) = a y_d(k) + (1 - a) r(k+1)", float),
    ("--mismatch-filter", "mismatch_filter", "control.mismatch_filter",
     "b of the first-order mismatch filter", float),
    ("--iterations", "iterations", "control.iterations",
     "linearisations per step (1: the AIMNC law)", int),
    ("--track", "track", "control.tracked", "outputs the controller matches, e.g. q2,q3 "
     "(empty: the end effector's position and velocity along the axis the torques move it "
     "most, and the last joint's angle and speed)", str),
    ("--scales", "scales", "control.scales", "error of each tracked output that counts as 1 "
     "(empty: its spread in the training data)", str),
    ("--torque-limit", "torque_limit", "control.torque_limit", "actuator limits per driven "
     "joint, N m (empty: the model's)", str),
    ("--rate-limit", "rate_limit", "control.rate_limit", "limit on the outer loop's torque "
     "rate per driven joint, N m/s (empty: 10 x the torque limit)", str),
    ("--no-guard", "no_guard", "!control.guard", "run the network without its trust region "
     "and fallback (to see what the guard prevents; a diverging loop is still stopped and "
     "reported)", bool),
    ("--trust-input", "trust_input", "control.trust_input",
     "|v| kept within this x the largest |v| in training", float),
    ("--trust-range", "trust_range", "control.trust_range", "the internal model's regressor "
     "and prediction must stay in the training range widened by this x its width", float),
    ("--trust-mismatch", "trust_mismatch", "control.trust_mismatch", "largest scaled "
     "mismatch on a tracked output before the network is distrusted", float),
    ("--engage", "engage", "control.engage", "seconds the outer loop waits at the start, the "
     "inner PD alone, before it starts its models from the measured history (absent: twice "
     "the start-up the model's training runs left out, 0.1 s)", float),
    ("--measurement-noise", "measurement_noise", "control.measurement_noise", "the sensors' "
     "noise, NAME=STD per measured output in its unit, e.g. q2=3e-6,dq2=4e-3,tip_vx=1e-3: "
     "every controller measures through it (control-study: see its noise case), and the "
     "internal-model controllers choose their horizon for it (the shortest whose predicted "
     "RMS tip acceleration from the noise is within 1 + the noise budget of the inner "
     "loop's alone)", str),
    ("--noise-budget", "noise_budget", "control.noise_budget", "with --measurement-noise: "
     "the increase of the noise's RMS tip acceleration over the inner loop's alone that the "
     "outer loop may add", float),
    ("--fallback-hold", "fallback_hold", "control.fallback_hold", "samples on the fallback "
     "after a first intervention, doubling with each further one", int),
)


def add_controller_arguments(parser: argparse.ArgumentParser) -> FlagKeys:
    """The controller's tuning flags; the settings key each sets, by its dest."""
    for flag, dest, _, text, kind in _CONTROL_TABLE:
        if kind is bool:
            parser.add_argument(flag, dest=dest, action="store_true", help=text)
        else:
            parser.add_argument(flag, dest=dest, type=kind, help=text)
    return {dest: key for _, dest, key, _, _ in _CONTROL_TABLE}


def noise_pairs(text: str | None) -> tuple[tuple[str, float], ...]:
    """``--measurement-noise``'s NAME=STD pairs (names are checked against the model later)."""
    from jointplay.neural.study.settings_schema import parse_text

    if not text:
        return ()
    value: tuple[tuple[str, float], ...] = parse_text(
        "--measurement-noise", SCHEMA["control"]["measurement_noise"], text)
    return value
