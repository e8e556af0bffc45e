"""Generated models checked into the repository (build products with provenance).

Each sub-folder holds ``model.c`` (stamped: do not edit), ``layout.json`` (every input and
output slot, with names and units) and ``robot.toml`` (the description it came from, whose
numbers are the default parameter vector). Compiled libraries never live here: they go to
the per-user cache (see :func:`jointplay.cache_root`).
"""

from __future__ import annotations

import json
from pathlib import Path

HERE = Path(__file__).resolve().parent


def folders() -> dict[str, Path]:
    """Name of each checked-in generated model -> its folder."""
    return {p.parent.name: p.parent for p in sorted(HERE.glob("*/layout.json"))}


def find(input_hash: str) -> Path | None:
    """The checked-in folder whose model was generated from ``input_hash``, if any."""
    for folder in folders().values():
        try:
            layout = json.loads((folder / "layout.json").read_text())
        except (OSError, ValueError):
            continue
        if layout.get("provenance", {}).get("input_hash") == input_hash:
            return folder
    return None
