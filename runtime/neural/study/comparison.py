"""The whole comparison: every controller on one scene against the ideal-joint robot's motion,
its metrics, what can be said about each loop's stability, and the runs written to HDF5.

Without a given bound the open loop runs first and sets the divergence bound (twice its
largest end-effector error by default: doing nothing does better). The stability verdict rests
on the realised runs (bounded or not, and how often the guard acted), with the linearisations
(at the nominal equilibrium and at states visited along the run) as supporting evidence.
"""

from __future__ import annotations

import json
import math
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from jointplay.neural.control.imc import (
    FLAGS,
    Controller,
    ControllerSettings,
    compile_controller,
    local_spectral_radii,
    nominal_spectral_radius,
    per_call_us,
)
from jointplay.neural.control.loop import (
    NO_CONDITIONS,
    Law,
    LoopConditions,
    Run,
    computed_torque_law,
    imc_law,
    pd_law,
    run_loop,
)
from jointplay.neural.control.metrics import WORSE_MARGIN, run_metrics, tip_errors
from jointplay.neural.control.noise_tuning import NoiseTuning, tune_to_noise
from jointplay.neural.model.narx import Narx

DEFAULT_TRANSIENT = 0.05  # s: what identification leaves out of each run (journals settling)
# Impacts closer than this to the previous one belong to the release sequence that starts at
# t = 0 (the journals falling from the bearing centres and bouncing): measured on the paper
# scene's open loop, that sequence ends at 19.9 ms (30 µm) and 36.5 ms (0.1 mm), its gaps at
# most 8.4 ms, and no impact follows in the next 0.36 s.
RELEASE_GAP = 0.01  # s
# The setpoint filter has let go of the deviation measured at engagement once a^n falls below
# this (a = 0.9: 44 samples).
SETPOINT_DECAY = 0.01
NEURAL, LINEAR, LPV = "neural IMC", "ARX-IMC", "LPV-ARX-IMC"
CONTROLLERS = ("open loop", "PD", "computed torque", LINEAR, LPV, NEURAL)
MODEL_BASED = (LINEAR, LPV, NEURAL)
DIVERGENCE_FACTOR = 2.0  # x the open loop's largest tip error


@dataclass(frozen=True)
class Settling:
    """Where the settling transient ends, and why: the later of the outer loop's engagement
    (plus its setpoint filter's decay) and the end of the open loop's release impacts."""

    time: float  # s: the metrics "after" start here
    engage: float | None  # s: the outer loop engages (None: no internal-model controller)
    filter_decayed: float | None  # s: its setpoint filter has decayed by SETPOINT_DECAY
    release_end: float  # s: the open loop's release impacts have ended (+ RELEASE_GAP)
    given: bool = False  # the window was given (--transient), not taken from the run

    def describe(self) -> str:
        ms = f"{self.time * 1e3:.0f} ms"
        if self.given:
            return f"the first {ms} are excluded from the \"after\" columns (--transient)"
        parts = [f"the open loop's release impacts (the journals falling from the bearing "
                 f"centres) end by {self.release_end * 1e3:.0f} ms" if self.release_end > 0
                 else "the open loop has no release impacts (no impact in its first "
                      f"{RELEASE_GAP * 1e3:g} ms)"]
        if self.engage is None and self.filter_decayed is not None:
            parts.insert(0, f"the internal-model controllers' engagement has settled by "
                            f"{self.filter_decayed * 1e3:.0f} ms")
        if self.engage is not None and self.filter_decayed is not None:
            parts.insert(0, f"the outer loop engages at {self.engage * 1e3:.0f} ms and its "
                            f"setpoint filter decays to {SETPOINT_DECAY:g} by "
                            f"{self.filter_decayed * 1e3:.0f} ms")
        return (f"the first {ms} are excluded from the \"after\" columns, taken from the "
                "run: " + "; ".join(parts))


def release_end(run: Run) -> float:
    """The end of the impact sequence that starts at t = 0 (gaps below RELEASE_GAP), plus one
    gap; 0 when the run has no impact."""
    times = np.sort(np.asarray(run.impact_times, dtype=float))
    if times.size == 0 or times[0] > RELEASE_GAP:
        return 0.0
    end = times[0]
    for t in times[1:]:
        if t - end > RELEASE_GAP:
            break
        end = t
    return float(end + RELEASE_GAP)


def engagement_end(engage: float, setpoint_filter: float, dt: float) -> float:
    """When an internal-model controller engaging at ``engage`` s has let its setpoint filter
    decay to SETPOINT_DECAY."""
    a = setpoint_filter
    samples = math.ceil(math.log(SETPOINT_DECAY) / math.log(a)) if 0 < a < 1 else 0
    return engage + samples * dt


def settling(runs: dict[str, Run], ctrls: dict[str, Controller], dt: float,
             settle_after: float = 0.0) -> Settling:
    """The settling transient of this comparison, from its runs (see :class:`Settling`)."""
    engage = max((c.settings.engage or 0.0 for c in ctrls.values()), default=None)
    decayed = None
    if engage is not None:
        decayed = max(engagement_end(c.settings.engage or 0.0, c.settings.setpoint_filter, dt)
                      for c in ctrls.values())
    elif settle_after > 0:
        decayed = settle_after
    base = runs.get("open loop")
    release = release_end(base) if base is not None else max(
        (release_end(r) for r in runs.values()), default=0.0)
    time = max(release, decayed if decayed is not None else 0.0, settle_after)
    return Settling(round(time / dt) * dt, engage, decayed, release)


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
    noise_tuning: NoiseTuning | None = None  # the horizon chosen for declared sensor noise
    settling: Settling | None = None  # where the "after" metrics start, and why

    @property
    def controller(self) -> Controller:
        """The neural controller (or the only internal-model controller there is)."""
        return self.controllers.get(NEURAL) or next(iter(self.controllers.values()))


def compare(scene: Any, narx: Narx, settings: ControllerSettings, *, arx: Narx | None = None,
            lpv: Narx | None = None,
            transient: float | None = None, ct_omega: float = 15.0,
            ct_zeta: float = 0.2, pd_kp: Sequence[float] = (), pd_kd: Sequence[float] = (),
            controllers: Sequence[str] = CONTROLLERS, quiet: bool = True,
            analyse: bool = True, conditions: LoopConditions = NO_CONDITIONS,
            limit: float | None = None, divergence_factor: float = DIVERGENCE_FACTOR,
            compiled: dict[str, Controller] | None = None,
            plant_tolerance: float | None = None, settle_after: float = 0.0) -> Comparison:
    """Run the scene with every controller against the ideal robot's motion.

    ``transient``: seconds left out of the "after" metrics; None takes them from the run
    (:func:`settling`), no earlier than ``settle_after`` (the engagement of controllers run
    elsewhere, so that their rows share one window). Without ``limit`` the open loop runs
    first and sets the divergence bound
    (``divergence_factor`` x its largest tip error). ``arx`` is the linear twin: the
    ARX-IMC's model and the neural controller's fallback (without it there is no ARX-IMC and
    the neural controller falls back to the inner loop alone). ``lpv``: the LPV-ARX model
    (the LPV-ARX-IMC's, with the ARX twin as its fallback; without it there is no such row).
    ``analyse`` also measures each
    compiled step's cost and its linearised loop's spectral radius (nominal, and along the
    run).
    """
    from jointplay.neural.identify.pipeline import (
        contact_joints,
        ideal_reference,
        reference_outputs,
    )
    from jointplay.neural.model.plant import PLANT_TOLERANCE, SUBSTEPS, control_plant
    from jointplay.sim import load_scene_model

    # One plant setting for every controller (jointplay.neural.model.plant); ``plant_tolerance``
    # only to measure what that setting changes (benchmarks/control_plant.py).
    scene = control_plant(scene, plant_tolerance or PLANT_TOLERANCE)
    ideal = ideal_reference(scene)
    # A model that measures the journals' eccentricities: every controller's run measures
    # them too (the baselines ignore them), so that all rows share one reference.
    contact = contact_joints(narx.output_names)
    reference = reference_outputs(ideal, contact)
    model = load_scene_model(scene)
    nj = len(scene.robot.moving_joints)
    names = [c for c in controllers if (arx is not None or c != LINEAR)
             and (lpv is not None or c != LPV)]
    tuning = None
    if settings.measurement_noise and any(c in MODEL_BASED for c in names):
        settings, tuning = tune_to_noise(narx, arx, settings)
    ctrls = _compile(names, narx, arx, settings, compiled, lpv)
    if limit is None:
        names = ["open loop", *[c for c in names if c != "open loop"]]
    gains = _Gains(pd_kp, pd_kd, ct_omega, ct_zeta)
    runs: dict[str, Run] = {}
    for name in names:
        log: dict[str, list[np.ndarray]] = {"v": [], "y_pred": [], "flags": [], "states": []}
        law = _law(name, scene, narx, ideal, reference, ctrls, gains, log)
        if limit is not None:
            bound = limit
        elif name == "open loop":
            bound = math.inf
        else:
            bound = open_loop_bound(runs["open loop"], reference, nj, divergence_factor)
        run = run_loop(scene, reference, law, name, model, limit=bound, conditions=conditions,
                       substeps=SUBSTEPS, contact=contact)
        _attach_log(run, log)
        runs[name] = run
        if not quiet:
            note = f"; DIVERGED: {run.diverged}" if run.diverged else ""
            print(f"  {name}: {run.seconds:.1f} s, {run.impacts} impacts{note}", flush=True)
    if limit is None:
        limit = open_loop_bound(runs["open loop"], reference, nj, divergence_factor)
    dt = scene.run.output_step
    settled = (settling(runs, ctrls, dt, settle_after) if transient is None else
               Settling(transient, None, None, 0.0, given=True))
    k0 = max(0, round(settled.time / dt))
    k_engaged = max(0, round(engagement(ctrls, settings) / dt))
    dense_reference = ideal_reference(scene.with_run(
        output_step=scene.run.output_step / SUBSTEPS)).tip_acceleration
    metrics = {name: run_metrics(run, reference, nj, k0, dense_reference, k_engaged)
               for name, run in runs.items()}
    result = Comparison(runs, reference, metrics, k0, limit, ctrls, tau_ff=ideal.tau,
                        dense_reference=dense_reference, noise_tuning=tuning,
                        settling=settled)
    if analyse:
        _analyse(result)
    return result


def engagement(ctrls: dict[str, Controller], settings: ControllerSettings) -> float:
    """When the outer loop engages (s): the latest of the internal-model controllers'; without
    one, the engagement they would have (``settings``, else twice the start-up identification
    leaves out), so that baselines run apart from them share their window."""
    engage = max((c.settings.engage or 0.0 for c in ctrls.values()), default=None)
    if engage is not None:
        return engage
    return settings.engage if settings.engage is not None else 2.0 * DEFAULT_TRANSIENT


def open_loop_bound(open_loop: Run, reference: np.ndarray, nj: int, factor: float) -> float:
    """The divergence bound: ``factor`` x the open loop's largest end-effector error (m)."""
    return factor * float(np.max(tip_errors(open_loop, reference, nj)["position"]))


def _compile(names: Sequence[str], narx: Narx, arx: Narx | None, settings: ControllerSettings,
             compiled: dict[str, Controller] | None,
             lpv: Narx | None = None) -> dict[str, Controller]:
    """The internal-model controllers ``names`` asks for; those in ``compiled`` are reused."""
    ctrls: dict[str, Controller] = dict(compiled or {})
    for name in names:
        if name == NEURAL and name not in ctrls:
            ctrls[name] = compile_controller(narx, settings, fallback=arx)
        elif name == LPV and name not in ctrls and lpv is not None:
            ctrls[name] = compile_controller(lpv, settings, fallback=arx)
        elif name == LINEAR and name not in ctrls and arx is not None:
            ctrls[name] = compile_controller(arx, settings)
    return ctrls


@dataclass(frozen=True)
class _Gains:
    """The baselines' tuning: PD gains (empty: the inner loop's), computed torque's bandwidth
    and damping ratio."""

    pd_kp: Sequence[float]
    pd_kd: Sequence[float]
    ct_omega: float
    ct_zeta: float


def _law(name: str, scene: Any, narx: Narx, ideal: Any, reference: np.ndarray,
         ctrls: dict[str, Controller], gains: _Gains, log: dict[str, list[np.ndarray]]) -> Law:
    """The law of the controller called ``name``; an internal-model law logs into ``log``."""
    nj = len(scene.robot.moving_joints)
    if name == "open loop":
        return lambda k, y: np.zeros(nj)
    if name == "PD":
        return pd_law(narx, reference, gains.pd_kp, gains.pd_kd)
    if name == "computed torque":
        return computed_torque_law(scene, ideal, reference, gains.ct_omega, gains.ct_zeta)
    if name in ctrls:
        return imc_law(ctrls[name], reference, ideal.tau, log)
    raise ValueError(f"unknown controller {name!r}")


def _attach_log(run: Run, log: dict[str, list[np.ndarray]]) -> None:
    """Copy an internal-model law's log (v, flags, states) into its run, cut to its length."""
    if log["v"]:
        n = run.y.shape[0]
        run.v[: min(n, len(log["v"]))] = np.array(log["v"])[:n]
        run.flags = np.array(log["flags"])[:n]
        run.states = np.array(log["states"])[:n]


def _analyse(result: Comparison) -> None:
    """Each compiled step's cost and its loop's spectral radii: nominal, and at up to eight
    controller states visited along its run."""
    for name, ctrl in result.controllers.items():
        if name not in result.runs:
            continue
        result.per_call_us[name] = per_call_us(ctrl)
        states = result.runs[name].states
        picks = states[np.linspace(0, len(states) - 1, min(8, len(states))).astype(int)] \
            if len(states) else states
        picks = picks[_trusted(result.runs[name], picks, states)] if len(states) else picks
        nominal, local = stability_radii(ctrl, picks)
        result.nominal_radius[name] = nominal
        result.local_radius[name] = local


def _trusted(run: Run, picks: np.ndarray, states: np.ndarray) -> np.ndarray:
    """Which picked states were visited with the model in charge (guard not acting): the
    linearisation there is the law that ran."""
    index = np.linspace(0, len(states) - 1, min(8, len(states))).astype(int)
    if run.flags.size == 0:
        return np.ones(len(picks), dtype=bool)
    flags = run.flags[np.minimum(index, run.flags.shape[0] - 1)]
    return np.asarray(flags[:, 0] < 0.5)


def stability_radii(ctrl: Controller, states: np.ndarray) -> tuple[float, np.ndarray]:
    """Nominal spectral radius and the radii at the given visited controller states.

    The nominal radius is that of the law with its model in charge: the same model compiled
    without the guard, so that a guard switching the model off while the loop settles cannot
    put its fallback's (or the mismatch filter's) poles in the model's place, and one model
    gives one verdict whichever controller it sits in."""
    primary = ctrl
    if ctrl.settings.guard:
        primary = compile_controller(ctrl.model, replace(ctrl.settings, guard=False),
                                     compiled=False)
    return nominal_spectral_radius(primary), local_spectral_radii(ctrl, states)


MARGINAL = 1e-3  # a radius this close to 1 is an integrator the verdict cannot decide on


def verdict(name: str, run: Run, comparison: Comparison) -> tuple[str, bool]:
    """What can be said about the loop's stability, and whether it calls for a warning."""
    counts = run.guard_counts
    duration = float(run.t[-1]) if run.t.size else 0.0
    if run.diverged:
        return f"{name}: DIVERGED ({run.diverged}); the run was stopped", True
    parts: list[str] = []
    warn = False
    # Judged where the controller acts (from its engagement on), a tie within WORSE_MARGIN.
    base = comparison.metrics.get("open loop", {}).get("max_position_engaged")
    worse = run.y.shape[0] and base is not None and \
        comparison.metrics[name]["max_position_engaged"] > base * (1 + WORSE_MARGIN)
    if counts.get("episodes", 0):
        warn = True
        # A controller without a fallback (ARX-IMC) hands over to the inner loop alone.
        what, where = ((f"its model ({'the network' if name == NEURAL else 'LPV-ARX'}) was",
                        f"{counts['on_fallback_model']} samples on the ARX fallback, ")
                       if name in (NEURAL, LPV) else (f"its model ({name}) was", ""))
        parts.append(f"bounded over the {duration:g} s run only with the guard: {what} "
                     f"distrusted {counts['episodes']} time(s) ({where}"
                     f"{counts['inner_loop_only']} samples with the inner loop alone)")
    else:
        parts.append(f"bounded over the {duration:g} s run, no fallback")
    if counts.get("input_at_trust_bound", 0):
        warn = True
        parts.append(f"v held at the trust bound (training range) on "
                     f"{counts['input_at_trust_bound']} samples")
    if worse:
        warn = True
        parts.append("its largest tip error from its engagement on exceeds the open loop's "
                     f"by more than {WORSE_MARGIN:.0%}")
    nominal = comparison.nominal_radius.get(name)
    local = comparison.local_radius.get(name)
    if nominal is not None:
        if nominal < 1 - MARGINAL:
            lin = (f"nominal linearisation (its model in charge) stable (spectral radius "
                   f"{nominal:.4f})")
        elif nominal <= 1 + MARGINAL:
            lin = (f"nominal linearisation (its model in charge) marginal (spectral radius "
                   f"{nominal:.4f}, within "
                   f"{MARGINAL:g} of 1: an integrating mode the tracked outputs do not see; "
                   "undecided)")
        else:
            # Supporting evidence, not the verdict: the linearisation takes the model as its
            # own plant. It warns when the loop that ran needed the guard or ran away from
            # the open loop (above); a bounded run without either is said, not warned about.
            lin = (f"nominal linearisation (its model in charge) unstable (spectral radius "
                   f"{nominal:.4f})")
        if local is not None and local.size:
            lin += (f"; at {local.size} states along the run with the model trusted "
                    f"{np.min(local):.4f} to {np.max(local):.4f}")
            if np.max(local) > 1 + MARGINAL:
                lin += " (above 1 at some: stability beyond this run is not established)"
        parts.append(lin)
    return f"{name}: " + "; ".join(parts), warn


def write_runs(path: Path, comparison: Comparison, meta: dict[str, Any],
               outputs: Sequence[tuple[str, str]]) -> None:
    """Every run of the comparison as a netCDF-4/CF file (the results file's conventions):
    the reference at the root, one group per controller, one variable per plant output
    (``outputs``: name and unit, e.g. ``("q2", "rad")``) with its UDUNITS ``units``.

    Built in memory and written with plain file I/O, atomically (a full disk: one line, no
    file).
    """
    import h5netcdf

    from jointplay.common.files import write_hdf5_in_memory
    from jointplay.results.netcdf import CONVENTIONS, UDUNITS

    def units(unit: str) -> str:
        return UDUNITS.get(unit, unit)

    def times(n: int) -> np.ndarray:
        """Output times of the reference: those of the longest run, continued at its step."""
        longest = max(comparison.runs.values(), key=lambda r: np.asarray(r.t).size).t
        longest = np.asarray(longest, dtype=np.float64)
        if longest.size >= n:
            return longest[:n]
        step = longest[1] - longest[0] if longest.size > 1 else 1.0
        start = longest[0] if longest.size else 0.0
        return start + step * np.arange(n)

    def variable(group: Any, name: str, dims: tuple[str, ...], data: Any, unit: str | None,
                 long_name: str) -> None:
        import h5py

        values = np.asarray(data)
        kwargs = {"dtype": h5py.string_dtype()} if values.dtype.kind in "UO" else {}
        var = group.create_variable(name, dims, data=values.astype(object) if kwargs
                                    else values, **kwargs)
        if unit is not None:
            var.attrs["units"] = unit
        var.attrs["long_name"] = long_name

    def signals(group: Any, values: np.ndarray, what: str) -> None:
        values = np.asarray(values, dtype=np.float64).reshape(group.dimensions["time"].size, -1)
        for k, (name, unit) in enumerate(outputs):
            variable(group, f"output_{name}", ("time",), values[:, k], units(unit),
                     f"{what}: plant output {name}")

    def build(fh: Any) -> None:
        with h5netcdf.File(fh, "w") as f:
            f.attrs["Conventions"] = CONVENTIONS
            f.attrs["title"] = "jointplay closed-loop comparison"
            f.attrs["format"] = "jointplay-control"
            f.attrs["format_version"] = 2
            f.attrs["meta"] = json.dumps(meta, default=str)
            f.attrs["controllers"] = json.dumps(list(comparison.runs))
            reference = np.asarray(comparison.reference)
            f.dimensions = {"time": reference.shape[0]}
            variable(f, "time", ("time",), times(reference.shape[0]), "s",
                     "time since the start of the run")
            signals(f, reference, "reference (the ideal robot)")
            for name, run in comparison.runs.items():
                g = f.create_group(name)
                t = np.asarray(run.t, dtype=np.float64)
                tau, v = np.asarray(run.tau), np.asarray(run.v)
                flags = np.asarray(run.flags)
                g.dimensions = {"time": t.size, "drive": tau.shape[1] if tau.ndim == 2 else 0,
                                "torque_sample": tau.shape[0], "flag": len(FLAGS),
                                "flag_sample": flags.shape[0]}
                variable(g, "time", ("time",), t, "s", "time since the start of the run")
                signals(g, np.asarray(run.y), f"controller {name}")
                variable(g, "flag", ("flag",), np.array(list(FLAGS), dtype=object), None,
                         "guard flag name")
                variable(g, "torque", ("torque_sample", "drive"), tau, "N m",
                         "torque added to the scene's from each sample (last row 0)")
                variable(g, "outer_torque", ("torque_sample", "drive"), v.reshape(tau.shape),
                         "N m", "the outer loop's part of the added torque")
                variable(g, "flags", ("flag_sample", "flag"),
                         flags.reshape(flags.shape[0], len(FLAGS)).astype(np.int8), "1",
                         "guard flags raised at each sample (1: raised)")
                g.attrs["metrics"] = json.dumps(comparison.metrics[name])
                g.attrs["diverged"] = run.diverged

    write_hdf5_in_memory(path, build)


__all__ = ["CONTROLLERS", "DEFAULT_TRANSIENT", "DIVERGENCE_FACTOR", "LINEAR", "LPV", "MARGINAL",
           "MODEL_BASED", "NEURAL", "RELEASE_GAP", "SETPOINT_DECAY", "Comparison", "Settling",
           "compare", "engagement", "engagement_end", "open_loop_bound", "release_end", "settling",
           "stability_radii",
           "verdict", "write_runs"]
