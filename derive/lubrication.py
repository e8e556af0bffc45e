"""Hydrodynamic film forces of a lubricated revolute clearance joint (short and long bearing).

The laws are the closed forms of Pinkus and Sternlicht (Theory of Hydrodynamic Lubrication,
McGraw-Hill, 1961) for a journal of radius R and length L in a bearing of radial clearance c,
as used for lubricated revolute joints in multibody dynamics by Flores, Ambrosio, Claro and
Lankarani (Flores et al., "Lubricated revolute joints in rigid multibody systems", Nonlinear
Dyn. 56:277-295, 2009; Flores, Ambrosio, Claro, "Dynamics of multibody systems with spherical
and revolute clearance joints with lubrication", 2006). With the eccentricity ratio eps = |e|/c,
its rate eps', the angle gamma of the line of centres and the journal and bearing angular
speeds w_j, w_b (w = w_j + w_b, the sum of the surface speeds over R), the force on the journal
along the line of centres (r) and across it (t) is

  short bearing (L/D small; Ocvirk's solution of Reynolds' equation, pi-film):
    F_r = -(mu R L^3 / (2 c^2)) [2 eps^2 (w - 2 gamma') / (1 - eps^2)^2
                                 + pi (1 + 2 eps^2) eps' / (1 - eps^2)^(5/2)]
    F_t =  (mu R L^3 / (2 c^2)) [pi eps (w - 2 gamma') / (2 (1 - eps^2)^(3/2))
                                 + 4 eps eps' / (1 - eps^2)^2]
  long bearing (L/D large; Sommerfeld's solution, pi-film):
    F_r = -(12 mu R^3 L / c^2) [eps^2 (w - 2 gamma') / ((2 + eps^2)(1 - eps^2))
                                + eps' (pi/2 - 8 / (pi (2 + eps^2))) / (1 - eps^2)^(3/2)]
    F_t =  (12 mu R^3 L / c^2) [pi eps (w - 2 gamma') / (2 (2 + eps^2) (1 - eps^2)^(1/2))
                                + 2 eps eps' / ((2 + eps^2)(1 - eps^2))]

(both rederived here from Reynolds' equation over the half film upstream of the narrowest
gap, with the pressure zero at its ends; the tests integrate that pressure numerically).

Written with the velocity v = e' - w/2 z x e of the journal centre seen from the frame turning
at the mean surface speed w/2 (v_r = c eps', v_t = c eps (gamma' - w/2)), both theories are one
symmetric, positive definite film damping matrix in the (r, t) frame:

    F = -C Xi(eps) v,   Xi = [[a, beta], [beta, b]],
    short: C = mu R L^3 / (2 c^3), a = pi (1 + 2 eps^2) / (1 - eps^2)^(5/2),
           b = pi / (1 - eps^2)^(3/2), beta = -4 eps / (1 - eps^2)^2;
    long:  C = 12 mu R^3 L / c^3, a = (pi/2 - 8 / (pi (2 + eps^2))) / (1 - eps^2)^(3/2),
           b = pi / ((2 + eps^2)(1 - eps^2)^(1/2)), beta = -2 eps / ((2 + eps^2)(1 - eps^2)).

So the film dissipates D = C v.Xi.v >= 0 (a b > beta^2 for every eps < 1). The mechanical
power F . e' that the film exchanges with the links differs from -D by (w/2) e F_t, the power
fed in through the surfaces' rotation (the film's shear torque, which these theories and the
multibody literature leave out); the energy balance of a run books F . e' exactly.

Two regularisations, both stated and tested:

* Film closing (eps -> 1, where every coefficient is singular). The coefficients are evaluated
  at eps* = sat(eps), equal to eps up to ``lubrication.transition`` = eps_t, then bending C1 to
  the constant (1 + eps_t)/2 reached at eps = 1 (sat = eps_t + s - s^2 / (2 (1 - eps_t)),
  s = clip(eps - eps_t, 0, 1 - eps_t)). Beyond eps_t the film keeps its last coefficients (finite,
  with finite derivatives); from eps = 1 the dry contact law (penetration |e| - c > 0) carries
  the load, with the film acting on as a bounded squeeze damper: the transition to dry contact.
* The centre (eps -> 0). A pi-film has an orientation even at zero eccentricity: the long
  bearing's a(0) != b(0), so Xi's (r, t) frame would make the force jump as e crosses 0. The
  anisotropic part (a - b) r r^T is faded in as s^2 (3 - 2 s), s = min(eps / eps_0, 1),
  eps_0 = ISOTROPY_RADIUS = 0.01: the law is exact from eps = 0.01 on, and below it the force
  is C1 in e (s^2 r r^T = e e^T / (eps_0 c)^2). Xi stays positive definite (the fade only
  shrinks a - b, which is negative there).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import sympy as sp

MODELS = ("short-bearing", "long-bearing")
# Below this eccentricity ratio the pi-film's orientation is faded out (see module docstring).
ISOTROPY_RADIUS = sp.Rational(1, 100)


@dataclass
class FilmTerms:
    eccentricity_ratio: sp.Expr  # eps* after the film-closing saturation
    force_x: sp.Expr  # film force on the journal, N components
    force_y: sp.Expr
    power: sp.Expr  # F . e': power the film delivers to the relative motion of the journal
    dissipation: sp.Expr  # C v.Xi.v >= 0: power dissipated in the film


def saturate(eps: sp.Expr, start: sp.Expr) -> sp.Expr:
    """eps up to ``start``, then C1 to the constant (1 + start) / 2 reached at eps = 1."""
    s = sp.Min(sp.Max(eps - start, 0), 1 - start)
    return sp.Min(eps, start) + s - s**2 / (2 * (1 - start))


def film_matrix(model: str, eps: sp.Expr) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """(a, b, beta) of Xi(eps) for ``model`` (see module docstring)."""
    one = 1 - eps**2
    if model == "short-bearing":
        return (sp.pi * (1 + 2 * eps**2) / one ** sp.Rational(5, 2),
                sp.pi / one ** sp.Rational(3, 2),
                -4 * eps / one**2)
    if model == "long-bearing":
        return ((sp.pi / 2 - 8 / (sp.pi * (2 + eps**2))) / one ** sp.Rational(3, 2),
                sp.pi / ((2 + eps**2) * sp.sqrt(one)),
                -2 * eps / ((2 + eps**2) * one))
    raise ValueError(f"unknown lubrication model {model!r}")


def film_scale(model: str, viscosity: sp.Expr, radius: sp.Expr, length: sp.Expr,
               clearance: sp.Expr) -> sp.Expr:
    """C of F = -C Xi v (N s/m)."""
    if model == "short-bearing":
        return viscosity * radius * length**3 / (2 * clearance**3)
    if model == "long-bearing":
        return 12 * viscosity * radius**3 * length / clearance**3
    raise ValueError(f"unknown lubrication model {model!r}")


def film_terms(model: str, *, ex: Any, ey: Any, vx: Any, vy: Any, ecc: sp.Expr,
               clearance: sp.Expr, omega_bearing: sp.Expr, omega_journal: sp.Expr,
               viscosity: sp.Expr, radius: sp.Expr, length: sp.Expr,
               transition: sp.Expr) -> FilmTerms:
    """The film force on the journal of one joint; ``ecc`` is |e| floored as in the dry law."""
    eps = saturate(ecc / clearance, transition)
    a, b, beta = film_matrix(model, eps)
    scale = film_scale(model, viscosity, radius, length, clearance)
    mean_speed = (omega_bearing + omega_journal) / 2
    # Velocity of the journal centre relative to the frame turning at the mean surface speed.
    wx, wy = vx + mean_speed * ey, vy - mean_speed * ex
    nx, ny = ex / ecc, ey / ecc
    tx, ty = -ny, nx
    w_r = nx * wx + ny * wy
    w_t = tx * wx + ty * wy
    near = sp.Min(ecc / (ISOTROPY_RADIUS * clearance), 1)
    fade = near**2 * (3 - 2 * near)
    # Xi v in N components: b v + (a - b) (r.v) r + beta ((t.v) r + (r.v) t)
    fx = -scale * (b * wx + (a - b) * fade * w_r * nx + beta * (w_t * nx + w_r * tx))
    fy = -scale * (b * wy + (a - b) * fade * w_r * ny + beta * (w_t * ny + w_r * ty))
    return FilmTerms(eccentricity_ratio=eps, force_x=fx, force_y=fy,
                     power=fx * vx + fy * vy, dissipation=-(fx * wx + fy * wy))
