"""Optional dependencies: the core simulates, inspects, builds and plots; each extra adds what
one group of commands needs (pyproject.toml, ``[project.optional-dependencies]``).

A command or function that needs an extra checks for it before any work, without importing
it (:func:`importlib.util.find_spec`), and stops with one line naming the ``pip install`` that
adds it.
"""

from __future__ import annotations

from importlib.util import find_spec

from jointplay.common.errors import JointplayError

EXTRAS: dict[str, tuple[str, ...]] = {
    "control": ("torch",),
    "sweep": ("dask", "distributed", "pyarrow", "pandas"),
    "xarray": ("xarray", "pandas"),
}
"""Each extra and the modules it installs (the ones the code imports)."""


class MissingExtra(JointplayError, ImportError):
    """An optional dependency is not installed: ``extra`` names the one to install."""

    def __init__(self, extra: str, what: str, missing: tuple[str, ...]) -> None:
        self.extra = extra
        self.missing = missing
        super().__init__(f"{what} needs {', '.join(missing)}, not installed; install it with "
                         f"pip install 'jointplay[{extra}]'")


def missing_modules(extra: str) -> tuple[str, ...]:
    """The modules of ``extra`` that cannot be imported here (none: the extra is there)."""
    missing = []
    for module in EXTRAS[extra]:
        try:
            found = find_spec(module) is not None
        except (ImportError, ValueError):  # a broken install counts as missing
            found = False
        if not found:
            missing.append(module)
    return tuple(missing)


def require(extra: str, what: str) -> None:
    """Raise :class:`MissingExtra` unless every module of ``extra`` is installed; ``what``
    says who needs it (``"jointplay identify"``, ``"result.to_xarray()"``)."""
    missing = missing_modules(extra)
    if missing:
        raise MissingExtra(extra, what, missing)


__all__ = ["EXTRAS", "MissingExtra", "missing_modules", "require"]
