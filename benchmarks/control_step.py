"""Cost of one compiled controller step, before and after the structural changes.

    python benchmarks/control_step.py --out out/bench/control_step [--model MODEL_DIR]

Variants, each generated, compiled (through the cache) and called through FastFunction's
preallocated buffers, 15 rounds of 20 000 calls with the variants interleaved; the fastest
round and the median round are reported:

- ``trivial``: a function that doubles two numbers (the Python-to-C call overhead);
- ``before``: the step as it was: CasADi's straight-line SX code, the network only, no guard,
  horizon 10, gcc -O1;
- the guarded step (ARX fallback) as CasADi SX code at the default horizon 5 (gcc -O1);
- the loop kernel (jointplay.neural.imc_kernel, gcc -O3) at horizon 10 and at the default 5;
- ``ARX-IMC``: the same law with the linear twin (constant matrices), loop kernel;
- the network with the scheduling signals (the ideal robot's joint angles as cos and sin, its
  joint speeds, the drive torques: 8 more regressors), guarded, loop kernel, default horizon;
- the network on an LPV-ARX base (``identify --lpv-base``: the same network with a bilinear
  input gain affine in the scheduling signals), guarded, loop kernel, default horizon;
- ``LPV-ARX-IMC``: the LPV-ARX model (input gain and offset affine in the scheduling
  signals), guarded, as CasADi SX code (its default) and as the loop kernel.

Times are CPU seconds of this process (``time.process_time``), so other work on a shared
machine inflates them less than wall time.

Without ``--model`` a random network of the default shape (10 outputs, lags 2/2, hidden 13,
14, two inputs) stands in: the cost does not depend on the weights. Writes control_step.md and
control_step.csv with the machine's load average.
"""

from __future__ import annotations

import argparse
import csv
import io
import os
import platform
import time
from pathlib import Path
from typing import Any

import casadi as ca
import numpy as np

from jointplay.common.files import atomic_write_text
from jointplay.neural.imc import (
    STEP_CFLAGS,
    ControllerSettings,
    compile_controller,
    generate_c,
    resolve_settings,
)
from jointplay.neural.narx import Narx
from jointplay.store.build import compile_source
from jointplay.store.model import FastFunction

NAMES = ("q2", "q3", "dq2", "dq3", "tip_x", "tip_y", "tip_vx", "tip_vy", "tip_ax", "tip_ay")
TRACKED = ("tip_x", "tip_vx", "q3", "dq3")


def random_model(seed: int = 0, hidden: tuple[int, ...] = (13, 14)) -> Narx:
    rng = np.random.default_rng(seed)
    ny, nu, na, nb = len(NAMES), 2, 2, 2
    n_phi = na * ny + nb * nu
    widths = [n_phi, *hidden, ny]
    weights = tuple(rng.normal(0, 0.3, (widths[i + 1], widths[i])) for i in range(len(widths) - 1))
    biases = tuple(rng.normal(0, 0.1, w.shape[0]) for w in weights)
    return Narx(output_names=NAMES, output_units=("-",) * ny, input_names=("v2", "v3"),
                input_units=("N m",) * 2, output_lags=na, input_lags=nb, weights=weights,
                biases=biases, regressor_mean=np.zeros(n_phi), regressor_scale=np.ones(n_phi),
                increment_mean=np.zeros(ny), increment_scale=np.full(ny, 1e-3),
                output_scale=np.ones(ny), sample_time=1e-3,
                context={"plant": {"inner_loop": {"joints": [2, 3], "kp": [200.0, 200.0],
                                                  "kd": [5.0, 5.0]},
                                   "torque_limit": [10.0, 5.0]}},
                increment=tuple(not n.startswith("tip_a") for n in NAMES),
                linear=rng.normal(0, 0.1, (ny, n_phi)))


def linear_twin(model: Narx) -> Narx:
    from dataclasses import replace

    rng = np.random.default_rng(1)
    return replace(model, weights=(rng.normal(0, 0.1, (model.n_outputs, model.n_regressor)),),
                   biases=(np.zeros(model.n_outputs),), linear=None)


def with_scheduling(model: Narx, seed: int = 2) -> Narx:
    """The network with the scheduling signals of joints 2 and 3 as further regressors."""
    from jointplay.neural.scheduling import with_random_scheduling

    return with_random_scheduling(model, [2, 3], np.random.default_rng(seed), linear_sd=0.1)


def lpv_model(twin: Narx, seed: int = 3) -> Narx:
    """An LPV-ARX model of the twin's shape: the scheduling signals' offsets and a bilinear
    input gain."""
    from dataclasses import replace

    rng = np.random.default_rng(seed)
    scheduled = with_scheduling(twin, seed)
    ns, n_u = scheduled.n_scheduling, scheduled.n_input_regressors
    return replace(scheduled, bilinear=rng.normal(0, 0.05, (twin.n_outputs, ns * n_u)))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True)
    parser.add_argument("--model", help="a model folder (default: a random network of the "
                                        "default shape)")
    args = parser.parse_args()
    if args.model:
        from jointplay.neural.control import load_lpv, load_twin
        from jointplay.neural.narx import load_narx

        model = load_narx(args.model)
        twin = load_twin(Path(args.model), model)
        lpv = load_lpv(Path(args.model))
        scheduled = model if model.n_scheduling else None
        model = _unscheduled(model)
    else:
        model = random_model()
        twin = linear_twin(model)
        lpv = scheduled = None
    pairs = [_call_overhead(), *_variants(model, twin, scheduled, lpv)]
    rows = _measure(pairs, ROUNDS, CALLS)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=list(rows[0]))
    writer.writeheader()
    writer.writerows(rows)
    atomic_write_text(out / "control_step.csv", buf.getvalue())
    what = f"model {args.model}" if args.model else "random network of the default shape"
    text = _markdown(rows, what)
    atomic_write_text(out / "control_step.md", text)
    print(text)


def _unscheduled(model: Narx) -> Narx:
    """The model without its scheduling regressors (for the variants of the step as it was:
    the cost does not depend on the weights)."""
    from dataclasses import replace

    if not model.n_scheduling:
        return model
    keep = model.n_regressor - model.n_scheduling
    return replace(model, weights=(model.weights[0][:, :keep], *model.weights[1:]),
                   linear=None if model.linear is None else model.linear[:, :keep],
                   regressor_mean=model.regressor_mean[:keep],
                   regressor_scale=model.regressor_scale[:keep], scheduling=(),
                   bilinear=None)


ROUNDS = 15  # rounds over all variants, interleaved: a burst of other work on a shared
CALLS = 20000  # machine then slows every variant's same round, not one variant's whole run


def _call_overhead() -> tuple[dict[str, Any], FastFunction]:
    """A trivial compiled function: the call's cost, the floor under every variant."""
    x = ca.SX.sym("x", 2)
    gen = ca.CodeGenerator("trivial.c", {"with_header": False})
    gen.add(ca.Function("trivial", [x], [2 * x]))
    lib, _ = compile_source(gen.dump())
    trivial = FastFunction(ca.external("trivial", str(lib)))
    return ({"variant": "trivial (call overhead)", "horizon": "-", "guard": "-",
             "code": "SX", "sx_operations": 2, "compile_s": 0.0}, trivial)


def _variants(model: Any, twin: Any, scheduled: Any = None,
              lpv: Any = None) -> list[tuple[dict[str, Any], FastFunction]]:
    """Each way of compiling the controller step: its size, gcc time and compiled call."""
    from dataclasses import replace

    scheduled = scheduled if scheduled is not None else with_scheduling(model)
    lpv = lpv if lpv is not None else lpv_model(twin)
    # A network on an LPV-ARX base (identify --lpv-base): the model's own bilinear part, or
    # one of the LPV-ARX model's shape; the plain scheduled row is the same network without it.
    if scheduled.bilinear is None:
        lpv_based = replace(scheduled, bilinear=lpv_model(twin).bilinear)
    else:
        lpv_based, scheduled = scheduled, replace(scheduled, bilinear=None)
    variants = [
        ("before: CasADi SX code, network only", model, None, False,
         ControllerSettings(horizon=10, guard=False, tracked=TRACKED)),
        ("CasADi SX code, guarded", model, twin, False, ControllerSettings(tracked=TRACKED)),
        ("loop kernel, guarded, horizon 10", model, twin, True,
         ControllerSettings(horizon=10, tracked=TRACKED)),
        ("after: loop kernel, guarded (default)", model, twin, True,
         ControllerSettings(tracked=TRACKED)),
        ("ARX-IMC, loop kernel (default)", twin, None, True, ControllerSettings(
            tracked=TRACKED)),
        ("network with scheduling signals, loop kernel, guarded (default)", scheduled, twin,
         True, ControllerSettings(tracked=TRACKED)),
        ("network on an LPV-ARX base, loop kernel, guarded (default)", lpv_based, twin,
         True, ControllerSettings(tracked=TRACKED)),
        ("LPV-ARX-IMC, CasADi SX code, guarded (default)", lpv, twin, False,
         ControllerSettings(tracked=TRACKED)),
        ("LPV-ARX-IMC, loop kernel, guarded", lpv, twin, True,
         ControllerSettings(tracked=TRACKED))]
    out = []
    for label, m, fallback, kernel, settings in variants:
        settings = resolve_settings(m, settings)
        _, fn, _ = generate_c(m, settings, fallback)
        ctrl = compile_controller(m, settings, fallback=fallback, kernel=kernel)
        ctrl.fast.inputs[3][:] = ctrl.initial_state(np.zeros(ctrl.model.n_outputs))
        out.append(({"variant": label, "horizon": settings.horizon,
                     "guard": "on" if settings.guard else "off",
                     "code": "loops" if kernel else "SX",
                     "sx_operations": fn.n_instructions(),
                     "compile_s": ctrl.compile_seconds}, ctrl.fast))
    return out


def _measure(pairs: list[tuple[dict[str, Any], FastFunction]], rounds: int,
             calls: int) -> list[dict[str, Any]]:
    """CPU time per call of every variant, ``rounds`` rounds of ``calls`` calls each, the
    variants interleaved within a round; the fastest round and the median round."""
    times: list[list[float]] = [[] for _ in pairs]
    for _ in range(rounds):
        for i, (_, fast) in enumerate(pairs):
            t0 = time.process_time()
            for _ in range(calls):
                fast.trigger()
            times[i].append((time.process_time() - t0) / calls * 1e6)
    rows = []
    for (row, _), t in zip(pairs, times, strict=True):
        rows.append({**row, "us_per_call_min": min(t), "us_per_call": float(np.median(t))})
        print(f"{row['variant']}: {min(t):.2f} us fastest, {np.median(t):.2f} median round",
              flush=True)
    return rows


def _markdown(rows: list[dict[str, Any]], what: str) -> str:
    before = rows[1]["us_per_call"]
    lines = [f"Compiled controller step ({what}); "
             f"gcc {' '.join(STEP_CFLAGS)}; {platform.processor() or platform.machine()}, "
             f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f} at the end", "",
             "| variant | horizon | guard | code | SX operations | compile s | CPU µs per call, "
             f"fastest / median of {ROUNDS} rounds | vs before (median) |",
             "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['variant']} | {r['horizon']} | {r['guard']} | {r['code']} | "
                     f"{r['sx_operations']} | "
                     f"{r['compile_s']:.1f} | {r['us_per_call_min']:.2f} / "
                     f"{r['us_per_call']:.2f} | {before / r['us_per_call']:.2f}x |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    main()
