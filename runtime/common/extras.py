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
    "control": ("torch", "h5netcdf"),
    "sweep": ("dask", "distributed", "pyarrow", "pandas"),
    "xarray": ("xarray", "pandas", "h5netcdf"),
}
"""Each extra and the modules it installs (the ones the code imports: h5netcdf writes
``control --out``; xarray reads results files through it)."""


class MissingExtra(JointplayError, ImportError):
    """An optional dependency is not installed: ``extra`` names the one to install."""

    def __init__(self, extra: str, what: str, missing: tuple[str, ...]) -> None:
        self.extra = extra
        self.missing = missing
        super().__init__(f"{what} needs {', '.join(missing)}, not installed; install it with "
                         f"pip install 'jointplay[{extra}]'")


def missing_modules(extra: str, modules: tuple[str, ...] | None = None) -> tuple[str, ...]:
    """The modules of ``extra`` (or only ``modules`` of it, where a function needs just those)
    that cannot be imported here (none: they are there)."""
    missing = []
    for module in EXTRAS[extra] if modules is None else modules:
        try:
            found = find_spec(module) is not None
        except (ImportError, ValueError):  # a broken install counts as missing
            found = False
        if not found:
            missing.append(module)
    return tuple(missing)


def require(extra: str, what: str, modules: tuple[str, ...] | None = None) -> None:
    """Raise :class:`MissingExtra` unless every module ``what`` needs is installed: those of
    ``extra``, or only ``modules`` of it (``result.impacts.to_pandas()`` needs pandas, not
    xarray). ``what`` says who needs them (``"jointplay identify"``, ``"to_xarray()"``); the
    message names exactly the modules missing."""
    if modules is not None and not set(modules) <= set(EXTRAS[extra]):
        raise ValueError(f"{modules} are not all modules of the extra {extra!r}")
    missing = missing_modules(extra, modules)
    if missing:
        raise MissingExtra(extra, what, missing)


__all__ = ["EXTRAS", "MissingExtra", "missing_modules", "require"]
