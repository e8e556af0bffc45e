"""The internal-model controller step: the law, its guard, and the compiled C.

The plant the models identified is the clearance robot under a joint PD around the ideal
robot's motion; its input is the torque v added to the PD's, its outputs y the deviations from
the ideal robot. At every sample k the step, for its internal model M (the NARX network, or the
linear ARX twin),

1. compares the measured deviation with M's free-run prediction, e(k) = y(k) - y^(k), and
   filters it, e_f(k) = b e_f(k-1) + (1 - b) e(k) (unity DC gain);
2. runs M d samples ahead with the input held, linearised about the previous input:
   y^(k+d) ~ N0(k) + J(k) dv (for the ARX model N0 is a constant matrix times the state and J
   a constant);
3. solves the regularised inverse on the tracked outputs (rows of C, scaled),
   dv = ((CJ)'(CJ) + lam I)^-1 (CJ)' C (y_d(k+d) - e_f(k) - N0(k));
4. limits the rate of v, keeps v inside what the model was trained on and the total actuator
   torque inside its limits, and advances the internal models with the v applied.

The guard. A network is trustworthy only where it was trained. The step checks, every sample,
that the internal model's regressor and its d-step prediction lie inside the training range
(widened by a margin), that they are finite, and that the mismatch on the tracked outputs stays
below a bound (filtered, like the mismatch the law uses: a single impact does not trip it; a
model running away does). When a check fails, the step uses the fallback model's increment
instead (the ARX twin runs in parallel, always advanced with the applied input), re-seeds the
network's history from it and stays on the fallback for a hold time that doubles with each
episode; when the fallback fails its own checks too, the outer loop lets go (v ramps to zero,
the inner PD alone). Every intervention comes out in the step's flags, and the closed loop
counts them.

The step is one CasADi SX function, generated to C and compiled through the robot models'
cache. Its cost is what the controller costs: see benchmarks/control_step.py.
"""

from __future__ import annotations

import hashlib
import json
import math
import platform
import time
from dataclasses import asdict, dataclass, field
from importlib.metadata import version
from pathlib import Path
from typing import Any

import casadi as ca
import numpy as np

from jointplay.neural.control.imc_settings import (
    ControllerSettings,
    default_tracked,
    resolve_settings,
)
from jointplay.neural.control.imc_step import FLAGS, STEP_NAME, build_step
from jointplay.neural.control.internal_model import (
    affine_rollout,
    horizon_gain,
    input_bound,
    is_linear,
    training_box,
)
from jointplay.neural.control.mismatch_filter import pair_gains
from jointplay.neural.model.narx import Narx
from jointplay.store.build import DEFAULT_CFLAGS


def _vector_flags(cpuinfo: str = "/proc/cpuinfo") -> tuple[str, ...]:
    """AVX2 and FMA where this machine's x86-64 processor has them (none elsewhere). The
    build cache's key holds the flags, so a cache shared with a machine without them keeps
    a separate build for it."""
    if platform.machine().lower() not in ("x86_64", "amd64"):
        return ()
    try:
        text = Path(cpuinfo).read_text(errors="replace")
    except OSError:
        return ()
    flags = next((line.split(":", 1)[1].split() for line in text.splitlines()
                  if line.startswith("flags")), [])
    return ("-mavx2", "-mfma") if {"avx2", "fma"} <= set(flags) else ()


# The loop kernel is a few kilobytes: -O3 compiles it in about a second and vectorises its
# column sums (2x faster than -O2 here), and with AVX2 and FMA faster again (3.7 us per
# step, docs/control.md "Cost of the controller step"; FMA changes the last bit of a
# product's rounding, and the kernel stays within 1e-12 of CasADi's step). CasADi's code
# for iterations > 1 keeps the models' flags (-O1, CasADi's helpers inlined: no flag that
# reorders arithmetic): -O2 compiled it 2.5x longer for no gain.
STEP_CFLAGS = ("-O3", "-fPIC", "-shared", "-fno-math-errno", *_vector_flags())
SX_CFLAGS = DEFAULT_CFLAGS


@dataclass
class Controller:
    """A compiled controller step, bound to preallocated buffers."""

    model: Narx
    fallback: Narx | None
    settings: ControllerSettings
    function: ca.Function  # the CasADi step (uncompiled), for checks and analysis
    library: Path | None
    compile_seconds: float
    source: str
    fast: Any = None  # FastFunction over the compiled step
    n_state: int = 0
    layout: dict[str, Any] = field(default_factory=dict)

    @property
    def narx(self) -> Narx:
        return self.model

    def initial_state(self, deviation: np.ndarray,
                      past: np.ndarray | None = None) -> np.ndarray:
        """Internal models started at the measured deviation, no added torque, no mismatch.

        ``past``: earlier measured deviations, newest first (rows), for the models' older
        lags (without them every lag holds ``deviation``: a history at rest)."""
        m = self.model
        # The models start at the nearest output they were trained on: the plant's first
        # sample can lie outside (the journals start centred, off their resting point, and
        # the first 50 ms of every training run are left out).
        lo, hi = training_box(m, 0.0)
        rows = [np.asarray(deviation, dtype=float)]
        if past is not None:
            rows += list(np.atleast_2d(np.asarray(past, dtype=float)))

        def history(lags: int) -> np.ndarray:
            return np.concatenate([np.clip(rows[min(i, len(rows) - 1)], lo[: m.n_outputs],
                                           hi[: m.n_outputs]) for i in range(lags)])
        parts = [history(m.output_lags)]
        if self.fallback is not None:
            parts.append(history(self.fallback.output_lags))
        parts += [np.zeros(m.input_lags * m.n_inputs), np.zeros(m.n_outputs)]
        if self.fallback is not None:
            parts.append(np.zeros(m.n_outputs))
        parts += [np.asarray(deviation, dtype=float), np.zeros(2)]
        return np.concatenate(parts)

    def step(self, y: np.ndarray, r: np.ndarray, tau_ff: np.ndarray,
             state: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(added torque, next state, v, predicted deviation) through the compiled code; the
        flags of the step are in :attr:`last_flags`."""
        f = self.fast
        f.inputs[0][:] = y
        f.inputs[1][:] = r
        f.inputs[2][:] = tau_ff
        f.inputs[3][:] = state
        f.trigger()
        return (f.outputs[0].copy(), f.outputs[1].copy(), f.outputs[2].copy(),
                f.outputs[3].copy())

    @property
    def last_flags(self) -> np.ndarray:
        return np.asarray(self.fast.outputs[4]).copy()


# ---- C, compile, cost ---------------------------------------------------------------------

def _header(model: Narx, fallback: Narx | None, settings: ControllerSettings,
            layout: dict[str, Any], body: str) -> str:
    settings_text = json.dumps(asdict(settings), default=str)
    kind = "linear ARX" if is_linear(model) else "NARX network"
    return (
        "/* GENERATED FILE: DO NOT EDIT.\n"
        " * Regenerated by `jointplay control` from the model folder's narx.json/arx.json.\n"
        f" * controller: {STEP_NAME} (internal-model control, {kind} inside"
        f"{', ARX fallback' if fallback is not None else ''})\n"
        f" * generator: jointplay.neural.control.imc {version('jointplay')}, "
        f"casadi {version('casadi')}\n"
        f" * model checksum: {model.checksum()}\n"
        f" * fallback checksum: {fallback.checksum() if fallback is not None else '-'}\n"
        f" * robot hash: {model.context.get('robot', {}).get('robot_hash', '?')}\n"
        f" * code sha256: {hashlib.sha256(body.encode()).hexdigest()}\n"
        f" * settings: {settings_text}\n"
        f" * state[{len(layout['state'])}]: {', '.join(layout['state'])}\n"
        f" * flags: {', '.join(FLAGS)}\n"
        f" * outputs y: {', '.join(layout['inputs']['y'])}\n"
        " */\n")


def generate_c(model: Narx, settings: ControllerSettings, fallback: Narx | None = None
               ) -> tuple[str, ca.Function, dict[str, Any]]:
    fn, layout = build_step(model, settings, fallback)
    gen = ca.CodeGenerator("imc.c", {"with_header": False, "verbose": False})
    gen.add(fn)
    body = gen.dump()
    return _header(model, fallback, settings, layout, body) + body, fn, layout


def compile_controller(model: Narx, settings: ControllerSettings, fallback: Narx | None = None,
                       compiled: bool = True, kernel: bool | None = None) -> Controller:
    """Build, generate, compile (through the cache) and load the controller step.

    ``kernel``: compile the loop kernel (jointplay.neural.control.imc_kernel) rather than CasADi's
    straight-line code for the same function (one Gauss-Newton iteration only); None: the
    kernel (for every model: since its layers run four outputs at a time in registers, the
    LPV-ARX model's kernel costs about a third of its straight-line code,
    benchmarks/control_step.py)."""
    from jointplay.store.build import compile_source
    from jointplay.store.model import FastFunction

    settings = resolve_settings(model, settings)
    # The loop kernel implements the first-order mismatch filter; the pairwise filter of
    # declared noise (mismatch_filter.py) runs as CasADi's code.
    # The kernel runs networks, ARX and LPV-ARX models (with their scheduling signals and
    # bilinear parts).
    if kernel is None:
        kernel = True
    if kernel and settings.iterations == 1 and not pair_gains(model, settings):
        from jointplay.neural.control.imc_kernel import kernel_library_source

        fn, layout = build_step(model, settings, fallback)
        body = kernel_library_source(model, settings, fallback, fn, STEP_NAME)
        source = _header(model, fallback, settings, layout, body) + body
        cflags = STEP_CFLAGS
    else:
        source, fn, layout = generate_c(model, settings, fallback)
        cflags = SX_CFLAGS
    library, seconds = (None, 0.0)
    external = fn
    if compiled:
        library, seconds = compile_source(source, cflags=cflags)
        external = ca.external(STEP_NAME, str(library))
    return Controller(model, fallback if settings.guard else None, settings, fn, library,
                      seconds, source, FastFunction(external), len(layout["state"]), layout)


def per_call_us(ctrl: Controller, repeat: int = 5, number: int = 20000) -> float:
    """Median CPU time of one compiled step through the buffer path, in microseconds (CPU
    time of this process: on a shared machine wall time also counts the others' work)."""
    f = ctrl.fast
    f.inputs[3][:] = ctrl.initial_state(np.zeros(ctrl.model.n_outputs))
    best = []
    for _ in range(repeat):
        t0 = time.process_time()
        for _ in range(number):
            f.trigger()
        best.append((time.process_time() - t0) / number)
    return float(np.median(best) * 1e6)


def _loop_functions(ctrl: Controller) -> tuple[ca.Function, ca.Function]:
    """The loop with the internal model as its own plant: state -> next state, and its
    Jacobian."""
    fn = ctrl.function
    ny = ctrl.model.n_outputs
    x = ca.MX.sym("x", ctrl.n_state)
    r, tau_ff = nominal_reference(ctrl.model)
    nxt = fn(x[:ny] + r, r, tau_ff, x)[1]
    return ca.Function("loop", [x], [nxt]), ca.Function("loop_jac", [x], [ca.jacobian(nxt, x)])


def nominal_reference(model: Narx) -> tuple[np.ndarray, np.ndarray]:
    """(reference outputs, feedforward) at which a model's scheduling signals take their
    training means (the angle from its mean cosine and sine): the operating point of the
    nominal linearisation. Zeros for a model without scheduling signals (it does not see
    them)."""
    r, tau_ff = np.zeros(model.n_outputs), np.zeros(model.n_inputs)
    ns = model.n_scheduling
    if not ns:
        return r, tau_ff
    mean = dict(zip(model.scheduling, model.regressor_mean[model.n_regressor - ns:],
                    strict=True))
    for name, value in mean.items():
        if name.startswith("cos(q"):
            out = name[4: -len("_ref)")]
            r[model.output_index(out)] = math.atan2(mean[f"sin({out}_ref)"], value)
        elif name.endswith("_ref") and not name.startswith(("cos(", "sin(")):
            r[model.output_index(name[: -len("_ref")])] = value
        elif name.startswith("tau"):
            tau_ff[model.input_names.index(f"v{name[3: -len('_ff')]}")] = value
    return r, tau_ff


def _radius(jac: np.ndarray, ctrl: Controller) -> float:
    """Spectral radius of the loop while the primary model is in charge.

    The fallback model runs in parallel, driven by the applied input but feeding nothing
    back, and the hold counters are bookkeeping: the Jacobian is block-triangular, and their
    eigenvalues (the fallback's own free-run poles, and 1 for the episode counter) say
    nothing about this loop. They are left out."""
    keep = [i for i, name in enumerate(ctrl.layout["state"])
            if not name.startswith(("y_hat_fallback", "e_f_fallback", "fallback_"))]
    sub = jac[np.ix_(keep, keep)]
    if not np.all(np.isfinite(sub)):
        return math.inf
    return float(np.max(np.abs(np.linalg.eigvals(sub))))


def nominal_spectral_radius(ctrl: Controller, settle: int = 3000) -> float:
    """Spectral radius of the loop with the internal model as the plant, linearised at the
    equilibrium it settles to (one operating point: see local_spectral_radii)."""
    loop, loop_jac = _loop_functions(ctrl)
    state = ctrl.initial_state(np.zeros(ctrl.model.n_outputs))
    for _ in range(settle):
        state = np.asarray(loop(state)).ravel()
        if not np.all(np.isfinite(state)):
            return math.inf
    return _radius(np.asarray(loop_jac(state)), ctrl)


def local_spectral_radii(ctrl: Controller, states: np.ndarray) -> np.ndarray:
    """The same linearisation at controller states visited along a closed-loop run."""
    _, loop_jac = _loop_functions(ctrl)
    return np.array([_radius(np.asarray(loop_jac(x)), ctrl) for x in states])


__all__ = ["FLAGS", "STEP_NAME", "Controller", "ControllerSettings", "affine_rollout",
           "build_step", "compile_controller", "default_tracked", "generate_c", "horizon_gain",
           "input_bound", "is_linear", "local_spectral_radii", "nominal_spectral_radius",
           "per_call_us", "resolve_settings", "training_box"]
