"""Compile generated C into a per-user cache keyed by a hash of what produced the build.

The key covers the C text, the compiler flags and the compiler's version, so a build is
reused only when all three match. A cache entry is complete only once its marker file,
written last and holding the library's size and checksum, agrees with the library on disk,
and the library is a whole ELF file (every segment the loader maps lies inside it: a
truncated library, even beside a forged marker, would crash the process with SIGBUS when
loaded). A corrupt or half-written entry is rebuilt, never loaded. A file lock per entry stops
two processes that build the same model at once from stepping on each other; the library is
compiled to a temporary name and renamed into place. Whoever holds an entry's lock is its only
builder, so every temporary file found there is left over from a killed build and is removed;
the compiler dies with the process that started it, so a killed build leaves no compiler
writing behind it. A build that fails (a full disk, say) removes what it wrote.
"""

from __future__ import annotations

import contextlib
import ctypes
import errno
import fcntl
import functools
import hashlib
import json
import os
import shutil
import signal
import struct
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from pathlib import Path

from jointplay.common import interrupts
from jointplay.common.errors import BuildError, FileError
from jointplay.common.files import atomic_write_text

# -O1: on CasADi's straight-line C, -O2 compiled 1.3-1.4x longer for 5-30 % faster calls at
# 4 links, -O3 no faster than -O2 (docs/results/build-times.md); compile time is what grows with the
# link count. -fno-math-errno lets sqrt/pow inline. CasADi emits its helpers (sq, fmax, ...)
# as exported functions, which in a -fPIC library may be interposed and so are never inlined,
# at any level: -fno-semantic-interposition with -finline-small-functions inlines them, for
# 0.82x the 12-link clearance chain's forward dynamics per call at about the same compile
# time and the same results to the bit (no flag here reorders arithmetic;
# docs/results/build-times.md,
# "Inlined helpers and 1/sqrt").
DEFAULT_CFLAGS: tuple[str, ...] = ("-O1", "-fPIC", "-shared", "-fno-math-errno",
                                   "-finline-small-functions", "-fno-semantic-interposition")
LIBRARY_NAME = "model.so"
MARKER_NAME = "complete.json"
OWNER_NAME = ".jointplay-entry"
"""The file that makes a cache folder jointplay's: written when jointplay creates an entry (a
build or a derived model), it is what `jointplay cache clear|prune` requires before removing
anything; a folder without it, or a link, is never touched."""
# gcc seconds per byte of C source, for the estimate said before a compile when the cache
# holds no build of its own with the same flags: measured on 2 cores on the paper robot's
# model (131 kB at -O1: 2.5 s) and the BDF driver (64 kB at -O3: 3.5 s).
COMPILE_S_PER_BYTE = {"-O1": 1.9e-5, "-O3": 5.5e-5}
# The estimate reads at most this many earlier builds' markers.
ESTIMATE_SAMPLES = 20


def cache_root() -> Path:
    """The per-user build cache's folder.

    Returns
    -------
    pathlib.Path
        ``$JOINTPLAY_CACHE``, else ``$XDG_CACHE_HOME/jointplay``, else ``~/.cache/jointplay``.
    """
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


def build_key(source: str, cflags: tuple[str, ...] = DEFAULT_CFLAGS, cc: str = "gcc",
              libraries: tuple[str, ...] = ()) -> str:
    """The cache key: the C text, the flags, the compiler and its version, and the libraries
    linked in (by path: a library linked against another names it by its path)."""
    h = hashlib.sha256()
    for part in (source, " ".join(cflags), cc, compiler_version(cc), *libraries):
        h.update(part.encode())
        h.update(b"\0")
    return h.hexdigest()


def _sha256_file(path: Path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as fh:
        for chunk in iter(lambda: fh.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def elf_is_whole(path: Path) -> bool:
    """Whether ``path`` is an ELF file that holds every byte its headers point at: the
    program headers, each loadable segment's file part, and the section headers. ``dlopen``
    maps the segments; a page of one beyond the end of the file raises SIGBUS when touched."""
    try:
        with open(path, "rb") as fh:
            size = os.fstat(fh.fileno()).st_size
            ident = fh.read(64)
            if len(ident) < 52 or ident[:4] != b"\x7fELF" or ident[4] not in (1, 2) \
                    or ident[5] not in (1, 2):
                return False
            wide, order = ident[4] == 2, "<" if ident[5] == 1 else ">"
            if wide:
                phoff, shoff = struct.unpack_from(order + "QQ", ident, 32)
                phentsize, phnum, shentsize, shnum = struct.unpack_from(order + "HHHH",
                                                                        ident, 54)
            else:
                phoff, shoff = struct.unpack_from(order + "II", ident, 28)
                phentsize, phnum, shentsize, shnum = struct.unpack_from(order + "HHHH",
                                                                        ident, 42)
            if phnum == 0 or phoff + phentsize * phnum > size \
                    or shoff + shentsize * shnum > size:
                return False
            fh.seek(phoff)
            table = fh.read(phentsize * phnum)
            for i in range(phnum):
                base = i * phentsize
                if wide:
                    kind, = struct.unpack_from(order + "I", table, base)
                    offset, = struct.unpack_from(order + "Q", table, base + 8)
                    filesz, = struct.unpack_from(order + "Q", table, base + 32)
                else:
                    kind, offset = struct.unpack_from(order + "II", table, base)
                    filesz, = struct.unpack_from(order + "I", table, base + 16)
                if kind == 1 and offset + filesz > size:  # PT_LOAD past the end
                    return False
            return True
    except (OSError, struct.error):
        return False


def _entry_is_complete(entry: Path) -> bool:
    """The marker names the library's size and checksum, the library on disk has both, and
    it is a whole ELF file: only then may it be loaded."""
    library = entry / LIBRARY_NAME
    try:
        marker = json.loads((entry / MARKER_NAME).read_text())
        # Markers written before sizes were recorded have none: checksum and ELF still hold.
        if "size" in marker and library.stat().st_size != int(marker["size"]):
            return False
        return bool(elf_is_whole(library) and marker["sha256"] == _sha256_file(library))
    except (OSError, ValueError, KeyError, TypeError):
        return False


def _note_use(entry: Path) -> None:
    """Mark the entry used now: `jointplay cache prune` removes the least recently used."""
    with contextlib.suppress(OSError):
        os.utime(entry / MARKER_NAME)


def compile_estimate(size: int, cflags: tuple[str, ...], cache: Path | None = None) -> float:
    """About how many seconds gcc takes on ``size`` bytes of C with ``cflags``: the median
    rate (seconds per byte) of earlier builds with the same flags in the cache, else
    :data:`COMPILE_S_PER_BYTE`."""
    import statistics

    rates: list[float] = []
    markers = ((cache or cache_root()) / "build").glob(f"*/{MARKER_NAME}")
    for marker in markers:
        if len(rates) >= ESTIMATE_SAMPLES:
            break
        try:
            record = json.loads(marker.read_text(encoding="utf-8"))
            c_size = (marker.parent / "model.c").stat().st_size
        except (OSError, ValueError):
            continue
        if (isinstance(record, dict) and record.get("cflags") == list(cflags) and c_size
                and isinstance(record.get("seconds"), int | float)):
            rates.append(float(record["seconds"]) / c_size)
    opt = next((f for f in cflags if f.startswith("-O")), "-O1")
    rate = statistics.median(rates) if rates else COMPILE_S_PER_BYTE.get(opt, 2e-5)
    return rate * size


def compile_source(
    source: str,
    cflags: tuple[str, ...] = DEFAULT_CFLAGS,
    cc: str = "gcc",
    cache: Path | None = None,
    libraries: tuple[str, ...] = (),
    announce: Callable[[], None] | None = None,
    what: str | None = None,
) -> tuple[Path, float]:
    """Compile C source into a shared library in the hash-keyed cache, or reuse the build there.

    Parameters
    ----------
    source : str
        The C source text.
    cflags : tuple of str, optional
        Compiler flags.
    cc : str, default "gcc"
        The compiler.
    cache : pathlib.Path, optional
        The cache folder (default: :func:`cache_root`).
    libraries : tuple of str, optional
        Paths of shared libraries linked in.
    announce : callable, optional
        Called just before the compiler starts.
    what : str, optional
        What is compiled (e.g. ``"model 'paper_4dof'"``): a compile is then first announced on
        stderr with its estimated duration (:func:`compile_estimate`).

    Returns
    -------
    pathlib.Path
        The compiled library.
    float
        Seconds spent compiling (0.0 when the cache already held a complete build).

    Raises
    ------
    BuildError
        When the compiler fails (its message included).
    """
    key = build_key(source, cflags, cc, libraries)
    root = cache or cache_root()
    entry = root / "build" / key
    if what is not None and announce is None:
        def announce() -> None:
            seconds = compile_estimate(len(source.encode()), cflags, root)
            print(f"jointplay: compiling {what} ({len(source) / 1000:.0f} kB of C): about "
                  f"{max(1, round(seconds))} s, once (then cached)", file=sys.stderr,
                  flush=True)

    library = entry / LIBRARY_NAME
    if _entry_is_complete(entry):
        _note_use(entry)
        return library, 0.0
    if (entry / MARKER_NAME).exists():  # was complete once: say why it is built again
        from jointplay.store.model import note

        note(f"the compiled model {library} is damaged (its size, checksum or ELF headers "
             "do not match); compiling it again")
    try:
        return _build(source, cflags, cc, entry, libraries, announce)
    except (OSError, FileError) as err:
        raise cache_error(entry, err) from None


def cache_error(path: Path, err: OSError | FileError) -> FileError:
    """A cache that cannot be written: say where, why, and how to use another."""
    from jointplay.common.files import describe_os_error

    cause = describe_os_error(err) if isinstance(err, OSError) else \
        err.cause.removeprefix("cannot write: ").split(";")[0]
    return FileError(str(path), f"cannot write the model cache ({cause}); set "
                     "JOINTPLAY_CACHE to a writable folder")


def is_owned(folder: Path) -> bool:
    """Whether ``folder`` is a cache entry jointplay made: a real folder (not a link) that
    holds jointplay's owner file (a regular file, not a link)."""
    import stat

    try:
        return stat.S_ISDIR(os.lstat(folder).st_mode) and \
            stat.S_ISREG(os.lstat(folder / OWNER_NAME).st_mode)
    except OSError:
        return False


def claim_entry(folder: Path) -> None:
    """Mark ``folder`` as jointplay's (call it holding the folder's lock, having made or
    rewritten what is in it)."""
    if not is_owned(folder):
        (folder / OWNER_NAME).write_text("a jointplay cache entry: `jointplay cache clear` "
                                         "may remove this folder\n", encoding="utf-8")


class LibraryGone(BuildError):
    """A library a build links against was removed before the build could hold it."""


@contextlib.contextmanager
def hold_libraries(libraries: tuple[str, ...]) -> Iterator[None]:
    """Hold the cache entries of ``libraries`` (shared locks) while a build links against
    them: `jointplay cache clear|prune` takes an entry's lock exclusively without waiting, so
    it keeps them. Raises :class:`LibraryGone` if one was removed before it could be held."""
    with contextlib.ExitStack() as stack:
        for library in map(Path, libraries):
            if not is_owned(library.parent):  # not a cache entry: nothing there to hold
                continue
            try:
                lock = stack.enter_context(open(library.parent / ".lock", "a"))
            except FileNotFoundError:
                raise LibraryGone(f"{library} was removed") from None
            fcntl.flock(lock, fcntl.LOCK_SH)
            if not _entry_is_complete(library.parent):
                raise LibraryGone(f"{library} was removed")
        yield


def discard_entry(entry: Path) -> None:
    """Mark a build entry incomplete, so the next :func:`compile_source` rebuilds it."""
    (entry / MARKER_NAME).unlink(missing_ok=True)


@contextlib.contextmanager
def entry_lock(entry: Path, blocking: bool = True) -> Iterator[bool]:
    """Hold ``entry``'s lock within (yields False, not waiting, if ``blocking`` is False and
    another process holds it). A lock file removed by a failed build while this process
    waited for it is taken again from the new file."""
    while True:
        with open(entry / ".lock", "a") as lock:
            try:
                fcntl.flock(lock, fcntl.LOCK_EX | (0 if blocking else fcntl.LOCK_NB))
            except BlockingIOError:
                yield False
                return
            try:
                current = os.stat(entry / ".lock").st_ino
            except FileNotFoundError:
                current = -1
            if current == os.fstat(lock.fileno()).st_ino:
                yield True
                return
        entry.mkdir(parents=True, exist_ok=True)


def remove_temporaries(folder: Path) -> int:
    """Remove every temporary file (``.*.part``) in ``folder``: call it holding the folder's
    lock, which makes them all leftovers of builds that were killed. Returns how many."""
    removed = 0
    for path in folder.glob(".*.part"):
        with contextlib.suppress(OSError):
            path.unlink()
            removed += 1
    return removed


def _die_with_parent() -> None:
    """In the compiler's process: die if the process that started it dies (Linux), so that a
    killed build leaves no compiler writing into the cache behind it."""
    with contextlib.suppress(OSError, AttributeError):
        ctypes.CDLL(None, use_errno=True).prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG


_OUT_OF_SPACE = ("No space left on device", "Disk quota exceeded", "File too large",
                 "Read-only file system")


def _compile(cc: str, cflags: tuple[str, ...], c_file: Path, output: Path,
             libraries: tuple[str, ...] = ()) -> None:
    preexec = _die_with_parent if sys.platform.startswith("linux") else None
    proc: subprocess.Popen[str] | None = None
    try:
        # A start with a preexec function runs Python's fork hooks, where a Ctrl-C would be
        # swallowed (see interrupts.fork): it is raised once the compiler has started.
        with interrupts.deferred():
            proc = subprocess.Popen(
                [cc, *cflags, str(c_file), "-o", str(output), *libraries, "-lm"],
                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, preexec_fn=preexec)
        _, stderr = proc.communicate()
    except BaseException:
        if proc is not None:
            proc.kill()
            proc.communicate()
        raise
    if proc.returncode == 0:
        return
    for cause in _OUT_OF_SPACE:  # the compiler could not write: an I/O error, one line
        if cause in stderr:
            number = {"No space left on device": errno.ENOSPC, "File too large": errno.EFBIG,
                      "Disk quota exceeded": errno.EDQUOT}.get(cause, errno.EROFS)
            raise OSError(number, os.strerror(number), str(output))
    raise BuildError(f"{cc} failed on {c_file}:\n{stderr[-4000:]}")


def _build(source: str, cflags: tuple[str, ...], cc: str, entry: Path,
           libraries: tuple[str, ...] = (), announce: Callable[[], None] | None = None
           ) -> tuple[Path, float]:
    from jointplay.common.files import temp_tag

    library = entry / LIBRARY_NAME
    fresh = not entry.exists()
    entry.mkdir(parents=True, exist_ok=True)
    try:
        with entry_lock(entry):
            if _entry_is_complete(entry):  # another process finished it while we waited
                return library, 0.0
            remove_temporaries(entry)  # no other build of this entry runs: all left over
            claim_entry(entry)
            for stale in (entry / MARKER_NAME, library):
                stale.unlink(missing_ok=True)
            c_file = entry / "model.c"
            atomic_write_text(c_file, source)
            tmp_lib = entry / f".{LIBRARY_NAME}.{temp_tag()}.x.part"
            if announce is not None:
                announce()
            t0 = time.perf_counter()
            try:
                with hold_libraries(libraries):
                    _compile(cc, cflags, c_file, tmp_lib, libraries)
            except BaseException:  # failed or interrupted: no half-written library left
                tmp_lib.unlink(missing_ok=True)
                raise
            elapsed = time.perf_counter() - t0
            os.replace(tmp_lib, library)
            atomic_write_text(entry / MARKER_NAME, json.dumps({
                "sha256": _sha256_file(library), "size": library.stat().st_size,
                "cflags": list(cflags), "cc": cc, "compiler": compiler_version(cc),
                "libraries": list(libraries),
                "seconds": round(elapsed, 3)}))
    except BaseException:
        _discard_failed(entry, fresh)
        raise
    return library, elapsed


def _discard_failed(entry: Path, fresh: bool) -> None:
    """A build that failed leaves nothing behind: what it wrote, and the entry's folder if it
    made it (unless another process completed the entry meanwhile)."""
    with contextlib.suppress(OSError), entry_lock(entry, blocking=False) as held:
        if not held or _entry_is_complete(entry):
            return
        remove_temporaries(entry)
        for name in (MARKER_NAME, LIBRARY_NAME, "model.c"):
            (entry / name).unlink(missing_ok=True)
        if fresh:
            (entry / OWNER_NAME).unlink(missing_ok=True)
            (entry / ".lock").unlink(missing_ok=True)
            entry.rmdir()


def clear_cache(cache: Path | None = None) -> None:
    shutil.rmtree((cache or cache_root()) / "build", ignore_errors=True)
