"""The slider-crank's model beside a serial chain with the same number of coordinates, and the
first revolution's accuracy and cost.

Part 1, the model: derivation and emission, gcc, and the per-call cost of the forward dynamics
and of its state Jacobian (the two functions integration calls), for the slider-crank
(scenes/slider_crank.toml: slider position, rod angle and the clock, 3 coordinates) and for
the one-link chain with a clearance joint (angle and eccentricity, 3 coordinates), built in
one run into a fresh cache, side by side.

Part 2, the first revolution (0.012 s): for each tolerance (rtol = atol), the slider's largest
difference from the same run 100x tighter, the impacts, steps, and the wall time (median of
five) of the integration in C and of the whole call (set-up, integration, and the outputs at
the 1201 samples).

    python benchmarks/mechanism_cost.py [--out FILE.json]

Wall times depend on the machine and its load; compare the ratios within one run.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import tempfile
import time
from pathlib import Path
from typing import Any

import numpy as np

SCENES = ("scenes/slider_crank.toml", "scenes/slider_crank_0_1mm.toml")
TOLERANCES = (1e-6, 1e-7, 1e-8, 1e-9, 1e-10)


def _per_call(function: Any, inputs: list[np.ndarray]) -> float:
    from jointplay.common.timing import per_call_seconds

    for slot, value in zip(function.inputs, inputs, strict=True):
        slot[:] = value
    return per_call_seconds(function.trigger)


def model_rows() -> list[dict[str, Any]]:
    import casadi as ca

    import jointplay
    from jointplay.derive.codegen import emit as emit_chain
    from jointplay.derive.mechanism import emit as emit_mechanism
    from jointplay.mechanism.model import MechanismModel, input_hash
    from jointplay.mechanism.reading import load_mechanism_scene
    from jointplay.store.build import DEFAULT_CFLAGS, compile_source
    from jointplay.store.model import FastFunction

    rows = []
    scene = load_mechanism_scene(SCENES[0])
    structure = scene.mechanism.structure()
    t0 = time.perf_counter()
    source = emit_mechanism(structure, scene.name, input_hash(structure))
    t1 = time.perf_counter()
    library, compile_s = compile_source(source, DEFAULT_CFLAGS)
    model = MechanismModel(scene.name, structure, library, {})
    p = model.parameter_vector(scene.mechanism)
    from jointplay.mechanism.simulate import assembled_state

    x = assembled_state(model, p)
    v = np.zeros(1)
    rows.append({"model": "slider-crank (mechanism)", "coordinates": model.n_coordinates,
                 "derive_emit_s": t1 - t0, "compile_s": compile_s, "c_kb": len(source) / 1e3,
                 "forward_dynamics_us": 1e6 * _per_call(model.function("forward_dynamics"),
                                                        [x, np.zeros(0), p, v]),
                 "jacobian_us": 1e6 * _per_call(model.function("jac_forward_dynamics"),
                                                [x, np.zeros(0), p, v])})
    robot = jointplay.uniform_chain(1, kinds=["clearance"], name="chain_clearance1")
    t0 = time.perf_counter()
    emitted = emit_chain(robot)
    t1 = time.perf_counter()
    library, compile_s = compile_source(emitted.source, DEFAULT_CFLAGS)
    fd = FastFunction(ca.external("forward_dynamics", str(library)))
    # The state block of the Jacobian, the function the integrator calls for a chain.
    jac = FastFunction(ca.external("jac_state", str(library)))
    n = len(emitted.layout["coordinates"])
    state = np.zeros(2 * n)
    state[1] = 0.9 * (robot.joints[0].bearing_radius - robot.joints[0].journal_radius)
    p_chain = np.asarray(robot.parameter_values())
    inputs = [state, np.zeros(fd.function.nnz_in(1)), p_chain, np.zeros(1)]
    rows.append({"model": "one-link chain, clearance joint", "coordinates": n,
                 "derive_emit_s": t1 - t0, "compile_s": compile_s,
                 "c_kb": len(emitted.source) / 1e3,
                 "forward_dynamics_us": 1e6 * _per_call(fd, inputs),
                 "jacobian_us": 1e6 * _per_call(jac, inputs)})
    return rows


def revolution_rows() -> list[dict[str, Any]]:
    from jointplay.mechanism.model import model_for
    from jointplay.mechanism.reading import load_mechanism_scene
    from jointplay.mechanism.simulate import simulate_mechanism

    rows = []
    for path in SCENES:
        scene = load_mechanism_scene(path).with_run(t_end=0.012)
        model = model_for(scene.mechanism)
        for tol in TOLERANCES:
            run = scene.with_run(rtol=tol, atol=tol)
            walls, calls = [], []
            for _ in range(5):
                started = time.perf_counter()
                result = simulate_mechanism(run, model=model)
                calls.append(time.perf_counter() - started)
                walls.append(result.stats["wall_time_s"])
            reference = simulate_mechanism(scene.with_run(rtol=tol / 100, atol=tol / 100,
                                                          max_steps=10**7), model=model)
            error = np.max(np.abs(result.coordinate("guide.position")
                                  - reference.coordinate("guide.position")))
            rows.append({"scene": Path(path).stem, "tolerance": tol,
                         "slider_error_m": float(error), "impacts": len(result.impacts),
                         "reference_impacts": len(reference.impacts),
                         "steps": int(result.stats["steps"]),
                         "wall_s": statistics.median(walls),
                         "call_s": statistics.median(calls)})
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", help="also write the rows as JSON")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as cache:
        previous = os.environ.get("JOINTPLAY_CACHE")
        os.environ["JOINTPLAY_CACHE"] = cache  # a fresh cache: every build is measured
        try:
            models = model_rows()
            revolutions = revolution_rows()
        finally:
            if previous is None:
                os.environ.pop("JOINTPLAY_CACHE", None)
            else:
                os.environ["JOINTPLAY_CACHE"] = previous
    print("| model | coordinates | derive + emit (s) | gcc (s) | C (kB) | forward dynamics "
          "(µs/call) | state Jacobian (µs/call) |")
    print("|---|---|---|---|---|---|---|")
    for r in models:
        print(f"| {r['model']} | {r['coordinates']} | {r['derive_emit_s']:.2f} | "
              f"{r['compile_s']:.2f} | {r['c_kb']:.0f} | {r['forward_dynamics_us']:.2f} | "
              f"{r['jacobian_us']:.2f} |")
    print()
    print("| scene | rtol = atol | slider error vs 100x tighter (m) | impacts (reference) | "
          "steps | integration (s) | whole call (s) |")
    print("|---|---|---|---|---|---|---|")
    for r in revolutions:
        print(f"| {r['scene']} | {r['tolerance']:g} | {r['slider_error_m']:.2g} | "
              f"{r['impacts']} ({r['reference_impacts']}) | {r['steps']} | "
              f"{r['wall_s']:.3f} | {r['call_s']:.3f} |")
    if args.out:
        from jointplay.common.files import atomic_write_text

        atomic_write_text(args.out, json.dumps({"models": models,
                                                "first_revolution": revolutions}, indent=1))


if __name__ == "__main__":
    main()
