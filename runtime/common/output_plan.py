"""A command's output plan: every file it will write and every file it reads, known before
any work, and the clashes between them refused (:class:`OutputPlan`). The plan's outputs are
written together by :func:`jointplay.common.files.all_or_nothing`."""

from __future__ import annotations

import fnmatch
import os
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from jointplay.common.names import check_output_name, file_above


@dataclass(frozen=True)
class PlannedOutput:
    """One output of a command: a file, or a folder the command writes files into."""

    flag: str  # the option it comes from, e.g. "--csv"
    path: Path
    kind: str  # "file" or "folder"
    derived: str = ""  # how it follows from the flag's value, e.g. "the impacts table"
    pattern: str = "*"  # a folder: the names of the files written into it (fnmatch, "|": or)

    def describe(self) -> str:
        what = f" ({self.derived})" if self.derived else ""
        return f"{self.flag} {self.path}{what}"


@dataclass(frozen=True)
class PlannedInput:
    flag: str
    path: Path


def matches_pattern(name: str, pattern: str) -> bool:
    """``name`` matches one of the ``|``-separated fnmatch patterns."""
    return any(fnmatch.fnmatch(name, p) for p in pattern.split("|"))


def _real(path: Path) -> Path:
    return Path(os.path.realpath(path))


def _same(a: Path, b: Path) -> bool:
    if _real(a) == _real(b):
        return True
    try:
        return a.exists() and b.exists() and os.path.samefile(a, b)  # hard links
    except OSError:
        return False


def _inside(path: Path, folder: Path) -> bool:
    return _real(folder) in _real(path).parents


@dataclass
class OutputPlan:
    """Every file a command will write, and every file it reads, known before any work.

    :meth:`check` refuses (a :class:`~jointplay.common.errors.DescriptionError`, exit 2) two
    outputs that are one file, an output that is one of the inputs, and an output that would
    land in a folder another output fills or that holds an input folder's files, comparing
    resolved real paths (links, ``..`` and hard links included).
    """

    outputs: list[PlannedOutput] = field(default_factory=list)
    inputs: list[PlannedInput] = field(default_factory=list)

    def file(self, flag: str, path: str | Path, derived: str = "") -> Path:
        """A file the command writes. Refused at once (exit 2): an empty name, ``-``
        (standard output: the outputs are binary or several files), a name ending in ``/``
        (a folder, as Unix tools read it, where a file is written) and a name that is not
        UTF-8 (it could not be reported or kept in the results)."""
        check_output_name(flag, path, "file")
        self.outputs.append(PlannedOutput(flag, Path(path), "file", derived))
        return Path(path)

    def folder(self, flag: str, path: str | Path, derived: str = "", pattern: str = "*"
               ) -> Path:
        """A folder the command fills with files named like ``pattern`` (at any depth)."""
        check_output_name(flag, path, "folder")
        self.outputs.append(PlannedOutput(flag, Path(path), "folder", derived, pattern))
        return Path(path)

    def input(self, flag: str, path: str | Path | None) -> None:
        if path is not None and str(path):
            self.inputs.append(PlannedInput(flag, Path(path)))

    def add_inputs(self, flag: str, paths: Iterable[str | Path | None]) -> None:
        for path in paths:
            self.input(flag, path)

    def check(self) -> None:
        from jointplay.common.errors import DescriptionError

        for output in self.outputs:  # under a file, nothing can be made: found now
            blocker = file_above(output.path)
            if blocker is not None:
                raise DescriptionError(output.flag, f"{output.path} lies under {blocker}, "
                                       "which is a file, not a folder; write elsewhere")
        files = [o for o in self.outputs if o.kind == "file"]
        folders = [o for o in self.outputs if o.kind == "folder"]
        for i, a in enumerate(files):
            for b in files[i + 1:]:
                if _same(a.path, b.path):
                    raise DescriptionError(b.flag, f"{b.describe()} is the same file as "
                                           f"{a.describe()}; give each output its own name")
            for inp in self.inputs:
                if _same(a.path, inp.path):
                    raise DescriptionError(a.flag, f"{a.describe()} is the input {inp.flag} "
                                           f"{inp.path}; writing it would overwrite the input: "
                                           "give another name")
                if inp.path.is_dir() and _inside(a.path, inp.path):
                    raise DescriptionError(a.flag, f"{a.describe()} lies inside the input "
                                           f"{inp.flag} {inp.path}; write elsewhere")
            for f in folders:
                if _same(a.path, f.path):
                    # The folder flag was given a file's name: that flag is the mistake.
                    raise DescriptionError(f.flag, f"names the same path as {a.flag} "
                                           f"({a.path}); {f.flag} takes a folder for "
                                           f"{f.derived or 'its files'}")
                if _inside(a.path, f.path) and matches_pattern(a.path.name, f.pattern):
                    raise DescriptionError(a.flag, f"{a.describe()} lies in {f.describe()}, "
                                           "which that output fills; write elsewhere")
        for i, f in enumerate(folders):
            for g in folders[i + 1:]:
                if _same(f.path, g.path):
                    raise DescriptionError(g.flag, f"{g.describe()} is the same folder as "
                                           f"{f.describe()}; give each its own folder")
            for inp in self.inputs:
                if _same(f.path, inp.path) or (inp.path.is_dir() and _inside(f.path, inp.path)):
                    raise DescriptionError(f.flag, f"{f.describe()} is or lies in the input "
                                           f"{inp.flag} {inp.path}; write elsewhere")
                if _inside(inp.path, f.path) and matches_pattern(inp.path.name, f.pattern):
                    raise DescriptionError(f.flag, f"{f.describe()} would hold the input "
                                           f"{inp.flag} {inp.path} among its files; write "
                                           "elsewhere")
