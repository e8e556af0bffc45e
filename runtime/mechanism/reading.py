"""Mechanism files: read a TOML file of data, validate every field, never execute anything.

A mechanism file is a scene: ``name``, ``description``, a ``[mechanism]`` table (bodies,
joints, driver, gravity, contact, friction) and a ``[run]`` table. Every error of a file is
reported at once, each naming the field and what is allowed (exit status 2 from the command
line). The format is documented in docs/reference/mechanism-file.md.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from jointplay.common.errors import DescriptionError
from jointplay.common.hints import did_you_mean
from jointplay.common.validation import (
    Problems,
    check_keys,
    number,
    plausible,
    positive,
    read_toml,
)
from jointplay.mechanism.description import (
    Body,
    Driver,
    Force,
    Joint,
    Mechanism,
    MechanismScene,
    RunSettings,
)

GROUND = "ground"
_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9_]{0,39}$")
_TOP = ("name", "description", "mechanism", "initial", "output", "run")
_MECHANISM = ("bodies", "joints", "driver", "gravity", "contact", "friction", "torques",
              "forces")
_FORCE = ("name", "body", "at", "x", "y")
_BODY = ("name", "mass", "inertia", "com")
_JOINT = ("name", "type", "kind", "parent", "child", "at_parent", "at_child", "axis", "angle",
          "bearing_radius", "journal_radius", "bearing_E", "bearing_nu", "journal_E",
          "journal_nu")
_DRIVER = ("joint", "speed", "start", "angle")
_GRAVITY = ("enabled", "vector")
_CONTACT = ("law", "exponent", "restitution", "impact_speed_floor")
_FRICTION = ("law", "ramp", "mu", "v0", "v1")
_OUTPUT = ("coordinate",)
_RUN = ("t_end", "output_step", "rtol", "atol", "max_steps", "integrator", "step")
CONTACT_LAWS = ("lankarani-nikravesh", "hunt-crossley", "gonthier", "flores")
KINDS = ("ideal", "clearance", "locked")


def is_mechanism_file(path: str | Path) -> bool:
    """Whether a scene file describes a mechanism (it has a ``[mechanism]`` table)."""
    try:
        data, _ = read_toml(path, "scene")
    except DescriptionError:
        return False
    return isinstance(data.get("mechanism"), Mapping)


def load_mechanism_scene(path: str | Path) -> MechanismScene:
    """Read and validate a mechanism file.

    Parameters
    ----------
    path : str or pathlib.Path
        The mechanism file (TOML, read as data, never executed).

    Returns
    -------
    MechanismScene
        The mechanism and its run settings.

    Raises
    ------
    DescriptionError
        Naming every bad field and its fix.

    Examples
    --------
    >>> from importlib.resources import files
    >>> import jointplay
    >>> scene = jointplay.load_mechanism_scene(files("jointplay.scenes") / "slider_crank.toml")
    >>> scene.name, scene.output_coordinate
    ('slider_crank', 'guide.position')
    """
    data, _ = read_toml(path, "mechanism")
    return mechanism_scene_from_dict(data, source=str(path))


def mechanism_scene_from_dict(data: Mapping[str, Any], source: str | None = None
                              ) -> MechanismScene:
    problems = Problems()
    with problems.check():
        check_keys(data, _TOP, "", source)
    name = data.get("name", "mechanism")
    with problems.check():
        if not isinstance(name, str) or not _NAME.match(name):
            raise DescriptionError("name", "must be letters, digits and '_' (at most 40), "
                                   f"starting with a letter, got {name!r}")
    table: Mapping[str, Any] = {}
    if isinstance(data.get("mechanism"), Mapping):
        table = data["mechanism"]
    else:
        problems.found.append(DescriptionError(
            "mechanism", "a mechanism file needs a [mechanism] table with [[mechanism.bodies]]"
            " and [[mechanism.joints]]"))
    with problems.check():
        check_keys(table, _MECHANISM, "mechanism")
    bodies = _bodies(table.get("bodies"), problems)
    # Cross-references are checked against every name given, valid or not, so that one
    # mistake is reported once.
    joints = _joints(table.get("joints"), _names(table.get("bodies")), problems)
    gravity = _gravity(table.get("gravity", {}), problems)
    contact = _section(table.get("contact", {}), _CONTACT, "mechanism.contact", problems)
    friction = _section(table.get("friction", {}), _FRICTION, "mechanism.friction", problems)
    driver = _driver(table.get("driver"), joints, _names(table.get("joints")), problems)
    torques = _torques(table.get("torques", {}), joints, driver, problems)
    forces = _forces(table.get("forces", []), _names(table.get("bodies")),
                     _names(table.get("bodies")) | _names(table.get("joints")), problems)
    run = _run(data.get("run", {}), problems)
    problems.raise_any(source)
    mechanism = Mechanism(
        name=name, bodies=tuple(bodies), joints=tuple(joints), driver=driver,
        gravity=gravity, contact_law=str(contact.get("law", "lankarani-nikravesh")),
        exponent=float(contact.get("exponent", 1.5)),
        restitution=float(contact.get("restitution", 0.9)),
        impact_speed_floor=float(contact.get("impact_speed_floor", 1.0e-3)),
        friction_law=str(friction.get("law", "coulomb")),
        friction_ramp=str(friction.get("ramp", "linear")),
        mu=float(friction.get("mu", 0.05)), v0=float(friction.get("v0", 1.0e-4)),
        v1=float(friction.get("v1", 1.0e-2)), torques=torques, forces=forces)
    try:
        mechanism.check()
    except DescriptionError as err:
        raise err.with_source(source) from None
    description = data.get("description", "")
    initial = _initial(data.get("initial", {}), mechanism, source)
    output = _output(data.get("output", {}), mechanism, source)
    return MechanismScene(name=name, description=str(description), mechanism=mechanism,
                          run=run, source=source, initial=initial, output=output)


def _output(table: Any, mechanism: Mechanism, source: str | None) -> str | None:
    """The coordinate the run follows, by name (None: jointplay.mechanism.output's rule)."""
    from jointplay.mechanism.structure import CLOCK, coordinates

    check_keys(table, _OUTPUT, "output", source)
    if "coordinate" not in table:
        return None
    name = table["coordinate"]
    names = [c.name for c in coordinates(mechanism.structure()) if c.name != CLOCK]
    if not isinstance(name, str) or name not in names:
        raise DescriptionError(
            "output.coordinate", f"must name one of the mechanism's coordinates "
            f"({', '.join(names) or 'none'}), got {name!r}"
            f"{did_you_mean(str(name), names)}", source)
    return name


def _initial(table: Any, mechanism: Mechanism, source: str | None) -> dict[str, float]:
    """Where the assembly at t = 0 starts looking: coordinates by name (rad, m)."""
    from jointplay.mechanism.structure import CLOCK, coordinates

    if isinstance(table, Mapping):  # `crank_pin.angle = 1.0` is a dotted key: a nested table
        table = {f"{key}.{inner}" if isinstance(value, Mapping) else key: v
                 for key, value in table.items()
                 for inner, v in (value.items() if isinstance(value, Mapping)
                                  else [(None, value)])}
    check_keys(table, [c.name for c in coordinates(mechanism.structure())
                       if c.name != CLOCK] or ["(none)"], "initial", source)
    out = {}
    for key, value in table.items():
        out[key] = number(value, f"initial.{key}")
        if not math.isfinite(out[key]):
            raise DescriptionError(f"initial.{key}", "must be finite", source)
    return out


def _names(tables: Any) -> set[str]:
    if not isinstance(tables, list):
        return set()
    return {str(t["name"]) for t in tables if isinstance(t, Mapping) and "name" in t}


def _list(value: Any, where: str, problems: Problems) -> list[Mapping[str, Any]]:
    if not isinstance(value, list) or not value:
        problems.found.append(DescriptionError(
            where, f"must be one or more [[{where}]] tables"))
        return []
    return value


def _vector(value: Any, where: str, default: tuple[float, float] | None = None
            ) -> tuple[float, float]:
    if value is None and default is not None:
        return default
    if not isinstance(value, list) or len(value) != 2:
        raise DescriptionError(where, f"must be a pair of numbers [x, y] in metres, got "
                               f"{value!r}")
    x, y = (number(v, where) for v in value)
    if not (math.isfinite(x) and math.isfinite(y)):
        raise DescriptionError(where, f"must be finite, got {value!r}")
    return x, y


def _name(table: Mapping[str, Any], where: str, seen: set[str]) -> str:
    name = table.get("name")
    if not isinstance(name, str) or not _NAME.match(name) or name in (GROUND, "t", "driver",
                                                                         "gravity", "contact",
                                                                         "friction"):
        raise DescriptionError(f"{where}.name", "must be a name of letters, digits and '_' "
                               "starting with a letter (not 'ground', 't', 'driver', "
                               f"'gravity', 'contact', 'friction'), got {name!r}")
    if name in seen:
        raise DescriptionError(f"{where}.name", f"{name!r} is used twice; names must differ")
    seen.add(name)
    return name


def _bodies(value: Any, problems: Problems) -> list[Body]:
    out: list[Body] = []
    seen: set[str] = set()
    for i, table in enumerate(_list(value, "mechanism.bodies", problems), start=1):
        where = f"mechanism.bodies[{i}]"
        with problems.check():
            check_keys(table, _BODY, where)
            name = _name(table, where, seen)
            for key in ("mass", "inertia"):
                if key not in table:
                    raise DescriptionError(f"{where}.{key}", "is required (kg; kg m^2 about "
                                           "the centre of mass)")
            mass, inertia = number(table["mass"], f"{where}.mass"), \
                number(table["inertia"], f"{where}.inertia")
            plausible(f"{where}.mass", mass, "link.mass")
            plausible(f"{where}.inertia", inertia, "link.inertia")
            com = _vector(table.get("com"), f"{where}.com", (0.0, 0.0))
            out.append(Body(name=name, mass=mass, inertia=inertia, com=com))
    return out


def _joints(value: Any, bodies: set[str], problems: Problems) -> list[Joint]:
    out: list[Joint] = []
    seen: set[str] = set()
    for i, table in enumerate(_list(value, "mechanism.joints", problems), start=1):
        where = f"mechanism.joints[{i}]"
        with problems.check():
            out.append(_joint(table, where, bodies, seen))
    return out


def _joint(table: Any, where: str, bodies: set[str], seen: set[str]) -> Joint:
    check_keys(table, _JOINT, where)
    name = _name(table, where, seen)
    jtype = table.get("type", "revolute")
    if jtype not in ("revolute", "prismatic"):
        raise DescriptionError(f"{where}.type", f"must be 'revolute' or 'prismatic', got "
                               f"{jtype!r}")
    kind = table.get("kind", "ideal")
    if kind not in KINDS:
        raise DescriptionError(f"{where}.kind", f"must be one of {', '.join(KINDS)}, got "
                               f"{kind!r}")
    if jtype == "prismatic" and kind != "ideal":
        raise DescriptionError(f"{where}.kind", "a prismatic joint is ideal; clearance and "
                               "locking are revolute joints' kinds (drop 'kind')")
    ends = {}
    for key in ("parent", "child"):
        body = table.get(key)
        allowed = bodies | {GROUND}
        if body not in allowed:
            from jointplay.common.hints import did_you_mean

            raise DescriptionError(f"{where}.{key}", f"must name a body or 'ground' (bodies: "
                                   f"{', '.join(sorted(bodies))}), got {body!r}"
                                   f"{did_you_mean(str(body), sorted(allowed))}")
        ends[key] = body
    if ends["parent"] == ends["child"]:
        raise DescriptionError(f"{where}.child", "must differ from the parent")
    if ends["child"] == GROUND:
        raise DescriptionError(f"{where}.child", "the ground is a parent only; swap parent "
                               "and child")
    at_parent = _vector(table.get("at_parent"), f"{where}.at_parent", (0.0, 0.0))
    at_child = _vector(table.get("at_child"), f"{where}.at_child", (0.0, 0.0))
    angle = number(table.get("angle", 0.0), f"{where}.angle")
    plausible(f"{where}.angle", angle, "joint.angle")
    axis = (1.0, 0.0)
    if jtype == "prismatic":
        ax, ay = _vector(table.get("axis"), f"{where}.axis", (1.0, 0.0))
        norm = math.hypot(ax, ay)
        if norm == 0.0:
            raise DescriptionError(f"{where}.axis", "must be a nonzero direction, e.g. [1, 0]")
        axis = (ax / norm, ay / norm)
    elif "axis" in table:
        raise DescriptionError(f"{where}.axis", "belongs to prismatic joints only; drop it")
    clearance: dict[str, float] = {}
    present = [k for k in _JOINT[9:] if k in table]
    if kind == "clearance":
        defaults = {"bearing_radius": 10.0e-3, "journal_radius": 9.97e-3, "bearing_E": 207e9,
                    "bearing_nu": 0.3, "journal_E": 207e9, "journal_nu": 0.3}
        for key, default in defaults.items():
            value = number(table.get(key, default), f"{where}.{key}")
            if key.endswith("radius"):
                plausible(f"{where}.{key}", value, "joint.radius")
            elif key.endswith("_E"):
                plausible(f"{where}.{key}", value, "joint.E")
            elif not 0.0 <= value < 0.5:
                raise DescriptionError(f"{where}.{key}", f"must be in [0, 0.5), got {value!r}")
            clearance[key] = value
        from jointplay.common.limits import MIN_RADIAL_CLEARANCE

        if clearance["bearing_radius"] - clearance["journal_radius"] < MIN_RADIAL_CLEARANCE:
            raise DescriptionError(f"{where}.journal_radius", "must be smaller than "
                                   "bearing_radius by at least a nanometre (a joint without "
                                   "play is kind = \"ideal\")")
    elif present:
        raise DescriptionError(f"{where}.{present[0]}", "belongs to kind = \"clearance\" "
                               "only; drop it or make the joint a clearance joint")
    return Joint(name=name, type=jtype, kind=kind, parent=ends["parent"], child=ends["child"],
                 at_parent=at_parent, at_child=at_child, angle=angle, axis=axis,
                 clearance=clearance)


def _gravity(table: Any, problems: Problems) -> tuple[float, float] | None:
    with problems.check():
        check_keys(table, _GRAVITY, "mechanism.gravity")
        enabled = table.get("enabled", True)
        if not isinstance(enabled, bool):
            raise DescriptionError("mechanism.gravity.enabled", "must be true or false")
        vector = _vector(table.get("vector"), "mechanism.gravity.vector", (0.0, -9.81))
        for value in vector:
            plausible("mechanism.gravity.vector", value, "gravity")
        return vector if enabled else None
    return None


def _section(table: Any, keys: tuple[str, ...], where: str, problems: Problems
             ) -> dict[str, Any]:
    out: dict[str, Any] = {}
    with problems.check():
        check_keys(table, keys, where)
        for key, value in table.items():
            if key in ("law", "ramp"):
                out[key] = _choice(value, key, where)
            else:
                out[key] = number(value, f"{where}.{key}")
                kind = {"exponent": "contact.exponent",
                        "impact_speed_floor": "contact.impact_speed_floor",
                        "mu": "friction.mu", "v0": "friction.v0", "v1": "friction.v1"}.get(key)
                if kind:
                    plausible(f"{where}.{key}", out[key], kind)
        if "restitution" in out and not 1e-3 <= out["restitution"] <= 1.0:
            raise DescriptionError(f"{where}.restitution", f"must be in [0.001, 1], got "
                                   f"{out['restitution']!r}")
        if where.endswith("friction") and out.get("v1", 1e-2) <= out.get("v0", 1e-4):
            raise DescriptionError(f"{where}.v1", "must be larger than v0")
    return out


def _choice(value: Any, key: str, where: str) -> str:
    allowed = {("law", "mechanism.contact"): CONTACT_LAWS,
               ("law", "mechanism.friction"): ("none", "coulomb"),
               ("ramp", "mechanism.friction"): ("linear", "smooth")}[(key, where)]
    if value not in allowed:
        raise DescriptionError(f"{where}.{key}", f"must be one of {', '.join(allowed)}, got "
                               f"{value!r}")
    return str(value)


def _driver(table: Any, joints: list[Joint], given: set[str], problems: Problems
            ) -> Driver | None:
    if table is None:
        return None
    with problems.check():
        check_keys(table, _DRIVER, "mechanism.driver")
        joint = table.get("joint")
        names = [j.name for j in joints]
        found = next((j for j in joints if j.name == joint), None)
        if found is None and joint in given:  # that joint's own error is reported
            return None
        if found is None:
            raise DescriptionError("mechanism.driver.joint", f"must name a joint (joints: "
                                   f"{', '.join(names)}), got {joint!r}")
        if found.type != "revolute" or found.kind != "ideal":
            raise DescriptionError("mechanism.driver.joint", f"{joint!r} is a {found.type} "
                                   f"joint of kind {found.kind!r}; a driver turns an ideal "
                                   "revolute joint")
        if ("angle" in table) == ("speed" in table):
            raise DescriptionError("mechanism.driver", "give either speed (rad/s, with start "
                                   "in rad) or angle (an expression of t, rad), not both")
        if "angle" in table:
            if "start" in table:
                raise DescriptionError("mechanism.driver.start", "belongs to speed; an angle "
                                       "expression holds its own start")
            from jointplay.scene.expressions import parse_expression

            text = table["angle"]
            parse_expression(text, field="mechanism.driver.angle")
            return Driver(joint=str(joint), angle=str(text), speed=0.0, start=0.0)
        speed = number(table["speed"], "mechanism.driver.speed")
        start = number(table.get("start", 0.0), "mechanism.driver.start")
        plausible("mechanism.driver.speed", speed, "initial.speed")
        plausible("mechanism.driver.start", start, "initial.angle")
        return Driver(joint=str(joint), angle=None, speed=speed, start=start)
    return None


def _torques(table: Any, joints: list[Joint], driver: Driver | None, problems: Problems
             ) -> tuple[tuple[str, str], ...]:
    """Applied torques: a joint's name to an expression of t (N m)."""
    from jointplay.scene.expressions import parse_expression

    out: list[tuple[str, str]] = []
    with problems.check():
        names = [j.name for j in joints if j.type == "revolute" and j.kind == "ideal"
                 and (driver is None or j.name != driver.joint)]
        check_keys(table, names or ["(none: no ideal revolute joint without the driver)"],
                   "mechanism.torques")
    for name, text in (table.items() if isinstance(table, Mapping) else []):
        with problems.check():
            parse_expression(text, field=f"mechanism.torques.{name}")
            out.append((str(name), str(text)))
    return tuple(out)


def _forces(value: Any, bodies: set[str], taken: set[str], problems: Problems
            ) -> tuple[Force, ...]:
    """Applied forces: [[mechanism.forces]] tables (a name, a body, a point, x and y)."""
    from jointplay.scene.expressions import parse_expression

    if not isinstance(value, list):
        problems.found.append(DescriptionError("mechanism.forces", "must be [[mechanism."
                                               "forces]] tables"))
        return ()
    out: list[Force] = []
    seen = set(taken)
    for i, table in enumerate(value, start=1):
        where = f"mechanism.forces[{i}]"
        with problems.check():
            check_keys(table, _FORCE, where)
            name = _name(table, where, seen)
            body = table.get("body")
            if body not in bodies:
                raise DescriptionError(f"{where}.body", f"must name a body (bodies: "
                                       f"{', '.join(sorted(bodies))}), got {body!r}")
            texts = []
            for axis in ("x", "y"):
                text = table.get(axis, "0")
                parse_expression(text, field=f"{where}.{axis}")
                texts.append(str(text))
            at = _vector(table.get("at"), f"{where}.at", (0.0, 0.0))
            out.append(Force(name=name, body=str(body), at=at, x=texts[0], y=texts[1]))
    return tuple(out)


def _run(table: Any, problems: Problems) -> RunSettings:
    values: dict[str, float] = {}
    defaults = RunSettings()
    integrator = defaults.integrator
    with problems.check():
        check_keys(table, _RUN, "run")
        for key in _RUN:
            if key == "integrator" and key in table:
                integrator = str(table[key])
            elif key in table:
                values[key] = number(table[key], f"run.{key}")
                positive(f"run.{key}", values[key])
    run = RunSettings(t_end=values.get("t_end", defaults.t_end),
                      output_step=values.get("output_step", defaults.output_step),
                      rtol=values.get("rtol", defaults.rtol),
                      atol=values.get("atol", defaults.atol),
                      max_steps=int(values.get("max_steps", defaults.max_steps)),
                      integrator=integrator, step=values.get("step", defaults.step))
    with problems.check():
        run.check()
    return run
