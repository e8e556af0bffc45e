"""The keys of a settings file's ``[identify]``, ``[control]`` and ``[study]`` tables: the type
and range of each, checked the same way whether the value comes from a file, from
``--set SECTION.KEY=VALUE`` or from Python; and the named presets.

The keys are the fields of :class:`jointplay.neural.identify.config.IdentifyConfig`,
:class:`jointplay.neural.control.imc_settings.ControllerSettings` and
:class:`jointplay.neural.study.settings.StudySettings` (tests/test_settings.py checks that
they agree); docs/how-to/settings-file.md says what each means.
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass
from typing import Any

from jointplay.common import limits as size_limits
from jointplay.common.errors import DescriptionError
from jointplay.neural.identify.config import (
    BASE_MOTIONS,
    MAX_SCENE_MOTIONS,
    MAX_SEED,
    RESIDUAL_CRITERIA,
)
from jointplay.neural.study.cases import CASES

SECTIONS = ("identify", "control", "study")

# The named presets, each what it changes from the dataclasses' defaults (which are the paper's
# NARX 13/14 as the commands set it up without flags). "best" is the best setting measured
# (docs/control.md, "What the network earns"); a new measurement changes one line here.
PRESETS: dict[str, dict[str, dict[str, Any]]] = {
    "paper": {},
    "best": {"identify": {
        "scheduling": True, "lpv_base": True, "residual_by": "closed-loop-scene",
        "hidden": (24, 24), "linear_input_gain": True, "base_motions": "scene-family",
        "n_train": 24, "n_validation": 2, "n_test": 2, "duration": 2.0,
        # 40,20 measured best; 20,5 brings the default identification toward 3 minutes on 2
        # cores (docs/results/control-defaults.md): the LPV-ARX base the network falls back
        # to does not depend on them, and the network is kept only where it beats that base.
        "one_step_iterations": 20, "multi_step_iterations": 5}},
}
DEFAULT_PRESET = "best"


@dataclass(frozen=True)
class Key:
    """One key's type and range.

    ``kind``: int, float, bool, str, optional-float (absent: decided at run time), ints,
    floats, strs (TOML arrays; empty: the default the field documents) or noise (a table
    of output name = standard deviation)."""

    kind: str
    low: float | None = None
    high: float | None = None
    low_open: bool = False  # the low bound itself is refused
    high_open: bool = False
    choices: tuple[str, ...] = ()
    least: int = 0  # entries a list needs at least
    most: int | None = None  # and at most


def _int(low: int, high: int) -> Key:
    return Key("int", low, high)


_POS = Key("float", 0.0, low_open=True)
_NONNEG = Key("float", 0.0)
_FRACTION = Key("float", 0.0, 1.0, low_open=True)
_UNIT_OPEN = Key("float", 0.0, 1.0, high_open=True)
_COUNT = _int(1, size_limits.MAX_TRAJECTORIES)
_BOOL = Key("bool")

SCHEMA: dict[str, dict[str, Key]] = {
    "identify": {
        "duration": Key("float", 0.0, size_limits.MAX_T_END, low_open=True),
        "n_train": _COUNT, "n_validation": _COUNT, "n_test": _COUNT,
        "output_lags": _int(1, size_limits.MAX_LAGS),
        "input_lags": _int(1, size_limits.MAX_LAGS),
        "hidden": Key("ints", 1, size_limits.MAX_HIDDEN_WIDTH, least=1,
                      most=size_limits.MAX_HIDDEN_LAYERS),
        "seed": _int(0, MAX_SEED),
        "kp": Key("floats", 0.0, low_open=True), "kd": Key("floats", 0.0),
        "torque_limit": Key("floats", 0.0, low_open=True),
        "base_fraction": _FRACTION,
        "base_motions": Key("str", choices=BASE_MOTIONS),
        "input_fraction": _FRACTION,
        "transient": _NONNEG,
        "linear_path": _BOOL, "scheduling": _BOOL, "lpv_base": _BOOL,
        "contact_outputs": _BOOL, "linear_input_gain": _BOOL,
        "clearances": Key("floats", 0.0, low_open=True), "payloads": Key("floats", 0.0),
        "residual_by": Key("str", choices=RESIDUAL_CRITERIA),
        "scene_motions": _int(1, MAX_SCENE_MOTIONS),
        "one_step_iterations": _int(0, size_limits.MAX_ITERATIONS),
        "multi_step_iterations": _int(0, size_limits.MAX_ITERATIONS),
        "window": _int(size_limits.MIN_WINDOW, size_limits.MAX_WINDOW),
        "patience": _int(1, size_limits.MAX_ITERATIONS),
        "workers": _int(0, size_limits.MAX_WORKERS),
    },
    "control": {
        "horizon": _int(1, 500),
        "regularisation": _NONNEG,
        "setpoint_filter": _UNIT_OPEN, "mismatch_filter": _UNIT_OPEN,
        "tracked": Key("strs"),
        "scales": Key("floats", 0.0, low_open=True),
        "torque_limit": Key("floats", 0.0, low_open=True),
        "rate_limit": Key("floats", 0.0, low_open=True),
        "iterations": _int(1, 20),
        "guard": _BOOL,
        "trust_input": _POS, "trust_range": _NONNEG, "trust_mismatch": _POS,
        "fallback_hold": _int(1, 10**9),
        "engage": Key("optional-float", 0.0),
        "measurement_noise": Key("noise", 0.0),
        "noise_budget": _POS,
    },
    "study": {
        "seeds": _int(1, size_limits.MAX_TRAJECTORIES),
        "first_seed": _int(0, MAX_SEED),
        "cases": Key("strs", choices=CASES, least=1),
        "clearances": Key("floats", 0.0, low_open=True),
        "clearance_seeds": _int(1, size_limits.MAX_TRAJECTORIES),
        "workers": _int(1, size_limits.MAX_WORKERS),
        "undeclared_noise": _BOOL, "verify": _BOOL,
    },
}


def checked(where: str, key: Key, value: Any) -> Any:
    """``value`` (as TOML or Python gives it) checked against ``key``: the field's Python
    value (lists as tuples, the noise table as (name, std) pairs); a one-line
    :class:`DescriptionError` naming ``where`` otherwise."""
    if key.kind in ("ints", "floats", "strs"):
        if not isinstance(value, (list, tuple)):
            raise DescriptionError(where, f"must be an array, got {value!r}")
        if len(value) < key.least or (key.most is not None and len(value) > key.most):
            most = f" and at most {key.most}" if key.most is not None else ""
            raise DescriptionError(where, f"needs at least {key.least}{most} entries, got "
                                   f"{len(value)}")
        item = Key(key.kind[:-1], key.low, key.high, key.low_open, key.high_open, key.choices)
        values = tuple(checked(f"{where}[{i}]", item, v) for i, v in enumerate(value))
        if key.kind == "strs":  # names (cases, tracked outputs): one would run or count twice
            twice = [v for i, v in enumerate(values) if v in values[:i]]
            if twice:
                raise DescriptionError(where, f"names {twice[0]!r} twice; name each once")
        return values
    if key.kind == "noise":
        if not isinstance(value, dict):
            raise DescriptionError(where, "must be a table of output name = standard "
                                   f"deviation, e.g. {{ q2 = 3e-6 }}, got {value!r}")
        return tuple((str(name), _noise_std(f"{where}.{name}", std))
                     for name, std in value.items())
    if key.kind == "bool":
        if not isinstance(value, bool):
            raise DescriptionError(where, f"must be true or false, got {value!r}")
        return value
    if key.kind == "str":
        if not isinstance(value, str):
            raise DescriptionError(where, f"must be a string, got {value!r}")
        if key.choices and value not in key.choices:
            raise DescriptionError(where, f"must be one of {', '.join(key.choices)}, got "
                                   f"{value!r}")
        return value
    number = _number(where, key, value)
    _in_range(where, key, number)
    return number


def _noise_std(where: str, value: Any) -> float:
    try:
        std: float = checked(where, Key("float", 0.0), value)
    except DescriptionError as err:
        raise DescriptionError(where, f"{err.message}: give NAME=STD pairs, STD >= 0 in the "
                               "output's unit") from None
    return std


def _number(where: str, key: Key, value: Any) -> float | int:
    if key.kind == "int":
        if isinstance(value, bool) or not isinstance(value, int):
            raise DescriptionError(where, f"must be a whole number, got {value!r}")
        return value
    if isinstance(value, bool) or not isinstance(value, (int, float)) \
            or not math.isfinite(value):
        raise DescriptionError(where, f"must be a finite number, got {value!r}")
    return float(value)


def _in_range(where: str, key: Key, value: float) -> None:
    low_ok = key.low is None or value > key.low or (value == key.low and not key.low_open)
    high_ok = key.high is None or value < key.high or (value == key.high and not key.high_open)
    if not (low_ok and high_ok) and key.kind == "int" and None not in (key.low, key.high):
        raise DescriptionError(where, f"must be a whole number from {int(key.low or 0)} to "
                               f"{int(key.high or 0)}, got {value!r}")
    if not (low_ok and high_ok):
        low = "" if key.low is None else f"{'above' if key.low_open else 'at least'} {key.low:g}"
        high = "" if key.high is None else (f"{'below' if key.high_open else 'at most'} "
                                             f"{key.high:g}")
        raise DescriptionError(where, f"must be {' and '.join(b for b in (low, high) if b)}, "
                               f"got {value!r}")


def parse_text(where: str, key: Key, text: str) -> Any:
    """A value written on the command line (``--set identify.hidden=24,24``): TOML where it
    reads as TOML (``24``, ``true``, ``[24, 24]``, ``"x"``), else a comma-separated list or
    bare text; then checked as a file's value."""
    try:
        value: Any = tomllib.loads(f"v = {text}")["v"]
    except tomllib.TOMLDecodeError:
        value = text
    if key.kind == "noise" and isinstance(value, str):
        value = _noise_pairs(where, value)
    elif key.kind in ("ints", "floats", "strs") and not isinstance(value, list):
        value = [_scalar(v.strip()) for v in str(value).split(",") if v.strip()] \
            if isinstance(value, str) else [value]
    return checked(where, key, value)


def _scalar(text: str) -> Any:
    try:
        return tomllib.loads(f"v = {text}")["v"]
    except tomllib.TOMLDecodeError:
        return text


def _noise_pairs(where: str, text: str) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for item in (i.strip() for i in text.split(",") if i.strip()):
        name, sep, value = item.partition("=")
        if not sep or not name.strip():
            raise DescriptionError(where, f"{item!r}: give NAME=STD pairs, e.g. "
                                   "q2=3e-6,dq2=4e-3 (STD >= 0, in the output's unit)")
        if name.strip() in out:
            raise DescriptionError(where, f"gives {name.strip()} twice; give each output once")
        out[name.strip()] = _scalar(value.strip())
    return out


def toml_value(key: Key, value: Any) -> str:
    """A field's value as TOML (what settings.toml records; read back, it is the same)."""
    if key.kind == "noise":
        pairs = ", ".join(f"{_toml_key(n)} = {float(s)!r}" for n, s in value)
        return "{ " + pairs + " }" if pairs else "{}"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(toml_value(Key(key.kind[:-1]), v) for v in value) + "]"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return _toml_string(value)
    if key.kind in ("float", "floats", "optional-float"):
        return repr(float(value))
    return str(int(value))


def _toml_string(text: str) -> str:
    import json

    return json.dumps(text, ensure_ascii=False)  # a JSON string is a TOML basic string


def _toml_key(name: str) -> str:
    bare = name.replace("_", "").replace("-", "").isalnum() and name.isascii()
    return name if bare else _toml_string(name)


__all__ = ["DEFAULT_PRESET", "PRESETS", "SCHEMA", "SECTIONS", "Key", "checked", "parse_text",
           "toml_value"]
