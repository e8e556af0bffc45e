"""Files in and out: atomic writes, stale temporary files, bounded reads, one-line I/O errors.

A reader never sees a half-written file under the final name: every result is written to a
temporary file beside it (``.NAME.<tag>.<random>.part``, ``tag`` naming the host and the
process) and renamed only when complete. A process killed outright (SIGKILL, power loss)
leaves its temporary file behind; :func:`sweep_stale` removes those of dead processes at the
next run. Every failure to read or write is a :class:`FileError` naming the path and the cause.
"""

from __future__ import annotations

import contextlib
import errno
import hashlib
import os
import re
import shutil
import socket
import stat
import tempfile
import time
from collections.abc import Iterator
from pathlib import Path

from jointplay.common import interrupts
from jointplay.common.errors import FileError

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
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.{temp_tag()}.", suffix=suffix,
                                   dir=path.parent)
    except OSError as err:
        raise file_error(path, err) from None
    os.close(fd)
    # mkstemp creates the file 0600; give the result the mode a plain open() would.
    umask = os.umask(0)
    os.umask(umask)
    tmp_path = Path(tmp)
    try:
        os.chmod(tmp, 0o666 & ~umask)
        yield tmp_path
        interrupts.raise_if_interrupted()
        with open(tmp_path, "rb") as fh:
            os.fsync(fh.fileno())
        interrupts.raise_if_interrupted()
        os.replace(tmp_path, path)
    except FileError:
        tmp_path.unlink(missing_ok=True)
        raise
    except OSError as err:
        tmp_path.unlink(missing_ok=True)
        raise file_error(path, err) from None
    except BaseException:
        tmp_path.unlink(missing_ok=True)
        raise


def atomic_write_text(path: str | Path, text: str) -> None:
    with atomic_path(path) as tmp:
        tmp.write_text(text, encoding="utf-8")


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
    prefix = f".{name}." if name else "."
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
