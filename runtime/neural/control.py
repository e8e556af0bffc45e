"""Closed loops on the clearance robot: the internal-model controllers, their baselines, metrics.

Controllers, each against the ideal-joint robot's motion under the scene's torques:

- open loop: the scene's torques only;
- PD: the inner loop alone;
- computed torque with the ideal-joint model;
- ARX-IMC: the internal-model law with the linear ARX twin inside;
- neural IMC: the same law with the NARX network inside, guarded (see jointplay.neural.imc), the ARX
  twin as its fallback.

A run is declared diverged when its end-effector error leaves a bound (by default twice the
open loop's largest error: doing nothing does better) or the plant cannot be integrated; it
stops there. The stability verdict printed by ``jointplay control`` rests on the realised runs
(bounded or not, and how often the guard acted), with the linearisations (at the nominal
equilibrium and at states visited along the run) as supporting evidence.
"""

from __future__ import annotations

import json
import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from jointplay.common.errors import DescriptionError, SimulationError
from jointplay.common.files import atomic_path
from jointplay.neural.imc import (
    FLAGS,
    Controller,
    ControllerSettings,
    _inner_gains,
    build_step,
    compile_controller,
    default_tracked,
    generate_c,
    horizon_gain,
    local_spectral_radii,
    nominal_spectral_radius,
    per_call_us,
    resolve_settings,
)
from jointplay.neural.narx import ARX_FILE, Narx, load_narx

DEFAULT_TRANSIENT = 0.05  # s: journals settling from e = 0, reported separately
NEURAL, LINEAR = "neural IMC", "ARX-IMC"
CONTROLLERS = ("open loop", "PD", "computed torque", LINEAR, NEURAL)
MODEL_BASED = (LINEAR, NEURAL)
DIVERGENCE_FACTOR = 2.0  # x the open loop's largest tip error
EXIT_DIVERGED = 3


# ---- closed loop ------------------------------------------------------------------------------

@dataclass
class Run:
    """One closed-loop (or open-loop) run: absolute outputs and the torque added.

    A diverged run stops where it diverged: its arrays are shorter than the reference."""

    name: str
    t: np.ndarray
    y: np.ndarray
    tau: np.ndarray  # (N+1, nu) torque added to the scene's from each sample (last row 0)
    v: np.ndarray  # the outer loop's part (internal-model controllers), else zeros
    impacts: int
    seconds: float
    diverged: str = ""  # empty, or where and why the run was stopped
    flags: np.ndarray = field(default_factory=lambda: np.zeros((0, len(FLAGS))))
    states: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)))  # controller states
    # The end effector's acceleration between samples (SUBSTEPS points per sample period,
    # (t_k, t_k+1]): times and (x, y) rows; empty when the plant gives no dense output.
    dense_t: np.ndarray = field(default_factory=lambda: np.zeros(0))
    dense_acceleration: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))

    @property
    def guard_counts(self) -> dict[str, int]:
        """Samples on which each guard flag was raised; 'episodes' counts distinct
        interventions (the network distrusted after having been trusted)."""
        if self.flags.size == 0:
            return {}
        out = {name: int(np.sum(self.flags[:, i] > 0.5)) for i, name in enumerate(FLAGS)}
        distrusted = self.flags[:, 0] > 0.5
        out["episodes"] = int(np.sum(distrusted[1:] & ~distrusted[:-1]) + distrusted[0])
        return out


Law = Callable[[int, np.ndarray], np.ndarray]


@dataclass(frozen=True)
class LoopConditions:
    """What the loop is exposed to beyond the scene: an unknown torque step on the plant,
    noise on every measured signal the controllers see, and a delay of the actuators."""

    disturbance: tuple[float, ...] = ()  # N m per driven joint, from disturbance_time on
    disturbance_time: float = 1.0
    noise: tuple[float, ...] = ()  # standard deviation per output (plant units); () none
    delay: int = 0  # samples between a law's output and the actuator
    seed: int = 0


def run_loop(scene: Any, reference: np.ndarray, law: Law, name: str,
             clearance_model: Any | None = None, *, limit: float = math.inf,
             conditions: LoopConditions = LoopConditions(), substeps: int = 1) -> Run:
    """Step the scene's clearance robot with ``law(k, y)`` added to the scene's torques.

    ``limit``: the run stops, marked diverged, once the end-effector position error exceeds
    it (m), as it does when the plant can no longer be integrated. ``substeps`` > 1 (``bdf``
    plants) also records the end effector's acceleration at that many points per sample."""
    from jointplay.neural.identify import measure
    from jointplay.sim import Stepper

    stepper = Stepper(scene, model=clearance_model, substeps=substeps)
    joints = scene.robot.moving_joints
    index = [stepper.model.coordinates.index(f"q{j}") for j in joints]
    n = scene.run.n_outputs
    dt = scene.run.output_step
    nj = len(joints)
    y = np.zeros_like(reference)
    tau = np.zeros((n + 1, nj))
    applied = [np.zeros(nj)] * conditions.delay
    rng = np.random.default_rng(conditions.seed)
    noise = np.asarray(conditions.noise, dtype=float) if conditions.noise else None
    dist = np.asarray(conditions.disturbance, dtype=float) if conditions.disturbance else None
    tip = slice(2 * nj, 2 * nj + 2)
    diverged = ""
    last = n
    start = time.perf_counter()
    for k in range(n + 1):
        y[k] = measure(stepper, index)
        error = float(np.linalg.norm(y[k, tip] - reference[k, tip]))
        if not np.all(np.isfinite(y[k])) or error > limit:
            diverged = (f"end-effector error {error:.3g} m at t = {k * dt:.3f} s exceeds the "
                        f"divergence bound {limit:.3g} m")
            last = k
            break
        if k == n:
            break
        seen = y[k] + rng.normal(0.0, noise) if noise is not None else y[k]
        tau[k] = law(k, seen)
        out = tau[k]
        if conditions.delay:
            applied.append(tau[k])
            out = applied.pop(0)
        if dist is not None and k * dt >= conditions.disturbance_time - 1e-12:
            out = out + dist
        try:
            stepper.step(out)
        except SimulationError as err:
            diverged = f"the plant could not be integrated: {err}"
            last = k
            break
    keep = slice(0, last + 1)
    t = np.arange(n + 1) * dt
    dense_t, dense_a = stepper.dense_tip_acceleration()
    return Run(name, t[keep], y[keep], tau[keep], np.zeros_like(tau[keep]),
               len(stepper.impacts), time.perf_counter() - start, diverged,
               dense_t=dense_t, dense_acceleration=dense_a)


def imc_law(ctrl: Controller, reference: np.ndarray, tau_ff: np.ndarray,
            log: dict[str, list[np.ndarray]]) -> Law:
    """The compiled internal-model step as a law; logs v, the prediction, flags, states.

    For the first ``settings.engage`` seconds the outer loop waits (v = 0, the inner PD
    alone, within the actuator limits); it then starts its internal models from the last
    measured deviations. The models were identified without that start-up (the journals
    falling from the centred start onto their bearings), and acting on it with them drove v
    to 0.42 N m and left the journals bouncing well past it (docs/control.md)."""
    state: list[np.ndarray] = []
    s = ctrl.settings
    engage = round((s.engage or 0.0) / ctrl.model.sample_time)
    q, dq, kp, kd = _inner_gains(ctrl.model)
    limit = np.asarray(s.torque_limit, dtype=float)
    nu, ny = ctrl.model.n_inputs, ctrl.model.n_outputs

    past: list[np.ndarray] = []  # measured deviations while waiting, newest first

    def law(k: int, y: np.ndarray) -> np.ndarray:
        dev = y - reference[k]
        if k <= engage:
            # The models start from the measured history (v was zero), as in training.
            state[:] = [ctrl.initial_state(dev, np.array(past) if past else None)]
            past.insert(0, dev)
            del past[4:]
        log["states"].append(state[0])
        if k < engage:
            inner = -kp * dev[q] - kd * dev[dq] if q else np.zeros(nu)
            log["v"].append(np.zeros(nu))
            log["y_pred"].append(np.zeros(ny))
            log["flags"].append(np.zeros(len(FLAGS)))
            return np.asarray(np.clip(tau_ff[k] + inner, -limit, limit) - tau_ff[k])
        tau, nxt, v, pred = ctrl.step(y, reference[k], tau_ff[k], state[0])
        state[0] = nxt
        log["v"].append(v)
        log["y_pred"].append(pred)
        log["flags"].append(ctrl.last_flags)
        return tau
    return law


def pd_law(narx: Narx, reference: np.ndarray, kp: Sequence[float] = (),
           kd: Sequence[float] = ()) -> Law:
    """PD on the moving joints around the reference (default: the inner loop's gains)."""
    q, dq, kp0, kd0 = _inner_gains(narx)
    p_gain = np.asarray(kp, dtype=float) if len(kp) else kp0
    d_gain = np.asarray(kd, dtype=float) if len(kd) else kd0

    def law(k: int, y: np.ndarray) -> np.ndarray:
        dev = y - reference[k]
        return np.asarray(-p_gain * dev[q] - d_gain * dev[dq])
    return law


def computed_torque_law(scene: Any, ideal: Any, reference: np.ndarray, omega: float,
                        zeta: float) -> Law:
    """Computed torque with the ideal-joint model: tau = M(q)(qdd_r + kd e' + kp e) - f0(q,
    qdot); the scene's torque at the sample is subtracted because the stepper adds it."""
    from jointplay.scene.definition import ideal_counterpart
    from jointplay.sim import load_scene_model

    model = load_scene_model(scene, ideal=True)
    p = np.asarray(ideal_counterpart(scene.robot).parameter_values(), dtype=float)
    nj = len(scene.robot.moving_joints)
    no_contact = np.zeros(0)
    zero = np.zeros(nj)
    kp, kd = omega ** 2, 2 * zeta * omega
    qdd_r = ideal.udot
    tau_scene = ideal.tau

    def law(k: int, y: np.ndarray) -> np.ndarray:
        q, qd = y[:nj], y[nj:2 * nj]
        e, ed = reference[k, :nj] - q, reference[k, nj:2 * nj] - qd
        x = np.concatenate([q, qd])
        a = qdd_r[k] + kd * ed + kp * e
        f0 = model.forcing(x, zero, p, no_contact)
        b = np.column_stack([model.forcing(x, unit, p, no_contact) - f0
                             for unit in np.eye(nj)])  # f is affine in the torques
        tau = np.linalg.solve(b, model.mass_matrix(q, p) @ a - f0)
        return np.asarray(tau - tau_scene[k])
    return law


# ---- metrics ----------------------------------------------------------------------------------

METRICS = ("position", "velocity", "acceleration")
_SLICES = {"position": slice(0, 2), "velocity": slice(2, 4), "acceleration": slice(4, 6)}


def tip_errors(run: Run, reference: np.ndarray, nj: int) -> dict[str, np.ndarray]:
    """|end-effector error| per sample (Euclidean norm over x, y) for each quantity."""
    base = 2 * nj
    ref = reference[: run.y.shape[0]]
    return {k: np.linalg.norm(run.y[:, base + s.start: base + s.stop]
                              - ref[:, base + s.start: base + s.stop], axis=1)
            for k, s in _SLICES.items()}


GUARD_METRICS = {"guard_episodes": "episodes", "distrusted_samples": "model_distrusted",
                 "fallback_samples": "on_fallback_model", "inner_only_samples": "inner_loop_only",
                 "input_bound_samples": "input_at_trust_bound"}


def dense_acceleration_error(run: Run, dense_reference: np.ndarray) -> np.ndarray:
    """|end-effector acceleration error| at the run's dense points; ``dense_reference`` is the
    reference's acceleration on the same grid from t = 0 (row i at i T / SUBSTEPS)."""
    n = run.dense_t.size
    return np.linalg.norm(run.dense_acceleration - dense_reference[1: n + 1], axis=1)


def run_metrics(run: Run, reference: np.ndarray, nj: int, transient: int,
                dense_reference: np.ndarray | None = None) -> dict[str, float]:
    """Maxima and RMS of the end-effector errors (whole run and after ``transient`` samples),
    the largest added torque, impacts, whether the run diverged and the guard's counts.

    With ``dense_reference`` and a run that recorded its acceleration between samples, the
    acceleration metrics are taken over those points (the RMS a time average), the others at
    the samples."""
    err = tip_errors(run, reference, nj)
    out: dict[str, float] = {}
    dense = dense_reference is not None and run.dense_t.size > 0
    for k, e in err.items():
        if k == "acceleration" and dense:
            assert dense_reference is not None
            substeps = round(run.dense_t.size / max(1, run.y.shape[0] - 1))
            after_k = transient * substeps  # the first point after the transient's end
            e = dense_acceleration_error(run, dense_reference)
            after = e[after_k:] if e.size > after_k else e
        else:
            after = e[transient:] if e.size > transient else e
        out[f"max_{k}"] = float(np.max(e))
        out[f"max_{k}_after"] = float(np.max(after))
        out[f"rms_{k}"] = float(np.sqrt(np.mean(e ** 2)))
        out[f"rms_{k}_after"] = float(np.sqrt(np.mean(after ** 2)))
    out["max_torque_added"] = float(np.max(np.abs(run.tau)))
    out["impacts"] = float(run.impacts)
    out["diverged"] = 1.0 if run.diverged else 0.0
    counts = run.guard_counts
    for key, name in GUARD_METRICS.items():
        out[key] = float(counts.get(name, 0))
    return out


def metrics_table(metrics: dict[str, dict[str, float]], transient_s: float) -> str:
    """Markdown table: every controller side by side, and the open-loop / controller ratio."""
    cols = [("max_position", "max \\|Δp\\| [m]"), ("max_velocity", "max \\|Δv\\| [m/s]"),
            ("max_acceleration", "max \\|Δa\\| [m/s²]"),
            ("rms_acceleration", "RMS \\|Δa\\| [m/s²]")]
    ms = f"{transient_s * 1e3:g} ms"
    head = ("| controller | " + " | ".join(f"{label}" for _, label in cols)
            + f" | after {ms}: max \\|Δv\\| | max \\|Δa\\| | RMS \\|Δa\\| | impacts |")
    lines = [head, "|---" * (len(cols) + 5) + "|"]
    base = metrics.get("open loop")
    for name, mt in metrics.items():
        cells = [f"{mt[k]:.3g}" for k, _ in cols]
        cells += [f"{mt['max_velocity_after']:.3g}", f"{mt['max_acceleration_after']:.3g}",
                  f"{mt['rms_acceleration_after']:.3g}", f"{mt['impacts']:.0f}"]
        label = f"{name} (DIVERGED)" if mt.get("diverged") else name
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    if base is not None:
        for name, mt in metrics.items():
            if name == "open loop":
                continue
            keys = [k for k, _ in cols] + ["max_velocity_after", "max_acceleration_after",
                                            "rms_acceleration_after"]
            cells = [f"{base[k] / mt[k]:.3g}x" if mt[k] > 0 else "-" for k in keys]
            lines.append(f"| reduction, {name} | " + " | ".join(cells) + " | |")
    return "\n".join(lines)


# ---- the whole comparison -----------------------------------------------------------------

@dataclass
class Comparison:
    runs: dict[str, Run]
    reference: np.ndarray
    metrics: dict[str, dict[str, float]]
    transient: int
    limit: float  # divergence bound on the tip error, m
    controllers: dict[str, Controller] = field(default_factory=dict)
    per_call_us: dict[str, float] = field(default_factory=dict)
    nominal_radius: dict[str, float] = field(default_factory=dict)
    local_radius: dict[str, np.ndarray] = field(default_factory=dict)
    tau_ff: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)))
    # the reference's end-effector acceleration every T / SUBSTEPS from t = 0
    dense_reference: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))

    @property
    def controller(self) -> Controller:
        """The neural controller (or the only internal-model controller there is)."""
        return self.controllers.get(NEURAL) or next(iter(self.controllers.values()))


def compare(scene: Any, narx: Narx, settings: ControllerSettings, *, arx: Narx | None = None,
            transient: float = DEFAULT_TRANSIENT, ct_omega: float = 15.0,
            ct_zeta: float = 0.2, pd_kp: Sequence[float] = (), pd_kd: Sequence[float] = (),
            controllers: Sequence[str] = CONTROLLERS, quiet: bool = True,
            analyse: bool = True, conditions: LoopConditions = LoopConditions(),
            limit: float | None = None, divergence_factor: float = DIVERGENCE_FACTOR,
            compiled: dict[str, Controller] | None = None,
            plant_tolerance: float | None = None) -> Comparison:
    """Run the scene with every controller against the ideal robot's motion.

    Without ``limit`` the open loop runs first and sets the divergence bound
    (``divergence_factor`` x its largest tip error). ``arx`` is the linear twin: the
    ARX-IMC's model and the neural controller's fallback (without it there is no ARX-IMC and
    the neural controller falls back to the inner loop alone). ``analyse`` also measures each
    compiled step's cost and its linearised loop's spectral radius (nominal, and along the
    run).
    """
    from jointplay.neural.identify import ideal_reference, reference_outputs
    from jointplay.neural.plant import PLANT_TOLERANCE, SUBSTEPS, control_plant
    from jointplay.sim import load_scene_model

    # One plant setting for every controller (jointplay.neural.plant); ``plant_tolerance`` only to
    # measure what that setting changes (benchmarks/control_plant.py).
    scene = control_plant(scene, plant_tolerance or PLANT_TOLERANCE)
    ideal = ideal_reference(scene)
    reference = reference_outputs(ideal)
    model = load_scene_model(scene)
    nj = len(scene.robot.moving_joints)
    names = [c for c in controllers if arx is not None or c != LINEAR]
    ctrls: dict[str, Controller] = dict(compiled or {})
    for name in names:
        if name == NEURAL and name not in ctrls:
            ctrls[name] = compile_controller(narx, settings, fallback=arx)
        elif name == LINEAR and name not in ctrls and arx is not None:
            ctrls[name] = compile_controller(arx, settings)
    runs: dict[str, Run] = {}
    if limit is None:
        names = ["open loop", *[c for c in names if c != "open loop"]]
    for name in names:
        log: dict[str, list[np.ndarray]] = {"v": [], "y_pred": [], "flags": [], "states": []}
        if name == "open loop":
            law: Law = lambda k, y: np.zeros(nj)  # noqa: E731
        elif name == "PD":
            law = pd_law(narx, reference, pd_kp, pd_kd)
        elif name == "computed torque":
            law = computed_torque_law(scene, ideal, reference, ct_omega, ct_zeta)
        elif name in ctrls:
            law = imc_law(ctrls[name], reference, ideal.tau, log)
        else:
            raise ValueError(f"unknown controller {name!r}")
        bound = math.inf if limit is None and name == "open loop" else (
            limit if limit is not None else divergence_factor * float(
                np.max(tip_errors(runs["open loop"], reference, nj)["position"])))
        run = run_loop(scene, reference, law, name, model, limit=bound, conditions=conditions,
                       substeps=SUBSTEPS)
        if log["v"]:
            n = run.y.shape[0]
            run.v[: min(n, len(log["v"]))] = np.array(log["v"])[:n]
            run.flags = np.array(log["flags"])[:n]
            run.states = np.array(log["states"])[:n]
        runs[name] = run
        if not quiet:
            note = f"; DIVERGED: {run.diverged}" if run.diverged else ""
            print(f"  {name}: {run.seconds:.1f} s, {run.impacts} impacts{note}", flush=True)
    if limit is None:
        limit = divergence_factor * float(np.max(tip_errors(runs["open loop"], reference,
                                                            nj)["position"]))
    k0 = max(0, round(transient / scene.run.output_step))
    dense_reference = ideal_reference(scene.with_run(
        output_step=scene.run.output_step / SUBSTEPS)).tip_acceleration
    metrics = {name: run_metrics(run, reference, nj, k0, dense_reference)
               for name, run in runs.items()}
    result = Comparison(runs, reference, metrics, k0, limit, ctrls, tau_ff=ideal.tau,
                        dense_reference=dense_reference)
    if analyse:
        for name, ctrl in ctrls.items():
            if name not in runs:
                continue
            result.per_call_us[name] = per_call_us(ctrl)
            states = runs[name].states
            picks = states[np.linspace(0, len(states) - 1, min(8, len(states))).astype(int)] \
                if len(states) else states
            nominal, local = stability_radii(ctrl, picks)
            result.nominal_radius[name] = nominal
            result.local_radius[name] = local
    return result


def stability_radii(ctrl: Controller, states: np.ndarray) -> tuple[float, np.ndarray]:
    """Nominal spectral radius and the radii at the given visited controller states."""
    return nominal_spectral_radius(ctrl), local_spectral_radii(ctrl, states)


MARGINAL = 1e-3  # a radius this close to 1 is an integrator the verdict cannot decide on


def verdict(name: str, run: Run, comparison: Comparison) -> tuple[str, bool]:
    """What can be said about the loop's stability, and whether it calls for a warning."""
    counts = run.guard_counts
    duration = float(run.t[-1]) if run.t.size else 0.0
    if run.diverged:
        return f"{name}: DIVERGED ({run.diverged}); the run was stopped", True
    parts: list[str] = []
    warn = False
    worse = run.y.shape[0] and comparison.metrics[name]["max_position"] > \
        comparison.limit / DIVERGENCE_FACTOR
    if counts.get("episodes", 0):
        warn = True
        parts.append(f"bounded over the {duration:g} s run only with the guard: the network was "
                     f"distrusted {counts['episodes']} time(s) ({counts['on_fallback_model']} "
                     f"samples on the ARX fallback, {counts['inner_loop_only']} with the inner "
                     "loop alone)")
    else:
        parts.append(f"bounded over the {duration:g} s run, no fallback")
    if counts.get("input_at_trust_bound", 0):
        warn = True
        parts.append(f"v held at the trust bound (training range) on "
                     f"{counts['input_at_trust_bound']} samples")
    if worse:
        warn = True
        parts.append("its largest tip error exceeds the open loop's")
    nominal = comparison.nominal_radius.get(name)
    local = comparison.local_radius.get(name)
    if nominal is not None:
        if nominal < 1 - MARGINAL:
            lin = f"nominal linearisation stable (spectral radius {nominal:.4f})"
        elif nominal <= 1 + MARGINAL:
            lin = (f"nominal linearisation marginal (spectral radius {nominal:.4f}, within "
                   f"{MARGINAL:g} of 1: an integrating mode the tracked outputs do not see; "
                   "undecided)")
        else:
            lin = f"nominal linearisation unstable (spectral radius {nominal:.4f})"
        if local is not None and local.size:
            lin += (f"; at {local.size} states along the run {np.min(local):.4f} to "
                    f"{np.max(local):.4f}")
            if np.max(local) > 1 + MARGINAL:
                lin += " (above 1 at some: stability beyond this run is not established)"
        parts.append(lin)
    return f"{name}: " + "; ".join(parts), warn


def write_runs(path: Path, comparison: Comparison, meta: dict[str, Any]) -> None:
    import h5py

    with atomic_path(path) as tmp, h5py.File(tmp, "w") as f:
        f.attrs["format"] = "jointplay-control"
        f.attrs["meta"] = json.dumps(meta, default=str)
        f.create_dataset("reference", data=comparison.reference)
        for name, run in comparison.runs.items():
            g = f.create_group(name)
            for key in ("t", "y", "tau", "v", "flags"):
                g.create_dataset(key, data=getattr(run, key))
            g.attrs["metrics"] = json.dumps(comparison.metrics[name])
            g.attrs["diverged"] = run.diverged
            g.attrs["flag_names"] = json.dumps(list(FLAGS))


# ---- the command ------------------------------------------------------------------------------

def test_case_scenes(model_dir: Path, scene: Any) -> list[tuple[str, Any]]:
    """Scenes driven by the base torques of the stored test trajectories."""
    from jointplay.neural.identify import Chirp, Multisine, read_datasets, with_torques
    from jointplay.scene.expressions import parse_expression
    from jointplay.scene.tables import TableColumn

    path = model_dir / "datasets.h5"
    if not path.is_file():
        raise DescriptionError("--test-cases", f"{path} is missing; the model folder has no "
                               "stored test trajectories (run `jointplay identify` again)")
    trajectories, meta = read_datasets(path)
    out = []
    for tr in (t for t in trajectories if t.split == "test"):
        torques: list[Any] = []
        for i, desc in enumerate(tr.description.get("base", [])):
            kind = desc.get("kind")
            if kind == "multisine":
                torques.append(Multisine(np.array(desc["amplitude"]), np.array(desc["frequency"]),
                                         np.array(desc["phase"])))
            elif kind == "chirp":
                torques.append(Chirp(desc["amplitude"], desc["f0"], desc["f1"],
                                     desc["duration"], desc["phase"]))
            elif kind == "steps":
                torques.append(TableColumn(f"joint{i}", np.array(desc["times"]),
                                           np.array(desc["values"])))
            else:
                torques.append(parse_expression(desc["text"], field="torques",
                                                constants=scene.constants))
        duration = float(tr.t[-1])
        out.append((f"test {tr.family}", with_torques(scene.with_run(t_end=duration), torques)))
    del meta
    return out


def load_twin(model_dir: Path, narx: Narx) -> Narx:
    """The ARX twin of a model folder: arx.json, or (folders written before it existed) a
    least-squares fit on the stored training runs, as identify makes it."""
    from dataclasses import replace

    if (model_dir / ARX_FILE).is_file():
        return load_narx(model_dir, filename=ARX_FILE)
    from jointplay.neural.identify import _segments, fit_arx, read_datasets

    path = model_dir / "datasets.h5"
    if not path.is_file():
        raise DescriptionError("--model", f"{model_dir} has neither {ARX_FILE} nor datasets.h5 "
                               "for the ARX baseline: run `jointplay identify` again")
    trajectories, _ = read_datasets(path)
    skip = max(0, round(narx.context.get("plant", {}).get("transient", DEFAULT_TRANSIENT)
                        / narx.sample_time))
    names = {"output_names": narx.output_names, "output_units": narx.output_units,
             "input_names": narx.input_names, "input_units": narx.input_units}
    arx = fit_arx(_segments([t for t in trajectories if t.split == "train"], skip), names,
                  narx.output_lags, narx.input_lags, narx.sample_time)
    return replace(arx, context=narx.context)


__all__ = ["CONTROLLERS", "LINEAR", "NEURAL", "Comparison", "Controller", "ControllerSettings",
           "LoopConditions", "Run", "build_step", "compare", "compile_controller",
           "computed_torque_law", "default_tracked", "generate_c", "horizon_gain", "load_twin",
           "metrics_table", "nominal_spectral_radius", "per_call_us",
           "resolve_settings", "run_loop", "run_metrics", "verdict"]
