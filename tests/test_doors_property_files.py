"""Property-based: calibrate's measured files and the neural commands' settings files, made
at random and broken at random, through their readers. Each read ends in one of two ways: a
:class:`DescriptionError` (the command's exit 2, one line naming the field), or a read that
is right, checked against the document by an independent parse here; never another error.
Nothing is simulated."""

from __future__ import annotations

import itertools
import math
import tomllib
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from jointplay import DescriptionError
from jointplay.common.limits import MAX_MEASURED

PROPERTY = settings(max_examples=80, deadline=None,
                    suppress_health_check=[HealthCheck.function_scoped_fixture,
                                           HealthCheck.too_slow])


# ---- calibrate's measured file -------------------------------------------------------------------

@pytest.fixture(scope="module")
def model() -> Any:
    from jointplay.scene.definition import default_scene
    from jointplay.sim import load_scene_model

    return load_scene_model(default_scene())


COLUMNS = ["time", "tip_x", "tip_y", "q2", "q3", "tip_z", "Time", "q9", "", "dq2"]
CELLS = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.floats(min_value=-2.0, max_value=2.0).map(repr),
    st.floats(min_value=-2.0, max_value=2.0).map(repr),
    st.sampled_from(["", " ", "nan", "inf", "-inf", "1e200", "1e308", "1e-320", "0x10", "1,5",
                     "abc", "1e6", "-1e6", "1.0000001e6", "  0.5  ", "\"0.1\"", "1_0", "٣"]),
)


@st.composite
def measured_csv(draw: st.DrawFn) -> bytes:
    """A valid table (time and some of tip_x, tip_y, q2, q3), then, half the time, one
    damage: a bad cell, a cell too many or too few, a time out of order, an odd header."""
    columns = draw(st.lists(st.sampled_from(["tip_x", "tip_y", "q2", "q3"]), min_size=1,
                            max_size=4, unique=True))
    header = draw(st.permutations(["time", *columns]))
    n = draw(st.integers(3, 7))
    steps = draw(st.lists(st.floats(1e-4, 0.01), min_size=n, max_size=n))
    times = list(itertools.accumulate(steps, initial=0.0))[:n]
    rows = [[repr(t) if name == "time" else repr(draw(st.floats(-2.0, 2.0)))
             for name in header] for t in times]
    damage = draw(st.sampled_from(["none"] * 6 + ["cell", "width", "order", "header",
                                                  "short", "bytes", "blank"]))
    if damage == "cell":
        i, k = draw(st.integers(0, n - 1)), draw(st.integers(0, len(header) - 1))
        rows[i][k] = draw(CELLS)
    elif damage == "width":
        i = draw(st.integers(0, n - 1))
        rows[i] = rows[i][:-1] if draw(st.booleans()) else [*rows[i], "0.1"]
    elif damage == "order":
        i, k = draw(st.integers(1, n - 1)), header.index("time")
        rows[i][k] = draw(st.sampled_from([rows[i - 1][k], "-0.001", "10.0"]))
    elif damage == "header":
        header[draw(st.integers(0, len(header) - 1))] = draw(st.sampled_from(COLUMNS))
    elif damage == "short":
        rows = rows[:draw(st.integers(0, 2))]
    text = "\n".join([",".join(header), *(",".join(r) for r in rows)])
    if damage == "blank":
        text = draw(st.sampled_from(["", "\n\n", ",,,\n", " \n time \n"]))
    data = (text + draw(st.sampled_from(["\n", "", "\n\n", "\r\n"]))).encode("utf-8")
    if draw(st.booleans()):
        data = b"\xef\xbb\xbf" + data  # a spreadsheet's byte-order mark
    if damage == "bytes":
        data = data.replace(b",", b"\xff", 1)  # not UTF-8
    return data


def _expected(data: bytes, columns: set[str]) -> tuple[list[str], list[list[float]]] | None:
    """An independent reading: the header and the numbers, or None where the file is not a
    valid measurement (the reader must refuse it)."""
    try:
        text = data.decode("utf-8").removeprefix("\ufeff")
    except UnicodeDecodeError:
        return None
    lines = [line for line in text.splitlines() if line.strip(" ,")]
    if not lines:
        return None
    header = [c.strip() for c in lines[0].split(",")]
    if "time" not in header or len(set(header)) != len(header) or len(header) < 2 \
            or any(c != "time" and c not in columns for c in header):
        return None
    rows = []
    for line in lines[1:]:
        cells = line.split(",")
        if len(cells) != len(header) or any('"' in c for c in cells):
            return None
        try:
            row = [float(c) for c in cells]
        except ValueError:
            return None
        if not all(math.isfinite(v) for v in row) or any(
                abs(v) > MAX_MEASURED for name, v in zip(header, row, strict=True)
                if name != "time"):
            return None
        rows.append(row)
    times = [row[header.index("time")] for row in rows]
    if len(rows) < 3 or any(b <= a for a, b in itertools.pairwise(times)):
        return None
    return header, rows


@PROPERTY
@given(data=measured_csv())
def test_a_measured_file_is_refused_or_read_right(data: bytes, model: Any,
                                                   tmp_path: Path) -> None:
    import numpy as np

    from jointplay.calibration.measured import TIP_COLUMNS, angle_columns, read_measured

    path = tmp_path / "m.csv"
    path.write_bytes(data)
    expected = _expected(data, {*TIP_COLUMNS, *angle_columns(model)})
    try:
        measured = read_measured(path, model)
    except DescriptionError as err:
        event("refused")
        assert str(path) in str(err) and "\n" not in err.message, str(err)
        # a quoted cell is CSV for the number inside: the reader may take it
        assert expected is None or b'"' in data, (data, str(err))
        return
    event("read")
    assert expected is not None or b'"' in data, data
    if expected is None:
        return
    header, rows = expected
    columns = [c for c in header if c != "time"]
    assert list(measured.columns) == columns
    table = np.asarray(rows)
    assert np.array_equal(measured.t, table[:, header.index("time")])
    assert np.array_equal(measured.values, table[:, [header.index(c) for c in columns]])


# ---- the settings file ---------------------------------------------------------------------------

def _schema() -> dict[str, dict[str, Any]]:
    from jointplay.neural.study.settings_schema import SCHEMA

    return SCHEMA


def _value_for(key: Any) -> st.SearchStrategy[Any]:
    """Values of the key's kind, in its range and beyond it, and of other kinds."""
    low = -5.0 if key.low is None else key.low
    high = low + 10.0 if key.high is None else key.high
    numbers = st.one_of(st.floats(min_value=low - 1, max_value=high + 1),
                        st.sampled_from([low, high, 0.0, -1.0, 1e300]))
    if key.kind == "int":
        scalar: st.SearchStrategy[Any] = st.integers(int(low) - 2, int(min(high, 10**6)) + 2)
    elif key.kind in ("float", "optional-float"):
        scalar = numbers
    elif key.kind == "bool":
        scalar = st.booleans()
    elif key.kind == "str":
        scalar = st.sampled_from([*key.choices, "x", ""])
    elif key.kind == "noise":
        scalar = st.dictionaries(st.sampled_from(["q2", "dq2", "tip_x"]),
                                 st.floats(-1.0, 1.0), max_size=2)
    else:
        item = {"ints": st.integers(int(low) - 1, int(min(high, 64)) + 1), "floats": numbers,
                "strs": st.sampled_from([*(key.choices or ("q2", "tip_x")), "zz"])}[key.kind]
        scalar = st.lists(item, max_size=3)
    return st.one_of(scalar, scalar, st.sampled_from(["text", True, [1, "a"], {"a": 1}]))


@st.composite
def settings_document(draw: st.DrawFn) -> dict[str, Any]:
    schema = _schema()
    doc: dict[str, Any] = {}
    if draw(st.booleans()):
        doc["preset"] = draw(st.sampled_from(["best", "paper", "bset", 3]))
    for section in draw(st.lists(st.sampled_from([*schema, "identfy", "studdy"]), max_size=3,
                                 unique=True)):
        keys = list(schema.get(section, schema["identify"]))
        names = draw(st.lists(st.sampled_from([*keys, "seeed", "hiden"]), max_size=3,
                              unique=True))
        table = {}
        for name in names:
            key = schema.get(section, {}).get(name) or schema["identify"]["seed"]
            table[name] = draw(_value_for(key))
        doc[section] = table
    return doc


def _toml(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        if isinstance(value, float) and not math.isfinite(value):
            return {"inf": "inf", "-inf": "-inf"}.get(repr(value), "nan")
        return repr(value)
    if isinstance(value, str):
        return '"' + value.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(value, list):
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    return "{ " + ", ".join(f'"{k}" = {_toml(v)}' for k, v in value.items()) + " }"


def _document_text(doc: dict[str, Any]) -> str:
    lines = [f"preset = {_toml(doc['preset'])}"] if "preset" in doc else []
    for section, table in doc.items():
        if section == "preset":
            continue
        lines.append(f"[{section}]")
        lines += [f"{name} = {_toml(value)}" for name, value in table.items()]
    return "\n".join(lines) + "\n"


def _within(key: Any, value: Any) -> bool:
    """The documented range of ``key`` (docs/how-to/settings-file.md), checked here anew."""
    if isinstance(value, tuple) and key.kind != "noise":
        return all(_within(type(key)(key.kind[:-1], key.low, key.high, key.low_open,
                                     key.high_open, key.choices), v) for v in value) \
            and key.least <= len(value) <= (key.most or len(value))
    if key.kind == "str":
        return not key.choices or value in key.choices
    if key.kind in ("bool", "noise") or value is None:
        return True
    above = key.low is None or value > key.low or (value == key.low and not key.low_open)
    below = key.high is None or value < key.high or (value == key.high and not key.high_open)
    return bool(math.isfinite(value) and above and below)


@PROPERTY
@given(doc=settings_document(), bom=st.booleans())
def test_a_settings_file_is_refused_or_read_right(doc: dict[str, Any], bom: bool,
                                                   tmp_path: Path) -> None:
    from jointplay.neural.study.settings import read_settings_file

    text = _document_text(doc)
    path = tmp_path / "settings.toml"
    path.write_bytes((b"\xef\xbb\xbf" if bom else b"") + text.encode("utf-8"))
    assert tomllib.loads(text) is not None  # the document itself is TOML
    try:
        read, scene = read_settings_file(path)
    except DescriptionError as err:
        event("refused")
        assert str(path) in str(err), str(err)
        return
    event("read")
    schema = _schema()
    assert scene is None
    assert read.preset == doc.get("preset", "best")
    for section, table in doc.items():
        if section == "preset":
            continue
        assert section in schema, section  # a misspelt table is never read
        for name, value in table.items():
            assert name in schema[section], name
            got = getattr(getattr(read, section), name)
            key = schema[section][name]
            if key.kind == "noise":
                assert dict(got) == value
                continue
            want = tuple(value) if isinstance(value, list) else value
            assert got == want, (section, name, got, value)
            if not isinstance(got, tuple):  # a number is never taken for a flag, or back
                assert isinstance(got, bool) == (key.kind == "bool"), (section, name, got)
            assert _within(key, got), (section, name, got)
