"""What ``jointplay identify``, ``control`` and ``control-study`` share: their scene, number
lists given per driven joint, the data and training flags of identification, and the
controller's tuning flags. Every flag is declared here once; a command picks the ones it has.
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path
from typing import TYPE_CHECKING, Any

from jointplay.common import limits as size_limits
from jointplay.common.errors import DescriptionError
from jointplay.neural.control.imc import ControllerSettings, resolve_settings
from jointplay.neural.identify.pipeline import IdentifyConfig

if TYPE_CHECKING:
    from jointplay.neural.model.narx import Narx
    from jointplay.neural.study.settings import Settings
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
    if count is not None and len(values) not in (1, count):
        raise DescriptionError(flag, f"give one value, or one per driven joint ({count}), got "
                               f"{len(values)}")
    return values * count if count is not None and len(values) == 1 else values


def int_list(text: str, flag: str, size: int | None = None, low: int = 1,
             high: int | None = None) -> tuple[int, ...]:
    """``"13,14"`` to integers >= ``low`` (and <= ``high``), exactly ``size`` of them if given."""
    try:
        values = tuple(int(v) for v in text.split(",") if v.strip())
    except ValueError:
        raise DescriptionError(flag, f"expects comma-separated integers, got {text!r}") from None
    if not values or any(v < low for v in values) or (size is not None and len(values) != size):
        what = f"{size} integers" if size else "integers"
        raise DescriptionError(flag, f"expects {what} >= {low}, got {text!r}")
    if high is not None and max(values) > high:
        raise DescriptionError(flag, f"every value must be at most {high}, got {text!r}")
    return values


# ---- identification: data and training ------------------------------------------------------

COUNTS_FLAG = "--train/--validation/--test"
_D = IdentifyConfig
# flag -> (type, default, help in ``identify``, help in ``control-study``, where the flags
# are the data of the models the study identifies)
_DATA_FLAGS: dict[str, tuple[Any, Any, str, str]] = {
    "--train": (int, _D.n_train, "training trajectories (default %(default)s)",
                f"identify: training runs (default {_D.n_train})"),
    "--validation": (int, _D.n_validation,
                     "validation trajectories, for early stopping (default %(default)s)",
                     f"identify: validation runs (default {_D.n_validation})"),
    "--test": (int, _D.n_test, "test trajectories (default %(default)s)",
               f"identify: test runs (default {_D.n_test})"),
    "--duration": (float, _D.duration, "seconds per trajectory (default %(default)s)",
                   f"identify: seconds per run (default {_D.duration:g})"),
}
ITERATIONS_DEFAULT = f"{_D.one_step_iterations},{_D.multi_step_iterations}"


def add_identify_data_arguments(parser: argparse.ArgumentParser, *, study: bool = False) -> None:
    """--train, --validation, --test, --duration: the trajectories identification simulates."""
    for flag, (kind, default, own_help, study_help) in _DATA_FLAGS.items():
        parser.add_argument(flag, type=kind, default=default,
                            help=study_help if study else own_help)


def add_scheduling_argument(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--scheduling", action="store_true",
                        help="the network also sees the scheduling signals: the ideal robot's "
                             "joint angles (cos, sin) and speeds and the drive torques of the "
                             "motion (the LPV-ARX baseline always does)")
    parser.add_argument("--lpv-base", action="store_true",
                        help="with --scheduling: the network's linear part is an LPV-ARX model "
                             "(input gain affine in the scheduling signals), started at its "
                             "least-squares fit, and its residual is weighed against it")


def add_contact_argument(parser: argparse.ArgumentParser, flag: str) -> None:
    parser.add_argument(flag, dest="contact_outputs", action="store_true",
                        help="the journals' eccentricities (ex, ey) at every clearance joint are "
                             "measured outputs too (bearing displacement sensors): every model "
                             "and controller sees the contact state")


def contact_setting(args: argparse.Namespace, scene: Any, flag: str) -> bool:
    """The contact-outputs flag, refused on a robot without a clearance joint."""
    if args.contact_outputs and not scene.robot.clearance_joints:
        raise DescriptionError(flag, "the scene's robot has no clearance joint, so there is "
                               "no journal eccentricity to measure: drop the flag")
    return bool(args.contact_outputs)


def add_linear_gain_argument(parser: argparse.ArgumentParser, flag: str) -> None:
    parser.add_argument(flag, dest="linear_input_gain", action="store_true",
                        help="the network's hidden layers do not see the added torque: the "
                             "model's input gain (what the controller inverts) is its linear "
                             "part's, and the network corrects only the rest of the response")


def add_residual_argument(parser: argparse.ArgumentParser, flag: str = "--residual-by"
                          ) -> None:
    from jointplay.neural.identify.config import RESIDUAL_CRITERIA

    parser.add_argument(flag, dest="residual_by", choices=RESIDUAL_CRITERIA,
                        default="free-run",
                        help="how the network's residual weight is chosen on validation: "
                             "free-run (its free-run loss over windows) or closed-loop (each "
                             "candidate runs as the internal-model controller on the "
                             "validation runs' motions; the lowest RMS acceleration error "
                             "after settling wins; needs --validation 2 or more) or "
                             "closed-loop-scene (the same on two motions of the scene's own "
                             "family: its torques at other amplitudes, rates and time "
                             "shifts, seeded) (default %(default)s)")


def add_scene_motions_argument(parser: argparse.ArgumentParser, flag: str) -> None:
    parser.add_argument(flag, dest="scene_motions", type=int, default=_D.scene_motions,
                        help="with closed-loop-scene: how many motions of the scene's family "
                             "each candidate runs on (default %(default)s)")


def scene_motions_setting(args: argparse.Namespace, flag: str) -> int:
    """The number of scene-family motions, refused outside 1 to MAX_SCENE_MOTIONS."""
    from jointplay.common.errors import DescriptionError
    from jointplay.neural.identify.config import MAX_SCENE_MOTIONS

    value = int(args.scene_motions)
    if not 1 <= value <= MAX_SCENE_MOTIONS:
        raise DescriptionError(flag, f"must be a whole number from 1 to {MAX_SCENE_MOTIONS}, "
                                     f"got {value}")
    return value


def residual_setting(args: argparse.Namespace, flag: str, n_validation: int) -> str:
    """--residual-by, refused as closed-loop without a validation run past the first (which
    drives the scene's own torques, the motion the controller is tested on)."""
    from jointplay.common.errors import DescriptionError

    if args.residual_by == "closed-loop" and n_validation < 2:
        raise DescriptionError(flag, "closed-loop needs a validation run whose motion is not "
                                     "the scene's own (the first drives the scene's torques): "
                                     "give --validation 2 or more")
    return str(args.residual_by)


def add_base_fraction_argument(parser: argparse.ArgumentParser, flag: str) -> None:
    parser.add_argument(flag, dest="base_fraction", type=float, default=_D.base_fraction,
                        help="peak of the excitation runs' base torques (multisines, steps, "
                             "chirps), as a fraction of the torque limit: the size of the "
                             "motions the model is identified on (default %(default)s)")


def add_base_motions_argument(parser: argparse.ArgumentParser, flag: str) -> None:
    from jointplay.neural.identify.config import BASE_MOTIONS

    parser.add_argument(flag, dest="base_motions", choices=BASE_MOTIONS,
                        default=_D.base_motions,
                        help="what drives the training and validation runs' reference "
                             "motions: mixed (the scene's torques, random multisines and "
                             "steps in turn) or scene-family (the scene's torques, then the "
                             "scene's torques at other amplitudes, rates and time shifts, "
                             "seeded: the motions the controller is judged on); the test runs "
                             "keep their families (default %(default)s)")


def base_fraction_setting(args: argparse.Namespace, flag: str) -> float:
    """The base torques' peak fraction, refused outside (0, 1]."""
    from jointplay.common.errors import DescriptionError

    value = float(args.base_fraction)
    if not 0 < value <= 1:
        raise DescriptionError(flag, f"must be above 0 and at most 1, got {value:g}")
    return value


def lpv_base_setting(args: argparse.Namespace) -> bool:
    """--lpv-base, refused without --scheduling."""
    from jointplay.common.errors import DescriptionError

    if args.lpv_base and not args.scheduling:
        raise DescriptionError("--lpv-base", "needs --scheduling (the LPV-ARX gain is affine "
                                             "in the scheduling signals)")
    return bool(args.lpv_base)


def add_operating_range_arguments(parser: argparse.ArgumentParser, prefix: str = "") -> None:
    parser.add_argument(f"--{prefix}clearances", dest="span_clearances", metavar="M,M",
                        help="radial clearances, m, the training and validation runs span "
                             "(each run on one, cycling with the payloads; e.g. "
                             "30e-6,100e-6; default: the scene's)")
    parser.add_argument(f"--{prefix}payloads", dest="span_payloads", metavar="KG,KG",
                        help="payload masses, kg, the training and validation runs span "
                             "(e.g. 0,2,3; default: the scene's)")


def operating_range(args: argparse.Namespace, prefix: str = "") -> dict[str, Any]:
    """The clearances and payloads the flags give (each checked, named when refused)."""
    out: dict[str, tuple[float, ...]] = {}
    for key, flag, positive in (("clearances", f"--{prefix}clearances", True),
                                ("payloads", f"--{prefix}payloads", False)):
        text = getattr(args, f"span_{key}")
        out[key] = float_list(text, flag, positive=positive) if text else ()
    return out


def add_iterations_argument(parser: argparse.ArgumentParser, flag: str, text: str) -> None:
    parser.add_argument(flag, default=ITERATIONS_DEFAULT, help=text)


def trajectory_counts(args: argparse.Namespace) -> tuple[int, ...]:
    """Training, validation and test trajectories, each at least 1."""
    return int_list(f"{args.train},{args.validation},{args.test}", COUNTS_FLAG)


def iteration_counts(text: str, flag: str, high: int | None = None) -> tuple[int, ...]:
    """L-BFGS iterations of the one-step and the free-run phase (0 skips a phase)."""
    return int_list(text, flag, 2, low=0, high=high)


def check_duration(duration: float, counts: tuple[int, ...], lags: tuple[int, ...],
                   dt: float) -> None:
    """Seconds per trajectory: positive, within the limits, long enough for the lags."""
    if not (isinstance(duration, float) and math.isfinite(duration) and duration > 0):
        raise DescriptionError("--duration", f"must be a positive number of seconds, got "
                               f"{duration!r}")
    if duration > size_limits.MAX_T_END:
        raise DescriptionError("--duration", f"must be at most {size_limits.MAX_T_END:g} s, got "
                               f"{duration:g}")
    samples = sum(counts) * duration / dt
    if samples > size_limits.MAX_IDENTIFY_SAMPLES:
        raise DescriptionError("--duration", f"{sum(counts)} trajectories of {duration:g} s "
                               f"at {dt:g} s per sample are {samples:.3g} "
                               f"samples; at most {size_limits.MAX_IDENTIFY_SAMPLES} are allowed")
    if round(duration / dt) < max(lags) + 2 + round(0.05 / dt):
        raise DescriptionError("--duration", f"{duration:g} s is too short for lags "
                               f"{lags} at {dt:g} s per sample after the 0.05 s transient")


# ---- the controller's tuning ----------------------------------------------------------------

def add_settings_arguments(p: argparse.ArgumentParser, d: ControllerSettings) -> None:
    """The controller's tuning flags (``control`` and ``control-study``)."""
    p.add_argument("--horizon", type=int, default=d.horizon,
                   help="samples ahead the prediction is matched (default %(default)s)")
    p.add_argument("--lambda", dest="lambda_", type=float, default=d.regularisation,
                   help="regularisation of the inverse (default %(default)s)")
    p.add_argument("--setpoint-filter", type=float, default=d.setpoint_filter,
                   help="a in y_d(k+1) = a y_d(k) + (1 - a) r(k+1) (default %(default)s)")
    p.add_argument("--mismatch-filter", type=float, default=d.mismatch_filter,
                   help="b of the first-order mismatch filter (default %(default)s)")
    p.add_argument("--iterations", type=int, default=d.iterations,
                   help="linearisations per step (default %(default)s: the AIMNC law)")
    p.add_argument("--track", help="outputs the controller matches, e.g. q2,q3 (default: the "
                                   "end effector's position and velocity along the axis the "
                                   "torques move it most, and the last joint's angle and "
                                   "speed)")
    p.add_argument("--scales", help="error of each tracked output that counts as 1 (default: "
                                    "its spread in the training data)")
    p.add_argument("--torque-limit", help="actuator limits per driven joint, N m (default: "
                                          "the model's)")
    p.add_argument("--rate-limit", help="limit on the outer loop's torque rate per driven "
                                        "joint, N m/s (default: 10 x the torque limit)")
    p.add_argument("--no-guard", action="store_true",
                   help="run the network without its trust region and fallback (to see what "
                        "the guard prevents; a diverging loop is still stopped and reported)")
    p.add_argument("--trust-input", type=float, default=d.trust_input,
                   help="|v| kept within this x the largest |v| in training (default "
                        "%(default)s)")
    p.add_argument("--trust-range", type=float, default=d.trust_range,
                   help="the internal model's regressor and prediction must stay in the "
                        "training range widened by this x its width (default %(default)s)")
    p.add_argument("--trust-mismatch", type=float, default=d.trust_mismatch,
                   help="largest scaled mismatch on a tracked output before the network is "
                        "distrusted (default %(default)s)")
    p.add_argument("--engage", type=float, default=None,
                   help="seconds the outer loop waits at the start, the inner PD alone, before "
                        "it starts its models from the measured history (default: twice the "
                        "start-up the model's training runs left out, 0.1 s)")
    p.add_argument("--measurement-noise", metavar="NAME=STD,...",
                   help="the sensors' noise, standard deviation per measured output in its "
                        "unit, e.g. q2=3e-6,dq2=4e-3,tip_vx=1e-3: every controller measures "
                        "through it (control-study: see its noise case), and the "
                        "internal-model controllers choose their horizon for it (the shortest "
                        "whose predicted RMS tip acceleration from the noise is within "
                        "1 + --noise-budget of the inner loop's alone)")
    p.add_argument("--noise-budget", type=float, default=d.noise_budget,
                   help="with --measurement-noise: the increase of the noise's RMS tip "
                        "acceleration over the inner loop's alone that the outer loop may add "
                        "(default %(default)s)")
    p.add_argument("--fallback-hold", type=int, default=d.fallback_hold,
                   help="samples on the fallback after a first intervention, doubling with "
                        "each further one (default %(default)s)")


def noise_pairs(text: str | None) -> tuple[tuple[str, float], ...]:
    """``--measurement-noise``'s NAME=STD pairs (names are checked against the model later)."""
    out = []
    for item in (text or "").split(","):
        if not item.strip():
            continue
        name, sep, value = item.partition("=")
        try:
            std = float(value)
        except ValueError:
            std = math.nan
        if not sep or not name.strip() or not math.isfinite(std) or std < 0:
            raise DescriptionError("--measurement-noise", f"{item.strip()!r}: give NAME=STD "
                                   "pairs, e.g. dq2=4e-3,tip_vx=1e-3 (STD >= 0, in the "
                                   "output's unit)")
        out.append((name.strip(), std))
    return tuple(out)


def settings_from_args(args: argparse.Namespace, narx: Narx | None) -> ControllerSettings:
    """The settings the flags give; resolved against ``narx`` when given (defaults filled
    from it, every value checked), else as given (each model resolves them for itself)."""
    tracked = tuple(n.strip() for n in args.track.split(",") if n.strip()) if args.track else ()
    settings = ControllerSettings(
        horizon=args.horizon, regularisation=args.lambda_, setpoint_filter=args.setpoint_filter,
        mismatch_filter=args.mismatch_filter, tracked=tracked,
        scales=float_list(args.scales, "--scales"),
        torque_limit=float_list(args.torque_limit, "--torque-limit"),
        rate_limit=float_list(args.rate_limit, "--rate-limit"), iterations=args.iterations,
        guard=not args.no_guard, trust_input=args.trust_input, trust_range=args.trust_range,
        trust_mismatch=args.trust_mismatch, fallback_hold=args.fallback_hold,
        engage=args.engage, measurement_noise=noise_pairs(args.measurement_noise),
        noise_budget=args.noise_budget)
    return resolve_settings(narx, settings) if narx is not None else settings


# ---- the settings file ----------------------------------------------------------------------

SETTINGS_HELP = ("every key of the [identify], [control] and [study] tables, its meaning and "
                 "its default per preset: docs/how-to/settings-file.md")


def add_settings_file_arguments(parser: argparse.ArgumentParser) -> None:
    """``--preset`` and ``--set``: the settings' preset and any key of them."""
    parser.add_argument("--preset", metavar="NAME",
                        help="the settings' starting point: best (the best setting measured; "
                             "the default) or paper (the paper's NARX 13/14)")
    parser.add_argument("--set", dest="overrides", action="append", default=[],
                        metavar="SECTION.KEY=VALUE",
                        help="override one key of the settings, e.g. identify.hidden=24,24 "
                             "(repeatable; " + SETTINGS_HELP + ")")


def scene_and_settings(args: argparse.Namespace) -> tuple[Scene, Settings, Path | None]:
    """The scene, the settings (the file's tables over its preset, ``--set`` on top) and the
    scene file to record: ``args.scene`` is a scene file (its settings tables, if any, read
    too), a settings file naming its scene, or None (the paper scene)."""
    from jointplay.common.validation import read_toml
    from jointplay.neural.study.settings import (
        is_settings_document,
        read_settings_file,
        resolve_settings,
        settings_tables,
    )

    path = Path(args.scene) if args.scene else None
    scene_file: Path | None = path
    if path is None:
        settings = resolve_settings({}, preset=args.preset, overrides=args.overrides,
                                    source="flags")
    else:
        data, _ = read_toml(path, "scene or settings")
        if is_settings_document(data):
            settings, scene_file = read_settings_file(path, preset=args.preset,
                                                      overrides=args.overrides)
        else:
            settings = resolve_settings(settings_tables(data), preset=args.preset,
                                        overrides=args.overrides, source=str(path))
    scene = load_control_scene(str(scene_file) if scene_file else None, args.quiet)
    return scene, settings, scene_file.resolve() if scene_file else None


# Each command's flags and the settings key each overrides (a tuple: the flag gives them as
# a comma-separated list; "!": the flag is the key's negation). A flag not given takes its
# value from the settings.
IDENTIFY_DATA = {
    "train": "identify.n_train", "validation": "identify.n_validation",
    "test": "identify.n_test", "duration": "identify.duration",
    "scheduling": "identify.scheduling", "lpv_base": "identify.lpv_base",
    "contact_outputs": "identify.contact_outputs",
    "linear_input_gain": "identify.linear_input_gain", "residual_by": "identify.residual_by",
    "base_fraction": "identify.base_fraction", "base_motions": "identify.base_motions",
    "scene_motions": "identify.scene_motions", "span_clearances": "identify.clearances",
    "span_payloads": "identify.payloads",
}
CONTROL_FLAGS = {
    "horizon": "control.horizon", "lambda_": "control.regularisation",
    "setpoint_filter": "control.setpoint_filter", "mismatch_filter": "control.mismatch_filter",
    "iterations": "control.iterations", "track": "control.tracked", "scales": "control.scales",
    "torque_limit": "control.torque_limit", "rate_limit": "control.rate_limit",
    "no_guard": "!control.guard", "trust_input": "control.trust_input",
    "trust_range": "control.trust_range", "trust_mismatch": "control.trust_mismatch",
    "engage": "control.engage", "measurement_noise": "control.measurement_noise",
    "noise_budget": "control.noise_budget", "fallback_hold": "control.fallback_hold",
}
FlagKeys = dict[str, str | tuple[str, ...]]


def settings_defaults(parser: argparse.ArgumentParser, flags: FlagKeys,
                      shown: tuple[str, ...] | None = None) -> None:
    """The flags in ``flags`` default to the settings (None until filled in); their help
    says so. With ``shown``, only those flags (and the others not in ``flags``) are listed
    by --help: the rest stay accepted, as overrides the settings file documents."""
    import re

    for action in parser._actions:
        if action.dest not in flags:
            continue
        action.default = None
        if shown is not None and action.dest not in shown:
            action.help = argparse.SUPPRESS
        elif action.help and action.help != argparse.SUPPRESS:
            action.help = re.sub(r" ?\(default[^()]*(\([^()]*\)[^()]*)*\)", "", action.help) \
                + f" (default: {_setting_name(flags[action.dest])} of the settings)"


def _setting_name(keys: str | tuple[str, ...]) -> str:
    return ", ".join(keys) if isinstance(keys, tuple) else keys.lstrip("!")


def fill_from_settings(args: argparse.Namespace, settings: Settings, flags: FlagKeys) -> None:
    """Every flag not given takes the settings' value, in the form the flag is read in."""
    for dest, keys in flags.items():
        if getattr(args, dest, None) is not None:
            continue
        if isinstance(keys, tuple):
            setattr(args, dest, ",".join(str(_value(settings, k)) for k in keys))
            continue
        value = _value(settings, keys.lstrip("!"))
        if keys.startswith("!"):
            value = not value
        elif isinstance(value, tuple):
            value = ",".join(f"{v[0]}={v[1]!r}" if isinstance(v, tuple) else str(v)
                             for v in value) or None
        setattr(args, dest, value)


def _value(settings: Settings, key: str) -> Any:
    section, _, name = key.partition(".")
    return getattr(getattr(settings, section), name)
