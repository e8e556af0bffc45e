"""The slider-crank's model beside a serial chain with the same number of coordinates, and the
first revolution's accuracy and cost.

Part 1, the model: derivation and emission, gcc, and the per-call cost of the forward dynamics
and of its state Jacobian (the two functions integration calls), for the slider-crank
(scenes/slider_crank.toml: slider position, rod angle and the clock, 3 coordinates) beside
the one-link chain with a clearance joint (angle and eccentricity, 3 coordinates), and for
the slider-crank with play at both of the rod's pins (the rod floats: 5 coordinates, two
contacts) beside the three-link chain with clearance at joint 1 (5 coordinates, one contact)
and the two-link chain with two clearance joints (6 coordinates, two contacts), built in one
run into a fresh cache, side by side.

Part 2, the first revolution (0.012 s): for each tolerance (rtol = atol), the slider's largest
difference from the same run 100x tighter, the impacts, steps, and the wall time (median of
five) of the integration in C and of the whole call (set-up, integration, and the outputs at
the 1201 samples).

    python benchmarks/mechanism_cost.py [--out FILE.json]

Wall times depend on the machine and its load; compare the ratios within one run. Per-call
costs are CPU time, the median of seven rounds in which every model is timed once.
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

from jointplay.common.timing import per_call_seconds

SCENES = ("scenes/slider_crank.toml", "scenes/slider_crank_0_1mm.toml")
TOLERANCES = (1e-6, 1e-7, 1e-8, 1e-9, 1e-10)


def _cpu_per_call(function: Any, inputs: list[np.ndarray]) -> float:
    """CPU seconds per call (``time.process_time``), the median of calibrated batches."""
    for slot, value in zip(function.inputs, inputs, strict=True):
        slot[:] = value
    return per_call_seconds(function.trigger, clock=time.process_time)


def _timed(rows: list[dict[str, Any]], rounds: int = 7) -> None:
    """Per-call CPU time of each row's two functions, measured in interleaved rounds (every
    model once a round, so that the machine's load falls on all alike): the medians."""
    samples: dict[tuple[int, str], list[float]] = {}
    for _ in range(rounds):
        for i, row in enumerate(rows):
            for key in ("forward_dynamics", "jacobian"):
                function, inputs = row[f"_{key}"]
                samples.setdefault((i, key), []).append(_cpu_per_call(function, inputs))
    for i, row in enumerate(rows):
        for key in ("forward_dynamics", "jacobian"):
            row[f"{key}_us"] = 1e6 * statistics.median(samples[(i, key)])
            del row[f"_{key}"]


# The rod's crank pin given play too: the rod then floats between two clearance joints.
BOTH_PINS = ('name = "crank_pin"             # crank - rod, ideal\ntype = "revolute"',
             'name = "crank_pin"\ntype = "revolute"\nkind = "clearance"\n'
             'bearing_radius = 10.5e-3\njournal_radius = 10.0e-3')


def _mechanism_row(label: str, text: str) -> dict[str, Any]:
    import tomllib

    from jointplay.derive.mechanism import emit
    from jointplay.mechanism.model import MechanismModel, input_hash
    from jointplay.mechanism.reading import mechanism_scene_from_dict
    from jointplay.mechanism.simulate import assembled_state
    from jointplay.store.build import DEFAULT_CFLAGS, compile_source

    scene = mechanism_scene_from_dict(tomllib.loads(text))
    structure = scene.mechanism.structure()
    t0 = time.perf_counter()
    source = emit(structure, scene.name, input_hash(structure))
    t1 = time.perf_counter()
    library, compile_s = compile_source(source, DEFAULT_CFLAGS)
    model = MechanismModel(scene.name, structure, library, {})
    p = model.parameter_vector(scene.mechanism)
    x = assembled_state(model, p, start=scene.initial)
    inputs = [x, np.zeros(0), p, np.zeros(len(model.clearance_joints))]
    return {"model": label, "coordinates": model.n_coordinates, "derive_emit_s": t1 - t0,
            "compile_s": compile_s, "c_kb": len(source) / 1e3,
            "_forward_dynamics": (model.function("forward_dynamics"), inputs),
            "_jacobian": (model.function("jac_forward_dynamics"), inputs)}


def _chain_row(label: str, kinds: list[str]) -> dict[str, Any]:
    import casadi as ca

    import jointplay
    from jointplay.derive.codegen import emit
    from jointplay.store.build import DEFAULT_CFLAGS, compile_source
    from jointplay.store.model import FastFunction

    robot = jointplay.uniform_chain(len(kinds), kinds=kinds, name=f"chain_{len(kinds)}")
    t0 = time.perf_counter()
    emitted = emit(robot)
    t1 = time.perf_counter()
    library, compile_s = compile_source(emitted.source, DEFAULT_CFLAGS)
    fd = FastFunction(ca.external("forward_dynamics", str(library)))
    # The state block of the Jacobian, the function the integrator calls for a chain.
    jac = FastFunction(ca.external("jac_state", str(library)))
    n = len(emitted.layout["coordinates"])
    state = np.zeros(2 * n)
    state[1] = 0.9 * (robot.joints[0].bearing_radius - robot.joints[0].journal_radius)
    inputs = [state, np.zeros(fd.function.nnz_in(1)), np.asarray(robot.parameter_values()),
              np.zeros(fd.function.nnz_in(3))]
    return {"model": label, "coordinates": n, "derive_emit_s": t1 - t0,
            "compile_s": compile_s, "c_kb": len(emitted.source) / 1e3,
            "_forward_dynamics": (fd, inputs), "_jacobian": (jac, inputs)}


def model_rows() -> list[dict[str, Any]]:
    text = Path(SCENES[0]).read_text(encoding="utf-8")
    assert BOTH_PINS[0] in text, "scenes/slider_crank.toml's crank pin has changed"
    rows = [
        _mechanism_row("slider-crank, play at the slider's pin", text),
        _chain_row("one-link chain, clearance joint", ["clearance"]),
        _mechanism_row("slider-crank, play at both of the rod's pins",
                       text.replace(*BOTH_PINS)),
        _chain_row("three-link chain, clearance at joint 1", ["clearance", "ideal", "ideal"]),
        _chain_row("two-link chain, two clearance joints", ["clearance", "clearance"]),
    ]
    _timed(rows)
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
          "(CPU µs/call) | state Jacobian (CPU µs/call) |")
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
