"""Drive torques as restricted expressions of time, parsed and never executed.

A scene file is data, so a torque such as ``"4*sin(2*pi*t)"`` must never be run as Python.
The text is parsed with :func:`ast.parse` and every node is checked against a whitelist, then
turned into a small tree of our own. That tree is evaluated by walking it, with numpy for
simulation and plotting and with CasADi for building symbolic models, so both always compute
the same formula. Nothing is passed to ``eval``, ``exec`` or ``compile``. The same tree
becomes a postfix program for the compiled simulator (:mod:`jointplay.sim.postfix`).

Longer than the ~400 lines aimed at, on purpose: the whitelist, the validator that enforces
it and the two evaluators must change together, and splitting them would separate a new
function's grammar from its numpy and CasADi meanings.
"""

from __future__ import annotations

import ast
import math
import numbers
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, Protocol, TypeAlias, runtime_checkable

import casadi as ca
import numpy as np

from jointplay.common.errors import DescriptionError
from jointplay.common.hints import did_you_mean

__all__ = [
    "FUNCTIONS",
    "MAX_DEPTH",
    "MAX_LENGTH",
    "Expression",
    "TimeFunction",
    "parse_expression",
]

MAX_LENGTH = 2000
"""Longest expression text accepted; longer text is almost surely a mistake, not a torque."""

MAX_DEPTH = 200
"""Deepest tree accepted, so that evaluating it by recursion stays far from Python's limit."""

Symbolic: TypeAlias = Any
"""A CasADi ``SX``, ``MX`` or ``DM`` (CasADi ships no type information)."""

TIME = "t"
_NO_CONSTANTS: Mapping[str, float] = MappingProxyType({})
BUILTIN_CONSTANTS: Mapping[str, float] = {"pi": math.pi, "e": math.e}


def _step_numpy(x: np.ndarray) -> np.ndarray:
    return np.where(x >= 0.0, 1.0, 0.0)


def _step_casadi(x: Symbolic) -> Symbolic:
    return ca.if_else(x >= 0, 1, 0)


# name -> (arity, numpy implementation, CasADi implementation). fmin/fmax (not minimum/maximum)
# because CasADi's fmin/fmax follow C and ignore a NaN argument; numpy's fmin/fmax do too.
_FUNCTIONS: dict[str, tuple[int, Callable[..., Any], Callable[..., Any]]] = {
    "sin": (1, np.sin, ca.sin),
    "cos": (1, np.cos, ca.cos),
    "tan": (1, np.tan, ca.tan),
    "exp": (1, np.exp, ca.exp),
    "log": (1, np.log, ca.log),
    "sqrt": (1, np.sqrt, ca.sqrt),
    "abs": (1, np.abs, ca.fabs),
    "tanh": (1, np.tanh, ca.tanh),
    "sinh": (1, np.sinh, ca.sinh),
    "cosh": (1, np.cosh, ca.cosh),
    "atan": (1, np.arctan, ca.atan),
    "min": (2, np.fmin, ca.fmin),
    "max": (2, np.fmax, ca.fmax),
    "step": (1, _step_numpy, _step_casadi),
}

FUNCTIONS: Mapping[str, int] = {name: spec[0] for name, spec in _FUNCTIONS.items()}
"""The callable functions and their exact number of (positional) arguments."""

_RESERVED = frozenset({TIME, *BUILTIN_CONSTANTS, *_FUNCTIONS})

_BINARY: dict[type[ast.operator], str] = {
    ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/", ast.Pow: "**",
}
_UNARY: dict[type[ast.unaryop], str] = {ast.UAdd: "+", ast.USub: "-"}
_OPERATOR_TEXT: dict[type[ast.AST], str] = {
    ast.FloorDiv: "//", ast.Mod: "%", ast.MatMult: "@", ast.LShift: "<<", ast.RShift: ">>",
    ast.BitAnd: "&", ast.BitOr: "|", ast.BitXor: "^", ast.Not: "not", ast.Invert: "~",
}
# What people most often try, phrased for the error message.
_CONSTRUCTS: dict[type[ast.AST], str] = {
    ast.Attribute: "attribute access (a.b) is",
    ast.Subscript: "subscripts (a[i]) are",
    ast.Lambda: "lambda functions are",
    ast.ListComp: "comprehensions are",
    ast.SetComp: "comprehensions are",
    ast.DictComp: "comprehensions are",
    ast.GeneratorExp: "comprehensions are",
    ast.Compare: "comparisons (use step(x) for a switch) are",
    ast.BoolOp: "boolean operators (and, or) are",
    ast.IfExp: "conditional expressions (a if c else b; use step(x) for a switch) are",
    ast.JoinedStr: "f-strings are",
    ast.FormattedValue: "f-strings are",
    ast.List: "lists are",
    ast.Tuple: "tuples are",
    ast.Set: "sets are",
    ast.Dict: "dicts are",
    ast.NamedExpr: "assignment expressions (:=) are",
    ast.Starred: "starred arguments (*a) are",
    ast.Slice: "slices are",
    ast.Await: "await is",
    ast.Yield: "yield is",
    ast.YieldFrom: "yield is",
}


# --- The validated tree -----------------------------------------------------------------------
# Only these node kinds exist after parsing, so evaluation cannot reach anything else.


@dataclass(frozen=True)
class _Number:
    value: float


@dataclass(frozen=True)
class _Time:
    pass


@dataclass(frozen=True)
class _Unary:
    op: str  # "+" or "-"
    operand: _Node


@dataclass(frozen=True)
class _Binary:
    op: str  # one of + - * / **
    left: _Node
    right: _Node


@dataclass(frozen=True)
class _Call:
    function: str  # a key of _FUNCTIONS
    args: tuple[_Node, ...]


_Node: TypeAlias = "_Number | _Time | _Unary | _Binary | _Call"


def _has_time(node: _Node) -> bool:
    if isinstance(node, _Time):
        return True
    if isinstance(node, _Unary):
        return _has_time(node.operand)
    if isinstance(node, _Binary):
        return _has_time(node.left) or _has_time(node.right)
    if isinstance(node, _Call):
        return any(_has_time(a) for a in node.args)
    return False


def _apply(op: str, left: Any, right: Any) -> Any:
    """Apply a binary operator; the same code serves numpy arrays and CasADi objects."""
    if op == "+":
        return left + right
    if op == "-":
        return left - right
    if op == "*":
        return left * right
    if op == "/":
        return left / right
    return left ** right


def _eval_numpy(node: _Node, t: np.ndarray) -> np.ndarray:
    if isinstance(node, _Number):
        return np.float64(node.value)  # type: ignore[return-value]
    if isinstance(node, _Time):
        return t
    if isinstance(node, _Unary):
        value = _eval_numpy(node.operand, t)
        return -value if node.op == "-" else value
    if isinstance(node, _Binary):
        return _apply(node.op, _eval_numpy(node.left, t), _eval_numpy(node.right, t))
    numpy_function = _FUNCTIONS[node.function][1]
    return numpy_function(*(_eval_numpy(a, t) for a in node.args))


def _eval_casadi(node: _Node, t: Symbolic, kind: Any) -> Symbolic:
    if isinstance(node, _Number):
        return kind(node.value)
    if isinstance(node, _Time):
        return t
    if isinstance(node, _Unary):
        value = _eval_casadi(node.operand, t, kind)
        return -value if node.op == "-" else value
    if isinstance(node, _Binary):
        return _apply(node.op, _eval_casadi(node.left, t, kind), _eval_casadi(node.right, t, kind))
    casadi_function = _FUNCTIONS[node.function][2]
    return casadi_function(*(_eval_casadi(a, t, kind) for a in node.args))


def _as_casadi(t: Any) -> tuple[Symbolic, Any]:
    """Return ``t`` as a CasADi object and its class, so constants are built of the same kind."""
    for kind in (ca.SX, ca.MX, ca.DM):
        if isinstance(t, kind):
            return t, kind
    return ca.DM(np.asarray(t, dtype=np.float64)), ca.DM


# --- Public types ------------------------------------------------------------------------------


@runtime_checkable
class TimeFunction(Protocol):
    """Anything giving a value of time both numerically and symbolically.

    Both :class:`Expression` and :class:`TableColumn` satisfy it, so callers need not care
    whether a torque came from a formula or a table.
    """

    def numpy(self, t: float | np.ndarray) -> np.ndarray:
        """Evaluate at ``t`` (float64, the shape of ``t``)."""
        ...

    def casadi(self, t: Symbolic) -> Symbolic:
        """Build the same function of the CasADi object ``t``."""
        ...


@dataclass(frozen=True)
class Expression:
    """A validated expression of time ``t``; build it with :func:`parse_expression`.

    User constants are already substituted, so the expression is self-contained.
    """

    text: str
    root: _Node

    @property
    def is_constant(self) -> bool:
        """True when the expression does not depend on ``t``."""
        return not _has_time(self.root)

    def numpy(self, t: float | np.ndarray) -> np.ndarray:
        """Evaluate with numpy in float64; the result always has the shape of ``t``.

        Out-of-domain values follow IEEE rules (``log(-1)`` is NaN, ``1/0`` is inf) silently,
        as in CasADi, so that a simulation loop is not flooded with warnings.
        """
        times = np.asarray(t, dtype=np.float64)
        with np.errstate(all="ignore"):
            value = _eval_numpy(self.root, times)
        return np.array(np.broadcast_to(value, times.shape), dtype=np.float64)

    def casadi(self, t: Symbolic) -> Symbolic:
        """Build the expression on a CasADi ``SX``/``MX`` (or numeric ``DM``) ``t``.

        Element-wise for a vector ``t``; a constant expression is repeated to ``t``'s shape.
        """
        t, kind = _as_casadi(t)
        value = _eval_casadi(self.root, t, kind)
        if value.shape != t.shape:
            value = ca.repmat(value, t.shape[0], t.shape[1])
        return value


# --- Parsing -----------------------------------------------------------------------------------


def _allowed_summary(constants: Mapping[str, float]) -> str:
    names = ", ".join([TIME, *BUILTIN_CONSTANTS, *sorted(constants)])
    return f"allowed: numbers, the names {names}, + - * / ** and the functions {_functions()}"


def _functions() -> str:
    def signature(name: str, arity: int) -> str:
        return f"{name}({', '.join(['x', 'y'][:arity])})"

    return ", ".join(signature(name, arity) for name, arity in FUNCTIONS.items())


class _Validator:
    """Turn a Python AST into the validated tree, rejecting everything not whitelisted."""

    def __init__(self, field: str, source: str | None, constants: Mapping[str, float],
                 text: str = "", lead: int = 0) -> None:
        self.field = field
        self.source = source
        self.constants = constants
        self.body = text
        self.lines = text.split("\n")
        self.lead = lead  # characters of leading white space removed before parsing

    def fail(self, message: str) -> DescriptionError:
        return DescriptionError(self.field, message, self.source)

    def where(self, line: int, column: int) -> str:
        """Locate a 1-based character column of the parsed text in the caller's text."""
        if line == 1:
            column += self.lead
        return f"line {line}, column {column}" if len(self.lines) > 1 else f"column {column}"

    def reject(self, what: str, node: ast.AST) -> DescriptionError:
        where = ""
        if isinstance(node, ast.expr) and node.lineno <= len(self.lines):
            line, offset = node.lineno, node.col_offset
            # col_offset counts UTF-8 bytes; report characters.
            prefix = self.lines[line - 1].encode()[:offset].decode(errors="ignore")
            where = f" ({self.where(line, len(prefix) + 1)})"
        return self.fail(f"{what} not allowed{where}; {_allowed_summary(self.constants)}")

    def reject_dunders(self, tree: ast.AST) -> None:
        """Name the usual escape routes (``__import__``, ``x.__class__``) before anything else."""
        for node in ast.walk(tree):  # iterative, so safe on deep trees
            if isinstance(node, ast.Name):
                name = node.id
            elif isinstance(node, ast.Attribute):
                name = node.attr
            else:
                continue
            if name.startswith("__"):
                raise self.reject(f"the name {name!r} (names starting with '__') is", node)

    def visit(self, node: ast.AST, depth: int = 0) -> _Node:
        if depth > MAX_DEPTH:
            raise self.fail(f"expression is nested more than {MAX_DEPTH} levels deep "
                            "(a long chain of + counts one level per term); simplify it")
        if isinstance(node, ast.Constant):
            return self.number(node)
        if isinstance(node, ast.Name):
            return self.name(node)
        if isinstance(node, ast.UnaryOp):
            if type(node.op) not in _UNARY:
                raise self.reject(f"operator {_OPERATOR_TEXT.get(type(node.op), '?')!r} is", node)
            return _Unary(_UNARY[type(node.op)], self.visit(node.operand, depth + 1))
        if isinstance(node, ast.BinOp):
            if type(node.op) not in _BINARY:
                raise self.reject(f"operator {_OPERATOR_TEXT.get(type(node.op), '?')!r} is", node)
            return _Binary(_BINARY[type(node.op)], self.visit(node.left, depth + 1),
                           self.visit(node.right, depth + 1))
        if isinstance(node, ast.Call):
            return self.call(node, depth)
        raise self.reject(_CONSTRUCTS.get(type(node), f"the construct {type(node).__name__} is"),
                          node)

    def number(self, node: ast.Constant) -> _Number:
        value = node.value
        if type(value) is bool:
            raise self.reject(f"the boolean {value!r} is", node)
        if type(value) is complex:
            raise self.reject(f"the complex number {ast.unparse(node)} is", node)
        if type(value) is str:
            raise self.reject("strings are", node)
        if not isinstance(value, int | float):
            raise self.reject(f"the literal {ast.unparse(node)} is", node)
        try:
            number = float(value)
        except OverflowError:
            number = math.inf
        if not math.isfinite(number):
            written = ast.get_source_segment(self.body, node) or ast.unparse(node)
            raise self.fail(f"the number {written[:40]} is too large; "
                            "numbers must be finite floats")
        return _Number(number)

    def name(self, node: ast.Name) -> _Number | _Time:
        name = node.id
        if name.startswith("__"):
            raise self.reject(f"the name {name!r} (names starting with '__') is", node)
        if name == TIME:
            return _Time()
        if name in BUILTIN_CONSTANTS:
            return _Number(BUILTIN_CONSTANTS[name])
        if name in self.constants:
            return _Number(self.constants[name])
        if name in _FUNCTIONS:
            raise self.fail(f"{name!r} is a function; call it as {name}(...)")
        known = [TIME, *BUILTIN_CONSTANTS, *self.constants, *_FUNCTIONS]
        raise self.fail(f"unknown name {name!r}{_suggest(name, known)}; "
                        f"{_allowed_summary(self.constants)}")

    def call(self, node: ast.Call, depth: int) -> _Call:
        if not isinstance(node.func, ast.Name):
            # Reports e.g. the attribute of os.system(...) or the lambda of (lambda: 1)().
            self.visit(node.func, depth + 1)
            raise self.reject("calling the result of an expression is", node)
        name = node.func.id
        if name not in _FUNCTIONS:
            if name.startswith("__"):
                raise self.reject(f"the name {name!r} (names starting with '__') is", node)
            if name == TIME or name in BUILTIN_CONSTANTS or name in self.constants:
                raise self.fail(f"{name!r} is not a function; allowed functions: {_functions()}")
            raise self.fail(f"unknown function {name!r}{_suggest(name, list(_FUNCTIONS))}; "
                            f"allowed functions: {_functions()}")
        if node.keywords:
            raise self.reject(f"keyword arguments (in {name}(...)) are", node)
        for arg in node.args:
            if isinstance(arg, ast.Starred):
                raise self.reject("starred arguments (*a) are", arg)
        arity = FUNCTIONS[name]
        if len(node.args) != arity:
            plural = "s" if arity > 1 else ""
            raise self.fail(f"{name}() takes exactly {arity} argument{plural}, "
                            f"got {len(node.args)}; allowed functions: {_functions()}")
        return _Call(name, tuple(self.visit(a, depth + 1) for a in node.args))


def _suggest(name: str, known: list[str]) -> str:
    """A "did you mean" hint; case is ignored so that ``Pi`` or ``SIN`` find their match."""
    hint = did_you_mean(name, list(reversed(known)))
    return f" ({hint[2:]})" if hint else ""


def _check_constants(field: str, constants: Mapping[str, float],
                     source: str | None) -> dict[str, float]:
    """Check the scene's constants and return them as plain floats."""
    checked: dict[str, float] = {}
    for name, value in constants.items():
        if not isinstance(name, str) or not name.isidentifier() or name.startswith("__"):
            raise DescriptionError(field, f"constant name {name!r} must be an identifier "
                                   "not starting with '__'", source)
        if name in _RESERVED:
            raise DescriptionError(field, f"constant name {name!r} is reserved (t, pi, e and "
                                   "the function names cannot be redefined)", source)
        if (isinstance(value, bool) or not isinstance(value, numbers.Real)
                or not math.isfinite(value)):
            raise DescriptionError(field, f"constant {name!r} must be a finite number, "
                                   f"got {value!r}", source)
        checked[name] = float(value)
    return checked


def parse_expression(text: str, *, field: str, constants: Mapping[str, float] = _NO_CONSTANTS,
                     source: str | None = None) -> Expression:
    """Parse ``text`` as a torque expression of time ``t`` without ever executing it.

    ``constants`` are the scene's named numbers (substituted now); ``field`` and ``source``
    locate the text in error messages. Raises :class:`DescriptionError` saying what is wrong
    and what is allowed.
    """
    values = _check_constants(field, constants, source)
    validator = _Validator(field, source, values)
    if not isinstance(text, str):
        raise validator.fail(f"must be a text expression of t such as \"4*sin(2*pi*t)\", "
                             f"got {text!r}")
    if not text.strip():
        raise validator.fail("is empty; expected an expression of t such as \"4*sin(2*pi*t)\"")
    if len(text) > MAX_LENGTH:
        raise validator.fail(f"is {len(text)} characters long; at most {MAX_LENGTH} are allowed")
    body = text.lstrip()
    validator = _Validator(field, source, values, body, len(text) - len(body))
    try:
        tree = ast.parse(body, mode="eval")
    except SyntaxError as error:
        where = validator.where(error.lineno or 1, error.offset) + ": " if error.offset else ""
        raise validator.fail(f"is not a valid expression ({where}{error.msg}); expected an "
                             "expression of t such as \"4*sin(2*pi*t)\"") from None
    except (ValueError, RecursionError, MemoryError) as error:
        raise validator.fail(f"is not a valid expression ({error})") from None
    validator.reject_dunders(tree)
    return Expression(text, validator.visit(tree.body))


