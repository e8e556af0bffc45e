"""The study's work: one identified model per seed, and the closed-loop runs (baselines once
per case, the internal-model controllers once per case and seed) through a process pool."""

from __future__ import annotations

import math
from functools import partial
from pathlib import Path
from typing import Any

from jointplay.common.pool import parallel_map
from jointplay.neural.control.loop_accuracy import accuracy_columns, check_tolerance, loop_accuracy
from jointplay.neural.control.metrics import SPLIT_METRICS
from jointplay.neural.model.narx import MODEL_FILE, REJECTED_FILE, load_narx, robot_identity
from jointplay.neural.study.comparison import (
    DIVERGENCE_FACTOR,
    MODEL_BASED,
    compare,
    open_loop_bound,
)
from jointplay.neural.study.control_run import load_lpv, load_twin

BASELINES = ("open loop", "PD", "computed torque")
GOAL_METRICS = (("max_position", "max |Δp| [m]"),
                ("max_velocity_after", "max |Δv| after settling [m/s]"),
                ("rms_acceleration_after", "RMS |Δa| after settling [m/s²]"))
GOAL_METRICS_KEYS = tuple(k for k, _ in GOAL_METRICS)
# The metrics judged against the open loop and PD ("worse than no control" is counted), where
# a controller can act: from the outer loop's engagement on, and after settling.
JUDGED = ("max_position_engaged", "max_velocity_engaged", "max_velocity_after",
          "max_acceleration_after", "rms_acceleration_after")
REPORTED = (*GOAL_METRICS_KEYS, "max_velocity", *(k for k in JUDGED
                                                  if k not in GOAL_METRICS_KEYS),
            *SPLIT_METRICS, "diverged", "guard_episodes", "fallback_samples",
            "input_bound_samples", "settle_s")


STUDY_JOBS: list[Any] = []  # filled before the pool forks: workers read their job by index


def study_engagement(settings: Any, dt: float) -> float:
    """When the study's internal-model controllers have engaged and their setpoint filter
    has decayed (the engagement default: twice identify's left-out start)."""
    from jointplay.neural.identify.config import IdentifyConfig
    from jointplay.neural.study.comparison import engagement_end

    engage = settings.engage if settings.engage is not None else 2.0 * IdentifyConfig.transient
    return engagement_end(engage, settings.setpoint_filter, dt)


def _run_unit(index: int) -> list[dict[str, Any]]:
    case, scene, model_dir, settings, limit, verify = STUDY_JOBS[index]
    rows = []
    if model_dir is None:
        narx = None
        # The baselines' window: the later of the case's release impacts and the engagement
        # of the internal-model controllers run after them (one window for every row).
        run = partial(compare, scene, _dummy_model(scene), settings, controllers=BASELINES,
                      analyse=False, conditions=case.conditions,
                      settle_after=study_engagement(settings, scene.run.output_step))
        seed = -1
    else:
        narx = load_narx(model_dir)
        arx = load_twin(model_dir, narx)
        limit, settle = limit
        run = partial(compare, scene, narx, settings, arx=arx, lpv=load_lpv(model_dir),
                      controllers=MODEL_BASED, analyse=False, conditions=case.conditions,
                      limit=limit, transient=settle)
        seed = int(narx.context["training"]["seed"])
    result = run()
    # --verify: the same loops with the plant 10x tighter (jointplay.neural.control.loop_accuracy)
    check_tol = check_tolerance(scene) if verify else None
    check = run(plant_tolerance=check_tol) if check_tol is not None else None
    settle_s = result.settling.time if result.settling else 0.0
    nj = len(scene.robot.moving_joints)
    for name, mt in result.metrics.items():
        row = {"case": case.name, "clearance_um": case.clearance * 1e6, "controller": name,
               "seed": seed, **{k: mt.get(k, math.nan) for k in REPORTED},
               "settle_s": settle_s}
        if check is not None and check_tol is not None:
            accuracy = loop_accuracy(result.runs[name], check.runs[name], scene=scene,
                                     check_tol=check_tol)
            row.update(accuracy_columns(accuracy, result.runs[name], check.runs[name]))
        if name == "open loop":
            row["limit"] = open_loop_bound(result.runs[name], result.reference, nj,
                                           DIVERGENCE_FACTOR)
        if narx is not None:
            tuning = result.noise_tuning
            row["horizon"] = tuning.horizon if tuning is not None else settings.horizon
            # What the horizon was chosen by: the twin's predicted RMS acceleration ratio
            # (against the inner loop alone), to set beside the ratio measured against PD.
            row["predicted_noise_ratio"] = tuning.ratio if tuning is not None else math.nan
        rows.append(row)
    return rows


def _dummy_model(scene: Any) -> Any:
    """The baselines need only the inner loop's gains: a model-shaped holder of them."""
    from types import SimpleNamespace

    from jointplay.neural.identify.pipeline import DEFAULT_KD, DEFAULT_KP, output_names

    joints = list(scene.robot.moving_joints)
    names, _ = output_names(joints)
    return SimpleNamespace(
        context={"plant": {"inner_loop": {"joints": joints, "kp": [DEFAULT_KP] * len(joints),
                                          "kd": [DEFAULT_KD] * len(joints)}}},
        output_index=names.index, output_names=names)


def pool_map(indices: list[int], workers: int, quiet: bool, label: str) -> list[Any]:
    """The rows of STUDY_JOBS' ``indices``, on up to ``workers`` forked processes."""
    from tqdm import tqdm

    with tqdm(total=len(indices), disable=quiet, desc=label, unit="run") as bar:
        return parallel_map(lambda k: _run_unit(indices[k]), len(indices), workers,
                            label="study", on_result=lambda _: bar.update(1))


def _matches(narx: Any, scene: Any, seed: int, identify_args: dict[str, Any]) -> bool:
    """Whether a model folder's model was identified for this robot with these settings (a
    folder from another study is identified again, not reused)."""
    training = narx.context.get("training", {})
    robot = narx.context.get("robot", {})
    here = robot_identity(scene.robot)["robot_hash"]
    same = robot.get("robot_hash") == here or here in robot.get("operating_range", {}).get(
        "robot_hashes", [])
    return same and training.get("seed") == seed and all(
        _setting(training, k) == (list(v) if isinstance(v, tuple) else v)
        for k, v in identify_args.items())


def _setting(training: dict[str, Any], key: str) -> Any:
    """A training setting of a model's context; settings added later take their default."""
    defaults: dict[str, Any] = {"scheduling": False, "lpv_base": False, "clearances": [],
                                "payloads": [], "residual_by": "free-run",
                                "base_fraction": 0.5, "base_motions": "mixed",
                                "scene_motions": 2,
                                "contact_outputs": False, "linear_input_gain": False}
    return training.get(key, defaults.get(key))


def ensure_models(scene: Any, folder: Path, seeds: int, identify_args: dict[str, Any],
                  quiet: bool, first: int = 0) -> list[Path]:
    """One identified model per seed (reused when its folder already holds one for this
    robot); rejected models are left out, and said so."""
    from jointplay.neural.identify.pipeline import IdentifyConfig, ModelRejected
    from jointplay.neural.study.closed_loop_choice import identify_model

    out = []
    for seed in range(first, first + seeds):
        path = folder / f"seed{seed}"
        ok = (path / MODEL_FILE).is_file() and _matches(load_narx(path), scene, seed,
                                                         identify_args)
        if not ok and not (path / REJECTED_FILE).is_file():
            if not quiet:
                print(f"identifying {path} ...", flush=True)
            try:
                identify_model(scene, path, IdentifyConfig(seed=seed, **identify_args), quiet=True)
            except ModelRejected as err:
                if not quiet:
                    print(f"  {err}")
        if (path / MODEL_FILE).is_file():
            out.append(path)
        elif not quiet:
            print(f"  seed {seed}: no usable model (rejected by identify), left out")
    return out


__all__ = ["BASELINES", "GOAL_METRICS", "JUDGED", "REPORTED", "ensure_models",
           "study_engagement"]
