"""Expressions as postfix programs for the compiled simulator's stack machine.

A scene's torque expression reaches the C loop as data (opcodes and constants), so a new
torque never needs a compiler; the opcode numbers are the contract with ``driver.c``.
"""

from __future__ import annotations

from jointplay.scene.expressions import (
    Expression,
    _Binary,
    _Node,
    _Number,
    _Time,
    _Unary,
)

# --- Postfix programs for compiled code -------------------------------------------------------
# Opcodes of the stack machine in jointplay/sim/driver.c (enum OP_*); the order is the contract.
OPCODES: dict[str, int] = {
    "const": 0, "t": 1, "neg": 2, "+": 3, "-": 4, "*": 5, "/": 6, "**": 7, "sin": 8, "cos": 9,
    "tan": 10, "exp": 11, "log": 12, "sqrt": 13, "abs": 14, "tanh": 15, "sinh": 16,
    "cosh": 17, "atan": 18, "min": 19, "max": 20, "step": 21, "<=": 22, "<": 23,
    "if_else_zero": 24, "sq": 25, "inv": 26, "twice": 27,
}
# Deepest operand stack driver.c allows (its STACK_DEPTH).
STACK_DEPTH = 256


def postfix_program(expression: Expression) -> tuple[list[int], list[float]]:
    """The expression as a postfix program: opcodes and, slot by slot, the constants.

    Compiled code evaluates it on a small stack, so a scene's torques reach C as data and
    never need a compiler. Raises ValueError if the stack would exceed ``STACK_DEPTH``.
    """
    ops: list[int] = []
    consts: list[float] = []
    depth = 0
    deepest = 0

    def emit(op: str, value: float = 0.0, effect: int = 0) -> None:
        nonlocal depth, deepest
        ops.append(OPCODES[op])
        consts.append(value)
        depth += effect
        deepest = max(deepest, depth)

    def visit(node: _Node) -> None:
        if isinstance(node, _Number):
            emit("const", node.value, 1)
        elif isinstance(node, _Time):
            emit("t", 0.0, 1)
        elif isinstance(node, _Unary):
            visit(node.operand)
            if node.op == "-":
                emit("neg")
        elif isinstance(node, _Binary):
            visit(node.left)
            visit(node.right)
            emit(node.op, 0.0, -1)
        else:
            for arg in node.args:
                visit(arg)
            emit(node.function, 0.0, 1 - len(node.args))

    visit(expression.root)
    if deepest > STACK_DEPTH:
        raise ValueError(f"{expression.text!r} needs a stack of {deepest} values; compiled "
                         f"torques allow {STACK_DEPTH}")
    return ops, consts


