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
