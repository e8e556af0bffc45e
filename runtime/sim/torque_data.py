"""Drive torques as data for the compiled simulator (driver.c): each driven joint's torque is a
postfix program for its stack machine or a table of samples, so a new torque never needs a
compiler."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from jointplay.scene.expressions import Expression, TimeFunction
from jointplay.scene.tables import TableColumn
from jointplay.sim.postfix import postfix_program

# CasADi SX operations and the stack-machine opcode each maps to (with its arity).
_SX_OPS = {
    "OP_ADD": "+", "OP_SUB": "-", "OP_MUL": "*", "OP_DIV": "/", "OP_POW": "**",
    "OP_CONSTPOW": "**", "OP_NEG": "neg", "OP_SIN": "sin", "OP_COS": "cos", "OP_TAN": "tan",
    "OP_EXP": "exp", "OP_LOG": "log", "OP_SQRT": "sqrt", "OP_FABS": "abs", "OP_TANH": "tanh",
    "OP_SINH": "sinh", "OP_COSH": "cosh", "OP_ATAN": "atan", "OP_FMIN": "min",
    "OP_FMAX": "max", "OP_LE": "<=", "OP_LT": "<", "OP_IF_ELSE_ZERO": "if_else_zero",
    "OP_SQ": "sq", "OP_INV": "inv", "OP_TWICE": "twice",
}


def traced_program(fn: TimeFunction) -> tuple[list[int], list[float]]:
    """A time function's CasADi form on a symbolic t, as a postfix program for driver.c.

    Serves time functions built in code (identification excitations, for example); scene
    expressions have their own direct translation (:func:`postfix_program`).
    """
    import casadi as ca

    from jointplay.sim.postfix import OPCODES

    codes = {getattr(ca, name): OPCODES[op] for name, op in _SX_OPS.items()}
    t = ca.SX.sym("t")
    root = ca.SX(fn.casadi(t))
    ops: list[int] = []
    consts: list[float] = []

    def visit(x: Any) -> None:
        if x.is_symbolic():
            ops.append(OPCODES["t"])
            consts.append(0.0)
        elif x.is_constant():
            ops.append(OPCODES["const"])
            consts.append(float(x))
        else:
            if x.op() not in codes:
                raise TypeError(f"a torque of type {type(fn).__name__} uses a CasADi "
                                f"operation ({x.op()}) compiled torques do not support")
            for i in range(x.n_dep()):
                visit(x.dep(i))
            ops.append(codes[x.op()])
            consts.append(0.0)

    visit(root)
    return ops, consts


@dataclass(frozen=True)
class TorqueData:
    """Every driven joint's torque as data for driver.c: a postfix program or a table."""

    kind: np.ndarray
    start: np.ndarray
    length: np.ndarray
    ops: np.ndarray
    consts: np.ndarray
    table_t: np.ndarray
    table_v: np.ndarray


def torque_data(torques: tuple[TimeFunction, ...]) -> TorqueData:
    """Lay every torque out in four parallel arrays sharing one index: a program's opcodes
    and constants, or a table's times and values (the other pair padded with zeros)."""
    kinds, starts, lengths = [], [], []
    ops: list[int] = []
    consts: list[float] = []
    table_t: list[float] = []
    table_v: list[float] = []
    for fn in torques:
        if isinstance(fn, TableColumn):
            size = int(fn.times.size)
            kinds.append(1)
            program_ops, program_consts = [0] * size, [0.0] * size
            times, values = [float(v) for v in fn.times], [float(v) for v in fn.values]
        else:  # a scene expression directly, any other time function through its CasADi form
            program_ops, program_consts = (postfix_program(fn) if isinstance(fn, Expression)
                                           else traced_program(fn))
            size = len(program_ops)
            kinds.append(0)
            times, values = [0.0] * size, [0.0] * size
        starts.append(len(ops))
        lengths.append(size)
        ops += program_ops
        consts += program_consts
        table_t += times
        table_v += values
    return TorqueData(*(np.ascontiguousarray(a, dtype=d) for a, d in (
        (kinds, np.int32), (starts, np.int32), (lengths, np.int32), ([*ops, 0], np.int32),
        ([*consts, 0.0], np.float64), ([*table_t, 0.0], np.float64),
        ([*table_v, 0.0], np.float64))))
