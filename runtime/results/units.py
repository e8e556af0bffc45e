"""The ``units`` attribute of a results file's variables, honoured when it is read.

The writer gives every variable the UDUNITS unit of its numbers (SI: ``m``, ``s``,
``m s-1``, ``rad``, ``N m``, ...). A file edited since (by hand or by a tool that rescaled a
variable and said so) may name another unit: where it is one of the same dimension
(``mm``, ``um``, ``ms``, ``deg``, ``kN``, ``mm s-1``), the reader converts the numbers to
the unit the records hold; where it is not (``kg`` where metres belong, a word no parser
knows), the file is refused naming the variable, never read as if nothing had changed.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.results.integrity import LoadedGroup
from jointplay.results.netcdf import _MOTION, IMPACT_COLUMNS, SAMPLE_FIELDS, UDUNITS

# Symbol: (factor to SI, exponents of length L, mass M, time T, angle A).
_SYMBOLS: dict[str, tuple[float, dict[str, int]]] = {
    "m": (1.0, {"L": 1}), "s": (1.0, {"T": 1}), "g": (1e-3, {"M": 1}),
    "rad": (1.0, {"A": 1}), "deg": (math.pi / 180, {"A": 1}),
    "N": (1.0, {"M": 1, "L": 1, "T": -2}), "J": (1.0, {"M": 1, "L": 2, "T": -2}),
    "min": (60.0, {"T": 1}), "h": (3600.0, {"T": 1}), "1": (1.0, {}),
}
_ALIASES = {"metre": "m", "meter": "m", "metres": "m", "meters": "m", "second": "s",
            "seconds": "s", "sec": "s", "radian": "rad", "radians": "rad", "degree": "deg",
            "degrees": "deg", "°": "deg", "newton": "N", "joule": "J", "micron": "um"}
_PREFIXES = {"n": 1e-9, "u": 1e-6, "µ": 1e-6, "μ": 1e-6, "m": 1e-3, "c": 1e-2, "k": 1e3,
             "M": 1e6}
_PREFIXABLE = ("m", "s", "g", "N", "J", "rad")
_TOKEN = re.compile(r"^([^\d\s^-]+)\^?(-?\d+)?$")


def parse(unit: str) -> tuple[float, dict[str, int]] | None:
    """A unit as its factor to SI and its dimension, or None where it cannot be read.
    UDUNITS products (``m s-2``, ``N m``) and ``/`` quotients (``m/s^2``) are understood."""
    text = unit.strip()
    if not text or len(text) > 64:
        return None
    factor, dims = 1.0, {}  # type: float, dict[str, int]
    numerator, *denominators = text.split("/")
    if len(denominators) > 1:
        return None
    for part, sign in ((numerator, 1), *((d, -1) for d in denominators)):
        tokens = part.replace("*", " ").replace(".", " ").split()
        if not tokens:
            return None
        for token in tokens:
            read = _token(token)
            if read is None:
                return None
            scale, exponents, power = read
            factor *= scale ** (sign * power)
            for dim, exponent in exponents.items():
                dims[dim] = dims.get(dim, 0) + sign * power * exponent
    return factor, {d: e for d, e in dims.items() if e}


def _token(token: str) -> tuple[float, dict[str, int], int] | None:
    m = _TOKEN.match(token)
    if token == "1":
        return 1.0, {}, 1
    if m is None:
        return None
    symbol, power = _ALIASES.get(m.group(1), m.group(1)), int(m.group(2) or 1)
    if symbol in _SYMBOLS:
        scale, exponents = _SYMBOLS[symbol]
        return scale, exponents, power
    if len(symbol) > 1 and symbol[0] in _PREFIXES and symbol[1:] in _PREFIXABLE:
        scale, exponents = _SYMBOLS[symbol[1:]]
        return _PREFIXES[symbol[0]] * scale, exponents, power
    return None


def expected_units() -> dict[str, str]:
    """The unit the writer gives each variable of a result group (the ones the reader
    takes numbers from)."""
    units = {"time": "s", "radial_clearance": "m"}
    for _, per, angle_name, offset_name, _, _ in _MOTION:
        units[angle_name] = "rad" + per
        units[offset_name] = "m" + per
    for f in SAMPLE_FIELDS:
        units[f.variable] = f.units
    for name, unit, _ in IMPACT_COLUMNS:
        units[f"impact_{name}"] = UDUNITS[unit]
    return units


def convert_units(group: LoadedGroup, path: str | Path) -> None:
    """Convert in place every float variable of ``group`` whose ``units`` attribute names
    another unit of the same dimension as the writer's; refuse (naming the variable) one of
    another dimension or one that cannot be read. Energies are checked as joules."""
    from jointplay.results.checks import text

    where = group.name.rstrip("/")
    wanted = expected_units()
    wanted.update({name: "J" for name in group.variables if name.startswith("energy_")})
    for name, unit in wanted.items():
        if name not in group.variables:
            continue
        found = text(group.variable_attrs.get(name, {}).get("units"))
        if found is None or found == unit:
            continue  # no attribute (an earlier layout): the writer's unit
        have, want = parse(found), parse(unit)
        values = group.variables[name]
        if have is None or want is None or have[1] != want[1] or values.dtype.kind != "f":
            raise DescriptionError(f"{where}/{name}@units",
                                   f"is {found!r}, which cannot be converted to {unit!r}, the "
                                   "unit of its numbers; give the unit they are in (one of "
                                   f"the same kind as {unit!r}) or write the file again",
                                   str(path))
        scale = have[0] / want[0]
        if scale != 1.0:
            group.variables[name] = np.asarray(values, dtype=np.float64) * scale
        group.variable_attrs[name] = {**group.variable_attrs.get(name, {}), "units": unit}


__all__ = ["convert_units", "expected_units", "parse"]
