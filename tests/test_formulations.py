"""The recursive formulation against the closed form (Kane's equations) on random states.

For every link count k = 1..8, every joint kind and every effect a scene can compile (gravity,
drive, the contact laws and elastic laws, friction ramps, the lubricated film, wear), the
compiled model's functions built from the recursion over the chain must equal those built from
sympy.physics.mechanics' closed form: the mass matrix, the forcing (contact, friction, film,
gravity, drive and velocity terms), the forward dynamics, every block of its Jacobian, the
contact terms and the energies. Tolerance: 1e-12 relative to the largest entry of the closed
form's value (norm-wise), on states with every clearance joint in contact and sliding, float64,
fixed seeds.

The functions are CasADi graphs evaluated in-process (no C compiled), so this tests the
formulation; that the emitted C equals its graph is tested in test_generated.py.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from jointplay import Contact, Friction, Gravity, Joint, Link, Robot
from jointplay.robot.description import Lubrication, Wear
from jointplay.robot.structure import JOINT_KINDS

TOLERANCE = 1e-12
STATES_PER_CASE = 4
FORMULATIONS = ("recursive",)  # each checked against "closed"


@dataclass(frozen=True)
class Effects:
    """The compile-time effects of one case (what changes the generated code besides joints)."""

    gravity: bool = True
    drive: bool = True
    law: str = "lankarani-nikravesh"
    stiffness: str = "hertz"
    friction: str = "linear"  # "none", "linear" or "smooth"
    lubrication: str = "none"
    wear: str = "none"


EFFECTS = (
    Effects(),
    Effects(gravity=False, drive=False, law="hunt-crossley", friction="smooth"),
    Effects(law="gonthier", stiffness="johnson", lubrication="short-bearing", wear="archard"),
    Effects(law="flores", stiffness="liu", friction="none", lubrication="long-bearing"),
    Effects(drive=False, stiffness="pereira", friction="smooth", wear="archard"),
)


def _kinds(k: int) -> tuple[str, ...]:
    """Every kind in turn, starting at a different one for each k (so each kind is the first,
    base joint somewhere, and a chain of 4 or more holds every kind)."""
    return tuple(JOINT_KINDS[(k + i) % len(JOINT_KINDS)] for i in range(k))


# (kinds, effects): k = 1..8 with mixed kinds and effects in turn, and chains of each single
# kind (a locked-only chain has no coordinate and is not a model).
CASES: list[tuple[tuple[str, ...], Effects]] = (
    [(_kinds(k), EFFECTS[k % len(EFFECTS)]) for k in range(1, 9)]
    + [((kind,) * 3, EFFECTS[i]) for i, kind in enumerate(("ideal", "clearance",
                                                           "locked_clearance"))]
    + [(("locked", "ideal", "locked"), EFFECTS[0])])


def _case_id(case: tuple[tuple[str, ...], Effects]) -> str:
    kinds, effects = case
    short = {"ideal": "i", "clearance": "c", "locked": "l", "locked_clearance": "lc"}
    return f"k{len(kinds)}-{'.'.join(short[k] for k in kinds)}-{effects.law}-{effects.stiffness}"


def _robot(kinds: Sequence[str], effects: Effects, rng: np.random.Generator) -> Robot:
    links = []
    for _ in kinds:
        length = rng.uniform(0.1, 1.0)
        links.append(Link(length=length, mass=rng.uniform(0.2, 5.0),
                          inertia=rng.uniform(1e-3, 0.3), com=rng.uniform(0.0, length)))
    joints = []
    for kind in kinds:
        rb = rng.uniform(8e-3, 12e-3)
        joints.append(Joint(kind=kind, angle=rng.uniform(-2.0, 2.0), bearing_radius=rb,  # type: ignore[arg-type]
                            journal_radius=rb - rng.uniform(1e-5, 1e-4),
                            bearing_E=rng.uniform(70e9, 210e9),
                            bearing_nu=rng.uniform(0.25, 0.35),
                            journal_E=rng.uniform(70e9, 210e9),
                            journal_nu=rng.uniform(0.25, 0.35),
                            length=rng.uniform(5e-3, 2e-2)))
    angle = rng.uniform(0.0, 2.0 * math.pi)
    friction = (Friction(law="none") if effects.friction == "none"
                else Friction(law="coulomb", ramp=effects.friction))  # type: ignore[arg-type]
    return Robot(
        links=tuple(links), joints=tuple(joints), name=f"eq{len(kinds)}",
        payload_mass=rng.uniform(0.0, 2.0),
        gravity=Gravity(effects.gravity, (9.81 * math.cos(angle), 9.81 * math.sin(angle))),
        contact=Contact(law=effects.law, stiffness=effects.stiffness,  # type: ignore[arg-type]
                        restitution=rng.uniform(0.5, 0.95)),
        friction=friction, drive=effects.drive,
        lubrication=Lubrication(model=effects.lubrication), wear=Wear(model=effects.wear))


@cache
def _functions(kinds: tuple[str, ...], effects: Effects, formulation: str
               ) -> dict[str, Any]:
    from jointplay.derive.codegen import build_functions
    from jointplay.derive.symbolic import derive

    robot = _robot(kinds, effects, np.random.default_rng(0))
    functions, _ = build_functions(derive(robot.structure(), formulation), formulation)
    return {fn.name(): fn for fn in functions}


def _random_inputs(kinds: Sequence[str], effects: Effects, rng: np.random.Generator
                   ) -> dict[str, np.ndarray]:
    """x with every clearance joint in contact (|e| = 1.02..1.2 c) and sliding, torques and
    impact speeds; the parameters of the case's robot."""
    robot = _robot(kinds, effects, np.random.default_rng(0))
    layout_coordinates = _coordinate_kinds(kinds)
    n = len(layout_coordinates)
    x = np.zeros(2 * n)
    for i, (kind, joint) in enumerate(layout_coordinates):
        if kind == "angle":
            x[i] = rng.uniform(-math.pi, math.pi)
            x[n + i] = rng.uniform(-3.0, 3.0)
        elif kind == "ex":
            j = robot.joints[joint - 1]
            c = j.bearing_radius - j.journal_radius
            phi = rng.uniform(0.0, 2.0 * math.pi)
            radius = c * rng.uniform(1.02, 1.2)
            x[i], x[i + 1] = radius * math.cos(phi), radius * math.sin(phi)
            x[n + i], x[n + i + 1] = rng.uniform(-0.05, 0.05, size=2)
    n_torques = sum(1 for k in kinds if k in ("ideal", "clearance")) if effects.drive else 0
    n_clearance = sum(1 for k in kinds if k in ("clearance", "locked_clearance"))
    return {"x": x, "q": x[:n], "tau": rng.uniform(-20.0, 20.0, size=n_torques),
            "p": np.asarray(robot.parameter_values(), dtype=float),
            "v_imp": rng.uniform(0.01, 0.5, size=n_clearance), "udot": rng.normal(size=n)}


def _coordinate_kinds(kinds: Sequence[str]) -> list[tuple[str, int]]:
    angles = [("angle", i) for i, k in enumerate(kinds, 1) if k in ("ideal", "clearance")]
    ecc = [(axis, i) for i, k in enumerate(kinds, 1) if k in ("clearance", "locked_clearance")
           for axis in ("ex", "ey")]
    return angles + ecc


def _evaluate(fn: Any, inputs: dict[str, np.ndarray]) -> list[np.ndarray]:
    args = [inputs[name] if name in inputs else np.zeros(fn.size_in(i))
            for i, name in enumerate(fn.name_in())]
    return [np.asarray(out, dtype=float) for out in fn.call(args)]


def _assert_close(actual: np.ndarray, expected: np.ndarray, what: str) -> None:
    assert actual.shape == expected.shape, f"{what}: shape {actual.shape} != {expected.shape}"
    if expected.size == 0:
        return
    assert np.all(np.isfinite(actual)), f"{what}: non-finite values"
    scale = float(np.max(np.abs(expected)))
    error = float(np.max(np.abs(actual - expected)))
    assert error <= TOLERANCE * scale, (
        f"{what}: max error {error:.3e} exceeds {TOLERANCE:.0e} x max|expected| {scale:.3e}")


COMPARED = ("mass_matrix", "forcing", "forward_dynamics", "jac_forward_dynamics_inputs",
            "jac_state", "contact", "energy", "end_effector", "wear")


def _check(kinds: tuple[str, ...], effects: Effects, formulation: str) -> None:
    reference = _functions(kinds, effects, "closed")
    candidate = _functions(kinds, effects, formulation)
    assert set(candidate) == set(reference)
    rng = np.random.default_rng(len(kinds))
    for _ in range(STATES_PER_CASE):
        inputs = _random_inputs(kinds, effects, rng)
        for name in COMPARED:
            if name not in reference:
                continue
            expected = _evaluate(reference[name], inputs)
            actual = _evaluate(candidate[name], inputs)
            for out_name, a, e in zip(reference[name].name_out(), actual, expected,
                                      strict=True):
                _assert_close(a, e, f"{formulation} {name}.{out_name}")


_FAST = [c for c in CASES if len(c[0]) <= 4]
_SLOW = [c for c in CASES if len(c[0]) > 4]


@pytest.mark.parametrize("formulation", FORMULATIONS)
@pytest.mark.parametrize("case", _FAST, ids=_case_id)
def test_recursion_equals_closed_form(case: tuple[tuple[str, ...], Effects],
                                      formulation: str) -> None:
    _check(*case, formulation)


@pytest.mark.slow
@pytest.mark.parametrize("formulation", FORMULATIONS)
@pytest.mark.parametrize("case", _SLOW, ids=_case_id)
def test_recursion_equals_closed_form_long_chains(case: tuple[tuple[str, ...], Effects],
                                                  formulation: str) -> None:
    _check(*case, formulation)


def test_every_kind_and_effect_is_covered() -> None:
    """The cases hold every joint kind at every k >= 4, and every effect value."""
    for kinds, _ in CASES:
        if len(kinds) >= 4:
            assert set(kinds) == set(JOINT_KINDS)
    for field in ("gravity", "drive", "law", "stiffness", "friction", "lubrication", "wear"):
        used = {getattr(e, field) for _, e in CASES}
        offered = {getattr(e, field) for e in EFFECTS}
        assert used == offered and len(offered) >= 2, field


def test_looped_state_jacobian_equals_closed_form(monkeypatch: pytest.MonkeyPatch) -> None:
    """The state Jacobian of long chains (columns differentiated in a loop) is the same
    Jacobian: forced on for a short chain (the k = 3 case above: joints with two, one and
    three coordinates, and a film; its closed form is shared)."""
    from jointplay.derive import codegen, recursive_jacobians
    from jointplay.derive.symbolic import derive

    kinds, effects = _kinds(3), EFFECTS[3]
    monkeypatch.setattr(recursive_jacobians, "LOOPED_STATE_JACOBIAN_FROM", 1)
    robot = _robot(kinds, effects, np.random.default_rng(0))
    functions, _ = codegen.build_functions(derive(robot.structure(), "recursive"))
    looped = {fn.name(): fn for fn in functions}
    assert "jac_state_columns_tangents" in {f.name() for f in looped["jac_state"].find_functions()}
    reference = _functions(kinds, effects, "closed")
    rng = np.random.default_rng(7)
    for _ in range(STATES_PER_CASE):
        inputs = _random_inputs(kinds, effects, rng)
        for name in ("jac_state", "jac_forward_dynamics_inputs"):
            for a, e in zip(_evaluate(looped[name], inputs), _evaluate(reference[name], inputs),
                            strict=True):
                _assert_close(a, e, f"looped {name}")


def test_formulation_switch(monkeypatch: pytest.MonkeyPatch) -> None:
    """auto: closed form up to the threshold, the recursion from it; the environment and an
    explicit argument override; a wrong value names where it came from and what is allowed;
    the formulation is part of the input hash."""
    from jointplay.common.errors import DescriptionError
    from jointplay.store import formulation as f
    from jointplay.store.stamp import provenance

    monkeypatch.delenv(f.ENVIRONMENT, raising=False)
    rng = np.random.default_rng(0)
    small = _robot(("locked", "clearance", "clearance", "locked"), EFFECTS[0], rng).structure()
    large = _robot(("clearance",) * 3, EFFECTS[0], rng).structure()
    assert f.coordinate_count(small) == 6 < f.RECURSIVE_FROM_COORDINATES
    assert f.formulation_for(small) == "closed"
    assert f.coordinate_count(large) == 9 >= f.RECURSIVE_FROM_COORDINATES
    assert f.formulation_for(large) == "recursive"
    assert f.formulation_for(large, "closed") == "closed"
    monkeypatch.setenv(f.ENVIRONMENT, "recursive")
    assert f.formulation_for(small) == "recursive"
    assert f.formulation_for(small, "auto") == "closed"
    monkeypatch.setenv(f.ENVIRONMENT, "fast")
    with pytest.raises(DescriptionError, match=r"\$JOINTPLAY_FORMULATION.*'fast'.*auto"):
        f.formulation_for(small)
    with pytest.raises(DescriptionError, match=r"the formulation.*'kane'"):
        f.formulation_for(small, "kane")
    hashes = {provenance(small.as_dict(), name)["input_hash"] for name in f.FORMULATIONS}
    assert len(hashes) == 2


@pytest.mark.parametrize("case", [CASES[0], CASES[2], CASES[8]], ids=_case_id)
def test_state_jacobian_layout(case: tuple[tuple[str, ...], Effects]) -> None:
    """The recursion's state Jacobian is stored so that the BDF driver sees the form
    [0 I; Jq Jv] and factors the n x n Newton matrix: nothing in the first n rows but the 1
    of I and, where the M^-1 solves write the output in place, an exact 0 in the row of each
    column's own coordinate (2n a multiple of four and not: four solve columns a call, and
    two). A chain of clearance joints only takes AD of the ABA instead, the others the
    solves."""
    from types import SimpleNamespace

    from jointplay.derive.recursive_jacobians import differentiates_the_aba

    kinds, effects = case
    fn = _functions(kinds, effects, "recursive")["jac_state"]
    inputs = _random_inputs(kinds, effects, np.random.default_rng(3))
    n = fn.size1_in(0) // 2
    direct = set(kinds) <= {"clearance", "locked"}
    assert differentiates_the_aba(SimpleNamespace(joints=kinds)) == direct
    rows, columns = fn.sparsity_out(0).get_triplet()
    top = sorted((r, c) for r, c in zip(rows, columns, strict=True) if r < n)
    if direct:
        assert top == [(r, n + r) for r in range(n)]
    else:
        assert top == sorted((c % n, c) for c in range(2 * n))
        assert sorted(zip(rows, columns, strict=True)) == sorted(
            top + [(r, c) for c in range(2 * n) for r in range(n, 2 * n)])
    dense = np.asarray(fn.call([inputs[name] for name in fn.name_in()])[0].full())
    np.testing.assert_array_equal(dense[:n], np.hstack([np.zeros((n, n)), np.eye(n)]))
    assert np.all(np.isfinite(dense[n:])) and np.any(dense[n:] != 0)


# The effects each chain of the chain-rule test takes: every one of EFFECTS once.
_CHAIN_RULE_EFFECTS = {1: 4, 2: 0, 3: 1, 5: 2, 8: 3}


def _chain_rule_case(k: int) -> tuple[tuple[str, ...], Effects]:
    """A chain of k clearance joints and its effects."""
    return ("clearance",) * k, EFFECTS[_CHAIN_RULE_EFFECTS[k]]


# One window (k = 1), two from the ground (2), the first hung from a link (3), the loop over
# the joints below a window (5, 8).
@pytest.mark.parametrize("k", [1, 2, 3, pytest.param(5, marks=pytest.mark.slow),
                               pytest.param(8, marks=pytest.mark.slow)])
def test_chain_rule_state_jacobian(k: int, monkeypatch: pytest.MonkeyPatch,
                                   tmp_path: Path) -> None:
    """A chain of clearance joints takes the state Jacobian by the chain rule through each
    link's pose and twist (jointplay.derive.recursive_chain_rule). It must equal AD of the
    recursion's forward dynamics (the straight-line Jacobian, CasADi's own) to 1e-12 of its
    largest entry, and central differences of the forward dynamics to 1e-6 of the largest
    entry of each column plus their rounding error (100 eps max|xdot| / step; steps of 1e-7
    times the coordinate's scale: rad, rad/s, and the joint's clearance for an eccentricity
    and its rate), on states in contact and sliding. For k = 5 (the loop in the C, the
    gather into the output's pattern) the compiled C must give the graph's values."""
    from jointplay.derive import codegen, recursive_jacobians
    from jointplay.derive.symbolic import derive

    kinds, effects = _chain_rule_case(k)
    robot = _robot(kinds, effects, np.random.default_rng(0))
    # Forced on below the threshold (the chains it is used for take longer to build).
    monkeypatch.setattr(recursive_jacobians, "CHAIN_RULE_FROM", 1)
    assert recursive_jacobians.uses_the_chain_rule(robot.structure(), 3 * k)
    built, _ = codegen.build_functions(derive(robot.structure(), "recursive"))
    functions = {fn.name(): fn for fn in built}
    forward, jac = functions["forward_dynamics"], functions["jac_state"]
    assert "chain_rule_law" in {f.name() for f in jac.find_functions()}
    straight_line = forward.jacobian()
    n = 3 * k
    # The form the BDF driver factors: nothing in the first n rows but the 1 of I.
    rows, columns = jac.sparsity_out(0).get_triplet()
    assert sorted((r, c) for r, c in zip(rows, columns, strict=True) if r < n) == [
        (r, n + r) for r in range(n)]
    rng = np.random.default_rng(100 + k)
    for _ in range(2 if k < 5 else 1):
        inputs = _random_inputs(kinds, effects, rng)
        args = [inputs[name] for name in forward.name_in()]
        actual = np.asarray(jac.call(args)[0].full())
        expected = np.asarray(straight_line.call([*args, np.zeros(2 * n)])[0].full())
        _assert_close(actual, expected[:, :2 * n], f"chain rule jac_state, k = {k}")
        x = inputs["x"]
        scale = np.ones(2 * n)
        for j in range(k):
            joint = robot.joints[j]
            clearance = joint.bearing_radius - joint.journal_radius
            for offset in (k + 2 * j, k + 2 * j + 1):
                scale[offset] = scale[n + offset] = clearance
        for column in range(2 * n):
            step = 1e-7 * scale[column]
            plus, minus = x.copy(), x.copy()
            plus[column] += step
            minus[column] -= step
            high = np.asarray(forward(plus, *args[1:])).ravel()
            low = np.asarray(forward(minus, *args[1:])).ravel()
            rounding = 100 * np.finfo(float).eps * np.max(np.abs(high)) / step
            error = np.max(np.abs((high - low) / (2 * step) - actual[:, column]))
            assert error <= 1e-6 * np.max(np.abs(actual[:, column])) + rounding, (
                f"k = {k}, column {column}: central differences differ by {error:.3e}")
        if k == 5:
            import casadi as ca

            from jointplay.store.build import compile_source

            generator = ca.CodeGenerator("jac_state.c", {"with_header": False})
            generator.add(jac)
            library, _ = compile_source(generator.dump(), cache=tmp_path)
            compiled = ca.external("jac_state", str(library))
            _assert_close(np.asarray(compiled.call(args)[0].full()), actual,
                          "compiled chain rule jac_state")


# Ideal chains, some with locked joints (at the base, inside, at the tip), with and without
# gravity and drive.
_IDEAL_CASES = {
    1: (("ideal",), EFFECTS[0]),
    3: (("locked", "ideal", "ideal"), EFFECTS[1]),
    5: (("ideal", "ideal", "locked", "ideal", "locked"), EFFECTS[0]),
    8: (("ideal",) * 3 + ("locked",) + ("ideal",) * 4, EFFECTS[4]),
}


@pytest.mark.parametrize("k", [1, 3, 5, pytest.param(8, marks=pytest.mark.slow)])
def test_ideal_chain_derivatives_in_closed_form(k: int) -> None:
    """A chain of ideal (and locked) joints takes dID/dx in closed form
    (jointplay.derive.ideal_derivatives). The state Jacobian built on it must equal AD of the
    recursion's forward dynamics (CasADi's own, straight-line) to 1e-12 of its largest
    entry, on random states with moving joints at speed."""
    from jointplay.derive import codegen, ideal_derivatives, recursive_jacobians
    from jointplay.derive.symbolic import derive

    kinds, effects = _IDEAL_CASES[k]
    robot = _robot(kinds, effects, np.random.default_rng(0))
    assert ideal_derivatives.applies(robot.structure())
    assert recursive_jacobians.IDEAL_DERIVATIVES_IN_CLOSED_FORM
    built, _ = codegen.build_functions(derive(robot.structure(), "recursive"))
    functions = {fn.name(): fn for fn in built}
    forward, jac = functions["forward_dynamics"], functions["jac_state"]
    straight_line = forward.jacobian()
    n = sum(1 for kind in kinds if kind == "ideal")
    rng = np.random.default_rng(200 + k)
    for _ in range(3):
        inputs = _random_inputs(kinds, effects, rng)
        args = [inputs[name] for name in forward.name_in()]
        actual = np.asarray(jac.call(args)[0].full())
        expected = np.asarray(straight_line.call([*args, np.zeros(2 * n)])[0].full())
        _assert_close(actual, expected[:, :2 * n], f"closed-form dID/dx jac_state, k = {k}")


def test_reciprocal_sqrt_only_in_the_recursion() -> None:
    """x^(-1/2) (the unit normal's 1/|e|) becomes 1/sqrt(x) in the recursive formulation's C
    and stays pow in the closed form's (whose checked-in C and figures it would move); both
    give the same value to within an ulp."""
    import casadi as ca
    import sympy as sp

    from jointplay.derive.to_casadi import SympyToCasadi

    x, x_sx = sp.Symbol("x", positive=True), ca.SX.sym("x")
    values = {}
    powers = {ca.OP_POW, ca.OP_CONSTPOW}
    for formulation, expected, absent in (("recursive", {ca.OP_SQRT}, powers),
                                          ("closed", powers, {ca.OP_SQRT})):
        out = SympyToCasadi({x: x_sx}, formulation=formulation)(x ** sp.Rational(-1, 2))
        fn = ca.Function("f", [x_sx], [out])
        ops = {fn.instruction_id(k) for k in range(fn.n_instructions())}
        assert ops & expected and not ops & absent, (formulation, ops)
        values[formulation] = float(fn(2.0))
    assert values["recursive"] == pytest.approx(values["closed"], rel=2.3e-16)
    assert values["recursive"] == pytest.approx(2.0 ** -0.5, rel=2.3e-16)


@pytest.mark.parametrize("formulation", ("closed", "recursive"))
@pytest.mark.parametrize("case", [CASES[1], CASES[3]], ids=_case_id)
def test_input_directions_are_the_input_jacobians_times_the_seeds(
        case: tuple[tuple[str, ...], Effects], formulation: str) -> None:
    """forward_dynamics_input_directions (forward-mode AD, what a sensitivity step calls) is
    d xdot / d p times the seeds' p rows plus d xdot / d v_imp times their v_imp rows, from
    the full input blocks of jac_forward_dynamics_inputs (reverse mode), column by column."""
    from jointplay.derive.deferred import INPUT_DIRECTIONAL, INPUT_DIRECTIONS, INPUT_JACOBIANS

    kinds, effects = case
    functions = _functions(kinds, effects, formulation)
    directional, blocks = functions[INPUT_DIRECTIONAL], functions[INPUT_JACOBIANS]
    rng = np.random.default_rng(11)
    for _ in range(STATES_PER_CASE):
        inputs = _random_inputs(kinds, effects, rng)
        _, d_p, d_v = (np.asarray(b.full() if hasattr(b, "full") else b, dtype=float)
                       for b in _evaluate(blocks, inputs))
        n_p = d_p.shape[1]
        seeds = rng.standard_normal((n_p + d_v.shape[1], INPUT_DIRECTIONS))
        seeds[:, -1] = 0.0  # an unused column gives zeros
        actual = _evaluate(directional, {**inputs, "seeds": seeds})[0]
        expected = d_p @ seeds[:n_p] + d_v @ seeds[n_p:]
        _assert_close(actual, expected, f"{INPUT_DIRECTIONAL} ({formulation})")
        np.testing.assert_array_equal(actual[:, -1], 0.0)
