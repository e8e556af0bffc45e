"""Cylindrical contact laws (contact.stiffness = johnson, liu, pereira): formulas, the implicit
solve, potentials, the description, and single impacts against closed forms and references."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace
from typing import Any

import casadi as ca
import mpmath as mp
import numpy as np
import pytest
import sympy as sp
from scipy import integrate, optimize

from jointplay.common.errors import DescriptionError
from jointplay.derive import cylindrical as cy
from jointplay.derive.to_casadi import SympyToCasadi
from jointplay.robot import Robot, robot_from_dict

STEEL_E, STEEL_NU = 207e9, 0.3
E_STAR = STEEL_E / (2 * (1 - STEEL_NU**2))  # composite modulus of two steel parts
CLEARANCE, LENGTH = 30e-6, 0.02  # the default joint, with a 20 mm journal
LAWS = tuple(cy.LAWS)


# ---- independent formulas (numpy / mpmath) ------------------------------------------------

def johnson_w(d: float, c: float) -> float:
    """w = -W_{-1}(-exp(-lam)), lam = ln(4 c / d) - 1 (mpmath's Lambert W, 40 digits)."""
    with mp.workdps(40):
        lam = mp.log(4 * mp.mpf(c) / mp.mpf(d)) - 1
        return float(-mp.lambertw(-mp.exp(-lam), -1))


def johnson_force(d: float, c: float, length: float, e_star: float) -> float:
    """Johnson's implicit law d = F/(pi L E*) (ln(4 pi L E* c / F) - 1), solved exactly."""
    return math.pi * length * e_star * d / johnson_w(d, c)


def liu_force(d: float, c: float, length: float, e_star: float) -> float:
    return math.pi / 2 * e_star * length * d * math.sqrt(d / (2 * (c + d)))


def pereira_force(d: float, c: float, length: float, e_star: float) -> float:
    """The paper's units: N, mm, MPa."""
    c_mm, d_mm, l_mm, e_mpa = c * 1e3, d * 1e3, length * 1e3, e_star * 1e-6
    y = (1.51 * math.log(1000 * c_mm) ** -0.151 if c_mm < 0.34954
         else 0.0151 * c_mm + 1.151)
    n = y * c_mm**-0.005
    return (0.965 * c_mm + 0.0965) / c_mm * l_mm * e_mpa * d_mm**n


REFERENCE: dict[str, Callable[[float, float, float, float], float]] = {
    "johnson": johnson_force, "liu": liu_force, "pereira": pereira_force}


# ---- the generated expressions, as CasADi functions of (d, c, L, E*) ----------------------

def _compiled_law(kind: str) -> ca.Function:
    d, c, length, e_star = sp.symbols("d c L E", real=True)
    leaves = [ca.SX.sym(n) for n in ("d", "c", "L", "E")]
    law = cy.LAWS[kind](d, c, length, e_star)
    convert = SympyToCasadi(dict(zip((d, c, length, e_star), leaves, strict=True)))
    force, potential = convert(law.force), convert(law.potential)
    return ca.Function(kind, leaves, [force, potential, ca.jacobian(force, leaves[0])])


_FUNCTIONS: dict[str, ca.Function] = {}


def law_function(kind: str) -> ca.Function:
    if kind not in _FUNCTIONS:
        _FUNCTIONS[kind] = _compiled_law(kind)
    return _FUNCTIONS[kind]


def evaluate(kind: str, d: float, c: float = CLEARANCE, length: float = LENGTH,
             e_star: float = E_STAR) -> tuple[float, float, float]:
    force, potential, slope = law_function(kind)(d, c, length, e_star)
    return float(force), float(potential), float(slope)


SAMPLES = (1e-12, 1e-9, 1e-7, 1e-6, 3e-6, 8e-6)  # m, at c = 30 um


@pytest.mark.parametrize("kind", LAWS)
def test_each_law_against_its_formula(kind: str) -> None:
    """The generated force equals the law written independently (Johnson's through mpmath's
    Lambert W) at sample penetrations and clearances, to 1e-13."""
    for c in (1e-5, CLEARANCE, 4e-4, 2e-3):
        for d in (s * c / CLEARANCE for s in SAMPLES):
            got = evaluate(kind, d, c)[0]
            assert got == pytest.approx(REFERENCE[kind](d, c, LENGTH, E_STAR), rel=1e-13), (c, d)


def test_johnson_solves_its_implicit_law_to_machine_precision() -> None:
    """Put the force back into d(F): the residual is at the rounding level (4e-16 relative)."""
    b = math.pi * LENGTH * E_STAR
    for d in np.geomspace(1e-15, 8 * CLEARANCE * math.exp(-3), 400):
        force = evaluate("johnson", float(d))[0]
        back = force / b * (math.log(4 * b * CLEARANCE / force) - 1)
        assert abs(back - d) <= 4e-16 * d * 8, d


def _newton_function(steps: int) -> ca.Function:
    x = ca.SX.sym("lam")
    return ca.Function("w", [x], [cy.johnson_newton(x, ca.log, steps)])


def test_johnson_newton_step_count_is_enough_over_the_whole_range() -> None:
    """lam from 2 - ln 2 (d at the hand-over to the tangent) to 800 (beyond the 1e-300 floor
    of d for every c < 1 m): one step fewer than JOHNSON_NEWTON_STEPS already reaches
    mpmath's root to 2 ulp, so the last step only polishes (and fixes the derivative)."""
    low = 2 - math.log(2)
    lams = np.concatenate([low + np.geomspace(1e-14, 1.0, 300) - 1e-14,
                           np.linspace(low, 800.0, 1500)])
    with mp.workdps(40):
        exact = np.array([float(-mp.lambertw(-mp.exp(-mp.mpf(v)), -1)) for v in lams])
    for steps in (cy.JOHNSON_NEWTON_STEPS - 1, cy.JOHNSON_NEWTON_STEPS):
        fn = _newton_function(steps)
        got = np.array([float(fn(v)) for v in lams])
        assert np.max(np.abs(got - exact) / exact) <= 2 * np.finfo(float).eps, steps
    # and the count is not generous by accident: two steps fewer is not converged
    fewer = _newton_function(cy.JOHNSON_NEWTON_STEPS - 2)
    assert max(abs(float(fewer(v)) - e) / e for v, e in zip(lams, exact, strict=True)) > 1e-12


def test_johnson_slope_is_the_implicit_function_derivative() -> None:
    """AD through the unrolled Newton steps gives dF/dd = B / (w - 1) (implicit-function
    theorem), to 1e-13; beyond the hand-over the tangent B continues it (C1)."""
    b = math.pi * LENGTH * E_STAR
    for d in np.geomspace(1e-14, 0.39 * CLEARANCE, 60):
        w = johnson_w(float(d), CLEARANCE)
        assert evaluate("johnson", float(d))[2] == pytest.approx(b / (w - 1), rel=1e-13)
    d_lim = 8 * CLEARANCE * math.exp(-3)
    below, above = evaluate("johnson", d_lim * (1 - 1e-9)), evaluate("johnson", d_lim * 1.5)
    assert below[2] == pytest.approx(b, rel=1e-7)
    assert above[2] == pytest.approx(b, rel=1e-12)
    assert above[0] == pytest.approx(b * d_lim / 2 + b * 0.5 * d_lim, rel=1e-12)


@pytest.mark.parametrize("kind", LAWS)
def test_finite_at_and_around_zero_penetration(kind: str) -> None:
    """Force, potential and slope are finite (and 0 out of contact) at d = 0, at the
    smallest penetrations and just outside contact."""
    for d in (-1e-6, -1e-300, 0.0, 5e-324, 1e-300, 1e-200, 1e-30):
        values = evaluate(kind, d)
        assert all(math.isfinite(v) for v in values), (d, values)
        if d <= 0:
            assert values == (0.0, 0.0, 0.0)


@pytest.mark.parametrize("kind", LAWS)
def test_potential_is_the_integral_of_the_force(kind: str) -> None:
    """U(d) against adaptive quadrature of F from 0 to d, to 1e-10 (Liu's across the switch
    from its series to its closed form, Johnson's across the hand-over to the tangent)."""
    for d in (1e-9, 1e-7, 2.9e-6, 3.1e-6, 1e-5, 0.5 * CLEARANCE):
        quad, _ = integrate.quad(lambda s: evaluate(kind, s)[0], 0.0, d, epsabs=0,
                                 epsrel=1e-12, limit=200,
                                 points=[8 * CLEARANCE * math.exp(-3)]
                                 if d > 8 * CLEARANCE * math.exp(-3) else None)
        assert evaluate(kind, d)[1] == pytest.approx(quad, rel=1e-10), d


def test_liu_is_a_three_halves_power_law_at_small_penetration() -> None:
    """For d << c Liu's law is pi E* L / (2 sqrt(2 c)) d^1.5 (1 - x/2 + 3 x^2/8 + ...),
    x = d / c: a Hertz-type 3/2 power law."""
    k = math.pi * E_STAR * LENGTH / (2 * math.sqrt(2 * CLEARANCE))
    for d in (1e-12, 1e-10, 1e-8):
        ratio = evaluate("liu", d)[0] / (k * d**1.5)
        x = d / CLEARANCE
        assert ratio == pytest.approx(1 - x / 2 + 3 * x**2 / 8, rel=1e-10)


def test_pereira_follows_johnson_over_its_fitted_range() -> None:
    """The paper fitted its law to Johnson's: for clearances from 10 um to 3 mm and
    penetrations from 1 % to 20 % of the clearance the two agree within -20 % / +15 %
    (measured 0.80 to 1.14). With the paper's mm / MPa units read as SI the ratio would be
    off by a factor 1000^n."""
    ratios = [evaluate("pereira", f * c, c)[0] / johnson_force(f * c, c, LENGTH, E_STAR)
              for c in (1e-5, 3e-5, 1e-4, 3e-4, 1e-3, 3e-3) for f in np.geomspace(0.01, 0.2, 12)]
    assert min(ratios) > 0.78 and max(ratios) < 1.16


# ---- the description ------------------------------------------------------------------------

def _paper_robot(stiffness: str = "hertz", length: float | None = LENGTH) -> Robot:
    from jointplay.scene.definition import default_scene

    robot = default_scene().robot
    joints = tuple(replace(j, length=length) if j.has_clearance else j for j in robot.joints)
    return replace(robot, joints=joints, contact=replace(robot.contact, stiffness=stiffness))


def test_hertz_structure_and_layout_are_unchanged() -> None:
    """No new structure key, no new parameter for Hertz (a length given is ignored)."""
    plain, with_length = _paper_robot(length=None), _paper_robot()
    assert "contact_stiffness" not in plain.structure().as_dict()
    assert with_length.structure() == plain.structure()
    assert [p.name for p in with_length.parameters()] == [p.name for p in plain.parameters()]
    assert "stiffness" not in plain.to_dict()["contact"]


@pytest.mark.parametrize("kind", LAWS)
def test_cylindrical_layout_has_lengths_and_no_exponent(kind: str) -> None:
    robot = _paper_robot(kind)
    names = [p.name for p in robot.parameters()]
    assert robot.structure().contact_stiffness == kind
    assert "joint2.length" in names and "joint3.length" in names
    assert "contact.exponent" not in names
    assert robot.parameter_values()[names.index("joint3.length")] == LENGTH
    assert robot_from_dict(robot.to_dict()) == robot


def test_length_is_required_only_where_a_law_uses_it() -> None:
    _paper_robot("hertz", length=None)  # fine
    with pytest.raises(DescriptionError, match=r"joints\[2\]\.length.*required.*johnson"):
        _paper_robot("johnson", length=None)
    for bad in (0.0, -0.01, math.nan, math.inf):
        with pytest.raises(DescriptionError, match=r"joints\[2\]\.length"):
            _paper_robot("hertz", length=bad)
    data = _paper_robot("liu").to_dict()
    data["joints"][1]["length"] = "20 mm"
    with pytest.raises(DescriptionError, match=r"joints\[2\]\.length"):
        robot_from_dict(data)
    data["contact"]["stiffness"] = "hertzian"
    data["joints"][1]["length"] = 0.02
    with pytest.raises(DescriptionError, match=r"contact\.stiffness"):
        robot_from_dict(data)


def test_pereira_refuses_clearances_outside_its_fitted_range() -> None:
    robot = _paper_robot("pereira")
    with pytest.raises(DescriptionError, match=r"journal_radius.*Pereira"):
        replace(robot, joints=tuple(replace(j, journal_radius=j.bearing_radius - 2e-6)
                                    if j.has_clearance else j for j in robot.joints))


def test_pereira_range_is_checked_on_parameters_given_at_run_time() -> None:
    """A clearance set through simulate(scene, parameters=...) (or a whole vector, or a
    Stepper) is held to the same range as one read from the scene: a 1 um clearance used to
    run into NaN states with a message about rtol."""
    from jointplay.scene.definition import default_scene
    from jointplay.sim import Stepper, simulate

    scene = default_scene().with_robot(_paper_robot("pereira")).with_run(t_end=0.002)
    # below the range (1 um) and above it (10.1 mm; a negative journal radius, as once
    # here, is refused earlier as a radius out of range)
    for change in ({"joint2.journal_radius": 10.0e-3 - 1e-6},
                   {"joint2.bearing_radius": 9.97e-3 + 10.1e-3}):
        with pytest.raises(DescriptionError, match=r"joint2.*Pereira contact law.*5e-06 m"):
            simulate(scene, parameters=change)
    with pytest.raises(DescriptionError, match=r"joint3.*Pereira"):
        Stepper(scene, parameters={"joint3.bearing_radius": 9.971e-3})
    simulate(scene, parameters={"joint2.journal_radius": 10.0e-3 - 6e-6})  # inside: runs


# ---- single impacts -------------------------------------------------------------------------

MASS, SPEED = 2.0, 0.2


def _single_impact(kind: str, law: str, ce: float) -> Any:
    from sim_fixtures import make_scene, pin_in_bearing

    from jointplay.sim import simulate

    robot = pin_in_bearing(law=law, restitution=ce, clearance=CLEARANCE, mass=MASS)
    robot["joints"][0]["length"] = LENGTH
    robot["contact"]["stiffness"] = kind
    scene = make_scene(robot, initial={"dex1": SPEED}, t_end=4e-4, output_step=1e-4,
                       rtol=1e-10, atol=1e-10)
    return simulate(scene)


@pytest.mark.parametrize("kind", LAWS)
def test_undamped_impact_matches_the_energy_closed_form(kind: str) -> None:
    """ce = 1: the located maximum penetration solves U(d_max) = m v^2 / 2 with U the
    quadrature of the independent formula, the peak force is F(d_max) (both to 1e-7), and
    the journal leaves at the speed it came."""
    force = REFERENCE[kind]

    def energy(d: float) -> float:
        return integrate.quad(lambda s: force(s, CLEARANCE, LENGTH, E_STAR), 0, d,
                              epsabs=0, epsrel=1e-13, limit=200)[0] - MASS * SPEED**2 / 2

    d_max = optimize.brentq(energy, 1e-9, 0.39 * CLEARANCE, xtol=1e-22, rtol=1e-15)
    phase = _single_impact(kind, "lankarani-nikravesh", 1.0).impacts
    assert phase.speed[0] == pytest.approx(SPEED, rel=1e-9)
    assert phase.max_penetration[0] == pytest.approx(d_max, rel=1e-7)
    assert phase.peak_force[0] == pytest.approx(force(d_max, CLEARANCE, LENGTH, E_STAR),
                                                rel=1e-7)
    assert phase.restitution[0] == pytest.approx(1.0, abs=1e-8)
    assert bool(phase.separated[0])


@pytest.mark.parametrize("kind", LAWS)
def test_restitution_of_a_damped_impact(kind: str) -> None:
    """Flores' damping at ce = 0.5: as the damping form chi = x F_e / v- makes the rebound
    independent of the elastic law, the simulated restitution is the exact closed form
    x (1 + e) = ln((1 + x) / (1 - x e)) (sim_fixtures.restitution_closed_form; to 1e-7,
    measured <= 6e-9), and equal to that of the same impact under Hertz's law."""
    from sim_fixtures import restitution_closed_form

    from jointplay.derive.laws import damping_factor

    x = float(damping_factor("flores", sp.Float(0.5)))
    got = _single_impact(kind, "flores", 0.5).impacts.restitution[0]
    hertz = _single_impact("hertz", "flores", 0.5).impacts.restitution[0]
    assert got == pytest.approx(restitution_closed_form(x), rel=1e-7)
    assert got == pytest.approx(hertz, rel=1e-7)


# johnson in the quick tier, the other laws in the slow one
@pytest.mark.parametrize("kind", [pytest.param(k, marks=[pytest.mark.slow] * (k != "johnson"))
                                  for k in LAWS])
def test_elastic_runs_conserve_energy(kind: str) -> None:
    """ce = 1, no friction: two links with clearance at both joints falling under gravity
    through repeated impacts; kinetic + gravity + the law's potential is conserved to 1e-6 of
    the energy that moved (the integrator's tolerance is 1e-9)."""
    from sim_fixtures import (
        assert_finite,
        clearance_joint,
        make_scene,
        relative_balance,
        robot_table,
    )

    from jointplay.sim import simulate

    joints = [clearance_joint() | {"length": LENGTH}, clearance_joint() | {"length": LENGTH}]
    robot = robot_table(2, joints, restitution=1.0, drive=False)
    robot["contact"]["stiffness"] = kind
    result = simulate(make_scene(robot, initial={"q1": -0.3}, t_end=0.05, output_step=1e-3,
                                 rtol=1e-9, atol=1e-9))
    assert_finite(result)
    assert len(result.impacts) >= 4
    assert relative_balance(result) < 1e-6


def test_the_stated_ratios_to_johnson_on_the_default_joint() -> None:
    """The statements of docs/results/contact-laws.md and derive/cylindrical.py, recomputed
    from the independent formulas: on the default joint (c = 30 um, 20 mm journal) Hertz's
    force is 4 %, 21 % and 27 % of Johnson's at 10 nm, 1 um and 3 um (Liu's 7 %, 35 %, 44 %),
    and Pereira's 0.59, 0.85 and 1.08-1.10 of it at 10 nm, 100 nm and 1-3 um."""
    c, rb = 30e-6, 10e-3
    hertz = 4 / 3 * E_STAR * math.sqrt(rb * (rb - c) / c)

    def ratio(law: Callable[[float, float, float, float], float], d: float) -> float:
        return law(d, c, LENGTH, E_STAR) / johnson_force(d, c, LENGTH, E_STAR)

    assert LENGTH == 0.02
    for d, h, lu in ((1e-8, 0.04, 0.07), (1e-6, 0.21, 0.35), (3e-6, 0.27, 0.44)):
        assert hertz * d**1.5 / johnson_force(d, c, LENGTH, E_STAR) == pytest.approx(h, abs=0.005)
        assert ratio(liu_force, d) == pytest.approx(lu, abs=0.005)
    assert ratio(pereira_force, 1e-8) == pytest.approx(0.59, abs=0.005)
    assert ratio(pereira_force, 1e-7) == pytest.approx(0.85, abs=0.005)
    assert all(1.075 <= ratio(pereira_force, d) <= 1.105 for d in np.linspace(1e-6, 3e-6, 9))
