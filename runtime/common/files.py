"""Files in and out: atomic writes, stale temporary files, bounded reads, one-line I/O errors.

A reader never sees a half-written file under the final name: every result is written to a
temporary file beside it (``.NAME.<tag>.<random>.part``, ``tag`` naming the host and the
process) and renamed only when complete. A process killed outright (SIGKILL, power loss)
leaves its temporary file behind; :func:`sweep_stale` removes those of dead processes at the
next run. Every failure to read or write is a :class:`FileError` naming the path and the cause.
"""

from __future__ import annotations

import contextlib
import contextvars
import errno
import hashlib
import os
import re
import shutil
import socket
import stat
import time
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from jointplay.common import interrupts
from jointplay.common.errors import FileError
from jointplay.common.names import temp_stem

# The output plan lives in its own module; its names stay importable from here.
from jointplay.common.output_plan import OutputPlan as OutputPlan
from jointplay.common.output_plan import PlannedInput as PlannedInput
from jointplay.common.output_plan import PlannedOutput as PlannedOutput
from jointplay.common.output_plan import matches_pattern

STALE_AGE_S = 24 * 3600.0
"""A temporary file of another host (or of no known process) is stale after a day."""

_HOST = hashlib.sha256(socket.gethostname().encode()).hexdigest()[:6]
_TAG = re.compile(r"\.j([0-9a-f]{6})p(\d+)\.[^.]*\.part(\.[A-Za-z0-9]+)?$")


def temp_tag() -> str:
    """This process's mark in temporary names: ``j<host hash>p<pid>``."""
    return f"j{_HOST}p{os.getpid()}"


def _errno(err: OSError) -> int:
    """The error number, also where h5py hides it in its message (0 if none)."""
    if err.errno:
        return int(err.errno)
    m = re.search(r"errno = (\d+)", str(err))
    return int(m.group(1)) if m else 0


def describe_os_error(err: OSError) -> str:
    """The cause of an I/O error in a few words."""
    if _errno(err):
        return os.strerror(_errno(err)).lower()
    text = str(err)
    return text.splitlines()[0][:200] if text else type(err).__name__


def file_error(path: str | Path, err: OSError, doing: str = "cannot write") -> FileError:
    """A one-line error for ``err`` met while ``doing`` ``path``, with a hint for the usual."""
    cause = describe_os_error(err)
    hint = {errno.ENOSPC: "; free some space or write elsewhere",
            errno.EDQUOT: "; free some space or write elsewhere",
            errno.EROFS: "; write elsewhere",
            errno.EACCES: "; write elsewhere or change the permissions",
            errno.EFBIG: "; write elsewhere"}.get(_errno(err), "")
    if not hint and "space" in cause:
        hint = "; free some space or write elsewhere"
    return FileError(str(path), f"{doing}: {cause}{hint}")


@contextlib.contextmanager
def atomic_path(path: str | Path, suffix: str = ".part") -> Iterator[Path]:
    """Yield a temporary path beside ``path``; rename it onto ``path`` only on success.

    An interrupt that arrived while writing (even one some library swallowed) discards the
    file; an ``OSError`` becomes a :class:`FileError` naming ``path``. ``suffix`` ends the
    temporary name: writers that choose the format by the file's extension need the real one
    there (e.g. ``".part.gif"``); it must start with ``.part``, which marks it temporary.
    """
    path = Path(path)
    # The name is chosen before the file exists and the file is created inside the ``try``
    # that removes it: an interrupt at any moment, even right after the creation, leaves
    # nothing behind. O_EXCL makes the name this call's own; the mode is a plain open()'s.
    tmp_path = path.with_name(f".{temp_stem(path.name)}.{temp_tag()}.{os.urandom(4).hex()}"
                              f"{suffix}")
    try:
        os.close(os.open(tmp_path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666))
        yield tmp_path
        interrupts.raise_if_interrupted()
        with open(tmp_path, "rb") as fh:
            os.fsync(fh.fileno())
        interrupts.raise_if_interrupted()
        pending = _TRANSACTION.get()
        if pending is not None and pending.defers(path):
            pending.hold(tmp_path, path)  # renamed with the command's other outputs at the end
        else:
            os.replace(tmp_path, path)
    except FileError:
        _discard(tmp_path)
        raise
    except OSError as err:
        _discard(tmp_path)
        raise file_error(path, err) from None
    except BaseException:
        _discard(tmp_path)
        raise


def _discard(tmp: Path) -> None:
    """Remove a temporary file (it may not exist yet, or be gone already)."""
    with contextlib.suppress(OSError):
        tmp.unlink(missing_ok=True)


def atomic_write_text(path: str | Path, text: str) -> None:
    with atomic_path(path) as tmp:
        tmp.write_text(text, encoding="utf-8")


def atomic_write_bytes(path: str | Path, data: bytes) -> None:
    """Write ``data`` with plain file I/O (errors are ``OSError``, reported naming ``path``)."""
    with atomic_path(path) as tmp, open(tmp, "wb") as fh:
        fh.write(data)


def write_hdf5_in_memory(path: str | Path, build: Callable[[Any], None], *,
                         libver: Any = None) -> None:
    """Build an HDF5 file in memory (the HDF5 core driver) with ``build(h5py_file)``, then
    write its bytes atomically with plain file I/O.

    A full disk, a quota or an I/O error then surfaces as an ``OSError`` of an ordinary
    ``write`` (a :class:`FileError` naming ``path``), never inside HDF5, whose failures while
    flushing to a full disk happen in destructors and can crash the process. ``libver`` is
    h5py's bound on the file format's version (None: the library's default, the oldest).
    """
    import h5py

    fh = h5py.File(f"jointplay-{id(build)}.h5", "w", driver="core", backing_store=False,
                   track_order=True, libver=libver)
    try:
        build(fh)
        fh.flush()
        image = fh.id.get_file_image()
    finally:
        fh.close()
    atomic_write_bytes(path, image)


# ------------------------------------------------------------------------- all or nothing


@dataclass
class _Transaction:
    """Completed temporaries waiting to be renamed onto their targets together."""

    targets: frozenset[Path]  # resolved real paths the transaction owns
    folders: tuple[tuple[Path, str], ...]  # folders (and name patterns) whose files it owns
    held: list[tuple[Path, Path]] = field(default_factory=list)
    created: list[Path] = field(default_factory=list)  # folders it made, deepest last

    def defers(self, path: Path) -> bool:
        real = Path(os.path.realpath(path))
        return real in self.targets or any(
            folder in real.parents and matches_pattern(real.name, pattern)
            for folder, pattern in self.folders)

    def hold(self, tmp: Path, path: Path) -> None:
        self.held.append((tmp, path))

    def discard(self) -> None:
        for tmp, _ in self.held:
            tmp.unlink(missing_ok=True)
        self.held.clear()
        for folder in reversed(self.created):
            with contextlib.suppress(OSError):
                folder.rmdir()  # only if still empty: never someone else's files

    def commit(self) -> list[Path]:
        """Rename every held temporary onto its target, with SIGINT and SIGTERM held
        (:func:`jointplay.common.interrupts.held`). Should a rename fail or a signal arrive,
        the targets are put back as they were, no temporary stays, and the signal is raised."""
        placed: list[tuple[Path, Path | None]] = []  # target, where its previous file is kept
        with interrupts.held() as arrived:
            try:
                for tmp, path in self.held:
                    if arrived():
                        raise KeyboardInterrupt  # undone below; the signal is raised after
                    # The previous file's place is recorded before it is linked there.
                    aside = path.with_name(f".{temp_stem(path.name)}.{temp_tag()}.old"
                                           f"{os.urandom(4).hex()}.part") \
                        if path.exists() else None
                    placed.append((path, aside))
                    if aside is not None:
                        _set_aside(path, aside)
                    os.replace(tmp, path)
                if arrived():
                    raise KeyboardInterrupt
            except BaseException as err:  # a failed rename, or an interrupt between two
                self._put_back(placed)
                if isinstance(err, OSError):
                    raise file_error(path, err) from None
                if not arrived():
                    raise
                return []  # the held signal is raised on leaving
            for _, previous in placed:
                if previous is not None:
                    previous.unlink(missing_ok=True)
            self.held.clear()
        return [path for path, _ in placed]

    def _put_back(self, placed: list[tuple[Path, Path | None]]) -> None:
        for target, previous in reversed(placed):
            with contextlib.suppress(OSError):
                if previous is None:
                    target.unlink(missing_ok=True)
                elif not os.path.lexists(previous):  # nothing set aside yet: nothing to undo
                    continue
                elif os.path.lexists(target) and os.path.samefile(previous, target):
                    previous.unlink()  # not replaced yet: drop the link
                else:
                    os.replace(previous, target)
        for tmp, _ in self.held:
            tmp.unlink(missing_ok=True)
        self.held.clear()


def _set_aside(path: Path, aside: Path) -> None:
    """Keep the file at ``path`` under ``aside`` too (a hard link), so that it can be put
    back; where links are not supported, the file is moved there."""
    try:
        os.link(path, aside)
    except OSError:
        os.replace(path, aside)


def replace_together(pairs: Iterable[tuple[Path, Path]]) -> list[Path]:
    """Rename each complete file onto its target, in order; should one rename fail (or an
    interrupt arrive between two), every target is put back as it was and the sources are
    removed. Errors are a :class:`FileError` naming the target."""
    moves = _Transaction(frozenset(), ())
    moves.held.extend(pairs)
    return moves.commit()


_TRANSACTION: contextvars.ContextVar[_Transaction | None] = contextvars.ContextVar(
    "jointplay_output_transaction", default=None)


def make_folder(path: str | Path, flag: str = "--out") -> Path:
    """Create an output folder (and its parents); inside :func:`all_or_nothing`, a failed run
    removes the folders it created (when they are empty again)."""
    path = Path(path)
    missing = []
    probe = path
    while not probe.exists() and probe != probe.parent:
        missing.append(probe)
        probe = probe.parent
    pending = _TRANSACTION.get()
    if pending is not None:  # known before they exist: an interrupt right after removes them
        pending.created.extend(reversed(missing))
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        raise file_error(path, err, "cannot create folder") from None
    return path


@contextlib.contextmanager
def all_or_nothing(plan: OutputPlan) -> Iterator[None]:
    """Write the outputs of ``plan`` together: each is completed under a temporary name, and
    only when the block ends without error are all renamed into place. On any error (or
    interrupt) no planned output appears, no temporary stays, and folders this block created
    are removed again. Writes to paths outside the plan (the model cache) are not deferred.
    Nested blocks join the outermost one.
    """
    if _TRANSACTION.get() is not None:
        yield
        return
    pending = _Transaction(frozenset(Path(os.path.realpath(o.path)) for o in plan.outputs
                                     if o.kind == "file"),
                           tuple((Path(os.path.realpath(o.path)), o.pattern)
                                 for o in plan.outputs if o.kind == "folder"))
    token = _TRANSACTION.set(pending)
    try:
        yield
        interrupts.raise_if_interrupted()
    except BaseException:
        _TRANSACTION.reset(token)
        pending.discard()
        raise
    _TRANSACTION.reset(token)
    try:
        pending.commit()
    except BaseException:
        pending.discard()
        raise


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # someone else's process
        return True
    return True


def _is_stale(entry: os.DirEntry[str], now: float) -> bool:
    m = _TAG.search(entry.name)
    if m and m.group(1) == _HOST:
        return int(m.group(2)) != os.getpid() and not _alive(int(m.group(2)))
    try:
        return now - entry.stat(follow_symlinks=False).st_mtime > STALE_AGE_S
    except OSError:
        return False


def sweep_stale(folder: str | Path, name: str | None = None) -> int:
    """Remove temporary files (``.*.part``) in ``folder`` left by processes that died.

    ``name`` limits the sweep to the temporaries of one target file. Returns how many were
    removed; a folder that cannot be listed is left alone (the write that follows reports it).
    """
    prefix = f".{temp_stem(name)}." if name else "."
    removed = 0
    now = time.time()
    try:
        entries = list(os.scandir(folder))
    except OSError:
        return 0
    for entry in entries:
        if not (entry.name.startswith(prefix)
                and (entry.name.endswith(".part") or _TAG.search(entry.name))):
            continue
        if not _is_stale(entry, now):
            continue
        try:
            if entry.is_dir(follow_symlinks=False):
                shutil.rmtree(entry.path)
            else:
                os.unlink(entry.path)
            removed += 1
        except OSError:
            pass
    return removed


def read_input(path: str | Path, field: str, what: str, limit: int) -> bytes:
    """The bytes of an input file, refused quickly unless it is a regular file of at most
    ``limit`` bytes (a device or FIFO would block or never end). Errors name ``field``."""
    from jointplay.common.errors import DescriptionError

    path = Path(path)
    try:
        st = os.stat(path)
    except FileNotFoundError:
        raise DescriptionError(field, f"not found; give the path of a {what}",
                               str(path)) from None
    except OSError as err:
        raise DescriptionError(field, f"cannot be read ({describe_os_error(err)})",
                               str(path)) from None
    if stat.S_ISDIR(st.st_mode):
        raise DescriptionError(field, f"is a folder; give the path of a {what}", str(path))
    if not stat.S_ISREG(st.st_mode):
        raise DescriptionError(field, f"is not a regular file (a device, FIFO or socket); give "
                               f"the path of a {what}", str(path))
    if st.st_size > limit:
        raise DescriptionError(field, f"is {st.st_size} bytes; a {what} may have at most "
                               f"{limit}", str(path))
    try:
        with open(path, "rb") as fh:
            data = fh.read(limit + 1)
    except OSError as err:
        raise DescriptionError(field, f"cannot be read ({describe_os_error(err)})",
                               str(path)) from None
    if len(data) > limit:
        raise DescriptionError(field, f"is more than {limit} bytes; a {what} may have at most "
                               f"{limit}", str(path))
    return data
