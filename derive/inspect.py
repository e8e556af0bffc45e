"""Human-readable views of a derived model: plain text, LaTeX, and Markdown that renders."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import sympy as sp
from sympy.physics import mechanics as me

from jointplay.derive.symbolic import SymbolicModel

FORMATS = ("text", "latex", "markdown")
_TABLE_SECTIONS = ("Coordinates", "Parameters", "Inputs")


def _simplifier(simplify: bool) -> Callable[[sp.Expr], sp.Expr]:
    # trigsimp turns sums of products of sines into cosines of angle differences; it takes
    # ~15 s for the 4-link robot's mass matrix, so it is asked for, never implied.
    return sp.trigsimp if simplify else (lambda e: e)


def sections(model: SymbolicModel, simplify: bool = False) -> list[tuple[str, list[Any]]]:
    """(title, rows) pairs; a row is (label, sympy expression or text, note)."""
    simp = _simplifier(simplify)
    coords = [(c.name, q, f"[{c.unit}] {c.doc}")
              for c, q in zip(model.coordinates, model.q, strict=True)]
    params = [(p.name, sym, f"[{p.unit}] {p.doc}")
              for p, sym in zip(model.parameters, model.parameter_symbols, strict=True)]
    inputs = [(f"tau{j}", t, f"[N m] drive torque of joint {j}")
              for j, t in zip(model.torque_joints, model.torques, strict=True)]
    inputs += [(f"v_imp{c.index}", c.impact_speed,
                f"[m/s] normal approach speed at the onset of joint {c.index}'s impact")
               for c in model.clearance]
    n = model.n_coordinates
    assert model.mass_matrix is not None and model.forcing is not None, \
        "the equations are shown for models derived in closed form"
    mass = [(f"M[{i + 1},{j + 1}]", simp(model.mass_matrix[i, j]), "")
            for i in range(n) for j in range(i, n) if model.mass_matrix[i, j] != 0]
    forcing = [(f"f[{i + 1}] ({model.coordinates[i].name})", simp(model.forcing[i]), "")
               for i in range(n)]
    out: list[tuple[str, list[Any]]] = [
        ("Coordinates (state x = [q, dq/dt]; speeds u = dq/dt)", coords),
        ("Parameters (runtime vector p, in slot order)", params),
        ("Inputs", inputs),
        ("Mass matrix M(q) (symmetric; upper triangle, non-zero entries)", mass),
        ("Forcing f(q, u): M du/dt = f", forcing),
    ]
    for c in model.clearance:
        law = c.law
        rows = [
            ("c", law.clearance, "radial clearance"),
            ("K", law.stiffness, "pin-in-hole Hertz stiffness"
             if model.structure.contact_stiffness is None else
             f"leading coefficient of {model.structure.contact_stiffness}'s law"),
            ("F_e", law.elastic_force, "elastic part of the normal force"),
            ("|e|", law.eccentricity, "eccentricity, floored far below c"),
            ("delta", law.penetration, "penetration (contact while > 0)"),
            ("delta_dot", law.penetration_rate, "normal rate"),
            ("v_t", law.sliding_speed, "sliding speed of the contact points"),
            ("x(ce)", law.damping_factor, f"damping factor, {model.structure.contact_law}"),
            ("F_n", law.normal_force, "normal force"),
            ("c_d", law.friction_factor, f"friction correction, {model.structure.friction}"),
            (str(c.force_t), law.friction_force, "friction force on the journal"),
            (str(c.force_x), law.force_x, "contact force on the journal, x"),
            (str(c.force_y), law.force_y, "contact force on the journal, y"),
            ("V_c", law.potential, "contact energy"),
        ]
        out.append((f"Contact and friction at clearance joint {c.index}", rows))
    return out


def render(model: SymbolicModel, fmt: str = "text", simplify: bool = False,
           title: str = "") -> str:
    if fmt not in FORMATS:
        raise ValueError(f"format must be one of {', '.join(FORMATS)}, got {fmt!r}")
    parts: list[str] = []
    structure = model.structure
    summary = (f"{structure.links} links, joints {list(structure.joints)}, gravity "
               f"{'on' if structure.gravity else 'off'}, contact law "
               f"{structure.contact_law}, friction {structure.friction}, drive "
               f"{'on' if structure.drive else 'off'}")
    if fmt == "markdown":
        parts.append(f"# {title or 'jointplay model'}\n\n{summary}\n")
    elif fmt == "latex":
        parts.append(f"% {title or 'jointplay model'}: {summary}")
    else:
        parts.append(f"{title or 'jointplay model'}: {summary}")
    for heading, rows in sections(model, simplify):
        if fmt == "markdown" and heading.startswith(_TABLE_SECTIONS):
            parts.append(f"\n## {heading}\n\n| name | symbol | meaning |\n|---|---|---|")
            parts += [f"| `{label}` | ${_latex(expr)}$ | {note} |" for label, expr, note in rows]
        elif fmt == "markdown":
            parts.append(f"\n## {heading}\n")
            for label, expr, note in rows:
                note_txt = f" ({note})" if note else ""
                parts.append(f"- `{label}`{note_txt}:\n\n  $$ {_latex(expr)} $$\n")
        elif fmt == "latex":
            parts.append(f"\n% {heading}\n\\begin{{align*}}")
            for label, expr, note in rows:
                comment = f"  % {note}" if note else ""
                parts.append(f"\\texttt{{{_tex_escape(label)}}} &= {_latex(expr)} \\\\{comment}")
            parts.append("\\end{align*}")
        else:
            parts.append(f"\n{heading}\n{'-' * len(heading)}")
            for label, expr, note in rows:
                note_txt = f"    # {note}" if note else ""
                parts.append(f"{label} = {me.msprint(expr)}{note_txt}")
    return "\n".join(parts) + "\n"


def _tex_escape(text: str) -> str:
    return text.replace("_", "\\_").replace("#", "\\#")


def _latex(expr: Any) -> str:
    return str(me.mlatex(expr))
