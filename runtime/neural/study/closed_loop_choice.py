"""The network's residual weight chosen by the closed loop it is identified for.

The free-run loss that :func:`jointplay.neural.model.twin.select_residual` minimises does not
predict the controller: on seeds 1 and 2 of the paper scene the network fitted the validation
runs better in free run than its linear base in 13 of 16 models and won in closed loop in 4
(docs/explanation/controller.md). Here each candidate internal model, the blends
``base + alpha (network - base)`` at :data:`CLOSED_LOOP_ALPHAS` (and the ARX twin without
scheduling signals, where the network has them), runs as the internal-model
controller on the validation runs' motions, and the candidate with the lowest RMS
end-effector acceleration error after settling is saved.

Only validation data decide: the motions are the base torques of the validation
trajectories, the scene's own torques left out (that motion is what a study tests the
controller on), on the robot each validation run was simulated with; or
(``--residual-by closed-loop-scene``) motions of the scene's own family, its torques at
other amplitudes, rates and time shifts (:func:`scene_family_motions`); the controller runs
with the default settings (:class:`jointplay.neural.control.imc_settings.ControllerSettings`) and
its step through CasADi (the same law as the compiled step, which is not built for each
candidate). The score of a candidate is the geometric mean over the runs of its error
divided by the linear base's (alpha = 0); a run that diverges scores infinity. The linear
base is kept unless another candidate earns its place: lower error than the base's on every
run, and a score at most 1 - :data:`MARGIN`. A smaller difference is within what moves
between motions of one family (the held-out scene then decides as often against the
network as for it), and the network would only add cost and risk to the controller.
Among the candidates that earn it, the lowest score wins; ties go to the twin, then to the
smaller weight.
"""

from __future__ import annotations

import math
import time
from collections.abc import Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import numpy as np

from jointplay.neural.model.narx import Narx

TWIN = "ARX twin"  # the candidate without scheduling signals
# A candidate replaces the linear base only with a score at most 1 - MARGIN (and a lower
# error on every run): the 2 % of the controller's goal against its linear base.
MARGIN = 0.02


@dataclass(frozen=True)
class ClosedLoopChoice:
    """What the closed-loop runs chose, and every figure behind it."""

    chosen: str  # a candidate's label: "alpha=0.25", or TWIN
    alpha: float  # the chosen residual weight (0 for the twin)
    score: dict[str, float]  # geometric mean of RMS |Δa| after settling / the base's
    rms: dict[str, list[float]]  # per candidate, per run: RMS |Δa| after settling, m/s²
    runs: list[str]  # each run's motion family and robot
    settle_s: float  # the "after settling" window's start, s (the latest over the runs)
    seconds: float
    motions: str = "validation runs"  # or "scene family" (scene_family_motions)
    margin: float = MARGIN  # what a candidate's score must beat the base's 1 by

    def summary(self) -> dict[str, Any]:
        return {"criterion": "RMS end-effector acceleration error after settling, in closed "
                             "loop on the validation runs' motions (geometric mean of the "
                             "ratio to the linear base; another candidate replaces the base "
                             "only below 1 - margin and better on every run)",
                "chosen": self.chosen, "alpha": self.alpha, "margin": self.margin,
                "best_other": self.best_other(),
                "score_by_candidate": {k: _finite(v) for k, v in self.score.items()},
                "rms_acceleration_after": {k: [_finite(x) for x in v]
                                           for k, v in self.rms.items()},
                "runs": self.runs, "motions": self.motions, "settle_s": self.settle_s,
                "seconds": self.seconds}


    def best_other(self) -> str | None:
        """The best-scoring candidate other than the linear base (None: there is none)."""
        others = {k: v for k, v in self.score.items() if k != label(0.0)}
        return min(others, key=lambda k: others[k]) if others else None


def earns_its_place(ratios: Sequence[float], margin: float = MARGIN) -> bool:
    """Whether a candidate with these per-run error ratios to the linear base replaces it:
    better on every run, and by at least ``margin`` in the geometric mean."""
    if not ratios or not all(math.isfinite(r) and r > 0 for r in ratios):
        return False
    return all(r < 1 for r in ratios) and math.exp(float(np.mean(np.log(ratios)))) <= 1 - margin


def _finite(value: float) -> float | None:
    """metrics.json holds no infinity: a diverged run is null."""
    return value if math.isfinite(value) else None


def label(alpha: float) -> str:
    return f"alpha={alpha:g}"


def validation_motions(scene: Any, config: Any, inner: Any,
                       limits: np.ndarray) -> list[tuple[str, Any]]:
    """(description, scene) of every validation run whose motion is not the scene's own: the
    validation trajectories' base torques on the robot they were simulated with."""
    from jointplay.neural.identify.trajectories import _plan

    out = []
    for task in _plan(scene, config, inner, limits):
        if task.split != "validation" or task.family == "scene":
            continue
        robot = task.description.get("robot")
        where = ", ".join(f"{k} {v:g}" for k, v in robot.items()) if robot else "scene robot"
        out.append((f"{task.family} ({where})", task.scene))
    return out


# Motions of the scene's family the closed-loop choice runs (--residual-by closed-loop-scene;
# how many: IdentifyConfig.scene_motions, by default SCENE_FAMILY_MOTIONS): each the scene's
# drive torques at one amplitude, rate and time shift
# (jointplay.neural.identify.trajectories.scene_family_torques) drawn from the identification's
# seed (a stream of its own, past the splits' 0-2).
SCENE_FAMILY_MOTIONS = 2
# The residual weights run in closed loop: every study of the best setting chose at most 0.5
# (seeds 11-20 at 30 µm and 0.1 mm; docs/control.md), and each weight costs a closed-loop
# run per motion.
CLOSED_LOOP_ALPHAS = (0.0, 0.25, 0.5)


def scene_family_motions(scene: Any, config: Any) -> list[tuple[str, Any]]:
    """(description, scene) of ``config.scene_motions`` motions like the scene's own:
    its drive torques, all joints alike, times a scale, at a rate and shifted in time (each
    drawn uniformly from the ranges above), on the scene's robot. Motions of the size and
    shape the controller is judged on, where the validation runs' multisines are far harsher;
    the scene's run itself (scale 1, rate 1, no shift) has probability zero."""
    from jointplay.neural.identify.trajectories import scene_family_torques
    from jointplay.neural.model.inner_loop import with_torques

    run_scene = scene.with_run(t_end=config.duration)
    out = []
    for i in range(config.scene_motions):
        rng = np.random.default_rng(np.random.SeedSequence([config.seed, 3, i]))
        torques = scene_family_torques(rng, scene, config.duration)
        f = torques[0]
        out.append((f"scene's torques x{f.scale:.3g} at {f.rate:.3g}x the rate, {f.shift:.3g} s "
                    "on (scene robot)", with_torques(run_scene, torques)))
    return out


def choose_in_closed_loop(network: Narx, base: Narx, twin: Narx | None,
                          motions: Sequence[tuple[str, Any]], alphas: Sequence[float],
                          settings: Any = None) -> tuple[Narx, ClosedLoopChoice]:
    """The candidate model with the best closed-loop score (see the module's text), and the
    figures; ``twin``: the ARX twin without scheduling signals, also the controllers'
    fallback (``base`` is when there is none)."""
    from jointplay.common.errors import DescriptionError
    from jointplay.neural.control.imc import compile_controller
    from jointplay.neural.control.imc_settings import ControllerSettings
    from jointplay.neural.model.twin import blend
    from jointplay.neural.study.comparison import NEURAL, compare, release_end
    from jointplay.neural.study.runs import study_engagement

    if not motions:
        raise DescriptionError("--validation", "choosing the residual weight in closed loop "
                               "needs a validation run whose motion is not the scene's own: "
                               "give --validation 2 or more")
    settings = settings or ControllerSettings()
    fallback = twin if twin is not None else base
    started = time.perf_counter()
    candidates: dict[str, Narx] = {}
    if twin is not None:
        candidates[TWIN] = twin
    for a in alphas:
        candidates[label(a)] = blend(network, base, a)
    rms: dict[str, list[float]] = {name: [] for name in candidates}
    settle_latest = 0.0
    for _, scene in motions:
        opened = compare(scene, base, settings, controllers=("open loop",), analyse=False)
        dt = scene.run.output_step
        settle = max(release_end(opened.runs["open loop"]), study_engagement(settings, dt))
        settle_latest = max(settle_latest, settle)
        for name, model in candidates.items():
            ctrl = compile_controller(model, settings, fallback=fallback if model is not
                                      fallback else None, compiled=False)
            result = compare(scene, model, settings, arx=fallback, controllers=(NEURAL,),
                             analyse=False, limit=opened.limit, transient=settle,
                             compiled={NEURAL: ctrl})
            run = result.runs[NEURAL]
            value = float(result.metrics[NEURAL]["rms_acceleration_after"])
            rms[name].append(value if not run.diverged and math.isfinite(value) else math.inf)
    # The geometric mean over the runs (each run's error counts by its ratio, not its size).
    mean_log = {name: _mean_log(values) for name, values in rms.items()}
    base_log = mean_log.get(label(0.0), math.inf)
    score = {name: (math.exp(v - base_log) if math.isfinite(v) and math.isfinite(base_log)
                    else math.inf) for name, v in mean_log.items()}
    # The base unless another earns its place; among those, ties go to the simpler model:
    # the twin, then the smaller weight.
    order = list(candidates)
    base_rms = rms.get(label(0.0), [])
    earned = [n for n in order if n != label(0.0) and base_rms and earns_its_place(
        [v / b if b > 0 else math.inf for v, b in zip(rms[n], base_rms, strict=True)])]
    chosen = min(earned, key=lambda n: (mean_log[n], order.index(n))) if earned \
        else label(0.0)
    alpha = 0.0 if chosen == TWIN else float(chosen.split("=")[1])
    return candidates[chosen], ClosedLoopChoice(
        chosen, alpha, score, rms, [d for d, _ in motions], round(settle_latest, 9),
        time.perf_counter() - started)


def choose_residual(scene: Any, config: Any, inner: Any, limits: np.ndarray, network: Narx,
                    base: Narx, twin: Narx | None) -> tuple[Narx, ClosedLoopChoice]:
    """The closed-loop choice identification hands in
    (:data:`jointplay.neural.identify.pipeline.ClosedLoopChooser`): the candidates run on the
    validation runs' motions, or (``residual_by = "closed-loop-scene"``) on the scene's
    family."""
    family = config.residual_by == "closed-loop-scene"
    motions = (scene_family_motions(scene, config) if family
               else validation_motions(scene, config, inner, limits))
    model, closed = choose_in_closed_loop(network, base, twin, motions, CLOSED_LOOP_ALPHAS)
    return model, replace(closed, motions="scene family") if family else closed


def identify_model(scene: Any, out: Path, config: Any, quiet: bool = False) -> dict[str, Any]:
    """:func:`jointplay.neural.identify.pipeline.identify` with the closed-loop choice of the
    residual weight at hand (used where ``config.residual_by`` asks for it)."""
    from jointplay.neural.identify.pipeline import identify

    return identify(scene, out, config, quiet, closed_loop=choose_residual)


def _mean_log(values: Sequence[float]) -> float:
    """Mean of the logarithms; infinity when a run diverged (or had no error to take)."""
    if not values or not all(math.isfinite(v) and v > 0 for v in values):
        return math.inf
    return float(np.mean(np.log(values)))


__all__ = ["CLOSED_LOOP_ALPHAS", "MARGIN", "SCENE_FAMILY_MOTIONS", "TWIN", "ClosedLoopChoice",
           "choose_in_closed_loop", "choose_residual", "earns_its_place", "identify_model",
           "label", "scene_family_motions", "validation_motions"]
