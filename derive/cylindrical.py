"""Elastic laws of conformal line contact: a journal of axial length L in a cylindrical bearing.

Hertz's pin-in-hole law K d^1.5 (see :mod:`jointplay.derive.laws`) is strictly the law of a
sphere in a spherical seat: it ignores the axial length of a pin in a hole. The laws here are
the ones the clearance-joint literature uses for that conformal line contact. Which is the
stiffer depends on the length: on the default joint (10 mm steel bearing, 0.03 mm clearance)
with a 20 mm journal, Hertz's force is 4 % of Johnson's at d = 10 nm, 21 % at 1 um and 27 % at
3 um (Liu's 7 %, 35 %, 44 %): Hertz is the softest law there, not the stiffest (measured with
``tests/test_cylindrical.py``'s reference formulas; docs/explanation/models.md, "Contact laws
for a pin in a hole"). With the radial clearance c = Rb - Rj,
the composite modulus E* = 1 / ((1 - nu_b^2)/E_b + (1 - nu_j^2)/E_j) and the penetration
d = |e| - c > 0:

``johnson``  Johnson's law for a cylinder in a cylindrical hole (K. L. Johnson, Contact
    Mechanics, Cambridge University Press 1985, sec. 5.6; in the clearance-joint form of
    Flores, Ambrosio, Claro & Lankarani, Kinematics and Dynamics of Multibody Systems with
    Imperfect Joints, Springer 2008, and of Pereira, Ramalho & Ambrosio 2011 below), an
    implicit law:

        d = F / (pi L E*) * (ln(4 pi L E* c / F) - 1).

    With B = pi L E* and w = B d / F it reads w - ln w = ln(4 c / d) - 1 =: lam, so
    w = -W_{-1}(-exp(-lam)) (Lambert W, lower branch) and F = B d / w. d(F) is monotone only
    for F < 4 B c e^-2 (d < 4 c e^-2 ~ 0.54 c), beyond which it has no solution. The law is
    used up to w = 2 (d_lim = 8 c e^-3 ~ 0.40 c, where the tangent stiffness dF/dd =
    B / (w - 1) equals B) and continued beyond by that tangent: C1, and a contact that deep
    (a fifth of the clearance and more) is far outside the elastic range anyway.

    w is found in the generated code by a fixed number of Newton steps on
    phi(w) = w - ln w - lam, from w0 = lam + ln(lam + ln lam). phi is increasing and convex
    for w > 1, so after the first step the iterates decrease monotonically onto the root;
    over the whole range lam in [2 - ln 2, 800] (d from d_lim down to the 1e-300 floor of
    the power branch, for any c < 1 m) 4 steps reach the root to one ulp (checked in the
    tests against mpmath's Lambert W). :data:`JOHNSON_NEWTON_STEPS` takes one more, so the
    derivative that CasADi's AD takes through the unrolled steps is the implicit-function
    derivative: at a converged iterate the Newton map's derivative with respect to w
    vanishes, and the last step contributes exactly -phi_lam / phi_w = dw/dlam (the tests
    compare dF/dd with the closed form B / (w - 1)). The potential is closed-form:
    U = F^2 (2 w - 1) / (4 B).

``liu``  Liu, Zhang & Yang's law for cylindrical joints with clearance (C.-S. Liu, K. Zhang,
    L. Yang, Normal force-displacement relationship of cylindrical joints with clearance,
    J. Comput. Nonlinear Dyn. 1 (2006) 160-167; C.-S. Liu, K. Zhang, R. Yang, The FEM
    analysis and approximate model for cylindrical joints with clearances, Mech. Mach.
    Theory 42 (2007) 183-197):

        F = (pi / 2) E* L d sqrt(d / (2 (c + d))),

    explicit; for d << c it is the power law pi E* L / (2 sqrt(2 c)) d^1.5, for d >> c it
    stiffens to linear. Its potential integrates in closed form (with an asinh); below
    d = c / 10 a 16-term series replaces it, where the closed form loses digits to
    cancellation.

``pereira``  Pereira, Ramalho & Ambrosio's law for internal cylinder contact (C. M. Pereira,
    A. L. Ramalho, J. A. Ambrosio, A critical overview of internal and external cylinder
    contact force models, Nonlinear Dyn. 63 (2011) 681-697), fitted to Johnson's law with
    a stiffness and an exponent that depend on the clearance:

        F = (a c + b) / c * L E* d^n,  n = Y c^-0.005,  a = 0.965, b = 0.0965,
        Y = 1.51 (ln(1000 c))^-0.151   for 0.005 <= c < 0.34954,
        Y = 0.0151 c + 1.151          for 0.34954 <= c < 10,

    in the paper's units: N, mm and N/mm^2 (c, L and d in mm, E* in MPa). Here everything is
    SI and converted where the law is written; the description refuses clearances outside
    the fitted range. In those units the law follows Johnson's, which the paper fitted it
    to, within -20 % / +14 % over clearances of 10 um to 3 mm and penetrations of 1 % to 20 %
    of the clearance (measured 0.80 to 1.14; tested), and less closely below: 0.59 of
    Johnson's at d = 10 nm, 0.85 at 100 nm, 1.08 to 1.10 from 1 to 3 um on the default joint.

Every law is written on the power-branch trick of :func:`laws.penetration_power` so that it
and its derivatives are finite at and around d = 0 (the force is 0 for d <= 0).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import sympy as sp

# Newton steps on w - ln w = lam (Johnson's law): 4 reach the root to one ulp over the whole
# range; the fifth makes AD through the steps give the implicit-function derivative.
JOHNSON_NEWTON_STEPS = 5
# Where Johnson's law hands over to its tangent: w = 2, d_lim = 8 c e^-3.
JOHNSON_W_LIMIT = 2
# Liu's potential: the series below d / c = LIU_SERIES_BELOW, with LIU_SERIES_TERMS terms.
LIU_SERIES_BELOW = sp.Rational(1, 10)
LIU_SERIES_TERMS = 16
# Pereira-Ramalho-Ambrosio, internal contact (the paper's mm / MPa units).
PEREIRA_A = sp.Float("0.965")
PEREIRA_B = sp.Float("0.0965")
PEREIRA_Y_SWITCH_MM = sp.Float("0.34954")
MM = 1000  # mm per m
MPA = sp.Rational(1, 10**6)  # MPa per Pa

_TINY = sp.Float(1e-300)


@dataclass
class Elastic:
    """The elastic part of the normal force and its potential, both 0 for d <= 0."""

    force: sp.Expr  # F_e(d)
    potential: sp.Expr  # U(d) = integral of F_e from 0 to d
    stiffness: sp.Expr  # the law's leading coefficient (shown by `jointplay inspect`)


def composite_modulus(P: Callable[[str], sp.Symbol], joint: int) -> sp.Expr:
    """E* = 1 / (sigma_b + sigma_j), sigma = (1 - nu^2) / E."""
    sigma_b = (1 - P(f"joint{joint}.bearing_nu") ** 2) / P(f"joint{joint}.bearing_E")
    sigma_j = (1 - P(f"joint{joint}.journal_nu") ** 2) / P(f"joint{joint}.journal_E")
    return 1 / (sigma_b + sigma_j)


def _in_contact(delta: sp.Expr, value: sp.Expr) -> sp.Expr:
    return sp.Piecewise((value, delta > 0), (0, True))


def johnson_newton(lam: Any, log: Callable[[Any], Any], steps: int = JOHNSON_NEWTON_STEPS
                   ) -> Any:
    """w with w - ln w = lam (w >= 2 for lam >= 2 - ln 2), by ``steps`` Newton steps; for
    any number type with its ``log`` (CasADi SX in the generated code, floats in tests)."""
    w = lam + log(lam + log(lam))
    for _ in range(steps):
        w = w - (w - log(w) - lam) / (1 - 1 / w)
    return w


class JohnsonW(sp.Function):
    """w(lam) with w - ln w = lam, w >= 1: -W_{-1}(-exp(-lam)), opaque to sympy.

    sympy only carries the node (and knows dw/dlam = w / (w - 1)); the Newton steps are
    unrolled where the expression becomes CasADi (:meth:`casadi`), whose graph shares the
    repeated w. Unrolled in sympy, each step would copy the penetration's expression three
    times, and deriving a two-joint model took minutes instead of a second.
    """

    nargs = 1

    def fdiff(self, argindex: int = 1) -> sp.Expr:
        return self / (self - 1)

    @staticmethod
    def casadi(lam: Any) -> Any:
        import casadi as ca

        return johnson_newton(lam, ca.log)


def johnson(delta: sp.Expr, clearance: sp.Expr, length: sp.Expr, modulus: sp.Expr) -> Elastic:
    b = sp.pi * length * modulus
    d_lim = 8 * clearance * sp.exp(-3)
    d_pos = sp.Max(delta, _TINY)
    d_law = sp.Min(d_pos, d_lim)
    # ln(4 c) - ln(d), not ln(4 c / d): the derivative of 1/d at the 1e-300 floor would be
    # -1e600 = -inf, and inf * 0 (the floor's zero slope) a NaN in the Jacobian.
    w = JohnsonW(sp.log(4 * clearance) - sp.log(d_law) - 1)
    f_law = b * d_law / w
    beyond = sp.Max(delta - d_lim, 0)
    force = f_law + b * beyond
    f_lim = b * d_lim / JOHNSON_W_LIMIT
    potential = f_law**2 * (2 * w - 1) / (4 * b) + f_lim * beyond + b * beyond**2 / 2
    return Elastic(_in_contact(delta, force), _in_contact(delta, potential), b)


def liu_potential_factor(x: sp.Expr) -> sp.Expr:
    """G(x) = integral_0^x t^1.5 (1 + t)^-0.5 dt, accurate for every x >= 0."""
    root = sp.sqrt(x * (1 + x))
    asinh = sp.log(sp.sqrt(x) + sp.sqrt(1 + x))
    closed = root * (2 * x - 3) / 4 + sp.Rational(3, 4) * asinh
    # (1 + t)^-1/2 = sum_k binom(-1/2, k) t^k, integrated term by term.
    series = sum(sp.binomial(sp.Rational(-1, 2), k) / (k + sp.Rational(5, 2))
                 * x ** (k + sp.Rational(5, 2)) for k in range(LIU_SERIES_TERMS))
    return sp.Piecewise((series, x < LIU_SERIES_BELOW), (closed, True))


def liu(delta: sp.Expr, clearance: sp.Expr, length: sp.Expr, modulus: sp.Expr) -> Elastic:
    k = sp.pi * modulus * length / (2 * sp.sqrt(2))
    d_pos = sp.Max(delta, _TINY)
    force = k * d_pos ** sp.Rational(3, 2) / sp.sqrt(clearance + d_pos)
    # U = k integral_0^d s^1.5 (c + s)^-0.5 ds = k c^2 G(d / c)
    potential = k * clearance**2 * liu_potential_factor(d_pos / clearance)
    return Elastic(_in_contact(delta, force), _in_contact(delta, potential), k)


def pereira_exponent(clearance: sp.Expr) -> sp.Expr:
    c_mm = MM * clearance
    y = sp.Piecewise((sp.Float("1.51") * sp.log(1000 * c_mm) ** sp.Float("-0.151"),
                      c_mm < PEREIRA_Y_SWITCH_MM),
                     (sp.Float("0.0151") * c_mm + sp.Float("1.151"), True))
    return y * c_mm ** sp.Float("-0.005")


def pereira(delta: sp.Expr, clearance: sp.Expr, length: sp.Expr, modulus: sp.Expr) -> Elastic:
    from jointplay.derive.laws import penetration_power

    c_mm = MM * clearance
    n = pereira_exponent(clearance)
    # F[N] = (a c + b)/c * L[mm] E*[MPa] d[mm]^n, so in SI: K = ... * MM^n
    k = (PEREIRA_A * c_mm + PEREIRA_B) / c_mm * (MM * length) * (MPA * modulus) * MM**n
    return Elastic(k * penetration_power(delta, n),
                   k * penetration_power(delta, n + 1) / (n + 1), k)


LAWS: dict[str, Callable[[sp.Expr, sp.Expr, sp.Expr, sp.Expr], Elastic]] = {
    "johnson": johnson, "liu": liu, "pereira": pereira}


def elastic_law(kind: str, delta: sp.Expr, joint: int, P: Callable[[str], sp.Symbol]
                ) -> Elastic:
    """The elastic force of a cylindrical law at penetration ``delta`` of ``joint``."""
    if kind not in LAWS:
        raise ValueError(f"unknown cylindrical contact stiffness {kind!r}")
    clearance = P(f"joint{joint}.bearing_radius") - P(f"joint{joint}.journal_radius")
    return LAWS[kind](delta, clearance, P(f"joint{joint}.length"), composite_modulus(P, joint))
