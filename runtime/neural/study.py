"""Statistics, not one run: the controllers over training seeds, trajectories and clearances.

``jointplay control-study`` identifies a model per seed (and per clearance size), then runs the
baselines once per case and both internal-model controllers once per case and seed. A case is
a trajectory and what the loop is exposed to:

- ``scene``: the scene's torques;
- ``slow``, ``fast``: other frequencies and amplitudes (0.5 Hz at 1.25x, 2 Hz at 0.5x);
- ``offset``: two harmonics and a constant offset;
- ``disturbance``: the scene, and a torque step on the plant at 1 s that no model knows;
- ``noise``: the scene, with white noise on every signal the controllers measure;
- ``delay``: the scene, with one sample of actuator delay;
- ``clearance <c>``: the scene's trajectory on a robot whose clearance joints have radial
  clearance c, with models identified on that robot.

It reports the median and the worst seed of every metric per controller and case
(``study.md``, ``study.csv``), checks the goals, and plots the statistics (``study_*.png``).
Model folders are kept under ``OUT/models`` and reused when the command is run again; runs go
through a process pool (``--workers``).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.neural.control import (
    LINEAR,
    MODEL_BASED,
    NEURAL,
    LoopConditions,
    compare,
    load_twin,
    tip_errors,
)
from jointplay.neural.narx import MODEL_FILE, REJECTED_FILE, load_narx, robot_identity

BASELINES = ("open loop", "PD", "computed torque")
CASES = ("scene", "slow", "fast", "offset", "disturbance", "noise", "delay")
GOAL_METRICS = (("max_position", "max |Δp| [m]"),
                ("max_velocity_after", "max |Δv| after 50 ms [m/s]"),
                ("rms_acceleration_after", "RMS |Δa| after 50 ms [m/s²]"))
REPORTED = (*(k for k, _ in GOAL_METRICS), "max_velocity", "max_acceleration_after",
            "diverged", "guard_episodes", "fallback_samples", "input_bound_samples")
# Measurement noise, standard deviation per output kind: a 21-bit encoder's angle, its
# 1 ms difference for speeds, and comparable figures for the end effector.
NOISE = {"q": 3e-6, "dq": 4e-3, "tip_x": 1e-6, "tip_y": 1e-6, "tip_vx": 1e-3, "tip_vy": 1e-3,
         "tip_ax": 0.05, "tip_ay": 0.05}
PAPER = {"max_position": 2.4e-4, "max_velocity": 7.7e-3}


@dataclass(frozen=True)
class Case:
    name: str
    clearance: float  # m, radial, of every clearance joint
    torques: tuple[str, ...]  # expressions per driven joint
    conditions: LoopConditions


def case_list(scene: Any, names: Sequence[str], clearances: Sequence[float],
              nominal: float) -> list[Case]:
    text = [scene.torque_text.get(f"joint{j}", "0") for j in scene.robot.moving_joints]
    t_end = scene.run.t_end

    def scaled(factor: float, freq: float) -> tuple[str, ...]:
        return tuple(_retime(t, factor, freq) for t in text)
    out = []
    for name in names:
        cond = LoopConditions()
        torques = tuple(text)
        if name == "slow":
            torques = scaled(1.25, 0.5)
        elif name == "fast":
            torques = scaled(0.5, 2.0)
        elif name == "offset":
            torques = tuple(f"{0.15 * p:g} + 0.75*({t}) + {_retime(t, 0.25, 3.0)}"
                            for t, p in zip(text, _peaks(scene), strict=True))
        elif name == "disturbance":
            peaks = _peaks(scene)
            cond = LoopConditions(disturbance=tuple(0.05 * p for p in peaks),
                                  disturbance_time=min(1.0, 0.5 * t_end))
        elif name == "noise":
            cond = LoopConditions(noise=noise_levels(scene), seed=1)
        elif name == "delay":
            cond = LoopConditions(delay=1)
        out.append(Case(name, nominal, torques, cond))
    for c in clearances:
        if not math.isclose(c, nominal, rel_tol=1e-9):
            out.append(Case(f"clearance {c * 1e6:g} µm", c, tuple(text), LoopConditions()))
    return out


def _retime(text: str, factor: float, freq: float) -> str:
    """The torque expression at another amplitude and (for sin(2*pi*t) forms) frequency."""
    return f"{factor:g}*({text.replace('2*pi*t', f'2*pi*{freq:g}*t')})"


def _peaks(scene: Any) -> list[float]:
    t = np.linspace(0.0, scene.run.t_end, scene.run.n_outputs + 1)
    return [float(np.max(np.abs(f.numpy(t)))) for f in scene.torques]


def noise_levels(scene: Any) -> tuple[float, ...]:
    from jointplay.neural.identify import output_names

    names, _ = output_names(scene.robot.moving_joints)
    return tuple(NOISE.get(n, NOISE["dq" if n.startswith("dq") else "q"]) for n in names)


def case_scene(scene: Any, case: Case) -> Any:
    from jointplay.neural.identify import with_torques
    from jointplay.robot import with_parameters
    from jointplay.scene.expressions import parse_expression

    robot = scene.robot
    values = {}
    for j in robot.clearance_joints:
        values[f"joint{j}.journal_radius"] = robot.joints[j - 1].bearing_radius - case.clearance
    out = scene.with_robot(with_parameters(robot, values)) if values else scene
    torques = [parse_expression(t, field="torques", constants=scene.constants)
               for t in case.torques]
    out = with_torques(out, torques)
    return replace(out, torque_text={f"joint{j}": t for j, t in zip(
        scene.robot.moving_joints, case.torques, strict=True)})


def nominal_clearance(scene: Any) -> float:
    robot = scene.robot
    values = {robot.joints[j - 1].bearing_radius - robot.joints[j - 1].journal_radius
              for j in robot.clearance_joints}
    if len(values) != 1:
        raise DescriptionError("scene", "the study needs every clearance joint to have the same "
                               f"radial clearance; they have {sorted(values)}")
    return values.pop()


# ---- work units -------------------------------------------------------------------------------

_JOBS: list[Any] = []  # filled before the pool forks: workers read their job by index


def _run_unit(index: int) -> list[dict[str, Any]]:
    case, scene, model_dir, settings, limit = _JOBS[index]
    rows = []
    if model_dir is None:
        narx = None
        result = compare(scene, _dummy_model(scene), settings, controllers=BASELINES,
                         analyse=False, conditions=case.conditions)
        seed = -1
    else:
        narx = load_narx(model_dir)
        arx = load_twin(model_dir, narx)
        result = compare(scene, narx, settings, arx=arx, controllers=MODEL_BASED,
                         analyse=False, conditions=case.conditions, limit=limit)
        seed = int(narx.context["training"]["seed"])
    nj = len(scene.robot.moving_joints)
    for name, mt in result.metrics.items():
        row = {"case": case.name, "clearance_um": case.clearance * 1e6, "controller": name,
               "seed": seed, **{k: mt.get(k, math.nan) for k in REPORTED}}
        if name == "open loop":
            row["limit"] = 2.0 * float(np.max(tip_errors(result.runs[name], result.reference,
                                                         nj)["position"]))
        rows.append(row)
    return rows


def _dummy_model(scene: Any) -> Any:
    """The baselines need only the inner loop's gains: a model-shaped holder of them."""
    from types import SimpleNamespace

    from jointplay.neural.identify import DEFAULT_KD, DEFAULT_KP, output_names

    joints = list(scene.robot.moving_joints)
    names, _ = output_names(joints)
    return SimpleNamespace(
        context={"plant": {"inner_loop": {"joints": joints, "kp": [DEFAULT_KP] * len(joints),
                                          "kd": [DEFAULT_KD] * len(joints)}}},
        output_index=names.index)


def _pool_map(indices: list[int], workers: int, quiet: bool, label: str) -> list[Any]:
    from tqdm import tqdm

    out: list[Any] = []
    with tqdm(total=len(indices), disable=quiet, desc=label, unit="run") as bar:
        if workers <= 1:
            for i in indices:
                out.append(_run_unit(i))
                bar.update(1)
        else:
            import multiprocessing
            from concurrent.futures import ProcessPoolExecutor

            methods = multiprocessing.get_all_start_methods()
            context = multiprocessing.get_context("fork" if "fork" in methods else "spawn")
            with ProcessPoolExecutor(workers, mp_context=context) as pool:
                for rows in pool.map(_run_unit, indices):
                    out.append(rows)
                    bar.update(1)
    return out


def ensure_models(scene: Any, folder: Path, seeds: int, identify_args: dict[str, Any],
                  quiet: bool) -> list[Path]:
    """One identified model per seed (reused when its folder already holds one for this
    robot); rejected models are left out, and said so."""
    from jointplay.neural.identify import IdentifyConfig, ModelRejected, identify

    out = []
    for seed in range(seeds):
        path = folder / f"seed{seed}"
        ok = (path / MODEL_FILE).is_file() and load_narx(path).context.get("robot", {}).get(
            "robot_hash") == robot_identity(scene.robot)["robot_hash"]
        if not ok and not (path / REJECTED_FILE).is_file():
            if not quiet:
                print(f"identifying {path} ...", flush=True)
            try:
                identify(scene, path, IdentifyConfig(seed=seed, **identify_args), quiet=True)
            except ModelRejected as err:
                if not quiet:
                    print(f"  {err}")
        if (path / MODEL_FILE).is_file():
            out.append(path)
        elif not quiet:
            print(f"  seed {seed}: no usable model (rejected by identify), left out")
    return out


# ---- summary ----------------------------------------------------------------------------------

def summarise(rows: list[dict[str, Any]]) -> dict[tuple[str, str], dict[str, Any]]:
    """(case, controller) -> count, and median and worst of every metric over seeds."""
    groups: dict[tuple[str, str], list[dict[str, Any]]] = {}
    for row in rows:
        groups.setdefault((row["case"], row["controller"]), []).append(row)
    out = {}
    for key, items in groups.items():
        stats: dict[str, Any] = {"runs": len(items)}
        for metric in REPORTED:
            values = np.array([r[metric] for r in items], dtype=float)
            stats[f"median_{metric}"] = float(np.median(values))
            stats[f"worst_{metric}"] = float(np.max(values))
        out[key] = stats
    return out


def goal_checks(summary: dict[tuple[str, str], dict[str, Any]], cases: list[Case]
                ) -> list[str]:
    lines = []
    first = cases[0].name
    neural, pd, linear, ol = ((first, n) for n in (NEURAL, "PD", LINEAR, "open loop"))
    if neural in summary and pd in summary:
        s, p = summary[neural], summary[pd]
        diverged = sum(summary[(c.name, n)]["worst_diverged"] > 0 for c in cases
                       for n in MODEL_BASED if (c.name, n) in summary)
        lines.append(f"- runs diverged over all cases: {diverged or 'none'}"
                     f" ({s['runs']} seeds)")
        for key, label in GOAL_METRICS:
            met = s[f"worst_{key}"] < p[f"median_{key}"]
            lines.append(f"- {first}: neural IMC worst seed {s[f'worst_{key}']:.3g} vs PD "
                         f"{p[f'median_{key}']:.3g} on {label}: "
                         f"{'beats PD' if met else 'does NOT beat PD'}")
        for key, label in GOAL_METRICS:
            if linear in summary:
                a = summary[linear][f"median_{key}"]
                n = s[f"median_{key}"]
                verdict = ("beats" if n < 0.98 * a else "matches (within 2 %)"
                           if n <= 1.02 * a else "is WORSE than")
                lines.append(f"- {first}: neural IMC median {n:.3g} {verdict} ARX-IMC median "
                             f"{a:.3g} on {label}")
        if ol in summary:
            ratio = summary[ol]["median_rms_acceleration_after"] / \
                s["median_rms_acceleration_after"]
            lines.append(f"- {first}: paper figures: median max |Δp| "
                         f"{s['median_max_position']:.3g} m (paper 2.4e-4), median max |Δv| "
                         f"after 50 ms {s['median_max_velocity_after']:.3g} m/s (paper 7.7e-3;"
                         f" over the whole run {s['median_max_velocity']:.3g}, the journals' "
                         f"fall), RMS |Δa| after 50 ms reduced {ratio:.3g}x from the open loop "
                         "(paper: tenfold)")
    for c in cases[1:]:
        worse = []
        for key, label in GOAL_METRICS:
            ns, ps = summary.get((c.name, NEURAL)), summary.get((c.name, "PD"))
            if ns and ps and ns[f"worst_{key}"] > 1.1 * ps[f"median_{key}"]:
                worse.append(f"{label} {ns[f'worst_{key}']:.3g} vs PD "
                             f"{ps[f'median_{key}']:.3g} "
                             f"({ns[f'worst_{key}'] / ps[f'median_{key}']:.2g}x)")
        lines.append(f"- {c.name}: neural IMC worst seed "
                     + ("within 10 % of PD or better on every metric" if not worse
                        else "worse than PD by more than 10 %: " + "; ".join(worse)))
    return lines


def summary_table(summary: dict[tuple[str, str], dict[str, Any]], cases: list[Case]) -> str:
    head = ("| case | controller | runs | " + " | ".join(
        f"{label} median | worst" for _, label in GOAL_METRICS)
        + " | diverged | guard episodes (median, worst) |")
    lines = [head, "|---|---|---|" + "---|---|" * len(GOAL_METRICS) + "---|---|"]
    for c in cases:
        for name in (*BASELINES, LINEAR, NEURAL):
            s = summary.get((c.name, name))
            if not s:
                continue
            cells = [f"{s[f'median_{k}']:.3g} | {s[f'worst_{k}']:.3g}" for k, _ in GOAL_METRICS]
            lines.append(f"| {c.name} | {name} | {s['runs']} | " + " | ".join(cells)
                         + f" | {'YES' if s['worst_diverged'] > 0 else 'no'} | "
                         f"{s['median_guard_episodes']:g}, "
                         f"{s['worst_guard_episodes']:g} |")
    return "\n".join(lines)


def plot_study(rows: list[dict[str, Any]], cases: list[Case], folder: Path) -> list[Path]:
    from jointplay.neural.control_plots import COLORS, figure, save

    names = (*BASELINES, LINEAR, NEURAL)
    fig, axes = figure(len(GOAL_METRICS), 1, max(10, 1.6 * len(cases)), 10, sharex=True)
    width = 0.8 / len(names)
    rng = np.random.default_rng(0)
    for row_i, (key, label) in enumerate(GOAL_METRICS):
        ax = axes[row_i, 0]
        for ci, case in enumerate(cases):
            for ni, name in enumerate(names):
                values = np.array([r[key] for r in rows if r["case"] == case.name
                                   and r["controller"] == name], dtype=float)
                if values.size == 0:
                    continue
                x = ci + (ni - (len(names) - 1) / 2) * width
                jitter = rng.uniform(-0.25, 0.25, values.size) * width
                ax.scatter(x + jitter, values, s=9, color=COLORS.get(name, "C5"), alpha=0.7,
                           label=name if ci == 0 else None)
                ax.hlines(np.median(values), x - 0.45 * width, x + 0.45 * width,
                          color=COLORS.get(name, "C5"), lw=2)
        ax.set_yscale("log")
        ax.set_ylabel(label)
        ax.grid(True, which="both", axis="y", alpha=0.3)
    axes[-1, 0].set_xticks(range(len(cases)), [c.name for c in cases], rotation=20)
    fig.suptitle("Controllers over training seeds, trajectories and clearances (dots: seeds; "
                 "bars: medians; baselines do not depend on the seed)")
    fig.legend(*axes[0, 0].get_legend_handles_labels(), loc="outside lower center", ncols=5)
    return [save(fig, folder / "study_errors.png")]


__all__ = ["CASES", "Case", "case_list", "case_scene", "goal_checks", "summarise"]
