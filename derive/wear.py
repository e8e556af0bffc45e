"""What the run needs to integrate Archard wear at a clearance joint (Archard 1953).

Archard's law (J. F. Archard, "Contact and rubbing of flat surfaces", J. Appl. Phys. 24:981,
1953) gives the worn volume per sliding distance as k F_n / H; locally, the depth grows as
dh/dt = k p |v_t| / H under the contact pressure p. Its use for revolute clearance joints in
multibody systems follows Flores ("Modeling and simulation of wear in revolute clearance
joints in multibody systems", Mech. Mach. Theory 44:1211-1222, 2009).

The generated function ``wear(x, p, v_imp)`` gives, per clearance joint, what the compiled
integration loop needs to spread that rate over the bearing's and the journal's surfaces:

* the contact angle on the bearing, measured in the bearing's link frame (atan2(ey, ex) minus
  the absolute angle of link i-1), and on the journal, in the journal's link frame;
* the volume rate k F_n |v_t| / H (m^3/s), F_n the dry normal force (a lubricant film carries
  its share of the load without wear), v_t the sliding speed of the contact points;
* the contact half-angles on each surface, b / R: b = (4 F_n R* / (pi L E*))^(1/2) is the
  half-width of Hertz's line contact between cylinders (Johnson, Contact Mechanics, 1985,
  section 4.3), R* = Rb Rj / (Rb - Rj) for the conformal pair, 1/E* = sum (1 - nu^2)/E; the
  pressure across it is elliptical, p(s) = 2 F_n / (pi b L) (1 - s^2/b^2)^(1/2);
* the surface per radian of each part, R L (m^2/rad), to turn volume into depth;
* the rates of both contact angles, so that the loop can cut a step into pieces over which
  the contact moves less than half a bin.

The loop integrates these in time over each accepted step and in angle exactly over each bin
(see driver.c, wear_step).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import sympy as sp

OUTPUTS = (
    ("bearing_angle", "rad", "contact angle on the bearing, in the frame of link i-1"),
    ("journal_angle", "rad", "contact angle on the journal, in the frame of link i"),
    ("volume_rate", "m^3/s", "Archard wear volume rate k F_n |v_t| / H"),
    ("bearing_half_angle", "rad", "half-width of the Hertz line contact over Rb"),
    ("journal_half_angle", "rad", "half-width of the Hertz line contact over Rj"),
    ("bearing_area", "m^2/rad", "bearing surface per radian, Rb L"),
    ("journal_area", "m^2/rad", "journal surface per radian, Rj L"),
    ("bearing_angle_rate", "rad/s", "rate of the contact angle on the bearing"),
    ("journal_angle_rate", "rad/s", "rate of the contact angle on the journal"),
)


@dataclass
class WearTerms:
    bearing_angle: sp.Expr
    journal_angle: sp.Expr
    volume_rate: sp.Expr
    bearing_half_angle: sp.Expr
    journal_half_angle: sp.Expr
    bearing_area: sp.Expr
    journal_area: sp.Expr
    bearing_angle_rate: sp.Expr
    journal_angle_rate: sp.Expr

    def values(self) -> list[sp.Expr]:
        return [getattr(self, name) for name, _, _ in OUTPUTS]


def wear_terms(law: Any, joint: int, ex: Any, ey: Any, vx: Any, vy: Any,
               angles: tuple[sp.Expr, sp.Expr], speeds: tuple[sp.Expr, sp.Expr],
               P: Callable[[str], sp.Symbol]) -> WearTerms:
    """The wear integrands of one clearance joint (``law``: its laws.ContactTerms; angles and
    speeds: absolute angle and angular speed of the bearing's and the journal's links)."""
    rb = P(f"joint{joint}.bearing_radius")
    rj = P(f"joint{joint}.journal_radius")
    length = P(f"joint{joint}.length")
    compliance = ((1 - P(f"joint{joint}.bearing_nu") ** 2) / P(f"joint{joint}.bearing_E")
                  + (1 - P(f"joint{joint}.journal_nu") ** 2) / P(f"joint{joint}.journal_E"))
    radius = rb * rj / (rb - rj)
    force = law.normal_force
    half_width = sp.sqrt(4 * force * radius * compliance / (sp.pi * length))
    direction = sp.atan2(ey, ex)
    # d atan2(ey, ex)/dt, with |e|^2 floored as in the contact law (no wear without contact)
    direction_rate = (ex * vy - ey * vx) / law.eccentricity**2
    return WearTerms(
        bearing_angle=direction - angles[0],
        journal_angle=direction - angles[1],
        volume_rate=P("wear.coefficient") / P("wear.hardness") * force
        * sp.Abs(law.sliding_speed),
        bearing_half_angle=half_width / rb,
        journal_half_angle=half_width / rj,
        bearing_area=rb * length,
        journal_area=rj * length,
        bearing_angle_rate=direction_rate - speeds[0],
        journal_angle_rate=direction_rate - speeds[1],
    )
