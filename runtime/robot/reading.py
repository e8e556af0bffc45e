"""Robot descriptions from TOML files, parsed dictionaries and command-line flags (data only,
never executed), validated on construction."""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from jointplay.common.errors import DescriptionError
from jointplay.common.hints import did_you_mean
from jointplay.common.validation import Problems, boolean, check_keys, number, read_toml
from jointplay.robot.description import (
    MAX_LINKS,
    Contact,
    Friction,
    Gravity,
    Joint,
    Link,
    Lubrication,
    Robot,
    Wear,
    uniform_chain,
)
from jointplay.robot.structure import JOINT_KINDS
from jointplay.robot.validation import check_robot_name

_TOP_KEYS = ("name", "links", "joints", "payload", "gravity", "contact", "friction", "drive",
             "lubrication", "wear")
_LINK_KEYS = ("length", "mass", "inertia", "com")
_JOINT_KEYS = ("kind", "angle", "bearing_radius", "journal_radius", "bearing_E", "bearing_nu",
               "journal_E", "journal_nu", "length")
_FLOAT_FIELDS = {"length", "mass", "inertia", "com", "angle", "bearing_radius", "journal_radius",
                 "bearing_E", "bearing_nu", "journal_E", "journal_nu", "exponent", "restitution",
                 "impact_speed_floor", "mu", "v0", "v1", "viscosity", "transition",
                 "coefficient", "hardness"}


def _known(table: Any, allowed: tuple[str, ...], where: str, values: Problems
           ) -> Mapping[str, Any]:
    """The table's known keys; unknown ones are reported (to ``values``) and left out, so that
    the rest is still checked. A value that is not a table at all leaves nothing to check."""
    if not isinstance(table, Mapping):
        check_keys(table, allowed, where)  # raises: must be a table
    with values.check():
        check_keys(table, allowed, where)
    return {k: v for k, v in table.items() if k in allowed}


def _numbers(table: Mapping[str, Any], where: str, problems: Problems) -> dict[str, Any]:
    """The table with its numbers as floats; a value that is not a number is reported (to
    ``problems``) and read as NaN, so that the robot's own checks of every other field still
    run and all problems are reported together, as for a robot built in Python."""
    out: dict[str, Any] = {}
    for key, value in table.items():
        if key in _FLOAT_FIELDS:
            out[key] = math.nan
            with problems.check():
                out[key] = number(value, f"{where}.{key}")
        else:
            out[key] = value
    return out


def robot_from_dict(data: Mapping[str, Any], source: str | None = None) -> Robot:
    """Build a validated :class:`Robot` from a parsed robot document (a robot file's tables).

    Parameters
    ----------
    data : mapping
        The document: ``name``, ``[[links]]``, ``[[joints]]`` and the optional ``[payload]``,
        ``[gravity]``, ``[contact]``, ``[friction]``, ``[drive]``, ``[lubrication]`` and
        ``[wear]`` tables (see docs/reference/robot-file.md).
    source : str, optional
        Where the document came from, named in error messages.

    Returns
    -------
    Robot
        The robot.

    Raises
    ------
    DescriptionError
        Naming the field and the fix (several together as :class:`DescriptionErrors`).
    """
    try:
        return _robot_from_dict(data)
    except DescriptionError as err:
        raise err.with_source(source) from None


def _robot_from_dict(data: Mapping[str, Any]) -> Robot:
    if "robot" in data and isinstance(data["robot"], Mapping):
        data = data["robot"]
    # Every part is read even after one fails, so that all problems are reported together:
    # ``structure`` holds those that leave no robot to check (a missing link field, an unknown
    # joint kind), ``values`` the numbers that are not numbers (read as NaN meanwhile).
    structure, values = Problems(), Problems()
    with structure.check():
        data = _known(data, _TOP_KEYS, "", values)
    links: tuple[Link, ...] = ()
    with structure.check():
        links = _links(data, values)
    joints: tuple[Joint, ...] = ()
    with structure.check():
        joints = _joints(data, len(links) or 1, values)
    payload = data.get("payload", {})
    payload_mass = math.nan
    with structure.check():
        payload = _known(payload, ("mass",), "payload", values)
    with values.check():
        payload_mass = number(payload.get("mass", 0.0) if isinstance(payload, Mapping)
                              else 0.0, "payload.mass")
    gravity = Gravity()
    with structure.check():
        gravity = _gravity(data, values)
    tables: dict[str, Mapping[str, Any]] = {}
    with structure.check():
        tables = _option_tables(data, values)
    name = data.get("name", "robot")
    drive = True
    with structure.check():
        check_robot_name(name)
        drive = boolean(tables["drive"].get("enabled", True), "drive.enabled") \
            if tables else True
    if structure:  # unknown keys first: a misspelt key is often why another one is missing
        values.found.extend(structure.found)
        values.raise_any()
    with values.check():
        robot = Robot(
            links=links,
            joints=joints,
            name=name,
            payload_mass=payload_mass,
            gravity=gravity,
            contact=Contact(**_numbers(tables["contact"], "contact", values)),
            friction=Friction(**_numbers(tables["friction"], "friction", values)),
            drive=drive,
            lubrication=Lubrication(**_numbers(tables["lubrication"], "lubrication", values)),
            wear=Wear(**_numbers(tables["wear"], "wear", values)),
        )
    values.raise_any()
    return robot


def _links(data: Mapping[str, Any], values: Problems) -> tuple[Link, ...]:
    """The [[links]] tables, each complete."""
    raw_links = data.get("links")
    if not isinstance(raw_links, list) or not raw_links:
        raise DescriptionError("links", "must be a non-empty array of [[links]] tables "
                                        f"(1 to {MAX_LINKS} links)")
    links = []
    problems = Problems()
    for i, raw in enumerate(raw_links, start=1):
        with problems.check():
            raw = _known(raw, _LINK_KEYS, f"links[{i}]", values)
            missing = [key for key in _LINK_KEYS if key not in raw]
            if missing:
                raise DescriptionError(f"links[{i}].{missing[0]}", "is required")
            links.append(Link(**_numbers(raw, f"links[{i}]", values)))
    problems.raise_any()
    return tuple(links)


def _joints(data: Mapping[str, Any], n_links: int, values: Problems) -> tuple[Joint, ...]:
    """The [[joints]] tables (every joint ideal when there are none), each of one known kind."""
    raw_joints = data.get("joints", [{"kind": "ideal"}] * n_links)
    if not isinstance(raw_joints, list):
        raise DescriptionError("joints", "must be an array of [[joints]] tables")
    joints = []
    problems = Problems()
    for i, raw in enumerate(raw_joints, start=1):
        with problems.check():
            joints.append(_joint(i, raw, values))
    problems.raise_any()
    return tuple(joints)


def _joint(i: int, raw: Any, values: Problems) -> Joint:
    """One [[joints]] table: known keys, one known kind, numbers."""
    raw = _known(raw, _JOINT_KEYS, f"joints[{i}]", values)
    kind = raw.get("kind", "ideal")
    if isinstance(kind, list):
        raise DescriptionError(f"joints[{i}].kind",
                               f"a joint has one kind, got {kind}; a locked joint with play "
                               "is kind = \"locked_clearance\"")
    if kind not in JOINT_KINDS:
        hint = did_you_mean(str(kind), JOINT_KINDS)
        raise DescriptionError(f"joints[{i}].kind",
                               f"must be one of {', '.join(JOINT_KINDS)}, got {kind!r}{hint}")
    return Joint(**_numbers(raw, f"joints[{i}]", values))


def _gravity(data: Mapping[str, Any], values: Problems) -> Gravity:
    gravity_raw = data.get("gravity", {})
    gravity_raw = _known(gravity_raw, ("enabled", "vector"), "gravity", values)
    vector = gravity_raw.get("vector", Gravity().vector)
    if not isinstance(vector, list | tuple) or len(vector) != 2:
        raise DescriptionError("gravity.vector", f"must be [gx, gy] in m/s^2, got {vector!r}")
    components = [math.nan, math.nan]
    for k, axis in enumerate("xy"):
        with values.check():
            components[k] = number(vector[k], f"gravity.vector.{axis}")
    return Gravity(enabled=boolean(gravity_raw.get("enabled", True), "gravity.enabled"),
                   vector=(components[0], components[1]))


def _option_tables(data: Mapping[str, Any], values: Problems
                   ) -> dict[str, Mapping[str, Any]]:
    """The contact, friction, drive, lubrication and wear tables (empty where absent), their
    keys checked; their numbers are read when the robot is built."""
    allowed = {"contact": tuple(vars(Contact())), "friction": tuple(vars(Friction())),
               "drive": ("enabled",), "lubrication": tuple(vars(Lubrication())),
               "wear": tuple(vars(Wear()))}
    tables = {}
    for table, keys in allowed.items():
        tables[table] = data.get(table, {})
        tables[table] = _known(tables[table], keys, table, values)
    return tables


def load_robot(path: str | Path) -> Robot:
    """Read and validate a robot description TOML file (never executed: data only).

    Parameters
    ----------
    path : str or pathlib.Path
        The robot file.

    Returns
    -------
    Robot
        The robot.

    Raises
    ------
    DescriptionError
        When the file is missing, is not TOML, or a field is invalid: the message names the
        file, the field and the fix.

    Examples
    --------
    >>> from pathlib import Path
    >>> import jointplay
    >>> robot = jointplay.uniform_chain(2, ["ideal", "clearance"], name="two_link")
    >>> _ = Path("two_link.toml").write_text(jointplay.robot_to_toml(robot))
    >>> jointplay.load_robot("two_link.toml") == robot
    True
    >>> _ = Path("typo.toml").write_text(Path("two_link.toml").read_text().replace(
    ...     'kind = "clearance"', 'kind = "clearence"'))
    >>> jointplay.load_robot("typo.toml")
    Traceback (most recent call last):
    ...
    jointplay.common.errors.DescriptionError: typo.toml: joints[2].kind: ...
    """
    data, _ = read_toml(path, "robot")
    return robot_from_dict(data, source=str(path))


def parse_index_list(text: str, flag: str, n_links: int) -> list[int]:
    """Parse ``"2,5"`` into ``[2, 5]``, checking each index names a joint 1..n_links."""
    out = []
    for part in (p.strip() for p in text.split(",")):
        if not part:
            continue
        if not part.isdigit():
            raise DescriptionError(flag, f"must be comma-separated joint numbers, got {part!r}")
        idx = int(part)
        if not 1 <= idx <= n_links:
            raise DescriptionError(flag, f"joint {idx} is out of range: joints are 1..{n_links}")
        out.append(idx)
    return out


def robot_from_flags(
    links: Any,
    clearance: str = "",
    locked: str = "",
    locked_clearance: str = "",
    friction: str = "coulomb",
    contact_law: str = "lankarani-nikravesh",
    gravity: bool = True,
) -> Robot:
    """The common case from command-line flags: k uniform links, chosen joint kinds.

    Links are 0.3 m, 1 kg, uniform rods; clearance joints are 10 mm steel bearings with 0.03
    mm radial clearance. Edit a TOML description for anything else.

    Parameters
    ----------
    links : int
        The number of links.
    clearance : str, default ""
        Joints with clearance, comma-separated (``"2,3"``).
    locked : str, default ""
        Locked joints.
    locked_clearance : str, default ""
        Locked joints whose journal floats in its bearing.
    friction : {"coulomb", "none"}, default "coulomb"
        The friction law of the clearance joints.
    contact_law : str, default "lankarani-nikravesh"
        The contact law's damping factor (see :class:`Contact`).
    gravity : bool, default True
        Gravity in the model.

    Returns
    -------
    Robot
        The robot, as ``jointplay build --links K --clearance ...`` makes it.

    Raises
    ------
    DescriptionError
        Naming the flag and the fix (a joint out of range, or given two kinds).
    """
    if isinstance(links, bool) or not isinstance(links, int):
        try:
            links = int(str(links), 10)
        except ValueError:
            raise DescriptionError("--links", f"must be an integer from 1 to {MAX_LINKS}, "
                                              f"got {links!r}") from None
    if not 1 <= links <= MAX_LINKS:
        raise DescriptionError("--links", f"must be from 1 to {MAX_LINKS}, got {links}")
    kinds: dict[int, str] = {}
    for flag, kind, text in (("--clearance", "clearance", clearance),
                             ("--locked", "locked", locked),
                             ("--locked-clearance", "locked_clearance", locked_clearance)):
        for idx in parse_index_list(text, flag, links):
            if idx in kinds and kinds[idx] != kind:
                raise DescriptionError(
                    flag, f"joint {idx} is given two kinds ({kinds[idx]} and {kind}); a locked "
                          "joint with play is --locked-clearance")
            kinds[idx] = kind
    return uniform_chain(
        links,
        kinds=[kinds.get(i, "ideal") for i in range(1, links + 1)],
        gravity=Gravity(enabled=gravity),
        contact=Contact(law=contact_law),  # type: ignore[arg-type]
        friction=Friction(law=friction),  # type: ignore[arg-type]
    )


