"""How derivation, emission, compilation and evaluation scale with the number of links.

For every link count k and every structure (``clearance``: clearance at every joint;
``ideal``: every joint ideal), plus the paper robot (``jointplay.default_robot()``), this
measures, each case in a fresh Python process (so sympy's caches start cold) and a fresh
temporary compile cache:

* sympy derivation time (Kane's method), CasADi emission time (SX graphs + C text);
* the C file size, split into the part behind ``jac_forward_dynamics`` (its own body plus the
  ``residual_jacobian`` it calls) and the rest;
* gcc compile time with the project's default flags (``jointplay.store.build.DEFAULT_CFLAGS``);
* per-call cost of ``forward_dynamics`` and ``jac_forward_dynamics`` through
  ``FastFunction.trigger`` (inputs written in place; median over repeated batches), through
  ``FastFunction.__call__`` with numpy arrays, and through the plain CasADi ``Function`` call.

With ``--flags-compare`` it also compiles the same C with the default flags' ``-O1`` replaced
by each of ``--compare-levels`` (default ``-O0,-O2,-O3``; an item may add -f flags, as in
``--compare-levels "2,1 -ftree-pre"``) and measures compile time, library
size, and per-call cost of both functions for every level (interleaved rounds, so drift in the
machine's speed hits every level alike), and the largest relative difference of their outputs
from the default build.

Writes ``build_scaling.csv``, ``build_scaling.md`` and, with ``--flags-compare``,
``build_flags.csv`` into ``--out`` (atomically), and prints the Markdown.

    python benchmarks/build_scaling.py --links 1-12 --out out/build_scaling
    python benchmarks/build_scaling.py --links 4,12 --flags-compare --out out/build_flags
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import math
import os
import platform
import re
import shlex
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from jointplay.bench import cpu_name
from jointplay.bench.child import ChildFailed, json_from_child
from jointplay.common.files import atomic_write_text
from jointplay.common.timing import per_call_seconds

PAPER = "paper"
STRUCTURES = ("clearance", "ideal")
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

    names = model.coordinates
    n = len(names)
    x = np.zeros(2 * n)
    pidx = {name: i for i, name in enumerate(model.parameters)}
    for i, name in enumerate(names):
        if name.startswith("q"):
            x[i] = rng.uniform(-1.0, 1.0)
            x[n + i] = rng.uniform(-1.0, 1.0)
        elif name.startswith("ex"):
            j = name[2:]
            c = (params[pidx[f"joint{j}.bearing_radius"]]
                 - params[pidx[f"joint{j}.journal_radius"]])
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


# ---- the driver ------------------------------------------------------------------------------

COLUMNS: list[tuple[str, str, str]] = [  # key, Markdown header, format
    ("structure", "structure", "{}"),
    ("k", "k", "{}"),
    ("n_coords", "n", "{}"),
    ("derive_s", "derive s", "{:.2f}"),
    ("kane_s", "(Kane s)", "{:.2f}"),
    ("emit_s", "emit s", "{:.2f}"),
    ("c_kb", "C KiB", "{:.0f}"),
    ("jac_c_kb", "jac C KiB", "{:.0f}"),
    ("compile_s", "gcc s", "{:.2f}"),
    ("total_s", "total s", "{:.2f}"),
    ("so_kb", ".so KiB", "{:.0f}"),
    ("gcc_rss_mb", "gcc MiB", "{:.0f}"),
    ("fd_trigger_us", "fd trigger us", "{:.2f}"),
    ("jac_trigger_us", "jac trigger us", "{:.2f}"),
    ("fd_call_us", "fd call us", "{:.2f}"),
    ("jac_call_us", "jac call us", "{:.2f}"),
    ("fd_casadi_us", "fd casadi us", "{:.1f}"),
]
FLAG_COLUMNS: list[tuple[str, str, str]] = [
    ("structure", "structure", "{}"),
    ("k", "k", "{}"),
    ("opt", "opt", "{}"),
    ("compile_s", "gcc s", "{:.2f}"),
    ("compile_x", "gcc x -O1", "{:.2f}"),
    ("so_kb", ".so KiB", "{:.0f}"),
    ("fd_trigger_us", "fd trigger us", "{:.2f}"),
    ("fd_x", "fd x -O1", "{:.2f}"),
    ("jac_trigger_us", "jac trigger us", "{:.2f}"),
    ("jac_x", "jac x -O1", "{:.2f}"),
    ("max_rel_diff", "max rel diff", "{:.1e}"),
]


def parse_links(text: str) -> list[int]:
    """``"1-12"``, ``"4,9,12"`` or ``"1-4,12"`` to a sorted list of link counts."""
    out: set[int] = set()
    for part in text.split(","):
        part = part.strip()
        if not part:
            continue
        lo, sep, hi = part.partition("-")
        first, last = int(lo), int(hi) if sep else int(lo)
        if first < 1 or last < first:
            raise argparse.ArgumentTypeError(f"bad link range {part!r}")
        out.update(range(first, last + 1))
    if not out:
        raise argparse.ArgumentTypeError("no link counts given")
    return sorted(out)


def parse_levels(text: str) -> list[str]:
    """``"0,2,3"`` to ``["-O0", "-O2", "-O3"]``; an item may add flags: ``"1 -ftree-pre"``."""
    levels = []
    for item in text.split(","):
        words = item.split()
        if not words:
            continue
        level = f"-O{words[0].lstrip('-').lstrip('O')}"
        if not re.fullmatch(r"-O[0-3sg]|-Ofast", level):
            raise argparse.ArgumentTypeError(f"bad optimisation level {words[0]!r}")
        if any(not re.fullmatch(r"-f[\w=-]+|-m[\w=-]+", w) for w in words[1:]):
            raise argparse.ArgumentTypeError(f"only -f/-m flags may follow a level: {item!r}")
        levels.append(" ".join([level, *words[1:]]))
    return levels


def _cell(value: Any, fmt: str) -> str:
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return ""
    return fmt.format(value)


def markdown(rows: list[dict[str, Any]], columns: list[tuple[str, str, str]]) -> str:
    lines = ["| " + " | ".join(h for _, h, _ in columns) + " |",
             "|" + "|".join("---" if f == "{}" else "---:" for _, _, f in columns) + "|"]
    for row in rows:
        if row.get("error"):
            cells = [str(row["structure"]), str(row["k"]), f"**failed:** {row['error']}"]
            cells += [""] * (len(columns) - len(cells))
            lines.append("| " + " | ".join(cells) + " |")
            continue
        lines.append("| " + " | ".join(_cell(row.get(k), f) for k, _, f in columns) + " |")
    return "\n".join(lines)


def to_csv(rows: list[dict[str, Any]], keys: list[str]) -> str:
    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=keys, extrasaction="ignore", lineterminator="\n")
    writer.writeheader()
    for row in rows:
        writer.writerow({k: json.dumps(v) if isinstance(v, dict) else v
                         for k, v in row.items()})
    return buf.getvalue()


def machine_facts() -> dict[str, str]:
    from jointplay.store.build import DEFAULT_CFLAGS, compiler_version

    cpu = cpu_name()
    import casadi
    import numpy
    import sympy

    root = Path(__file__).resolve().parents[1]
    try:
        head = subprocess.run(["git", "-C", str(root), "rev-parse", "--short", "HEAD"],
                              capture_output=True, text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", str(root), "status", "--porcelain", "--",
                                "runtime", "derive", "generated"],
                               capture_output=True, text=True, check=True).stdout.strip()
        commit = head + (" (runtime/derive/generated modified)" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        commit = "unknown"
    return {
        "commit": commit,
        "cpu": cpu,
        "nproc": str(os.cpu_count()),
        "gcc": compiler_version(),
        "default cflags": " ".join(DEFAULT_CFLAGS),
        "python": platform.python_version(),
        "sympy": sympy.__version__,
        "casadi": casadi.__version__,
        "numpy": numpy.__version__,
    }


def run_in_child(spec: dict[str, Any], timeout: float) -> dict[str, Any]:
    """Run :func:`run_case` in a fresh interpreter; kill its process group on timeout."""
    try:
        return json_from_child([sys.executable, __file__, "--worker", json.dumps(spec)],
                               timeout)
    except ChildFailed as err:
        return {**spec, "error": str(err)}


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n\n")[0])
    parser.add_argument("--links", type=parse_links, default=parse_links("1-12"),
                        help="link counts, e.g. 1-12 or 4,9,12 (default 1-12)")
    parser.add_argument("--structures", default=",".join(STRUCTURES),
                        help="comma list of clearance, ideal (default both)")
    parser.add_argument("--no-paper", action="store_true",
                        help="skip the paper robot (jointplay.default_robot()) row")
    parser.add_argument("--out", type=Path, help="folder for CSV and Markdown (required)")
    parser.add_argument("--flags-compare", action="store_true",
                        help="also compile with other -O levels and time both functions")
    parser.add_argument("--compare-levels", type=parse_levels, default=parse_levels("0,2,3"),
                        help="levels to compare with the default -O1 (default 0,2,3); an "
                             "item may add -f/-m flags, e.g. '0,2,3,1 -ftree-pre'")
    parser.add_argument("--compare-links", type=parse_links, default=None,
                        help="link counts to run the flag comparison at (default: all); "
                             "the paper robot is compared whenever 4 is among them")
    parser.add_argument("--repeats", type=int, default=15, help="timed batches per function")
    parser.add_argument("--batch-ms", type=float, default=20.0, help="length of one batch")
    parser.add_argument("--timeout", type=float, default=1800.0, help="seconds per case")
    parser.add_argument("--paper-budget", type=float, default=20.0,
                        help="derive + emit + compile budget of the paper robot (s)")
    parser.add_argument("--worker", help=argparse.SUPPRESS)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    parser = _parser()
    args = parser.parse_args(argv)
    if args.worker:
        print(json.dumps(run_case(json.loads(args.worker))))
        return 0
    if args.out is None:
        parser.error("--out is required")

    structures = [s.strip() for s in args.structures.split(",") if s.strip()]
    for s in structures:
        if s not in STRUCTURES:
            parser.error(f"unknown structure {s!r}; choose from {', '.join(STRUCTURES)}")
    compare = set(args.compare_links or args.links) if args.flags_compare else set()
    cases = [] if args.no_paper else [(PAPER, 4)]
    cases += [(s, k) for s in structures for k in args.links]
    args.out.mkdir(parents=True, exist_ok=True)
    facts = machine_facts()

    load_before = os.getloadavg()
    started = time.perf_counter()
    rows = _run_cases(cases, args, compare)
    sweep_s = time.perf_counter() - started
    load_after = os.getloadavg()
    facts["load average (1/5/15 min) before"] = " ".join(f"{v:.2f}" for v in load_before)
    facts["load average (1/5/15 min) after"] = " ".join(f"{v:.2f}" for v in load_after)
    facts["max 1-min load during a case"] = (
        f"{max((r.get('load_end', 0) for r in rows), default=0):.2f} "
        "(this process alone is about 1.0; more means something else was running)")

    flag_rows = _flag_rows(rows)
    command = shlex.join(["python", "benchmarks/build_scaling.py", *(argv or sys.argv[1:])])
    text = _markdown(rows, flag_rows, facts, command, sweep_s,
                     _checks(rows, args.paper_budget))
    keys = [k for k, _, _ in COLUMNS] + ["kane_s", "n_params", "py_rss_mb", "import_s",
                                          "load_start", "load_end", "cache_hit", "finite",
                                          "sections_kb", "error"]
    keys = list(dict.fromkeys(keys))
    atomic_write_text(args.out / "build_scaling.csv", to_csv(rows, keys))
    if flag_rows:
        flag_keys = [k for k, _, _ in FLAG_COLUMNS] + ["cflags"]
        atomic_write_text(args.out / "build_flags.csv", to_csv(flag_rows, flag_keys))
    atomic_write_text(args.out / "build_scaling.md", text)
    print(text)
    return 1 if any(r.get("error") for r in rows) else 0


def _run_cases(cases: Sequence[tuple[str, int]], args: argparse.Namespace,
               compare: set[int]) -> list[dict[str, Any]]:
    """Every case in its own process, a line on each as it finishes."""
    from tqdm import tqdm

    rows: list[dict[str, Any]] = []
    with tqdm(cases, unit="case", dynamic_ncols=True) as bar:
        for structure, k in bar:
            bar.set_description(f"{structure} k={k}")
            spec = {"structure": structure, "k": k, "repeats": args.repeats,
                    "batch_s": args.batch_ms / 1000,
                    "levels": args.compare_levels if k in compare else []}
            row = run_in_child(spec, args.timeout)
            rows.append(row)
            if row.get("error"):
                tqdm.write(f"{structure} k={k}: FAILED {row['error']}")
            else:
                tqdm.write(f"{structure} k={k}: derive {row['derive_s']:.2f} s, "
                           f"emit {row['emit_s']:.2f} s, C {row['c_kb']:.0f} KiB, "
                           f"gcc {row['compile_s']:.2f} s, "
                           f"fd {row['fd_trigger_us']:.2f} us, "
                           f"jac {row['jac_trigger_us']:.2f} us")
    return rows


def _flag_rows(rows: Sequence[dict[str, Any]]) -> list[dict[str, Any]]:
    """Every case's flag variants, each with its ratios to the case's -O1 build."""
    flag_rows: list[dict[str, Any]] = []
    for row in rows:
        base = next((f for f in row.get("flags", []) if f["opt"] == "-O1"), None)
        for f in row.get("flags", []):
            if base is not None:
                f["compile_x"] = f["compile_s"] / base["compile_s"] if base["compile_s"] else None
                f["fd_x"] = f["fd_trigger_us"] / base["fd_trigger_us"]
                f["jac_x"] = f["jac_trigger_us"] / base["jac_trigger_us"]
            flag_rows.append(f)
    flag_rows.sort(key=lambda f: (f["structure"], f["k"], f["opt"]))
    return flag_rows


def _checks(rows: Sequence[dict[str, Any]], paper_budget: float) -> list[str]:
    """The requirements: the paper robot's build budget, 12 links completing, every case a
    cache hit with finite outputs."""
    paper = next((r for r in rows if r["structure"] == PAPER and not r.get("error")), None)
    checks = []
    if paper is not None:
        ok = paper["total_s"] < paper_budget
        checks.append(f"- paper robot derive + emit + compile: {paper['total_s']:.2f} s "
                      f"(budget {paper_budget:.0f} s): {'PASS' if ok else 'FAIL'}")
    for row in rows:
        if row["structure"] == "clearance" and row["k"] == 12:
            checks.append("- 12 links, clearance at every joint: "
                          + (f"FAILED ({row['error']})" if row.get("error") else
                             f"completed, {row['total_s']:.1f} s"))
    bad = [r for r in rows if not r.get("error") and not (r["cache_hit"] and r["finite"])]
    for r in bad:
        checks.append(f"- {r['structure']} k={r['k']}: cache_hit={r['cache_hit']} "
                      f"finite={r['finite']}")
    return checks


def _markdown(rows: list[dict[str, Any]], flag_rows: list[dict[str, Any]],
              facts: dict[str, str], command: str, sweep_s: float, checks: list[str]) -> str:
    md = ["# Build scaling", "",
          f"Command: `{command}`  ", f"Sweep wall time: {sweep_s:.0f} s", "",
          *[f"- {k}: {v}" for k, v in facts.items()], "",
          "Times in seconds, per-call costs in microseconds (median over batches). "
          "`total` = derive + emit + gcc with the default flags, in a cold process and an "
          "empty cache. `jac C` = bytes of C behind jac_forward_dynamics (its body plus "
          "residual_jacobian). `trigger`: FastFunction.trigger with inputs in place; `call`: "
          "FastFunction(*numpy arrays); `casadi`: the plain casadi.Function call.", "",
          markdown(rows, COLUMNS), ""]
    if checks:
        md += ["## Requirements", "", *checks, ""]
    if flag_rows:
        md += ["## Optimisation level", "",
               "Same C, default flags with -O1 replaced; `x -O1` is the ratio to the default "
               "build; per-call costs through FastFunction.trigger, timed in interleaved "
               "rounds. `max rel diff`: largest output difference from the -O1 build, "
               "relative to each output's largest entry.", "",
               markdown(flag_rows, FLAG_COLUMNS), ""]
    return "\n".join(md)


if __name__ == "__main__":
    sys.exit(main())
