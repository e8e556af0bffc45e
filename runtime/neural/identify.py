"""Neural identification of a clearance robot for the internal-model controller.

What is identified. Torque to joint angle is a double integration, and the fast dynamics of a
clearance joint (the journal flying across the clearance) sit far below one sample, so a
network that maps torque to angle directly is neither stable in free run nor invertible one
step ahead. The plant identified here is therefore the clearance robot under a fixed inner
loop: a PD on the moving joints around the ideal robot's motion, with the scene's torques as
feedforward. Its input is the torque v an outer loop adds to the PD's (``v2``, ``v3``, ...), and
its outputs are the deviations from the ideal robot of the moving joints' angles and speeds and
of the end effector's position, velocity and acceleration. The inner loop makes this plant
stable, and the deviations are the quantities the controller must drive to zero.

Data. Each trajectory drives the ideal robot with a base torque (the scene's own,
random-phase multisines, amplitude-modulated steps) to get a reference motion, and the
clearance robot, under the inner loop around that reference, with an added torque v of
amplitude-modulated pseudo-random steps (holds from one sample up, so the response within one
sample is identifiable) plus a random-phase multisine. Training, validation and test
trajectories are separate realisations; the test base torques include a family never used in
training (a swept sine). Everything is seeded.

Training (PyTorch, float64, CPU): one-step-ahead least squares (L-BFGS, full batch), then
simulation-error training on windows of the training trajectories (the controller runs the
model in free run), each phase stopped early on the validation loss. torch is imported inside
the training function only.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import math
import os
import shutil
import tempfile
import time
from collections.abc import Sequence
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path
from typing import Any

import casadi as ca
import numpy as np

from jointplay.common import interrupts
from jointplay.common.errors import DescriptionError, JointplayError
from jointplay.common.files import atomic_path, atomic_write_text, file_error, sweep_stale, temp_tag
from jointplay.neural.narx import (
    ARX_FILE,
    MODEL_FILE,
    REJECTED_FILE,
    Narx,
    fit_percent,
    nrmse,
    robot_identity,
    save_narx,
)
from jointplay.neural.twin import describe, judge, select_residual
from jointplay.scene.expressions import TimeFunction
from jointplay.scene.tables import TableColumn

DATASETS_FILE = "datasets.h5"
METRICS_FILE = "metrics.json"
REPORT_FILE = "report.md"
DATA_FORMAT = "jointplay-narx-data"
SPLITS = ("train", "validation", "test")
TRAIN_FAMILIES = ("scene", "multisine", "steps")
TEST_FAMILIES = ("chirp", "multisine", "steps")
# Inner-loop defaults. The derivative gain is bounded by the journal: out of contact a link
# turns about its own centre of mass, with an effective inertia ~50x smaller than when pinned,
# and a sampled derivative gain near that inertia / sample period makes the loop chatter.
DEFAULT_KP = 200.0  # N m/rad
DEFAULT_KD = 5.0  # N m s/rad
# Torque limit of each actuator, as a multiple of the scene's peak torque on that joint.
LIMIT_FACTOR = 2.5


class ModelRejected(JointplayError):
    """Identification finished but its model is worse than persistence or ARX on validation."""


# ---- excitation signals ---------------------------------------------------------------------

@dataclass(frozen=True, eq=False)
class Multisine:
    """sum_i a_i sin(2 pi f_i t + phi_i): a TimeFunction for scenes (numpy and CasADi)."""

    amplitude: np.ndarray
    frequency: np.ndarray
    phase: np.ndarray

    def numpy(self, t: float | np.ndarray) -> np.ndarray:
        times = np.asarray(t, dtype=float)
        arg = 2 * np.pi * self.frequency[:, None] * times.reshape(-1)[None, :] \
            + self.phase[:, None]
        return np.asarray(np.sum(self.amplitude[:, None] * np.sin(arg), axis=0),
                          dtype=float).reshape(times.shape)

    def casadi(self, t: Any) -> Any:
        out = 0.0 * t
        for a, f, p in zip(self.amplitude, self.frequency, self.phase, strict=True):
            out = out + float(a) * ca.sin(2 * math.pi * float(f) * t + float(p))
        return out

    def describe(self) -> dict[str, Any]:
        return {"kind": "multisine", "amplitude": self.amplitude.tolist(),
                "frequency": self.frequency.tolist(), "phase": self.phase.tolist()}


@dataclass(frozen=True, eq=False)
class Chirp:
    """A linear sine sweep from f0 to f1 Hz over ``duration`` s, of amplitude ``amplitude``."""

    amplitude: float
    f0: float
    f1: float
    duration: float
    phase: float = 0.0

    def _arg(self, t: Any) -> Any:
        rate = (self.f1 - self.f0) / self.duration
        return 2 * math.pi * (self.f0 * t + 0.5 * rate * t * t) + self.phase

    def numpy(self, t: float | np.ndarray) -> np.ndarray:
        times = np.asarray(t, dtype=float)
        return np.asarray(self.amplitude * np.sin(self._arg(times)), dtype=float)

    def casadi(self, t: Any) -> Any:
        return self.amplitude * ca.sin(self._arg(t))

    def describe(self) -> dict[str, Any]:
        return {"kind": "chirp", "amplitude": self.amplitude, "f0": self.f0, "f1": self.f1,
                "duration": self.duration, "phase": self.phase}


def random_multisine(rng: np.random.Generator, peak: float, f_low: float, f_high: float,
                     period: float, max_lines: int = 12) -> Multisine:
    """Random-phase multisine on harmonics of 1/period in [f_low, f_high], scaled to ``peak``."""
    base = 1.0 / period
    lines = np.arange(max(1, math.ceil(f_low / base)), math.floor(f_high / base) + 1) * base
    if lines.size > max_lines:
        lines = np.sort(rng.choice(lines, max_lines, replace=False))
    if lines.size == 0:
        lines = np.array([f_low])
    phase = rng.uniform(0.0, 2 * np.pi, lines.size)
    unit = Multisine(np.ones(lines.size), lines, phase)
    grid = np.linspace(0.0, period, 4001)
    scale = peak / max(float(np.max(np.abs(unit.numpy(grid)))), 1e-12)
    return Multisine(np.full(lines.size, scale), lines, phase)


def aprbs(rng: np.random.Generator, n: int, peak: float, hold_min: int,
          hold_max: int) -> np.ndarray:
    """Amplitude-modulated pseudo-random steps: uniform levels in [-peak, peak], held for a
    log-uniform number of samples in [hold_min, hold_max]."""
    out = np.zeros(n)
    k = 0
    while k < n:
        hold = round(math.exp(rng.uniform(math.log(hold_min), math.log(hold_max))))
        out[k:k + max(hold, 1)] = rng.uniform(-peak, peak)
        k += max(hold, 1)
    return out


def step_torque(rng: np.random.Generator, peak: float, duration: float, hold_min: float,
                hold_max: float, ramp: float, name: str) -> TableColumn:
    """Amplitude-modulated steps as a piecewise-linear table (``ramp`` s between levels)."""
    times, values = [0.0], [0.0]
    t = 0.0
    while t < duration:
        level = rng.uniform(-peak, peak)
        times += [t + ramp]
        values += [level]
        t += rng.uniform(hold_min, hold_max)
        times += [t]
        values += [level]
    return TableColumn(name, np.array(times), np.array(values))


# ---- the plant: clearance robot under the inner loop ----------------------------------------

@dataclass(frozen=True)
class InnerLoop:
    """PD on the moving joints around the reference motion: tau = -kp dq_err - kd d(dq)."""

    joints: tuple[int, ...]
    kp: tuple[float, ...]
    kd: tuple[float, ...]

    def torque(self, deviation: np.ndarray) -> np.ndarray:
        n = len(self.joints)
        return -np.asarray(self.kp) * deviation[:n] - np.asarray(self.kd) * deviation[n:2 * n]


def output_names(joints: Sequence[int]) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """Names and units of the plant's outputs (deviations from the ideal robot)."""
    names = [f"q{j}" for j in joints] + [f"dq{j}" for j in joints] + \
        ["tip_x", "tip_y", "tip_vx", "tip_vy", "tip_ax", "tip_ay"]
    units = ["rad"] * len(joints) + ["rad/s"] * len(joints) + \
        ["m", "m", "m/s", "m/s", "m/s^2", "m/s^2"]
    return tuple(names), tuple(units)


def output_increments(names: Sequence[str]) -> tuple[bool, ...]:
    """Angles, speeds, positions and velocities integrate the input: predicted as increments.
    Accelerations follow the torque directly: predicted as values."""
    return tuple(not n.startswith("tip_a") for n in names)


def input_names(joints: Sequence[int]) -> tuple[tuple[str, ...], tuple[str, ...]]:
    return tuple(f"v{j}" for j in joints), tuple("N m" for _ in joints)


def measure(stepper: Any, angle_index: Sequence[int]) -> np.ndarray:
    """The plant's outputs (absolute) at the stepper's current sample."""
    x = stepper.x
    n = stepper.model.n_coordinates
    ee = stepper.end_effector()
    return np.concatenate([x[list(angle_index)], x[[n + i for i in angle_index]],
                           ee["position"], ee["velocity"], ee["acceleration"]])


def reference_outputs(ideal: Any) -> np.ndarray:
    """The same outputs for a simulated ideal-joint robot (rows: samples)."""
    return np.hstack([ideal.q, ideal.u, ideal.tip_position, ideal.tip_velocity,
                      ideal.tip_acceleration])


def default_limits(scene: Any) -> np.ndarray:
    """Actuator torque limits: LIMIT_FACTOR x the scene's peak torque on each joint."""
    t = np.linspace(0.0, scene.run.t_end, scene.run.n_outputs + 1)
    peaks = np.array([float(np.max(np.abs(f.numpy(t)))) for f in scene.torques])
    if peaks.size == 0 or not np.all(peaks > 0):
        raise DescriptionError("--torque-limit", "the scene has no torque on some driven joint, "
                               "so no default actuator limit can be inferred; give one per "
                               "driven joint, e.g. --torque-limit 10,5 (N m)")
    return LIMIT_FACTOR * peaks


def with_torques(scene: Any, torques: Sequence[TimeFunction]) -> Any:
    """The scene with other drive torques (and texts saying where they came from)."""
    return replace(scene, torques=tuple(torques),
                   torque_text={f"joint{j}": "excitation" for j in scene.robot.moving_joints})


# ---- trajectories ---------------------------------------------------------------------------

@dataclass
class Trajectory:
    """One identification run, sampled every ``dt``: absolute outputs ``y``, the reference's
    ``r``, the added torque ``v`` (applied from each sample to the next), the base torque
    (feedforward) and the inner loop's torque."""

    split: str
    family: str
    seed: int
    t: np.ndarray
    y: np.ndarray
    r: np.ndarray
    v: np.ndarray
    tau_base: np.ndarray
    tau_inner: np.ndarray
    description: dict[str, Any] = field(default_factory=dict)

    @property
    def deviation(self) -> np.ndarray:
        return self.y - self.r


@dataclass
class _Task:
    split: str
    family: str
    seed: int
    scene: Any
    v: np.ndarray
    inner: InnerLoop
    description: dict[str, Any]


_MODELS: dict[str, Any] = {}


def _models(scene: Any) -> tuple[Any, Any]:
    from jointplay.sim import load_scene_model

    key = scene.robot.structure_hash()
    if key not in _MODELS:
        _MODELS[key] = (load_scene_model(scene), load_scene_model(scene, ideal=True))
    return _MODELS[key]


def ideal_reference(scene: Any, ideal_model: Any | None = None) -> Any:
    """The ideal-joint robot under the scene's torques: the motion the controller tracks."""
    from jointplay.scene.definition import ideal_counterpart
    from jointplay.sim import load_scene_model, simulate

    model = ideal_model or load_scene_model(scene, ideal=True)
    return simulate(scene.with_robot(ideal_counterpart(scene.robot)), model=model)


def run_task(task: _Task) -> Trajectory:
    """Simulate one identification trajectory (a worker's job)."""
    from jointplay.sim import Stepper

    clearance, ideal_model = _models(task.scene)
    ideal = ideal_reference(task.scene, ideal_model)
    r = reference_outputs(ideal)
    stepper = Stepper(task.scene, model=clearance)
    angle_index = [clearance.coordinates.index(f"q{j}") for j in task.inner.joints]
    n = task.scene.run.n_outputs
    y = np.zeros_like(r)
    tau_inner = np.zeros((n + 1, len(task.inner.joints)))
    for k in range(n + 1):
        y[k] = measure(stepper, angle_index)
        if k == n:
            break
        tau_inner[k] = task.inner.torque(y[k] - r[k])
        stepper.step(tau_inner[k] + task.v[k])
    return Trajectory(task.split, task.family, task.seed, ideal.t, y, r, task.v.copy(),
                      ideal.tau.copy(), tau_inner, task.description)


@dataclass(frozen=True)
class IdentifyConfig:
    """Everything that decides the data and the training (all seeded by ``seed``)."""

    duration: float = 2.0  # s per trajectory
    n_train: int = 12
    n_validation: int = 3
    n_test: int = 3
    output_lags: int = 2
    input_lags: int = 2
    hidden: tuple[int, ...] = (13, 14)
    seed: int = 0
    kp: tuple[float, ...] = ()  # empty: DEFAULT_KP on every moving joint
    kd: tuple[float, ...] = ()
    torque_limit: tuple[float, ...] = ()  # empty: LIMIT_FACTOR x the scene's peak torques
    base_fraction: float = 0.5  # peak of the base excitation torques, x the limit
    input_fraction: float = 0.03  # peak of the added-torque excitation, x the limit
    transient: float = 0.05  # s at the start of each trajectory left out (journals settling)
    linear_path: bool = True  # a linear direct path beside the hidden layers
    one_step_iterations: int = 60
    multi_step_iterations: int = 30
    window: int = 200  # samples per free-run training window
    patience: int = 8
    workers: int = 0  # 0: one per core, at most 4


def _plan(scene: Any, config: IdentifyConfig, inner: InnerLoop,
          limits: np.ndarray) -> list[_Task]:
    """Every trajectory's excitation, drawn from one seeded generator per trajectory."""
    dt = scene.run.output_step
    run_scene = scene.with_run(t_end=config.duration)
    n = run_scene.run.n_outputs
    tasks: list[_Task] = []
    counts = {"train": config.n_train, "validation": config.n_validation, "test": config.n_test}
    for s_index, split in enumerate(SPLITS):
        families = TEST_FAMILIES if split == "test" else TRAIN_FAMILIES
        for i in range(counts[split]):
            seed = int(np.random.SeedSequence([config.seed, s_index, i]).generate_state(1)[0])
            rng = np.random.default_rng(seed)
            family = families[i % len(families)]
            base: list[TimeFunction]
            if family == "scene":
                base = list(scene.torques)
            elif family == "multisine":
                band = (0.2, 4.0) if split == "test" else (0.2, 3.0)
                base = [random_multisine(rng, config.base_fraction * lim, *band,
                                         config.duration) for lim in limits]
            elif family == "steps":
                base = [step_torque(rng, config.base_fraction * lim, config.duration, 0.1, 0.4,
                                    0.01, f"joint{j}") for lim, j in zip(limits, inner.joints,
                                                                         strict=True)]
            else:  # chirp
                base = [Chirp(0.6 * config.base_fraction * lim, 0.2, 3.0, config.duration,
                              float(rng.uniform(0, 2 * np.pi))) for lim in limits]
            v = np.zeros((n + 1, len(limits)))
            for c, lim in enumerate(limits):
                peak = config.input_fraction * lim
                v[:n, c] = aprbs(rng, n, 0.6 * peak, 1, 100)
                v[:n, c] += random_multisine(rng, 0.4 * peak, 0.1, 10.0,
                                             config.duration).numpy(np.arange(n) * dt)
            description = {"base": [_describe(f) for f in base],
                           "added": "aprbs(1..100 samples) + multisine(0.1..10 Hz)",
                           "added_peak": (config.input_fraction * limits).tolist()}
            tasks.append(_Task(split, family, seed, with_torques(run_scene, base), v, inner,
                               description))
    return tasks


def _describe(f: TimeFunction) -> Any:
    if isinstance(f, (Multisine, Chirp)):
        return f.describe()
    if isinstance(f, TableColumn):
        return {"kind": "steps", "times": f.times.tolist(), "values": f.values.tolist()}
    return {"kind": "expression", "text": getattr(f, "text", repr(f))}


def collect(scene: Any, config: IdentifyConfig, inner: InnerLoop, limits: np.ndarray,
            quiet: bool = False) -> list[Trajectory]:
    """Simulate every planned trajectory, in parallel processes when there are cores."""
    from tqdm import tqdm

    tasks = _plan(scene, config, inner, limits)
    workers = config.workers or min(4, os.cpu_count() or 1)
    workers = max(1, min(workers, len(tasks)))
    _models(scene)  # compile (or load) once before any worker starts
    results: list[Trajectory] = []
    with tqdm(total=len(tasks), disable=quiet, unit="traj", desc="simulating") as bar:
        if workers == 1:
            for task in tasks:
                results.append(run_task(task))
                bar.update(1)
        else:
            import multiprocessing
            from concurrent.futures import ProcessPoolExecutor

            # fork where there is one: no re-import of the caller's main module, and the
            # compiled models are already loaded; workers use numpy and CasADi only.
            methods = multiprocessing.get_all_start_methods()
            context = multiprocessing.get_context("fork" if "fork" in methods else "spawn")
            # Workers leave Ctrl-C to this process, which stops them without waiting.
            pool = ProcessPoolExecutor(workers, mp_context=context,
                                       initializer=interrupts.ignore_in_child)
            try:
                for traj in pool.map(run_task, tasks):
                    results.append(traj)
                    bar.update(1)
            except BaseException:
                for process in list(getattr(pool, "_processes", {}).values()):
                    process.terminate()
                pool.shutdown(wait=False, cancel_futures=True)
                raise
            pool.shutdown()
    return results


# ---- datasets in HDF5 -----------------------------------------------------------------------

def write_datasets(path: Path, trajectories: Sequence[Trajectory], meta: dict[str, Any]) -> None:
    import h5py

    with atomic_path(path) as tmp, h5py.File(tmp, "w") as f:
        f.attrs["format"] = DATA_FORMAT
        f.attrs["format_version"] = 1
        f.attrs["meta"] = json.dumps(meta)
        f.attrs["doc"] = ("Identification trajectories, one group per split and run. y: plant "
                          "outputs (absolute), r: the ideal robot's, v: torque added to the "
                          "inner loop's from each sample to the next, tau_base: feedforward "
                          "(drives the ideal robot), tau_inner: the inner PD's torque.")
        for split in SPLITS:
            group = f.create_group(split)
            for i, tr in enumerate(t for t in trajectories if t.split == split):
                g = group.create_group(f"{i:03d}")
                for name in ("t", "y", "r", "v", "tau_base", "tau_inner"):
                    g.create_dataset(name, data=getattr(tr, name), compression="gzip",
                                     shuffle=True)
                g.attrs["family"] = tr.family
                g.attrs["seed"] = tr.seed
                g.attrs["description"] = json.dumps(tr.description)


def read_datasets(path: str | Path) -> tuple[list[Trajectory], dict[str, Any]]:
    import h5py

    path = Path(path)
    try:
        with h5py.File(path, "r") as f:
            if f.attrs.get("format") != DATA_FORMAT:
                raise DescriptionError("--model", f"{path}: not a jointplay identification "
                                       "dataset")
            meta = json.loads(f.attrs["meta"])
            out = []
            for split in SPLITS:
                for key in sorted(f[split]):
                    g = f[split][key]
                    arrays = {n: np.array(g[n]) for n in ("t", "y", "r", "v", "tau_base",
                                                          "tau_inner")}
                    out.append(Trajectory(split, str(g.attrs["family"]), int(g.attrs["seed"]),
                                          description=json.loads(g.attrs["description"]),
                                          **arrays))
    except (OSError, KeyError, ValueError) as err:
        raise DescriptionError("--model", f"{path}: cannot be read ({err}); the file is "
                               "corrupt: run `jointplay identify` again") from None
    return out, meta


# ---- training -------------------------------------------------------------------------------

def _segments(trajectories: Sequence[Trajectory], skip: int) -> list[tuple[np.ndarray,
                                                                          np.ndarray]]:
    return [(tr.deviation[skip:], tr.v[skip:]) for tr in trajectories]


def _regress(segments: Sequence[tuple[np.ndarray, np.ndarray]], na: int, nb: int,
             carry: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Regressors and targets (increments where ``carry`` is 1, values where 0)."""
    m = max(na, nb) - 1
    xs, ts = [], []
    for d, u in segments:
        n = d.shape[0]
        rows = [d[m - i: n - 1 - i] for i in range(na)] + [u[m - i: n - 1 - i] for i in range(nb)]
        xs.append(np.concatenate(rows, axis=1))
        ts.append(d[m + 1:] - carry * d[m: n - 1])
    return np.vstack(xs), np.vstack(ts)


def _least_squares(z: np.ndarray, t: np.ndarray, ridge: float) -> np.ndarray:
    a = np.hstack([z, np.ones((z.shape[0], 1))])
    return np.linalg.solve(a.T @ a + ridge * np.eye(a.shape[1]), a.T @ t)


def fit_arx(segments: Sequence[tuple[np.ndarray, np.ndarray]], names: dict[str, Any],
            na: int, nb: int, dt: float, ridge: float = 1e-9) -> Narx:
    """The linear ARX baseline on the same regressor, by least squares (a network with no
    hidden layer, so it runs through the same code)."""
    carry = np.asarray(output_increments(names["output_names"]), dtype=float)
    x, t = _regress(segments, na, nb, carry)
    mu, sigma = x.mean(0), _scale(x.std(0))
    tm, ts = t.mean(0), _scale(t.std(0))
    theta = _least_squares((x - mu) / sigma, (t - tm) / ts, ridge)
    return Narx(weights=(theta[:-1].T.copy(),), biases=(theta[-1].copy(),), regressor_mean=mu,
                regressor_scale=sigma, increment_mean=tm, increment_scale=ts,
                output_scale=_scale(np.vstack([d for d, _ in segments]).std(0)),
                output_lags=na, input_lags=nb, sample_time=dt,
                increment=tuple(bool(c) for c in carry), **names)


def _scale(std: np.ndarray) -> np.ndarray:
    """Standard deviations floored so that constant columns normalise to themselves."""
    return np.where(std > 1e-300, std, 1.0)


def train_narx(train: Sequence[Trajectory], validation: Sequence[Trajectory],
               config: IdentifyConfig, names: dict[str, Any], dt: float,
               context: dict[str, Any], quiet: bool = False) -> tuple[Narx, dict[str, Any]]:
    """Train the network (PyTorch, float64); return the model and the loss history."""
    import torch

    threads, deterministic = torch.get_num_threads(), torch.are_deterministic_algorithms_enabled()
    # One thread: these matrices are small, and OpenMP threads waiting on a busy machine cost
    # ten times the arithmetic.
    torch.set_num_threads(1)
    torch.use_deterministic_algorithms(True)
    torch.manual_seed(config.seed)
    try:
        return _train(torch, train, validation, config, names, dt, context, quiet)
    finally:
        torch.set_num_threads(threads)
        torch.use_deterministic_algorithms(deterministic)


def _train(torch: Any, train: Sequence[Trajectory], validation: Sequence[Trajectory],
           config: IdentifyConfig, names: dict[str, Any], dt: float, context: dict[str, Any],
           quiet: bool) -> tuple[Narx, dict[str, Any]]:
    from tqdm import tqdm

    dtype = torch.float64
    na, nb = config.output_lags, config.input_lags
    m = max(na, nb) - 1
    skip = max(0, round(config.transient / dt))
    seg_train, seg_val = _segments(train, skip), _segments(validation, skip)
    increment = output_increments(names["output_names"])
    carry = np.asarray(increment, dtype=float)
    x, t = _regress(seg_train, na, nb, carry)
    xv, tv = _regress(seg_val, na, nb, carry)
    mu, sigma = x.mean(0), _scale(x.std(0))
    tm, ts = t.mean(0), _scale(t.std(0))
    ys = _scale(np.vstack([d for d, _ in seg_train]).std(0))
    ny = t.shape[1]

    layers: list[Any] = []
    width = x.shape[1]
    for h in config.hidden:
        layers += [torch.nn.Linear(width, h, dtype=dtype), torch.nn.Tanh()]
        width = h
    layers.append(torch.nn.Linear(width, ny, dtype=dtype))
    net = torch.nn.Sequential(*layers)
    direct = torch.nn.Linear(x.shape[1], ny, bias=False, dtype=dtype)
    params = list(net.parameters())
    if config.linear_path:
        # Start from the least-squares linear model, with the hidden layers' output near zero:
        # training then only has to add what is nonlinear.
        theta = _least_squares((x - mu) / sigma, (t - tm) / ts, 1e-9)
        with torch.no_grad():
            direct.weight.copy_(torch.tensor(theta[:-1].T, dtype=dtype))
            net[-1].bias.copy_(torch.tensor(theta[-1], dtype=dtype))
            net[-1].weight.mul_(0.01)
        params += list(direct.parameters())
    mu_t, sg_t, tm_t, ts_t, ys_t, carry_t = (torch.tensor(a, dtype=dtype)
                                             for a in (mu, sigma, tm, ts, ys, carry))

    def net_out(z: Any) -> Any:
        return net(z) + direct(z) if config.linear_path else net(z)

    def model_step(phi: Any) -> Any:
        return carry_t * phi[..., :ny] + tm_t + ts_t * net_out((phi - mu_t) / sg_t)

    zx = torch.tensor((x - mu) / sigma, dtype=dtype)
    zt = torch.tensor((t - tm) / ts, dtype=dtype)
    zxv = torch.tensor((xv - mu) / sigma, dtype=dtype)
    ztv = torch.tensor((tv - tm) / ts, dtype=dtype)

    def windows(segments: Sequence[tuple[np.ndarray, np.ndarray]]) -> tuple[Any, Any]:
        ds, us = [], []
        h = config.window
        for d, u in segments:
            for s in range(m, d.shape[0] - h, max(1, h // 2)):
                ds.append(d[s - m: s + h + 1])
                us.append(u[s - m: s + h + 1])
        if not ds:  # trajectories shorter than a window: one window each, as long as it gets
            for d, u in segments:
                ds.append(d)
                us.append(u)
            h = min(d.shape[0] for d, _ in segments) - m - 1
            ds = [d[: m + h + 1] for d in ds]
            us = [u[: m + h + 1] for u in us]
        return torch.tensor(np.array(ds), dtype=dtype), torch.tensor(np.array(us), dtype=dtype)

    def free_run(d: Any, u: Any) -> Any:
        hist = [d[:, m - i] for i in range(na)]
        outs = []
        for j in range(d.shape[1] - m - 1):
            k = m + j
            phi = torch.cat(hist + [u[:, k - i] for i in range(nb)], dim=1)
            nxt = model_step(phi)
            outs.append(nxt)
            hist = [nxt, *hist[:-1]]
        return torch.stack(outs, dim=1)

    def sim_loss(d: Any, u: Any) -> Any:
        return (((free_run(d, u) - d[:, m + 1:]) / ys_t) ** 2).mean()

    history: dict[str, list[float | None]] = {"one_step_train": [], "one_step_validation": [],
                                       "free_run_train": [], "free_run_validation": []}
    total = config.one_step_iterations + config.multi_step_iterations
    start = time.perf_counter()
    with tqdm(total=total, disable=quiet, desc="training", unit="it") as bar:
        # Phase 1: one step ahead, full batch.
        opt = torch.optim.LBFGS(params, lr=1.0, max_iter=20, history_size=50,
                                line_search_fn="strong_wolfe")

        def closure() -> Any:
            opt.zero_grad()
            loss = ((net_out(zx) - zt) ** 2).mean()
            loss.backward()
            return loss

        best, best_state, stale = math.inf, _state(net, direct), 0
        for _ in range(config.one_step_iterations):
            loss = float(opt.step(closure).detach())
            with torch.no_grad():
                val = float(((net_out(zxv) - ztv) ** 2).mean())
            history["one_step_train"].append(loss if math.isfinite(loss) else None)
            history["one_step_validation"].append(val if math.isfinite(val) else None)
            bar.update(1)
            bar.set_postfix(phase="one-step", train=f"{loss:.3g}", val=f"{val:.3g}")
            if val < best * (1 - 1e-4):
                best, best_state, stale = val, _state(net, direct), 0
            else:
                stale += 1
                if stale >= config.patience:
                    break
        _restore(best_state, net, direct)
        bar.n = config.one_step_iterations
        bar.refresh()
        # Phase 2: simulation error on windows (what the controller relies on).
        if config.multi_step_iterations > 0:
            dw, uw = windows(seg_train)
            dvw, uvw = windows(seg_val)
            opt2 = torch.optim.LBFGS(params, lr=1.0, max_iter=10, history_size=50,
                                     line_search_fn="strong_wolfe")

            def closure2() -> Any:
                opt2.zero_grad()
                loss = sim_loss(dw, uw)
                loss.backward()
                return loss

            with torch.no_grad():
                best = float(sim_loss(dvw, uvw))
            best_state, stale = _state(net, direct), 0
            for _ in range(config.multi_step_iterations):
                loss = float(opt2.step(closure2).detach())
                with torch.no_grad():
                    val = float(sim_loss(dvw, uvw))
                # A diverged L-BFGS step gives NaN: recorded as null (the run stops here and
                # keeps its best state); metrics.json holds no NaN.
                history["free_run_train"].append(loss if math.isfinite(loss) else None)
                history["free_run_validation"].append(val if math.isfinite(val) else None)
                bar.update(1)
                bar.set_postfix(phase="free-run", train=f"{loss:.3g}", val=f"{val:.3g}")
                if not math.isfinite(loss):
                    break
                if val < best * (1 - 1e-4):
                    best, best_state, stale = val, _state(net, direct), 0
                else:
                    stale += 1
                    if stale >= config.patience:
                        break
            _restore(best_state, net, direct)
    linear = [mod for mod in net if isinstance(mod, torch.nn.Linear)]
    model = Narx(weights=tuple(mod.weight.detach().numpy().astype(float).copy()
                               for mod in linear),
                 biases=tuple(mod.bias.detach().numpy().astype(float).copy() for mod in linear),
                 regressor_mean=mu, regressor_scale=sigma, increment_mean=tm,
                 increment_scale=ts, output_scale=ys, output_lags=na, input_lags=nb,
                 sample_time=dt, context=context, increment=increment,
                 linear=(direct.weight.detach().numpy().astype(float).copy()
                         if config.linear_path else None), **names)
    # float64 check: the exported weights reproduce torch's predictions through CasADi.
    with torch.no_grad():
        ref = model_step(torch.tensor(xv[:256], dtype=dtype)).numpy()
    got = np.asarray(model.casadi_function().map(min(256, xv.shape[0]))(xv[:256].T)).T
    err = float(np.max(np.abs(got - ref) / ys))
    if not err < 1e-9:
        raise RuntimeError(f"exported network differs from the trained one by {err:.3g} "
                           "(output scales)")
    history["seconds"] = [time.perf_counter() - start]
    history["export_check"] = [err]
    return model, history


def _state(net: Any, direct: Any) -> tuple[dict[str, Any], dict[str, Any]]:
    return ({k: v.detach().clone() for k, v in net.state_dict().items()},
            {k: v.detach().clone() for k, v in direct.state_dict().items()})


def _restore(state: tuple[dict[str, Any], dict[str, Any]], net: Any, direct: Any) -> None:
    net.load_state_dict(state[0])
    direct.load_state_dict(state[1])


# ---- evaluation -----------------------------------------------------------------------------

def evaluate(models: dict[str, Narx | None], trajectories: Sequence[Trajectory], skip: int,
             history: int) -> dict[str, Any]:
    """One-step and free-run NRMSE / fit per output over ``trajectories`` (concatenated).

    ``None`` stands for persistence: y(k+1) = y(k) one step ahead, and the first sample held
    in free run.
    """
    out: dict[str, Any] = {}
    for name, model in models.items():
        preds_one, preds_free, truth = [], [], []
        for tr in trajectories:
            d, u = tr.deviation[skip:], tr.v[skip:]
            truth.append(d[history + 1:])
            if model is None:
                preds_one.append(d[history: -1])
                preds_free.append(np.repeat(d[history: history + 1], d.shape[0] - history - 1,
                                            axis=0))
            else:
                preds_one.append(model.one_step(d, u))
                with np.errstate(all="ignore"):
                    preds_free.append(model.free_run(d, u))
        y = np.vstack(truth)
        one, free = np.vstack(preds_one), np.vstack(preds_free)
        free = np.where(np.isfinite(free), free, np.sign(np.nan_to_num(free)) * 1e300)
        with np.errstate(all="ignore"):
            out[name] = {"one_step": {"nrmse": nrmse(one, y).tolist(),
                                      "fit": fit_percent(one, y).tolist()},
                         "free_run": {"nrmse": nrmse(free, y).tolist(),
                                      "fit": fit_percent(free, y).tolist()}}
    return out


def _fmt(value: float, kind: str = "nrmse") -> str:
    if not math.isfinite(value) or abs(value) >= 1e3:
        return "diverges"
    if kind == "fit":
        return f"{value:.1f}"
    return f"{value:.4f}" if value < 10 else f"{value:.1f}"


def metrics_table(metrics: dict[str, Any], outputs: Sequence[str], kind: str = "nrmse") -> str:
    """Markdown: NRMSE (or fit %) per output, one-step and free run, for each model."""
    models = list(metrics)
    head = "| output | " + " | ".join(f"{m} 1-step | {m} free run" for m in models) + " |"
    rule = "|---|" + "---|---|" * len(models)
    lines = [head, rule]
    for i, name in enumerate(outputs):
        cells = []
        for m in models:
            cells += [_fmt(metrics[m]["one_step"][kind][i], kind),
                      _fmt(metrics[m]["free_run"][kind][i], kind)]
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    cells = []
    for m in models:
        for mode in ("one_step", "free_run"):
            vals = np.asarray(metrics[m][mode][kind], dtype=float)
            cells.append(_fmt(float(np.mean(np.clip(vals, -1e3, 1e3))), kind))
    lines.append("| **mean** | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def inner_loop_for(scene: Any, kp: Sequence[float], kd: Sequence[float]) -> InnerLoop:
    joints = tuple(scene.robot.moving_joints)
    n = len(joints)
    return InnerLoop(joints, tuple(kp) or (DEFAULT_KP,) * n, tuple(kd) or (DEFAULT_KD,) * n)


def check_finite(trajectories: Sequence[Trajectory]) -> None:
    """Refuse training data with NaN or Inf, naming the run, the sample and the column."""
    for k, traj in enumerate(trajectories):
        for name in ("t", "y", "r", "v", "tau_base", "tau_inner"):
            values = np.asarray(getattr(traj, name), dtype=float)
            bad = np.argwhere(~np.isfinite(values))
            if bad.size:
                where = ", column ".join(str(int(i)) for i in bad[0])
                raise DescriptionError(
                    "training data", f"run {k} ({traj.split}, {traj.family}) has a non-finite "
                    f"{name} at sample {where}: identification needs finite data; check the "
                    "scene's torques and limits")


def identify(scene: Any, out: Path, config: IdentifyConfig, quiet: bool = False) -> dict[str,
                                                                                        Any]:
    """Collect the data, train, evaluate and write the model folder; return the metrics."""
    from jointplay.neural.plant import control_plant

    scene = control_plant(scene)  # the plant the controllers are judged on
    dt = scene.run.output_step
    joints = tuple(scene.robot.moving_joints)
    inner = inner_loop_for(scene, config.kp, config.kd)
    limits = np.asarray(config.torque_limit) if config.torque_limit else default_limits(scene)
    created = not out.exists()
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        raise DescriptionError("--out", f"cannot create folder {out}: {err}") from None
    sweep_stale(out)  # the staging folder of a run that was killed
    # Everything is written into a staging folder and moved into ``out`` only once training
    # and evaluation succeeded: a failed run leaves a previous model folder as it was.
    try:
        stage = Path(tempfile.mkdtemp(prefix=f".identify.{temp_tag()}.", suffix=".part",
                                      dir=out))
    except OSError as err:
        raise file_error(out, err) from None
    try:
        metrics = _identify_into(scene, stage, config, inner, limits, joints, dt, quiet)
        for name in (MODEL_FILE, REJECTED_FILE):  # a model only once every file is in
            (out / name).unlink(missing_ok=True)
        for name in (DATASETS_FILE, METRICS_FILE, REPORT_FILE, ARX_FILE,
                     REJECTED_FILE if "rejected" in metrics else MODEL_FILE):
            os.replace(stage / name, out / name)
    except BaseException:
        shutil.rmtree(stage, ignore_errors=True)
        if created:  # leave no empty model folder behind
            with contextlib.suppress(OSError):
                out.rmdir()
        raise
    shutil.rmtree(stage, ignore_errors=True)
    if "rejected" in metrics:
        raise ModelRejected(f"{out}: the identified model is not usable: {metrics['rejected']}")
    return metrics


def _identify_into(scene: Any, out: Path, config: IdentifyConfig, inner: InnerLoop,
                   limits: np.ndarray, joints: tuple[int, ...], dt: float,
                   quiet: bool) -> dict[str, Any]:
    from importlib.metadata import version

    t0 = time.perf_counter()
    trajectories = collect(scene, config, inner, limits, quiet)
    check_finite(trajectories)
    t1 = time.perf_counter()
    names_out, units_out = output_names(joints)
    names_in, units_in = input_names(joints)
    names = {"output_names": names_out, "output_units": units_out, "input_names": names_in,
             "input_units": units_in}
    identity = robot_identity(scene.robot)
    context = {
        "robot": identity,
        "scene": {"name": scene.name, "source": scene.source or "(built-in)",
                  "torques": dict(scene.torque_text),
                  "scene_hash": hashlib.sha256(scene.text.encode()).hexdigest()},
        "plant": {
            "description": "clearance robot under a PD on the moving joints around the ideal "
                           "robot's motion (scene torques as feedforward); outputs are "
                           "deviations from the ideal robot, inputs the torque added to the "
                           "PD's",
            "outputs": "deviation from the ideal-joint robot",
            "inner_loop": {"joints": list(joints), "kp": list(inner.kp),
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
    write_datasets(out / "datasets.h5", trajectories,
                   {"output_names": list(names_out), "output_units": list(units_out),
                    "input_names": list(names_in), "input_units": list(units_in),
                    "sample_time": dt, "robot": identity, "plant": context["plant"],
                    "config": context["training"]})
    split = {s: [t for t in trajectories if t.split == s] for s in SPLITS}
    skip = max(0, round(config.transient / dt))
    x_train, _ = _regress(_segments(split["train"], skip), config.output_lags,
                          config.input_lags,
                          np.asarray(output_increments(names_out), dtype=float))
    # What the model has seen: the controller's guard keeps the internal model inside it.
    context["training_range"] = {"regressor_min": x_train.min(0).tolist(),
                                 "regressor_max": x_train.max(0).tolist()}
    trained, history = train_narx(split["train"], split["validation"], config, names, dt,
                                  context, quiet)
    t2 = time.perf_counter()
    arx = fit_arx(_segments(split["train"], skip), names, config.output_lags,
                  config.input_lags, dt)
    arx = replace(arx, context={**context, "model": "linear ARX twin (least squares)"})
    seg_val = _segments(split["validation"], skip)
    model, selection = select_residual(trained, arx, seg_val, config.window)
    verdict = judge(model, arx, selection, seg_val, config.window)
    metrics: dict[str, Any] = {
        "test": evaluate({"narx": model, "arx": arx, "persistence": None}, split["test"], skip,
                         model.history),
        "validation": evaluate({"narx": model, "arx": arx, "persistence": None},
                               split["validation"], skip, model.history),
        "residual": describe(selection, verdict),
        "outputs": list(names_out),
        "training_history": history,
        "seconds": {"simulate": t1 - t0, "train": t2 - t1},
        "trajectories": {s: len(v) for s, v in split.items()},
        "test_families": [t.family for t in split["test"]],
    }
    atomic_write_text(out / METRICS_FILE, json.dumps(metrics, indent=1, allow_nan=False,
                                                     default=float) + "\n")
    report = identify_report(scene, model, metrics, config)
    atomic_write_text(out / REPORT_FILE, report)
    summary = {"test_free_run_nrmse": metrics["test"]["narx"]["free_run"]["nrmse"],
               "test_one_step_nrmse": metrics["test"]["narx"]["one_step"]["nrmse"],
               "residual_weight": selection.alpha}
    model = replace(model, context={**model.context,
                                    "training": {**model.context["training"],
                                                 "metrics": summary}})
    save_narx(arx, out, ARX_FILE)
    # last: the presence of narx.json marks a complete, usable model folder
    save_narx(model, out, MODEL_FILE if verdict.usable else REJECTED_FILE)
    if not verdict.usable:
        metrics["rejected"] = verdict.message()
    return metrics


def identify_report(scene: Any, model: Narx, metrics: dict[str, Any],
                    config: IdentifyConfig) -> str:
    inner = model.context["plant"]["inner_loop"]
    lines = [
        f"# Identification of {scene.name}",
        "",
        f"NARX: {model.n_regressor} regressors ({model.output_lags} output lags, "
        f"{model.input_lags} input lags) -> hidden {list(model.hidden)} (tanh)"
        f"{' + linear direct path' if model.linear is not None else ''} -> "
        f"{model.n_outputs} outputs; sample time {model.sample_time:g} s.",
        f"Plant: clearance robot under a joint PD (kp {inner['kp']}, kd {inner['kd']}) around "
        "the ideal robot's motion; outputs are deviations from it.",
        f"Trajectories: {metrics['trajectories']} of {config.duration:g} s; test families "
        f"{metrics['test_families']} (fresh realisations; the chirp is never used in "
        "training). The first "
        f"{config.transient:g} s of each (journals settling from e = 0) are left out.",
        f"Time: simulate {metrics['seconds']['simulate']:.1f} s, train "
        f"{metrics['seconds']['train']:.1f} s.",
        "",
        "NRMSE on the test trajectories (RMS error / standard deviation of the output; fit % "
        "= 100 (1 - NRMSE)); `persistence` is y(k+1) = y(k) one step ahead and the first "
        "sample held in free run; `arx` is a linear model on the same regressor:",
        "",
        metrics_table(metrics["test"], metrics["outputs"]),
        "",
        "Fit % on the same trajectories:",
        "",
        metrics_table(metrics["test"], metrics["outputs"], "fit"),
        "",
    ]
    res = metrics.get("residual")
    if res:
        tried = ", ".join(f"{a}: {v:.4g}" for a, v in res["free_run_loss_by_alpha"].items())
        lines += [
            "Network = ARX + alpha x (nonlinear residual), alpha chosen on the validation "
            f"trajectories by the free-run loss over {config.window}-sample windows: "
            f"alpha = {res['alpha']:g} (loss by alpha: {tried}; persistence "
            f"{res['free_run_loss_persistence']:.4g}). "
            + ("The residual improves on the linear model on validation."
               if res["alpha"] > 0 and res["free_run_loss"] < res["free_run_loss_arx"]
               else "The residual does not improve on the linear model on validation: the "
                    "saved network is the ARX model."),
            f"Validation, mean one-step NRMSE: model {res['one_step_nrmse']:.4g}, ARX "
            f"{res['one_step_nrmse_arx']:.4g}, persistence "
            f"{res['one_step_nrmse_persistence']:.4g}.",
            "",
        ]
        if not res["usable"]:
            lines += ["**REJECTED**: " + "; ".join(res["problems"]) + ".", ""]
    return "\n".join(lines)


__all__ = [
    "Chirp",
    "IdentifyConfig",
    "InnerLoop",
    "ModelRejected",
    "Multisine",
    "Trajectory",
    "aprbs",
    "collect",
    "evaluate",
    "fit_arx",
    "ideal_reference",
    "identify",
    "measure",
    "metrics_table",
    "output_names",
    "read_datasets",
    "reference_outputs",
    "train_narx",
    "write_datasets",
]
