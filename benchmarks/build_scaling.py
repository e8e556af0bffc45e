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
import subprocess
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from build_scaling_case import PAPER, run_case

from jointplay.bench import cpu_name
from jointplay.bench.child import ChildFailed, json_from_child
from jointplay.common.files import atomic_write_text

STRUCTURES = ("clearance", "ideal")


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
