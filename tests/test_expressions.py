"""Torque expressions and tables: numpy and CasADi agree, and nothing but the whitelist parses."""

from __future__ import annotations

import ast
import builtins
import re
from collections.abc import Callable
from pathlib import Path
from typing import Any

import casadi as ca
import numpy as np
import pytest

import jointplay.scene.expressions as expressions
import jointplay.scene.tables as tables
import jointplay.sim.postfix as postfix
from jointplay.common.errors import DescriptionError
from jointplay.scene.expressions import Expression, TimeFunction, parse_expression
from jointplay.scene.tables import TableColumn, load_torque_table

FIELD = "torques.joint2"
RTOL = 1e-14
T = np.concatenate([np.linspace(-2.0, 3.0, 1001), [0.0, 0.25, 0.5, 1.0, -0.0]])
CONSTANTS = {"A": 2.5, "T": 0.4, "w": 7.0}

# (text, hand-written numpy formula)
CASES: list[tuple[str, Callable[[np.ndarray], np.ndarray]]] = [
    ("4*sin(2*pi*t)", lambda t: 4 * np.sin(2 * np.pi * t)),
    ("A*exp(-t/T)*cos(w*t) + 0.5", lambda t: 2.5 * np.exp(-t / 0.4) * np.cos(7.0 * t) + 0.5),
    ("2 * t**2 - 1e-3", lambda t: 2 * t**2 - 1e-3),
    ("-t**2 + +t", lambda t: -(t**2) + t),
    ("sqrt(abs(t)) + log(1 + t*t) - tan(t/3)",
     lambda t: np.sqrt(np.abs(t)) + np.log(1 + t * t) - np.tan(t / 3)),
    ("tanh(t) * sinh(t/2) / cosh(t)", lambda t: np.tanh(t) * np.sinh(t / 2) / np.cosh(t)),
    ("atan(t) + e**(-t)", lambda t: np.arctan(t) + np.e ** (-t)),
    ("min(t, 0.5) + max(sin(t), cos(t))",
     lambda t: np.minimum(t, 0.5) + np.maximum(np.sin(t), np.cos(t))),
    ("step(t - 0.25) * 3 + step(-t)", lambda t: (t - 0.25 >= 0) * 3.0 + (-t >= 0) * 1.0),
    ("(1 + t)**-1.5", lambda t: (1 + t) ** -1.5),
    ("t / 7 - 3 * (t - 1) ** 3", lambda t: t / 7 - 3 * (t - 1) ** 3),
    ("(\n t + 1\n) * 2", lambda t: (t + 1) * 2),
]


def casadi_values(function: TimeFunction, t: np.ndarray, kind: Any = ca.SX) -> np.ndarray:
    """Evaluate ``function.casadi`` numerically through a CasADi Function over all of ``t``."""
    symbol = kind.sym("t")
    f = ca.Function("f", [symbol], [function.casadi(symbol)])
    return np.asarray(f.map(t.size)(t.reshape(1, -1))).reshape(t.shape)


def assert_agree(actual: float | np.ndarray, expected: float | np.ndarray) -> None:
    with np.errstate(invalid="ignore"):
        np.testing.assert_allclose(np.asarray(actual, dtype=np.float64),
                                   np.asarray(expected, dtype=np.float64),
                                   rtol=RTOL, atol=0.0, equal_nan=True)


# --- Evaluation --------------------------------------------------------------------------------


@pytest.mark.parametrize(("text", "formula"), CASES, ids=[c[0] for c in CASES])
def test_numpy_matches_hand_written_formula(text: str, formula: Callable) -> None:
    expression = parse_expression(text, field=FIELD, constants=CONSTANTS)
    values = expression.numpy(T)
    assert values.dtype == np.float64 and values.shape == T.shape
    with np.errstate(all="ignore"):
        assert_agree(values, formula(T))
    assert not expression.is_constant


@pytest.mark.parametrize(("text", "formula"), CASES, ids=[c[0] for c in CASES])
@pytest.mark.parametrize("kind", [ca.SX, ca.MX], ids=["SX", "MX"])
def test_casadi_matches_numpy(text: str, formula: Callable, kind: Any) -> None:
    expression = parse_expression(text, field=FIELD, constants=CONSTANTS)
    assert_agree(casadi_values(expression, T, kind), expression.numpy(T))


def test_casadi_on_numbers_and_vectors() -> None:
    expression = parse_expression("A*exp(-t/T)*cos(w*t) + 0.5", field=FIELD, constants=CONSTANTS)
    expected = expression.numpy(T[:5])
    assert_agree(np.asarray(expression.casadi(ca.DM(T[:5]))).ravel(), expected)
    assert_agree(float(expression.casadi(T[3])), expected[3])
    vector = ca.SX.sym("t", 5)
    f = ca.Function("f", [vector], [expression.casadi(vector)])
    assert_agree(np.asarray(f(T[:5])).ravel(), expected)


def test_scalar_and_broadcast_shapes() -> None:
    expression = parse_expression("sin(t) + 1", field=FIELD)
    scalar = expression.numpy(0.3)
    assert isinstance(scalar, np.ndarray) and scalar.shape == ()
    assert float(scalar) == np.sin(0.3) + 1
    grid = np.arange(6.0).reshape(2, 3)
    assert expression.numpy(grid).shape == (2, 3)


def test_constant_expression() -> None:
    expression = parse_expression("2*pi + e - A", field=FIELD, constants=CONSTANTS)
    expected = 2 * np.pi + np.e - 2.5
    assert expression.is_constant
    assert expression.numpy(1.0).shape == ()
    assert float(expression.numpy(1.0)) == expected
    values = expression.numpy(T)
    assert values.shape == T.shape and np.all(values == expected)
    assert_agree(casadi_values(expression, T), values)
    assert expression.casadi(ca.SX.sym("t", 3)).shape == (3, 1)
    assert expression.casadi(ca.MX.sym("t")).shape == (1, 1)
    assert not parse_expression("0*t + 1", field=FIELD).is_constant


def test_step_is_heaviside_with_step_at_zero_equal_one() -> None:
    expression = parse_expression("step(t)", field=FIELD)
    t = np.array([-1.0, -1e-300, -0.0, 0.0, 1e-300, 2.0])
    expected = np.array([0.0, 0.0, 1.0, 1.0, 1.0, 1.0])
    np.testing.assert_array_equal(expression.numpy(t), expected)
    np.testing.assert_array_equal(casadi_values(expression, t), expected)


def test_expression_keeps_text_and_is_frozen() -> None:
    text = "  4*sin(2*pi*t)"
    expression = parse_expression(text, field=FIELD)
    assert expression.text == text
    assert expression == parse_expression(text, field=FIELD)
    target: Any = expression
    with pytest.raises(AttributeError):
        target.text = "t"


def test_both_kinds_are_time_functions(tmp_path: Path) -> None:
    path = tmp_path / "torques.csv"
    path.write_text("t,joint1\n0,1\n1,2\n")
    table = load_torque_table(path, columns=1, field=FIELD)
    assert isinstance(parse_expression("t", field=FIELD), TimeFunction)
    assert isinstance(table.column(0), TimeFunction)


# --- Rejection ---------------------------------------------------------------------------------

# (text, a fragment the message must contain)
FORBIDDEN: list[tuple[str, str]] = [
    ("__import__('os').system('ls')", "'__import__'"),
    ("os.system('ls')", "attribute access"),
    ("t.real", "attribute access"),
    ("t.__class__", "'__class__'"),
    ("__builtins__", "'__builtins__'"),
    ("(lambda: 1)()", "lambda"),
    ("[x for x in t]", "comprehensions"),
    ("sum(x for x in t)", "unknown function 'sum'"),
    ("t if t else 1", "conditional expressions"),
    ("t > 1", "comparisons"),
    ("t and 1", "boolean operators"),
    ("not t", "'not'"),
    ("t // 2", "'//'"),
    ("t % 2", "'%'"),
    ("~t", "'~'"),
    ("sin(t, 2)", "takes exactly 1 argument, got 2"),
    ("max(t)", "takes exactly 2 arguments, got 1"),
    ("foo(t)", "unknown function 'foo'"),
    ("tt", "unknown name 'tt'"),
    ("x", "unknown name 'x'"),
    ("'a'", "strings"),
    ("b'a'", "literal"),
    ("f'{t}'", "f-strings"),
    ("t[0]", "subscripts"),
    ("sin(x=t)", "keyword arguments"),
    ("sin(*t)", "starred"),
    ("1j", "complex"),
    ("True", "boolean"),
    ("None", "literal None"),
    ("(t, 1)", "tuples"),
    ("{'a': t}", "dicts"),
    ("(y := t)", "assignment"),
    ("sin", "is a function"),
    ("t(1)", "'t' is not a function"),
    ("sin(t)(1)", "calling the result"),
    ("1e999", "too large"),
    ("", "empty"),
    ("   ", "empty"),
    ("x" * 2001, "at most 2000"),
    ("+".join(["t"] * 500), "nested more than"),
    ("sin(t", "never closed"),
    ("import os", "not a valid expression"),
    ("t = 1", "not a valid expression"),
]


@pytest.mark.parametrize(("text", "fragment"), FORBIDDEN, ids=[f[0][:30] for f in FORBIDDEN])
def test_forbidden_constructs_are_rejected(text: str, fragment: str) -> None:
    with pytest.raises(DescriptionError) as caught:
        parse_expression(text, field=FIELD, source="scene.toml")
    error = caught.value
    assert error.field == FIELD and error.source == "scene.toml"
    assert FIELD in str(error) and "scene.toml" in str(error)
    assert fragment in error.message
    # Every message says what is allowed or expected, not only what is wrong.
    assert re.search(r"allowed|expected|must|call it as|simplify", error.message)


def test_rejected_constructs_list_the_allowed_ones() -> None:
    with pytest.raises(DescriptionError) as caught:
        parse_expression("t.real", field=FIELD, constants={"omega": 1.0})
    message = caught.value.message
    for allowed in ("t", "pi", "omega", "sin(x)", "min(x, y)", "step(x)", "**"):
        assert allowed in message


@pytest.mark.parametrize(("text", "suggestion"), [
    ("sine(t)", "did you mean 'sin'?"),
    ("Sin(t)", "did you mean 'sin'?"),
    ("tt", "did you mean 't'?"),
    ("Pi", "did you mean 'pi'?"),
    ("omgea*t", "did you mean 'omega'?"),
    ("stpe(t)", "did you mean 'step'?"),
])
def test_near_miss_names_get_a_suggestion(text: str, suggestion: str) -> None:
    with pytest.raises(DescriptionError, match=re.escape(suggestion)):
        parse_expression(text, field=FIELD, constants={"omega": 3.0})


@pytest.mark.parametrize(("text", "column"), [
    ("sin(t", "column 4"),
    ("  sin(t", "column 6"),
    ("4*sin(2*pi*t))", "column 14"),
    ("2 * * t", "column 5"),
    ("t + t[0]", "column 5"),
])
def test_errors_give_the_column(text: str, column: str) -> None:
    with pytest.raises(DescriptionError) as caught:
        parse_expression(text, field=FIELD)
    assert column in caught.value.message


def test_text_must_be_a_string() -> None:
    number: Any = 4
    with pytest.raises(DescriptionError, match="text expression"):
        parse_expression(number, field=FIELD)


@pytest.mark.parametrize(("constants", "fragment"), [
    ({"t": 1.0}, "reserved"),
    ({"sin": 1.0}, "reserved"),
    ({"pi": 3.0}, "reserved"),
    ({"__x": 1.0}, "identifier"),
    ({"a b": 1.0}, "identifier"),
    ({"k": float("nan")}, "finite number"),
    ({"k": True}, "finite number"),
    ({"k": "1"}, "finite number"),
])
def test_bad_constants_are_rejected(constants: dict, fragment: str) -> None:
    with pytest.raises(DescriptionError, match=fragment) as caught:
        parse_expression("t", field=FIELD, constants=constants)
    assert caught.value.field == FIELD


def test_numpy_scalar_constants_are_accepted() -> None:
    expression = parse_expression("k*t", field=FIELD, constants={"k": np.float64(2.0), "n": 3})
    assert float(expression.numpy(1.5)) == 3.0


# --- Never executes code -----------------------------------------------------------------------


@pytest.mark.parametrize("module", [expressions, tables, postfix])
def test_module_source_has_no_eval_exec_or_compile_calls(module: Any) -> None:
    source = Path(module.__file__).read_text()
    assert not re.search(r"\b(eval|exec|compile)\s*\(", source)
    called = {node.func.id for node in ast.walk(ast.parse(source))
              if isinstance(node, ast.Call) and isinstance(node.func, ast.Name)}
    assert not called & {"eval", "exec", "compile", "__import__", "getattr", "globals"}


def test_parsing_and_evaluating_never_run_code(monkeypatch: pytest.MonkeyPatch) -> None:
    """ast.parse compiles to an AST only; nothing may ask for executable code."""
    real_compile = builtins.compile

    def ast_only_compile(*args: Any, **kwargs: Any) -> Any:
        flags = args[3] if len(args) > 3 else kwargs.get("flags", 0)
        assert flags & ast.PyCF_ONLY_AST, "compile() asked for executable code"
        return real_compile(*args, **kwargs)

    def forbidden(*args: Any, **kwargs: Any) -> Any:
        raise AssertionError("eval/exec called")

    monkeypatch.setattr(builtins, "compile", ast_only_compile)
    monkeypatch.setattr(builtins, "eval", forbidden)
    monkeypatch.setattr(builtins, "exec", forbidden)
    for text, _ in CASES:
        expression = parse_expression(text, field=FIELD, constants=CONSTANTS)
        expression.numpy(T)
        expression.casadi(ca.SX.sym("t"))
    for text, _ in FORBIDDEN:
        with pytest.raises(DescriptionError):
            parse_expression(text, field=FIELD)


# --- Tables ------------------------------------------------------------------------------------

TABLE = "t,joint1,joint2\n0,1.5,-2\n0.5,3,0\n1.5,-1,4.25\n2,0.5,4\n"


def write(tmp_path: Path, text: str | bytes, name: str = "torques.csv") -> Path:
    path = tmp_path / name
    if isinstance(text, bytes):
        path.write_bytes(text)
    else:
        path.write_text(text, encoding="utf-8")
    return path


def test_table_loads(tmp_path: Path) -> None:
    table = load_torque_table(write(tmp_path, TABLE), columns=2, field=FIELD)
    np.testing.assert_array_equal(table.times, [0, 0.5, 1.5, 2])
    np.testing.assert_array_equal(table.values, [[1.5, -2], [3, 0], [-1, 4.25], [0.5, 4]])
    assert table.header == ("t", "joint1", "joint2")
    assert table.columns == 2
    assert table.column(1).name == "joint2"
    with pytest.raises(ValueError):
        table.values[0, 0] = 9.0
    with pytest.raises(IndexError):
        table.column(2)


def test_table_tolerates_bom_spaces_and_blank_lines(tmp_path: Path) -> None:
    text = "\ufeff t , joint1\n\n 0 , 1 \n1,2\n\n\n"
    table = load_torque_table(write(tmp_path, text), columns=1, field=FIELD)
    assert table.header == ("t", "joint1")
    np.testing.assert_array_equal(table.values[:, 0], [1, 2])


@pytest.mark.parametrize("i", [0, 1])
def test_table_interpolation_matches_np_interp_and_casadi(tmp_path: Path, i: int) -> None:
    table = load_torque_table(write(tmp_path, TABLE), columns=2, field=FIELD)
    column = table.column(i)
    assert isinstance(column, TableColumn)
    t = np.concatenate([np.linspace(-1.0, 3.0, 801), table.times])
    numpy_values = column.numpy(t)
    np.testing.assert_array_equal(numpy_values, np.interp(t, table.times, table.values[:, i]))
    for kind in (ca.SX, ca.MX):
        assert_agree(casadi_values(column, t, kind), numpy_values)
    # End values are held outside the table.
    assert float(column.numpy(-5.0)) == table.values[0, i]
    assert float(column.numpy(7.0)) == table.values[-1, i]
    outside = np.array([-5.0, -1e-9, 2.0 + 1e-9, 7.0])
    assert_agree(casadi_values(column, outside), column.numpy(outside))
    assert_agree(float(column.casadi(7.0)), table.values[-1, i])
    assert column.numpy(0.25).shape == ()
    assert column.casadi(ca.SX.sym("t", 3)).shape == (3, 1)


BAD_TABLES: list[tuple[str | bytes, str]] = [
    ("", "is empty"),
    ("\n\n", "is empty"),
    ("t,a,b\n", "at least 2"),
    ("t,a,b\n0,1,2\n", "at least 2"),
    ("t,a\n0,1\n1,2\n", "header has 2 column(s), expected 3"),
    ("t,a,b,c\n0,1,2,3\n1,2,3,4\n", "header has 4 column(s), expected 3"),
    ("time,a,b\n0,1,2\n1,2,3\n", "must be 't'"),
    ("t,,b\n0,1,2\n1,2,3\n", "header column 2 is empty"),
    ("t,a,b\n0,1,2\n1,2\n", "line 3 has 2 cell(s), expected 3"),
    ("t,a,b\n0,1,2\n1,x,3\n", "line 3, column 'a' (2): 'x' is not a number"),
    ("t,a,b\n0,1,2\n1,2,\n", "line 3, column 'b' (3): '' is not a number"),
    ("t,a,b\n0,1,nan\n1,2,3\n", "line 2, column 'b' (3): 'nan' is not finite"),
    ("t,a,b\n0,1,2\ninf,2,3\n", "'inf' is not finite"),
    ("t,a,b\n0,1,2\n1,2,3\n1,2,3\n", "line 4: t = 1.0 is not greater than the previous t = 1.0"),
    ("t,a,b\n0,1,2\n1,2,3\n0.5,2,3\n", "times must be strictly increasing"),
    (b"t,a,b\n0,1,2\n1,2,\xff\n", "cannot be read"),
]


@pytest.mark.parametrize(("text", "fragment"), BAD_TABLES, ids=[str(b[0])[:30] for b in BAD_TABLES])
def test_bad_tables_are_rejected(tmp_path: Path, text: str | bytes, fragment: str) -> None:
    path = write(tmp_path, text)
    with pytest.raises(DescriptionError) as caught:
        load_torque_table(path, columns=2, field=FIELD, source="scene.toml")
    error = caught.value
    assert error.field == FIELD and error.source == "scene.toml"
    assert FIELD in str(error) and str(path) in error.message
    assert fragment in error.message


def test_missing_table_and_directory(tmp_path: Path) -> None:
    with pytest.raises(DescriptionError, match="file not found") as caught:
        load_torque_table(tmp_path / "nope.csv", columns=1, field=FIELD)
    assert caught.value.field == FIELD and "header 't'" in caught.value.message
    with pytest.raises(DescriptionError, match="is not a file"):
        load_torque_table(tmp_path, columns=1, field=FIELD)


@pytest.mark.parametrize("columns", [0, -1, True, 1.0])
def test_table_column_count_must_be_positive_int(tmp_path: Path, columns: Any) -> None:
    with pytest.raises(ValueError, match="columns"):
        load_torque_table(write(tmp_path, TABLE), columns=columns, field=FIELD)


def test_expression_and_table_are_interchangeable(tmp_path: Path) -> None:
    table = load_torque_table(write(tmp_path, TABLE), columns=2, field=FIELD)
    drives: list[TimeFunction] = [parse_expression("4*sin(2*pi*t)", field=FIELD),
                                  table.column(0)]
    t = ca.SX.sym("t")
    f = ca.Function("f", [t], [ca.vertcat(*(d.casadi(t) for d in drives))])
    for time in (0.1, 0.7, 2.5):
        expected = np.array([d.numpy(time) for d in drives])
        assert_agree(np.asarray(f(time)).ravel(), expected)
    assert isinstance(drives[0], Expression)
