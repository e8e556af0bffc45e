"""What keeps a results file honest: checksums written with it, and the checks a read makes
before it trusts a byte.

Two layers, both written by :func:`jointplay.results.write.write_hdf5`:

* every numeric variable is stored chunked with HDF5's **Fletcher-32** filter: HDF5 itself
  (and so xarray, h5netcdf, netCDF-C, any reader) verifies each chunk as it reads it, and a
  damaged chunk is an error naming the variable, never other numbers;
* the root attribute :data:`DIGEST_ATTRIBUTE` holds a **SHA-256** of the whole content as read
  back: every group, every variable's name, type, shape and values (strings included, which
  HDF5 cannot filter), every attribute's name and value (the solver statistics, the metadata's
  JSON, the accuracy's numbers). It catches what Fletcher-32 cannot see: attributes, strings,
  shapes, added or removed objects, and values rewritten through an HDF5 library (which
  recomputes Fletcher-32). It is a check against damage and careless edits, not a signature:
  whoever can write the file can write a matching digest.

Reading (:func:`load`) refuses, before opening, anything but a regular file (a FIFO would block
the read, ``/dev/zero`` never ends), and, before reading a variable, links other than plain
ones, data stored outside the file, types a results file never holds, and sizes the file
does not actually store (a declared ten-billion-sample variable is refused, not allocated).
The dimension bookkeeping of netCDF-4 (``DIMENSION_LIST``, ``REFERENCE_LIST``: object
addresses) is neither read nor digested; jointplay does not use it.
"""

from __future__ import annotations

import hashlib
import os
import stat
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from jointplay.common.errors import DescriptionError

DIGEST_ATTRIBUTE = "jointplay_sha256"
"""Root attribute: SHA-256 (hex) of the file's content (see :func:`digest`)."""
REWRITE = "write it again with `jointplay simulate --out`"
# netCDF-4's dimension-scale references: object addresses, meaningless outside the file.
_BOOKKEEPING = frozenset({"DIMENSION_LIST", "REFERENCE_LIST"})
# A chunk deflated at best about 1032:1; beyond that a declared size is not in the file.
_MAX_EXPANSION = 1100
_SLACK_BYTES = 1 << 16
_MAX_DEPTH = 3  # root, /ideal, /ideal/wear


def shown(name: object) -> str:
    """A name from a file, printable on one line (odd characters escaped)."""
    text = str(name)
    return text if text.isprintable() and len(text) <= 80 else ascii(text[:80])


def damaged(path: str | Path, where: str, what: str) -> DescriptionError:
    """The error a read gives for a file it cannot trust: one line, the file, the part."""
    one_line = " ".join(str(what).split())
    return DescriptionError(where, f"{one_line}; the file is damaged or not a results file: "
                            f"{REWRITE}", str(path))


def regular_file(path: str | Path) -> int:
    """The size of ``path`` if it is a non-empty regular file (symbolic links followed);
    otherwise a one-line error saying what it is. Nothing is opened."""
    path = Path(path)
    try:
        info = os.stat(path)
    except FileNotFoundError:
        why = (f"a symbolic link to {shown(os.readlink(path))}, which does not exist"
               if path.is_symlink() else "no such file")
        raise DescriptionError("path", f"{why} (give a results file written by "
                               "`jointplay simulate --out RUN.h5`)", str(path)) from None
    except OSError as err:
        from jointplay.common.files import describe_os_error

        raise DescriptionError("path", f"cannot read it ({describe_os_error(err)})",
                               str(path)) from None
    mode = info.st_mode
    kinds = ((stat.S_ISDIR, "a folder"), (stat.S_ISFIFO, "a FIFO (named pipe)"),
             (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
             (stat.S_ISSOCK, "a socket"))
    for test, kind in kinds:
        if test(mode):
            raise DescriptionError("path", f"is {kind}, not a results file (give a file "
                                   "written by `jointplay simulate --out RUN.h5`)", str(path))
    if not stat.S_ISREG(mode):
        raise DescriptionError("path", "is not a regular file", str(path))
    if info.st_size == 0:
        raise DescriptionError("path", f"is empty (0 bytes), not a results file: {REWRITE}",
                               str(path))
    return int(info.st_size)


@dataclass
class LoadedGroup:
    """A group of a results file read into memory: attributes, variables (arrays, with their
    own attributes) and subgroups. Indexing by name gives a subgroup or a variable, as h5py
    does, so the readers of every layout work on it."""

    name: str
    attrs: dict[str, Any] = field(default_factory=dict)
    variables: dict[str, np.ndarray] = field(default_factory=dict)
    variable_attrs: dict[str, dict[str, Any]] = field(default_factory=dict)
    groups: dict[str, LoadedGroup] = field(default_factory=dict)

    def __getitem__(self, name: str) -> Any:
        return self.groups[name] if name in self.groups else self.variables[name]

    def __contains__(self, name: object) -> bool:
        return name in self.groups or name in self.variables

    def items(self) -> list[tuple[str, np.ndarray]]:
        """The variables (as h5py's ``items()`` of a group holding only datasets)."""
        return list(self.variables.items())


def load(fh: Any, path: str | Path) -> LoadedGroup:
    """The whole open file in memory, every object checked before it is read."""
    return _load_group(fh, "/", path, 0)


def _load_group(group: Any, name: str, path: str | Path, depth: int) -> LoadedGroup:
    import h5py

    if depth > _MAX_DEPTH:
        raise damaged(path, name, "groups nested deeper than a results file has")
    loaded = LoadedGroup(name, attrs=_attributes(group, name, path))
    for key in group:
        where = f"{name.rstrip('/')}/{shown(key)}"
        if group.id.links.get_info(group._e(key)).type != h5py.h5l.TYPE_HARD:
            raise damaged(path, where, "is a soft or external link; a results file holds "
                          "no links to elsewhere")
        item = group[key]
        if isinstance(item, h5py.Group):
            loaded.groups[str(key)] = _load_group(item, where, path, depth + 1)
        elif isinstance(item, h5py.Dataset):
            loaded.variables[str(key)] = _dataset(item, where, path)
            loaded.variable_attrs[str(key)] = _attributes(item, where, path)
        else:
            raise damaged(path, where, f"is a {type(item).__name__}, which a results file "
                          "does not hold")
    return loaded


def _attributes(obj: Any, where: str, path: str | Path) -> dict[str, Any]:
    attrs = obj.attrs
    return {str(key): attrs[key] for key in attrs if key not in _BOOKKEEPING}


def _dataset(ds: Any, where: str, path: str | Path) -> np.ndarray:
    """A variable's values, after checking that the file really stores what it declares."""
    import h5py

    text = h5py.check_string_dtype(ds.dtype) is not None
    if not text and ds.dtype.kind not in "fiub":
        raise damaged(path, where, f"has type {shown(ds.dtype)}, which a results file does "
                      "not use")
    layout = ds.id.get_create_plist().get_layout()
    if layout == h5py.h5d.VIRTUAL or (layout == h5py.h5d.CONTIGUOUS and ds.external):
        raise damaged(path, where, "keeps its values outside the file")
    declared = int(np.prod(ds.shape, dtype=object)) * max(int(ds.dtype.itemsize), 1)
    stored = int(ds.id.get_storage_size())
    if declared > _MAX_EXPANSION * stored + _SLACK_BYTES:
        raise damaged(path, where, f"declares shape {ds.shape} ({declared:.3g} bytes) but "
                      f"the file stores {stored} bytes of it")
    try:
        values = ds[()]
    except OSError as err:
        raise damaged(path, where, f"cannot be read ({' '.join(str(err).split())[:160]}): a "
                      "part fails its Fletcher-32 checksum, or the file is cut short") from None
    if not isinstance(values, np.ndarray):  # a scalar (the version-1 layout's statistics)
        boxed = np.empty((), dtype=object)
        boxed[()] = values
        return boxed
    return values


# ----------------------------------------------------------------------------------- digest


def digest(root: LoadedGroup) -> str:
    """SHA-256 (hex) of everything in ``root`` but the digest attribute itself: groups,
    variables (name, type, shape, values) and attributes (name, value), in name order."""
    sha = hashlib.sha256()
    _digest_group(sha, root)
    return sha.hexdigest()


def _feed(sha: Any, tag: bytes, payload: bytes) -> None:
    sha.update(tag + len(payload).to_bytes(8, "little") + payload)


def _digest_group(sha: Any, group: LoadedGroup) -> None:
    _feed(sha, b"G", group.name.encode("utf-8", "surrogatepass"))
    _digest_attrs(sha, {k: v for k, v in group.attrs.items() if k != DIGEST_ATTRIBUTE})
    for key in sorted(group.variables):
        _feed(sha, b"V", key.encode("utf-8", "surrogatepass"))
        _feed(sha, b"v", value_bytes(group.variables[key]))
        _digest_attrs(sha, group.variable_attrs.get(key, {}))
    for key in sorted(group.groups):
        _digest_group(sha, group.groups[key])


def _digest_attrs(sha: Any, attrs: dict[str, Any]) -> None:
    for key in sorted(attrs):
        _feed(sha, b"A", key.encode("utf-8", "surrogatepass"))
        _feed(sha, b"a", value_bytes(attrs[key]))


def value_bytes(value: Any) -> bytes:
    """An attribute's or variable's value as bytes that differ whenever the value, its type
    or its shape does."""
    if isinstance(value, str):
        return b"s" + value.encode("utf-8", "surrogatepass")
    if isinstance(value, bytes):
        return b"b" + value
    array = np.asarray(value)
    head = f"{array.dtype.str}{array.shape}".encode()
    if array.dtype.kind == "O":
        parts = [value_bytes(item) for item in array.ravel().tolist()]
        return b"o" + head + b"".join(len(p).to_bytes(8, "little") + p for p in parts)
    if array.dtype.hasobject:
        raise TypeError(f"a value of type {array.dtype} has no byte form")
    return b"n" + head + np.ascontiguousarray(array).tobytes()


def stamp(fh: Any) -> None:
    """Write the digest of the open (complete) file ``fh`` into its root attributes."""
    fh.attrs[DIGEST_ATTRIBUTE] = digest(load(fh, "the file being written"))


def verify(root: LoadedGroup, path: str | Path) -> bool:
    """True if ``root`` carries a digest and it matches; False if it carries none (a file
    written before results files had one); a mismatch is an error."""
    stored = root.attrs.get(DIGEST_ATTRIBUTE)
    if stored is None:
        return False
    text = stored.decode("ascii", "replace") if isinstance(stored, bytes) else stored
    if not isinstance(text, str) or text != digest(root):
        raise damaged(path, DIGEST_ATTRIBUTE, "the file's content does not match its "
                      "checksum (it was changed or damaged after it was written)")
    return True
