"""``jointplay inspect`` on a mechanism file: its tree, cut joints, coordinates, parameters
and the form of its equations, as text or Markdown."""

from __future__ import annotations

from jointplay.mechanism.description import MechanismScene
from jointplay.mechanism.structure import coordinates, parameter_names

EQUATIONS = (
    "M(q) q'' = Q_gravity(q, t) + Q_loads(q, t) + sum over cut joints of J_journal^T F "
    "- J_bearing^T F (+ friction moments Rj Ft, -Rb Ft) - bias(q, q', t)",
    "F: the clearance joint's law at e = journal centre - bearing centre (the serial arms' "
    "laws: Hertz pin-in-hole stiffness, damping by contact.law, modified Coulomb friction)",
    "driving torque = the driven joint's row of d'Alembert's principle at the computed q''",
)


def render(scene: MechanismScene, fmt: str = "text") -> str:
    mechanism = scene.mechanism
    structure = mechanism.structure()
    values = mechanism.parameter_values()
    md = fmt == "markdown"
    lines = [f"# {scene.name}" if md else f"mechanism {scene.name}: {scene.description}", ""]
    lines.append("## Joints" if md else "joints (tree order, then the cut joints):")
    for joint in structure.joints:
        role = ("cut: a force element" if joint.cut else
                "driven" if joint.driven else "tree")
        lines.append(f"{'- ' if md else '  '}{joint.name}: {joint.type} {joint.kind}, "
                     f"{joint.parent} -> {joint.child} ({role})")
    if mechanism.driver is not None:
        law = (mechanism.driver.angle if mechanism.driver.angle is not None else
               f"{mechanism.driver.start:g} + {mechanism.driver.speed:g}*t")
        lines.append(f"{'- ' if md else '  '}driver angle of {mechanism.driver.joint}: {law} "
                     "(rad)")
    for joint_name, text in mechanism.torques:
        lines.append(f"{'- ' if md else '  '}torque across {joint_name}: {text} (N m)")
    for force in mechanism.forces:
        lines.append(f"{'- ' if md else '  '}force {force.name} on {force.body} at "
                     f"({force.at[0]:g}, {force.at[1]:g}) m: ({force.x}, {force.y}) (N)")
    lines += ["", "## Coordinates" if md else "coordinates:"]
    for c in coordinates(structure):
        lines.append(f"{'- ' if md else '  '}{c.name} [{c.unit}]")
    source = "the file's [output]" if scene.output else "the default rule"
    lines.append(f"{'- ' if md else '  '}output (what the summary and the figures follow, "
                 f"{source}): {scene.output_coordinate}")
    lines += ["", "## Parameters" if md else "parameters (runtime inputs; never recompile):"]
    for name in parameter_names(structure):
        lines.append(f"{'- ' if md else '  '}{name} = {values[name]:.6g}")
    lines += ["", "## Equations" if md else "equations:"]
    lines += [f"{'- ' if md else '  '}{line}" for line in EQUATIONS]
    return "\n".join(lines) + "\n"
