"""What the per-user model cache holds, and removing it: ``jointplay cache list|clear|prune``.

Two kinds of entry live under the cache root (:func:`jointplay.store.build.cache_root`):
``models/<input hash>/``, generated C of a robot derived on demand, and ``build/<key>/``, a
compiled library. An entry's age is the time since it was last used (a build's marker is
touched at every load; a model folder when it is found). An entry whose lock another process
holds is being built or repaired right now, or linked against by a build: it is listed, never
removed.

A folder is an entry only if jointplay made it: it carries jointplay's owner file
(:data:`jointplay.store.build.OWNER_NAME`). Anything else found there (a folder without it, a
link, a file) is reported and left alone: `clear` and `prune` never follow a link and never
remove, or write into, what jointplay did not create.
"""

from __future__ import annotations

import contextlib
import os
import re
import shutil
import stat
import time
from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path

from jointplay.common.errors import DescriptionError
from jointplay.store.build import (
    MARKER_NAME,
    cache_root,
    entry_lock,
    is_owned,
    remove_temporaries,
)

KINDS = ("models", "build")
_MODEL_LINE = re.compile(r"^ \* model: (\S+)$", re.MULTILINE)


@dataclass(frozen=True)
class CacheEntry:
    """One cache entry: ``kind`` (``"models"`` or ``"build"``), its folder, the model's name
    (from its C header), its size in bytes and the time it was last used (epoch s)."""

    kind: str
    path: Path
    name: str
    size: int
    last_used: float

    @property
    def key(self) -> str:
        return self.path.name

    def age(self, now: float | None = None) -> float:
        """Seconds since it was last used."""
        return max(0.0, (time.time() if now is None else now) - self.last_used)


def _folder_size(folder: Path) -> int:
    total = 0
    for root, _, files in os.walk(folder):
        for name in files:
            with contextlib.suppress(OSError):
                total += os.lstat(os.path.join(root, name)).st_size
    return total


def _model_name(folder: Path) -> str:
    try:
        with open(folder / "model.c", encoding="utf-8", errors="replace") as fh:
            head = fh.read(2000)
    except OSError:
        return "?"
    match = _MODEL_LINE.search(head)
    if match:
        return match.group(1)
    return "(integration loop)" if "integration loop" in head[:200] else "?"


def _last_used(folder: Path, kind: str) -> float:
    marker = folder / MARKER_NAME if kind == "build" else folder
    for path in (marker, folder):
        with contextlib.suppress(OSError):
            return path.stat().st_mtime
    return 0.0


def _kind_folder(root: Path, kind: str) -> Path | None:
    """``root/kind`` if it is a real folder (a link there is not followed)."""
    folder = root / kind
    try:
        return folder if stat.S_ISDIR(os.lstat(folder).st_mode) else None
    except OSError:
        return None


def entries(root: Path | None = None) -> list[CacheEntry]:
    """Every entry of the cache jointplay made, least recently used first."""
    root = root or cache_root()
    found = []
    for kind in KINDS:
        parent = _kind_folder(root, kind)
        if parent is None:
            continue
        try:
            folders = sorted(p for p in parent.iterdir() if is_owned(p))
        except OSError:
            continue
        for folder in folders:
            found.append(CacheEntry(kind, folder, _model_name(folder), _folder_size(folder),
                                    _last_used(folder, kind)))
    return sorted(found, key=lambda e: (e.last_used, e.kind, e.key))


def foreign(root: Path | None = None) -> list[Path]:
    """What lies where entries live but is not jointplay's (no owner file, a link, a file,
    or ``build``/``models`` itself a link): never removed."""
    root = root or cache_root()
    found = []
    for kind in KINDS:
        path = root / kind
        if not os.path.lexists(path):
            continue
        parent = _kind_folder(root, kind)
        if parent is None:
            found.append(path)
            continue
        with contextlib.suppress(OSError):
            found.extend(sorted(p for p in parent.iterdir() if not is_owned(p)))
    return found


def remove(entry: CacheEntry) -> bool:
    """Remove one entry unless another process holds its lock (building or repairing it,
    or linking against it). Returns whether it was removed."""
    if not is_owned(entry.path):  # replaced by a link, say, since it was listed
        return False
    try:
        with entry_lock(entry.path, blocking=False) as held:
            if not held:
                return False
            shutil.rmtree(entry.path)
            return True
    except FileNotFoundError:
        return True  # removed meanwhile by another process


def clear(root: Path | None = None) -> tuple[list[CacheEntry], list[CacheEntry]]:
    """Remove every entry; returns (removed, kept because in use)."""
    return prune(root, older_than=0.0)


def prune(root: Path | None = None, *, older_than: float | None = None,
          max_size: int | None = None, now: float | None = None
          ) -> tuple[list[CacheEntry], list[CacheEntry]]:
    """Remove entries not used for ``older_than`` seconds, then the least recently used
    until the cache holds at most ``max_size`` bytes. Returns (removed, kept because in use).
    Temporary files left by killed builds are removed from every entry not in use."""
    if older_than is None and max_size is None:
        raise DescriptionError("prune", "give --older-than, --max-size or both")
    now = time.time() if now is None else now
    listed = entries(root)
    removed: list[CacheEntry] = []
    busy: list[CacheEntry] = []
    total = sum(e.size for e in listed)
    for entry in listed:  # least recently used first
        too_old = older_than is not None and entry.age(now) >= older_than
        too_big = max_size is not None and total > max_size
        if not (too_old or too_big):
            with contextlib.suppress(OSError), entry_lock(entry.path, blocking=False) as held:
                if held:
                    remove_temporaries(entry.path)
            continue
        if remove(entry):
            removed.append(entry)
            total -= entry.size
        else:
            busy.append(entry)
    return removed, busy


# ---- sizes and ages, read and written ------------------------------------------------------

# A size is read exactly; beyond this many digits it is not a size but a mistake.
_MAX_SIZE_DIGITS = 4000
_UNITS = {"": 1, "k": 1 << 10, "m": 1 << 20, "g": 1 << 30, "t": 1 << 40}
_TIMES = {"s": 1.0, "m": 60.0, "h": 3600.0, "d": 86400.0, "w": 604800.0}


def parse_size(text: str, flag: str = "--max-size") -> int:
    """``"500M"``, ``"2G"``, ``"1.5GiB"``, ``"0"`` (bytes without a unit) to bytes, exactly
    (a size of any number of digits means what it says: a cache smaller than it is kept)."""
    match = re.fullmatch(r"\s*([0-9]*\.?[0-9]+)\s*([kKmMgGtT]?)(?:i?[bB])?\s*", text)
    if not match or len(match.group(1)) > _MAX_SIZE_DIGITS:
        raise DescriptionError(flag, f"expects a size like 500M or 2G, got {text[:40]!r}"
                               + ("..." if len(text) > 40 else ""))
    return int(Fraction(match.group(1)) * _UNITS[match.group(2).lower()])


def parse_age(text: str, flag: str = "--older-than") -> float:
    """``"30d"``, ``"12h"``, ``"90m"``, ``"2w"``, ``"45s"`` to seconds (a bare number is days)."""
    match = re.fullmatch(r"\s*([0-9]*\.?[0-9]+)\s*([smhdw]?)\s*", text)
    if not match:
        raise DescriptionError(flag, f"expects an age like 30d, 12h or 90m, got {text!r}")
    return float(match.group(1)) * _TIMES[match.group(2) or "d"]


def format_size(size: float) -> str:
    for unit in ("B", "KiB", "MiB", "GiB"):
        if size < 1024 or unit == "GiB":
            return f"{size:.0f} {unit}" if unit == "B" else f"{size:.1f} {unit}"
        size /= 1024
    raise AssertionError("unreachable")


def format_age(seconds: float) -> str:
    for unit, length in (("d", 86400.0), ("h", 3600.0), ("min", 60.0)):
        if seconds >= length:
            return f"{seconds / length:.0f} {unit}"
    return f"{seconds:.0f} s"


def table(listed: Sequence[CacheEntry], now: float | None = None) -> list[str]:
    """The lines of ``jointplay cache list``: one per entry, newest last."""
    now = time.time() if now is None else now
    lines = [f"{'kind':<7}{'model':<24}{'key':<14}{'size':>11}  last used"]
    for e in listed:
        kind = "model" if e.kind == "models" else "build"
        lines.append(f"{kind:<7}{e.name[:23]:<24}{e.key[:12]:<14}{format_size(e.size):>11}  "
                     f"{format_age(e.age(now))} ago")
    return lines


__all__ = ["CacheEntry", "clear", "entries", "foreign", "format_age", "format_size", "parse_age",
           "parse_size", "prune", "remove", "table"]
