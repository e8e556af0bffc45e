"""Contact and friction laws of a revolute clearance joint, written to stay finite everywhere.

Normal force, continuous dissipative Hertz family (Lankarani & Nikravesh 1990, J. Mech. Des.
112:369; Hunt & Crossley 1975, J. Appl. Mech. 42:440; Gonthier et al. 2004, Multibody Syst.
Dyn. 11:209; Flores, Machado, Silva & Martins 2011, "On the continuous contact force models
for soft materials in multibody dynamics", Multibody Syst. Dyn. 25:357-375):

    F_n = max(0, K d+^n (1 + x(ce) d'/v-)),   d+ = max(0, |e| - c),

with the pin-in-hole stiffness K = 4 / (3 (sb + sj)) sqrt(Rb Rj / (Rb - Rj)), s = (1 - nu^2)/E,
and v- the normal approach speed at the onset of this impact (an input, floored at the
parameter ``contact.impact_speed_floor`` for grazing contact). The outer max(0, .) stops the
damping term from pulling the bodies together while they separate.

Elastic laws of conformal cylinders (``contact.stiffness`` = johnson, liu, pereira; see
:mod:`jointplay.derive.cylindrical`) replace K d+^n by F_e(d), with the same damping factors.

Damping with any elastic law. The damping term is kept proportional to the elastic force:
F_n = F_e(d) (1 + x(ce) d'/v-), i.e. chi(d) = x F_e(d) / v- (for Hertz, x K d^n / v-). With
this choice every x(ce) above keeps its meaning exactly. For one impact of a mass m,
m d'' = -F_e(d) (1 + x d'/v-); with U(d) the elastic potential (dU = F_e dd) this is
m d' dd'/dU = -(1 + x d'/v-), an equation between d' and U in which the elastic law no longer
appears. The rebound speed, so the effective restitution, is the same function of (x, v-) for
every elastic law, and each x(ce) derived for K d^n (Lankarani-Nikravesh's energy balance,
Gonthier's and Flores' integrations) holds unchanged. A damping chi d^n d' with the Hertz
exponent, or a constant chi, would not have this property.

Friction, modified Coulomb law (Ambrosio 2002): F_t = -mu c_d(|v_t|) F_n v_t / |v_t| with the
dynamic correction c_d = 0 below v0, 1 above v1, and a ramp between: linear (the literature's)
or, as the named option ``smooth``, the C1 cubic s^2 (3 - 2 s).

Finiteness (the traps of the literature): the unit normal n = e/|e| is undefined at e = 0, and
step(d) * e/|e| is 0 * NaN there, derivatives included; and pow(0, n) differentiated by the
runtime exponent n is log(0) * 0 = NaN. Here |e| is evaluated as
sqrt(max(|e|^2, (1e-6 c)^2)): exact wherever |e| > 1e-6 c, bounded away from 0 below, where
d+ = 0 multiplies everything. Likewise v_t / |v_t| becomes v_t / max(|v_t|, v_floor) with the
direction floor v_floor = max(v0, v1 / 1000) (see :data:`DIRECTION_FLOOR`). The power d+^n is
a branch, d > 0 ? max(d, 1e-300)^n : 0, with no NaN in any derivative and a continuous
derivative in d at contact onset (n > 1).

The direction floor. Where v0 >= v1 / 1000 (the defaults: v0 = 1e-4, v1 = 1e-2 m/s) it is v0,
and the law is exact wherever c_d > 0 (below v0, c_d = 0 multiplies the floored quotient).
With v0 = 0 (the dynamic correction ramping from zero speed, as in other codes' regularised
Coulomb law) a floor of v0 would divide 0 by 0 at v_t = 0; v1 / 1000 takes over. The rule has
no parameter of its own: it scales with the ramp's width. Below the floor the force is
mu c_d F_n v_t / v_floor, which is smaller than the exact mu c_d F_n sign(v_t) by at most
mu F_n c_d(v1 / 1000) <= 1e-3 mu F_n (linear ramp; 3e-6 mu F_n for the smooth one), and its
slope in v_t stays below 2 mu F_n / v1, the ramp's own scale, so it adds no stiffness.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import sympy as sp

from jointplay.derive import cylindrical
from jointplay.robot.structure import Structure

# |e| is floored at this fraction of the radial clearance (see module docstring).
ECCENTRICITY_FLOOR = sp.Rational(1, 10**6)
# The friction direction v_t / max(|v_t|, v0, DIRECTION_FLOOR * v1) (see module docstring).
DIRECTION_FLOOR = sp.Rational(1, 10**3)


def friction_direction(sliding: sp.Expr, v0: sp.Expr, v1: sp.Expr) -> sp.Expr:
    """v_t / |v_t|, finite at v_t = 0 for every v0 >= 0 (exact where |v_t| >= the floor)."""
    return sliding / sp.Max(sp.Abs(sliding), v0, DIRECTION_FLOOR * v1)


def penetration_power(delta: sp.Expr, exponent: sp.Expr) -> sp.Expr:
    """max(0, delta)^exponent, with derivatives finite in delta *and* in the exponent.

    pow(max(0, d), n) differentiated by n gives log(0) * 0 = NaN out of contact; the branch
    keeps the power's base positive, and the untaken branch is masked exactly.
    """
    return sp.Piecewise((sp.Max(delta, sp.Float(1e-300)) ** exponent, delta > 0), (0, True))


@dataclass
class ContactTerms:
    clearance: sp.Expr  # c = Rb - Rj
    stiffness: sp.Expr  # K (Hertz), or the leading coefficient of a cylindrical law
    eccentricity: sp.Expr  # |e| (floored far below c)
    penetration: sp.Expr  # d = |e| - c (negative: no contact)
    penetration_rate: sp.Expr  # d' = e'.n
    sliding_speed: sp.Expr  # v_t: relative tangential speed of the contact points
    damping_factor: sp.Expr  # x(ce) of the chosen law
    normal_force: sp.Expr  # F_n >= 0, pushes the journal towards the bearing centre
    friction_factor: sp.Expr  # c_d(|v_t|) in [0, 1]
    friction_force: sp.Expr  # F_t, on the journal, along the tangent t = z x n
    force_x: sp.Expr  # total contact force on the journal, N components
    force_y: sp.Expr
    elastic_force: sp.Expr  # F_e(d): K d+^n, or a cylindrical law's
    potential: sp.Expr  # integral of F_e: K d+^(n+1) / (n+1) for Hertz
    dissipation: sp.Expr  # power lost to damping and friction: (F_n - F_e) d' - F_t v_t >= 0
    # (with a lubricant, minus the film's power F_film . e', see add_film)
    film: Any = None  # the lubricant film's terms (lubrication.FilmTerms) when compiled


def damping_factor(law: str, ce: sp.Expr) -> sp.Expr:
    """x(ce) in chi = x K / v-, for each law of the Hertz family."""
    if law == "lankarani-nikravesh":
        return sp.Rational(3, 4) * (1 - ce**2)
    if law == "hunt-crossley":
        return sp.Rational(3, 2) * (1 - ce)
    if law == "gonthier":
        return (1 - ce**2) / ce
    if law == "flores":
        return sp.Rational(8, 5) * (1 - ce) / ce
    raise ValueError(f"unknown contact law {law!r}")


def friction_ramp(ramp: str, speed: sp.Expr, v0: sp.Expr, v1: sp.Expr) -> sp.Expr:
    """c_d(|v_t|): 0 below v0, 1 above v1; linear or C1-smooth in between."""
    s = sp.Min(sp.Max((speed - v0) / (v1 - v0), 0), 1)
    if ramp == "linear":
        return s
    if ramp == "smooth":
        return s**2 * (3 - 2 * s)
    raise ValueError(f"unknown friction ramp {ramp!r}")


@dataclass(frozen=True)
class _Kinematics:
    """Where the journal sits in the bearing and how fast it moves, along the line of centres
    n = e/|e| and the tangent t = z x n."""

    eccentricity: sp.Expr  # |e|, floored far below c
    penetration: sp.Expr  # d = |e| - c
    normal: tuple[sp.Expr, sp.Expr]  # n
    tangent: tuple[sp.Expr, sp.Expr]  # t
    rate: sp.Expr  # d' = e'.n
    sliding: sp.Expr  # v_t, relative tangential speed of the contact points


@dataclass(frozen=True)
class _NormalForce:
    damping_factor: sp.Expr  # x(ce)
    stiffness: sp.Expr
    elastic: sp.Expr  # F_e(d)
    potential: sp.Expr  # integral of F_e
    normal: sp.Expr  # F_n >= 0


def contact_terms(
    structure: Structure,
    joint: int,
    ex: Any,
    ey: Any,
    vx: Any,
    vy: Any,
    omega_bearing: sp.Expr,
    omega_journal: sp.Expr,
    impact_speed: sp.Symbol,
    P: Callable[[str], sp.Symbol],
) -> ContactTerms:
    rb = P(f"joint{joint}.bearing_radius")
    rj = P(f"joint{joint}.journal_radius")
    clearance = rb - rj
    kin = _kinematics(ex, ey, vx, vy, clearance, rb, rj, omega_bearing, omega_journal)
    normal = _normal_force(structure, joint, kin, _hertz_stiffness(joint, rb, rj, P),
                           impact_speed, P)
    c_d, friction = _friction(structure, kin.sliding, normal.normal, P)
    (nx, ny), (tx, ty) = kin.normal, kin.tangent
    terms = ContactTerms(
        clearance=clearance,
        stiffness=normal.stiffness,
        eccentricity=kin.eccentricity,
        penetration=kin.penetration,
        penetration_rate=kin.rate,
        sliding_speed=kin.sliding,
        damping_factor=normal.damping_factor,
        normal_force=normal.normal,
        friction_factor=c_d,
        friction_force=friction,
        force_x=-normal.normal * nx + friction * tx,
        force_y=-normal.normal * ny + friction * ty,
        elastic_force=normal.elastic,
        potential=normal.potential,
        # The elastic part F_e(d) d' is stored in the potential; the rest of the normal force
        # (hysteresis damping, clipped at zero) and all of friction take energy out.
        dissipation=(normal.normal - normal.elastic) * kin.rate - friction * kin.sliding,
    )
    if structure.lubrication:
        add_film(terms, structure.lubrication, joint, ex, ey, vx, vy, omega_bearing,
                 omega_journal, P)
    return terms


def _hertz_stiffness(joint: int, rb: sp.Expr, rj: sp.Expr, P: Callable[[str], sp.Symbol]
                     ) -> sp.Expr:
    """The pin-in-hole K = 4 / (3 (sb + sj)) sqrt(Rb Rj / (Rb - Rj)), s = (1 - nu^2)/E."""
    sigma_b = (1 - P(f"joint{joint}.bearing_nu") ** 2) / P(f"joint{joint}.bearing_E")
    sigma_j = (1 - P(f"joint{joint}.journal_nu") ** 2) / P(f"joint{joint}.journal_E")
    return sp.Rational(4, 3) / (sigma_b + sigma_j) * sp.sqrt(rb * rj / (rb - rj))


def _kinematics(ex: Any, ey: Any, vx: Any, vy: Any, clearance: sp.Expr, rb: sp.Expr,
                rj: sp.Expr, omega_bearing: sp.Expr, omega_journal: sp.Expr) -> _Kinematics:
    ecc = sp.sqrt(sp.Max(ex**2 + ey**2, (ECCENTRICITY_FLOOR * clearance) ** 2))
    nx, ny = ex / ecc, ey / ecc
    tx, ty = -ny, nx
    # Contact points: bearing centre + Rb n (on link i-1), journal centre + Rj n (on link i).
    sliding = tx * vx + ty * vy + omega_journal * rj - omega_bearing * rb
    return _Kinematics(eccentricity=ecc, penetration=ecc - clearance, normal=(nx, ny),
                       tangent=(tx, ty), rate=nx * vx + ny * vy, sliding=sliding)


def _normal_force(structure: Structure, joint: int, kin: _Kinematics, hertz: sp.Expr,
                  impact_speed: sp.Symbol, P: Callable[[str], sp.Symbol]) -> _NormalForce:
    """The elastic law (Hertz's K d+^n, or a cylindrical law) with its damping."""
    if structure.contact_law is None:
        raise ValueError("contact terms asked of a structure without clearance")
    x_ce = damping_factor(structure.contact_law, P("contact.restitution"))
    approach = sp.Max(impact_speed, P("contact.impact_speed_floor"))
    kind = structure.contact_stiffness
    if kind is None:
        n_exp = P("contact.exponent")
        stiffness = hertz
        elastic = stiffness * penetration_power(kin.penetration, n_exp)
        potential = stiffness * penetration_power(kin.penetration, n_exp + 1) / (n_exp + 1)
    else:
        law = cylindrical.elastic_law(kind, kin.penetration, joint, P)
        elastic, potential, stiffness = law.force, law.potential, law.stiffness
    # The damping is proportional to the elastic force, chi(d) = x F_e(d) / v-, for every
    # elastic law: see "Damping with any elastic law" in the module docstring.
    normal = sp.Max(elastic * (1 + x_ce * kin.rate / approach), 0)
    return _NormalForce(damping_factor=x_ce, stiffness=stiffness, elastic=elastic,
                        potential=potential, normal=normal)


def _friction(structure: Structure, sliding: sp.Expr, normal: sp.Expr,
              P: Callable[[str], sp.Symbol]) -> tuple[sp.Expr, sp.Expr]:
    """The dynamic correction c_d(|v_t|) and the friction force F_t (both 0 without
    friction)."""
    if structure.friction_ramp is None:
        return sp.Integer(0), sp.Integer(0)
    v0, v1 = P("friction.v0"), P("friction.v1")
    c_d = friction_ramp(structure.friction_ramp, sp.Abs(sliding), v0, v1)
    friction = -P("friction.mu") * c_d * normal * friction_direction(sliding, v0, v1)
    return c_d, friction


def add_film(terms: ContactTerms, model: str, joint: int, ex: Any, ey: Any, vx: Any, vy: Any,
             omega_bearing: sp.Expr, omega_journal: sp.Expr,
             P: Callable[[str], sp.Symbol]) -> None:
    """Add the hydrodynamic film of a lubricated joint (see :mod:`.lubrication`) to the dry
    contact: its force to the total force, the power it takes out to the dissipation."""
    from jointplay.derive.lubrication import film_terms

    film = film_terms(model, ex=ex, ey=ey, vx=vx, vy=vy, ecc=terms.eccentricity,
                      clearance=terms.clearance, omega_bearing=omega_bearing,
                      omega_journal=omega_journal, viscosity=P("lubrication.viscosity"),
                      radius=P(f"joint{joint}.journal_radius"), length=P(f"joint{joint}.length"),
                      transition=P("lubrication.transition"))
    terms.film = film
    terms.force_x = terms.force_x + film.force_x
    terms.force_y = terms.force_y + film.force_y
    terms.dissipation = terms.dissipation - film.power
