"""How derivation, emission, compilation and evaluation scale with the number of links, with
Pinocchio beside.

For every link count k and every structure (``clearance``: clearance at every joint;
``ideal``: every joint ideal), plus the paper robot (``jointplay.default_robot()``), this
measures, each case in a fresh Python process (so sympy's caches start cold) and a fresh
temporary compile cache:

* the formulation emitted (closed form or recursion; ``--formulation`` forces one), sympy
  derivation time, CasADi emission time (SX graphs + C text), gcc compile time with the
  project's default flags (``jointplay.store.build.DEFAULT_CFLAGS``);
* peak resident memory of each stage: the build process during the derivation and during the
  emission (its high-water mark reset between them), the compiler's (gcc, cc1 and as
  together, sampled every 20 ms), and the build's peak (the larger of those, and the build
  process's resident memory plus the compiler's); the parent also samples the whole process
  group's resident memory every 0.1 s;
* the C file size (model.c; the deferred library's C apart) and the gcc time of the deferred
  library, compiled at the first call of ``jac_forward_dynamics`` after the build;
* per-call cost of ``forward_dynamics``, ``jac_state`` (the state Jacobian, what the BDF
  calls) and ``jac_forward_dynamics`` (the full Jacobian) through ``FastFunction.trigger``,
  and of Pinocchio's ``aba`` and ``computeABADerivatives`` on an equivalent chain (a planar
  joint, 3 coordinates, for each clearance joint; a revolute joint for each ideal one), each
  a Python call without arguments, timed in alternating rounds with the same batches and the
  same median, and their ratios; then jointplay's other calling paths
  (``FastFunction.__call__`` with numpy arrays, the plain CasADi ``Function`` call).

A case that runs past ``--build-timeout`` (derive + emit + gcc + load), ``--timeout`` (the
whole case) or ``--memory-limit`` (the case's process group) is killed and kept as a row that
says so, with what it had measured before.

With ``--flags-compare`` it also compiles the same C with the default flags' ``-O1`` replaced
by each of ``--compare-levels`` (default ``-O0,-O2,-O3``; an item may add -f flags, as in
``--compare-levels "2,1 -ftree-pre"``) and measures compile time, library
size, and per-call cost of both functions for every level (interleaved rounds, so drift in the
machine's speed hits every level alike), and the largest relative difference of their outputs
from the default build.

Writes ``build_scaling.csv``, ``build_scaling.md``, ``build_scaling.png`` (per-call cost,
build time and memory against k, log scales) and, with ``--flags-compare``, ``build_flags.csv`` into
``--out`` (each atomically, all at the end), and prints the Markdown.

    python benchmarks/build_scaling.py --links 1,2,4,8,12,16,20,24,32 --out out/build_scaling
    python benchmarks/build_scaling.py --links 1 --no-paper --quick --out out/build_quick
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
import subprocess
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from build_scaling_case import PAPER, run_case

from jointplay.bench import cpu_name
from jointplay.bench.child import ChildLimits, ChildProgress, watch_child
from jointplay.common.errors import DescriptionError
from jointplay.common.files import atomic_write_text

STRUCTURES = ("clearance", "ideal")
FORMULATION_CHOICES = ("auto", "closed", "recursive")
GOAL_BUILD_S = {32: 30.0, 12: 10.0}  # the all-clearance chain's build budget at these k
GOAL_BUILD_MB = 1000.0  # and its memory budget at k = 32 (1 GB)


# ---- the driver ------------------------------------------------------------------------------

NOTE = ("error", "note", "{}")
BUILD_COLUMNS: list[tuple[str, str, str]] = [  # key, Markdown header, format
    ("structure", "structure", "{}"),
    ("k", "k", "{}"),
    ("n_coords", "n", "{}"),
    ("formulation", "formulation", "{}"),
    ("derive_s", "derive s", "{:.2f}"),
    ("emit_s", "emit s", "{:.2f}"),
    ("compile_s", "gcc s", "{:.2f}"),
    ("compile_cpu_s", "gcc CPU s", "{:.2f}"),
    ("total_s", "total s", "{:.2f}"),
    ("c_kb", "C KiB", "{:.0f}"),
    ("deferred_compile_s", "deferred gcc s", "{:.2f}"),
    ("deferred_cpu_s", "deferred gcc CPU s", "{:.2f}"),
    ("deferred_c_kb", "deferred C KiB", "{:.0f}"),
    ("derive_mib", "derive MiB", "{:.0f}"),
    ("emit_mib", "emit MiB", "{:.0f}"),
    ("gcc_mib", "gcc MiB", "{:.0f}"),
    ("build_peak_mib", "build peak MiB", "{:.0f}"),
    ("group_peak_mib", "sampled peak MiB", "{:.0f}"),
    NOTE,
]
CALL_COLUMNS: list[tuple[str, str, str]] = [
    ("structure", "structure", "{}"),
    ("k", "k", "{}"),
    ("n_coords", "n", "{}"),
    ("fd_trigger_us", "fd us", "{:.2f}"),
    ("pin_aba_us", "Pinocchio aba us", "{:.2f}"),
    ("fd_vs_aba", "fd / aba", "{:.2f}"),
    ("jac_state_us", "jac_state us", "{:.1f}"),
    ("pin_derivatives_us", "Pinocchio ABA derivatives us", "{:.1f}"),
    ("jac_vs_derivatives", "jac_state / derivatives", "{:.2f}"),
    ("jac_trigger_us", "full Jacobian us", "{:.1f}"),
    ("fd_call_us", "fd call us", "{:.2f}"),
    ("jac_call_us", "jac call us", "{:.1f}"),
    ("fd_casadi_us", "fd casadi us", "{:.1f}"),
    NOTE,
]
COLUMNS = BUILD_COLUMNS[:-1] + CALL_COLUMNS[3:-1]  # every measured figure, for the CSV
FLAG_COLUMNS: list[tuple[str, str, str]] = [
    ("structure", "structure", "{}"),
    ("k", "k", "{}"),
    ("opt", "opt", "{}"),
    ("compile_s", "gcc s", "{:.2f}"),
    ("compile_x", "gcc x -O1", "{:.2f}"),
    ("so_kb", ".so KiB", "{:.0f}"),
    ("fd_trigger_us", "fd trigger us", "{:.2f}"),
    ("fd_x", "fd x -O1", "{:.2f}"),
    ("jac_trigger_us", "jac_state trigger us", "{:.2f}"),
    ("jac_x", "jac_state x -O1", "{:.2f}"),
    ("max_rel_diff", "max rel diff", "{:.1e}"),
]
CSV_KEYS = list(dict.fromkeys(
    [k for k, _, _ in COLUMNS] + ["kane_s", "jac_c_kb", "so_kb", "n_params", "pin_nv",
                                  "pin_version", "py_rss_mb", "import_s", "case_wall_s",
                                  "load_start", "load_end", "cache_hit", "finite",
                                  "sections_kb", "failed_stage", "error"]))


def parse_links(text: str) -> list[int]:
    """``"1-12"``, ``"4,9,12"`` or ``"1-4,12"`` to a sorted list of link counts (1 to 32)."""
    from jointplay.cli.args import parse_links as parse

    try:
        return parse(text)
    except DescriptionError as err:
        raise argparse.ArgumentTypeError(str(err)) from None


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
    return fmt.format(value).replace("|", "\\|")


def markdown(rows: list[dict[str, Any]], columns: list[tuple[str, str, str]]) -> str:
    """A Markdown table. A failed row shows what it measured and its error in the ``error``
    column, or, where ``columns`` has none, the error in its third cell."""
    keys = [k for k, _, _ in columns]
    lines = ["| " + " | ".join(h for _, h, _ in columns) + " |",
             "|" + "|".join("---" if f == "{}" else "---:" for _, _, f in columns) + "|"]
    for row in rows:
        if row.get("error") and "error" not in keys:
            cells = [str(row["structure"]), str(row["k"]), f"**failed:** {row['error']}"]
            cells += [""] * (len(columns) - len(cells))
            lines.append("| " + " | ".join(cells) + " |")
            continue
        cells = [_cell(row.get(k), f) for k, _, f in columns]
        if row.get("error") and "error" in keys:
            cells[keys.index("error")] = f"**failed:** {_cell(row['error'], '{}')}"
        lines.append("| " + " | ".join(cells) + " |")
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


def run_in_child(spec: dict[str, Any], limits: ChildLimits,
                 on_progress: Any = None) -> dict[str, Any]:
    """Run :func:`run_case` in a fresh interpreter, watched: a case killed for time or
    memory, or one that fails, is a row with its error and what it measured before."""
    outcome = watch_child([sys.executable, __file__, "--worker", json.dumps(spec)], limits,
                          on_progress)
    base = {"structure": spec["structure"], "k": spec["k"]}
    if outcome.row is not None:
        row = {**base, **outcome.row}
    else:
        row = {**base, **outcome.measured, "error": outcome.failure,
               "failed_stage": outcome.stage}
    row["group_peak_mib"] = outcome.peak_rss_mib
    row["case_wall_s"] = outcome.elapsed_s
    for ratio, num, den in (("fd_vs_aba", "fd_trigger_us", "pin_aba_us"),
                            ("jac_vs_derivatives", "jac_state_us", "pin_derivatives_us")):
        if row.get(num) and row.get(den):
            row[ratio] = row[num] / row[den]
    return row


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n\n")[0])
    parser.add_argument("--links", type=parse_links, default=parse_links("1-12"),
                        help="link counts, e.g. 1-32 or 1,2,4,8,12,16,20,24,32 (default 1-12)")
    parser.add_argument("--structures", default=",".join(STRUCTURES),
                        help="comma list of clearance, ideal (default both)")
    parser.add_argument("--no-paper", action="store_true",
                        help="skip the paper robot (jointplay.default_robot()) row")
    parser.add_argument("--formulation", choices=FORMULATION_CHOICES, default=None,
                        help="emit this formulation (default: $JOINTPLAY_FORMULATION, else "
                             "auto, the runtime's own choice)")
    parser.add_argument("--no-pinocchio", action="store_true",
                        help="do not time Pinocchio beside jointplay")
    parser.add_argument("--out", type=Path, help="folder for CSV, Markdown and PNG (required)")
    parser.add_argument("--flags-compare", action="store_true",
                        help="also compile with other -O levels and time both functions")
    parser.add_argument("--compare-levels", type=parse_levels, default=parse_levels("0,2,3"),
                        help="levels to compare with the default -O1 (default 0,2,3); an "
                             "item may add -f/-m flags, e.g. '0,2,3,1 -ftree-pre'")
    parser.add_argument("--compare-links", type=parse_links, default=None,
                        help="link counts to run the flag comparison at (default: all); "
                             "the paper robot is compared whenever 4 is among them")
    parser.add_argument("--quick", action="store_true",
                        help="few short timing batches (3 of 2 ms): checks the harness, its "
                             "per-call figures are rough")
    parser.add_argument("--repeats", type=int, default=15, help="timed batches per function")
    parser.add_argument("--batch-ms", type=float, default=20.0, help="length of one batch")
    parser.add_argument("--build-timeout", type=float, default=600.0,
                        help="seconds for a case's derive + emit + gcc + load (default 600)")
    parser.add_argument("--timeout", type=float, default=1800.0,
                        help="seconds for a whole case, timing included (default 1800)")
    parser.add_argument("--memory-limit", type=float, default=4096.0,
                        help="MiB of resident memory for a case's processes, gcc included "
                             "(default 4096)")
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
    if args.quick:
        args.repeats, args.batch_ms = 3, 2.0
    for flag, value in (("--repeats", args.repeats), ("--batch-ms", args.batch_ms),
                        ("--build-timeout", args.build_timeout), ("--timeout", args.timeout),
                        ("--memory-limit", args.memory_limit)):
        if not value > 0:
            parser.error(f"{flag} must be positive, got {value:g}")

    structures = [s.strip() for s in args.structures.split(",") if s.strip()]
    for s in structures:
        if s not in STRUCTURES:
            parser.error(f"unknown structure {s!r}; choose from {', '.join(STRUCTURES)}")
    compare = set(args.compare_links or args.links) if args.flags_compare else set()
    cases = [] if args.no_paper else [(PAPER, 4)]
    cases += [(s, k) for s in structures for k in args.links]
    outputs = _plan_outputs(args.out, args.flags_compare)
    facts = machine_facts()
    limits = ChildLimits(timeout_s=args.timeout, clock_s={"build": args.build_timeout},
                         memory_mib=args.memory_limit)

    load_before = os.getloadavg()
    started = time.perf_counter()
    rows = _run_cases(cases, args, compare, limits)
    sweep_s = time.perf_counter() - started
    load_after = os.getloadavg()
    facts["load average (1/5/15 min) before"] = " ".join(f"{v:.2f}" for v in load_before)
    facts["load average (1/5/15 min) after"] = " ".join(f"{v:.2f}" for v in load_after)
    facts["max 1-min load during a case"] = (
        f"{max((r.get('load_end', 0) for r in rows), default=0):.2f} "
        "(this process alone is about 1.0; more means something else was running)")
    pin = next((r["pin_version"] for r in rows if r.get("pin_version")), None)
    facts["pinocchio"] = pin or ("not timed (--no-pinocchio)" if args.no_pinocchio
                                 else "not installed")
    facts["limits per case"] = (f"build {args.build_timeout:g} s, whole case "
                                f"{args.timeout:g} s, {args.memory_limit:g} MiB")

    flag_rows = _flag_rows(rows)
    command = shlex.join(["python", "benchmarks/build_scaling.py",
                          *(sys.argv[1:] if argv is None else argv)])
    text = _markdown(rows, flag_rows, facts, command, sweep_s,
                     _checks(rows, args.paper_budget))
    atomic_write_text(outputs["csv"], to_csv(rows, CSV_KEYS))
    if flag_rows:
        flag_keys = [k for k, _, _ in FLAG_COLUMNS] + ["cflags"]
        atomic_write_text(outputs["flags"], to_csv(flag_rows, flag_keys))
    plot(rows, outputs["png"])
    atomic_write_text(outputs["md"], text)  # last: its presence says the run finished
    print(text)
    return 1 if any(r.get("error") for r in rows) else 0


def _plan_outputs(out: Path, flags: bool) -> dict[str, Path]:
    """Every file this run will write, checked writable before any case runs; earlier
    results there are removed, so a failed run never leaves them looking like its own."""
    paths = {"csv": out / "build_scaling.csv", "md": out / "build_scaling.md",
             "png": out / "build_scaling.png"}
    if flags:
        paths["flags"] = out / "build_flags.csv"
    try:
        out.mkdir(parents=True, exist_ok=True)
        probe = out / ".build_scaling.probe"
        probe.write_text("")
        probe.unlink()
        for path in (*paths.values(), out / "build_flags.csv"):
            path.unlink(missing_ok=True)
    except OSError as err:
        raise SystemExit(f"--out {out}: cannot write there ({err.strerror}); choose another "
                         "folder") from None
    return paths


def _run_cases(cases: Sequence[tuple[str, int]], args: argparse.Namespace,
               compare: set[int], limits: ChildLimits) -> list[dict[str, Any]]:
    """Every case in its own process, its stage, time and memory on the bar while it runs,
    a line on each as it finishes."""
    from tqdm import tqdm

    rows: list[dict[str, Any]] = []
    with tqdm(cases, unit="case", dynamic_ncols=True) as bar:
        for structure, k in bar:
            bar.set_description(f"{structure} k={k}")
            shown = [0.0]

            def progress(p: ChildProgress, shown: list[float] = shown) -> None:
                if p.elapsed_s - shown[0] >= 1.0:
                    shown[0] = p.elapsed_s
                    bar.set_postfix_str(f"{p.stage}, {p.elapsed_s:.0f} s, "
                                        f"{p.rss_mib:.0f} MiB")

            spec = {"structure": structure, "k": k, "repeats": args.repeats,
                    "batch_s": args.batch_ms / 1000, "formulation": args.formulation,
                    "pinocchio": not args.no_pinocchio,
                    "levels": args.compare_levels if k in compare else []}
            row = run_in_child(spec, limits, progress)
            rows.append(row)
            tqdm.write(_summary(row))
    return rows


def _summary(row: dict[str, Any]) -> str:
    head = f"{row['structure']} k={row['k']}: "
    if row.get("error"):
        return head + f"FAILED {row['error']}"
    text = (head + f"{row['formulation']}, derive {row['derive_s']:.2f} s, "
            f"emit {row['emit_s']:.2f} s, gcc {row['compile_s']:.2f} s, "
            f"peak {row['build_peak_mib']:.0f} MiB, C {row['c_kb']:.0f} KiB; "
            f"fd {row['fd_trigger_us']:.2f} us, jac_state {row['jac_state_us']:.2f} us")
    if row.get("fd_vs_aba") is not None:
        text += (f"; / Pinocchio: fd {row['fd_vs_aba']:.2f}x, "
                 f"jac {row['jac_vs_derivatives']:.2f}x")
    return text


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
    """The requirements, each PASS, FAIL or what was not measured: the paper robot's build
    budget, the all-clearance chain's build at 12 and 32 links, per-call cost against
    Pinocchio at every measured k, every case a cache hit with finite outputs."""
    paper = next((r for r in rows if r["structure"] == PAPER and not r.get("error")), None)
    checks = []
    if paper is not None:
        ok = paper["total_s"] < paper_budget
        checks.append(f"- paper robot derive + emit + compile: {paper['total_s']:.2f} s "
                      f"(budget {paper_budget:.0f} s): {'PASS' if ok else 'FAIL'}")
    for k, budget_s in sorted(GOAL_BUILD_S.items()):
        row = next((r for r in rows if r["structure"] == "clearance" and r["k"] == k), None)
        goal = f"build <= {budget_s:g} s" + (f" and <= {GOAL_BUILD_MB:g} MB" if k == 32 else "")
        if row is None:
            checks.append(f"- {k} links, clearance at every joint ({goal}): not measured")
        elif row.get("error"):
            checks.append(f"- {k} links, clearance at every joint ({goal}): FAIL, "
                          f"{row['error']}")
        else:
            mb = row["build_peak_mib"] * (1 << 20) / 1e6
            ok = row["total_s"] <= budget_s and (k != 32 or mb <= GOAL_BUILD_MB)
            checks.append(f"- {k} links, clearance at every joint ({goal}): "
                          f"{row['total_s']:.1f} s, {mb:.0f} MB peak: "
                          f"{'PASS' if ok else 'FAIL'}")
    for ratio, what in (("fd_vs_aba", "forward dynamics <= Pinocchio aba"),
                        ("jac_vs_derivatives", "jac_state <= Pinocchio ABA derivatives")):
        timed = [r for r in rows if r.get(ratio) is not None]
        if not timed:
            checks.append(f"- {what}: not measured")
            continue
        worse = [f"{r['structure']} k={r['k']} ({r[ratio]:.2f}x)" for r in timed
                 if r[ratio] > 1.0]
        ks = sorted({r["k"] for r in timed})
        checks.append(f"- {what} at every measured k ({', '.join(map(str, ks))}): "
                      + ("PASS" if not worse else "FAIL at " + ", ".join(worse)))
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
          "## Build", "",
          "Times in seconds. `total` = derive + emit + gcc with the default flags, in a cold "
          "process and an empty cache: what a run waits for. `deferred gcc` compiles the "
          "deferred library (the Jacobian's input blocks), on the first call that needs it, "
          "after the build and not in `total`. Memory is peak resident MiB: `derive` and `emit` of "
          "the build process during that stage (its high-water mark), `gcc` of the compiler's "
          "processes together (sampled every 20 ms), `build peak` the largest of those and "
          "of the build process plus the compiler, `sampled "
          "peak` the case's whole process group (timing included) sampled every 0.1 s.", "",
          markdown(rows, BUILD_COLUMNS), "",
          "## Per call", "",
          "Microseconds per call, median over batches. `fd`, `jac_state` (the state "
          "Jacobian) and `full Jacobian` (jac_forward_dynamics: state, torques, parameters, "
          "impact speeds) through FastFunction.trigger with inputs in place; Pinocchio's "
          "`aba` and `computeABADerivatives` on an equivalent chain (a planar joint for each "
          "clearance joint, a revolute joint for each ideal one), each a Python call timed "
          "in the same alternating rounds, so Python's call overhead is in both figures. "
          "`fd call`: FastFunction(*numpy arrays); `fd casadi`: the plain casadi.Function "
          "call.", "",
          markdown(rows, CALL_COLUMNS), ""]
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


def plot(rows: Sequence[dict[str, Any]], path: Path) -> Path:
    """Per-call cost (jointplay and Pinocchio), build time (by stage) and the build's peak
    memory against k, log scales; a failed case is marked at its k."""
    from matplotlib.ticker import NullFormatter, ScalarFormatter

    from jointplay.common.figures import figure, save

    fig, axes = figure(1, 3, 15.0, 4.4)
    calls, build, memory = axes[0, 0], axes[0, 1], axes[0, 2]
    styles = {"clearance": "-", "ideal": "--"}
    for structure, style in styles.items():
        ok = [r for r in rows if r["structure"] == structure and not r.get("error")]
        for i, (key, label) in enumerate((("fd_trigger_us", "jointplay fd"),
                                          ("pin_aba_us", "Pinocchio aba"),
                                          ("jac_state_us", "jointplay jac_state"),
                                          ("pin_derivatives_us", "Pinocchio ABA deriv."))):
            pts = [(r["k"], r[key]) for r in ok if r.get(key)]
            if pts:
                calls.plot(*zip(*pts, strict=True), style, marker="o", ms=3, color=f"C{i}",
                           label=f"{label} ({structure})")
        for i, (key, label) in enumerate((("derive_s", "derive"), ("emit_s", "emit"),
                                          ("compile_s", "gcc"), ("total_s", "total"))):
            pts = [(r["k"], r[key]) for r in ok if r.get(key)]
            if pts:
                build.plot(*zip(*pts, strict=True), style, marker="o", ms=3, color=f"C{i}",
                           label=f"{label} ({structure})")
        for i, (key, label) in enumerate((("build_peak_mib", "build peak"),
                                          ("gcc_mib", "gcc"), ("emit_mib", "emit"))):
            pts = [(r["k"], r[key]) for r in ok if r.get(key)]
            if pts:
                memory.plot(*zip(*pts, strict=True), style, marker="o", ms=3, color=f"C{i}",
                            label=f"{label} ({structure})")
        failed = [r for r in rows if r["structure"] == structure and r.get("error")]
        for r in failed:
            build.axvline(r["k"], color="C3", ls=":", lw=1)
            build.annotate(f"{structure} k={r['k']} failed", (r["k"], 0.5),
                           xycoords=("data", "axes fraction"), rotation=90, fontsize=7,
                           color="C3", ha="right", va="center")
    calls.set_ylabel("µs per call (median)")
    calls.set_title("per call, through Python", fontsize=10)
    build.set_ylabel("seconds (cold process, empty cache)")
    build.set_title("derive, emit and gcc", fontsize=10)
    memory.set_ylabel("MiB resident (peak)")
    memory.set_title("memory of the build", fontsize=10)
    links = sorted({r["k"] for r in rows if r["structure"] != PAPER})
    for ax in (calls, build, memory):
        ax.set_xscale("log", base=2)
        ax.set_yscale("log")
        if links:
            ax.set_xticks(links)
        ax.xaxis.set_major_formatter(ScalarFormatter())
        ax.xaxis.set_minor_formatter(NullFormatter())
        ax.set_xlabel("links k")
        ax.grid(True, which="both", alpha=0.25)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=6, ncol=2)
    return save(fig, path)


if __name__ == "__main__":
    sys.exit(main())
