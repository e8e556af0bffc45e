"""Names of the files a command writes: refused before any work when no write could honour
them, and the short stems of their temporary files (:mod:`jointplay.common.files`)."""

from __future__ import annotations

import hashlib
import os
import stat
from pathlib import Path

NAME_MAX = 255
"""Bytes of one file name (Linux, macOS and Windows file systems alike)."""
# Above this many bytes a target's name is replaced, in its temporary names, by a hash: the
# temporary name adds about 40 bytes, and must never be longer than a legal name (255).
_LONG_NAME_BYTES = 180


def temp_stem(name: str) -> str:
    """How the temporary files of the target ``name`` begin (after the dot): the name itself,
    or, for a long one, a short hash of it, so that no legal name fails for its temporary."""
    raw = os.fsencode(name)
    if len(raw) <= _LONG_NAME_BYTES:
        return name
    return "h" + hashlib.sha256(raw).hexdigest()[:24]


def check_output_name(flag: str, path: str | Path, kind: str = "file") -> None:
    """Refuse (exit 2, naming ``flag``) an output name no write could honour: empty, ``-``,
    a file name ending in ``/`` (that names a folder), or one that is not UTF-8."""
    from jointplay.common.errors import DescriptionError

    text = os.fspath(path)
    if text == "":
        raise DescriptionError(flag, f"is empty; give the name of a {kind} to write")
    if text == "-":
        raise DescriptionError(flag, f"'-' (standard output) is not supported; give the "
                               f"name of a {kind} to write")
    if kind == "file" and text.endswith(("/", os.sep)):
        raise DescriptionError(flag, f"{text!r} ends in '/', which names a folder; give a "
                               f"file name (e.g. {text.rstrip('/' + os.sep) or '.'}/NAME)")
    for part in Path(text).parts:  # the folders on the way too, not only the last name
        name = os.fsencode(part)
        if len(name) > NAME_MAX:
            raise DescriptionError(flag, f"the name {part[:40]!r}... is {len(name)} bytes; a "
                                   f"file system takes at most {NAME_MAX}: give a shorter "
                                   "name")
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        shown = text.encode("utf-8", "surrogateescape").decode("utf-8", "replace")
        raise DescriptionError(flag, f"the name {shown!r} is not valid UTF-8; give a name in "
                               "UTF-8") from None


def file_above(path: Path) -> Path | None:
    """The nearest existing ancestor of ``path`` when it is not a folder (else None)."""
    for ancestor in path.parents:
        try:
            mode = os.stat(ancestor).st_mode
        except (FileNotFoundError, NotADirectoryError):  # absent, or under a file: higher up
            continue
        except OSError:
            return None  # unreadable: the write that follows reports it
        return None if stat.S_ISDIR(mode) else ancestor
    return None


__all__ = ["NAME_MAX", "check_output_name", "file_above", "temp_stem"]
