"""sympy expression trees to CasADi SX, by a memoised walk.

sympy has no CasADi printer, and ``lambdify`` with a CasADi namespace fails on ``Piecewise``
and ``sign`` and silently returns NaN if ``math`` functions slip in. Walking the tree once with
a cache keyed by sub-expression shares common sub-expressions for free and is 10-40x faster
than ``lambdify(cse=True)``. Unknown node types raise instead of guessing.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import casadi as ca
import sympy as sp

_UNARY = {
    sp.sin: ca.sin,
    sp.cos: ca.cos,
    sp.tan: ca.tan,
    sp.exp: ca.exp,
    sp.log: ca.log,
    sp.tanh: ca.tanh,
    sp.Abs: ca.fabs,
    sp.sign: ca.sign,
}


def _children(node: sp.Basic) -> tuple[sp.Basic, ...]:
    """Sub-expressions to convert first; for a Piecewise, its values and its conditions'
    operands (conditions themselves are not numbers)."""
    if isinstance(node, sp.Piecewise):
        out: list[sp.Basic] = []
        for value, cond in node.args:
            out.append(value)
            if cond is not sp.true:
                out.extend(cond.args)
        return tuple(out)
    return tuple(node.args)


# The formulations whose emitted C writes x^(-1/2) as 1 / sqrt(x) (SympyToCasadi's
# ``formulation``). The closed form joins once the paper robot's model and the figures
# measured on it are regenerated, as with RECURSIVE_FROM_COORDINATES.
RECIPROCAL_SQRT_FORMULATIONS = ("recursive",)


class SympyToCasadi:
    """Convert sympy expressions, given a map from leaf symbols (or applied functions) to SX.

    For a ``formulation`` in :data:`RECIPROCAL_SQRT_FORMULATIONS` it emits x^(-1/2) as
    1 / sqrt(x) instead of libm's general ``pow``: the unit normal's 1/|e| in every contact
    evaluation, at a fraction of the cost. The two differ by round-off only, but round-off
    moves a run's step sequence; so only the recursive formulation takes it, and the closed
    form (the paper robot) keeps the C, and the figures measured on it, that it has."""

    def __init__(self, leaves: Mapping[sp.Basic, Any], *, formulation: str = "closed"
                 ) -> None:
        self._cache: dict[sp.Basic, Any] = dict(leaves)
        self._reciprocal_sqrt = formulation in RECIPROCAL_SQRT_FORMULATIONS

    def __call__(self, expr: Any) -> Any:
        if isinstance(expr, sp.MatrixBase):
            rows = [[self(expr[i, j]) for j in range(expr.cols)] for i in range(expr.rows)]
            return ca.vertcat(*[ca.horzcat(*r) for r in rows]) if rows else ca.SX(0, 1)
        return self._convert(sp.sympify(expr))

    def _convert(self, root: sp.Basic) -> Any:
        cache = self._cache
        if root in cache:
            return cache[root]
        # Iterative post-order walk: deep chains would overflow Python's recursion limit.
        stack: list[tuple[sp.Basic, bool]] = [(root, False)]
        while stack:
            node, expanded = stack.pop()
            if node in cache:
                continue
            if not expanded and node.args and not node.is_Number:
                stack.append((node, True))
                stack.extend((a, False) for a in _children(node) if a not in cache)
                continue
            cache[node] = self._node(node)
        return cache[root]

    def _node(self, node: sp.Basic) -> Any:
        cache = self._cache
        if isinstance(node, sp.Piecewise):
            result = ca.SX(float("nan"))  # sympy's value where no condition holds
            for value, cond in reversed(node.args):
                result = ca.if_else(self._condition(cond), cache[value], result)
            return result
        args = [cache[a] for a in node.args] if node.args else []
        if node.is_Number or node in (sp.pi, sp.E):
            return ca.SX(float(node))
        if isinstance(node, sp.Add):
            total = args[0]
            for a in args[1:]:
                total = total + a
            return total
        if isinstance(node, sp.Mul):
            prod = args[0]
            for a in args[1:]:
                prod = prod * a
            return prod
        if isinstance(node, sp.Pow):
            exponent = node.args[1]
            if exponent == sp.Rational(1, 2):
                return ca.sqrt(args[0])
            if exponent == -1:
                return 1 / args[0]
            if self._reciprocal_sqrt and exponent == sp.Rational(-1, 2):
                return 1 / ca.sqrt(args[0])
            if exponent.is_Integer:
                return ca.constpow(args[0], int(exponent))
            return ca.power(args[0], args[1])
        if isinstance(node, sp.Max):
            out = args[0]
            for a in args[1:]:
                out = ca.fmax(out, a)
            return out
        if isinstance(node, sp.Min):
            out = args[0]
            for a in args[1:]:
                out = ca.fmin(out, a)
            return out
        if isinstance(node, sp.atan2):
            return ca.atan2(args[0], args[1])
        custom = getattr(type(node), "casadi", None)  # a function that builds its own SX
        if custom is not None:
            return custom(*args)
        for fn, cafn in _UNARY.items():
            if isinstance(node, fn):
                return cafn(args[0])
        raise TypeError(f"cannot convert sympy node {type(node).__name__}: {node}")

    def _condition(self, cond: sp.Basic) -> Any:
        if cond is sp.true:
            return ca.SX(1)
        lhs, rhs = (self._cache[a] for a in cond.args)
        ops = {sp.StrictGreaterThan: lambda a, b: a > b, sp.GreaterThan: lambda a, b: a >= b,
               sp.StrictLessThan: lambda a, b: a < b, sp.LessThan: lambda a, b: a <= b}
        for kind, op in ops.items():
            if isinstance(cond, kind):
                return op(lhs, rhs)
        raise TypeError(f"cannot convert condition {cond}")


# CasADi's common-subexpression elimination on every emitted function: the symbolic laws and
# AD repeat subexpressions that are not shared nodes (at 12 clearance joints it takes the
# straight-line state Jacobian from 33779 to 21697 instructions). It merges identical
# operations only, so every output is bit for bit what it was.
FUNCTION_OPTIONS: dict[str, Any] = {"cse": True}


def emitted_function(name: str, inputs: list[Any], outputs: list[Any],
              input_names: list[str] | None = None, output_names: list[str] | None = None
              ) -> ca.Function:
    """``ca.Function`` with FUNCTION_OPTIONS (and the slots' names, when given)."""
    if input_names is None or output_names is None:
        return ca.Function(name, inputs, outputs, FUNCTION_OPTIONS)
    return ca.Function(name, inputs, outputs, input_names, output_names, FUNCTION_OPTIONS)
