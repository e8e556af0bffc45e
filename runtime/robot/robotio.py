"""Write a robot description back to TOML (the reader is :func:`jointplay.load_robot`)."""

from __future__ import annotations

from typing import Any

from jointplay.robot.description import Robot


def _value(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return repr(float(v))
    if isinstance(v, str):
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    raise TypeError(f"cannot write {type(v).__name__} to TOML")


def robot_to_toml(robot: Robot, comment: str = "") -> str:
    """A robot description file's text for ``robot``: what :func:`load_robot` reads back.

    Parameters
    ----------
    robot : Robot
        The robot to write out.
    comment : str, default ""
        Lines written first, each as a TOML comment.

    Returns
    -------
    str
        The TOML text, every table and field written out (defaults included), so that
        ``load_robot`` of the file gives a robot equal to ``robot``.

    Examples
    --------
    >>> import jointplay
    >>> text = jointplay.robot_to_toml(jointplay.uniform_chain(2), comment="two rods")
    >>> print(text.splitlines()[0])
    # two rods
    >>> text.count("[[links]]"), text.count("[[joints]]")
    (2, 2)
    """
    data = robot.to_dict()
    lines = [f"# {line}" for line in comment.splitlines()]
    lines.append(f"name = {_value(data.pop('name'))}")
    arrays = {key: data.pop(key) for key in ("links", "joints")}
    for key, table in data.items():
        lines.append(f"\n[{key}]")
        lines += [f"{k} = {_value(v)}" for k, v in table.items()]
    for key, items in arrays.items():
        for item in items:
            lines.append(f"\n[[{key}]]")
            lines += [f"{k} = {_value(v)}" for k, v in item.items()]
    return "\n".join(lines) + "\n"
