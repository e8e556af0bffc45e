"""One case of the build-scaling benchmark (see build_scaling.py), run in a fresh process:
derive, emit and compile a (structure, k) model into an empty cache, time its functions per
call, and optionally the same C at other optimisation levels."""

from __future__ import annotations

import json
import math
import os
import re
import statistics
import tempfile
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from jointplay.common.files import atomic_write_text
from jointplay.common.timing import per_call_seconds

PAPER = "paper"
SECTION = re.compile(r"^/\* (\w+):\(", re.MULTILINE)
JAC_SECTIONS = ("jac_forward_dynamics", "residual_jacobian")


# ---- the measurement, run in a child process per case ------------------------------------------

def _robot(structure: str, k: int) -> Any:
    import jointplay

    if structure == PAPER:
        return jointplay.default_robot()
    return jointplay.uniform_chain(k, kinds=[structure] * k, name=f"{structure}{k}")


def _section_sizes(source: str) -> dict[str, int]:
    """Bytes of C per CasADi function: from its ``/* name:(...) */`` comment to the next."""
    marks = [(m.start(), m.group(1)) for m in SECTION.finditer(source)]
    sizes: dict[str, int] = {}
    for i, (start, name) in enumerate(marks):
        end = marks[i + 1][0] if i + 1 < len(marks) else len(source)
        sizes[name] = sizes.get(name, 0) + end - start
    return sizes


def _state(model: Any, params: Any, rng: Any) -> Any:
    """A state with every clearance joint in contact (|e| = 1.1 c) and moving."""
    import numpy as np

    layout = model.layout
    n = len(layout.coordinates)
    x = np.zeros(2 * n)
    for i, coordinate in enumerate(layout.coordinates):
        if coordinate.kind == "angle":
            x[i] = rng.uniform(-1.0, 1.0)
            x[n + i] = rng.uniform(-1.0, 1.0)
        elif coordinate.kind == "ex":
            j = coordinate.joint
            c = (params[layout.parameter_slot("joint", j, "bearing_radius")]
                 - params[layout.parameter_slot("joint", j, "journal_radius")])
            phi = rng.uniform(0.0, 2.0 * math.pi)
            x[i], x[i + 1] = 1.1 * c * math.cos(phi), 1.1 * c * math.sin(phi)
            x[n + i], x[n + i + 1] = rng.uniform(-1e-3, 1e-3, size=2)
    return x


def _interleaved(fns: dict[str, Callable[[], Any]], repeats: int, batch_s: float
                 ) -> dict[str, float]:
    """Like :func:`_time_per_call` for several functions, in alternating rounds."""
    rounds = max(3, repeats // 3)
    per_round = max(1, repeats // rounds)
    samples: dict[str, list[float]] = {name: [] for name in fns}
    for _ in range(rounds):
        for name, fn in fns.items():
            samples[name].append(per_call_seconds(fn, per_round, batch_s))
    return {name: statistics.median(values) for name, values in samples.items()}


def _bind(ff: Any, values: Sequence[Any]) -> None:
    for arr, value in zip(ff.inputs, values, strict=False):
        arr[:] = value


def _rel_diff(a: Sequence[Any], b: Sequence[Any]) -> float:
    import numpy as np

    worst = 0.0
    for u, v in zip(a, b, strict=True):
        u, v = np.ravel(u), np.ravel(v)  # shapes may differ (1-D vs n x 1); data order agrees
        scale = max(float(np.max(np.abs(v), initial=0.0)), 1e-300)
        worst = max(worst, float(np.max(np.abs(u - v), initial=0.0)) / scale)
    return worst


def run_case(spec: dict[str, Any]) -> dict[str, Any]:
    """Measure one (structure, k); ``spec`` holds structure, k, levels, repeats, batch_s."""
    import resource

    with tempfile.TemporaryDirectory(prefix="jointplay-bench-") as tmp_name:
        tmp = Path(tmp_name)
        cache = tmp / "cache"
        os.environ["JOINTPLAY_CACHE"] = str(cache)  # load_model compiles through cache_root()
        built = _cold_build(spec, tmp, cache)
        calls = _prepared_calls(built.model, built.params)
        repeats, batch_s = spec["repeats"], spec["batch_s"]
        per_call = _per_call(calls, repeats, batch_s)
        row: dict[str, Any] = {
            "structure": spec["structure"],
            "k": spec["k"],
            "n_coords": built.model.n_coordinates,
            "n_params": len(built.model.parameters),
            "derive_s": built.emitted.timings["derive"],
            "kane_s": built.emitted.timings.get("kane", math.nan),
            "emit_s": built.emitted.timings["emit"],
            "c_kb": len(built.source.encode()) / 1024,
            "jac_c_kb": built.jac_bytes / 1024,
            "compile_s": built.compile_s,
            "so_kb": built.library.stat().st_size / 1024,
            "total_s": built.wall_emit + built.compile_s,
            **{key: value * 1e6 for key, value in per_call.items()},
            "gcc_rss_mb": built.gcc_rss_mb,
            "py_rss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
            "import_s": built.import_s,
            "load_start": built.load_at_start,
            "load_end": os.getloadavg()[0],
            "cache_hit": built.cache_hit,
            "finite": calls.finite,
            "sections_kb": {name: round(b / 1024, 1) for name, b in built.sizes.items()},
        }
        row["flags"] = _flag_variants(spec, built, calls, cache) if spec["levels"] else []
        return row


@dataclass
class _Built:
    """One model built from a cold start, with what its build cost."""

    emitted: Any
    source: str
    sizes: dict[str, int]
    jac_bytes: int
    library: Path
    compile_s: float
    wall_emit: float
    gcc_rss_mb: float
    import_s: float
    load_at_start: float
    model: Any
    params: Any
    cache_hit: bool


def _cold_build(spec: dict[str, Any], tmp: Path, cache: Path) -> _Built:
    """Derive, emit, write and compile the (structure, k) model into an empty cache; load it."""
    import resource

    t_import = time.perf_counter()
    import casadi  # noqa: F401  (timed with the rest)
    import numpy as np

    from jointplay.derive import emit
    from jointplay.robot.robotio import robot_to_toml
    from jointplay.store.build import DEFAULT_CFLAGS, compile_source
    from jointplay.store.model import LAYOUT_NAME, ROBOT_NAME, SOURCE_NAME, load_model
    import_s = time.perf_counter() - t_import

    robot = _robot(spec["structure"], spec["k"])
    load_at_start = os.getloadavg()[0]
    t0 = time.perf_counter()
    emitted = emit(robot)
    wall_emit = time.perf_counter() - t0
    source = emitted.source
    sizes = _section_sizes(source)

    folder = tmp / "model"
    folder.mkdir()
    atomic_write_text(folder / SOURCE_NAME, source)
    atomic_write_text(folder / LAYOUT_NAME, json.dumps(emitted.layout, indent=1) + "\n")
    atomic_write_text(folder / ROBOT_NAME, robot_to_toml(robot))

    library, compile_s = compile_source(source, DEFAULT_CFLAGS, cache=cache)
    gcc_rss_mb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    model = load_model(folder)  # must be a cache hit on the build just made
    return _Built(emitted=emitted, source=source, sizes=sizes,
                  jac_bytes=sum(sizes.get(name, 0) for name in JAC_SECTIONS),
                  library=library, compile_s=compile_s, wall_emit=wall_emit,
                  gcc_rss_mb=gcc_rss_mb, import_s=import_s, load_at_start=load_at_start,
                  model=model, params=np.asarray(robot.parameter_values(), dtype=float),
                  cache_hit=model.compile_seconds == 0.0 and model.library == library)


@dataclass
class _Calls:
    """Both functions bound to one state in contact, with their outputs there."""

    fd: Any
    jac: Any
    fd_args: list[Any]
    jac_args: list[Any]
    finite: bool
    reference: list[Any]


def _prepared_calls(model: Any, params: Any) -> _Calls:
    import numpy as np

    rng = np.random.default_rng(1)
    x = _state(model, params, rng)
    tau = rng.uniform(-1.0, 1.0, size=len(model.torque_joints))
    v_imp = np.full(len(model.clearance_joints), 0.05)
    fd_args = [x, tau, params, v_imp]
    jac_args = [*fd_args, np.zeros(0)]

    fd = model.function("forward_dynamics")
    jac = model.function("jac_forward_dynamics")
    _bind(fd, fd_args)
    _bind(jac, jac_args)
    fd.trigger()
    jac.trigger()
    finite = bool(all(np.all(np.isfinite(o)) for o in (*fd.outputs, *jac.outputs)))
    return _Calls(fd=fd, jac=jac, fd_args=fd_args, jac_args=jac_args, finite=finite,
                  reference=[fd(*fd_args), jac(*jac_args)])


def _per_call(calls: _Calls, repeats: int, batch_s: float) -> dict[str, float]:
    """Seconds per call of each calling path."""
    fd, jac, fd_args, jac_args = calls.fd, calls.jac, calls.fd_args, calls.jac_args
    return {
        "fd_trigger_us": per_call_seconds(fd.trigger, repeats, batch_s),
        "jac_trigger_us": per_call_seconds(jac.trigger, repeats, batch_s),
        "fd_call_us": per_call_seconds(lambda: fd(*fd_args), repeats, batch_s),
        "jac_call_us": per_call_seconds(lambda: jac(*jac_args), repeats, batch_s),
        "fd_casadi_us": per_call_seconds(lambda: fd.function(*fd_args), repeats, batch_s),
    }


def _flag_variants(spec: dict[str, Any], built: _Built, calls: _Calls, cache: Path
                   ) -> list[dict[str, Any]]:
    """The same C at each of ``spec["levels"]`` beside the default build: compile time, size,
    per-call cost (interleaved rounds) and the largest output difference."""
    import casadi as ca

    from jointplay.store.build import DEFAULT_CFLAGS, compile_source
    from jointplay.store.model import FastFunction

    repeats, batch_s = spec["repeats"], spec["batch_s"]
    variants: dict[str, tuple[tuple[str, ...], float, Path, Any, Any]] = {
        " ".join(DEFAULT_CFLAGS): (DEFAULT_CFLAGS, built.compile_s, built.library, calls.fd,
                                   calls.jac)}
    for level in spec["levels"]:
        words = level.split()
        cflags = tuple(w for f in DEFAULT_CFLAGS
                       for w in (words if f.startswith("-O") else [f]))
        lib, seconds = compile_source(built.source, cflags, cache=cache)
        vfd = FastFunction(ca.external("forward_dynamics", str(lib)))
        vjac = FastFunction(ca.external("jac_forward_dynamics", str(lib)))
        _bind(vfd, calls.fd_args)
        _bind(vjac, calls.jac_args)
        variants[" ".join(cflags)] = (cflags, seconds, lib, vfd, vjac)
    timed_fd = _interleaved({k: v[3].trigger for k, v in variants.items()}, repeats, batch_s)
    timed_jac = _interleaved({k: v[4].trigger for k, v in variants.items()}, repeats, batch_s)
    flags = []
    for key, (cflags, seconds, lib, vfd, vjac) in variants.items():
        out = [vfd(*calls.fd_args), vjac(*calls.jac_args)]
        flags.append({
            "structure": spec["structure"],
            "k": spec["k"],
            "opt": " ".join(f for f in cflags if f not in DEFAULT_CFLAGS or f.startswith("-O")),
            "cflags": key,
            "compile_s": seconds,
            "so_kb": lib.stat().st_size / 1024,
            "fd_trigger_us": timed_fd[key] * 1e6,
            "jac_trigger_us": timed_jac[key] * 1e6,
            "max_rel_diff": _rel_diff([*out[0], *out[1]],
                                      [*calls.reference[0], *calls.reference[1]]),
        })
    return flags
