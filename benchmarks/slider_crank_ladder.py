"""What the slider-crank's ladder benchmarks share (slider_crank_peers.py,
mechanism_methods.py): their command line and their atomic outputs."""

from __future__ import annotations

import argparse
from pathlib import Path

from jointplay.common.files import atomic_write_text


def ladder_arguments(doc: str, argv: list[str] | None, repeats: int) -> argparse.Namespace:
    """--out DIR, --target (the slider error matched, m) and --repeats (runs per rung)."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--out", type=Path, required=True)
    parser.add_argument("--target", type=float, default=1e-6, help="slider error (m)")
    parser.add_argument("--repeats", type=int, default=repeats, help="runs per rung")
    args = parser.parse_args(argv)
    if args.repeats < 1 or not args.target > 0.0:
        parser.error("--repeats must be >= 1 and --target > 0")
    return args


def write_outputs(folder: Path, files: dict[str, str]) -> None:
    """Each file written whole under ``folder`` (made if missing), or not at all."""
    folder.mkdir(parents=True, exist_ok=True)
    for name, text in files.items():
        atomic_write_text(folder / name, text)
