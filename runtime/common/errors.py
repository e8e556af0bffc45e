"""Errors jointplay raises for bad input, each naming the field at fault and what is allowed."""

from __future__ import annotations


class JointplayError(Exception):
    """Base class of every error jointplay raises on purpose."""


class DescriptionError(JointplayError, ValueError):
    """A robot description (file, table or flags) is invalid.

    ``source`` is the file (or ``"flags"``), ``field`` the dotted path of the offending field
    (for example ``joints[2].journal_radius``) and ``message`` says what is allowed.
    """

    def __init__(self, field: str, message: str, source: str | None = None) -> None:
        self.field = field
        self.message = message
        self.source = source
        where = f"{source}: " if source else ""
        super().__init__(f"{where}{field}: {message}")


class BuildError(JointplayError, RuntimeError):
    """Compiling or loading a generated model failed."""


class GeneratedCodeError(JointplayError, RuntimeError):
    """Generated files are missing, edited by hand, or stamped by other tool versions."""


class SimulationError(JointplayError, RuntimeError):
    """A simulation could not continue: the integrator failed or the state stopped being finite.

    ``time`` is where it stopped (s), ``joint`` the clearance joint involved when one is
    (1-based, else None), and ``cause`` what happened and what to try.
    """

    def __init__(self, time: float, cause: str, joint: int | None = None) -> None:
        self.time = time
        self.joint = joint
        self.cause = cause
        where = f" at joint {joint}" if joint is not None else ""
        super().__init__(f"simulation stopped at t = {time:.9g} s{where}: {cause}")


class FileError(JointplayError):
    """Reading or writing a file failed: ``path`` and ``cause`` in one line."""

    def __init__(self, path: str, cause: str) -> None:
        self.path = path
        self.cause = cause
        super().__init__(f"{path}: {cause}")
