"""Errors jointplay raises for bad input, each naming the field at fault and what is allowed."""

from __future__ import annotations

from collections.abc import Callable, Sequence


class JointplayError(Exception):
    """Base class of every error jointplay raises on purpose.

    Catch it to handle any of them; the command line turns each into one line on stderr and
    an exit status.

    Attributes
    ----------
    args : tuple
        The message, as for any exception.
    """


class DescriptionError(JointplayError, ValueError):
    """An input is invalid: a robot or scene description (file, table or flags), an option or a
    file given to read.

    Parameters
    ----------
    field : str
        The dotted path of the offending field (for example ``joints[2].journal_radius``).
    message : str
        What is wrong and what is allowed.
    source : str, optional
        The file (or ``"flags"``).

    Attributes
    ----------
    field : str
        As given.
    message : str
        As given.
    source : str or None
        As given.
    problems : list of DescriptionError
        Every invalid field the error reports (this one here).
    """

    def __init__(self, field: str, message: str, source: str | None = None) -> None:
        self.field = field
        self.message = message
        self.source = source
        where = f"{source}: " if source else ""
        super().__init__(f"{where}{field}: {message}")

    @property
    def problems(self) -> list[DescriptionError]:
        """Every invalid field this error reports (one here; several in a
        :class:`DescriptionErrors`)."""
        return [self]

    def with_source(self, source: str | None) -> DescriptionError:
        """The same error(s) attributed to ``source`` (a file, or ``"flags"``)."""
        return DescriptionError(self.field, self.message, source)

    def renamed(self, rename: Callable[[str], str]) -> DescriptionError:
        """The same error(s) with each field renamed (an API name for a file's, say)."""
        return DescriptionError(rename(self.field), self.message, self.source)


class DescriptionErrors(DescriptionError):
    """Several invalid fields, reported together so that one round of corrections fixes them all.

    Parameters
    ----------
    problems : sequence of DescriptionError
        The problems (at least one); each one's own problems are taken in.

    Attributes
    ----------
    field : str
        The first problem's (code that handles one error keeps working).
    message : str
        The first problem's.
    source : str or None
        The first problem's.
    problems : list of DescriptionError
        Every one; the text has one line per problem.
    """

    def __init__(self, problems: Sequence[DescriptionError]) -> None:
        flat = [p for problem in problems for p in problem.problems]
        if not flat:
            raise ValueError("DescriptionErrors needs at least one problem")
        self._problems = flat
        first = flat[0]
        self.field = first.field
        self.message = first.message
        self.source = first.source
        lines = [str(p) for p in flat]
        Exception.__init__(self, f"{len(flat)} problems:\n  " + "\n  ".join(lines)
                           if len(flat) > 1 else lines[0])

    @property
    def problems(self) -> list[DescriptionError]:
        return list(self._problems)

    def with_source(self, source: str | None) -> DescriptionError:
        return DescriptionErrors([p.with_source(source) for p in self._problems])

    def renamed(self, rename: Callable[[str], str]) -> DescriptionError:
        return DescriptionErrors([p.renamed(rename) for p in self._problems])


def combined(problems: Sequence[DescriptionError]) -> DescriptionError:
    """One error for several problems (the problem itself when there is one); a field is
    named once, by its first problem (a value that is not a number, say, not again as NaN)."""
    flat: list[DescriptionError] = []
    seen: set[tuple[str | None, str]] = set()
    for one in (p for problem in problems for p in problem.problems):
        if (one.source, one.field) not in seen:
            seen.add((one.source, one.field))
            flat.append(one)
    return flat[0] if len(flat) == 1 else DescriptionErrors(flat)


class BuildError(JointplayError, RuntimeError):
    """Compiling or loading a generated model failed.

    Attributes
    ----------
    args : tuple
        The message: what failed, and the compiler's own words where it ran.
    """


class GeneratedCodeError(JointplayError, RuntimeError):
    """Generated files are missing, edited by hand, or stamped by other tool versions.

    Attributes
    ----------
    args : tuple
        The message: which file, and how to regenerate it.
    """


class SimulationError(JointplayError, RuntimeError):
    """A simulation could not continue: the integrator failed or the state stopped being finite.

    Parameters
    ----------
    time : float
        Where it stopped, s.
    cause : str
        What happened and what to try.
    joint : int, optional
        The clearance joint involved when one is (1-based).

    Attributes
    ----------
    time : float
        As given.
    cause : str
        As given.
    joint : int or None
        As given.
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
