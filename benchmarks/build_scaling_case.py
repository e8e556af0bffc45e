"""One case of the build-scaling benchmark (see build_scaling.py), run in a fresh process:
derive, emit and compile a (structure, k) model into an empty cache, each stage reported to
the parent (:func:`jointplay.bench.child.report_stage`) with its peak memory, time its
functions per call beside Pinocchio's on the same chain, and optionally the same C at other
optimisation levels."""

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
JAC_SECTIONS = ("jac_forward_dynamics", "residual_jacobian")  # a model.c of one library


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
    """Seconds per call of each of ``fns`` (:func:`per_call_seconds`), in alternating rounds:
    the median over the rounds of each round's median."""
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
    """Measure one (structure, k); ``spec`` holds structure, k, formulation (None: the
    default), levels, repeats, batch_s and pinocchio (whether to time it beside)."""
    import resource

    from jointplay.bench.child import report_stage

    with tempfile.TemporaryDirectory(prefix="jointplay-bench-") as tmp_name:
        tmp = Path(tmp_name)
        cache = tmp / "cache"
        os.environ["JOINTPLAY_CACHE"] = str(cache)  # load_model compiles through cache_root()
        built = _cold_build(spec, tmp, cache)
        row: dict[str, Any] = {
            "structure": spec["structure"],
            "k": spec["k"],
            "formulation": built.formulation,
            "n_coords": built.model.n_coordinates,
            "n_params": len(built.model.parameters),
            "derive_s": built.emitted.timings["derive"],
            "kane_s": built.emitted.timings.get("kane", math.nan),
            "emit_s": built.emitted.timings["emit"],
            "c_kb": len(built.source.encode()) / 1024,
            "jac_c_kb": built.jac_bytes / 1024,
            "compile_s": built.compile_s,
            "deferred_c_kb": len(built.emitted.deferred_source.encode()) / 1024,
            "deferred_compile_s": built.deferred_compile_s,
            "compile_cpu_s": built.compile_cpu_s,
            "deferred_cpu_s": built.deferred_cpu_s,
            "so_kb": built.library.stat().st_size / 1024,
            "total_s": built.wall_emit + built.compile_s,
            **built.memory,
            "import_s": built.import_s,
            "load_start": built.load_at_start,
            "cache_hit": built.cache_hit,
            "sections_kb": {name: round(b / 1024, 1) for name, b in built.sizes.items()},
        }
        report_stage("timing", clock="timing", **{k: v for k, v in row.items()
                                                   if k != "sections_kb"})
        calls = _prepared_calls(built.model, built.params)
        repeats, batch_s = spec["repeats"], spec["batch_s"]
        peer = pinocchio_chain(_robot(spec["structure"], spec["k"])) if (
            spec.get("pinocchio", True) and spec["structure"] != PAPER) else None
        row.update({key: value * 1e6 for key, value in
                    _per_call(calls, peer, repeats, batch_s).items()})
        row["pin_nv"] = peer.nv if peer is not None else None
        row["pin_version"] = peer.version if peer is not None else None
        row["py_rss_mb"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
        row["load_end"] = os.getloadavg()[0]
        row["finite"] = calls.finite
        if spec["levels"]:
            report_stage("flags", clock="timing")
        row["flags"] = _flag_variants(spec, built, calls, cache) if spec["levels"] else []
        return row


# ---- peak memory of a stage -------------------------------------------------------------------

def _reset_peak() -> bool:
    """Reset this process's resident high-water mark (Linux: ``clear_refs`` 5)."""
    try:
        with open("/proc/self/clear_refs", "w") as fh:
            fh.write("5")
        return True
    except OSError:
        return False


def _peak_mib() -> float:
    """This process's resident high-water mark (MiB) since the last reset."""
    import resource

    try:
        with open("/proc/self/status") as fh:
            for line in fh:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) / 1024
    except OSError:
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


class _DescendantPeak:
    """While open, samples every ``interval_s`` the resident memory of this process's
    descendants (gcc, cc1, as) and of this process with them; their peaks in MiB.

    Sampled rather than read from ``getrusage(RUSAGE_CHILDREN)``: a child's ``ru_maxrss``
    starts from the resident size of the Python process it was forked from, which would
    hide a compiler smaller than that."""

    def __init__(self, interval_s: float = 0.02) -> None:
        import threading

        self.interval_s = interval_s
        self.descendants_mib = 0.0
        self.with_self_mib = 0.0
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)

    def __enter__(self) -> _DescendantPeak:
        self._thread.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self._stop.set()
        self._thread.join()

    def _run(self) -> None:
        page = os.sysconf("SC_PAGE_SIZE") / (1 << 20)
        me = os.getpid()
        while True:
            parent_rss: dict[int, tuple[int, int]] = {}
            for entry in os.scandir("/proc"):
                if entry.name.isdigit():
                    try:
                        with open(f"/proc/{entry.name}/stat", "rb") as fh:
                            fields = fh.read().rsplit(b")", 1)[1].split()
                    except OSError:
                        continue
                    parent_rss[int(entry.name)] = (int(fields[1]), int(fields[21]))
            family, grew = {me}, True
            while grew:
                grew = False
                for pid, (ppid, _) in parent_rss.items():
                    if ppid in family and pid not in family:
                        family.add(pid)
                        grew = True
            below = sum(parent_rss[p][1] for p in family - {me} if p in parent_rss) * page
            own = parent_rss.get(me, (0, 0))[1] * page
            self.descendants_mib = max(self.descendants_mib, below)
            self.with_self_mib = max(self.with_self_mib, below + own)
            if self._stop.wait(self.interval_s):
                return


@dataclass
class _Built:
    """One model built from a cold start, with what its build cost."""

    emitted: Any
    formulation: str
    source: str
    sizes: dict[str, int]
    jac_bytes: int
    library: Path
    compile_s: float
    wall_emit: float
    memory: dict[str, float | None]
    import_s: float
    load_at_start: float
    model: Any
    params: Any
    cache_hit: bool
    deferred_compile_s: float = 0.0  # the deferred library's gcc time, at its first use
    compile_cpu_s: float = 0.0  # gcc's CPU time (user + system), all its processes
    deferred_cpu_s: float = 0.0


def _emit_by_stage(robot: Any, formulation: str | None) -> tuple[Any, dict[str, float | None]]:
    """``emit(robot)`` with the derivation and the emission reported as stages of their own,
    each with its peak resident memory (the derivation's only when ``emit`` derives through
    ``codegen.derive``; otherwise ``emit_mib`` spans both and ``derive_mib`` is None)."""
    from jointplay.bench.child import report_stage
    from jointplay.derive import codegen

    memory: dict[str, float | None] = {"derive_mib": None}
    original = codegen.derive

    def derive_as_a_stage(*args: Any, **kwargs: Any) -> Any:
        _reset_peak()
        model = original(*args, **kwargs)
        memory["derive_mib"] = _peak_mib()
        report_stage("emit", clock="build", derive_mib=memory["derive_mib"])
        _reset_peak()
        return model

    report_stage("derive", clock="build")
    _reset_peak()
    codegen.derive = derive_as_a_stage
    try:
        emitted = codegen.emit(robot, formulation)
    finally:
        codegen.derive = original
    memory["emit_mib"] = _peak_mib()
    return emitted, memory


def _children_cpu() -> float:
    """CPU seconds (user + system) of this process's finished child processes."""
    import resource

    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def _cold_build(spec: dict[str, Any], tmp: Path, cache: Path) -> _Built:
    """Derive, emit, write and compile the (structure, k) model into an empty cache; load it."""

    from jointplay.bench.child import report_stage

    t_import = time.perf_counter()
    import casadi  # noqa: F401  (timed with the rest)
    import numpy as np

    from jointplay.robot.robotio import robot_to_toml
    from jointplay.store.build import DEFAULT_CFLAGS, compile_source
    from jointplay.store.model import (
        DEFERRED_SOURCE_NAME,
        LAYOUT_NAME,
        ROBOT_NAME,
        SOURCE_NAME,
        load_model,
    )
    import_s = time.perf_counter() - t_import

    robot = _robot(spec["structure"], spec["k"])
    load_at_start = os.getloadavg()[0]
    t0 = time.perf_counter()
    emitted, memory = _emit_by_stage(robot, spec.get("formulation"))
    wall_emit = time.perf_counter() - t0
    formulation = str(emitted.layout.get("provenance", {}).get("formulation", "closed"))
    source = emitted.source
    sizes = _section_sizes(source)

    folder = tmp / "model"
    folder.mkdir()
    atomic_write_text(folder / SOURCE_NAME, source)
    if emitted.deferred_source:
        atomic_write_text(folder / DEFERRED_SOURCE_NAME, emitted.deferred_source)
    atomic_write_text(folder / LAYOUT_NAME, json.dumps(emitted.layout, indent=1) + "\n")
    atomic_write_text(folder / ROBOT_NAME, robot_to_toml(robot))

    report_stage("gcc", clock="build", formulation=formulation,
                 derive_s=emitted.timings["derive"], emit_s=emitted.timings["emit"],
                 c_kb=len(source.encode()) / 1024, **memory)
    cpu_before = _children_cpu()
    with _DescendantPeak() as during_gcc:  # this process stays resident while gcc runs
        library, compile_s = compile_source(source, DEFAULT_CFLAGS, cache=cache)
    compile_cpu_s = _children_cpu() - cpu_before
    memory["gcc_mib"] = during_gcc.descendants_mib
    memory["build_peak_mib"] = max(memory["derive_mib"] or 0.0, memory["emit_mib"] or 0.0,
                                   during_gcc.with_self_mib)
    report_stage("load", clock="build", compile_s=compile_s, **memory)
    model = load_model(folder)  # must be a cache hit on the build just made
    # The deferred library (the Jacobian's input blocks), compiled on its first use, after the
    # build: integration does not wait for it.
    cpu_before = _children_cpu()
    model.function("jac_forward_dynamics")
    deferred_cpu_s = _children_cpu() - cpu_before
    return _Built(emitted=emitted, formulation=formulation, source=source, sizes=sizes,
                  jac_bytes=sum(sizes.get(name, 0) for name in JAC_SECTIONS),
                  library=library, compile_s=compile_s, wall_emit=wall_emit,
                  memory=memory, import_s=import_s, load_at_start=load_at_start,
                  model=model, params=np.asarray(robot.parameter_values(), dtype=float),
                  cache_hit=model.compile_seconds == 0.0 and model.library == library,
                  deferred_compile_s=model.deferred_compile_seconds,
                  compile_cpu_s=compile_cpu_s, deferred_cpu_s=deferred_cpu_s)


@dataclass
class _Calls:
    """The functions bound to one state in contact, with their outputs there."""

    fd: Any
    jac: Any
    jac_state: Any
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
    jac_state = model.function("jac_state")
    _bind(fd, fd_args)
    _bind(jac, jac_args)
    _bind(jac_state, fd_args)
    outputs = []
    for fn in (fd, jac, jac_state):
        fn.trigger()
        outputs += list(fn.outputs)
    finite = bool(all(np.all(np.isfinite(o)) for o in outputs))
    return _Calls(fd=fd, jac=jac, jac_state=jac_state, fd_args=fd_args, jac_args=jac_args,
                  finite=finite, reference=[fd(*fd_args), jac(*jac_args),
                                            jac_state(*fd_args)])


# ---- Pinocchio on the same chain ---------------------------------------------------------------

@dataclass(frozen=True)
class PinocchioChain:
    """Pinocchio's ``aba`` and ``computeABADerivatives`` on a chain standing in for a robot,
    each a call without arguments (like ``FastFunction.trigger``) on a fixed random state."""

    aba: Callable[[], Any]
    derivatives: Callable[[], Any]
    nv: int
    version: str


def pinocchio_chain(robot: Any) -> PinocchioChain | None:
    """A planar joint (x, y, theta: the 3 coordinates a clearance joint spans) for each
    clearance joint, a revolute joint about z for each ideal one, the links' masses, centres
    and inertias; None where Pinocchio is not installed."""
    try:
        import pinocchio as pin
    except ImportError:
        return None
    import numpy as np

    model = pin.Model()
    parent, offset = 0, 0.0
    for i, (link, joint) in enumerate(zip(robot.links, robot.joints, strict=True), start=1):
        kind = pin.JointModelPlanar() if joint.kind == "clearance" else pin.JointModelRZ()
        jid = model.addJoint(parent, kind, pin.SE3(np.eye(3), np.array([offset, 0.0, 0.0])),
                             f"joint{i}")
        inertia = np.diag([link.inertia + 0.5, link.inertia + 0.7, link.inertia])
        model.appendBodyToJoint(jid, pin.Inertia(link.mass, np.array([link.com, 0.0, 0.0]),
                                                 inertia), pin.SE3.Identity())
        parent, offset = jid, link.length
    data = model.createData()
    rng = np.random.default_rng(1)
    q = pin.randomConfiguration(model, -np.ones(model.nq), np.ones(model.nq))
    v = rng.uniform(-1.0, 1.0, model.nv)
    tau = rng.uniform(-1.0, 1.0, model.nv)
    return PinocchioChain(aba=lambda: pin.aba(model, data, q, v, tau),
                          derivatives=lambda: pin.computeABADerivatives(model, data, q, v, tau),
                          nv=int(model.nv), version=str(pin.__version__))


def _per_call(calls: _Calls, peer: PinocchioChain | None, repeats: int, batch_s: float
              ) -> dict[str, float]:
    """Seconds per call. jointplay's functions through ``FastFunction.trigger`` and
    Pinocchio's, each a Python call without arguments, are timed in alternating rounds (so
    a change in the machine's load hits them alike), the same batches and the same median;
    then jointplay's other calling paths."""
    side_by_side: dict[str, Callable[[], Any]] = {
        "fd_trigger_us": calls.fd.trigger, "jac_state_us": calls.jac_state.trigger,
        "jac_trigger_us": calls.jac.trigger}
    if peer is not None:
        side_by_side.update(pin_aba_us=peer.aba, pin_derivatives_us=peer.derivatives)
    fd, jac, fd_args, jac_args = calls.fd, calls.jac, calls.fd_args, calls.jac_args
    return {
        **_interleaved(side_by_side, repeats, batch_s),
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
                                   calls.jac_state)}
    for level in spec["levels"]:
        words = level.split()
        cflags = tuple(w for f in DEFAULT_CFLAGS
                       for w in (words if f.startswith("-O") else [f]))
        lib, seconds = compile_source(built.source, cflags, cache=cache)
        vfd = FastFunction(ca.external("forward_dynamics", str(lib)))
        # The state Jacobian: the eager library's (the full one is in the deferred library).
        vjac = FastFunction(ca.external("jac_state", str(lib)))
        _bind(vfd, calls.fd_args)
        _bind(vjac, calls.fd_args)
        variants[" ".join(cflags)] = (cflags, seconds, lib, vfd, vjac)
    timed_fd = _interleaved({k: v[3].trigger for k, v in variants.items()}, repeats, batch_s)
    timed_jac = _interleaved({k: v[4].trigger for k, v in variants.items()}, repeats, batch_s)
    flags = []
    for key, (cflags, seconds, lib, vfd, vjac) in variants.items():
        out = [vfd(*calls.fd_args), vjac(*calls.fd_args)]
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
                                      [*calls.reference[0], *calls.reference[2]]),
        })
    return flags
