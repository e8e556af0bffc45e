"""Compile generated C into a per-user cache keyed by a hash of what produced the build.

The key covers the C text, the compiler flags and the compiler's version, so a build is
reused only when all three match. A cache entry is complete only once its marker file,
written last and holding the library's checksum, agrees with the library on disk: a corrupt
or half-written entry is rebuilt, never loaded. A file lock per entry stops two processes
that build the same model at once from stepping on each other; the library is compiled to a
temporary name and renamed into place.
"""

from __future__ import annotations

import fcntl
import functools
import hashlib
import json
import os
import shutil
import subprocess
import time
from pathlib import Path

from jointplay.common.errors import BuildError, FileError
from jointplay.common.files import atomic_write_text

# -O1: on CasADi's straight-line C, -O2 compiled 1.3-1.4x longer for 5-30 % faster calls at
# 4 links, -O3 no faster than -O2 (README, "Build times"); compile time is what grows with the
# link count. -fno-math-errno lets sqrt/pow inline.
DEFAULT_CFLAGS: tuple[str, ...] = ("-O1", "-fPIC", "-shared", "-fno-math-errno")
LIBRARY_NAME = "model.so"
MARKER_NAME = "complete.json"


def cache_root() -> Path:
    """``$JOINTPLAY_CACHE``, else ``$XDG_CACHE_HOME/jointplay``, else ``~/.cache/jointplay``."""
    env = os.environ.get("JOINTPLAY_CACHE")
    if env:
        return Path(env)
    xdg = os.environ.get("XDG_CACHE_HOME")
    return (Path(xdg) if xdg else Path.home() / ".cache") / "jointplay"


@functools.cache
def compiler_version(cc: str = "gcc") -> str:
    try:
        out = subprocess.run([cc, "--version"], capture_output=True, text=True, check=True)
    except (OSError, subprocess.CalledProcessError) as err:
        raise BuildError(f"the C compiler {cc!r} is not usable ({err}); install gcc") from None
    return out.stdout.splitlines()[0].strip()


def build_key(source: str, cflags: tuple[str, ...] = DEFAULT_CFLAGS, cc: str = "gcc") -> str:
    h = hashlib.sha256()
    for part in (source, " ".join(cflags), cc, compiler_version(cc)):
        h.update(part.encode())
        h.update(b"\0")
    return h.hexdigest()


def _sha256_file(path: Path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as fh:
        for chunk in iter(lambda: fh.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def _entry_is_complete(entry: Path) -> bool:
    try:
        marker = json.loads((entry / MARKER_NAME).read_text())
        return bool(marker["sha256"] == _sha256_file(entry / LIBRARY_NAME))
    except (OSError, ValueError, KeyError, TypeError):
        return False


def compile_source(
    source: str,
    cflags: tuple[str, ...] = DEFAULT_CFLAGS,
    cc: str = "gcc",
    cache: Path | None = None,
) -> tuple[Path, float]:
    """Return the path of the compiled library for ``source`` and the seconds spent compiling
    (0.0 when the cache already held a complete build)."""
    key = build_key(source, cflags, cc)
    entry = (cache or cache_root()) / "build" / key
    library = entry / LIBRARY_NAME
    if _entry_is_complete(entry):
        return library, 0.0
    try:
        return _build(source, cflags, cc, entry)
    except (OSError, FileError) as err:
        raise cache_error(entry, err) from None


def cache_error(path: Path, err: OSError | FileError) -> FileError:
    """A cache that cannot be written: say where, why, and how to use another."""
    from jointplay.common.files import describe_os_error

    cause = describe_os_error(err) if isinstance(err, OSError) else \
        err.cause.removeprefix("cannot write: ").split(";")[0]
    return FileError(str(path), f"cannot write the model cache ({cause}); set "
                     "JOINTPLAY_CACHE to a writable folder")


def discard_entry(entry: Path) -> None:
    """Mark a build entry incomplete, so the next :func:`compile_source` rebuilds it."""
    (entry / MARKER_NAME).unlink(missing_ok=True)


def _build(source: str, cflags: tuple[str, ...], cc: str, entry: Path) -> tuple[Path, float]:
    from jointplay.common.files import sweep_stale, temp_tag

    library = entry / LIBRARY_NAME
    entry.mkdir(parents=True, exist_ok=True)
    with open(entry / ".lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if _entry_is_complete(entry):  # another process finished it while we waited
            return library, 0.0
        sweep_stale(entry)  # temporaries of builds that were killed
        for stale in (entry / MARKER_NAME, library):
            stale.unlink(missing_ok=True)
        c_file = entry / "model.c"
        atomic_write_text(c_file, source)
        tmp_lib = entry / f".{LIBRARY_NAME}.{temp_tag()}.x.part"
        t0 = time.perf_counter()
        try:
            proc = subprocess.run([cc, *cflags, str(c_file), "-o", str(tmp_lib), "-lm"],
                                  capture_output=True, text=True)
        except BaseException:  # interrupted: no half-written library left behind
            tmp_lib.unlink(missing_ok=True)
            raise
        elapsed = time.perf_counter() - t0
        if proc.returncode != 0:
            tmp_lib.unlink(missing_ok=True)
            raise BuildError(f"{cc} failed on {c_file}:\n{proc.stderr[-4000:]}")
        os.replace(tmp_lib, library)
        atomic_write_text(entry / MARKER_NAME, json.dumps({
            "sha256": _sha256_file(library), "cflags": list(cflags), "cc": cc,
            "compiler": compiler_version(cc), "seconds": round(elapsed, 3)}))
    return library, elapsed


def clear_cache(cache: Path | None = None) -> None:
    shutil.rmtree((cache or cache_root()) / "build", ignore_errors=True)
