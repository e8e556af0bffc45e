"""What every report shares: Markdown and CSV tables, and where the numbers were measured."""

from __future__ import annotations

import csv
import io
import math
import os
import platform
import subprocess
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any


def _cell(value: Any, fmt: str) -> str:
    if value is None or value == "" or (isinstance(value, float) and math.isnan(value)):
        return ""
    try:
        return fmt.format(value)
    except (ValueError, TypeError):
        return str(value)


def markdown_table(rows: Sequence[dict[str, Any]], columns: Sequence[tuple[str, str, str]]
                   ) -> str:
    lines = ["| " + " | ".join(h for _, h, _ in columns) + " |",
             "|" + "|".join("---" if f == "{}" else "---:" for _, _, f in columns) + "|"]
    for row in rows:
        cells = [_cell(row.get(k), f).replace("|", "\\|") for k, _, f in columns]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def to_csv(rows: Sequence[dict[str, Any]], keys: Sequence[str]) -> str:
    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=list(keys), extrasaction="ignore",
                            lineterminator="\n")
    writer.writeheader()
    for row in rows:
        writer.writerow({k: ("" if v is None else repr(v) if isinstance(v, float) else v)
                         for k, v in row.items() if k in keys})
    return buf.getvalue()


def cpu_name() -> str:
    """The processor's model name (from /proc/cpuinfo where there is one)."""
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def machine_facts() -> dict[str, str]:
    """Where the numbers were measured: they mean little without it."""
    from importlib.metadata import version

    from jointplay.store.build import compiler_version

    cpu = cpu_name()
    load = os.getloadavg()
    return {
        "code": _commit(),
        "cpu": f"{cpu}, {os.cpu_count()} cores",
        "load average (1/5/15 min) at the end": " ".join(f"{v:.2f}" for v in load),
        "versions": ", ".join(f"{p} {version(p)}" for p in ("jointplay", "casadi", "numpy"))
        + f", python {platform.python_version()}, {compiler_version()}",
    }


def _commit() -> str:
    """The git commit measured, and whether the package's sources differ from it."""
    root = Path(__file__).resolve().parents[2]
    try:
        head = subprocess.run(["git", "-C", str(root), "rev-parse", "--short", "HEAD"],
                              capture_output=True, text=True, check=True, timeout=10)
        dirty = subprocess.run(["git", "-C", str(root), "status", "--porcelain", "--",
                                "runtime", "derive", "generated", "scenes"],
                               capture_output=True, text=True, check=True, timeout=10)
    except (OSError, subprocess.SubprocessError):
        return "unknown (not a git checkout)"
    changed = [line[3:] for line in dirty.stdout.splitlines() if line.strip()]
    return f"commit {head.stdout.strip()}" + (
        f" with local changes in {', '.join(changed)}" if changed else "")


def heading(title: str, command: str = "") -> list[str]:
    """The first Markdown lines of a report: its title, and the command that made it."""
    return [f"# {title}", ""] + ([f"Command: `{command}`", ""] if command else [])


def write_report(out: Path, stem: str, rows: Sequence[dict[str, Any]], csv_keys: Sequence[str],
                 markdown: Sequence[str], plot: Callable[[Path], Path]) -> list[Path]:
    """``stem``.csv, .md and .png in ``out``, each written atomically; their paths."""
    from jointplay.common.files import atomic_write_text

    paths = [out / f"{stem}.csv", out / f"{stem}.md", out / f"{stem}.png"]
    atomic_write_text(paths[0], to_csv(rows, csv_keys))
    atomic_write_text(paths[1], "\n".join(markdown))
    plot(paths[2])
    return paths
