"""Neural identification of a clearance robot for the internal-model controller.

What is identified. Torque to joint angle is a double integration, and the fast dynamics of a
clearance joint (the journal flying across the clearance) sit far below one sample, so a
network that maps torque to angle directly is neither stable in free run nor invertible one
step ahead. The plant identified here is therefore the clearance robot under a fixed inner
loop: a PD on the moving joints around the ideal robot's motion, with the scene's torques as
feedforward. Its input is the torque v an outer loop adds to the PD's (``v2``, ``v3``, ...), and
its outputs are the deviations from the ideal robot of the moving joints' angles and speeds and
of the end effector's position, velocity and acceleration. The inner loop makes this plant
stable, and the deviations are the quantities the controller must drive to zero
(:mod:`jointplay.neural.model.inner_loop`).

Data (:mod:`jointplay.neural.identify.trajectories`, :mod:`jointplay.neural.identify.excitation`,
stored by :mod:`jointplay.neural.identify.datasets`): seeded excitation runs, training, validation
and test trajectories separate realisations, the test base torques including a family never used in
training (a swept sine).

Training (:mod:`jointplay.neural.identify.training`, PyTorch, float64, CPU): one-step-ahead least
squares, then simulation-error training on windows, each phase stopped early on the
validation loss, a runaway or NaN free run repaired and recorded; the linear ARX twin beside
it, and an LPV-ARX model as the stronger linear baseline (:mod:`jointplay.neural.identify.lpv`).
Judging (:mod:`jointplay.neural.model.twin`, :mod:`jointplay.neural.identify.evaluation`): the
network's residual weight chosen on validation, the model refused when worse than persistence or
ARX, errors reported on the test runs; data that cannot identify the model (an input too small,
runs shorter than a free-run window) warned about.

This module runs the whole identification into a model folder, and keeps every name of the
identification importable from one place.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import shutil
import time
from collections.abc import Callable, Sequence
from dataclasses import asdict, replace
from pathlib import Path
from typing import Any

import numpy as np

from jointplay.common.errors import DescriptionError, FileError, JointplayError
from jointplay.common.files import (
    atomic_write_text,
    file_error,
    replace_together,
    sweep_stale,
    temp_tag,
)
from jointplay.neural.identify.config import CLOSED_LOOP_CRITERIA, IdentifyConfig
from jointplay.neural.identify.datasets import DATA_FORMAT, read_datasets, write_datasets
from jointplay.neural.identify.evaluation import evaluate, identify_report, metrics_table
from jointplay.neural.identify.excitation import (
    Chirp,
    Multisine,
    aprbs,
    random_multisine,
    step_torque,
)
from jointplay.neural.identify.linear_fit import (
    Segment,
    fit_arx,
    model_scheduling,
    regress,
    segments,
)
from jointplay.neural.identify.training import train_narx
from jointplay.neural.identify.trajectories import (
    SPLITS,
    TEST_FAMILIES,
    TRAIN_FAMILIES,
    Trajectory,
    check_finite,
    collect,
    measured_contact,
    run_task,
)
from jointplay.neural.model.inner_loop import (
    DEFAULT_KD,
    DEFAULT_KP,
    LIMIT_FACTOR,
    InnerLoop,
    contact_index,
    contact_joints,
    default_limits,
    ideal_reference,
    inner_loop_for,
    input_names,
    measure,
    output_increments,
    output_names,
    reference_outputs,
    with_torques,
)
from jointplay.neural.model.narx import (
    ARX_FILE,
    LPV_FILE,
    MODEL_FILE,
    REJECTED_FILE,
    Narx,
    robot_identity,
    save_narx,
)
from jointplay.neural.model.twin import (
    Selection,
    Verdict,
    describe,
    judge,
    select_residual,
)

DATASETS_FILE = "datasets.h5"
METRICS_FILE = "metrics.json"
REPORT_FILE = "report.md"


class ModelRejected(JointplayError):
    """Identification finished but its model is worse than persistence or ARX on validation."""


# Chooses the network's residual weight by running the candidates in closed loop
# (config.residual_by "closed-loop" or "closed-loop-scene"): called with the scene, the
# settings, the inner loop, the torque limits, the trained network, its linear base and the ARX
# twin (None without scheduling signals); returns the model chosen and a record with
# ``chosen``, ``alpha``, ``summary()``. The runs need the controller and the comparison, which
# identification does not import: jointplay.neural.study.closed_loop_choice.choose_residual.
ClosedLoopChooser = Callable[[Any, IdentifyConfig, InnerLoop, np.ndarray, Narx, Narx,
                              Narx | None], tuple[Narx, Any]]


def identify(scene: Any, out: Path, config: IdentifyConfig, quiet: bool = False,
             closed_loop: ClosedLoopChooser | None = None) -> dict[str, Any]:
    """Collect the data, train, evaluate and write the model folder; return the metrics.

    ``closed_loop`` chooses the residual weight when ``config.residual_by`` asks for the
    closed loop (:func:`jointplay.neural.study.closed_loop_choice.identify_model` passes it)."""
    from jointplay.common.extras import require
    from jointplay.neural.model.plant import control_plant

    if config.residual_by in CLOSED_LOOP_CRITERIA and closed_loop is None:
        raise DescriptionError("residual_by", f"{config.residual_by!r} runs the controller in "
                               "closed loop: call jointplay.neural.study.closed_loop_choice."
                               "identify_model, or pass closed_loop=choose_residual")
    require("control", "identify()", modules=("torch",))  # training needs torch: say so first

    scene = control_plant(scene)  # the plant the controllers are judged on
    inner = inner_loop_for(scene, config.kp, config.kd)
    limits = np.asarray(config.torque_limit) if config.torque_limit else default_limits(scene)
    # The folders made here (out, missing parents; deepest first): removed if a run fails.
    created = [folder for folder in (out, *out.parents) if not folder.exists()]
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        raise DescriptionError("--out", f"cannot create folder {out}: {err}") from None
    sweep_stale(out)  # the staging folder of a run that was killed
    # Everything is written into a staging folder and moved into ``out`` only once training
    # and evaluation succeeded: a failed run leaves a previous model folder as it was.
    # Named first, made inside the try that removes it (an interrupt then leaves nothing).
    stage = out / f".identify.{temp_tag()}.{os.urandom(4).hex()}.part"
    try:
        try:
            stage.mkdir()
        except OSError as err:
            raise file_error(out, err) from None
        metrics = _identify_into(scene, stage, config, inner, limits, quiet, closed_loop)
        _move_in(stage, out, rejected="rejected" in metrics)
    except BaseException as err:
        shutil.rmtree(stage, ignore_errors=True)
        for folder in created:  # leave no empty folder behind
            with contextlib.suppress(OSError):
                folder.rmdir()
        if isinstance(err, FileError) and Path(err.path).parent == stage:
            # the file the user asked for, not its hidden staging copy
            raise FileError(str(out / Path(err.path).name), err.cause) from None
        raise
    shutil.rmtree(stage, ignore_errors=True)
    if "rejected" in metrics:
        raise ModelRejected(f"{out}: the identified model is not usable: {metrics['rejected']}")
    return metrics


def _move_in(stage: Path, out: Path, rejected: bool) -> None:
    """The staged files into the model folder; the model file (usable or not) last."""
    for name in (MODEL_FILE, REJECTED_FILE):  # a model only once every file is in
        (out / name).unlink(missing_ok=True)
    replace_together((stage / name, out / name)
                     for name in (DATASETS_FILE, METRICS_FILE, REPORT_FILE, ARX_FILE, LPV_FILE,
                                  REJECTED_FILE if rejected else MODEL_FILE))


def _identify_into(scene: Any, out: Path, config: IdentifyConfig, inner: InnerLoop,
                   limits: np.ndarray, quiet: bool,
                   closed_loop: ClosedLoopChooser | None) -> dict[str, Any]:
    """Simulate, train, judge and write every file of a model folder into ``out``."""
    dt = scene.run.output_step
    t0 = time.perf_counter()
    trajectories = collect(scene, config, inner, limits, quiet)
    check_finite(trajectories)
    t1 = time.perf_counter()
    names = _signal_names(inner.joints, measured_contact(scene, config))
    context = _context(scene, config, inner, limits)
    _store_datasets(out, trajectories, names, context, dt)
    split = {s: [t for t in trajectories if t.split == s] for s in SPLITS}
    skip = max(0, round(config.transient / dt))
    # What the model has seen: the controller's guard keeps the internal model inside it.
    # (The range covers the scheduling signals too, at the regressor's end: a model without
    # them uses the range's first entries.)
    context["training_range"] = _training_range(split["train"], skip, config, names)
    warnings = data_warnings(split["train"], split["validation"], skip, config, names, dt)
    trained, history = train_narx(split["train"], split["validation"], config, names, dt,
                                  context, quiet)
    t2 = time.perf_counter()
    arx = fit_arx(segments(split["train"], skip), names, config.output_lags,
                  config.input_lags, dt)
    arx = replace(arx, context={**context, "model": "linear ARX twin (least squares)"})
    # The residual is weighed against the linear model on the network's own regressor (with
    # the scheduling signals where the network has them): ARX + alpha (network - ARX).
    # With lpv_base the linear model is the LPV-ARX fit in the network's normalisation:
    # LPV-ARX + alpha (network - LPV-ARX), never worse than it on validation.
    start = arx if not config.scheduling else replace(
        fit_arx(segments(split["train"], skip, names), names, config.output_lags,
                config.input_lags, dt, scheduling=model_scheduling(names),
                lpv=config.lpv_base),
        context={**context, "model": ("LPV-ARX (input gain affine in the scheduling signals; "
                                      "least squares)" if config.lpv_base else
                                      "ARX with the scheduling signals (least squares)")})
    seg_val = segments(split["validation"], skip, names)
    model, selection = select_residual(trained, start, seg_val, config.window)
    dropped = None
    if config.scheduling and config.residual_by == "free-run":
        # The ARX twin (no scheduling signals) is a candidate too: where it is better on
        # validation than every blend, the scheduling signals did not help, and it is saved.
        from jointplay.neural.model.twin import window_loss, windows

        d, u, w = windows(seg_val, config.window, arx.history)
        twin_loss = window_loss(arx, d, u, model.output_scale, w)
        if twin_loss < selection.losses[selection.alpha]:
            dropped = {"twin_loss": twin_loss,
                       "best_blend_loss": selection.losses[selection.alpha]}
            model = replace(arx, context=trained.context)
            selection = replace(selection, alpha=0.0)
    closed = None
    if config.residual_by in CLOSED_LOOP_CRITERIA and closed_loop is not None:
        model, closed = closed_loop(scene, config, inner, limits, trained, start,
                                    arx if config.scheduling else None)
        if closed.chosen == "ARX twin":
            model = replace(arx, context=trained.context)
        selection = replace(selection, alpha=closed.alpha)
    # Chosen in closed loop, the model is no worse than the linear base there (it is a
    # candidate), and it need not be in free run: the free-run loss is reported, not a bar.
    verdict = judge(model, start, selection, seg_val, config.window,
                    against_linear=closed is None)
    baselines, lpv = linear_baselines(model, arx, split, skip, config, inner, names, context)
    metrics: dict[str, Any] = {
        **_errors(model, arx, split, skip),
        "free_run_loss": baselines,
        "residual": {**describe(selection, verdict),
                     **({"scheduling_dropped": dropped} if dropped else {}),
                     **({"closed_loop": closed.summary()} if closed else {})},
        "outputs": list(names["output_names"]),
        "training_history": history,
        "seconds": {"simulate": t1 - t0, "train": t2 - t1},
        "trajectories": {s: len(v) for s, v in split.items()},
        "test_families": [t.family for t in split["test"]],
        "warnings": warnings,
    }
    from jointplay.neural.identify.recommendation import recommend_from_identification

    metrics["recommendation"] = recommend_from_identification(metrics["residual"],
                                                              config.lpv_base)
    _write_results(out, scene, config, model, arx, metrics, selection, verdict)
    save_narx(lpv, out, LPV_FILE)
    return metrics


# The added torque must remove at least this share (median over the outputs) of what an
# output-only linear model leaves unexplained one step ahead on the validation runs. Measured
# on the paper scene: 0.047 to 0.21 at the default excitation (1 s runs, seeds 11-15; 0.6 s,
# seed 11: 0.19), -0.009 at 1e-8 N m (--torque-limit 1e-6,1e-6), where the input lags fit
# only chance on the training runs. The median, as single outputs (tip_y, tip_vy) that the
# input barely moves swing to -0.3 on some seeds.
MIN_INPUT_SHARE = 0.02


def input_share(train: Sequence[Segment], validation: Sequence[Segment], config: IdentifyConfig,
                names: dict[str, Any]) -> np.ndarray:
    """Per output: the share of an output-only least-squares model's one-step residual on the
    validation runs that adding the input lags removes (0 or below: the input explains
    nothing that carries over to runs it was not fitted on)."""
    carry = np.asarray(output_increments(names["output_names"]), dtype=float)
    x, t = regress(train, config.output_lags, config.input_lags, carry)
    xv, tv = regress(validation, config.output_lags, config.input_lags, carry)

    def residual(columns: slice) -> np.ndarray:
        z, zv = x[:, columns], xv[:, columns]
        mu, sd = z.mean(0), np.where(z.std(0) > 0, z.std(0), 1.0)
        a = np.hstack([(z - mu) / sd, np.ones((z.shape[0], 1))])
        av = np.hstack([(zv - mu) / sd, np.ones((zv.shape[0], 1))])
        theta = np.linalg.lstsq(a, t, rcond=None)[0]
        return np.sum((tv - av @ theta) ** 2, axis=0)

    full = residual(slice(None))
    outputs_only = residual(slice(0, config.output_lags * t.shape[1]))
    return np.where(outputs_only > 0, 1 - full / np.where(outputs_only > 0, outputs_only, 1),
                    0.0)


def data_warnings(train: list[Trajectory], validation: list[Trajectory], skip: int,
                  config: IdentifyConfig, names: dict[str, Any], dt: float) -> list[str]:
    """What in the data makes the model untrustworthy: an input too small to identify, or
    trajectories too short for the free-run windows."""
    warnings = []
    share = float(np.median(input_share(segments(train, skip), segments(validation, skip),
                                        config, names)))
    if share < MIN_INPUT_SHARE:
        rms = np.sqrt(np.mean(np.vstack([t.v[skip:] for t in train]) ** 2, axis=0))
        warnings.append(
            "the excitation is too small to identify the input's effect: the added torque "
            f"(RMS {', '.join(f'{r:.3g}' for r in rms)} N m) removes {share:.2g} of the "
            "one-step residual of an output-only model on the validation runs (median over "
            f"the outputs; needs {MIN_INPUT_SHARE:g}); the controller would invert chance "
            "correlations. Raise --torque-limit")
    usable = config.duration - skip * dt
    if usable < config.window * dt:
        warnings.append(
            f"--duration {config.duration:g} s leaves {usable:.3g} s per trajectory after the "
            f"{skip * dt:g} s transient, shorter than one free-run window ({config.window} "
            f"samples = {config.window * dt:g} s): the free run the controller relies on is "
            "trained and judged on shorter horizons than it meets. Use --duration of at "
            f"least {config.window * dt + skip * dt:g} s (or a shorter --window)")
    return warnings


def linear_baselines(model: Narx, arx: Narx, split: dict[str, list[Trajectory]], skip: int,
                     config: IdentifyConfig, inner: InnerLoop, names: dict[str, Any],
                     context: dict[str, Any]) -> tuple[dict[str, Any], Narx]:
    """Free-run window losses (the selection's loss) of the saved model, its ARX twin and the
    LPV-ARX baseline on the validation and test runs: "better than linear" means better than
    the better of the two linear models. Also the LPV-ARX model, as the controller runs it."""
    from jointplay.neural.identify.lpv import fit_lpv_arx, scheduled_segments
    from jointplay.neural.model.twin import window_loss, windows

    nj = len(inner.joints)
    fitted = fit_lpv_arx(scheduled_segments(split["train"], skip, nj), config.output_lags,
                         config.input_lags, model.increment)
    lpv = fitted.as_narx(names, model_scheduling(names), model.sample_time, arx.output_scale,
                         {**context, "model": "LPV-ARX (input gain and offset affine in the "
                                              "scheduling signals; least squares)"})
    out: dict[str, Any] = {"window": config.window,
                           "scheduling": "cos, sin of the ideal joint angles, ideal joint "
                                         "speeds, drive torques of the motion"}
    for part in ("validation", "test"):
        segs = segments(split[part], skip, names)
        d, u, w = windows(segs, config.window, model.history)
        out[part] = {"model": window_loss(model, d, u, model.output_scale, w),
                     "arx": window_loss(arx, d, u, model.output_scale, w),
                     "lpv_arx": window_loss(lpv, d, u, model.output_scale, w)}
    return out, lpv


def _signal_names(joints: tuple[int, ...], contact: tuple[int, ...] = ()) -> dict[str, Any]:
    names_out, units_out = output_names(joints, contact)
    names_in, units_in = input_names(joints)
    return {"output_names": names_out, "output_units": units_out, "input_names": names_in,
            "input_units": units_in}


def _context(scene: Any, config: IdentifyConfig, inner: InnerLoop,
             limits: np.ndarray) -> dict[str, Any]:
    """Where the model came from: robot, scene, plant, training settings, versions."""
    from importlib.metadata import version

    from jointplay.neural.identify.trajectories import robot_variants

    robot: dict[str, Any] = robot_identity(scene.robot)
    if config.clearances or config.payloads:
        # The robots the runs span: a controller may use the model on any of them.
        robot["operating_range"] = {
            "clearances": list(config.clearances), "payloads": list(config.payloads),
            "robot_hashes": sorted({robot["robot_hash"], *(
                robot_identity(s.robot)["robot_hash"]
                for _, s in robot_variants(scene, config))})}
    return {
        "robot": robot,
        "scene": {"name": scene.name, "source": scene.source or "(built-in)",
                  "torques": dict(scene.torque_text),
                  "scene_hash": hashlib.sha256(scene.text.encode()).hexdigest()},
        "plant": {
            "description": "clearance robot under a PD on the moving joints around the ideal "
                           "robot's motion (scene torques as feedforward); outputs are "
                           "deviations from the ideal robot, inputs the torque added to the "
                           "PD's",
            "outputs": "deviation from the ideal-joint robot",
            "inner_loop": {"joints": list(inner.joints), "kp": list(inner.kp),
                           "kd": list(inner.kd)},
            "torque_limit": limits.tolist(),
            "transient": config.transient,
            "integrator": {"name": scene.run.integrator, "rtol": scene.run.rtol,
                           "atol": scene.run.atol},
        },
        "training": {**{k: (list(v) if isinstance(v, tuple) else v)
                        for k, v in asdict(config).items()}},
        "versions": {pkg: version(pkg) for pkg in ("jointplay", "casadi", "torch", "numpy")},
    }


def _store_datasets(out: Path, trajectories: list[Trajectory], names: dict[str, Any],
                    context: dict[str, Any], dt: float) -> None:
    write_datasets(out / DATASETS_FILE, trajectories,
                   {**{k: list(v) for k, v in names.items()},
                    "sample_time": dt, "robot": context["robot"], "plant": context["plant"],
                    "config": context["training"]})


def _training_range(train: list[Trajectory], skip: int, config: IdentifyConfig,
                    names: dict[str, Any]) -> dict[str, Any]:
    x_train, _ = regress(segments(train, skip, names), config.output_lags, config.input_lags,
                          np.asarray(output_increments(names["output_names"]), dtype=float))
    return {"regressor_min": x_train.min(0).tolist(), "regressor_max": x_train.max(0).tolist()}


def _errors(model: Narx, arx: Narx, split: dict[str, list[Trajectory]],
            skip: int) -> dict[str, Any]:
    """Test and validation errors of the model, its twin and persistence."""
    models: dict[str, Narx | None] = {"narx": model, "arx": arx, "persistence": None}
    return {part: evaluate(models, split[part], skip, model.history)
            for part in ("test", "validation")}


def _write_results(out: Path, scene: Any, config: IdentifyConfig, model: Narx, arx: Narx,
                   metrics: dict[str, Any], selection: Selection, verdict: Verdict) -> None:
    """metrics.json, report.md, arx.json, then the model: narx.json when usable (its presence
    marks a complete, usable model folder), narx.rejected.json when not."""
    atomic_write_text(out / METRICS_FILE, json.dumps(metrics, indent=1, allow_nan=False,
                                                     default=float) + "\n")
    atomic_write_text(out / REPORT_FILE, identify_report(scene, model, metrics, config))
    summary = {"test_free_run_nrmse": metrics["test"]["narx"]["free_run"]["nrmse"],
               "test_one_step_nrmse": metrics["test"]["narx"]["one_step"]["nrmse"],
               "residual_weight": selection.alpha}
    model = replace(model, context={**model.context,
                                    "training": {**model.context["training"],
                                                 "metrics": summary}})
    save_narx(arx, out, ARX_FILE)
    save_narx(model, out, MODEL_FILE if verdict.usable else REJECTED_FILE)
    if not verdict.usable:
        metrics["rejected"] = verdict.message()


__all__ = [
    "DATASETS_FILE",
    "DATA_FORMAT",
    "DEFAULT_KD",
    "DEFAULT_KP",
    "LIMIT_FACTOR",
    "METRICS_FILE",
    "MIN_INPUT_SHARE",
    "REPORT_FILE",
    "SPLITS",
    "TEST_FAMILIES",
    "TRAIN_FAMILIES",
    "Chirp",
    "IdentifyConfig",
    "InnerLoop",
    "ModelRejected",
    "Multisine",
    "Trajectory",
    "aprbs",
    "check_finite",
    "collect",
    "contact_index",
    "contact_joints",
    "data_warnings",
    "default_limits",
    "evaluate",
    "fit_arx",
    "ideal_reference",
    "identify",
    "identify_report",
    "inner_loop_for",
    "input_names",
    "input_share",
    "measure",
    "metrics_table",
    "output_increments",
    "output_names",
    "random_multisine",
    "read_datasets",
    "reference_outputs",
    "run_task",
    "step_torque",
    "train_narx",
    "with_torques",
    "write_datasets",
]
