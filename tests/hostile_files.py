"""A generator of damaged and hostile results files, made from one real ``run.h5``.

:func:`make_hostile_files` writes, into a folder, copies of a results file damaged in every
way the reader must survive: seeded bit flips across the whole file, truncations, variables
of the wrong shape, type or rank, missing, extra and odd attributes, broken JSON, huge
declared sizes, NaN and inf in places, bytes that are not HDF5, an empty file, symbolic
links, a FIFO and a folder. Each edit made through h5py comes twice: as it is (the file's
digest no longer matches) and ``forged``, with the digest written again over the edit, so that
the layout's own checks are reached too.

Each :class:`Hostile` says whether the file is ``damaged`` (a read must give the original's
numbers or refuse it) or ``forged`` (a read must refuse it or give what it holds: a forger
can write any self-consistent file; only a crash or a raw error is wrong).
"""

from __future__ import annotations

import os
import shutil
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import h5py
import numpy as np

from jointplay.results import integrity


@dataclass(frozen=True)
class Hostile:
    """One generated file: its path, what was done to it, and whether it is forged."""

    path: Path
    what: str
    forged: bool = False


Edit = Callable[[h5py.File], None]


def _replace(name: str, data: Any, **options: Any) -> Edit:
    def edit(fh: h5py.File) -> None:
        if name in fh:
            del fh[name]
        fh.create_dataset(name, data=data, **options)
    return edit


def _reshaped(name: str, transform: Callable[[np.ndarray], np.ndarray]) -> Edit:
    def edit(fh: h5py.File) -> None:
        values = fh[name][()]
        del fh[name]
        fh.create_dataset(name, data=transform(values))
    return edit


def _attr(name: str, value: Any, group: str = "/") -> Edit:
    def edit(fh: h5py.File) -> None:
        fh[group].attrs[name] = value
    return edit


def _del_attr(name: str, group: str = "/") -> Edit:
    def edit(fh: h5py.File) -> None:
        del fh[group].attrs[name]
    return edit


def _delete(name: str) -> Edit:
    def edit(fh: h5py.File) -> None:
        del fh[name]
    return edit


def _poke(name: str, index: tuple[int, ...], value: float) -> Edit:
    def edit(fh: h5py.File) -> None:
        fh[name][index] = value
    return edit


def _huge(name: str, shape: tuple[int, ...]) -> Edit:
    """The variable replaced by one declaring ``shape`` with (almost) nothing stored."""
    def edit(fh: h5py.File) -> None:
        del fh[name]
        chunks = tuple(min(s, 1024) for s in shape)
        fh.create_dataset(name, shape=shape, dtype="f8", chunks=chunks)
    return edit


def _link(name: str, kind: str) -> Edit:
    def edit(fh: h5py.File) -> None:
        del fh[name]
        fh[name] = (h5py.SoftLink("/time") if kind == "soft"
                    else h5py.ExternalLink("/dev/zero", "/x"))
    return edit


def _extra_group(fh: h5py.File) -> None:
    fh.create_group("extra").create_dataset("x", data=np.arange(3.0))


def _nested(depth: int) -> str:
    return "[" * depth + "]" * depth


def structural_edits() -> Iterator[tuple[str, Edit]]:
    """(description, edit) of every edit made through h5py."""
    yield from [
        ("joint_angle one sample short", _reshaped("joint_angle", lambda v: v[:-1])),
        ("joint_angle an extra column", _reshaped("joint_angle", lambda v: np.c_[v, v[:, :1]])),
        ("joint_angle rank 1", _reshaped("joint_angle", lambda v: v[:, 0])),
        ("joint_angle rank 3", _reshaped("joint_angle", lambda v: v[..., None])),
        ("time one sample short", _reshaped("time", lambda v: v[:-1])),
        ("time rank 2", _reshaped("time", lambda v: v[:, None])),
        ("time scalar", _replace("time", 0.0)),
        ("impact_time a row short", _reshaped("impact_time", lambda v: v[:-1])),
        ("ideal/tip_position transposed", _reshaped("ideal/tip_position", lambda v: v.T)),
        ("joint_angle float32", _reshaped("joint_angle", lambda v: v.astype(np.float32))),
        ("joint_angle int64", _reshaped("joint_angle", lambda v: v.astype(np.int64))),
        ("joint_angle text", _reshaped("joint_angle", lambda v: v.astype("S8"))),
        ("joint_angle complex", _reshaped("joint_angle", lambda v: v.astype(np.complex128))),
        ("time int64", _reshaped("time", lambda v: (v * 1e3).astype(np.int64))),
        ("joint float", _reshaped("joint", lambda v: v.astype(np.float64))),
        ("joint zero", _reshaped("joint", lambda v: v * 0)),
        ("coordinate numbers", _replace("coordinate", np.arange(2))),
        ("axis three entries", _replace("axis", np.array([b"x", b"y", b"z"]))),
        ("impact_separated 7", _reshaped("impact_separated", lambda v: v + 7)),
        ("impact_joint 9", _reshaped("impact_joint", lambda v: v + 9)),
        ("parameter_value compound", _reshaped(
            "parameter_value", lambda v: v.astype([("a", "f8")]))),
        ("missing time", _delete("time")),
        ("missing joint_angle", _delete("joint_angle")),
        ("missing impact_joint", _delete("impact_joint")),
        ("missing energy_total", _delete("energy_total")),
        ("missing ideal/journal_offset", _delete("ideal/journal_offset")),
        ("extra variable", _replace("extra", np.arange(5.0))),
        ("extra group", _extra_group),
        ("soft link for joint_angle", _link("joint_angle", "soft")),
        ("external link for energy_total", _link("energy_total", "external")),
        ("huge time", _huge("time", (10**10,))),
        ("huge joint_angle", _huge("joint_angle", (10**9, 2))),
        ("huge impact_time", _huge("impact_time", (2**40,))),
        ("NaN in time", _poke("time", (5,), np.nan)),
        ("time not increasing", _poke("time", (5,), 0.0)),
        ("NaN in joint_angle", _poke("joint_angle", (10, 0), np.nan)),
        ("inf in tip_position", _poke("tip_position", (3, 1), np.inf)),
        ("NaN in parameter_value", _poke("parameter_value", (0,), np.nan)),
        ("NaN in impact_time", _poke("impact_time", (0,), np.nan)),
        ("-inf in energy_total", _poke("energy_total", (3,), -np.inf)),
        ("NaN in ideal/joint_angle", _poke("ideal/joint_angle", (4, 1), np.nan)),
    ]
    for name in ("scene_name", "integrator", "coordinate_names", "energy_components",
                 "solver_stats", "metadata_text", "metadata_json", "format",
                 "format_version", "scene"):
        yield f"missing attribute {name}", _del_attr(name)
    yield from [
        ("missing digest", _del_attr(integrity.DIGEST_ATTRIBUTE)),
        ("digest not text", _attr(integrity.DIGEST_ATTRIBUTE, 7)),
        ("extra attribute", _attr("extra", 1.5)),
        ("coordinate_names a number", _attr("coordinate_names", 12)),
        ("coordinate_names too few", _attr("coordinate_names", "q2 q3")),
        ("coordinate_names odd bytes", _attr("coordinate_names", np.bytes_(b"\xff\xfe q3"))),
        ("energy_components names a missing one", _attr("energy_components", "total nowhere")),
        ("metadata_text names a missing one", _attr("metadata_text", "scene absent")),
        ("format_version text", _attr("format_version", "3")),
        ("format_version 2.5", _attr("format_version", 2.5)),
        ("format_version 99", _attr("format_version", 99)),
        ("format other", _attr("format", "something-else")),
        ("solver_stats not JSON", _attr("solver_stats", "{")),
        ("solver_stats a list", _attr("solver_stats", "[1, 2]")),
        ("solver_stats nested deep", _attr("solver_stats", _nested(100_000))),
        ("metadata_json null", _attr("metadata_json", "null")),
        ("metadata_json NaN", _attr("metadata_json", "NaN")),
        ("metadata_json run settings odd", _attr(
            "metadata_json", '{"run": {"t_end": "long", "bogus": 1}}')),
        ("integrator array", _attr("integrator", np.arange(3))),
        ("scene_name text array", _attr("scene_name", np.array([b"a", b"b"]))),
        ("ideal coordinate_names missing", _del_attr("coordinate_names", "/ideal")),
    ]


def _edited(base: Path, target: Path, edit: Edit) -> None:
    shutil.copyfile(base, target)
    with h5py.File(target, "r+") as fh:
        edit(fh)


def _forge(edited: Path, target: Path) -> bool:
    """A copy of ``edited`` with its digest written again over the edit; False (and no
    copy) where the edit cannot be loaded to be digested: a link to elsewhere, a huge
    declared size, an odd type."""
    shutil.copyfile(edited, target)
    with h5py.File(target, "r+") as fh:
        try:
            fh.attrs[integrity.DIGEST_ATTRIBUTE] = integrity.digest(integrity.load(fh, target))
        except Exception:
            forged = False
        else:
            forged = True
    if not forged:
        target.unlink()
    return forged


def make_hostile_files(base: Path, folder: Path, *, flips: int = 110, seed: int = 41
                       ) -> list[Hostile]:
    """Write the hostile files made from ``base`` into ``folder``; return them."""
    folder.mkdir(parents=True, exist_ok=True)
    data = base.read_bytes()
    rng = np.random.default_rng(seed)
    made: list[Hostile] = []

    def write(name: str, content: bytes, what: str) -> None:
        path = folder / name
        path.write_bytes(content)
        made.append(Hostile(path, what))

    for k, offset in enumerate(rng.integers(0, len(data), size=flips)):
        bit = int(rng.integers(0, 8))
        flipped = bytearray(data)
        flipped[offset] ^= 1 << bit
        write(f"flip{k:03d}.h5", bytes(flipped), f"bit {bit} of byte {offset} flipped")
    for fraction in (0.0001, 0.001, 0.01, 0.05, 0.1, 0.25, 0.4, 0.5, 0.6, 0.75, 0.9, 0.99):
        size = max(1, int(len(data) * fraction))
        write(f"cut{size}.h5", data[:size], f"cut to {size} of {len(data)} bytes")
    for size in (8, 512, 2048, len(data) - 1):
        write(f"cut{size}.h5", data[:size], f"cut to {size} of {len(data)} bytes")
    write("random.h5", rng.integers(0, 256, 4096, dtype=np.uint8).tobytes(), "random bytes")
    write("text.h5", b"time,q2\n0,1\n", "a CSV file")
    write("png.h5", b"\x89PNG\r\n\x1a\n" + bytes(64), "a PNG header")
    write("signature.h5", data[:8] + bytes(4096), "the HDF5 signature, then zeros")
    write("empty.h5", b"", "an empty file")
    write("doubled.h5", data + data, "the file twice over")

    for k, (what, edit) in enumerate(structural_edits()):
        path = folder / f"edit{k:03d}.h5"
        _edited(base, path, edit)
        made.append(Hostile(path, what))
        if _forge(path, folder / f"forged{k:03d}.h5"):
            made.append(Hostile(folder / f"forged{k:03d}.h5", f"{what} (digest written "
                                "again)", forged=True))

    links = {"link.h5": base, "dangling.h5": folder / "nowhere.h5",
             "loop.h5": folder / "loop.h5", "device.h5": Path("/dev/zero")}
    for name, target in links.items():
        os.symlink(target, folder / name)
        made.append(Hostile(folder / name, f"a symbolic link to {target}"))
    os.mkfifo(folder / "fifo.h5")
    made.append(Hostile(folder / "fifo.h5", "a FIFO"))
    (folder / "folder.h5").mkdir()
    made.append(Hostile(folder / "folder.h5", "a folder"))
    made.append(Hostile(Path("/dev/zero"), "/dev/zero"))
    return made
